// POV-Ray's parallel and cylinder lights.
#include <cmath>
#include <limits>

#include "lights/lights.h"

namespace lancer {

DirectionalLight::DirectionalLight(const DirectionalLightParameters& parameters, float scene_radius)
    : m_parameters(parameters), m_scene_radius(scene_radius) {
    const float length = glm::length(parameters.to_light);
    m_parameters.to_light = length > 0.0f ? parameters.to_light / length : Vec3(0.0f, 1.0f, 0.0f);
}

LightSample DirectionalLight::sample(const Vec3& p, const Vec2&) const {
    const DirectionalLightParameters& light = m_parameters;
    LightSample s;
    s.wi = light.to_light;
    s.distance = kInfinity;
    s.pdf = 1.0f;
    s.is_delta = true;
    // POV-Ray's shadow ray runs from p to the light's plane (its length is
    // the projection of position - p on the light's direction); a surface
    // past that plane is lit with nothing in between (the point is p).
    const glm::dvec3 to_light(light.to_light);
    const glm::dvec3 from_light = glm::dvec3(p) - glm::dvec3(light.position);
    const double reach = -glm::dot(from_light, to_light);
    s.point = reach > 0.0 ? Vec3(glm::dvec3(p) + reach * to_light) : p;
    double attenuation = 1.0;
    if (light.beam_falloff > 0.0f) {
        // POV's Attenuate_Light for a cylinder source.
        if (!(reach > 0.0)) return s;  // behind the light: pdf stays 1, radiance 0
        const double off_axis = glm::length(from_light + reach * to_light);
        if (!(off_axis < light.beam_falloff)) return s;
        const double inside = 1.0 - off_axis / light.beam_falloff;
        attenuation = light.tightness > 0.0f ? std::pow(inside, double(light.tightness)) : 1.0;
        if (light.beam_radius > 0.0f && off_axis > light.beam_radius)
            attenuation *= smooth_step(0.0, 1.0 - double(light.beam_radius) / light.beam_falloff, inside);
    }
    if (light.fade_power > 0.0f) {
        // POV fades by the signed distance to the plane; its magnitude
        // gives the same for the usual even powers and stays defined.
        attenuation *= pov_fade(std::fabs(reach), light.fade_distance, light.fade_power);
    }
    s.radiance = light.irradiance * float(attenuation);
    if (!std::isfinite(max_component(s.radiance))) s.radiance = Color(std::numeric_limits<float>::max());
    return s;
}

Color DirectionalLight::power() const {
    const DirectionalLightParameters& light = m_parameters;
    // A beam carries what crosses its disc.
    if (light.beam_falloff > 0.0f) return kPi * light.beam_falloff * light.beam_falloff * light.irradiance;
    return kPi * m_scene_radius * m_scene_radius * light.irradiance;
}

}  // namespace lancer
