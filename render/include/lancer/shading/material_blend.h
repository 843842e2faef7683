// POV-Ray's texture_map between two entries (lancer/hit.h): the surface is
// lit once with each entry's material and the lit colours are blended, as
// POV-Ray blends them. An integrator that shades a hit by a function of
// the hit alone wraps it in shade_blended(); one that samples (path)
// takes one entry with its weight's probability, which has the same mean.
#pragma once

#include "lancer/hit.h"

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

}  // namespace lancer
