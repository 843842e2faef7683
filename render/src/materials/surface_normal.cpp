// POV-Ray's normal { }: the shading normal bent by a pattern, as POV's
// Perturb_Normal does it (normal.cpp in POV-Ray 3.7, read for its rules):
//   - a normal_map blends the normals of its entries by the pattern's
//     value (a block pattern's list picks one), each evaluated at the
//     parent's pattern point with the normal carried into that space;
//   - bumps, dents, ripples, waves, wrinkles, quilted and facets bend it
//     by their own formulas;
//   - any other pattern bends it by the slope of its value (through a
//     slope_map when given), sampled at four points of a tetrahedron
//     `accuracy` from the point and weighted by -5 bump_size 0.02/accuracy;
//   - average takes the mean of its normals, weighted by their values;
//   - bump_map tilts it by the slope of an image's heights.
// The normal is renormalised on entering and leaving each pattern space,
// so a pattern's scale does not change how deep its bumps look.
#include <algorithm>
#include <cmath>
#include <optional>
#include <stdexcept>

#include "lancer/scene_error.h"
#include "materials/average_weights.h"
#include "materials/blend_map.h"
#include "materials/image_sampler.h"
#include "materials/palette_image.h"
#include "materials/pattern.h"
#include "materials/pattern_space.h"
#include "materials/point_pigment.h"

namespace lancer {
namespace {

// POV's Pyramid_Vect: a regular tetrahedron's vertex directions.
const glm::dvec3 kTetrahedron[4] = {{0.942809041, -0.333333333, 0.0},
                                    {-0.471404521, -0.333333333, 0.816496581},
                                    {-0.471404521, -0.333333333, -0.816496581},
                                    {0.0, 1.0, 0.0}};

glm::dvec3 unit(const glm::dvec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : v;
}

// The value at t in [0, 1] of the cubic through (0, h0) with slope s0 and
// (1, h1) with slope s1.
double hermite(double t, double h0, double s0, double h1, double s1) {
    const double t2 = t * t, t3 = t2 * t;
    return (2.0 * t3 - 3.0 * t2 + 1.0) * h0 + (t3 - 2.0 * t2 + t) * s0 + (3.0 * t2 - 2.0 * t3) * h1 + (t3 - t2) * s1;
}

class NormalNode {
  public:
    virtual ~NormalNode() = default;
    // The normal at `point`, both in the space the normal was written in.
    virtual glm::dvec3 perturb(const glm::dvec3& normal, const glm::dvec3& point) const = 0;
};

std::unique_ptr<NormalNode> make_node(const sg::Normal& normal, const MaterialBuild& build);

class PatternNormalNode final : public NormalNode {
  public:
    PatternNormalNode(const sg::Normal& normal, const MaterialBuild& build)
        : m_pattern(normal.block_normals.empty() ? compile_pattern(*normal.pattern, build)
                                                 : compile_block_pattern(*normal.pattern, build)),
          m_amount(normal.bump_size),
          m_accuracy(normal.accuracy),
          m_own_normal(m_pattern.has_own_normal()) {
        for (const auto& entry : normal.slope_map) {
            m_slope_values.push_back(float(entry.value));
            m_slopes.push_back({entry.height, entry.slope});
        }
        for (const auto& entry : normal.normal_map) {
            m_map_values.push_back(float(entry.value));
            m_map.push_back(make_node(*entry.normal, build));
        }
        for (const auto& block : normal.block_normals) m_blocks.push_back(make_node(*block, build));
    }

    glm::dvec3 perturb(const glm::dvec3& normal, const glm::dvec3& point) const override {
        if (!m_map.empty()) return perturb_by_map(normal, point);
        if (!m_blocks.empty()) return perturb_by_block(normal, point);
        if (m_own_normal) return m_pattern.perturb_normal(unit(normal), point, m_amount);
        return perturb_by_slope(normal, point);
    }

  private:
    glm::dvec3 perturb_by_map(const glm::dvec3& normal, const glm::dvec3& point) const {
        const glm::dvec3 inner_point = m_pattern.pattern_point(point);
        const BlendPair pair = search_blend_map(m_map_values, m_pattern.value_at_pattern_point(inner_point));
        const glm::dvec3 inner_normal = m_pattern.normal_to_pattern_space(normal);
        glm::dvec3 result = m_map[pair.current]->perturb(inner_normal, inner_point);
        if (pair.previous != pair.current) {
            const glm::dvec3 before = m_map[pair.previous]->perturb(inner_normal, inner_point);
            result = before + double(pair.fraction) * (result - before);
        }
        return m_pattern.normal_from_pattern_space(result);
    }

