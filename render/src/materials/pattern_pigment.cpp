// Patterned pigments: a pattern's value through a color_map or a
// pigment_map, a block pattern's list of pigments, and POV's `average`.
// As in POV-Ray's Compute_Pigment, a map's pigments are evaluated at the
// parent's pattern point (after its transforms and warps), so nested maps
// compose.
#include <algorithm>
#include <cmath>

#include "lancer/scene_error.h"
#include "materials/average_weights.h"
#include "materials/blend_map.h"
#include "materials/function_natives.h"
#include "materials/pattern_space.h"
#include "materials/point_pigment.h"

namespace lancer {
namespace {

TextureSample mix(const TextureSample& a, const TextureSample& b, float fraction) {
    return {a.rgb + fraction * (b.rgb - a.rgb), a.filter + fraction * (b.filter - a.filter),
            a.transmit + fraction * (b.transmit - a.transmit)};
}

TextureSample scaled(const TextureSample& a, float weight) {
    return {a.rgb * weight, a.filter * weight, a.transmit * weight};
}

TextureSample sum(const TextureSample& a, const TextureSample& b) {
    return {a.rgb + b.rgb, a.filter + b.filter, a.transmit + b.transmit};
}

class SolidPointPigment final : public PointPigment {
  public:
    explicit SolidPointPigment(const TextureSample& value) : m_value(value) {}
    TextureSample at(const glm::dvec3&, const PatternContext&) const override { return m_value; }
    TextureSample average() const override { return m_value; }

  private:
    TextureSample m_value;
};

class ColorMapPigment final : public PointPigment {
  public:
    ColorMapPigment(const sg::Pigment& pigment, const MaterialBuild& build)
        : m_pattern(compile_pattern(*pigment.pattern, build)) {
        for (const auto& entry : *pigment.color_map) {
            m_values.push_back(float(entry.value));
            m_colours.push_back(to_sample(entry.color));
        }
    }
    TextureSample at(const glm::dvec3& point, const PatternContext& context) const override {
        const BlendPair pair = search_blend_map(m_values, m_pattern.value(point, context));
        if (pair.previous == pair.current) return m_colours[pair.current];
        return mix(m_colours[pair.previous], m_colours[pair.current], pair.fraction);
    }
    // The map's mean over values uniform in [0, 1]: the colours held
    // below the first and above the last entry, linear between.
    TextureSample average() const override {
        TextureSample total;
        double previous_value = 0.0;
        TextureSample previous = m_colours.front();
        for (std::size_t i = 0; i < m_values.size(); ++i) {
            const double value = std::clamp(double(m_values[i]), 0.0, 1.0);
            const float width = float(std::max(0.0, value - previous_value));
            total = sum(total, scaled(mix(previous, m_colours[i], 0.5f), width));
            previous_value = std::max(previous_value, value);
            previous = m_colours[i];
        }
        return sum(total, scaled(m_colours.back(), float(1.0 - previous_value)));
    }

  private:
    CompiledPattern m_pattern;
    std::vector<float> m_values;
    std::vector<TextureSample> m_colours;
};

class PigmentMapPigment final : public PointPigment {
  public:
    PigmentMapPigment(const sg::Pigment& pigment, const MaterialBuild& build)
        : m_pattern(compile_pattern(*pigment.pattern, build)) {
        for (const auto& entry : pigment.pigment_map) {
            m_values.push_back(float(entry.value));
            m_pigments.push_back(make_point_pigment(*entry.pigment, build));
        }
    }
    TextureSample at(const glm::dvec3& point, const PatternContext& context) const override {
        // One pass through the warps serves the value and the entries' point.
        const glm::dvec3 inner = m_pattern.pattern_point(point);
        const BlendPair pair = search_blend_map(m_values, m_pattern.value_at_pattern_point(inner, context));
        const TextureSample current = m_pigments[pair.current]->at(inner, context);
        if (pair.previous == pair.current) return current;
        return mix(m_pigments[pair.previous]->at(inner, context), current, pair.fraction);
    }
    TextureSample average() const override {
        TextureSample total;
        for (const auto& pigment : m_pigments) total = sum(total, pigment->average());
        return scaled(total, 1.0f / float(m_pigments.size()));
    }

