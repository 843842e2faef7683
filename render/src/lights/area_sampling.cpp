// What the area lights and emitters share: a light sample from a point on
// a surface, area-to-solid-angle densities, and sampling the cone a sphere
// subtends.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "lights/lights.h"

namespace lancer {
namespace {

// Orthonormal basis with w as its third axis.
void basis_about(const DVec3& w, DVec3& a, DVec3& b) {
    const double sign = std::copysign(1.0, w.z);
    const double k = -1.0 / (sign + w.z);
    const double m = w.x * w.y * k;
    a = DVec3(1.0 + sign * w.x * w.x * k, sign * m, -sign * w.x);
    b = DVec3(m, sign + w.y * w.y * k, -w.y);
}

}  // namespace

LightSample area_light_sample(const DVec3& p, const DVec3& surface_point, const DVec3& normal, const Color& radiance,
                              float pdf) {
    LightSample s;
    const DVec3 point = lift_towards(surface_point, normal, p);
    const DVec3 offset = point - p;
    const double distance = glm::length(offset);
    if (!(distance > 0.0) || !(pdf > 0.0f)) return s;
    s.radiance = radiance;
    s.wi = Vec3(offset / distance);
    s.distance = float(distance);
    s.point = Vec3(point);
    s.pdf = pdf;
    return s;
}

float area_to_solid_angle(double pdf_area, const DVec3& p, const DVec3& point, const DVec3& light_normal) {
    const DVec3 offset = point - p;
    const double d2 = glm::dot(offset, offset);
    if (!(d2 > 0.0)) return 0.0f;
    const double cos_light = std::fabs(glm::dot(light_normal, offset)) / std::sqrt(d2);
    if (!(cos_light > 0.0)) return 0.0f;
    const double pdf = pdf_area * d2 / cos_light;
    return std::isfinite(pdf) ? float(pdf) : 0.0f;
}

DVec3 lift_towards(const DVec3& point, const DVec3& normal, const DVec3& p) {
    const double magnitude = std::max({std::fabs(point.x), std::fabs(point.y), std::fabs(point.z)});
    const double lift = 4.0 * double(FLT_EPSILON) * magnitude;
    return glm::dot(normal, p - point) >= 0.0 ? point + lift * normal : point - lift * normal;
}

// True if p, at squared distance d2 from the centre, is clearly outside the
// sphere. A point on the surface itself (a hit on an emissive sphere, whose
// float position may round to just outside) must take the area branch: the
// cone seen from there degenerates to the point's own neighbourhood, losing
// most samples (the furnace test read 0.94 instead of 1). Area sampling is
// valid from anywhere, and sample() and pdf() share this predicate, so the
// margin costs nothing in bias.
static bool outside_sphere(double d2, double radius) {
    return d2 > radius * radius * (1.0 + 1e-4);
}

bool sample_sphere_cone(const DVec3& center, double radius, const DVec3& p, const Vec2& u, ConeSample& out) {
    const DVec3 to_center = center - p;
    const double d2 = glm::dot(to_center, to_center);
    if (!outside_sphere(d2, radius)) return false;
    const double sin2_max = radius * radius / d2;
    const double sin_max = std::sqrt(sin2_max);
    const double cos_max = std::sqrt(std::max(0.0, 1.0 - sin2_max));
    double one_minus_cos_max = 1.0 - cos_max;
    // Cosine of the sampled direction from the cone axis, uniform in solid
    // angle; for tiny cones 1 - cos_max is taken from its series.
    double cos_theta = 1.0 - double(u.x) * one_minus_cos_max;
    double sin2_theta = 1.0 - cos_theta * cos_theta;
    if (sin2_max < 1e-4) {
        one_minus_cos_max = 0.5 * sin2_max * (1.0 + 0.25 * sin2_max);
        sin2_theta = sin2_max * double(u.x);
        cos_theta = std::sqrt(1.0 - sin2_theta);
    }
    // Angle at the centre between -axis and the surface point seen along
    // that direction (the nearer intersection).
    const double cos_alpha = sin2_theta / sin_max + cos_theta * std::sqrt(std::max(0.0, 1.0 - sin2_theta / sin2_max));
    const double sin_alpha = std::sqrt(std::max(0.0, 1.0 - cos_alpha * cos_alpha));
    const double phi = 2.0 * kPiD * double(u.y);
    const DVec3 axis = to_center / std::sqrt(d2);
    DVec3 a, b;
    basis_about(axis, a, b);
    out.normal = -(sin_alpha * std::cos(phi) * a + sin_alpha * std::sin(phi) * b + cos_alpha * axis);
    out.point = center + radius * out.normal;
    out.pdf = 1.0 / (2.0 * kPiD * one_minus_cos_max);
    return std::isfinite(out.pdf);
}

double sphere_cone_pdf(const DVec3& center, double radius, const DVec3& p) {
    const DVec3 to_center = center - p;
    const double d2 = glm::dot(to_center, to_center);
    if (!outside_sphere(d2, radius)) return 0.0;
    const double sin2_max = radius * radius / d2;
    const double one_minus_cos_max =
        sin2_max < 1e-4 ? 0.5 * sin2_max * (1.0 + 0.25 * sin2_max) : 1.0 - std::sqrt(1.0 - sin2_max);
    return 1.0 / (2.0 * kPiD * one_minus_cos_max);
}

}  // namespace lancer
