// POV-Ray's superellipsoid { <e, n> }: the unit ball of the "norm"
// N(p) = ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2), evaluated as
// POV's evaluate_g does (ratios, so no power overflows). N is homogeneous
// of degree 1, so a point projects onto the surface exactly as p / N(p).
//
// Crossings are where f(t) = N(o + t d) - 1 changes sign inside the unit
// box, each found by Illinois false position to the last bits of t.
// - For e, n <= 2 (the usual, rounded shapes) N is a norm, so f is convex
//   along the ray: at most two crossings, on either side of its minimum.
//   The minimum is sought only until it is found below 0 or proven above:
//   a convex function lies above every chord's extension, and
//   |f(t) - f(s)| <= |t - s| N(d) (the triangle inequality), so lines
//   through the samples bound each stretch between them from below. A ray
//   that misses is dismissed in a few samples, a grazing one is followed
//   to its thin pair of crossings.
// - The pinched shapes (e or n above 2) can turn back along a ray: the
//   ray is cut where it crosses x = 0, y = 0 or z = 0 (where |.| bends f),
//   each piece is sampled, and where the samples dip towards 0 without
//   changing sign a golden-section search looks for the dip. It stops when
//   the dip is proven absent: with r = min(2/e, 2/n) < 1, N^r is
//   subadditive, so |N^r(o + t d) - N^r(o + s d)| <= |t - s|^r N(d)^r.
// POV-Ray 3.7 gives the shape no (u, v): lancer gives (0, 0).
#include <algorithm>
#include <cmath>

#include "geometry/shape.h"

namespace lancer {
namespace {

// (x^e + y^e)^(1/e) for x, y >= 0, as POV's evaluate_g; the common
// exponents 1 and 2 (e or n of 2 and 1) without pow.
double combine(double x, double y, double e) {
    const double larger = std::max(x, y), smaller = std::min(x, y);
    if (larger == 0.0) return 0.0;
    const double ratio = smaller / larger;
    if (e == 2.0) return larger * std::sqrt(1.0 + ratio * ratio);
    if (e == 1.0) return larger + smaller;
    return larger * std::pow(1.0 + std::pow(ratio, e), 1.0 / e);
}

// x^e for x >= 0 where e may be 0 or 1.
double power_of(double x, double e) {
    if (e == 0.0) return 1.0;
    if (e == 1.0) return x;
    return std::pow(x, e);
}

class SuperellipsoidShape final : public Shape {
  public:
    SuperellipsoidShape(double e, double n)
        : m_p(2.0 / e), m_q(2.0 / n), m_convex(e <= 2.0 && n <= 2.0), m_exponent(std::min({1.0, m_p, m_q})) {}

    double norm(const DVec3& p) const {
        return combine(combine(std::fabs(p.x), std::fabs(p.y), m_p), std::fabs(p.z), m_q);
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        find_crossings(o, d, t_min, t_max, false, out);
    }

    // The first crossing alone: the second of a pair is never refined.
    bool nearest(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossing& hit) const override {
        ShapeCrossings found;
        find_crossings(o, d, t_min, t_max, true, found);
        if (found.count == 0) return false;
        hit = *std::min_element(found.items, found.items + found.count,
                                [](const ShapeCrossing& a, const ShapeCrossing& b) { return a.t < b.t; });
        return true;
    }

    SurfaceGeometry surface(const DVec3& p, int) const override {
        SurfaceGeometry g;
        const double n = norm(p);
        g.point = n > 0.0 ? p / n : p;
        g.normal = m_convex ? convex_normal_at(g.point) : normal_at(g.point);
        g.uv = Vec2(0.0f);
        return g;
    }

    bool inside(const DVec3& p) const override { return norm(p) - 1.0 < 1e-10; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = DVec3(-1.0);
        upper = DVec3(1.0);
        return true;
    }