  private:
    CompiledPattern m_pattern;
    std::vector<float> m_values;
    std::vector<std::unique_ptr<PointPigment>> m_pigments;
};

class BlockPigment final : public PointPigment {
  public:
    BlockPigment(const sg::Pigment& pigment, const MaterialBuild& build)
        : m_pattern(compile_block_pattern(*pigment.pattern, build)) {
        for (const auto& block : pigment.block_pigments) m_blocks.push_back(make_point_pigment(*block, build));
    }
    TextureSample at(const glm::dvec3& point, const PatternContext& context) const override {
        const int index = block_in_list(m_pattern.block_index(point), m_blocks.size());
        return m_blocks[index]->at(m_pattern.pattern_point(point), context);
    }
    TextureSample average() const override {
        TextureSample total;
        for (const auto& block : m_blocks) total = sum(total, block->average());
        return scaled(total, 1.0f / float(m_blocks.size()));
    }

  private:
    CompiledPattern m_pattern;
    std::vector<std::unique_ptr<PointPigment>> m_blocks;
};

// POV's average: the pigments of the map weighted by their values.
class AveragePigment final : public PointPigment {
  public:
    AveragePigment(const sg::Pigment& pigment, const MaterialBuild& build)
        : m_warps(compile_pattern(*pigment.pattern, build)) {
        std::vector<double> values;
        for (const auto& entry : pigment.pigment_map) {
            values.push_back(entry.value);
            m_pigments.push_back(make_point_pigment(*entry.pigment, build));
        }
        for (double weight : average_weights(values)) m_weights.push_back(float(weight));
    }
    TextureSample at(const glm::dvec3& point, const PatternContext& context) const override {
        const glm::dvec3 inner = m_warps.pattern_point(point);
        TextureSample result;
        for (std::size_t i = 0; i < m_pigments.size(); ++i)
            result = sum(result, scaled(m_pigments[i]->at(inner, context), m_weights[i]));
        return result;
    }
    TextureSample average() const override {
        TextureSample result;
        for (std::size_t i = 0; i < m_pigments.size(); ++i)
            result = sum(result, scaled(m_pigments[i]->average(), m_weights[i]));
        return result;
    }

