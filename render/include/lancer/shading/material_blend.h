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

// The hit as the entry it is mostly (first) or the other entry (second).
inline Hit first_entry(const Hit& hit) {
    Hit entry = hit;
    entry.blend_material = nullptr;
    entry.blend_weight = 0.0f;
    return entry;
}
inline Hit second_entry(const Hit& hit) {
    Hit entry = first_entry(hit);
    entry.material = hit.blend_material;
    entry.shading_normal = hit.blend_shading_normal;
    return entry;
}

// shade(hit) for a hit of one material; the weighted sum of both for a hit
// between two entries.
template <class Shade>
auto shade_blended(const Hit& hit, const Shade& shade) -> decltype(shade(hit)) {
    if (hit.blend_material == nullptr) return shade(hit);
    return (1.0f - hit.blend_weight) * shade(first_entry(hit)) + hit.blend_weight * shade(second_entry(hit));
}

// The entry a sampling integrator shades, chosen by u in [0, 1).
inline Hit chosen_entry(const Hit& hit, float u) {
    if (hit.blend_material == nullptr) return hit;
    return u < hit.blend_weight ? second_entry(hit) : first_entry(hit);
}

// A layered texture (lancer/shading/material_layers.h lights it): each
// layer sees the hit with its own material and normal.
// Whether the light passing the layers so far still counts (POV's trans).
inline bool layers_pass_enough(const Color& passed, float bailout) {
    return std::min(1.0f, std::fabs(pov_grey(passed))) > bailout;
}

// The hit as one layer sees it: its material, its normal bent by its own
// normal { } (from the surface's unbent normal, turned towards the ray as
// the scene bends normals).
inline Hit layer_hit(const Hit& hit, const Material& layer, const Vec3& ray_direction) {
    Hit seen = hit;
    seen.material = &layer;
    seen.blend_material = nullptr;
    seen.blend_weight = 0.0f;
    const bool bent_before = seen.unbumped_normal != Vec3(0.0f);
    const Vec3 unbent = bent_before ? seen.unbumped_normal : seen.shading_normal;
    seen.shading_normal = unbent;
    if (const NormalPerturbation* normal = layer.normal_perturbation()) {
        const bool behind = glm::dot(hit.geometric_normal, ray_direction) > 0.0f;
        const Vec3 bent = normal->perturb(seen, behind ? -unbent : unbent);
        seen.shading_normal = behind ? -bent : bent;
    }
    return seen;
}

// A hit's layers are lit one by one unless it has none or is a light's
// surface (whose emission is the light's, counted once).
inline const MaterialLayers* layers_to_light(const Hit& hit) {
    return hit.emitter == nullptr ? hit.material->layers() : nullptr;
}

}  // namespace lancer
