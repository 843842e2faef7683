// POV-Ray's sphere_sweep: the union of the spheres of centre c(s) and
// radius |r(s)| for s in [0, 1] over every segment of a spline through (or
// near) the modeling spheres. Each segment is a polynomial in s of degree 1
// (linear_spline, from sphere i to i + 1) or 3 (b_spline and cubic_spline,
// POV's uniform B-spline and Catmull-Rom matrices over spheres i .. i + 3),
// the centre and the radius alike. The surface is the boundary of that
// union: the envelope of each segment's moving sphere (where
// f = |p - c(s)|^2 - r(s)^2 = 0 and df/ds = 0) and the spheres at the
// segment ends, less whatever lies inside another sphere of the sweep.
// POV gives it no (u, v) (3.7 has no UV code for it): (0, 0) here.
//
// Intersection: exact, per segment, by root finding in s (rather than
// conical frusta refined by Newton, whose chords can miss grazing hits and
// need a subdivision depth tuned to the curvature). Along the ray
// (unit direction D, origin q) f = tau^2 + 2 tau A(s) + B(s); the ray
// meets sphere s at tau = -A -+ sqrt(Delta), Delta = A^2 - B, and it meets
// the envelope where one of those is stationary in s, i.e. at the roots of
// P = Delta'^2 - 4 A'^2 Delta (degree 10, or 2 for linear segments; for
// those it is exactly the ray against the cone tangent to both end
// spheres). P has near-double roots exactly where the tube is seen square
// on (A' ~ 0: a planar sweep viewed along its normal), where its expanded
// coefficients cannot tell the pair apart. So P's coefficients only serve
// to find its critical points (polynomial_roots_in on P'); P itself is
// evaluated in the factored form above, whose rounding shrinks with the
// terms, and a critical point where P is zero within that rounding is a
// double root: both crossings of sphere s (POV's own fallback there). Each
// root gives tau from the sphere at s, which is stationary in s there, so
// an error in s moves the hit only quadratically. A crossing lying deeper
// than a relative 1e-9 inside any sphere of the sweep (found by minimising
// f over s per segment, a degree-5 derivative) is interior and dropped:
// this replaces POV's parity count, which needs paired crossings. The
// normal is exact and smooth: p - c(s*) at the s* minimising f at p.
// inside() is that union (min over s of f <= 0). POV's Inside looks for a
// root of f in [0, 1] instead, so it calls a point inside every sphere of a
// segment (the middle of a short fat one) outside; that is a POV bug which
// would make CSG disagree with the surface, so it is not copied.
#include "geometry/sphere_sweep.h"

#include <algorithm>
#include <cmath>

#include "geometry/polynomial_roots.h"

namespace lancer {
namespace {

constexpr double kEpsilon = 2.220446049250313e-16;
// How deep (relative to the segment's bounding radius) a point may lie in
// a sphere of the sweep and still count as on the surface.
constexpr double kCoveredDepth = 1e-9;
// Rounding of P's factored evaluation, in units of its terms' magnitudes.
constexpr double kRounding = 64.0 * kEpsilon;

// Polynomials in s, coefficients ascending.
double horner(const double* c, int degree, double s) {
    double value = c[degree];
    for (int i = degree - 1; i >= 0; --i) value = value * s + c[i];
    return value;
}

void multiply(const double* a, int a_degree, const double* b, int b_degree, double* product) {
    for (int i = 0; i <= a_degree + b_degree; ++i) product[i] = 0.0;
    for (int i = 0; i <= a_degree; ++i)
        for (int j = 0; j <= b_degree; ++j) product[i + j] += a[i] * b[j];
}

void differentiate(const double* c, int degree, double* derivative) {
    for (int i = 1; i <= degree; ++i) derivative[i - 1] = double(i) * c[i];
    if (degree == 0) derivative[0] = 0.0;
}

struct Segment {
    int degree = 1;  // of the centre and the radius in s
    // In units centred on `middle` and scaled by 1 / reach, so every
    // coefficient is O(1) whatever the sweep's size and position.
    DVec3 centre[4] = {DVec3(0.0), DVec3(0.0), DVec3(0.0), DVec3(0.0)};
    double radius[4] = {0.0, 0.0, 0.0, 0.0};
    double squared[7] = {};            // |centre(s)|^2 - radius(s)^2
    double squared_magnitude[7] = {};  // the same with every term's magnitude
    DVec3 middle{0.0};                 // bounding sphere, object units
    double reach = 0.0;
    DVec3 lower{0.0}, upper{0.0};  // bounding box, object units

