// POV-Ray's projected_through (Trace::TracePointLightShadowRay): light
// passes only where its ray meets the projector object.
#include <algorithm>
#include <cmath>

#include "lights/lights.h"

namespace lancer {

ProjectedLight::ProjectedLight(std::unique_ptr<Light> light, std::unique_ptr<RenderScene> projector)
    : m_light(std::move(light)), m_projector(std::move(projector)) {
    set_casts_shadows(m_light->casts_shadows());
}

ProjectedLight::~ProjectedLight() = default;

LightSample ProjectedLight::sample(const Vec3& p, const Vec2& u) const {
    LightSample s = m_light->sample(p, u);
    if (!(s.pdf > 0.0f)) return s;
    const Vec3 to_point = s.point - p;
    const float length = glm::length(to_point);
    Ray ray;
    ray.origin = p;
    // POV's MIN_ISECT_DEPTH: a point on the projector itself does not meet
    // it where it stands, so its side towards the light is lit only where
    // the light passes through it elsewhere.
    ray.t_min = 1e-4f;
    if (length > 0.0f && std::isfinite(length)) {
        ray.direction = to_point / length;
        ray.t_max = length;
    } else {
        ray.direction = s.wi;  // a point past the light's plane: towards the light
    }
    Hit through;
    if (!m_projector->intersect(ray, through)) {
        s.radiance = Color(0.0f);
        return s;
    }
    // Only what lies between the point and the projector can shadow it:
    // the projector itself, which is in the scene too, does not (POV tests
    // shadows up to SMALL_TOLERANCE short of where the ray meets it).
    constexpr float kSmallTolerance = 0.001f;
    const float before = std::max(through.t - kSmallTolerance, 0.0f);
    s.point = p + ray.direction * before;
    s.distance = before;
    return s;
}

}  // namespace lancer
