// POV-Ray's prism: closed spline curves in the x-z plane swept along y
// between two heights, straight (linear_sweep) or towards the origin
// (conic_sweep: at height y the curve is scaled by y), capped unless open.
//
// A side crossing solves one cubic in the curve's parameter: for a linear
// sweep, the curve meets the ray's shadow on the x-z plane; for a conic
// sweep, the curve meets the line where the ray's x/y and z/y lie (the
// product terms cancel, so it stays a cubic). Caps are the even-odd inside
// test at the cap's height (planar_spline.h). Normals are made to face out
// of the solid by POV's inside test. POV-Ray 3.7 gives prisms no (u, v):
// lancer gives (0, 0).
#include <algorithm>
#include <cmath>

#include "geometry/planar_spline.h"
#include "geometry/polynomial_roots.h"
#include "geometry/shape.h"

namespace lancer {
namespace {

enum PrismFace { kBottom = 0, kTop = 1, kSide = 2 };

// ray_box_interval's x and z slabs for a box unbounded in y (whose y slab
// never narrows the interval), with the ray's inverses taken once for all
// of a curve's segment boxes: the same arithmetic, the same answers, not
// three divisions a segment (text is prisms of many segments).
struct RayShadow {
    double ox, oz, dx, dz, inverse_x, inverse_z;
    RayShadow(const DVec3& o, const DVec3& d)
        : ox(o.x), oz(o.z), dx(d.x), dz(d.z), inverse_x(1.0 / d.x), inverse_z(1.0 / d.z) {}

    bool crosses(const glm::dvec2& lower, const glm::dvec2& upper, double& near, double& far) const {
        return ray_slab_interval(ox, dx, inverse_x, lower.x, upper.x, near, far) &&
               ray_slab_interval(oz, dz, inverse_z, lower.y, upper.y, near, far);
    }
};

class PrismShape final : public Shape {
  public:
    PrismShape(std::vector<SplineSegment> segments, double height1, double height2, bool conic, bool open)
        : m_segments(std::move(segments)), m_h1(height1), m_h2(height2), m_conic(conic), m_open(open) {
        // The curves' exact box (each segment's extremes), as POV-Ray's:
        // min_extent and max_extent of a prism or a text (centring text
        // with them is common) are the outline's, not a padded box.
        m_boxes = segment_boxes(m_segments);
        m_lower2 = glm::dvec2(INFINITY);
        m_upper2 = glm::dvec2(-INFINITY);
        for (const SegmentBox& box : m_boxes) {
            m_lower2 = glm::min(m_lower2, box.lower);
            m_upper2 = glm::max(m_upper2, box.upper);
        }
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        // Caps.
        if (!m_open && d.y != 0.0) {
            for (int face : {kBottom, kTop}) {
                const double h = face == kBottom ? m_h1 : m_h2;
                const double t = (h - o.y) / d.y;
                if (!(t > t_min && t < t_max)) continue;
                glm::dvec2 q(o.x + t * d.x, o.z + t * d.z);
                if (m_conic) {
                    if (h == 0.0) continue;
                    q /= h;
                }
                if (inside_curves(m_segments, m_boxes, q)) out.add(t, face);
            }
        }
        // Sides: alpha x(s) + beta z(s) + gamma = 0.
        double alpha, beta, gamma;
        if (m_conic) {
            alpha = o.y * d.z - o.z * d.y;
            beta = o.x * d.y - o.y * d.x;
            gamma = o.z * d.x - o.x * d.z;
        } else {
            alpha = d.z;
            beta = -d.x;
            gamma = d.x * o.z - d.z * o.x;
        }
        if (alpha == 0.0 && beta == 0.0) return;
        // A linear sweep's side is met where the ray's shadow on the x-z
        // plane, over the stretch of it between the two heights, meets the
        // curve: a segment whose box that stretch misses has no crossing.
        // The heights are widened as the side test's height check rounds,
        // the boxes by the rounding of a ray from far away.
        double near = t_min, far = t_max;
        const double height_slack = 1e-9 * (std::fabs(m_h1) + std::fabs(m_h2)) + 1e-12;
        const double shadow_slack = 1e-13 * (std::fabs(o.x) + std::fabs(o.z));
        if (!m_conic && !ray_box_interval(DVec3(-INFINITY, m_h1 - height_slack, -INFINITY),
                                          DVec3(INFINITY, m_h2 + height_slack, INFINITY), o, d, near, far))
            return;
        const RayShadow shadow(o, d);
        const glm::dvec2 slack(shadow_slack);
        for (std::size_t index = 0; index < m_segments.size(); ++index) {
            const SegmentBox& box = m_boxes[index];
            double segment_near = near, segment_far = far;
            if (!m_conic && !shadow.crosses(box.lower - slack, box.upper + slack, segment_near, segment_far)) continue;
            const SplineSegment& s = m_segments[index];
            const double c[4] = {alpha * s.d.x + beta * s.d.y + gamma, alpha * s.c.x + beta * s.c.y,
                                 alpha * s.b.x + beta * s.b.y, alpha * s.a.x + beta * s.a.y};
            int degree = 3;
            while (degree > 0 && c[degree] == 0.0) --degree;
            if (degree == 0) continue;
            double roots[kMaxPolynomialDegree];
            const int n = polynomial_roots_in(c, degree, -1e-12, 1.0 + 1e-12, roots);
            for (int i = 0; i < n; ++i) {
                const double param = std::min(std::max(roots[i], 0.0), 1.0);
                if (param >= 1.0) continue;  // the next segment's start
                const glm::dvec2 p = s.at(param);
                double t;
                if (m_conic) {
                    // o + t d = y (p.x, 1, p.z): from the better conditioned of x and z.
                    const double ax = d.x - d.y * p.x, az = d.z - d.y * p.y;
                    t = std::fabs(ax) >= std::fabs(az) ? (o.y * p.x - o.x) / ax : (o.y * p.y - o.z) / az;
                } else {
                    t = std::fabs(d.x) >= std::fabs(d.z) ? (p.x - o.x) / d.x : (p.y - o.z) / d.z;
                }
                if (!(t > t_min && t < t_max) || !std::isfinite(t)) continue;
                const double y = o.y + t * d.y;
                if (y < m_h1 || y > m_h2) continue;
                out.add(t, kSide + int(index));
            }
        }
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        SurfaceGeometry g;
        g.uv = Vec2(0.0f);
        if (face == kBottom || face == kTop) {
            g.point = DVec3(p.x, face == kBottom ? m_h1 : m_h2, p.z);
            g.normal = DVec3(0.0, face == kBottom ? -1.0 : 1.0, 0.0);
            return g;
        }
        const SplineSegment& segment = m_segments[std::size_t(face - kSide)];
        const double y = std::clamp(p.y, m_h1, m_h2);
        const double scale = m_conic ? y : 1.0;
        const glm::dvec2 target = scale != 0.0 ? glm::dvec2(p.x, p.z) / scale : glm::dvec2(0.0);
        const double s = nearest_parameter(segment, target);
        const glm::dvec2 q = segment.at(s), tangent = segment.tangent(s);
        g.point = DVec3(scale * q.x, y, scale * q.y);
        DVec3 normal = m_conic ? DVec3(-tangent.y, tangent.y * q.x - tangent.x * q.y, tangent.x)
                               : DVec3(-tangent.y, 0.0, tangent.x);
        const double length = glm::length(normal);
        normal = length > 0.0 ? normal / length : DVec3(1.0, 0.0, 0.0);
        // Out of the solid: the side where POV's inside test fails.
        const double step = 1e-6 * std::max(1.0, glm::length(m_upper2 - m_lower2) * std::max(1.0, std::fabs(scale)));
        DVec3 probe = g.point + step * normal;
        probe.y = std::clamp(probe.y, m_h1 + 0.5 * (m_h2 - m_h1) * 1e-9, m_h2 - 0.5 * (m_h2 - m_h1) * 1e-9);
        if (inside(probe)) normal = -normal;
        g.normal = normal;
        return g;
    }

