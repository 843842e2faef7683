// A scene graph pattern made ready to evaluate: POV-Ray 3.7's
// Evaluate_TPat (transforms and warps, the pattern function, then
// frequency, phase and wave type), and the normal a pattern perturbs
// (internal to liblancer; maps, pigments and normals build on it).
#pragma once

#include <functional>
#include <memory>

#include <glm/glm.hpp>

#include "lancer/scene_graph.h"
#include "materials/noise.h"

namespace lancer {

// What a few patterns need beyond the point (slope, aoi). POV takes these
// in world space, untouched by the pattern's transforms (a rotated slope
// pattern does not turn), so pass world-space values to match it.
struct PatternContext {
    glm::dvec3 normal{0.0, 1.0, 0.0};         // unit shading normal
    glm::dvec3 ray_direction{0.0, 0.0, 1.0};  // unit, towards the surface
    glm::dvec3 hit_point{0.0};                // slope { point_at }: the point the normal is compared from
};

class CompiledPattern {
  public:
    // global_generator: global_settings' noise_generator (POV's default 2).
    // Throws std::runtime_error for the patterns whose values come from
    // elsewhere (object, image_pattern, pigment_pattern: use the source
    // constructors below, as compile_pattern() does), for function ("not
    // supported yet"), and for parameters POV
    // refuses (mandel exponent outside 2..33,
    // magnet type other than 1 or 2, slope without any direction, tiling
    // outside 1..27, pavement sides/tiles/pattern out of POV's ranges).
    CompiledPattern(const sg::Pattern& pattern, NoiseGenerator global_generator);
    // Patterns whose value comes from elsewhere in the renderer
    // (pigment_pattern: a pigment's grey): `source` gives the value at a
    // pattern-space point; transforms, warps, frequency and waves apply
    // as for any pattern.
    using ValueSource = std::function<double(const glm::dvec3& pattern_point, const PatternContext& context)>;
    CompiledPattern(const sg::Pattern& pattern, NoiseGenerator global_generator, ValueSource source);
    // A list pattern whose block index comes from elsewhere (object: 1
    // inside the object, 0 outside).
    struct BlockSource {
        ValueSource index;
    };
    CompiledPattern(const sg::Pattern& pattern, NoiseGenerator global_generator, BlockSource source);
    ~CompiledPattern();
    CompiledPattern(CompiledPattern&&) noexcept;
    CompiledPattern& operator=(CompiledPattern&&) noexcept;

    // POV's pattern value at a point in the space of the object the texture
    // is attached to: pattern_from_object, the warps from last to first, the
    // pattern function, frequency, phase and the wave type; in [0, 1] for
    // every pattern that maps through a map.
    double value(const glm::dvec3& object_point, const PatternContext& context = {}) const;

    // Block patterns (checker, hexagon, brick, cubic, square, triangular):
    // the number of entries POV expects (2, 3, 2, 6, 4, 6) and which one
    // holds at a point (0-based).
    bool is_block() const;
    int block_count() const;
    int block_index(const glm::dvec3& object_point) const;

    // Patterns POV gives a normal of their own (bumps, dents, ripples, waves,
    // wrinkles, quilted, facets): the unit normal perturbed by `amount`
    // (POV's bump_size) at the point. object_normal is unit and in object
    // space; the result is too. False for other patterns (callers then
    // perturb by the slope of value()).
    bool has_own_normal() const;
    glm::dvec3 perturb_normal(const glm::dvec3& object_normal, const glm::dvec3& object_point, double amount) const;

    // The point after pattern_from_object and the warps, where the pattern
    // function is evaluated (for normals that take the slope of value()).
    glm::dvec3 pattern_point(const glm::dvec3& object_point) const;
    // value() at a point already in pattern space (pattern_point's result):
    // the pattern function, frequency, phase and wave type.
    double value_at_pattern_point(const glm::dvec3& pattern_point, const PatternContext& context = {}) const;
    // A normal carried into pattern space and back through the pattern's
    // transforms (POV's Warp_Normal and UnWarp_Normal), unit length.
    glm::dvec3 normal_to_pattern_space(const glm::dvec3& normal) const;
    glm::dvec3 normal_from_pattern_space(const glm::dvec3& normal) const;

  private:
    struct State;
    std::unique_ptr<State> m_state;
};

}  // namespace lancer
