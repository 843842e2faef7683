// Rectangle area lights: physically present one-sided emitters.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "lights/lights.h"

namespace lancer {
namespace {}  // namespace

RectangleLight::RectangleLight(const AnalyticRectangle& rectangle, const Color& color) : m_rectangle(rectangle) {
    const DVec3 cross = glm::cross(rectangle.axis1, rectangle.axis2);
    m_area = glm::length(cross);
    m_normal = cross / m_area;
    // On-axis intensity Le * area equals a point light's pi * C.
    m_radiance = Color(kPiD * glm::dvec3(color) / m_area);
    m_proxy = std::make_unique<PointLight>(PointLightParameters{.position = Vec3(rectangle.center),
                                                                .intensity = kPi * color,
                                                                .pattern_axis = Vec3(m_normal),
                                                                .one_sided = true});
    m_parameters = {Vec3(rectangle.center), Vec3(rectangle.axis1), Vec3(rectangle.axis2), m_radiance};
}

LightSample RectangleLight::sample(const Vec3& p, const Vec2& u) const {
    const DVec3 point =
        m_rectangle.center + (double(u.x) - 0.5) * m_rectangle.axis1 + (double(u.y) - 0.5) * m_rectangle.axis2;
    const DVec3 origin(p);
    // Behind the emitting side nothing arrives: no sample, and pdf() agrees.
    if (!emits_towards(origin - point)) return LightSample{};
    return area_light_sample(origin, point, m_normal, m_radiance,
                             area_to_solid_angle(1.0 / m_area, origin, point, m_normal));
}

float RectangleLight::pdf(const Vec3& p, const Vec3&, const Hit& light_hit) const {
    const DVec3 point(light_hit.position);
    if (!emits_towards(DVec3(p) - point)) return 0.0f;
    return area_to_solid_angle(1.0 / m_area, DVec3(p), point, m_normal);
}

Color RectangleLight::emitted(const Hit&, const Vec3& wo) const {
    return emits_towards(glm::dvec3(wo)) ? m_radiance : Color(0.0f);
}

Color RectangleLight::power() const {
    return float(kPiD * m_area) * m_radiance;
}

}  // namespace lancer
