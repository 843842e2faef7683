// A pigment evaluated at a point of the space it was written in: object
// space at the top, its parent's pattern space inside a map (POV-Ray's
// Compute_Pigment). Patterned pigments and patterned normals build on it
// (internal to liblancer).
#pragma once

#include <memory>

#include "lancer/hit.h"
#include "lancer/scene_graph.h"
#include "lancer/texture.h"
#include "materials/pattern.h"
#include "materials/textures.h"

namespace lancer {

class PointPigment {
  public:
    virtual ~PointPigment() = default;
    virtual TextureSample at(const glm::dvec3& point, const PatternContext& context) const = 0;
    virtual TextureSample average() const = 0;
};

// Solid, patterned and average pigments; throws lancer::SceneError for an
// image_map nested in a map.
std::unique_ptr<PointPigment> make_point_pigment(const sg::Pigment& pigment, NoiseGenerator generator);

// A pattern ready to evaluate, pigment_pattern included (its pigment's
// grey is the value).
CompiledPattern compile_pattern(const sg::Pattern& pattern, NoiseGenerator generator);

// Where a hit lies for a pattern (object space, or (u, v, 0) with
// uv_mapping), and what slope and aoi read there (world space, as POV).
glm::dvec3 surface_point(const Hit& hit, const TextureSpaces& spaces, bool uv_mapping);
PatternContext surface_context(const Hit& hit);

}  // namespace lancer