    DVec3 centre_at(double s) const {
        DVec3 c = centre[degree];
        for (int i = degree - 1; i >= 0; --i) c = c * s + centre[i];
        return c;
    }
    double radius_at(double s) const { return horner(radius, degree, s); }
    bool holds(const DVec3& p) const {
        return p.x >= lower.x && p.y >= lower.y && p.z >= lower.z && p.x <= upper.x && p.y <= upper.y && p.z <= upper.z;
    }
    // The s in [0, 1] minimising f(p, s) = |p - c(s)|^2 - r(s)^2 (the
    // sphere p is deepest in, or nearest outside), with p in the segment's
    // units; returns that minimum.
    double deepest(const DVec3& q, double& s_best) const {
        const int n = 2 * degree;
        double f[7] = {}, slope[6] = {};
        for (int k = 0; k <= n; ++k) f[k] = squared[k];
        for (int k = 0; k <= degree; ++k) f[k] -= 2.0 * glm::dot(q, centre[k]);
        f[0] += glm::dot(q, q);
        differentiate(f, n, slope);
        double roots[kMaxPolynomialDegree];
        const int count = polynomial_roots_in(slope, n - 1, 0.0, 1.0, roots);
        s_best = 0.0;
        double best = f[0];
        const double at_end = horner(f, n, 1.0);
        if (at_end < best) best = at_end, s_best = 1.0;
        for (int i = 0; i < count; ++i) {
            const double value = horner(f, n, roots[i]);
            if (value < best) best = value, s_best = roots[i];
        }
        return best;
    }
};

struct JointSphere {
    DVec3 centre{0.0};
    double radius = 0.0;  // >= 0
};

// The nearest crossings found so far (as many as ShapeCrossings holds),
// ascending, without near-duplicates (a segment's envelope meets its end
// spheres tangentially, so both may report one point).
class NearestCrossings {
  public:
    explicit NearestCrossings(double merge_distance) : m_merge(merge_distance) {}
    bool wants(double t) const { return m_count < ShapeCrossings::kCapacity || t < m_items[m_count - 1].t; }
    void add(double t, int face) {
        const double merge = std::max(m_merge, 1e-14 * std::fabs(t));
        for (int i = 0; i < m_count; ++i)
            if (std::fabs(m_items[i].t - t) <= merge) return;
        int at = std::min(m_count, ShapeCrossings::kCapacity - 1);
        while (at > 0 && m_items[at - 1].t > t) {
            if (at < ShapeCrossings::kCapacity) m_items[at] = m_items[at - 1];
            --at;
        }
        m_items[at] = ShapeCrossing{t, face};
        if (m_count < ShapeCrossings::kCapacity) ++m_count;
    }
    void copy_to(ShapeCrossings& out) const {
        for (int i = 0; i < m_count; ++i) out.add(m_items[i].t, m_items[i].face);
    }