  private:
    // Every crossing in (t_min, t_max), or with first_only at least the
    // nearest of them.
    void find_crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, bool first_only,
                        ShapeCrossings& out) const {
        double lo = t_min, hi = t_max;
        const double slack = 1e-9;
        if (!ray_box_interval(DVec3(-1.0 - slack), DVec3(1.0 + slack), o, d, lo, hi)) return;
        const auto f = [&](double t) { return norm(o + t * d) - 1.0; };
        const auto add = [&](double t) {
            if (t > t_min && t < t_max) out.add(t, 0);
        };
        if (m_convex) {
            convex_crossings(f, lo, hi, norm(d), first_only, out, add);
        } else {
            pinched_crossings(f, o, d, lo, hi, first_only, out, add);
        }
    }

    // Margins on f that cover N's rounding (a few ulps of each power).
    static constexpr double kMargin = 1e-12;

    template <class F, class Add>
    static void convex_crossings(const F& f, double lo, double hi, double lipschitz, bool first_only,
                                 const ShapeCrossings& out, const Add& add) {
        const double f_lo = f(lo), f_hi = f(hi);
        if (f_lo < 0.0 || f_hi < 0.0) {
            // An end inside (the ray starts in the solid or t_max stops it
            // there): one crossing at most, where the sign changes. An end on
            // the surface (f = 0) is searched from as from outside: a ray
            // leaving the surface inwards still finds its way out.
            if ((f_lo < 0.0) != (f_hi < 0.0)) add(refine_crossing(f, lo, hi, f_lo, f_hi));
            return;
        }
        constexpr int kMaxSamples = 72;
        double ts[kMaxSamples], fs[kMaxSamples];
        int count = 2;
        ts[0] = lo, fs[0] = f_lo, ts[1] = hi, fs[1] = f_hi;
        while (count < kMaxSamples) {
            const int lowest = static_cast<int>(std::min_element(fs, fs + count) - fs);
            // The minimum lies on one of the two stretches beside the lowest
            // sample: bound each from below, sample the lower bound's place.
            double best_bound = HUGE_VAL, best_t = 0.0;
            int best_stretch = -1;
            for (int j = std::max(0, lowest - 1); j <= std::min(lowest, count - 2); ++j) {
                // Rising from the right end of the chord before, falling to the
                // left end of the chord after (or at the steepest N allows).
                double left_slope = -lipschitz, right_slope = lipschitz;
                if (j > 0) left_slope = std::max(left_slope, (fs[j] - fs[j - 1]) / (ts[j] - ts[j - 1]));
                if (j + 2 < count)
                    right_slope = std::min(right_slope, (fs[j + 2] - fs[j + 1]) / (ts[j + 2] - ts[j + 1]));
                const double a = ts[j], b = ts[j + 1];
                const auto bound_at = [&](double t) {
                    return std::max(fs[j] + left_slope * (t - a), fs[j + 1] + right_slope * (t - b));
                };
                double t_low = bound_at(a) <= bound_at(b) ? a : b;
                if (left_slope < right_slope) {
                    const double meet =
                        (fs[j + 1] - fs[j] + left_slope * a - right_slope * b) / (left_slope - right_slope);
                    if (meet > a && meet < b && bound_at(meet) < bound_at(t_low)) t_low = meet;
                }
                const double bound = bound_at(t_low);
                if (bound < best_bound) {
                    best_bound = bound;
                    best_stretch = j;
                    // Inside the stretch, at least an eighth of it from either end.
                    const double eighth = 0.125 * (b - a);
                    best_t = std::clamp(t_low, a + eighth, b - eighth);
                }
            }
            if (best_stretch < 0 || best_bound > kMargin) return;  // the minimum stays above 1
            const int j = best_stretch;
            const double t = best_t;
            if (!(t > ts[j] && t < ts[j + 1])) return;  // a stretch of one ulp: tangent
            // Below 0 strictly: a sample on the surface (a ray leaving it,
            // whose start rounds to it) is no way in.
            const double value = f(t);
            if (value < 0.0) {
                const int before = out.count;
                add(refine_crossing(f, ts[j], t, fs[j], value));
                if (!first_only || out.count == before) add(refine_crossing(f, t, ts[j + 1], value, fs[j + 1]));
                return;
            }
            std::copy_backward(ts + j + 1, ts + count, ts + count + 1);
            std::copy_backward(fs + j + 1, fs + count, fs + count + 1);
            ts[j + 1] = t, fs[j + 1] = value;
            ++count;
        }
    }

