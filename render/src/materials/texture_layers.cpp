// POV-Ray's patterned textures (texture_map, a block pattern's list of
// textures) and layered textures as one material each.
//
// POV lights every texture of a map or a layer with its own finish and
// normal and blends the lit colours. lancer does so for the entries of a
// map (materials/material_entries.h) and the layers of a layered texture
// (lancer/shading/material_layers.h); the one material built here is what
// the object is made of where one material must stand for all (the light
// an emitting object becomes, a layered texture in `path`). It
// is the map of the entries' pigments (a pigment_map over the same
// pattern) and of their normals, with the first entry's finish; a layered
// texture's pigments are composited as POV composites its layers (each
// layer's filter and transmit let the layers below show through), with the
// layers' finishes blended by how much of each shows on average and the
// topmost normal. Where the layers' finishes agree, which is the usual case, this
// is POV's picture; docs/scene-language.md lists the difference.
#include <algorithm>

#include "materials/average_weights.h"
#include "materials/pattern_space.h"
#include "materials/textures.h"

namespace lancer {
namespace {

// A normal that leaves the surface as it is, for map entries without one.
sg::NormalRef flat_normal() {
    auto flat = std::make_shared<sg::Normal>();
    flat->bump_size = 0.0;
    return flat;
}

class LayeredTexture final : public Texture {
  public:
    explicit LayeredTexture(std::vector<std::unique_ptr<Texture>> layers) : m_layers(std::move(layers)) {}

    TextureSample evaluate(const Hit& hit) const override {
        std::vector<TextureSample> samples;
        samples.reserve(m_layers.size());
        for (const auto& layer : m_layers) samples.push_back(layer->evaluate(hit));
        return composite(samples);
    }
    TextureSample average() const override {
        std::vector<TextureSample> samples;
        for (const auto& layer : m_layers) samples.push_back(layer->average());
        return composite(samples);
    }

  private:
    // Bottom to top: what the surface shows (colour times opacity) and
    // what light passing through it is multiplied by.
    static TextureSample composite(const std::vector<TextureSample>& layers) {
        Color shown(0.0f), passed(1.0f);
        bool first = true;
        for (const TextureSample& layer : layers) {
            const float transparency = std::clamp(layer.filter + layer.transmit, 0.0f, 1.0f);
            const Color tint = layer.filter * layer.rgb + Color(layer.transmit);
            shown = (1.0f - transparency) * layer.rgb + (first ? Color(0.0f) : tint * shown);
            passed = first ? tint : tint * passed;
            first = false;
        }
        // One (colour, filter) that shows `shown` and passes `passed`.
        const Color colour = shown + passed;
        const float total = colour.r + colour.g + colour.b;
        const float filter = total > 0.0f ? std::clamp((passed.r + passed.g + passed.b) / total, 0.0f, 1.0f) : 0.0f;
        return {colour, filter, 0.0f};
    }