  private:
    ShapeCrossing m_items[ShapeCrossings::kCapacity];
    int m_count = 0;
    double m_merge;
};

// One ray's query: its origin, unit direction and accepted interval.
struct RayQuery {
    DVec3 origin;
    DVec3 d;          // as given
    DVec3 direction;  // unit
    double length;    // |d|: t = distance / length
    double t_lo, t_hi;
};

// Joint spheres are faces -1, -2, ...; segment i's envelope is face i.
int sphere_face(int index) {
    return -1 - index;
}
int sphere_of_face(int face) {
    return -1 - face;
}

class SphereSweepShape final : public Shape {
  public:
    SphereSweepShape(std::vector<Segment> segments, std::vector<JointSphere> spheres, double tolerance)
        : m_segments(std::move(segments)), m_spheres(std::move(spheres)), m_tolerance(tolerance) {
        m_lower = DVec3(INFINITY);
        m_upper = DVec3(-INFINITY);
        for (const Segment& s : m_segments) {
            m_lower = glm::min(m_lower, s.lower);
            m_upper = glm::max(m_upper, s.upper);
        }
        m_size = 0.5 * glm::length(m_upper - m_lower);
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double length = glm::length(d);
        if (!(length > 0.0) || !std::isfinite(length)) return;
        const RayQuery ray{o, d, d / length, length, std::max(t_min, m_tolerance), t_max};
        if (!(ray.t_lo < ray.t_hi)) return;
        double box_lo = ray.t_lo, box_hi = ray.t_hi;
        if (!ray_box_interval(m_lower, m_upper, o, d, box_lo, box_hi)) return;
        NearestCrossings kept(1e-9 * m_size / length);
        for (std::size_t k = 0; k < m_spheres.size(); ++k) sphere_crossings(ray, int(k), kept);
        for (std::size_t i = 0; i < m_segments.size(); ++i) envelope_crossings(ray, int(i), kept);
        kept.copy_to(out);
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        DVec3 centre;
        double radius;
        if (face < 0 && sphere_of_face(face) < int(m_spheres.size())) {
            centre = m_spheres[sphere_of_face(face)].centre;
            radius = m_spheres[sphere_of_face(face)].radius;
        } else {
            // The sphere of the sweep p lies on: the one minimising f at p.
            int index = face;
            if (index < 0 || index >= int(m_segments.size())) index = nearest_segment(p);
            const Segment& segment = m_segments[index];
            double s;
            segment.deepest((p - segment.middle) / segment.reach, s);
            centre = segment.middle + segment.reach * segment.centre_at(s);
            radius = segment.reach * std::fabs(segment.radius_at(s));
        }
        SurfaceGeometry g;
        const DVec3 offset = p - centre;
        const double distance = glm::length(offset);
        g.normal = distance > 0.0 && std::isfinite(distance) ? offset / distance : DVec3(0.0, 1.0, 0.0);
        g.point = centre + radius * g.normal;
        g.uv = Vec2(0.0f);
        return g;
    }

    bool inside(const DVec3& p) const override {
        for (const Segment& segment : m_segments) {
            if (!segment.holds(p)) continue;
            double s;
            if (segment.deepest((p - segment.middle) / segment.reach, s) <= 0.0) return true;
        }
        return false;
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = m_lower;
        upper = m_upper;
        return true;
    }

  private:
    // Keeps the crossing at t unless it lies inside the sweep.
    void consider(const RayQuery& ray, double t, int face, NearestCrossings& kept) const {
        if (!(t > ray.t_lo && t < ray.t_hi) || !kept.wants(t)) return;
        const DVec3 p = ray.origin + t * ray.d;
        if (covered(p)) return;
        kept.add(t, face);
    }

    bool covered(const DVec3& p) const {
        for (const Segment& segment : m_segments) {
            if (!segment.holds(p)) continue;
            const DVec3 q = (p - segment.middle) / segment.reach;
            double s;
            if (segment.deepest(q, s) >= 0.0) continue;
            const double depth = std::fabs(segment.radius_at(s)) - glm::length(q - segment.centre_at(s));
            if (depth > kCoveredDepth) return true;
        }
        return false;
    }

    int nearest_segment(const DVec3& p) const {
        int best_index = 0;
        double best = INFINITY;
        for (std::size_t i = 0; i < m_segments.size(); ++i) {
            const Segment& segment = m_segments[i];
            double s;
            const DVec3 q = (p - segment.middle) / segment.reach;
            const double value = segment.deepest(q, s) * segment.reach * segment.reach;
            if (value < best) best = value, best_index = int(i);
        }
        return best_index;
    }

