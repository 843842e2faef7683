// Infinite planes.
#include "geometry/shapes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace lancer {
namespace {

// Orthonormal tangents of a unit normal: for +y they are +x and +z, which
// makes a y-plane's (u,v) its (x,z).
void tangent_frame(const DVec3& n, DVec3& t1, DVec3& t2) {
    DVec3 reference = std::fabs(n.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 0.0, 1.0);
    t2 = glm::normalize(glm::cross(reference, n));
    t1 = glm::cross(n, t2);
    if (std::fabs(n.x) >= 0.9) std::swap(t1, t2);
}

}  // namespace

bool intersect_plane(const AnalyticPlane& p, const DVec3& o, const DVec3& d, double t_min, double t_max, double& t) {
    return cross_plane(p.normal, p.distance, o, d, t_min, t_max, t);
}

AnalyticPlane::AnalyticPlane(const DVec3& unit_normal, double plane_distance)
    : normal(unit_normal), distance(plane_distance) {
    tangent_frame(normal, tangent1, tangent2);
}

SurfaceGeometry plane_surface(const AnalyticPlane& plane, const DVec3& p) {
    SurfaceGeometry g;
    g.normal = plane.normal;
    g.point = p - (glm::dot(plane.normal, p) - plane.distance) * plane.normal;
    g.uv = Vec2(float(glm::dot(g.point, plane.tangent1)), float(glm::dot(g.point, plane.tangent2)));
    return g;
}

}  // namespace lancer
