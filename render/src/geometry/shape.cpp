// The Shape interface over spheres, boxes and planes, and what every shape
// shares (shape.h).
#include "geometry/shape.h"

#include <algorithm>
#include <cmath>

namespace lancer {

bool Shape::nearest(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossing& hit) const {
    ShapeCrossings all;
    crossings(o, d, t_min, t_max, all);
    if (all.count == 0) return false;
    hit = all.items[0];
    for (int i = 1; i < all.count; ++i)
        if (all.items[i].t < hit.t) hit = all.items[i];
    return true;
}

void Shape::narrow_box(DVec3& lower, DVec3& upper, bool inverted) const {
    DVec3 own_lower, own_upper;
    if (inverted || !solid() || !inside_within_bounds() || !bounds(own_lower, own_upper)) return;
    lower = glm::max(lower, own_lower);
    upper = glm::min(upper, own_upper);
}

bool ray_box_interval(const DVec3& lower, const DVec3& upper, const DVec3& o, const DVec3& d, double& t_min,
                      double& t_max) {
    for (int axis = 0; axis < 3; ++axis)
        if (!ray_slab_interval(o[axis], d[axis], 1.0 / d[axis], lower[axis], upper[axis], t_min, t_max)) return false;
    return true;
}

namespace {

class SphereShape final : public Shape {
  public:
    explicit SphereShape(const AnalyticSphere& s) : m_sphere(s) {}
    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        // Both roots, each found as intersect_sphere finds the nearest.
        double t;
        if (!intersect_sphere(m_sphere, o, d, t_min, t_max, t)) return;
        out.add(t, 0);
        if (intersect_sphere(m_sphere, o, d, t, t_max, t) && t > out.items[out.count - 1].t) out.add(t, 0);
    }
    bool nearest(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossing& hit) const override {
        double t;
        if (!intersect_sphere(m_sphere, o, d, t_min, t_max, t)) return false;
        hit = ShapeCrossing{t, 0};
        return true;
    }
    SurfaceGeometry surface(const DVec3& p, int) const override { return sphere_surface(m_sphere, p); }
    bool inside(const DVec3& p) const override {
        const DVec3 offset = p - m_sphere.center;
        return glm::dot(offset, offset) <= m_sphere.radius * m_sphere.radius;
    }
    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = m_sphere.center - DVec3(m_sphere.radius);
        upper = m_sphere.center + DVec3(m_sphere.radius);
        return true;
    }

  private:
    AnalyticSphere m_sphere;
};

class BoxShape final : public Shape {
  public:
    explicit BoxShape(const AnalyticBox& b) : m_box(b) {}
    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        double t;
        int face;
        if (!intersect_box(m_box, o, d, t_min, t_max, t, face)) return;
        out.add(t, face);
        if (intersect_box(m_box, o, d, t, t_max, t, face)) out.add(t, face);
    }
    bool nearest(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossing& hit) const override {
        double t;
        int face;
        if (!intersect_box(m_box, o, d, t_min, t_max, t, face)) return false;
        hit = ShapeCrossing{t, face};
        return true;
    }
    SurfaceGeometry surface(const DVec3& p, int face) const override { return box_surface(m_box, p, face); }
    bool inside(const DVec3& p) const override {
        return p.x >= m_box.lower.x && p.x <= m_box.upper.x && p.y >= m_box.lower.y && p.y <= m_box.upper.y &&
               p.z >= m_box.lower.z && p.z <= m_box.upper.z;
    }
    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = m_box.lower;
        upper = m_box.upper;
        return true;
    }

  private:
    AnalyticBox m_box;
};

class PlaneShape final : public Shape {
  public:
    explicit PlaneShape(const AnalyticPlane& p) : m_plane(p) {}
    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        double t;
        if (intersect_plane(m_plane, o, d, t_min, t_max, t)) out.add(t, 0);
    }
    SurfaceGeometry surface(const DVec3& p, int) const override { return plane_surface(m_plane, p); }
    // POV: the half-space the normal points away from.
    bool inside(const DVec3& p) const override { return glm::dot(p, m_plane.normal) <= m_plane.distance; }
    bool bounds(DVec3&, DVec3&) const override { return false; }
    // A plane across an axis bounds that axis on one side.
    void narrow_box(DVec3& lower, DVec3& upper, bool inverted) const override {
        const DVec3& n = m_plane.normal;
        const int zeros = (n.x == 0.0) + (n.y == 0.0) + (n.z == 0.0);
        if (zeros != 2) return;
        const int axis = n.x != 0.0 ? 0 : n.y != 0.0 ? 1 : 2;
        // Inside: n_axis * p_axis <= distance; inverted, >= (the surface
        // itself belongs to both).
        const double edge = m_plane.distance / n[axis];
        if ((n[axis] > 0.0) != inverted)
            upper[axis] = std::min(upper[axis], edge);
        else
            lower[axis] = std::max(lower[axis], edge);
    }

  private:
    AnalyticPlane m_plane;
};

}  // namespace

std::shared_ptr<const Shape> make_sphere_shape(const AnalyticSphere& sphere) {
    return std::make_shared<SphereShape>(sphere);
}
std::shared_ptr<const Shape> make_box_shape(const AnalyticBox& box) {
    return std::make_shared<BoxShape>(box);
}
std::shared_ptr<const Shape> make_plane_shape(const AnalyticPlane& plane) {
    return std::make_shared<PlaneShape>(plane);
}

}  // namespace lancer