    std::vector<std::unique_ptr<Texture>> m_layers;
};

// An average texture as one material (where one must stand for all: an
// emitting object's light): the pigments and normals averaged and the
// finishes weighed alike. Hits light each entry (material_entries.h).
sg::Material average_of(const std::vector<sg::Material>& entries, const std::vector<double>& values,
                        sg::Material result) {
    const std::vector<double> weights = average_weights(values);
    result.pigment.kind = sg::Pigment::Kind::Average;
    result.pigment.location = result.location;
    std::vector<sg::Finish> finishes;
    for (std::size_t i = 0; i < entries.size(); ++i) {
        result.pigment.pigment_map.push_back({weights[i], std::make_shared<sg::Pigment>(entries[i].pigment)});
        finishes.push_back(*entries[i].finish);
    }
    result.finish = blend_finishes(finishes, weights);
    const bool any_normal =
        std::any_of(entries.begin(), entries.end(), [](const sg::Material& m) { return bool(m.normal); });
    if (any_normal) {
        auto normal = std::make_shared<sg::Normal>();
        normal->kind = sg::Normal::Kind::Average;
        normal->location = result.location;
        for (std::size_t i = 0; i < entries.size(); ++i)
            normal->normal_map.push_back({weights[i], entries[i].normal ? entries[i].normal : flat_normal()});
        result.normal = normal;
    }
    return result;
}

}  // namespace

sg::Material flatten_patterned_texture(const sg::Material& texture) {
    if (!texture.pattern) return texture;
    std::vector<sg::MaterialRef> entries;
    std::vector<double> values;
    for (const auto& entry : texture.texture_map) {
        entries.push_back(entry.texture);
        values.push_back(entry.value);
    }
    for (const auto& block : texture.block_textures) entries.push_back(block);
    sg::Material result;
    result.interior = texture.interior;
    result.name = texture.name;
    result.location = texture.location;
    if (entries.empty()) return result;
    std::vector<sg::Material> flat;
    for (const auto& entry : entries) flat.push_back(flatten_patterned_texture(*entry));
    result.finish = flat.front().finish;
    if (texture.average) return average_of(flat, values, result);

    result.pigment.kind = sg::Pigment::Kind::Patterned;
    result.pigment.pattern = *texture.pattern;
    result.pigment.location = texture.location;
    const bool blocks = !texture.block_textures.empty();
    for (std::size_t i = 0; i < flat.size(); ++i) {
        auto pigment = std::make_shared<sg::Pigment>(flat[i].pigment);
        if (blocks)
            result.pigment.block_pigments.push_back(pigment);
        else
            result.pigment.pigment_map.push_back({values[i], pigment});
    }

    const bool any_normal = std::any_of(flat.begin(), flat.end(), [](const sg::Material& m) { return bool(m.normal); });
    if (any_normal) {
        auto normal = std::make_shared<sg::Normal>();
        normal->pattern = *texture.pattern;
        normal->location = texture.location;
        for (std::size_t i = 0; i < flat.size(); ++i) {
            const sg::NormalRef entry = flat[i].normal ? flat[i].normal : flat_normal();
            if (blocks)
                normal->block_normals.push_back(entry);
            else
                normal->normal_map.push_back({values[i], entry});
        }
        result.normal = normal;
    }
    return result;
}

std::vector<double> layer_visibility(const std::vector<TextureSample>& averages) {
    std::vector<double> weights(averages.size(), 0.0);
    double through = 1.0;  // the share of the view reaching this layer
    for (std::size_t k = averages.size(); k-- > 0;) {
        const double transparency = std::clamp(double(averages[k].filter + averages[k].transmit), 0.0, 1.0);
        weights[k] = through * (1.0 - transparency);
        through *= transparency;
    }
    weights[0] += through;  // what shows through every layer is lit as the bottom one
    return weights;
}

sg::Finish blend_finishes(const std::vector<sg::Finish>& finishes, const std::vector<double>& weights) {
    double total = 0.0;
    for (double w : weights) total += w;
    if (!(total > 0.0)) return finishes.front();
    sg::Finish blended = finishes.front();
    auto mix = [&](auto member) {
        auto sum = finishes.front().*member * 0.0;
        for (std::size_t k = 0; k < finishes.size(); ++k) sum += finishes[k].*member * (weights[k] / total);
        blended.*member = sum;
    };
    mix(&sg::Finish::ambient);
    mix(&sg::Finish::emission);
    mix(&sg::Finish::diffuse);
    mix(&sg::Finish::brilliance);
    mix(&sg::Finish::specular);
    mix(&sg::Finish::roughness);
    mix(&sg::Finish::phong);
    mix(&sg::Finish::phong_size);
    mix(&sg::Finish::metallic);
    auto mix_reflection = [&](auto member) {
        auto sum = finishes.front().reflection.*member * 0.0;
        for (std::size_t k = 0; k < finishes.size(); ++k) sum += finishes[k].reflection.*member * (weights[k] / total);
        blended.reflection.*member = sum;
    };
    mix_reflection(&sg::Reflection::min);
    mix_reflection(&sg::Reflection::max);
    return blended;
}

std::unique_ptr<Texture> make_layered_texture(std::vector<std::unique_ptr<Texture>> layers) {
    return std::make_unique<LayeredTexture>(std::move(layers));
}

}  // namespace lancer