    void sphere_crossings(const RayQuery& ray, int index, NearestCrossings& kept) const {
        const JointSphere& sphere = m_spheres[index];
        if (!(sphere.radius > 0.0)) return;
        // From the ray's closest approach to the centre: no cancellation.
        const double along = glm::dot(sphere.centre - ray.origin, ray.direction);
        const DVec3 miss = ray.origin + along * ray.direction - sphere.centre;
        const double half_chord2 = sphere.radius * sphere.radius - glm::dot(miss, miss);
        if (!(half_chord2 > 0.0)) return;
        const double half_chord = std::sqrt(half_chord2);
        consider(ray, (along - half_chord) / ray.length, sphere_face(index), kept);
        consider(ray, (along + half_chord) / ray.length, sphere_face(index), kept);
    }

    void envelope_crossings(const RayQuery& ray, int index, NearestCrossings& kept) const {
        const Segment& seg = m_segments[index];
        const DVec3& D = ray.direction;
        // The ray from its closest approach to the bounding sphere's centre,
        // in the segment's units (tau = distance / reach from there).
        const double along = glm::dot(seg.middle - ray.origin, D);
        const DVec3 q = (ray.origin + along * D - seg.middle) / seg.reach;
        const double q2 = glm::dot(q, q);
        if (!(q2 < 1.0)) return;
        const double half = seg.reach * std::sqrt(1.0 - q2);
        if ((along + half) / ray.length <= ray.t_lo || (along - half) / ray.length >= ray.t_hi) return;

        // A(s) = D.(q - c(s)), B(s) = |q - c(s)|^2 - r(s)^2, with term magnitudes.
        const int n = seg.degree, n2 = 2 * n;
        double A[4], A_mag[4], B[7], B_mag[7];
        for (int k = 0; k <= n; ++k) {
            A[k] = -glm::dot(D, seg.centre[k]);
            A_mag[k] = std::fabs(A[k]);
        }
        A[0] += glm::dot(D, q);
        A_mag[0] += std::fabs(glm::dot(D, q));
        for (int k = 0; k <= n2; ++k) {
            B[k] = seg.squared[k];
            B_mag[k] = seg.squared_magnitude[k];
        }
        for (int k = 0; k <= n; ++k) {
            const double cross = 2.0 * glm::dot(q, seg.centre[k]);
            B[k] -= cross;
            B_mag[k] += std::fabs(cross);
        }
        B[0] += q2;
        B_mag[0] += q2;
        // Delta = A^2 - B (the squared half chord of sphere s), A', Delta'.
        EnvelopePolynomials e;
        e.degree = n;
        double AA[7], AA_mag[7];
        multiply(A, n, A, n, AA);
        multiply(A_mag, n, A_mag, n, AA_mag);
        for (int k = 0; k <= n2; ++k) {
            e.delta[k] = AA[k] - B[k];
            e.delta_mag[k] = AA_mag[k] + B_mag[k];
        }
        differentiate(A, n, e.slope_a);
        differentiate(A_mag, n, e.slope_a_mag);
        differentiate(e.delta, n2, e.slope_delta);
        differentiate(e.delta_mag, n2, e.slope_delta_mag);
        // P = Delta'^2 - 4 A'^2 Delta, degree 4n - 2, and P'.
        const int p_degree = 4 * n - 2;
        double sd2[11], sa2[5], sa2_delta[11], P[11], P_slope[10];
        multiply(e.slope_delta, n2 - 1, e.slope_delta, n2 - 1, sd2);
        multiply(e.slope_a, n - 1, e.slope_a, n - 1, sa2);
        multiply(sa2, 2 * n - 2, e.delta, n2, sa2_delta);
        for (int k = 0; k <= p_degree; ++k) P[k] = sd2[k] - 4.0 * sa2_delta[k];
        differentiate(P, p_degree, P_slope);

        // P is monotonic between its critical points: a sign change between
        // two is one simple root; a critical point where P vanishes within
        // its rounding is a double root.
        double ends[kMaxPolynomialDegree + 2];
        int end_count = 0;
        ends[end_count++] = 0.0;
        end_count += polynomial_roots_in(P_slope, p_degree - 1, 0.0, 1.0, ends + 1);
        ends[end_count++] = 1.0;
        double values[kMaxPolynomialDegree + 2];
        for (int i = 0; i < end_count; ++i) {
            const EnvelopeTerms terms = e.at(ends[i]);
            values[i] = std::fabs(terms.value) <= terms.error ? 0.0 : terms.value;
        }
        const EnvelopeContext context{ray, seg, q, along, index};
        for (int i = 0; i + 1 < end_count; ++i) {
            if (values[i] != 0.0 && values[i + 1] != 0.0 && (values[i] < 0.0) != (values[i + 1] < 0.0)) {
                const double s = e.root_between(P_slope, p_degree - 1, ends[i], ends[i + 1], values[i]);
                emit_root(context, e, s, false, kept);
            }
            if (i > 0 && values[i] == 0.0) emit_root(context, e, ends[i], true, kept);
        }
    }

