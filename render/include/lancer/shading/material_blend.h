// The hits of POV-Ray's patterned and layered textures.
//
// POV-Ray's texture_map between two entries (lancer/hit.h): the surface is
// lit once with each entry's material and the lit colours are blended, as
// POV-Ray blends them. An integrator that shades a hit by a function of
// the hit alone wraps it in shade_blended(); one that samples (path)
// takes one entry with its weight's probability, which has the same mean.
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

// The hit as the entry it is mostly (first) or the other entry (second),
// with that entry's own bumps.
inline Hit first_entry(const Hit& hit) {
    Hit entry = hit;
    entry.blend_material = nullptr;
    entry.blend_weight = 0.0f;
    return entry;
}
inline Hit second_entry(const Hit& hit) {
    Hit entry = first_entry(hit);
    entry.material = hit.blend_material;
    entry.shading_normal = bent_normal(hit, hit.blend_material, unbent_normal(hit), hit.ray_direction);
    return entry;
}

// shade(hit) for a hit of one material; the weighted sum of both for a hit
// between two entries.
template <class Shade>
auto shade_blended(const Hit& hit, const Shade& shade) -> decltype(shade(hit)) {
    if (hit.blend_material == nullptr) return shade(hit);
    return (1.0f - hit.blend_weight) * shade(first_entry(hit)) + hit.blend_weight * shade(second_entry(hit));
}

// The entry a sampling integrator shades, chosen by u in [0, 1), which is
// then rescaled to a fresh uniform number in [0, 1) (it can serve the
// next choice: the sampler's dimensions stay as they were).
inline Hit chosen_entry(const Hit& hit, float& u) {
    if (hit.blend_material == nullptr) return hit;
    const float w = hit.blend_weight;
    constexpr float kBelowOne = 0x1.fffffep-1f;
    if (u < w) {
        u = std::min(u / w, kBelowOne);
        return second_entry(hit);
    }
    u = std::min((u - w) / (1.0f - w), kBelowOne);
    return first_entry(hit);
}

// A layered texture (lancer/shading/material_layers.h lights it): each
// layer sees the hit with its own material and normal.

// Whether the light passing the layers so far still counts (POV's trans).
inline bool layers_pass_enough(const Color& passed, float bailout) {
    return std::min(1.0f, std::fabs(pov_grey(passed))) > bailout;
}

// The hit as one layer sees it: its material, its normal bent by its own
// normal { } from the surface's unbent normal.
inline Hit layer_hit(const Hit& hit, const Material& layer, const Vec3& ray_direction) {
    Hit seen = first_entry(hit);
    seen.material = &layer;
    seen.shading_normal = bent_normal(hit, &layer, unbent_normal(hit), ray_direction);
    return seen;
}

// A hit's layers are lit one by one unless it has none or is a light's
// surface (whose emission is the light's, counted once).
inline const MaterialLayers* layers_to_light(const Hit& hit) {
    return hit.emitter == nullptr ? hit.material->layers() : nullptr;
}

}  // namespace lancer