    bool inside(const DVec3& p) const override {
        if (!(p.y >= m_h1 && p.y < m_h2)) return false;
        glm::dvec2 q(p.x, p.z);
        if (m_conic) {
            if (std::fabs(p.y) <= 1e-10) return false;
            q /= p.y;
        }
        return inside_curves(m_segments, m_boxes, q);
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        if (!m_conic) {
            lower = DVec3(m_lower2.x, m_h1, m_lower2.y);
            upper = DVec3(m_upper2.x, m_h2, m_upper2.y);
            return true;
        }
        lower = DVec3(INFINITY);
        upper = DVec3(-INFINITY);
        for (double h : {m_h1, m_h2})
            for (const glm::dvec2& corner :
                 {m_lower2, m_upper2, glm::dvec2(m_lower2.x, m_upper2.y), glm::dvec2(m_upper2.x, m_lower2.y)}) {
                const DVec3 p(h * corner.x, h, h * corner.y);
                lower = glm::min(lower, p);
                upper = glm::max(upper, p);
            }
        return true;
    }

  private:
    // The parameter of the segment's point nearest `target` (samples, then Newton).
    static double nearest_parameter(const SplineSegment& segment, const glm::dvec2& target) {
        double best = 0.0, best_distance = INFINITY;
        for (int i = 0; i <= 16; ++i) {
            const double s = i / 16.0;
            const glm::dvec2 offset = segment.at(s) - target;
            const double distance = glm::dot(offset, offset);
            if (distance < best_distance) {
                best_distance = distance;
                best = s;
            }
        }
        for (int i = 0; i < 8; ++i) {
            const glm::dvec2 offset = segment.at(best) - target, tangent = segment.tangent(best);
            const glm::dvec2 second = 6.0 * segment.a * best + 2.0 * segment.b;
            const double derivative = glm::dot(offset, tangent);
            const double curvature = glm::dot(tangent, tangent) + glm::dot(offset, second);
            if (!(curvature > 0.0)) break;
            best = std::clamp(best - derivative / curvature, 0.0, 1.0);
        }
        return best;
    }

    std::vector<SplineSegment> m_segments;
    std::vector<SegmentBox> m_boxes;  // by segment (segment_boxes)
    double m_h1, m_h2;
    bool m_conic, m_open;
    glm::dvec2 m_lower2, m_upper2;
};

}  // namespace

std::shared_ptr<const Shape> make_prism_shape(const PrismParameters& prism) {
    std::vector<SplineSegment> segments = spline_segments(prism.spline, prism.points);
    if (segments.empty()) return nullptr;
    return std::make_shared<PrismShape>(std::move(segments), std::min(prism.height1, prism.height2),
                                        std::max(prism.height1, prism.height2), prism.conic, prism.open);
}

std::shared_ptr<const Shape> make_prism_shape(std::vector<SplineSegment> segments, double height1, double height2) {
    if (segments.empty()) return nullptr;
    return std::make_shared<PrismShape>(std::move(segments), std::min(height1, height2), std::max(height1, height2),
                                        false, false);
}

}  // namespace lancer
