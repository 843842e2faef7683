// Spheres: intersection and surface in double precision, and sampling by
// world area for emissive spheres under any placement.
#include "geometry/shapes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <limits>

namespace lancer {
namespace {

DMat3 linear_part(const DMat4& m) {
    return DMat3(m);
}

}  // namespace

bool intersect_sphere(const AnalyticSphere& s, const DVec3& o, const DVec3& d, double t_min, double t_max, double& t) {
    const DVec3 oc = o - s.center;
    const double a = glm::dot(d, d);
    if (!(a > 0.0)) return false;
    const double b = glm::dot(oc, d);
    // Discriminant from the closest approach of the line to the centre
    // (pbrt-v4): no cancellation when the origin is far from a small sphere.
    const DVec3 closest = oc - (b / a) * d;
    const double r2 = s.radius * s.radius;
    const double discriminant = a * (r2 - glm::dot(closest, closest));
    if (discriminant < 0.0) return false;
    const double root = std::sqrt(discriminant);
    const double q = -(b + std::copysign(root, b));
    // c is accurate exactly when the origin is near the surface, which is
    // when t1 = c / q is the small root.
    const double c = glm::dot(oc, oc) - r2;
    double t0 = q / a;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_min && t0 < t_max) {
        t = t0;
        return true;
    }
    if (t1 > t_min && t1 < t_max) {
        t = t1;
        return true;
    }
    return false;
}

SurfaceGeometry sphere_surface(const AnalyticSphere& s, const DVec3& p, bool with_uv) {
    SurfaceGeometry g;
    DVec3 offset = p - s.center;
    const double length = glm::length(offset);
    g.normal = length > 0.0 ? offset / length : DVec3(0.0, 1.0, 0.0);
    g.point = s.center + s.radius * g.normal;
    if (!with_uv) {
        g.uv = Vec2(0.0f);
        return g;
    }
    // POV's spherical map: u from +x towards +z, v from the south pole.
    const double horizontal = std::sqrt(g.normal.x * g.normal.x + g.normal.z * g.normal.z);
    double u = horizontal > 0.0 ? std::atan2(g.normal.z, g.normal.x) / (2.0 * kPiD) : 0.0;
    if (u < 0.0) u += 1.0;
    const double v = 0.5 + std::atan2(g.normal.y, horizontal) / kPiD;
    g.uv = Vec2(float(u), float(v));
    return g;
}

namespace {

// Area element ratio world/object at a point with world normal n.
double area_jacobian(const Placement& placement, const DVec3& world_normal) {
    const DMat3 a = linear_part(placement.world_from_object);
    const double det = std::fabs(glm::determinant(a));
    const double projected = glm::length(glm::transpose(a) * world_normal);
    return projected > 0.0 ? det / projected : 0.0;
}

class SphereSampler final : public SurfaceSampler {
  public:
    SphereSampler(const AnalyticSphere& s, const Placement& placement, const Material* material)
        : m_sphere(s), m_placement(placement), m_material(material) {
        const double object_area = 4.0 * kPiD * s.radius * s.radius;
        // World area: exact for similarities, a fixed stratified estimate otherwise.
        if (placement.is_similarity()) {
            const double k = placement.uniform_scale();
            m_area = object_area * k * k;
        } else {
            double sum = 0.0;
            const int n = 64;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    sum += area_jacobian(m_placement, sample(Vec2((i + 0.5f) / n, (j + 0.5f) / n)).normal);
            m_area = object_area * sum / double(n * n);
        }
    }
    double area() const override { return m_area; }
    SurfacePoint sample(const Vec2& u) const override {
        const double z = 1.0 - 2.0 * double(u.x);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = 2.0 * kPiD * double(u.y);
        const DVec3 direction(r * std::cos(phi), z, r * std::sin(phi));
        const SurfaceGeometry g = sphere_surface(m_sphere, m_sphere.center + m_sphere.radius * direction);
        SurfacePoint point;
        point.position = m_placement.point_to_world(g.point);
        point.normal = m_placement.normal_to_world_unit(g.normal);
        point.uv = g.uv;
        const double object_area = 4.0 * kPiD * m_sphere.radius * m_sphere.radius;
        const double jacobian = area_jacobian(m_placement, point.normal);
        point.pdf_area = jacobian > 0.0 && object_area > 0.0 ? 1.0 / (object_area * jacobian) : 0.0;
        point.material = m_material;
        return point;
    }
    double pdf_area(const Hit& hit) const override {
        const double object_area = 4.0 * kPiD * m_sphere.radius * m_sphere.radius;
        const double jacobian = area_jacobian(m_placement, DVec3(hit.geometric_normal));
        return jacobian > 0.0 && object_area > 0.0 ? 1.0 / (object_area * jacobian) : 0.0;
    }
    DVec3 centroid() const override { return m_placement.point_to_world(m_sphere.center); }
    bool is_flat(DVec3&) const override { return false; }
    bool is_closed() const override { return true; }
    void bounds(DVec3& lower, DVec3& upper) const override {
        // The object box's corners in the world: the transformed sphere lies
        // inside the transformed box.
        lower = DVec3(std::numeric_limits<double>::infinity());
        upper = -lower;
        for (int corner = 0; corner < 8; ++corner) {
            const DVec3 offset((corner & 1) ? 1.0 : -1.0, (corner & 2) ? 1.0 : -1.0, (corner & 4) ? 1.0 : -1.0);
            const DVec3 world = m_placement.point_to_world(m_sphere.center + m_sphere.radius * offset);
            lower = glm::min(lower, world);
            upper = glm::max(upper, world);
        }
    }

  private:
    AnalyticSphere m_sphere;
    Placement m_placement;
    const Material* m_material;
    double m_area = 0.0;
};

}  // namespace

std::unique_ptr<SurfaceSampler> make_sphere_sampler(const AnalyticSphere& s, const Placement& placement,
                                                    const Material* material) {
    return std::make_unique<SphereSampler>(s, placement, material);
}

}  // namespace lancer
