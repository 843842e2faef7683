// POV-Ray's cone and cylinder: a quadric side between two planar end discs.
//
// Worked in a frame along the axis: h = (p - base) . axis, the radial part
// q = (p - base) - h axis, and the radius r(h) = base_radius + slope h. The
// side is |q|^2 = r(h)^2, a quadratic in t along a ray, solved with the
// stable quadratic (polynomial_roots.h) after moving the origin to the
// point of the line nearest the base, so a far origin loses no digits.
// (u, v): u the angle about the axis, v = h / length (0 on the base disc,
// 1 on the cap disc); POV-Ray 3.7 defines none for these shapes.
#include <algorithm>
#include <cmath>

#include "geometry/polynomial_roots.h"
#include "geometry/shape.h"

namespace lancer {
namespace {

enum ConeFace { kSide = 0, kBaseDisc = 1, kCapDisc = 2 };

class ConeShape final : public Shape {
  public:
    explicit ConeShape(const ConeParameters& c)
        : m_base(c.base), m_base_radius(c.base_radius), m_cap_radius(c.cap_radius), m_open(c.open) {
        const DVec3 axis = c.cap - c.base;
        m_length = glm::length(axis);
        m_axis = axis / m_length;
        m_slope = (c.cap_radius - c.base_radius) / m_length;
        // A frame across the axis, for u.
        const DVec3 reference = std::fabs(m_axis.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 1.0, 0.0);
        m_across1 = glm::normalize(glm::cross(reference, m_axis));
        m_across2 = glm::cross(m_axis, m_across1);
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double dd = glm::dot(d, d);
        if (!(dd > 0.0)) return;
        const double shift = glm::dot(m_base - o, d) / dd;
        const DVec3 from_base = o + shift * d - m_base;
        const double h0 = glm::dot(from_base, m_axis), dh = glm::dot(d, m_axis);
        const DVec3 q0 = from_base - h0 * m_axis, dq = d - dh * m_axis;
        const double r0 = m_base_radius + m_slope * h0;
        const double a = glm::dot(dq, dq) - m_slope * m_slope * dh * dh;
        const double b_half = glm::dot(q0, dq) - m_slope * r0 * dh;
        const double c = glm::dot(q0, q0) - r0 * r0;
        double roots[2];
        const int n = solve_quadratic(a, b_half, c, roots);
        for (int i = 0; i < n; ++i) {
            // Where the ray nearly follows the side's slope, a is tiny and
            // the roots lose digits: polish each on |q| - r(h), which is well
            // conditioned, and drop one that does not land on the side.
            double s_root = roots[i];
            bool on_side = false;
            const double size = std::max({m_length, m_base_radius, m_cap_radius});
            for (int step = 0; step < 4; ++step) {
                const DVec3 q = q0 + s_root * dq;
                const double h_here = h0 + s_root * dh;
                const double radial = glm::length(q);
                const double miss = radial - (m_base_radius + m_slope * h_here);
                on_side = std::fabs(miss) <= 1e-9 * size;
                const double slope = (radial > 0.0 ? glm::dot(q, dq) / radial : 0.0) - m_slope * dh;
                if (on_side || slope == 0.0) break;
                s_root -= miss / slope;
            }
            if (!on_side) continue;
            roots[i] = s_root;
            const double h = h0 + roots[i] * dh;
            const double t = roots[i] + shift;
            // The side of the cone on the right sheet (r(h) >= 0) between the discs.
            if (h >= 0.0 && h <= m_length && t > t_min && t < t_max) out.add(t, kSide);
        }
        if (m_open || dh == 0.0) return;
        for (int face : {kBaseDisc, kCapDisc}) {
            const double target = face == kBaseDisc ? 0.0 : m_length;
            const double radius = face == kBaseDisc ? m_base_radius : m_cap_radius;
            const double s = (target - h0) / dh;
            const DVec3 q = q0 + s * dq;
            const double t = s + shift;
            if (glm::dot(q, q) <= radius * radius && t > t_min && t < t_max) out.add(t, face);
        }
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override { return surface_at(p, face, true); }
    SurfaceGeometry surface_without_uv(const DVec3& p, int face) const override { return surface_at(p, face, false); }

    SurfaceGeometry surface_at(const DVec3& p, int face, bool with_uv) const {
        SurfaceGeometry g;
        const DVec3 from_base = p - m_base;
        double h = glm::dot(from_base, m_axis);
        DVec3 q = from_base - h * m_axis;
        const double radial = glm::length(q);
        const DVec3 out = radial > 0.0 ? q / radial : m_across1;
        if (face == kSide) {
            h = std::clamp(h, 0.0, m_length);
            const double r = m_base_radius + m_slope * h;
            g.point = m_base + h * m_axis + r * out;
            // Gradient of |q|^2 - r(h)^2: radially out, tilted by the slope.
            g.normal = glm::normalize(out - m_slope * m_axis);
        } else {
            const double target = face == kBaseDisc ? 0.0 : m_length;
            g.point = m_base + target * m_axis + q;
            g.normal = face == kBaseDisc ? -m_axis : m_axis;
            h = target;
        }
        g.uv = Vec2(0.0f);
        if (!with_uv) return g;
        double u = std::atan2(glm::dot(out, m_across2), glm::dot(out, m_across1)) / (2.0 * kPiD);
        if (u < 0.0) u += 1.0;
        g.uv = Vec2(float(u), float(h / m_length));
        return g;
    }

    bool inside(const DVec3& p) const override {
        const DVec3 from_base = p - m_base;
        const double h = glm::dot(from_base, m_axis);
        if (h < 0.0 || h > m_length) return false;
        const DVec3 q = from_base - h * m_axis;
        const double r = m_base_radius + m_slope * h;
        return glm::dot(q, q) <= r * r;
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        // Each end disc spans radius * sqrt(1 - axis_i^2) along axis i.
        const DVec3 spread = glm::sqrt(glm::max(DVec3(0.0), DVec3(1.0) - m_axis * m_axis));
        const DVec3 cap = m_base + m_length * m_axis;
        lower = glm::min(m_base - m_base_radius * spread, cap - m_cap_radius * spread);
        upper = glm::max(m_base + m_base_radius * spread, cap + m_cap_radius * spread);
        return true;
    }

  private:
    DVec3 m_base;
    double m_base_radius, m_cap_radius;
    bool m_open;
    DVec3 m_axis{0.0, 1.0, 0.0}, m_across1{1.0, 0.0, 0.0}, m_across2{0.0, 0.0, 1.0};
    double m_length = 1.0, m_slope = 0.0;
};

}  // namespace

std::shared_ptr<const Shape> make_cone_shape(const ConeParameters& cone) {
    return std::make_shared<ConeShape>(cone);
}

}  // namespace lancer