  private:
    CompiledPattern m_warps;       // its transforms and warps; the pattern is not used
    std::vector<float> m_weights;  // divided by their sum (when it is not 0)
    std::vector<std::unique_ptr<PointPigment>> m_pigments;
};

}  // namespace

std::unique_ptr<PointPigment> make_point_pigment(const sg::Pigment& pigment, const MaterialBuild& build) {
    switch (pigment.kind) {
    case sg::Pigment::Kind::Solid: return std::make_unique<SolidPointPigment>(to_sample(pigment.color));
    case sg::Pigment::Kind::Average: return std::make_unique<AveragePigment>(pigment, build);
    case sg::Pigment::Kind::Patterned:
        if (!pigment.block_pigments.empty()) return std::make_unique<BlockPigment>(pigment, build);
        if (!pigment.pigment_map.empty()) return std::make_unique<PigmentMapPigment>(pigment, build);
        if (pigment.color_map && !pigment.color_map->empty()) return std::make_unique<ColorMapPigment>(pigment, build);
        throw SceneError(pigment.location,
                         "the pattern has no colour map, pigment map or list to take its colours from");
    case sg::Pigment::Kind::Image: return make_image_point_pigment(pigment, build);
    }
    throw SceneError(pigment.location, "unknown pigment kind");
}

CompiledPattern compile_pattern(const sg::Pattern& pattern, const MaterialBuild& build) {
    if (pattern.kind == sg::Pattern::Kind::Object) {
        if (!pattern.object) throw SceneError(pattern.location, "the object pattern needs an object");
        if (!build.inside_tests) throw SceneError(pattern.location, "the object pattern needs a scene to test against");
        InsideTest inside = (*build.inside_tests)(*pattern.object);
        return CompiledPattern(pattern, build.generator,
                               CompiledPattern::BlockSource{[inside](const glm::dvec3& point, const PatternContext&) {
                                   return inside(point) ? 1.0 : 0.0;
                               }});
    }
    if (pattern.kind == sg::Pattern::Kind::Function) {
        if (!pattern.function) throw SceneError(pattern.location, "the function pattern needs a function");
        auto natives = std::make_shared<const RenderFunctionNatives>(*pattern.function, build);
        sg::FunctionRef function = pattern.function;
        return CompiledPattern(pattern, build.generator,
                               [function, natives](const glm::dvec3& point, const PatternContext&) {
                                   const double xyz[3] = {point.x, point.y, point.z};
                                   return sg::evaluate_function(*function, xyz, 3, natives.get());
                               });
    }
    if (pattern.kind == sg::Pattern::Kind::ImagePattern)
        return CompiledPattern(pattern, build.generator, image_pattern_source(pattern, build));
    if (pattern.kind != sg::Pattern::Kind::PigmentPattern) return CompiledPattern(pattern, build.generator);
    if (!pattern.pigment) throw SceneError(pattern.location, "pigment_pattern needs a pigment");
    std::shared_ptr<const PointPigment> inner = make_point_pigment(*pattern.pigment, build);
    // POV's value is the pigment's grey (its Colour::greyscale weights).
    return CompiledPattern(pattern, build.generator, [inner](const glm::dvec3& point, const PatternContext& context) {
        const Color c = inner->at(point, context).rgb;
        return pov_greyscale(c);
    });
}

glm::dvec3 surface_point(const Hit& hit, const TextureSpaces& spaces, bool uv_mapping) {
    if (uv_mapping) return glm::dvec3(hit.uv.x, hit.uv.y, 0.0);
    return pattern_point(hit, spaces, glm::dmat4(1.0));
}

PatternContext surface_context(const Hit& hit) {
    PatternContext context;
    context.normal = glm::dvec3(hit.shading_normal);
    context.hit_point = glm::dvec3(hit.position);
    const float along = glm::length(hit.ray_direction);
    if (along > 0.0f && std::isfinite(along)) context.ray_direction = glm::dvec3(hit.ray_direction / along);
    return context;
}

bool pigment_reads_surface_uv(const sg::Pigment& pigment) {
    // An image through the surface's (u,v) is uv-mapped however it was
    // asked for (uv_mapping, or an OBJ material's texture).
    if (pigment.kind == sg::Pigment::Kind::Image && pigment.image && pigment.image->map_type == sg::MapType::UV)
        return true;
    return pigment.pattern && pigment.pattern->uv_mapping;
}

namespace {

// The top-level pigment: the hit in the space of the object the texture
// was attached to, or at (u, v, 0) with uv_mapping.
class PatternTexture final : public Texture {
  public:
    PatternTexture(const sg::Pigment& pigment, const TextureSpaces& spaces, const MaterialBuild& build)
        : m_pigment(make_point_pigment(pigment, build)),
          m_spaces(spaces),
          m_uv_mapping(pigment_reads_surface_uv(pigment)),
          m_average(m_pigment->average()) {}
    TextureSample evaluate(const Hit& hit) const override {
        return m_pigment->at(surface_point(hit, m_spaces, m_uv_mapping), surface_context(hit));
    }
    TextureSample average() const override { return m_average; }

  private:
    std::unique_ptr<PointPigment> m_pigment;
    const TextureSpaces& m_spaces;
    bool m_uv_mapping;
    TextureSample m_average;
};

}  // namespace

std::unique_ptr<Texture> make_pattern_texture(const sg::Pigment& pigment, const TextureSpaces& spaces,
                                              const MaterialBuild& build) {
    return std::make_unique<PatternTexture>(pigment, spaces, build);
}

}  // namespace lancer
