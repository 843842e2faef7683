// POV-Ray's sor (surface of revolution): about the y axis, the squared
// radius is a cubic in y on each segment, fitted as POV's Compute_Sor
// fits it (through points i+1 and i+2, with slopes from their
// neighbours), closed by discs at the first and last heights unless open.
// Along a ray x^2 + z^2 - r^2(y) is then a cubic in t per segment, solved
// by the derivative-isolating root finder. (u, v): u the angle about y,
// v the height from the bottom disc (0) to the top (1).
#include <algorithm>
#include <cmath>

#include "geometry/polynomial_roots.h"
#include "geometry/revolution_bands.h"
#include "geometry/shape.h"

namespace lancer {
namespace {

struct SorSegment {
    double a, b, c, d;  // r^2(y) = a y^3 + b y^2 + c y + d
    double y_low, y_high;
    double r2(double y) const { return ((a * y + b) * y + c) * y + d; }
    double slope(double y) const { return (3.0 * a * y + 2.0 * b) * y + c; }
};

enum SorFace { kBottomDisc = -1, kTopDisc = -2 };

class SorShape final : public Shape {
  public:
    SorShape(std::vector<SorSegment> segments, double bottom, double bottom_r, double top, double top_r, bool open)
        : m_segments(std::move(segments)),
          m_bottom(bottom),
          m_bottom_r(bottom_r),
          m_top(top),
          m_top_r(top_r),
          m_open(open) {
        // Each segment's exact widest radius; the widest makes the bounds,
        // as POV-Ray's (min_extent and max_extent are the curve's).
        std::vector<double> radii;
        for (const SorSegment& s : m_segments) {
            const double r2[4] = {s.d, s.c, s.b, s.a};
            double lowest, highest;
            cubic_range(r2, s.y_low, s.y_high, lowest, highest);
            radii.push_back(std::sqrt(std::max(highest, 0.0)));
            m_radius = std::max(m_radius, radii.back());
        }
        // Each segment's band, and the bounds, widened past the tolerance
        // crossings() allows a point off the surface.
        const double margin = 2e-6 * (m_radius + (m_top - m_bottom)) + 1e-9;
        for (std::size_t i = 0; i < m_segments.size(); ++i)
            m_bands.push_back(
                RevolutionBand{m_segments[i].y_low - margin, m_segments[i].y_high + margin, radii[i] + margin});
        m_radius += margin;
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        // Only the stretch inside the bounds, and only where the point lies
        // on the surface: a cubic fitted to close heights far from the
        // origin is ill-conditioned away from its segment, and the ray's
        // polynomial then has roots that are rounding, not surface.
        double near = t_min, far = t_max;
        if (!ray_box_interval(DVec3(-m_radius, m_bottom, -m_radius), DVec3(m_radius, m_top, m_radius), o, d, near, far))
            return;
        const double tolerance = 1e-6 * (m_radius + (m_top - m_bottom));
        for (std::size_t index = 0; index < m_segments.size(); ++index) {
            if (!m_bands[index].may_meet(o, d, near, far)) continue;
            const SorSegment& s = m_segments[index];
            // x(t)^2 + z(t)^2 - r^2(o.y + t d.y) = 0.
            const double y0 = o.y, dy = d.y;
            double c[4];
            c[0] = o.x * o.x + o.z * o.z - s.r2(y0);
            c[1] = 2.0 * (o.x * d.x + o.z * d.z) - s.slope(y0) * dy;
            c[2] = d.x * d.x + d.z * d.z - (3.0 * s.a * y0 + s.b) * dy * dy;
            c[3] = -s.a * dy * dy * dy;
            double roots[kMaxPolynomialDegree];
            const int n = polynomial_roots_in(c, 3, t_min, t_max, roots);
            for (int i = 0; i < n; ++i) {
                const double t = roots[i];
                const double y = y0 + t * dy;
                if (!(y >= s.y_low && y <= s.y_high && t >= near && t <= far)) continue;
                const double x = o.x + t * d.x, z = o.z + t * d.z;
                if (std::fabs(std::sqrt(x * x + z * z) - std::sqrt(std::max(0.0, s.r2(y)))) > tolerance) continue;
                out.add(t, int(index));
            }
        }
        if (m_open || d.y == 0.0) return;
        for (int face : {kBottomDisc, kTopDisc}) {
            const double h = face == kBottomDisc ? m_bottom : m_top;
            const double r = face == kBottomDisc ? m_bottom_r : m_top_r;
            const double t = (h - o.y) / d.y;
            if (!(t > t_min && t < t_max)) continue;
            const double x = o.x + t * d.x, z = o.z + t * d.z;
            if (x * x + z * z <= r * r) out.add(t, face);
        }
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        SurfaceGeometry g;
        double angle = std::atan2(p.z, p.x) / (2.0 * kPiD);
        if (angle < 0.0) angle += 1.0;
        const double span = m_top - m_bottom;
        if (face == kBottomDisc || face == kTopDisc) {
            g.point = DVec3(p.x, face == kBottomDisc ? m_bottom : m_top, p.z);
            g.normal = DVec3(0.0, face == kBottomDisc ? -1.0 : 1.0, 0.0);
        } else {
            const SorSegment& s = m_segments[std::size_t(face)];
            const double y = std::clamp(p.y, s.y_low, s.y_high);
            const double rho = std::sqrt(p.x * p.x + p.z * p.z);
            const double r = std::sqrt(std::max(0.0, s.r2(y)));
            const glm::dvec2 around = rho > 0.0 ? glm::dvec2(p.x, p.z) / rho : glm::dvec2(1.0, 0.0);
            g.point = DVec3(r * around.x, y, r * around.y);
            const DVec3 gradient(2.0 * g.point.x, -s.slope(y), 2.0 * g.point.z);
            const double length = glm::length(gradient);
            g.normal = length > 0.0 ? gradient / length : DVec3(0.0, 1.0, 0.0);
        }
        g.uv = Vec2(float(angle), float(span > 0.0 ? (g.point.y - m_bottom) / span : 0.0));
        return g;
    }

