// POV-Ray's parallel light.
#include <cmath>

#include "lights/lights.h"

namespace lancer {

DirectionalLight::DirectionalLight(const Vec3& position, const Vec3& travel, const Color& irradiance,
                                   float scene_radius)
    : m_position(position), m_scene_radius(scene_radius) {
    const float length = glm::length(travel);
    m_parameters.to_light = length > 0.0f ? -travel / length : Vec3(0.0f, 1.0f, 0.0f);
    m_parameters.irradiance = irradiance;
}

LightSample DirectionalLight::sample(const Vec3& p, const Vec2&) const {
    LightSample s;
    s.radiance = m_parameters.irradiance;
    s.wi = m_parameters.to_light;
    s.distance = kInfinity;
    // POV-Ray's shadow ray runs from p to the light's plane (its length is
    // the projection of position - p on the light's direction); a surface
    // past that plane is lit with nothing in between (the point is p).
    const glm::dvec3 to_light(m_parameters.to_light);
    const double reach = glm::dot(m_position - glm::dvec3(p), to_light);
    s.point = reach > 0.0 ? Vec3(glm::dvec3(p) + reach * to_light) : p;
    s.pdf = 1.0f;
    s.is_delta = true;
    return s;
}

Color DirectionalLight::power() const {
    return kPi * m_scene_radius * m_scene_radius * m_parameters.irradiance;
}

}  // namespace lancer
