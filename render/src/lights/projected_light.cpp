// POV-Ray's projected_through (Trace::TracePointLightShadowRay): light
// passes only where its ray meets the projector object.
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
    if (length > 0.0f && std::isfinite(length)) {
        ray.direction = to_point / length;
        ray.t_max = length;
    } else {
        ray.direction = s.wi;  // a point past the light's plane: towards the light
    }
    if (!m_projector->occluded(ray)) s.radiance = Color(0.0f);
    return s;
}

}  // namespace lancer
