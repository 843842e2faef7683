// POV-Ray's parallel light.
#include <cmath>

#include "lights/lights.h"

namespace lancer {

DirectionalLight::DirectionalLight(const Vec3& travel, const Color& irradiance, const Vec3& scene_center,
                                   float scene_radius)
    : m_scene_center(scene_center), m_scene_radius(scene_radius) {
    const float length = glm::length(travel);
    m_parameters.to_light = length > 0.0f ? -travel / length : Vec3(0.0f, 1.0f, 0.0f);
    m_parameters.irradiance = irradiance;
}

LightSample DirectionalLight::sample(const Vec3& p, const Vec2&) const {
    LightSample s;
    s.radiance = m_parameters.irradiance;
    s.wi = m_parameters.to_light;
    s.distance = kInfinity;
    // A target past every object: the shadow ray sees the whole scene.
    const float reach = 2.0f * m_scene_radius + glm::length(p - m_scene_center);
    s.point = p + reach * m_parameters.to_light;
    s.pdf = 1.0f;
    s.is_delta = true;
    return s;
}

Color DirectionalLight::power() const {
    return kPi * m_scene_radius * m_scene_radius * m_parameters.irradiance;
}

}  // namespace lancer
