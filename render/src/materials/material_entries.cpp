#include "materials/material_entries.h"

#include <algorithm>

#include "materials/blend_map.h"
#include "materials/point_pigment.h"

namespace lancer {

MaterialEntries::MaterialEntries(CompiledPattern pattern, std::vector<float> values,
                                 std::vector<const Material*> materials, const TextureSpaces& spaces, bool uv_mapping)
    : m_pattern(std::move(pattern)),
      m_values(std::move(values)),
      m_materials(std::move(materials)),
      m_spaces(spaces),
      m_uv_mapping(uv_mapping) {}

void MaterialEntries::select(Hit& hit) const {
    hit.blend_material = nullptr;
    hit.blend_weight = 0.0f;
    Picks picks;
    gather(surface_point(hit, m_spaces, m_uv_mapping), surface_context(hit), 1.0f, picks);
    if (picks.count == 0) return;
    std::sort(picks.pick, picks.pick + picks.count, [](const Pick& a, const Pick& b) { return a.weight > b.weight; });
    hit.material = picks.pick[0].material;
    if (picks.count == 1) return;
    const float kept = picks.pick[0].weight + picks.pick[1].weight;
    hit.blend_material = picks.pick[1].material;
    hit.blend_weight = kept > 0.0f ? picks.pick[1].weight / kept : 0.0f;
}

void MaterialEntries::gather(const glm::dvec3& point, const PatternContext& context, float weight, Picks& picks) const {
    if (m_materials.empty()) return;
    const glm::dvec3 inner = m_pattern.pattern_point(point);
    if (m_values.empty()) {
        const int block = block_in_list(m_pattern.block_index(point), m_materials.size());
        add(m_materials[std::size_t(block)], inner, context, weight, picks);
        return;
    }
    const BlendPair pair = search_blend_map(m_values, m_pattern.value_at_pattern_point(inner, context));
    if (pair.previous == pair.current) {
        add(m_materials[pair.current], inner, context, weight, picks);
        return;
    }
    add(m_materials[pair.previous], inner, context, weight * (1.0f - pair.fraction), picks);
    add(m_materials[pair.current], inner, context, weight * pair.fraction, picks);
}

void MaterialEntries::add(const Material* material, const glm::dvec3& inner_point, const PatternContext& context,
                          float weight, Picks& picks) const {
    if (!(weight > 0.0f)) return;
    if (const MaterialEntries* nested = material->entries()) {
        nested->gather(inner_point, context, weight, picks);
        return;
    }
    for (int i = 0; i < picks.count; ++i)
        if (picks.pick[i].material == material) {
            picks.pick[i].weight += weight;
            return;
        }
    if (picks.count < kMostPicks) {
        picks.pick[picks.count++] = Pick{material, weight};
        return;
    }
    // More than kMostPicks entries at once (maps nested deeper than three):
    // the lightest gives way.
    Pick* lightest = std::min_element(picks.pick, picks.pick + picks.count,
                                      [](const Pick& a, const Pick& b) { return a.weight < b.weight; });
    if (lightest->weight < weight) *lightest = Pick{material, weight};
}

}  // namespace lancer