    struct EnvelopeTerms {
        double delta, slope_delta, slope_a;
        double delta_error, slope_delta_error, slope_a_error;
        double value, error;  // P and a bound on its rounding
    };

    struct EnvelopePolynomials {
        int degree = 1;
        double delta[7], delta_mag[7], slope_delta[6], slope_delta_mag[6], slope_a[3], slope_a_mag[3];

        EnvelopeTerms at(double s) const {
            const int n2 = 2 * degree;
            EnvelopeTerms t;
            t.delta = horner(delta, n2, s);
            t.slope_delta = horner(slope_delta, n2 - 1, s);
            t.slope_a = horner(slope_a, degree - 1, s);
            t.delta_error = kRounding * horner(delta_mag, n2, s);
            t.slope_delta_error = kRounding * horner(slope_delta_mag, n2 - 1, s);
            t.slope_a_error = kRounding * horner(slope_a_mag, degree - 1, s);
            const double a2 = t.slope_a * t.slope_a;
            t.value = t.slope_delta * t.slope_delta - 4.0 * a2 * t.delta;
            t.error = (2.0 * std::fabs(t.slope_delta) + t.slope_delta_error) * t.slope_delta_error +
                      4.0 * (a2 * t.delta_error + (2.0 * std::fabs(t.slope_a) + t.slope_a_error) * t.slope_a_error *
                                                      (std::fabs(t.delta) + t.delta_error));
            return t;
        }

        // The root of P in (lo, hi), P(lo) = value_lo and P(hi) of the other
        // sign: Newton steps on P' kept inside the shrinking bracket.
        double root_between(const double* slope, int slope_degree, double lo, double hi, double value_lo) const {
            double s = 0.5 * (lo + hi);
            for (int iteration = 0; iteration < 100; ++iteration) {
                const double value = at(s).value;
                if (value == 0.0) return s;
                if ((value < 0.0) == (value_lo < 0.0)) {
                    lo = s;
                } else {
                    hi = s;
                }
                const double derivative = horner(slope, slope_degree, s);
                double next = derivative != 0.0 ? s - value / derivative : 0.5 * (lo + hi);
                if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
                if (next == s || hi - lo <= 4.0 * kEpsilon) return next;
                s = next;
            }
            return s;
        }
    };

    struct EnvelopeContext {
        const RayQuery& ray;
        const Segment& segment;
        DVec3 q;       // the ray's origin, segment units
        double along;  // its distance from the caller's origin, object units
        int index;
    };