    template <class F, class Add>
    void pinched_crossings(const F& f, const DVec3& o, const DVec3& d, double lo, double hi, bool first_only,
                           const ShapeCrossings& out, const Add& add) const {
        // The Hölder bound is too weak to prove anything for e or n above 8:
        // not tried there.
        const bool provable = m_exponent >= 0.25;
        const double reach = provable ? power(norm(d)) : 0.0;
        // Pieces between the ray's crossings of the coordinate planes.
        double cuts[5] = {lo, hi, hi, hi, hi};
        int count = 1;
        for (int axis = 0; axis < 3; ++axis) {
            if (d[axis] == 0.0) continue;
            const double t = -o[axis] / d[axis];
            if (t > lo && t < hi) cuts[count++] = t;
        }
        cuts[count++] = hi;
        std::sort(cuts, cuts + count);
        // The pieces in order along the ray, so the first to hold a crossing
        // holds the nearest.
        double f_cut = f(cuts[0]);
        for (int piece = 0; piece + 1 < count && !(first_only && out.count > 0); ++piece) {
            const double a = cuts[piece], b = cuts[piece + 1];
            if (!(b > a)) continue;
            constexpr int kSamples = 8;
            double samples[kSamples + 1];
            samples[0] = f_cut;
            samples[kSamples] = f_cut = f(b);
            if (provable && samples[0] > 0.0 && samples[kSamples] > 0.0 &&
                dip_excluded(samples[0], samples[kSamples], b - a, reach))
                continue;
            int lowest = 0;
            bool found = false;
            for (int i = 1; i <= kSamples; ++i) {
                const double t = a + (b - a) * i / kSamples, t_prev = a + (b - a) * (i - 1) / kSamples;
                if (i < kSamples) samples[i] = f(t);
                if ((samples[i] < 0.0) != (samples[i - 1] < 0.0)) {
                    add(refine_crossing(f, t_prev, t, samples[i - 1], samples[i]));
                    found = true;
                }
                if (samples[i] < samples[lowest]) lowest = i;
            }
            if (found || samples[lowest] <= 0.0) continue;
            // No sign change: the minimum may still dip below 0 between samples.
            const double step = (b - a) / kSamples;
            const int left_index = std::max(0, lowest - 1), right_index = std::min(kSamples, lowest + 1);
            double left = a + step * left_index, right = a + step * right_index;
            double f_left = samples[left_index], f_right = samples[right_index];
            const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
            double x1 = right - ratio * (right - left), x2 = left + ratio * (right - left);
            double f1 = f(x1), f2 = f(x2);
            for (int i = 0; i < 60 && f1 > 0.0 && f2 > 0.0; ++i) {
                if (i % 4 == 0 && provable && dip_excluded(f_left, f1, x1 - left, reach) &&
                    dip_excluded(f1, f2, x2 - x1, reach) && dip_excluded(f2, f_right, right - x2, reach))
                    break;
                if (f1 < f2) {
                    right = x2, f_right = f2;
                    x2 = x1, f2 = f1;
                    x1 = right - ratio * (right - left);
                    f1 = f(x1);
                } else {
                    left = x1, f_left = f1;
                    x1 = x2, f1 = f2;
                    x2 = left + ratio * (right - left);
                    f2 = f(x2);
                }
            }
            const double t_dip = f1 <= f2 ? x1 : x2, f_dip = std::min(f1, f2);
            if (!(f_dip <= 0.0)) continue;
            add(refine_crossing(f, a, t_dip, samples[0], f_dip));
            add(refine_crossing(f, t_dip, b, f_dip, samples[kSamples]));
        }
    }

    double power(double x) const { return std::pow(x, m_exponent); }

    // Whether N stays above 1 on a stretch of the given width between two
    // samples of f = N - 1 (the Hölder bound above, each end covering the
    // nearer half).
    bool dip_excluded(double f_a, double f_b, double width, double reach) const {
        return power(1.0 + std::min(f_a, f_b)) - power(0.5 * width) * reach > 1.0 + kMargin;
    }

