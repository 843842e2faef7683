// One camera ray shaded on its own, for tools and tests that look at
// single rays: its nearest hit, then the integrator's shade_camera_hit().
// The host itself always shades batches (Integrator::shade_camera_hits).
#pragma once

#include "lancer/integrator.h"

namespace lancer {

inline Color shade_camera_ray(const Integrator& integrator, const Ray& ray, const RenderScene& scene,
                              Sampler& sampler) {
    Hit hit;
    const bool found = scene.intersect(ray, hit);
    return integrator.shade_camera_hit(ray, found ? &hit : nullptr, scene, sampler);
}

}  // namespace lancer