    // The envelope crossing(s) for root s of P: the ray's crossing of sphere
    // s that is stationary in s (entering where Delta' and A' differ in
    // sign, leaving where they agree), both crossings for a double root.
    void emit_root(const EnvelopeContext& c, const EnvelopePolynomials& e, double s, bool both,
                   NearestCrossings& kept) const {
        if (!(s > 0.0 && s < 1.0)) return;  // the end spheres hold those
        const EnvelopeTerms terms = e.at(s);
        const double product = terms.slope_delta * terms.slope_a;
        const double product_error = std::fabs(terms.slope_delta) * terms.slope_a_error +
                                     std::fabs(terms.slope_a) * terms.slope_delta_error +
                                     terms.slope_delta_error * terms.slope_a_error;
        const bool entering = both || product <= product_error;
        const bool leaving = both || product >= -product_error;
        // The ray against sphere s itself, from the ray's origin q.
        const DVec3 w = c.segment.centre_at(s) - c.q;
        const double w_along = glm::dot(w, c.ray.direction);
        const DVec3 w_across = w - w_along * c.ray.direction;
        const double r = c.segment.radius_at(s);
        double half_chord2 = r * r - glm::dot(w_across, w_across);
        if (half_chord2 < 0.0) {
            if (half_chord2 < -1e-12) return;
            half_chord2 = 0.0;
        }
        const double half_chord = std::sqrt(half_chord2);
        const double scale = c.segment.reach / c.ray.length, base = c.along / c.ray.length;
        if (entering) consider(c.ray, base + scale * (w_along - half_chord), c.index, kept);
        if (leaving) consider(c.ray, base + scale * (w_along + half_chord), c.index, kept);
    }

