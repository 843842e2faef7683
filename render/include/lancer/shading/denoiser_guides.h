// What a denoiser takes beside the beauty, per camera ray, as Intel Open
// Image Denoise defines its guides: the albedo, linear in [0, 1], and the
// shading normal, unencoded in [-1, 1], both of the first surface that is
// not a perfect mirror or clear glass. A surface whose mirror or refraction
// carries more light than its diffuse lobe passes the guides on along that
// direction (tinted by its weight), so glass and mirrors show what they
// reflect or let through instead of black. Also the alpha an image's
// alpha channel holds (POV-Ray's +UA). Shared by the albedo and normal
// plugins and the host's --aov layers (lancer/host/aov.h).
#pragma once

#include <algorithm>

#include "lancer/render_scene.h"
#include "lancer/shading/specular_tracing.h"

namespace lancer {

struct DenoiserGuides {
    Color albedo{0.0f};  // in [0, 1]
    Vec3 normal{0.0f};   // unit, facing the ray that found it; 0 where the ray escaped
};

// Perfect specular surfaces followed at most this many times, as deep as a
// glass sphere in front of a mirror needs.
inline constexpr int kGuideSpecularDepth = 8;

// The camera-facing shading normal at `hit` (or the geometric one).
inline Vec3 camera_facing_normal(const Ray& ray, const Hit& hit, bool shading = true) {
    const Vec3 toward_camera = -ray.direction;
    Vec3 n = shading ? hit.facing_normal(toward_camera) : hit.geometric_normal;
    if (glm::dot(n, toward_camera) < 0.0f) n = -n;
    return n;
}

// The pigment a matte surface would scatter: pigment x diffuse x opacity,
// each channel in [0, 1].
inline Color diffuse_albedo(const ShadingContext& at) {
    const float opacity = 1.0f - at.material.transparency(at.surface);
    const float weight = std::min(at.material.parameters().diffuse, 1.0f) * opacity;
    return glm::clamp(at.surface.pigment * weight, Color(0.0f), Color(1.0f));
}

// The guides along a camera ray whose nearest hit is known (null: it
// escaped, and the albedo is the background's, clamped).
inline DenoiserGuides denoiser_guides(const Ray& camera_ray, const Hit* camera_hit, const RenderScene& scene) {
    Ray ray = camera_ray;
    Hit found;
    const Hit* hit = camera_hit;
    Color tint(1.0f);
    for (int bounce = 0;; ++bounce) {
        if (!hit) return {glm::clamp(tint * scene.background(ray), Color(0.0f), Color(1.0f)), Vec3(0.0f)};
        const ShadingContext at = make_shading_context(*hit, ray);
        const Color diffuse = diffuse_albedo(at);
        const SpecularSplit split = split_specular(at, SpecularOptions{});
        const bool mirror = max_component(split.reflection) >= max_component(split.transmission);
        const Color weight = mirror ? split.reflection : split.transmission;
        if (bounce == kGuideSpecularDepth || max_component(weight) <= max_component(diffuse))
            return {tint * diffuse, at.normal};
        tint *= glm::clamp(weight, Color(0.0f), Color(1.0f));
        ray = hit->spawn_ray(mirror ? split.reflected : split.refracted);
        hit = scene.intersect(ray, found) ? &found : nullptr;
    }
}

// The alpha of a camera ray, as POV-Ray's +UA computes it: 1 minus the
// share of the background seen through the surfaces along the ray (their
// transmit, and their filter weighted by the grey of the colour it tints
// by, the ray taken straight on) and through the background itself (its
// transmit). A ray that meets an opaque surface is 1.
inline float camera_alpha(const Ray& camera_ray, const Hit* camera_hit, const RenderScene& scene) {
    Ray ray = camera_ray;
    Hit found;
    const Hit* hit = camera_hit;
    float seen_through = 1.0f;
    for (int crossed = 0; hit && seen_through > 0.0f; ++crossed) {
        if (crossed == kGuideSpecularDepth * 4) return 1.0f;
        const SurfaceSample surface = hit->material->sample_surface(*hit);
        seen_through *= glm::clamp(surface.filter * pov_grey(surface.pigment) + surface.transmit, 0.0f, 1.0f);
        ray = hit->spawn_ray(glm::normalize(ray.direction));
        hit = scene.intersect(ray, found) ? &found : nullptr;
    }
    return 1.0f - seen_through * (hit ? 0.0f : scene.background_transparency());
}

}  // namespace lancer
