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

// POV's Colour::greyscale(), the grey a pattern reads from a colour.
inline double pov_greyscale(const Color& c) {
    return 0.297 * c.r + 0.589 * c.g + 0.114 * c.b;
}

class PointPigment {
  public:
    virtual ~PointPigment() = default;
    virtual TextureSample at(const glm::dvec3& point, const PatternContext& context) const = 0;
    virtual TextureSample average() const = 0;
};

// Solid, patterned and average pigments; throws lancer::SceneError for an
// image_map nested in a map.
std::unique_ptr<PointPigment> make_point_pigment(const sg::Pigment& pigment, const MaterialBuild& build);

// An image_map inside a map, a block list or average; and image_pattern's
// value at a pattern-space point (image_pattern.cpp).
std::unique_ptr<PointPigment> make_image_point_pigment(const sg::Pigment& pigment, const MaterialBuild& build);
CompiledPattern::ValueSource image_pattern_source(const sg::Pattern& pattern, const MaterialBuild& build);

// A pattern ready to evaluate, pigment_pattern included (its pigment's
// grey is the value).
CompiledPattern compile_pattern(const sg::Pattern& pattern, const MaterialBuild& build);
// A pattern whose value is a block number (material_map.cpp): a block
// pattern's, or a material_map image's; and a block number as an index
// into a list of `count` blocks (a material_map's may be past its end).
CompiledPattern::BlockSource material_map_source(const sg::Pattern& pattern, const MaterialBuild& build);
CompiledPattern compile_block_pattern(const sg::Pattern& pattern, const MaterialBuild& build);
int block_in_list(int index, std::size_t count);

// Where a hit lies for a pattern (object space, or (u, v, 0) with
// uv_mapping), and what slope and aoi read there (world space, as POV).
glm::dvec3 surface_point(const Hit& hit, const TextureSpaces& spaces, bool uv_mapping);
PatternContext surface_context(const Hit& hit);

}  // namespace lancer