    std::vector<Segment> m_segments;
    std::vector<JointSphere> m_spheres;
    double m_tolerance;
    DVec3 m_lower{0.0}, m_upper{0.0};
    double m_size = 0.0;
};

// POV's basis matrices (row k: the weights of the four spheres in s^k).
constexpr double kBSpline[4][4] = {{1.0 / 6.0, 4.0 / 6.0, 1.0 / 6.0, 0.0},
                                   {-3.0 / 6.0, 0.0, 3.0 / 6.0, 0.0},
                                   {3.0 / 6.0, -6.0 / 6.0, 3.0 / 6.0, 0.0},
                                   {-1.0 / 6.0, 3.0 / 6.0, -3.0 / 6.0, 1.0 / 6.0}};
constexpr double kCatmullRom[4][4] = {
    {0.0, 1.0, 0.0, 0.0}, {-0.5, 0.0, 0.5, 0.0}, {1.0, -2.5, 2.0, -0.5}, {-0.5, 1.5, -1.5, 0.5}};

// A segment from its power-basis centre and radius coefficients (object
// units): bounds from its Bezier control points, which hold the curve.
bool build_segment(int degree, const DVec3* centre, const double* radius, Segment& seg) {
    seg.degree = degree;
    DVec3 control[4];
    double control_radius[4];
    if (degree == 1) {
        control[0] = centre[0], control[1] = centre[0] + centre[1];
        control_radius[0] = radius[0], control_radius[1] = radius[0] + radius[1];
    } else {
        control[0] = centre[0];
        control[1] = centre[0] + centre[1] / 3.0;
        control[2] = centre[0] + 2.0 * centre[1] / 3.0 + centre[2] / 3.0;
        control[3] = centre[0] + centre[1] + centre[2] + centre[3];
        control_radius[0] = radius[0];
        control_radius[1] = radius[0] + radius[1] / 3.0;
        control_radius[2] = radius[0] + 2.0 * radius[1] / 3.0 + radius[2] / 3.0;
        control_radius[3] = radius[0] + radius[1] + radius[2] + radius[3];
    }
    double largest_radius = 0.0;
    seg.lower = DVec3(INFINITY);
    seg.upper = DVec3(-INFINITY);
    for (int i = 0; i <= degree; ++i) {
        largest_radius = std::max(largest_radius, std::fabs(control_radius[i]));
        seg.lower = glm::min(seg.lower, control[i]);
        seg.upper = glm::max(seg.upper, control[i]);
    }
    seg.lower -= DVec3(largest_radius);
    seg.upper += DVec3(largest_radius);
    seg.middle = 0.5 * (seg.lower + seg.upper);
    seg.reach = 0.5 * glm::length(seg.upper - seg.lower);
    // A segment of zero-radius spheres at one point has no surface.
    if (!(seg.reach > 0.0) || !std::isfinite(seg.reach)) return false;
    for (int k = 0; k <= degree; ++k) {
        seg.centre[k] = (k == 0 ? centre[0] - seg.middle : centre[k]) / seg.reach;
        seg.radius[k] = radius[k] / seg.reach;
    }
    for (int i = 0; i <= degree; ++i)
        for (int j = 0; j <= degree; ++j) {
            seg.squared[i + j] += glm::dot(seg.centre[i], seg.centre[j]) - seg.radius[i] * seg.radius[j];
            seg.squared_magnitude[i + j] +=
                glm::length(seg.centre[i]) * glm::length(seg.centre[j]) + std::fabs(seg.radius[i] * seg.radius[j]);
        }
    return true;
}

}  // namespace

std::shared_ptr<const Shape> make_sphere_sweep_shape(SphereSweepSpline spline, const std::vector<glm::dvec4>& spheres,
                                                     double tolerance) {
    const int count = int(spheres.size());
    if (count < 2 || (spline != SphereSweepSpline::Linear && count < 4)) return nullptr;
    if (!std::isfinite(tolerance)) return nullptr;
    for (const glm::dvec4& s : spheres)
        if (!std::isfinite(s.x + s.y + s.z + s.w)) return nullptr;

    std::vector<Segment> segments;
    std::vector<JointSphere> joints;
    auto add_joint = [&](const DVec3& centre, double radius) { joints.push_back({centre, std::fabs(radius)}); };
    if (spline == SphereSweepSpline::Linear) {
        for (int i = 0; i + 1 < count; ++i) {
            const DVec3 centre[2] = {DVec3(spheres[i]), DVec3(spheres[i + 1]) - DVec3(spheres[i])};
            const double radius[2] = {spheres[i].w, spheres[i + 1].w - spheres[i].w};
            Segment seg;
            if (build_segment(1, centre, radius, seg)) segments.push_back(seg);
        }
        for (const glm::dvec4& s : spheres) add_joint(DVec3(s), s.w);
    } else {
        const auto& basis = spline == SphereSweepSpline::BSpline ? kBSpline : kCatmullRom;
        for (int i = 0; i + 3 < count; ++i) {
            DVec3 centre[4];
            double radius[4];
            for (int k = 0; k < 4; ++k) {
                centre[k] = DVec3(0.0);
                radius[k] = 0.0;
                for (int m = 0; m < 4; ++m) {
                    centre[k] += basis[k][m] * DVec3(spheres[i + m]);
                    radius[k] += basis[k][m] * spheres[i + m].w;
                }
            }
            // Joints: each segment's start, and the last segment's end.
            add_joint(centre[0], radius[0]);
            if (i + 4 == count)
                add_joint(centre[0] + centre[1] + centre[2] + centre[3], radius[0] + radius[1] + radius[2] + radius[3]);
            Segment seg;
            if (build_segment(3, centre, radius, seg)) segments.push_back(seg);
        }
    }
    if (segments.empty()) {
        // Every sphere has radius 0 at one point: nothing to hit, but a shape.
        Segment point;
        point.middle = DVec3(spheres[0]);
        point.reach = 1.0;
        point.lower = point.upper = point.middle;
        point.squared[0] = 1.0;  // f > 0 everywhere: never inside
        point.squared_magnitude[0] = 1.0;
        segments.push_back(point);
    }
    return std::make_shared<SphereSweepShape>(std::move(segments), std::move(joints), tolerance);
}

}  // namespace lancer
