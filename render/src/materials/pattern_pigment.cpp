// Patterned pigments: a pattern's value through a color_map or a
// pigment_map, a block pattern's list of pigments, and POV's `average`.
// As in POV-Ray's Compute_Pigment, a map's pigments are evaluated at the
// parent's pattern point (after its transforms and warps), so nested maps
// compose.
#include <algorithm>

#include "lancer/scene_error.h"
#include "materials/blend_map.h"
#include "materials/pattern.h"
#include "materials/pattern_space.h"

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

// A pigment evaluated at a point of the space it was written in: object
// space at the top, its parent's pattern space inside a map.
class PointPigment {
  public:
    virtual ~PointPigment() = default;
    virtual TextureSample at(const glm::dvec3& point) const = 0;
    virtual TextureSample average() const = 0;
};

class SolidPointPigment final : public PointPigment {
  public:
    explicit SolidPointPigment(const TextureSample& value) : m_value(value) {}
    TextureSample at(const glm::dvec3&) const override { return m_value; }
    TextureSample average() const override { return m_value; }

  private:
    TextureSample m_value;
};

std::unique_ptr<PointPigment> make_point_pigment(const sg::Pigment& pigment, NoiseGenerator generator);

class ColorMapPigment final : public PointPigment {
  public:
    ColorMapPigment(const sg::Pigment& pigment, NoiseGenerator generator) : m_pattern(pigment.pattern, generator) {
        for (const auto& entry : *pigment.color_map) {
            m_values.push_back(float(entry.value));
            m_colours.push_back(to_sample(entry.color));
        }
    }
    TextureSample at(const glm::dvec3& point) const override {
        const BlendPair pair = search_blend_map(m_values, m_pattern.value(point));
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
    PigmentMapPigment(const sg::Pigment& pigment, NoiseGenerator generator) : m_pattern(pigment.pattern, generator) {
        for (const auto& entry : pigment.pigment_map) {
            m_values.push_back(float(entry.value));
            m_pigments.push_back(make_point_pigment(*entry.pigment, generator));
        }
    }
    TextureSample at(const glm::dvec3& point) const override {
        const BlendPair pair = search_blend_map(m_values, m_pattern.value(point));
        const glm::dvec3 inner = m_pattern.pattern_point(point);
        const TextureSample current = m_pigments[pair.current]->at(inner);
        if (pair.previous == pair.current) return current;
        return mix(m_pigments[pair.previous]->at(inner), current, pair.fraction);
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
    BlockPigment(const sg::Pigment& pigment, NoiseGenerator generator) : m_pattern(pigment.pattern, generator) {
        for (const auto& block : pigment.block_pigments) m_blocks.push_back(make_point_pigment(*block, generator));
    }
    TextureSample at(const glm::dvec3& point) const override {
        const int index = std::clamp(m_pattern.block_index(point), 0, int(m_blocks.size()) - 1);
        return m_blocks[index]->at(m_pattern.pattern_point(point));
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
    AveragePigment(const sg::Pigment& pigment, NoiseGenerator generator) : m_warps(pigment.pattern, generator) {
        double total = 0.0;
        for (const auto& entry : pigment.pigment_map) {
            m_weights.push_back(float(entry.value));
            total += entry.value;
            m_pigments.push_back(make_point_pigment(*entry.pigment, generator));
        }
        m_total = float(total);
    }
    TextureSample at(const glm::dvec3& point) const override {
        const glm::dvec3 inner = m_warps.pattern_point(point);
        TextureSample result;
        for (std::size_t i = 0; i < m_pigments.size(); ++i)
            result = sum(result, scaled(m_pigments[i]->at(inner), m_weights[i]));
        return m_total != 0.0f ? scaled(result, 1.0f / m_total) : result;
    }
    TextureSample average() const override {
        TextureSample result;
        for (std::size_t i = 0; i < m_pigments.size(); ++i)
            result = sum(result, scaled(m_pigments[i]->average(), m_weights[i]));
        return m_total != 0.0f ? scaled(result, 1.0f / m_total) : result;
    }

  private:
    CompiledPattern m_warps;  // its transforms and warps; the pattern is not used
    std::vector<float> m_weights;
    float m_total = 0.0f;
    std::vector<std::unique_ptr<PointPigment>> m_pigments;
};

std::unique_ptr<PointPigment> make_point_pigment(const sg::Pigment& pigment, NoiseGenerator generator) {
    switch (pigment.kind) {
    case sg::Pigment::Kind::Solid: return std::make_unique<SolidPointPigment>(to_sample(pigment.color));
    case sg::Pigment::Kind::Average: return std::make_unique<AveragePigment>(pigment, generator);
    case sg::Pigment::Kind::Patterned:
        if (!pigment.block_pigments.empty()) return std::make_unique<BlockPigment>(pigment, generator);
        if (!pigment.pigment_map.empty()) return std::make_unique<PigmentMapPigment>(pigment, generator);
        if (pigment.color_map && !pigment.color_map->empty())
            return std::make_unique<ColorMapPigment>(pigment, generator);
        throw SceneError(pigment.location,
                         "the pattern has no colour map, pigment map or list to take its colours from");
    default:
        throw SceneError(pigment.location,
                         "an image_map inside a pigment_map, a block pattern or average is not supported yet");
    }
}

// The top-level pigment: the hit in the space of the object the texture
// was attached to.
class PatternTexture final : public Texture {
  public:
    PatternTexture(const sg::Pigment& pigment, const TextureSpaces& spaces, NoiseGenerator generator)
        : m_pigment(make_point_pigment(pigment, generator)), m_spaces(spaces), m_average(m_pigment->average()) {}
    TextureSample evaluate(const Hit& hit) const override {
        return m_pigment->at(pattern_point(hit, m_spaces, glm::dmat4(1.0)));
    }
    TextureSample average() const override { return m_average; }

  private:
    std::unique_ptr<PointPigment> m_pigment;
    const TextureSpaces& m_spaces;
    TextureSample m_average;
};

}  // namespace

std::unique_ptr<Texture> make_pattern_texture(const sg::Pigment& pigment, const TextureSpaces& spaces,
                                              NoiseGenerator generator) {
    return std::make_unique<PatternTexture>(pigment, spaces, generator);
}

}  // namespace lancer
