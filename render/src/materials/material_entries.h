// POV-Ray's patterned textures lit entry by entry: a texture_map, a block
// pattern's list of textures and a material_map pick, at each hit, the
// entry that holds there (or, in a map, the two around the pattern's
// value), and POV lights each with its own pigment, finish and normal and
// blends the lit colours. The scene calls select() on every hit whose
// material has entries; the hit then carries the entries' materials and
// the blend (lancer/hit.h), and the integrators light each
// (lancer/shading/material_blend.h). Internal to liblancer.
#pragma once

#include <vector>

#include "lancer/hit.h"
#include "materials/pattern.h"
#include "materials/textures.h"

namespace lancer {

class MaterialEntries {
  public:
    // `values`: a map's entry values (empty for a block list); `materials`:
    // one per entry, in the written order, each with its pigment and normal
    // already read at this pattern's point (as POV evaluates a map's
    // entries after the map's own transforms and warps). An entry that is
    // itself a texture_map has entries of its own, read at this pattern's
    // point in turn.
    MaterialEntries(CompiledPattern pattern, std::vector<float> values, std::vector<const Material*> materials,
                    const TextureSpaces& spaces, bool uv_mapping);

    // Replaces hit.material by the entry that holds at the hit; between two
    // entries of a map, by the heavier one, with the other as the hit's
    // blend_material. Where nested maps blend more than two entries, the
    // two heaviest are kept, their weights rescaled to sum to 1.
    void select(Hit& hit) const;

  private:
    struct Pick {
        const Material* material = nullptr;
        float weight = 0.0f;
    };
    static constexpr int kMostPicks = 8;
    struct Picks {
        Pick pick[kMostPicks];
        int count = 0;
    };
    // The entries at `point` (in the space this pattern reads) with their
    // share of `weight`, added to `picks`.
    void gather(const glm::dvec3& point, const PatternContext& context, float weight, Picks& picks) const;
    void add(const Material* material, const glm::dvec3& inner_point, const PatternContext& context, float weight,
             Picks& picks) const;

    CompiledPattern m_pattern;
    std::vector<float> m_values;
    std::vector<const Material*> m_materials;
    const TextureSpaces& m_spaces;
    bool m_uv_mapping;
};

}  // namespace lancer