    bool inside(const DVec3& p) const override {
        if (p.y < m_bottom || p.y > m_top) return false;
        const double rho2 = p.x * p.x + p.z * p.z;
        for (const SorSegment& s : m_segments)
            if (p.y >= s.y_low && p.y <= s.y_high) return rho2 <= s.r2(p.y);
        return false;
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = DVec3(-m_radius, m_bottom, -m_radius);
        upper = DVec3(m_radius, m_top, m_radius);
        return true;
    }

  private:
    std::vector<SorSegment> m_segments;
    std::vector<RevolutionBand> m_bands;  // by segment
    double m_bottom, m_bottom_r, m_top, m_top_r;
    bool m_open;
    double m_radius = 0.0;
};

}  // namespace

std::shared_ptr<const Shape> make_sor_shape(const std::vector<glm::dvec2>& p, bool open) {
    const int n = int(p.size());
    if (n < 4) return nullptr;
    // POV's Parse_Sor: radii not negative, the heights of the points a
    // segment spans (the second to the last but one) increasing.
    for (int i = 0; i < n; ++i)
        if (p[i].x < 0.0 || (i > 1 && i < n - 1 && !(p[i].y > p[i - 1].y))) return nullptr;
    std::vector<SorSegment> segments;
    for (int i = 0; i + 3 < n; ++i) {
        if (!(std::fabs(p[i + 2].y - p[i].y) > 0.0) || !(std::fabs(p[i + 3].y - p[i + 1].y) > 0.0)) return nullptr;
        // r^2 and its slope d(r^2)/dy = 2 r dr/dy at the two ends.
        const double k0 = p[i + 1].x * p[i + 1].x, k1 = p[i + 2].x * p[i + 2].x;
        const double k2 = 2.0 * p[i + 1].x * (p[i + 2].x - p[i].x) / (p[i + 2].y - p[i].y);
        const double k3 = 2.0 * p[i + 2].x * (p[i + 3].x - p[i + 1].x) / (p[i + 3].y - p[i + 1].y);
        const double w1 = p[i + 1].y, w2 = p[i + 2].y;
        // Rows: value at w1, value at w2, slope at w1, slope at w2 (GLM is column-major: transpose).
        const glm::dmat4 rows(w1 * w1 * w1, w2 * w2 * w2, 3.0 * w1 * w1, 3.0 * w2 * w2,  //
                              w1 * w1, w2 * w2, 2.0 * w1, 2.0 * w2,                      //
                              w1, w2, 1.0, 1.0,                                          //
                              1.0, 1.0, 0.0, 0.0);
        if (glm::determinant(rows) == 0.0) return nullptr;
        const glm::dvec4 coefficients = glm::inverse(rows) * glm::dvec4(k0, k1, k2, k3);
        segments.push_back(SorSegment{coefficients.x, coefficients.y, coefficients.z, coefficients.w, std::min(w1, w2),
                                      std::max(w1, w2)});
    }
    const double bottom = std::min(p[1].y, p[n - 2].y), top = std::max(p[1].y, p[n - 2].y);
    const double bottom_r = p[1].y <= p[n - 2].y ? p[1].x : p[n - 2].x;
    const double top_r = p[1].y <= p[n - 2].y ? p[n - 2].x : p[1].x;
    return std::make_shared<SorShape>(std::move(segments), bottom, std::fabs(bottom_r), top, std::fabs(top_r), open);
}

}  // namespace lancer
