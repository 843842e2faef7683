// POV-Ray 3.7's ovus (see ovus.h for the shape and the parameters POV
// refuses or replaces).
//
// Object space, with b = bottom_radius, a = top_radius, s = a / b < 2:
//  - bottom sphere: centre <0, 0, 0>, radius b, surface where y < y_low;
//  - top sphere: centre <0, b, 0>, radius a, surface where y > y_high;
//  - connection: h = sqrt(x^2 + z^2), (h + H)^2 + (y - V)^2 = R^2 for
//    y_low < y < y_high, R = 2 max(a, b): the meridian circle's centre sits
//    H beyond the axis, so rotated about y it is the inner "lemon" of a
//    spindle torus (major radius H < minor radius R), tangent inside both
//    spheres at y_low and y_high. V, H, y_low and y_high are POV's.
//
// Intersection. The solid is the union of three convex pieces (the two
// balls and the lemon cut to the slab y_low < y < y_high; it is exactly
// POV's inside test) and is itself convex, so a line crosses it over one
// interval: the lowest entry and the highest exit over the pieces. The
// balls' intervals are closed-form quadratics. The lemon is the inner
// branch of a torus, a quartic in t; its roots come from
// polynomial_roots_in (isolation by derivatives, robust for close roots)
// over the slab's stretch of the line only, and the lemon's interval is
// read from the inside test at the midpoints between consecutive roots, so
// a root of the outer "apple" branch or a spurious root changes nothing.
// The lemon's end roots are then polished by Newton steps on the distance
// to the meridian circle, which is well conditioned where the quartic is
// not. Taking min/max over pieces leaves no crack or double hit where the
// pieces meet: near a tangent circle two pieces give nearly the same t and
// one is kept. All work is from the line's closest approach to the ovus
// with a unit direction, so neither scale nor far origins cost digits.
//
// (u, v): POV 3.7's Ovus::CalcUV, a spherical map about <0, a / 2, 0>:
// u the angle from +x towards +z over 2 pi, v = 1/2 + asin(y') / pi of the
// unit direction from that centre ((0, 0) at the centre itself).
#include "geometry/ovus.h"

#include <algorithm>
#include <cmath>

#include "geometry/polynomial_roots.h"

namespace lancer {
namespace {

// A stretch of the line (in distance along the unit direction) and the
// pieces its ends lie on.
struct LineInterval {
    double lo = INFINITY, hi = -INFINITY;
    int lo_face = 0, hi_face = 0;
    bool empty() const { return !(lo < hi); }
};

// The stretch of p + s u (|u| = 1) inside the ball about `centre`.
LineInterval ball_interval(const DVec3& p, const DVec3& u, const DVec3& centre, double radius, int face) {
    LineInterval interval;
    const DVec3 offset = p - centre;
    const double along = glm::dot(offset, u);
    const DVec3 closest = offset - along * u;
    const double miss = glm::length(closest);
    // (r - m)(r + m) rather than r^2 - m^2: no digits lost to grazing rays.
    const double half_chord2 = (radius - miss) * (radius + miss);
    if (!(half_chord2 > 0.0)) return interval;
    const double half_chord = std::sqrt(half_chord2);
    interval.lo = -along - half_chord;
    interval.hi = -along + half_chord;
    interval.lo_face = interval.hi_face = face;
    return interval;
}

class OvusShape final : public Shape {
  public:
    OvusShape(double bottom, double top) : m_bottom(bottom), m_top(top) {
        const double s = top / bottom;
        if (top < bottom) {
            // POV: the meridian circle has twice the larger sphere's radius.
            m_connecting = 2.0 * bottom;
            m_vertical = bottom * (2.0 * s - 1.0 - 0.5 * s * s);
            // H^2 = b^2 - V^2, factored so a tiny top radius keeps its digits.
            m_horizontal = bottom * std::sqrt(std::max(0.0, s * (2.0 - 0.5 * s) * 0.5 * (2.0 - s) * (2.0 - s)));
            m_low = -m_vertical;
            m_high = bottom + (bottom - m_vertical) * top / (m_connecting - top);
        } else {
            m_connecting = 2.0 * top;
            m_vertical = bottom * (1.5 * s * s - 2.0 * s + 1.0);
            // H^2 = a^2 - (V - b)^2 = a^2 (1.5 s - 1)(3 - 1.5 s).
            m_horizontal = top * std::sqrt(std::max(0.0, (1.5 * s - 1.0) * (3.0 - 1.5 * s)));
            m_high = 2.0 * bottom - m_vertical;
            m_low = -m_vertical * bottom / (m_connecting - bottom);
        }
        m_has_connection = m_horizontal > 0.0 && m_high > m_low;
        // POV's bounding cylinder: the lemon is widest (R - H) at y = V.
        m_widest = std::max({m_connecting - m_horizontal, bottom, top});
        m_centre = DVec3(0.0, 0.5 * top, 0.0);
        const double half_height = bottom + 0.5 * top;
        m_reach = 1.01 * std::sqrt(half_height * half_height + m_widest * m_widest);
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double length = glm::length(d);
        if (!(length > 0.0) || !std::isfinite(length)) return;
        const DVec3 u = d / length;
        // Work from the line's closest approach to the ovus.
        const double along = glm::dot(m_centre - o, u);
        const DVec3 foot = o + along * u;
        const DVec3 off_centre = foot - m_centre;
        const double miss2 = glm::dot(off_centre, off_centre);
        if (!(miss2 < m_reach * m_reach)) return;
        const double reach_half_chord = std::sqrt(m_reach * m_reach - miss2);

        LineInterval solid;
        const auto unite = [&solid](const LineInterval& piece) {
            if (piece.empty()) return;
            if (piece.lo < solid.lo) solid.lo = piece.lo, solid.lo_face = piece.lo_face;
            if (piece.hi > solid.hi) solid.hi = piece.hi, solid.hi_face = piece.hi_face;
        };
        unite(ball_interval(foot, u, DVec3(0.0), m_bottom, kOvusBottomSphere));
        if (m_top > 0.0) unite(ball_interval(foot, u, DVec3(0.0, m_bottom, 0.0), m_top, kOvusTopSphere));
        if (m_has_connection) unite(connection_interval(foot, u, -reach_half_chord, reach_half_chord));
        if (solid.empty()) return;

        const double t_in = (along + solid.lo) / length;
        const double t_out = (along + solid.hi) / length;
        if (t_in > t_min && t_in < t_max) out.add(t_in, solid.lo_face);
        if (t_out > t_min && t_out < t_max) out.add(t_out, solid.hi_face);
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        if (face != kOvusBottomSphere && face != kOvusTopSphere && face != kOvusConnection)
            face = p.y < m_low ? kOvusBottomSphere : p.y > m_high ? kOvusTopSphere : kOvusConnection;
        if (face == kOvusConnection && !m_has_connection) face = kOvusBottomSphere;
        if (face == kOvusTopSphere && !(m_top > 0.0)) face = kOvusBottomSphere;
        DVec3 centre(0.0);
        double radius = m_bottom;
        if (face == kOvusTopSphere) {
            centre = DVec3(0.0, m_bottom, 0.0);
            radius = m_top;
        } else if (face == kOvusConnection) {
            centre = circle_centre(meridian(p));
            radius = m_connecting;
        }
        SurfaceGeometry g;
        const DVec3 offset = p - centre;
        const double distance = glm::length(offset);
        g.normal = distance > 0.0 ? offset / distance : DVec3(0.0, 1.0, 0.0);
        g.point = centre + radius * g.normal;
        g.uv = uv(g.point);
        return g;
    }

