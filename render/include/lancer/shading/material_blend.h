// The hits of POV-Ray's patterned and layered textures.
//
// POV-Ray's patterned textures where more than one entry holds (lancer/hit.h:
// between two texture_map entries, an average): the surface is lit once
// with each entry's material and the lit colours are blended, as POV-Ray
// blends them. An integrator that shades a hit by a function of the hit
// alone wraps it in shade_blended(); one that samples (path) takes one
// entry with its share's probability, which has the same mean.
#pragma once

#include <algorithm>
#include <cmath>

#include "lancer/hit.h"
#include "lancer/material.h"

namespace lancer {

// A normal bent by `material`'s normal { } from `unbent`: turned towards
// the ray first (a bump seen from behind stays a bump), then back to the
// side it was on. The one rule the scene and the layers bend normals by.
inline Vec3 bent_normal(const Hit& hit, const Material* material, const Vec3& unbent, const Vec3& ray_direction) {
    const NormalPerturbation* normal = material ? material->normal_perturbation() : nullptr;
    if (normal == nullptr) return unbent;
    const bool behind = glm::dot(hit.geometric_normal, ray_direction) > 0.0f;
    const Vec3 bent = normal->perturb(hit, behind ? -unbent : unbent);
    return behind ? -bent : bent;
}

// The shading normal before any normal { } bent it.
inline Vec3 unbent_normal(const Hit& hit) {
    return hit.unbumped_normal != Vec3(0.0f) ? hit.unbumped_normal : hit.shading_normal;
}

// The hit as one entry of its mix (or one layer of a layered texture)
// sees it: that material, with its own bumps.
inline Hit entry_hit(const Hit& hit, const Material* material) {
    Hit entry = hit;
    entry.mix = nullptr;
    if (material == hit.material) return entry;
    entry.material = material;
    entry.shading_normal = bent_normal(hit, material, unbent_normal(hit), hit.ray_direction);
    return entry;
}

// The entries of a hit's mix and their shares, heaviest first.
inline int mix_parts(const Hit& hit, MaterialMix::Part* parts) {
    Hit unbent = hit;
    unbent.shading_normal = unbent_normal(hit);
    return hit.mix->parts(unbent, parts);
}

// shade(hit) for a hit of one material; for a mix, the sum of each
// entry's shade weighted by its share.
template <class Shade>
auto shade_blended(const Hit& hit, const Shade& shade) -> decltype(shade(hit)) {
    if (hit.mix == nullptr) return shade(hit);
    MaterialMix::Part parts[MaterialMix::kMostParts];
    const int count = mix_parts(hit, parts);
    auto sum = parts[0].weight * shade(entry_hit(hit, parts[0].material));
    for (int i = 1; i < count; ++i) sum += parts[i].weight * shade(entry_hit(hit, parts[i].material));
    return sum;
}

// The entry a sampling integrator shades, chosen by u in [0, 1) with its
// share's probability; u is then rescaled to a fresh uniform number in
// [0, 1) (it can serve the next choice: the sampler's dimensions stay as
// they were).
inline Hit chosen_entry(const Hit& hit, float& u) {
    if (hit.mix == nullptr) return hit;
    MaterialMix::Part parts[MaterialMix::kMostParts];
    const int count = mix_parts(hit, parts);
    constexpr float kBelowOne = 0x1.fffffep-1f;
    float start = 0.0f;
    for (int i = 0; i < count; ++i) {
        const float share = parts[i].weight;
        if (u < start + share || i + 1 == count) {
            u = share > 0.0f ? std::clamp((u - start) / share, 0.0f, kBelowOne) : 0.0f;
            return entry_hit(hit, parts[i].material);
        }
        start += share;
    }
    return entry_hit(hit, parts[0].material);
}

// A layered texture (lancer/shading/material_layers.h lights it): each
// layer sees the hit as entry_hit(hit, layer) does.

// Whether the light passing the layers so far still counts (POV's trans).
inline bool layers_pass_enough(const Color& passed, float bailout) {
    return std::min(1.0f, std::fabs(pov_grey(passed))) > bailout;
}

// A hit's layers are lit one by one unless it has none or is a light's
// surface (whose emission is the light's, counted once).
inline const MaterialLayers* layers_to_light(const Hit& hit) {
    return hit.emitter == nullptr ? hit.material->layers() : nullptr;
}

}  // namespace lancer
