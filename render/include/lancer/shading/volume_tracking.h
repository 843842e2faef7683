// Unbiased tracking of participating media for `path` (docs/integrators.md):
// free-flight sampling with null collisions against a majorant (exact
// free-flight sampling when the medium is homogeneous and grey, delta
// tracking when its density varies), ratio tracking for the transmittance
// of shadow connections, which pass through index-matched transparent
// surfaces (ior 1, no mirror) as the camera's rays do.
//
// Units are physical: the phase functions are normalised (lancer/medium.h),
// emission is radiance per unit length.
#pragma once

#include "lancer/shading/pov_media.h"

namespace lancer {

// What tracking one segment found.
struct MediumInteraction {
    bool scattered = false;          // true: a real scattering at `point`, the segment ends there
    Vec3 point{0.0f};                // the scattering point
    const Medium* medium = nullptr;  // whose phase function scatters
    Color weight{1.0f};              // multiplies the path throughput (scattering or reaching the surface)
    Color emitted{0.0f};             // radiance the media emitted towards the origin, before `weight`
};

// Tracks the segment from `origin` along unit `direction` over `length`
// through `media`. Unbiased: E[emitted + weight * L(next)] is the radiance
// arriving at the origin.
MediumInteraction track_segment(const SegmentMedia& media, const Vec3& origin, const Vec3& direction, float length,
                                Sampler& sampler);

// Unbiased estimate of the transmittance through `media` on the segment.
Color segment_transmittance(const SegmentMedia& media, const Vec3& origin, const Vec3& direction, float length,
                            Sampler& sampler);

// Whether a surface lets a straight ray through unbent, and by how much
// (ior 1 transparent surfaces without mirror): black for any other surface.
Color pass_through_weight(const Hit& hit);

// Transmittance of a shadow connection along `ray` (as Hit::spawn_ray_to
// makes it: t_max short of the target) in a scene with media: surfaces
// on the way pass light only when they pass it straight through
// (pass_through_weight); each stretch is dimmed by the media it runs in.
// `own_light`'s surfaces are not blockers.
Color shadow_transmittance(const RenderScene& scene, const Ray& ray, const Light* own_light, Sampler& sampler);

}  // namespace lancer
