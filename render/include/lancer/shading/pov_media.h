// POV-Ray's media along one ray segment, as the classic integrators (whitted,
// gather) see them: POV 3.7's sampling (media.cpp, method 3 by default)
// of emission, extinction and light scattered from the scene's lights,
// with POV's unnormalised phase weights (lancer/medium.h).
//
// Which media a segment crosses (POV's rule: an interior's media show only
// inside a `hollow` object; the atmosphere fills the open and hollow
// objects): media_along(). A scene without media never gets here
// (RenderScene::has_media()).
#pragma once

#include <array>

#include "lancer/interior_stack.h"
#include "lancer/medium.h"
#include "lancer/render_scene.h"
#include "lancer/sampler.h"

namespace lancer {

// The interiors' media of a stretch, in the order the ray entered them
// (POV's list of interiors), which POV-Ray samples as one: the coefficients
// summed at each sample, placed by the settings of the first medium with
// the most intervals.
struct InteriorMedia {
    std::array<MediumRegion, InteriorStack::kDepth> regions{};
    int count = 0;
    void add(const MediumRegion& region) {
        if (count < InteriorStack::kDepth) regions[std::size_t(count++)] = region;
    }
    explicit operator bool() const { return count > 0; }
};

// The media of a stretch of ray that runs inside the objects `inside` lists
// (POV's list of interiors, lancer/interior_stack.h): the media of each
// (when all of them are hollow, as POV shows them), and the atmosphere
// then too (none: the open air).
struct SegmentMedia {
    InteriorMedia interiors;
    MediumRegion open;
    bool in_open = false;  // outside every solid object: the atmosphere and fog apply
    bool empty() const { return !interiors && !open; }
};
SegmentMedia media_along(const RenderScene& scene, const InteriorStack& inside);
// The interiors' media alone (none when one of the objects is solid).
InteriorMedia interior_media(const InteriorStack& inside);
// For a ray whose list nobody kept (path's shadow rays through media): the
// stretch that ends on a back face ran inside that object, one that ends
// on a front face or escapes ran in the open.
SegmentMedia media_before_judged_by_face(const RenderScene& scene, const Ray& ray, const Hit* hit);

// POV's distance for a ray that escapes (its BOUND_HUGE).
inline constexpr float kMediaEscapeDistance = 2.0e10f;

// How a medium's samples are lit: as POV-Ray lights them, each light behind
// a shadow ray and the samples jittered by `jitter` (whitted, gather,
// shadow), or, for raycast, each light unoccluded and the samples at POV's
// fixed fractions (raycast draws no random numbers).
struct MediaLighting {
    Sampler* jitter = nullptr;  // null: POV's sample positions without jitter
    bool shadows = true;
};

// POV's media on the segment from `origin` along unit `direction` over
// `length`: `behind` (the radiance arriving from the far end) attenuated,
// plus what the medium emits and scatters towards the origin. Light
// reaching a sample is each light of the simple model (as whitted's
// surfaces see them), behind a shadow ray (transmittance_to) unless
// `lighting` says otherwise.
// `inside`: the objects the segment runs in, which its samples' shadow
// rays start in (POV's light rays copy their ray's list); null: shadow
// rays judge interiors by the faces they leave through.
Color pov_media_radiance(const RenderScene& scene, const MediumRegion* regions, int count, const Vec3& origin,
                         const Vec3& direction, float length, const Color& behind, const MediaLighting& lighting,
                         const InteriorStack* inside = nullptr);
inline Color pov_media_radiance(const RenderScene& scene, const MediumRegion& region, const Vec3& origin,
                                const Vec3& direction, float length, const Color& behind, const MediaLighting& lighting,
                                const InteriorStack* inside = nullptr) {
    return pov_media_radiance(scene, &region, region ? 1 : 0, origin, direction, length, behind, lighting, inside);
}
// The optical depth of the segment (extinction integrated), per channel,
// as POV estimates it for a shadow ray: the media sampled as one.
Color pov_media_optical_depth(const MediumRegion* regions, int count, const Vec3& origin, const Vec3& direction,
                              float length);
inline Color pov_media_optical_depth(const MediumRegion& region, const Vec3& origin, const Vec3& direction,
                                     float length) {
    return pov_media_optical_depth(&region, region ? 1 : 0, origin, direction, length);
}

// What an integrator calls with the radiance it found along `ray` (hit null:
// the background): the radiance after the segment's media. Free when the
// scene has none. `inside` lists the objects the ray runs in; a camera ray's
// are RenderScene::camera_interiors().
// Rainbows (lancer/rainbow.h) come first, fog (lancer/fog.h) last, nearest
// the eye, as in POV.
inline Color seen_through_media(const RenderScene& scene, const Ray& ray, const Hit* hit, const Color& radiance,
                                const MediaLighting& lighting, const InteriorStack& inside) {
    const SceneFog* fog = scene.fog();
    const SceneRainbows* rainbows = scene.rainbows();
    if (!scene.has_media() && fog == nullptr && rainbows == nullptr) return radiance;
    const SegmentMedia media = media_along(scene, inside);
    if (media.empty() && !((fog || rainbows) && media.in_open)) return radiance;
    const float scale = glm::length(ray.direction);
    const Vec3 direction = ray.direction / scale;
    const float length = hit ? hit->t * scale : kMediaEscapeDistance;
    Color seen = radiance;
    if (rainbows && media.in_open) seen = rainbows->seen_through(direction, length, seen);
    if (media.interiors)
        seen = pov_media_radiance(scene, media.interiors.regions.data(), media.interiors.count, ray.origin, direction,
                                  length, seen, lighting, &inside);
    if (media.open)
        seen = pov_media_radiance(scene, media.open, ray.origin, direction, length, seen, lighting, &inside);
    if (fog && media.in_open) seen = fog->seen_through(ray.origin, direction, length, seen);
    return seen;
}

}  // namespace lancer
