// POV-Ray's area_light: lit from its centre, its rectangle sampled for shadows.
#include "lancer/area_light_grid.h"
#include "lights/lights.h"

namespace lancer {

PovAreaLight::PovAreaLight(const PovAreaLightParameters& parameters, float scene_radius)
    : m_parameters(parameters), m_center(parameters.center, scene_radius) {}

LightSample PovAreaLight::sample(const Vec3& p, const Vec2& u) const {
    const PovAreaLightParameters& light = m_parameters;
    LightSample s = m_center.sample(p, u);
    if (!(s.pdf > 0.0f)) return s;
    const AreaGridAxes axes = area_grid_axes(light, glm::dvec3(s.wi));
    const glm::dvec3 point =
        glm::dvec3(light.center.position) +
        area_grid_offset(light, axes, double(u.x) * double(light.size1 - 1), double(u.y) * double(light.size2 - 1));
    if (light.area_illumination) {
        // The point lights as a point light of its own, with the centre's
        // colour, fade and cone.
        PointLightParameters lightlet = light.center;
        lightlet.position = Vec3(point);
        const LightSample own = sample_point_light(lightlet, p);
        if (own.pdf > 0.0f) return own;
        return s;
    }
    s.point = Vec3(point);
    s.distance = float(glm::length(point - glm::dvec3(p)));
    return s;
}

}  // namespace lancer