    // POV's Ovus::Inside: in either ball, or in the lemon within the slab.
    bool inside(const DVec3& p) const override {
        if (glm::dot(p, p) < m_bottom * m_bottom) return true;
        const DVec3 from_top = p - DVec3(0.0, m_bottom, 0.0);
        if (glm::dot(from_top, from_top) < m_top * m_top) return true;
        return p.y > m_low && p.y < m_high && in_lemon(p);
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = DVec3(-m_widest, -m_bottom, -m_widest);
        upper = DVec3(m_widest, m_bottom + m_top, m_widest);
        return true;
    }

  private:
    // The unit horizontal direction of p's meridian half-plane, <x, 0, z>;
    // +x on the axis (no connection point lies there).
    static glm::dvec2 meridian(const DVec3& p) {
        const double h = std::hypot(p.x, p.z);
        return h > 0.0 ? glm::dvec2(p.x / h, p.z / h) : glm::dvec2(1.0, 0.0);
    }
    // The centre of the meridian circle in the half-plane of `direction`.
    DVec3 circle_centre(const glm::dvec2& direction) const {
        return DVec3(-m_horizontal * direction.x, m_vertical, -m_horizontal * direction.y);
    }

    bool in_lemon(const DVec3& p) const {
        const double h = std::hypot(p.x, p.z) + m_horizontal;
        const double dy = p.y - m_vertical;
        return h * h + dy * dy < m_connecting * m_connecting;
    }

    // Distance from the lemon's meridian circle (negative inside) and its
    // derivative along u at p.
    double lemon_distance(const DVec3& p, const DVec3& u, double& slope) const {
        const double h = std::hypot(p.x, p.z);
        const double dh = h > 0.0 ? (p.x * u.x + p.z * u.z) / h : 0.0;
        const double wide = h + m_horizontal, dy = p.y - m_vertical;
        const double radial = std::hypot(wide, dy);
        slope = radial > 0.0 ? (wide * dh + dy * u.y) / radial : 0.0;
        return radial - m_connecting;
    }

    // Newton steps on the distance to the meridian circle from a quartic
    // root; a step is kept only if it gets closer.
    double polish(const DVec3& p, const DVec3& u, double s) const {
        double slope;
        double distance = lemon_distance(p + s * u, u, slope);
        for (int step = 0; step < 4; ++step) {
            if (!(std::fabs(slope) > 1e-12)) break;
            const double next = s - distance / slope;
            double next_slope;
            const double next_distance = lemon_distance(p + next * u, u, next_slope);
            if (!(std::fabs(next_distance) < std::fabs(distance))) break;
            s = next, distance = next_distance, slope = next_slope;
            if (distance == 0.0) break;
        }
        return s;
    }

