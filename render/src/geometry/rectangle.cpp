// Parallelograms: the surfaces of rectangle area lights.
#include "geometry/shapes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace lancer {

bool intersect_rectangle(const AnalyticRectangle& r, const DVec3& o, const DVec3& d, double t_min, double t_max,
                         double& t) {
    const DVec3 normal = glm::cross(r.axis1, r.axis2);
    const double denominator = glm::dot(normal, d);
    if (denominator == 0.0) return false;
    const double candidate = glm::dot(r.center - o, normal) / denominator;
    if (!(candidate > t_min && candidate < t_max)) return false;
    const DVec3 local = o + candidate * d - r.center;
    const double s1 = glm::dot(local, r.axis1) / glm::dot(r.axis1, r.axis1);
    const double s2 = glm::dot(local, r.axis2) / glm::dot(r.axis2, r.axis2);
    if (std::fabs(s1) > 0.5 || std::fabs(s2) > 0.5) return false;
    t = candidate;
    return true;
}

SurfaceGeometry rectangle_surface(const AnalyticRectangle& r, const DVec3& p) {
    SurfaceGeometry g;
    const DVec3 normal = glm::cross(r.axis1, r.axis2);
    g.normal = glm::normalize(normal);
    g.point = p - glm::dot(p - r.center, g.normal) * g.normal;
    const DVec3 local = g.point - r.center;
    g.uv = Vec2(float(glm::dot(local, r.axis1) / glm::dot(r.axis1, r.axis1) + 0.5),
                float(glm::dot(local, r.axis2) / glm::dot(r.axis2, r.axis2) + 0.5));
    return g;
}

}  // namespace lancer
