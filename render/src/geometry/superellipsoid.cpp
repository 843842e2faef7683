// POV-Ray's superellipsoid { <e, n> }: the unit ball of the "norm"
// N(p) = ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n))^(n/2), evaluated as
// POV's evaluate_g does (ratios, so no power overflows). N is homogeneous
// of degree 1, so a point projects onto the surface exactly as p / N(p).
//
// Along a ray N(o + t d) - 1 is found inside the unit box, split where the
// ray crosses x = 0, y = 0 or z = 0 (where |.| bends the function): each
// piece is sampled, sign changes are bisected, and where the samples dip
// towards 0 without changing sign a golden-section search finds the
// minimum first, so grazing rays still find the thin pair of roots. For
// e, n <= 2 (the usual, convex shapes) N is a norm, convex along any line,
// so that finds every root. POV-Ray 3.7 gives it no (u, v): lancer gives
// (0, 0).
#include <algorithm>
#include <cmath>

#include "geometry/shape.h"

namespace lancer {
namespace {

// (x^e + y^e)^(1/e) for x, y >= 0, as POV's evaluate_g.
double combine(double x, double y, double e) {
    const double larger = std::max(x, y), smaller = std::min(x, y);
    if (larger == 0.0) return 0.0;
    return larger * std::pow(1.0 + std::pow(smaller / larger, e), 1.0 / e);
}

class SuperellipsoidShape final : public Shape {
  public:
    SuperellipsoidShape(double e, double n) : m_e(e), m_n(n) {}

    double norm(const DVec3& p) const {
        return combine(combine(std::fabs(p.x), std::fabs(p.y), 2.0 / m_e), std::fabs(p.z), 2.0 / m_n);
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        double lo = t_min, hi = t_max;
        const double slack = 1e-9;
        if (!ray_box_interval(DVec3(-1.0 - slack), DVec3(1.0 + slack), o, d, lo, hi)) return;
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
        auto f = [&](double t) { return norm(o + t * d) - 1.0; };
        for (int piece = 0; piece + 1 < count; ++piece) {
            const double a = cuts[piece], b = cuts[piece + 1];
            if (!(b > a)) continue;
            constexpr int kSamples = 8;
            double t_prev = a, f_prev = f(a);
            double t_low = a, f_low = f_prev;
            bool found = false;
            for (int i = 1; i <= kSamples; ++i) {
                const double t = a + (b - a) * i / kSamples;
                const double value = f(t);
                if ((value < 0.0) != (f_prev < 0.0)) {
                    add_root(f, t_prev, t, f_prev, t_min, t_max, out);
                    found = true;
                }
                if (value < f_low) {
                    f_low = value;
                    t_low = t;
                }
                t_prev = t;
                f_prev = value;
            }
            if (found || f_low <= 0.0) continue;
            // No sign change: the minimum may still dip below 0 between samples.
            const double step = (b - a) / kSamples;
            double left = std::max(a, t_low - step), right = std::min(b, t_low + step);
            const double ratio = 0.5 * (std::sqrt(5.0) - 1.0);
            double x1 = right - ratio * (right - left), x2 = left + ratio * (right - left);
            double f1 = f(x1), f2 = f(x2);
            for (int i = 0; i < 60 && f1 > 0.0 && f2 > 0.0; ++i) {
                if (f1 < f2) {
                    right = x2;
                    x2 = x1;
                    f2 = f1;
                    x1 = right - ratio * (right - left);
                    f1 = f(x1);
                } else {
                    left = x1;
                    x1 = x2;
                    f1 = f2;
                    x2 = left + ratio * (right - left);
                    f2 = f(x2);
                }
            }
            const double t_dip = f1 <= f2 ? x1 : x2, f_dip = std::min(f1, f2);
            if (!(f_dip <= 0.0)) continue;
            add_root(f, a, t_dip, f(a), t_min, t_max, out);
            add_root(f, t_dip, b, f_dip, t_min, t_max, out);
        }
    }

    SurfaceGeometry surface(const DVec3& p, int) const override {
        SurfaceGeometry g;
        const double n = norm(p);
        g.point = n > 0.0 ? p / n : p;
        g.normal = normal_at(g.point);
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
    template <class F>
    static void add_root(const F& f, double a, double b, double f_a, double t_min, double t_max, ShapeCrossings& out) {
        for (int i = 0; i < 100; ++i) {
            const double mid = 0.5 * (a + b);
            if (!(mid > a && mid < b)) break;
            const double value = f(mid);
            if ((value < 0.0) == (f_a < 0.0)) {
                a = mid;
                f_a = value;
            } else {
                b = mid;
            }
        }
        const double t = 0.5 * (a + b);
        if (t > t_min && t < t_max) out.add(t, 0);
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

    double m_e, m_n;
};

}  // namespace

std::shared_ptr<const Shape> make_superellipsoid_shape(double east_west, double north_south) {
    // Above kMaxSuperellipsoidExponent the norm's powers overflow double
    // (2^(e/2) and more); the parser warns and caps there.
    const auto cap = [](double x) { return std::clamp(x, 1e-6, kMaxSuperellipsoidExponent); };
    return std::make_shared<SuperellipsoidShape>(cap(east_west), cap(north_south));
}

}  // namespace lancer