    glm::dvec3 perturb_by_block(const glm::dvec3& normal, const glm::dvec3& point) const {
        const int index = block_in_list(m_pattern.block_index(point), m_blocks.size());
        const glm::dvec3 inner =
            m_blocks[index]->perturb(m_pattern.normal_to_pattern_space(normal), m_pattern.pattern_point(point));
        return m_pattern.normal_from_pattern_space(inner);
    }

    double slope_mapped(double value) const {
        if (m_slopes.empty()) return value;
        const BlendPair pair = search_blend_map(m_slope_values, value);
        const glm::dvec2& to = m_slopes[pair.current];
        if (pair.previous == pair.current) return to.x;
        const glm::dvec2& from = m_slopes[pair.previous];
        return hermite(pair.fraction, from.x, from.y, to.x, to.y);
    }

    glm::dvec3 perturb_by_slope(const glm::dvec3& normal, const glm::dvec3& point) const {
        glm::dvec3 bent = m_pattern.normal_to_pattern_space(normal);
        const glm::dvec3 center = m_pattern.pattern_point(point);
        const double weight = -5.0 * m_amount * 0.02 / m_accuracy;
        for (const glm::dvec3& direction : kTetrahedron) {
            const double value = slope_mapped(m_pattern.value_at_pattern_point(center + m_accuracy * direction));
            bent += value * weight * direction;
        }
        return m_pattern.normal_from_pattern_space(bent);
    }

    CompiledPattern m_pattern;
    double m_amount;
    double m_accuracy;
    bool m_own_normal;
    std::vector<float> m_slope_values;
    std::vector<glm::dvec2> m_slopes;  // (height, slope)
    std::vector<float> m_map_values;
    std::vector<std::unique_ptr<NormalNode>> m_map;
    std::vector<std::unique_ptr<NormalNode>> m_blocks;
};

class AverageNormalNode final : public NormalNode {
  public:
    AverageNormalNode(const sg::Normal& normal, const MaterialBuild& build)
        : m_warps(compile_pattern(*normal.pattern, build)) {
        std::vector<double> values;
        for (const auto& entry : normal.normal_map) {
            values.push_back(entry.value);
            m_normals.push_back(make_node(*entry.normal, build));
        }
        m_weights = average_weights(values);
    }
    glm::dvec3 perturb(const glm::dvec3& normal, const glm::dvec3& point) const override {
        const glm::dvec3 inner_normal = m_warps.normal_to_pattern_space(normal);
        const glm::dvec3 inner_point = m_warps.pattern_point(point);
        glm::dvec3 sum(0.0);
        for (std::size_t i = 0; i < m_normals.size(); ++i)
            sum += m_weights[i] * m_normals[i]->perturb(inner_normal, inner_point);
        return m_warps.normal_from_pattern_space(sum);
    }

  private:
    CompiledPattern m_warps;        // its transforms and warps; the pattern is not used
    std::vector<double> m_weights;  // average_weights: divided by their sum
    std::vector<std::unique_ptr<NormalNode>> m_normals;
};

// POV's bump_map: the image is a height field (its grey times bump_size;
// with use_index, a colour-mapped file's palette index times bump_size, as
// POV-Ray reads it) over the pattern's x-y plane. The
// surface through the heights at the point's pixel and at the two pixels
// diagonally below it tilts the normal, in a frame whose x axis is
// horizontal (normal x world y).
class BumpMapNode final : public NormalNode {
  public:
    BumpMapNode(const sg::Normal& normal, const MaterialBuild& build)
        : m_warps(*normal.pattern, build.generator),
          m_image(open_image(normal.bump_map, build)),
          m_amount(normal.bump_size),
          m_interpolate(normal.bump_map.interpolate != 0) {
        if (!normal.bump_map_use_color) {
            try {
                m_indices = read_palette_image(normal.bump_map.path);
            } catch (const std::runtime_error& error) {
                throw SceneError(normal.bump_map.location,
                                 "cannot read image '" + normal.bump_map.path + "': " + error.what());
            }
        }
    }

    glm::dvec3 perturb(const glm::dvec3& normal, const glm::dvec3& point) const override {
        const std::optional<glm::dvec2> uv = m_image.project(m_warps.pattern_point(point));
        if (!uv) return normal;
        const glm::dvec2 pixel(1.0 / m_image.width(), 1.0 / m_image.height());
        const double here = height(*uv);
        const double below_left = height(*uv + glm::dvec2(-pixel.x, -pixel.y));
        const double below_right = height(*uv + glm::dvec2(pixel.x, -pixel.y));
        // The triangle (0, here, 0), (-1, below_left, 1), (1, below_right, 1).
        const glm::dvec3 left(-1.0, below_left, 1.0);
        const glm::dvec3 tilt =
            unit(glm::cross(glm::dvec3(1.0, below_right, 1.0) - left, glm::dvec3(0.0, here, 0.0) - left));

        glm::dvec3 up = unit(m_warps.normal_to_pattern_space(normal));
        glm::dvec3 across = glm::cross(up, glm::dvec3(0.0, 1.0, 0.0));
        double length = glm::length(across);
        if (length < 1e-10) {
            // Along the y axis: POV's fixed frame.
            up = glm::dvec3(0.0, std::fabs(up.y - 1.0) < 1e-10 ? 1.0 : -1.0, 0.0);
            across = glm::dvec3(1.0, 0.0, 0.0);
            length = 1.0;
        }
        across /= length;
        const glm::dvec3 along = unit(glm::cross(across, up));
        return m_warps.normal_from_pattern_space(tilt.x * across + tilt.y * up - tilt.z * along);
    }

