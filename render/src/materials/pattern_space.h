// What every pattern family shares: where a hit lies in pattern space, and
// the scene graph's colours as texture samples (internal to liblancer).
#pragma once

#include <glm/glm.hpp>

#include "lancer/hit.h"
#include "lancer/scene_graph.h"
#include "lancer/texture.h"
#include "materials/textures.h"

namespace lancer {

inline TextureSample to_sample(const sg::Color& c) {
    return {Color(c.rgb), float(c.filter), float(c.transmit)};
}

// Pattern-space point of a hit: world -> texture-owner object -> pattern.
inline glm::dvec3 pattern_point(const Hit& hit, const TextureSpaces& spaces, const glm::dmat4& pattern_from_object) {
    glm::dvec4 p(glm::dvec3(hit.position), 1.0);
    if (hit.object_id < spaces.size()) p = spaces[hit.object_id] * p;
    return glm::dvec3(pattern_from_object * p);
}

}  // namespace lancer
