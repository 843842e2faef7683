// POV-Ray's point light, and the proxies of area lights and emitters.
#include <algorithm>
#include <cmath>
#include <limits>

#include "lights/lights.h"

namespace lancer {

PointLight::PointLight(const PointLightParameters& parameters, float scene_radius)
    : m_parameters(parameters), m_plain(parameters.is_plain()), m_scene_radius(std::max(scene_radius, 1e-6f)) {}

double pov_fade(double distance, float fade_distance, float fade_power) {
    return fade_distance != 0.0f ? 2.0 / (1.0 + std::pow(distance / fade_distance, double(fade_power)))
                                 : std::pow(distance, -double(fade_power));
}

double smooth_step(double low, double high, double x) {
    if (x < low) return 0.0;
    if (x >= high) return 1.0;
    const double t = (x - low) / (high - low);
    return (3.0 - 2.0 * t) * t * t;
}

double spot_cone(const PointLightParameters& light, double cos_from_axis) {
    if (!(cos_from_axis > 0.0)) return 0.0;
    double cone = light.tightness > 0.0f ? std::pow(cos_from_axis, double(light.tightness)) : 1.0;
    if (light.spot_cos_radius > 0.0f && cos_from_axis < light.spot_cos_radius)
        cone *= smooth_step(light.spot_cos_falloff, light.spot_cos_radius, cos_from_axis);
    return cone;
}

LightSample PointLight::sample(const Vec3& p, const Vec2&) const {
    // Float where nothing can overflow or underflow: a squared distance
    // well inside float's range. Every shading point of an ordinary scene
    // takes this path; it is half the cost of the double one below.
    const PointLightParameters& light = m_parameters;
    const Vec3 to_light_float = light.position - p;
    const float distance_squared = glm::dot(to_light_float, to_light_float);
    if (m_plain && in_plain_point_range(distance_squared)) {
        const PointIncidence incidence = plain_point_incidence(distance_squared, light.falloff);
        LightSample s;
        s.radiance = light.intensity * incidence.falloff;
        s.wi = to_light_float * incidence.inverse_distance;
        s.distance = incidence.distance;
        s.point = light.position;
        s.pdf = 1.0f;
        s.is_delta = true;
        return s;
    }
    return sample_point_light(light, p);
}

LightSample sample_point_light(const PointLightParameters& light, const Vec3& p) {
    LightSample s;
    // Difference in double: at large offsets the float subtraction is
    // exact anyway, but the length must not overflow for huge scenes.
    const glm::dvec3 to_light = glm::dvec3(light.position) - glm::dvec3(p);
    const double distance = glm::length(to_light);
    if (!(distance > 0.0) || !std::isfinite(distance)) return s;  // pdf 0: no sample
    const glm::dvec3 wi = to_light / distance;
    double attenuation;
    if (light.fade_power > 0.0f)
        attenuation = pov_fade(distance, light.fade_distance, light.fade_power);
    else if (light.falloff == PointFalloff::InverseSquare)
        attenuation = 1.0 / (distance * distance);
    else
        attenuation = 1.0;
    if (light.spot_axis != Vec3(0.0f)) attenuation *= spot_cone(light, -glm::dot(glm::dvec3(light.spot_axis), wi));
    double pattern = 1.0;
    if (light.pattern_axis != Vec3(0.0f)) {
        const double cos_emitted = -glm::dot(glm::dvec3(light.pattern_axis), wi);  // light -> p
        pattern = light.one_sided ? std::max(0.0, cos_emitted) : std::fabs(cos_emitted);
    }
    const glm::dvec3 radiance = glm::dvec3(light.intensity) * (attenuation * pattern);
    s.radiance = Color(radiance);
    if (!std::isfinite(max_component(s.radiance))) s.radiance = Color(std::numeric_limits<float>::max());
    s.wi = Vec3(wi);
    s.distance = float(distance);
    s.point = light.position;
    s.pdf = 1.0f;
    s.is_delta = true;
    return s;
}

Color PointLight::power() const {
    // Integral of the pattern over the sphere: 4 pi isotropic, 2 pi for
    // |cos|, pi for max(0, cos).
    const PointLightParameters& light = m_parameters;
    // A light without falloff has no finite power. For choosing among
    // lights it counts what lands on the scene, as a parallel light's
    // power does (DirectionalLight::power): its radiance over the disc of
    // the scene's bounding sphere.
    if (light.falloff == PointFalloff::None && light.fade_power == 0.0f)
        return kPi * m_scene_radius * m_scene_radius * light.intensity;
    const float solid_angle = light.pattern_axis == Vec3(0.0f) ? 4.0f * kPi : light.one_sided ? kPi : 2.0f * kPi;
    return solid_angle * light.intensity;
}

}  // namespace lancer