  private:
    double height(const glm::dvec2& uv) const {
        if (m_indices) return m_amount * palette_index_at(uv);
        return m_amount * pov_greyscale(m_image.at(uv).rgb);
    }

    // The palette index at (u, v) as POV's image_colour_at gives it: the
    // pixel's, or the four nearest pixels' blended with the colours'
    // weights and truncated.
    double palette_index_at(const glm::dvec2& uv) const {
        const PaletteImage& image = *m_indices;
        const auto index = [&](double column, double row) {
            const glm::ivec2 at =
                m_image.wrap((long long)std::floor(column), (long long)std::floor(row), image.width, image.height);
            return double(image.indices[std::size_t(at.y) * std::size_t(image.width) + std::size_t(at.x)]);
        };
        const glm::dvec2 position = ImageSampler::pixel_position(uv, image.width, image.height);
        const double x = position.x, y = position.y;
        if (!m_interpolate) return index(x, y);
        const double left = std::floor(x - 0.5), top = std::floor(y - 0.5);
        const double fx = x - 0.5 - left, fy = y - 0.5 - top;
        const double blended = (1.0 - fy) * ((1.0 - fx) * index(left, top) + fx * index(left + 1.0, top)) +
                               fy * ((1.0 - fx) * index(left, top + 1.0) + fx * index(left + 1.0, top + 1.0));
        return std::trunc(blended);
    }

    CompiledPattern m_warps;  // the normal's transforms and warps
    ImageSampler m_image;
    double m_amount;
    bool m_interpolate;
    std::optional<PaletteImage> m_indices;  // a colour-mapped file read by its indices
};

std::unique_ptr<NormalNode> make_node(const sg::Normal& normal, const MaterialBuild& build) {
    try {
        switch (normal.kind) {
        case sg::Normal::Kind::Patterned: return std::make_unique<PatternNormalNode>(normal, build);
        case sg::Normal::Kind::Average: return std::make_unique<AverageNormalNode>(normal, build);
        case sg::Normal::Kind::BumpMap: return std::make_unique<BumpMapNode>(normal, build);
        }
    } catch (const std::runtime_error& unsupported) {
        if (dynamic_cast<const SceneError*>(&unsupported)) throw;
        throw SceneError(normal.location, std::string("normal: ") + unsupported.what());
    }
    throw SceneError(normal.location, "unknown normal kind");
}

// The top level: from the world to the space of the object the texture was
// attached to, and back.
class SurfaceNormal final : public NormalPerturbation {
  public:
    SurfaceNormal(const sg::Normal& normal, const TextureSpaces& spaces, const MaterialBuild& build)
        : m_root(make_node(normal, build)), m_spaces(spaces), m_uv_mapping(normal.pattern->uv_mapping) {}

    Vec3 perturb(const Hit& hit, const Vec3& shading_normal) const override {
        const glm::dmat3 object_from_world =
            hit.object_id < m_spaces.size() ? glm::dmat3(m_spaces[hit.object_id]) : glm::dmat3(1.0);
        // Normals move by the inverse transpose of what moves points.
        const glm::dmat3 normal_to_object = glm::transpose(glm::inverse(object_from_world));
        const glm::dvec3 object_normal = unit(normal_to_object * glm::dvec3(shading_normal));
        const glm::dvec3 bent = m_root->perturb(object_normal, surface_point(hit, m_spaces, m_uv_mapping));
        const glm::dvec3 world = unit(glm::transpose(object_from_world) * bent);
        if (!std::isfinite(world.x) || !std::isfinite(world.y) || !std::isfinite(world.z) || world == glm::dvec3(0.0))
            return shading_normal;
        return Vec3(world);
    }

  private:
    std::unique_ptr<NormalNode> m_root;
    const TextureSpaces& m_spaces;
    bool m_uv_mapping;
};

}  // namespace

std::unique_ptr<NormalPerturbation> make_surface_normal(const sg::Normal& normal, const TextureSpaces& spaces,
                                                        const MaterialBuild& build) {
    return std::make_unique<SurfaceNormal>(normal, spaces, build);
}

}  // namespace lancer
