#include "materials/material_entries.h"

#include <algorithm>

#include "materials/blend_map.h"
#include "materials/point_pigment.h"

namespace lancer {

MaterialEntries::MaterialEntries(CompiledPattern pattern, Pick pick, std::vector<float> values,
                                 std::vector<const Material*> materials, const TextureSpaces& spaces, bool uv_mapping)
    : m_pattern(std::move(pattern)),
      m_pick(pick),
      m_values(std::move(values)),
      m_materials(std::move(materials)),
      m_spaces(spaces),
      m_uv_mapping(uv_mapping) {
    for (const Material* material : m_materials)
        m_nested.push_back(dynamic_cast<const MaterialEntries*>(material->entries()));
}

int MaterialEntries::parts(const Hit& hit, Part* out) const {
    Parts parts{out};
    gather(surface_point(hit, m_spaces, m_uv_mapping), surface_context(hit), 1.0f, parts);
    std::sort(out, out + parts.count, [](const Part& a, const Part& b) { return a.weight > b.weight; });
    // Shares lost to the lightest giving way (or to rounding) go to the rest.
    float total = 0.0f;
    for (int i = 0; i < parts.count; ++i) total += out[i].weight;
    if (total > 0.0f && total != 1.0f)
        for (int i = 0; i < parts.count; ++i) out[i].weight /= total;
    if (parts.count == 0) out[parts.count++] = Part{m_materials.front(), 1.0f};
    return parts.count;
}

bool MaterialEntries::every_entry_blocks_light() const {
    for (std::size_t i = 0; i < m_materials.size(); ++i) {
        const bool blocks =
            m_nested[i] ? m_nested[i]->every_entry_blocks_light() : m_materials[i]->parameters().blocks_light;
        if (!blocks) return false;
    }
    return true;
}

void MaterialEntries::gather(const glm::dvec3& point, const PatternContext& context, float weight, Parts& parts) const {
    const glm::dvec3 inner = m_pattern.pattern_point(point);
    switch (m_pick) {
    case Pick::Blocks:
        add(std::size_t(block_in_list(m_pattern.block_index(point), m_materials.size())), inner, context, weight,
            parts);
        return;
    case Pick::Average:
        for (std::size_t i = 0; i < m_materials.size(); ++i) add(i, inner, context, weight * m_values[i], parts);
        return;
    case Pick::Map: break;
    }
    const BlendPair pair = search_blend_map(m_values, m_pattern.value_at_pattern_point(inner, context));
    if (pair.previous == pair.current) {
        add(pair.current, inner, context, weight, parts);
        return;
    }
    add(pair.previous, inner, context, weight * (1.0f - pair.fraction), parts);
    add(pair.current, inner, context, weight * pair.fraction, parts);
}

void MaterialEntries::add(std::size_t entry, const glm::dvec3& inner_point, const PatternContext& context, float weight,
                          Parts& parts) const {
    if (!(weight > 0.0f)) return;
    if (const MaterialEntries* nested = m_nested[entry]) {
        nested->gather(inner_point, context, weight, parts);
        return;
    }
    const Material* material = m_materials[entry];
    for (int i = 0; i < parts.count; ++i)
        if (parts.part[i].material == material) {
            parts.part[i].weight += weight;
            return;
        }
    if (parts.count < kMostParts) {
        parts.part[parts.count++] = Part{material, weight};
        return;
    }
    // More entries at once than a mix holds: the lightest gives way.
    Part* lightest = std::min_element(parts.part, parts.part + parts.count,
                                      [](const Part& a, const Part& b) { return a.weight < b.weight; });
    if (lightest->weight < weight) *lightest = Part{material, weight};
}

}  // namespace lancer