    // The t in [a, b] where f = 0, given f_a and f_b of opposite signs (or
    // one of them 0): Illinois false position, halving the bracket when it
    // shrinks slowly, to the last bits of t.
    template <class F>
    static double refine_crossing(const F& f, double a, double b, double f_a, double f_b) {
        // An end on the surface is the crossing (add() drops it at t_min).
        if (f_a == 0.0) return a;
        if (f_b == 0.0) return b;
        if (b < a) {
            std::swap(a, b);
            std::swap(f_a, f_b);
        }
        int kept_side = 0;
        double width = b - a;
        for (int i = 0; i < 200; ++i) {
            const bool halve = i % 4 == 3 && b - a > 0.5 * width;
            if (i % 4 == 3) width = b - a;
            double t = halve ? 0.5 * (a + b) : (a * f_b - b * f_a) / (f_b - f_a);
            if (!(t > a && t < b)) t = 0.5 * (a + b);
            if (!(t > a && t < b)) break;
            const double value = f(t);
            if (value == 0.0) return t;
            if ((value < 0.0) == (f_b < 0.0)) {
                b = t, f_b = value;
                if (kept_side == -1) f_a *= 0.5;
                kept_side = -1;
            } else {
                a = t, f_a = value;
                if (kept_side == 1) f_b *= 0.5;
                kept_side = 1;
            }
        }
        return 0.5 * (a + b);
    }

    // N's gradient on the surface (N = 1): with A = (|x|^p + |y|^p)^(1/p),
    // dN/dx = A^(q-1) (|x| / A)^(p-1) sign(x), dN/dz = |z|^(q-1) sign(z).
    // Bounded for p, q >= 1; at a crease (p or q = 1, a coordinate 0) the
    // coordinate's term is left 0, the mean of the two sides.
    DVec3 convex_normal_at(const DVec3& p) const {
        const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
        const auto sign = [](double v) { return v > 0.0 ? 1.0 : v < 0.0 ? -1.0 : 0.0; };
        const double a = combine(ax, ay, m_p);
        DVec3 gradient(0.0, 0.0, sign(p.z) * power_of(az, m_q - 1.0));
        if (a > 0.0) {
            const double outer = power_of(a, m_q - 1.0);
            gradient.x = sign(p.x) * outer * power_of(ax / a, m_p - 1.0);
            gradient.y = sign(p.y) * outer * power_of(ay / a, m_p - 1.0);
        }
        const double length = glm::length(gradient);
        if (length > 0.0 && std::isfinite(length)) return gradient / length;
        return normal_at(p);
    }

    // The gradient of N, by central differences scaled to the point (N's
    // analytic gradient has poles on the axes for e or n above 2).
    DVec3 normal_at(const DVec3& p) const {
        const double h = 1e-6;
        DVec3 gradient;
        for (int axis = 0; axis < 3; ++axis) {
            DVec3 plus = p, minus = p;
            plus[axis] += h;
            minus[axis] -= h;
            gradient[axis] = norm(plus) - norm(minus);
        }
        const double length = glm::length(gradient);
        if (length > 0.0 && std::isfinite(length)) return gradient / length;
        const double radius = glm::length(p);
        return radius > 0.0 ? p / radius : DVec3(0.0, 1.0, 0.0);
    }

    double m_p, m_q;  // 2 / e and 2 / n
    bool m_convex;
    double m_exponent;  // r above, for the pinched shapes
};

}  // namespace

std::shared_ptr<const Shape> make_superellipsoid_shape(double east_west, double north_south) {
    // Above kMaxSuperellipsoidExponent the norm's powers overflow double
    // (2^(e/2) and more); the parser warns and caps there.
    const auto cap = [](double x) { return std::clamp(x, 1e-6, kMaxSuperellipsoidExponent); };
    return std::make_shared<SuperellipsoidShape>(cap(east_west), cap(north_south));
}

}  // namespace lancer