    // The stretch of foot + s u (s in (s_lo, s_hi), which holds the whole
    // ovus) inside the lemon and the slab.
    LineInterval connection_interval(const DVec3& foot, const DVec3& u, double s_lo, double s_hi) const {
        LineInterval interval;
        if (u.y != 0.0) {
            double s1 = (m_low - foot.y) / u.y, s2 = (m_high - foot.y) / u.y;
            if (s1 > s2) std::swap(s1, s2);
            s_lo = std::max(s_lo, s1);
            s_hi = std::min(s_hi, s2);
        } else if (!(foot.y > m_low && foot.y < m_high)) {
            return interval;
        }
        if (!(s_lo < s_hi)) return interval;

        // The torus (|q|^2 - H^2 - R^2)^2 + 4 H^2 (q_y^2 - R^2) = 0 with
        // q = p + s u about the lemon's centre, |u| = 1, in units of R: the
        // coefficients are then of size 1 at any scale (the root finder
        // drops leading terms small against the largest).
        const double unit = 1.0 / m_connecting;
        const DVec3 p = (foot - DVec3(0.0, m_vertical, 0.0)) * unit;
        const double H = m_horizontal * unit, H2 = H * H;
        const double k1 = glm::dot(p, p) - H2 - 1.0;
        const double k2 = glm::dot(p, u);
        double c[5];
        c[4] = 1.0;
        c[3] = 4.0 * k2;
        c[2] = 2.0 * k1 + 4.0 * k2 * k2 + 4.0 * H2 * u.y * u.y;
        c[1] = 4.0 * k1 * k2 + 8.0 * H2 * p.y * u.y;
        c[0] = k1 * k1 + 4.0 * H2 * (p.y * p.y - 1.0);
        double ends[kMaxPolynomialDegree + 2];
        ends[0] = s_lo;
        const int roots = polynomial_roots_in(c, 4, s_lo * unit, s_hi * unit, ends + 1);
        for (int i = 1; i <= roots; ++i) ends[i] *= m_connecting;
        ends[roots + 1] = s_hi;

        // Which stretches between consecutive ends lie in the lemon (it is
        // convex: they are consecutive).
        int first = -1, last = -1;
        for (int i = 0; i <= roots; ++i) {
            if (!in_lemon(foot + (0.5 * (ends[i] + ends[i + 1])) * u)) continue;
            if (first < 0) first = i;
            last = i;
        }
        if (first < 0) return interval;
        interval.lo = first > 0 ? polish(foot, u, ends[first]) : ends[first];
        interval.hi = last < roots ? polish(foot, u, ends[last + 1]) : ends[last + 1];
        interval.lo_face = interval.hi_face = kOvusConnection;
        return interval;
    }

    // POV 3.7's Ovus::CalcUV.
    Vec2 uv(const DVec3& p) const {
        const DVec3 from_centre(p.x, p.y - 0.5 * m_top, p.z);
        const double distance = glm::length(from_centre);
        if (!(distance > 0.0)) return Vec2(0.0f);
        const DVec3 unit = from_centre / distance;
        const double v = 0.5 + std::asin(std::clamp(unit.y, -1.0, 1.0)) / kPiD;
        double u = 0.0;
        if (unit.x * unit.x + unit.z * unit.z > 1e-10) {
            u = std::atan2(unit.z, unit.x) / (2.0 * kPiD);
            if (u < 0.0) u += 1.0;
        }
        return Vec2(float(u), float(v));
    }

    double m_bottom, m_top;
    double m_connecting = 0.0;         // R, the meridian circle's radius
    double m_vertical = 0.0;           // V, its centre's height
    double m_horizontal = 0.0;         // H, its centre's distance beyond the axis
    double m_low = 0.0, m_high = 0.0;  // the tangent circles' heights
    bool m_has_connection = false;
    double m_widest = 0.0;  // bounding cylinder radius
    DVec3 m_centre{0.0};    // of the bounding box
    double m_reach = 0.0;   // radius of a sphere about m_centre holding the ovus
};

}  // namespace

std::shared_ptr<const Shape> make_ovus_shape(double bottom_radius, double top_radius) {
    if (!std::isfinite(bottom_radius) || !std::isfinite(top_radius)) return nullptr;
    if (bottom_radius < 0.0 || top_radius < 0.0) return nullptr;  // POV: "Both Ovus radii must be positive"
    // POV substitutes the top sphere, which then holds the bottom one.
    if (!(top_radius < 2.0 * bottom_radius))
        return make_sphere_shape(AnalyticSphere{DVec3(0.0, bottom_radius, 0.0), top_radius});
    return std::make_shared<OvusShape>(bottom_radius, top_radius);
}

}  // namespace lancer
