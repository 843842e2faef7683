// POV-Ray's lathe: an open spline curve of points <r, y> turned about the
// y axis. Along a ray that is not horizontal, t = (y(s) - o.y) / d.y turns
// x^2 + z^2 = r(s)^2 into one polynomial in the curve parameter s (degree
// 2, 4 or 6 for linear, quadratic and cubic or Bezier segments), solved by
// the derivative-isolating root finder; a horizontal ray meets each height
// y(s) = o.y on a circle, a quadratic in t. Inside is POV's test (an odd
// number of curve crossings outward from the axis). (u, v): u the angle
// about y (POV's sense), v along the curve from its first segment.
#include <algorithm>
#include <cmath>

#include "geometry/planar_spline.h"
#include "geometry/polynomial_roots.h"
#include "geometry/revolution_bands.h"
#include "geometry/shape.h"

namespace lancer {
namespace {

// Coefficients (ascending) of a segment coordinate as a polynomial in s.
void coordinate(const SplineSegment& s, int axis, double out[4]) {
    out[0] = s.d[axis];
    out[1] = s.c[axis];
    out[2] = s.b[axis];
    out[3] = s.a[axis];
}

void multiply(const double* a, int na, const double* b, int nb, double* out) {
    for (int i = 0; i <= na + nb; ++i) out[i] = 0.0;
    for (int i = 0; i <= na; ++i)
        for (int j = 0; j <= nb; ++j) out[i + j] += a[i] * b[j];
}

class LatheShape final : public Shape {
  public:
    explicit LatheShape(std::vector<SplineSegment> segments) : m_segments(std::move(segments)) {
        // Each segment's exact extremes; the whole curve's make the bounds,
        // as POV-Ray's (min_extent and max_extent are the curve's).
        struct Range {
            double r, y_low, y_high;
        };
        std::vector<Range> ranges;
        for (const SplineSegment& segment : m_segments) {
            double r[4], y[4], r_low, r_high, y_low, y_high;
            coordinate(segment, 0, r);
            coordinate(segment, 1, y);
            cubic_range(r, 0.0, 1.0, r_low, r_high);
            cubic_range(y, 0.0, 1.0, y_low, y_high);
            ranges.push_back({std::max(std::fabs(r_low), std::fabs(r_high)), y_low, y_high});
            m_radius = std::max(m_radius, ranges.back().r);
            m_y_low = std::min(m_y_low, y_low);
            m_y_high = std::max(m_y_high, y_high);
        }
        // Each segment's band, and the bounds, widened past the tolerance
        // crossings() allows a point off the surface.
        const double margin = 2e-6 * (m_radius + (m_y_high - m_y_low)) + 1e-9;
        for (const Range& range : ranges)
            m_bands.push_back(RevolutionBand{range.y_low - margin, range.y_high + margin, range.r + margin});
        m_radius += margin;
        m_y_low -= margin;
        m_y_high += margin;
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double scale = glm::length(d);
        if (!(scale > 0.0)) return;
        // Only the stretch inside the bounds: a nearly horizontal ray's
        // polynomial (scaled by d.y^2) has roots far along it that are
        // rounding, not surface.
        double near = t_min, far = t_max;
        if (!ray_box_interval(DVec3(-m_radius, m_y_low, -m_radius), DVec3(m_radius, m_y_high, m_radius), o, d, near,
                              far))
            return;
        const double tolerance = 1e-6 * (m_radius + (m_y_high - m_y_low));
        const bool horizontal = std::fabs(d.y) <= 1e-9 * scale;
        // A horizontal ray is met at its origin's height, over its whole
        // range (below).
        const DVec3 banded_direction = horizontal ? DVec3(d.x, 0.0, d.z) : d;
        const double band_near = horizontal ? t_min : near, band_far = horizontal ? t_max : far;
        for (std::size_t index = 0; index < m_segments.size(); ++index) {
            if (!m_bands[index].may_meet(o, banded_direction, band_near, band_far)) continue;
            const SplineSegment& segment = m_segments[index];
            double r[4], y[4];
            coordinate(segment, 0, r);
            coordinate(segment, 1, y);
            double roots[kMaxPolynomialDegree];
            if (horizontal) {
                y[0] -= o.y;
                const int n = polynomial_roots_in(y, 3, -1e-12, 1.0 + 1e-12, roots);
                for (int i = 0; i < n; ++i) {
                    const double s = std::clamp(roots[i], 0.0, 1.0);
                    const double radius = segment.at(s).x;
                    // (o + t d) on the circle of that radius, in x-z.
                    double t_roots[2];
                    const int m = solve_quadratic(d.x * d.x + d.z * d.z, o.x * d.x + o.z * d.z,
                                                  o.x * o.x + o.z * o.z - radius * radius, t_roots);
                    for (int k = 0; k < m; ++k)
                        if (t_roots[k] > t_min && t_roots[k] < t_max) out.add(t_roots[k], int(index));
                }
                continue;
            }
            // u(s) = y(s) - o.y; (o.x d.y + d.x u)^2 + (o.z d.y + d.z u)^2 - d.y^2 r(s)^2 = 0.
            double u[4] = {y[0] - o.y, y[1], y[2], y[3]};
            double u2[7], r2[7];
            multiply(u, 3, u, 3, u2);
            multiply(r, 3, r, 3, r2);
            const double a1 = o.x * d.y, a2 = o.z * d.y;
            const double k2 = d.x * d.x + d.z * d.z, k1 = 2.0 * (a1 * d.x + a2 * d.z), k0 = a1 * a1 + a2 * a2;
            double c[7];
            for (int i = 0; i <= 6; ++i) c[i] = k2 * u2[i] - d.y * d.y * r2[i] + (i <= 3 ? k1 * u[i] : 0.0);
            c[0] += k0;
            const int n = polynomial_roots_in(c, 6, -1e-12, 1.0 + 1e-12, roots);
            for (int i = 0; i < n; ++i) {
                const double s = std::clamp(roots[i], 0.0, 1.0);
                const glm::dvec2 curve = segment.at(s);
                const double t = (curve.y - o.y) / d.y;
                if (!(t > t_min && t < t_max && t >= near && t <= far)) continue;
                const DVec3 p = o + t * d;
                if (std::fabs(std::sqrt(p.x * p.x + p.z * p.z) - std::fabs(curve.x)) > tolerance) continue;
                out.add(t, int(index));
            }
        }
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        SurfaceGeometry g;
        const SplineSegment& segment = m_segments[std::size_t(face)];
        const double rho = std::sqrt(p.x * p.x + p.z * p.z);
        // The parameter at the point's height whose radius is nearest.
        double y[4];
        coordinate(segment, 1, y);
        y[0] -= p.y;
        double roots[kMaxPolynomialDegree];
        int n = polynomial_roots_in(y, 3, -1e-9, 1.0 + 1e-9, roots);
        double s = 0.5;
        if (n == 0) {
            // A flat (constant-height) segment: the parameter by radius.
            double r[4];
            coordinate(segment, 0, r);
            r[0] -= rho;
            n = polynomial_roots_in(r, 3, -1e-9, 1.0 + 1e-9, roots);
            if (n > 0) s = roots[0];
        } else {
            double best = INFINITY;
            for (int i = 0; i < n; ++i) {
                const double miss = std::fabs(std::fabs(segment.at(roots[i]).x) - rho);
                if (miss < best) {
                    best = miss;
                    s = roots[i];
                }
            }
        }
        s = std::clamp(s, 0.0, 1.0);
        const glm::dvec2 q = segment.at(s), tangent = segment.tangent(s);
        const glm::dvec2 around = rho > 0.0 ? glm::dvec2(p.x, p.z) / rho : glm::dvec2(1.0, 0.0);
        const double radius = std::fabs(q.x);
        g.point = DVec3(radius * around.x, q.y, radius * around.y);
        const double sign = q.x < 0.0 ? -1.0 : 1.0;
        DVec3 normal(tangent.y * sign * around.x, -tangent.x * sign, tangent.y * sign * around.y);
        const double length = glm::length(normal);
        normal = length > 0.0 ? normal / length : DVec3(around.x, 0.0, around.y);
        // Out of the solid: the side where POV's inside test fails.
        const double step = 1e-6 * std::max(1.0, m_radius);
        if (inside(g.point + step * normal)) normal = -normal;
        g.normal = normal;
        double angle = std::atan2(p.z, p.x) / (2.0 * kPiD);
        if (angle < 0.0) angle += 1.0;
        g.uv = Vec2(float(angle), float((double(face) + s) / double(m_segments.size())));
        return g;
    }

    bool inside(const DVec3& p) const override {
        const double rho = std::sqrt(p.x * p.x + p.z * p.z);
        int crossings = 0;
        for (const SplineSegment& segment : m_segments) {
            double roots[3];
            const int n = segment_roots(segment, 1, p.y, roots);
            for (int i = 0; i < n; ++i)
                if (std::fabs(segment.at(roots[i]).x) >= rho) ++crossings;
        }
        return crossings % 2 == 1;
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = DVec3(-m_radius, m_y_low, -m_radius);
        upper = DVec3(m_radius, m_y_high, m_radius);
        return true;
    }

  private:
    std::vector<SplineSegment> m_segments;
    std::vector<RevolutionBand> m_bands;  // by segment
    double m_radius = 0.0, m_y_low = INFINITY, m_y_high = -INFINITY;
};

}  // namespace

std::shared_ptr<const Shape> make_lathe_shape(SplineKind spline, const std::vector<glm::dvec2>& points) {
    std::vector<SplineSegment> segments = open_spline_segments(spline, points);
    if (segments.empty()) return nullptr;
    return std::make_shared<LatheShape>(std::move(segments));
}

}  // namespace lancer
