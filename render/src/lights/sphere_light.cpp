// Sphere area lights: physically present emitters, sampled by the cone
// they subtend.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "lights/lights.h"

namespace lancer {

SphereLight::SphereLight(const DVec3& center, double radius, const Color& color) : m_center(center), m_radius(radius) {
    // Intensity Le * pi R^2 = pi * C in every direction.
    m_radiance = Color(glm::dvec3(color) / (radius * radius));
    m_proxy = std::make_unique<PointLight>(PointLightParameters{.position = Vec3(center), .intensity = kPi * color});
    m_parameters = {Vec3(center), float(radius), m_radiance};
}

LightSample SphereLight::sample(const Vec3& p, const Vec2& u) const {
    const DVec3 origin(p);
    ConeSample cone;
    if (sample_sphere_cone(m_center, m_radius, origin, u, cone))
        return area_light_sample(origin, cone.point, cone.normal, m_radiance, float(cone.pdf));
    // Inside (or on) the sphere: uniform over its area.
    const double z = 1.0 - 2.0 * double(u.x);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = 2.0 * kPiD * double(u.y);
    const DVec3 normal(r * std::cos(phi), z, r * std::sin(phi));
    const DVec3 point = m_center + m_radius * normal;
    const double pdf_area = 1.0 / (4.0 * kPiD * m_radius * m_radius);
    return area_light_sample(origin, point, normal, m_radiance, area_to_solid_angle(pdf_area, origin, point, normal));
}

float SphereLight::pdf(const Vec3& p, const Vec3&, const Hit& light_hit) const {
    const DVec3 origin(p);
    const double cone = sphere_cone_pdf(m_center, m_radius, origin);
    if (cone > 0.0) return float(cone);
    const double pdf_area = 1.0 / (4.0 * kPiD * m_radius * m_radius);
    return area_to_solid_angle(pdf_area, origin, DVec3(light_hit.position), DVec3(light_hit.geometric_normal));
}

Color SphereLight::power() const {
    // Outward radiance over the closed surface: pi * area * Le.
    return float(4.0 * kPiD * kPiD * m_radius * m_radius) * m_radiance;
}

}  // namespace lancer
