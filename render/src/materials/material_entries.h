// POV-Ray's patterned textures lit entry by entry: a texture_map, a block
// pattern's list of textures, a material_map and an `average` of textures
// hold, at each hit, the entry the pattern picks (a block), the two around
// the pattern's value (a map), or all of them weighted (average), and POV
// lights each with its own pigment, finish and normal and blends the lit
// colours. The scene asks parts() at every hit whose material has entries
// and keeps the mix where more than one holds (lancer/hit.h); the
// integrators light each (lancer/shading/material_blend.h). Internal to
// liblancer.
#pragma once

#include <vector>

#include "lancer/hit.h"
#include "lancer/material.h"
#include "materials/pattern.h"
#include "materials/textures.h"

namespace lancer {

class MaterialEntries final : public MaterialMix {
  public:
    enum class Pick {
        Map,      // the two entries around the pattern's value
        Blocks,   // the block's entry
        Average,  // every entry, by its weight
    };
    // `values`: a map's entry values, or an average's weights (summing to
    // 1); empty for blocks. `materials`: one per entry, in the written
    // order, each with its pigment and normal already read at this
    // pattern's point (as POV evaluates a map's entries after the map's own
    // transforms and warps). An entry that is itself patterned has entries
    // of its own, read at this pattern's point in turn.
    MaterialEntries(CompiledPattern pattern, Pick pick, std::vector<float> values,
                    std::vector<const Material*> materials, const TextureSpaces& spaces, bool uv_mapping);

    int parts(const Hit& hit, Part* out) const override;
    // Whether every entry blocks light (MaterialParameters::blocks_light),
    // whichever the pattern picks.
    bool every_entry_blocks_light() const;

  private:
    struct Parts {
        Part* part;
        int count = 0;
    };
    // The entries at `point` (in the space this pattern reads) with their
    // share of `weight`, added to `parts`.
    void gather(const glm::dvec3& point, const PatternContext& context, float weight, Parts& parts) const;
    void add(std::size_t entry, const glm::dvec3& inner_point, const PatternContext& context, float weight,
             Parts& parts) const;

    CompiledPattern m_pattern;
    Pick m_pick;
    std::vector<float> m_values;
    std::vector<const Material*> m_materials;
    std::vector<const MaterialEntries*> m_nested;  // per entry: its own entries, if patterned
    const TextureSpaces& m_spaces;
    bool m_uv_mapping;
};

}  // namespace lancer
