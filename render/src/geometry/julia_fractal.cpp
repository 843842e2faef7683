// POV-Ray's julia_fractal: the points p of object space whose 4D orbit
// z0 = (p.x, p.y, p.z, w), w from the slice dot(S, z0) = D, under
// z -> f(z) + c stays within the bailout for max_iteration steps: for
// k = 0 .. max_iteration - 1, |z_k|^2 <= bailout (the last iterate computed,
// z_N, is never tested). Quaternion (sqr, cube): bailout R^2 + 1e-7 with
// R = min(2, 1 + |c| + 1e-7), the radius of the bounding sphere; hypercomplex
// (every function): bailout 16 in the sphere of radius 4. POV-Ray gives the
// shape no (u, v): (0, 0) here.
//
// Method. The surface is the boundary of a set given only by an escape test,
// so no root solver applies: the ray is marched through the bounding sphere
// and every change of the inside state is bisected down to ~1e-14 of the
// radius. The march takes POV-Ray's own steps (its quaternion distance
// estimate, its hypercomplex linear extrapolation of |z|^2, never shorter
// than 1 / precision, never longer than 30 / precision for hypercomplex),
// because what POV shows is what its samples find: a step that jumps a thin
// fin in POV jumps it here too, and a more careful marcher would show fins
// POV-Ray does not (its hypercomplex sqr and cube, the same set marched with
// different steps, already differ in ~600 pixels of a 160x120 frame). The
// steps are bounded below, so a march is at most 2 R precision samples long.
//
// Hypercomplex numbers are kept in POV's duplex form, two complex numbers
// a = (x - w) + i(y + z), b = (x + w) + i(y - z): there the product is
// componentwise and every function (sqr, reciprocal, exp, ..., pwr) is the
// complex one applied to a and to b, with POV's formulas and branches.
// POV-Ray's hypercomplex `cube` iterates z^2 + c (its code says so; Debian's
// 3.7 renders it so), which is kept.
//
// Normals are POV-Ray's, as it shades with them: the gradient of |z_N|^2
// (N = max_iteration), by forward derivatives through the orbit, with w
// held fixed (exact for the default slice; POV drops dw/dp of a tilted one)
// and, for hypercomplex functions other than sqr, cube, reciprocal and exp,
// f(z) where f'(z) belongs (POV's shortcut). Against POV's own shading of
// the reference scene this agrees to 0.003 on average, where the exact
// gradient of the failing test is off by 0.05. That exact gradient, which
// points outwards, decides the side (POV's can face inwards) and stands in
// where POV's is not finite. Hit points are polished by Newton steps onto
// |z_k|^2 = bailout, k the failing iterate (the face).
//
// Where this differs from POV-Ray: every crossing is reported (POV stops
// at the first outside CSG; here at ShapeCrossings::kCapacity); beyond the
// bounding sphere counts as outside, so a set that fills its sphere (as
// reciprocal's) shows the sphere where POV shows rounding dust; an orbit
// that turns NaN escapes (POV keeps it inside).
#include "geometry/julia_fractal.h"

#include <algorithm>
#include <cmath>
#include <complex>

namespace lancer {
namespace {

using Algebra = JuliaFractalParameters::Algebra;
using Function = JuliaFractalParameters::Function;
using Complex = std::complex<double>;
using DVec4 = glm::dvec4;

constexpr double kSlack = 1e-7;             // POV's margin on the quaternion radius and bailout
constexpr double kDescentThreshold = 1e-8;  // POV's: slopes above this give the least step
constexpr double kLongestStepInLeastSteps = 30.0;
constexpr double kHypercomplexRadius = 4.0;
constexpr double kHypercomplexBailout = 16.0;
constexpr double kChordEpsilon = 1e-10;  // POV's sphere test drops chords^2 below this
constexpr double kRefineWidth = 1e-14;   // bisection stops at this fraction of the radius

// Complex arithmetic spelled out: std::complex's * and / take a slow path
// for infinities that the orbit never needs (an infinite norm escapes).
Complex mul(Complex a, Complex b) {
    return {a.real() * b.real() - a.imag() * b.imag(), a.real() * b.imag() + a.imag() * b.real()};
}
Complex div(Complex a, Complex b) {
    const double n = std::norm(b);
    return Complex(a.real() * b.real() + a.imag() * b.imag(), a.imag() * b.real() - a.real() * b.imag()) / n;
}
Complex times_i(Complex a) {
    return {-a.imag(), a.real()};
}
double dot(Complex a, Complex b) {
    return a.real() * b.real() + a.imag() * b.imag();
}  // Re(conj(a) b)

Complex principal_sqrt(Complex z) {
    if (z.real() == 0.0 && z.imag() == 0.0) return 0.0;
    const double magnitude = std::sqrt(std::sqrt(std::norm(z)));
    const double half_angle = 0.5 * std::atan2(z.imag(), z.real());
    return {magnitude * std::cos(half_angle), magnitude * std::sin(half_angle)};
}
Complex principal_log(Complex z) {
    return {0.5 * std::log(std::norm(z)), std::atan2(z.imag(), z.real())};
}
Complex exponential(Complex z) {
    const double scale = std::exp(z.real());
    return {scale * std::cos(z.imag()), scale * std::sin(z.imag())};
}
Complex sine(Complex z) {
    return {std::sin(z.real()) * std::cosh(z.imag()), std::cos(z.real()) * std::sinh(z.imag())};
}
Complex cosine(Complex z) {
    return {std::cos(z.real()) * std::cosh(z.imag()), -std::sin(z.real()) * std::sinh(z.imag())};
}
Complex hyperbolic_sine(Complex z) {
    return {std::sinh(z.real()) * std::cos(z.imag()), std::cosh(z.real()) * std::sin(z.imag())};
}
Complex hyperbolic_cosine(Complex z) {
    return {std::cosh(z.real()) * std::cos(z.imag()), std::sinh(z.real()) * std::sin(z.imag())};
}
Complex tangent(Complex z) {
    const double denominator = std::cos(2.0 * z.real()) + std::cosh(2.0 * z.imag());
    return Complex(std::sin(2.0 * z.real()), std::sinh(2.0 * z.imag())) / denominator;
}
Complex hyperbolic_tangent(Complex z) {
    const double denominator = std::cosh(2.0 * z.real()) + std::cos(2.0 * z.imag());
    return Complex(std::sinh(2.0 * z.real()), std::sin(2.0 * z.imag())) / denominator;
}
// atanh z = log((1 + z) / (1 - z)) / 2, with POV's cases for real and
// imaginary z (at z = +-1 POV leaves garbage; infinity escapes instead).
Complex inverse_hyperbolic_tangent(Complex z) {
    const double x = z.real(), y = z.imag();
    if (x == 0.0) return {0.0, std::atan(y)};
    if (y == 0.0 && std::fabs(x) == 1.0) return {std::copysign(INFINITY, x), 0.0};
    if (y == 0.0 && std::fabs(x) < 1.0) return {0.5 * std::log((1.0 + x) / (1.0 - x)), 0.0};
    return 0.5 * principal_log(div(Complex(1.0 + x, y), Complex(1.0 - x, -y)));
}
// atan z = (i / 2) log((1 - iz) / (1 + iz)), with POV's real and imaginary cases.
Complex inverse_tangent(Complex z) {
    const double x = z.real(), y = z.imag();
    if (x == 0.0 && y == 0.0) return 0.0;
    if (y == 0.0) return {std::atan(x), 0.0};
    if (x == 0.0) return times_i(inverse_hyperbolic_tangent(Complex(y, 0.0)));
    const Complex iz = times_i(z);
    return 0.5 * times_i(principal_log(div(1.0 - iz, 1.0 + iz)));
}

// The function of z -> f(z) + c on one duplex half.
Complex apply(Function function, Complex z, Complex power) {
    switch (function) {
    case Function::Sqr:
    case Function::Cube: return mul(z, z);  // POV's hypercomplex cube is z^2
    case Function::Reciprocal: return div(1.0, z);
    case Function::Exp: return exponential(z);
    case Function::Ln: return principal_log(z);
    case Function::Sin: return sine(z);
    case Function::Cos: return cosine(z);
    case Function::Tan: return tangent(z);
    case Function::Sinh: return hyperbolic_sine(z);
    case Function::Cosh: return hyperbolic_cosine(z);
    case Function::Tanh: return hyperbolic_tangent(z);
    case Function::Asin: {  // -i log(iz + sqrt(1 - z^2))
        const Complex l = principal_log(times_i(z) + principal_sqrt(1.0 - mul(z, z)));
        return {l.imag(), -l.real()};
    }
    case Function::Acos: {  // -i log(z + sqrt(z^2 - 1))
        const Complex l = principal_log(z + principal_sqrt(mul(z, z) - 1.0));
        return {l.imag(), -l.real()};
    }
    case Function::Asinh: return principal_log(z + principal_sqrt(mul(z, z) + 1.0));
    case Function::Acosh: return principal_log(z + principal_sqrt(mul(z, z) - 1.0));
    case Function::Atan: return inverse_tangent(z);
    case Function::Atanh: return inverse_hyperbolic_tangent(z);
    case Function::Pwr: {  // exp(power log z); POV's 0 at z = 0 and below e^-690
        if (z.real() == 0.0 && z.imag() == 0.0) return 0.0;
        const Complex exponent = mul(principal_log(z), power);
        return exponent.real() < -690.0 ? Complex(0.0) : exponential(exponent);
    }
    }
    return 0.0;
}

// apply(), with POV's usual squares taken here: apply() is too large to
// inline, and its call and dispatch cost the orbit more than the square
// (POV's objects/fractal2.pov).
inline Complex apply_inline(Function function, Complex z, Complex power) {
    if (function == Function::Sqr || function == Function::Cube) return mul(z, z);
    return apply(function, z, power);
}

// f'(z), for the derivatives of the orbit (normals and polishing).
Complex slope_of(Function function, Complex z, Complex power) {
    switch (function) {
    case Function::Sqr:
    case Function::Cube: return 2.0 * z;
    case Function::Reciprocal: return -div(1.0, mul(z, z));
    case Function::Exp: return exponential(z);
    case Function::Ln: return div(1.0, z);
    case Function::Sin: return cosine(z);
    case Function::Cos: return -sine(z);
    case Function::Tan: {
        const Complex t = tangent(z);
        return 1.0 + mul(t, t);
    }
    case Function::Sinh: return hyperbolic_cosine(z);
    case Function::Cosh: return hyperbolic_sine(z);
    case Function::Tanh: {
        const Complex t = hyperbolic_tangent(z);
        return 1.0 - mul(t, t);
    }
    case Function::Asin: return div(1.0, principal_sqrt(1.0 - mul(z, z)));
    case Function::Acos: return -times_i(div(1.0, principal_sqrt(mul(z, z) - 1.0)));
    case Function::Asinh: return div(1.0, principal_sqrt(mul(z, z) + 1.0));
    case Function::Acosh: return div(1.0, principal_sqrt(mul(z, z) - 1.0));
    case Function::Atan: return div(1.0, 1.0 + mul(z, z));
    case Function::Atanh: return div(1.0, 1.0 - mul(z, z));
    case Function::Pwr: {
        if (z.real() == 0.0 && z.imag() == 0.0) return 0.0;
        return div(mul(power, apply(Function::Pwr, z, power)), z);
    }
    }
    return 0.0;
}

struct Duplex {
    Complex a, b;
};
Duplex to_duplex(const DVec4& q) {
    return {Complex(q.x - q.w, q.y + q.z), Complex(q.x + q.w, q.y - q.z)};
}
double norm4(const Duplex& z) {
    return 0.5 * (std::norm(z.a) + std::norm(z.b));
}
double dot4(const Duplex& u, const Duplex& v) {
    return 0.5 * (dot(u.a, v.a) + dot(u.b, v.b));
}

// What one orbit says about a point.
struct Sample {
    bool inside = true;
    int escape = 0;     // the iterate whose test failed (outside only)
    double step = 0.0;  // POV's step to the next sample, when asked for
};

// An iterate and its derivatives along x, y, z, the latter held scaled by
// 2^exponent so long orbits neither overflow nor underflow them.
struct QuaternionJet {
    DVec4 value;
    DVec4 partial[3];
};
struct DuplexJet {
    Duplex value;
    Duplex partial[3];
};
struct OrbitGradient {
    double norm = 0.0;  // |z_n|^2
    DVec3 gradient{0.0};
    int exponent = 0;  // gradient of |z_n|^2 = gradient * 2^exponent
    bool finite = false;
};

class JuliaFractalShape final : public Shape {
  public:
    JuliaFractalShape(const JuliaFractalParameters& p, const DVec4& unit_slice)
        : m_algebra(p.algebra),
          m_function(p.function),
          m_power(p.power.x, p.power.y),
          m_c(p.julia_parameter),
          m_c_duplex(to_duplex(p.julia_parameter)),
          m_iterations(std::max(1, p.max_iteration)),
          m_least_step(1.0 / std::max(1.0, p.precision)),
          m_slice(unit_slice),
          m_slice_distance(p.slice_distance) {
        if (m_algebra == Algebra::Quaternion) {
            m_radius = std::min(2.0, 1.0 + glm::length(m_c) + kSlack);
            m_bailout = m_radius * m_radius + kSlack;
        } else {
            m_radius = kHypercomplexRadius;
            m_bailout = kHypercomplexBailout;
        }
        // dz0/dp: w(p) = (D - S.xyz . p) / S.t moves with p.
        for (int axis = 0; axis < 3; ++axis) {
            m_start_partial[axis] = DVec4(0.0);
            m_start_partial[axis][axis] = 1.0;
            m_start_partial[axis].w = -m_slice[axis] / m_slice.w;
        }
    }

    bool finds_crossings_past_t_min() const override { return false; }
    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        march(o, d, t_min, t_max, false, out);
    }

    // The march stops at the first crossing: a ray that enters the set
    // would otherwise cross its inside at the least step.
    bool nearest(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossing& hit) const override {
        ShapeCrossings found;
        march(o, d, t_min, t_max, true, found);
        if (found.count == 0) return false;
        hit = found.items[0];
        return true;
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        const int escape = std::clamp(face, 0, m_iterations - 1);
        SurfaceGeometry g;
        g.point = polish(p, escape);
        g.uv = Vec2(0.0f);
        // POV's normal (what POV-Ray shades with) turned to the side the
        // failing test's gradient, exactly outward, points to: POV's can face
        // inwards (reciprocal, the hole's side), and POV then shades it
        // turned towards the viewer. Either alone where the other is not
        // finite; on the bounding sphere (the first test fails) the sphere's.
        const OrbitGradient pov =
            escape == 0 ? OrbitGradient{} : orbit_gradient(g.point, m_iterations, Derivative::PovNormal);
        const OrbitGradient exact = orbit_gradient(g.point, escape, Derivative::Exact);
        const auto direction_of = [](const OrbitGradient& o, DVec3& unit) {
            const double length = glm::length(o.gradient);
            if (!o.finite || !(length > 0.0) || !std::isfinite(length)) return false;
            unit = o.gradient / length;
            return true;
        };
        DVec3 pov_normal, exact_normal;
        const bool has_pov = direction_of(pov, pov_normal), has_exact = direction_of(exact, exact_normal);
        if (has_pov) {
            g.normal = has_exact && glm::dot(pov_normal, exact_normal) < 0.0 ? -pov_normal : pov_normal;
            return g;
        }
        if (has_exact) {
            g.normal = exact_normal;
            return g;
        }
        const double radial = glm::length(g.point);
        g.normal = radial > 0.0 ? g.point / radial : DVec3(0.0, 1.0, 0.0);
        return g;
    }

    bool inside(const DVec3& p) const override { return sample(p, DVec3(0.0), false).inside; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = DVec3(-m_radius);
        upper = DVec3(m_radius);
        return true;
    }

  private:
    // Every crossing in (t_min, t_max), in order along the ray; with
    // first_only, the first alone.
    void march(const DVec3& o, const DVec3& d, double t_min, double t_max, bool first_only, ShapeCrossings& out) const {
        const double length = glm::length(d);
        if (!(length > 0.0) || !std::isfinite(length)) return;
        const DVec3 direction = d / length;
        // The chord of the bounding sphere, in unit-direction distance s;
        // samples are taken from its entry point, so far origins lose no digits.
        const double along = -glm::dot(o, direction);
        const DVec3 closest = o + along * direction;
        const double half_chord2 = m_radius * m_radius - glm::dot(closest, closest);
        if (!(half_chord2 > kChordEpsilon)) return;
        const double half_chord = std::sqrt(half_chord2);
        const double entry = along - half_chord;
        const DVec3 base = o + entry * direction;
        const double u_end = 2.0 * half_chord;  // the sphere's exit, from base
        const double u_first = std::max(0.0, t_min * length - entry);
        const double u_last = std::min(u_end, t_max * length - entry);
        if (!(u_first < u_last)) return;
        const auto point_at = [&](double u) { return base + u * direction; };
        const auto add = [&](const Bracketed& crossing) {
            const double t = (entry + crossing.u) / length;
            if (t > t_min && t < t_max) out.add(t, crossing.escape);
        };

        // March with POV's steps; a sample past t_max (within the sphere)
        // still closes the bracket that holds t_max. Beyond the sphere is
        // outside: a set that fills it (reciprocal, small c) is met at the
        // sphere, where POV-Ray, starting or ending "inside" by rounding on
        // |z_0|^2 = 16, shows a random dust of hits or loses the far side.
        double u = u_first;
        Sample current = sample(point_at(u), direction, true);
        if (u_first == 0.0 && current.inside) add(Bracketed{0.0, 0});
        const double most_samples = std::ceil((u_end - u_first) / m_least_step) + 2.0;
        const int enough = first_only ? 1 : ShapeCrossings::kCapacity;
        for (double count = 0.0; count < most_samples && out.count < enough; ++count) {
            const double u_next = u + current.step;
            if (!(u_next <= u_end)) {
                const Sample exit_sample = sample(point_at(u_end), direction, false);
                if (exit_sample.inside != current.inside) add(refine(point_at, u, current, u_end, exit_sample));
                if (exit_sample.inside) add(Bracketed{u_end, 0});
                break;
            }
            const Sample next = sample(point_at(u_next), direction, true);
            if (next.inside != current.inside) add(refine(point_at, u, current, u_next, next));
            if (u_next >= u_last) break;
            u = u_next;
            current = next;
        }
    }

    DVec4 start(const DVec3& p) const {
        const double w = (m_slice_distance - m_slice.x * p.x - m_slice.y * p.y - m_slice.z * p.z) / m_slice.w;
        return DVec4(p, w);
    }

    Sample sample(const DVec3& p, const DVec3& direction, bool with_step) const {
        return m_algebra == Algebra::Quaternion ? sample_quaternion(p, with_step)
                                                : sample_hypercomplex(p, direction, with_step);
    }

    // Quaternion orbit; outside, POV's distance estimate
    // log|z_k|^2 / (n^(k+1) |z_0| ... |z_(k-1)|) for z^n, n = 2 or 3.
    Sample sample_quaternion(const DVec3& p, bool with_step) const {
        const bool cube = m_function == Function::Cube;
        const double inverse_degree = cube ? 1.0 / 3.0 : 0.5;
        DVec4 z = start(p);
        double norm_product = 1.0, degree_power = inverse_degree;
        for (int k = 0; k < m_iterations; ++k) {
            const double vector2 = z.y * z.y + z.z * z.z + z.w * z.w;
            const double real2 = z.x * z.x;
            const double norm = real2 + vector2;
            if (!(norm <= m_bailout)) {
                Sample s{false, k, m_least_step};
                if (with_step) {
                    const double estimate = degree_power * std::log(norm) / std::sqrt(norm_product);
                    if (estimate > m_least_step) s.step = estimate;  // false for NaN
                }
                return s;
            }
            norm_product *= norm;
            degree_power *= inverse_degree;
            if (cube) {
                const double vector_scale = 3.0 * real2 - vector2;
                z = DVec4(z.x * (real2 - 3.0 * vector2), z.y * vector_scale, z.z * vector_scale, z.w * vector_scale) +
                    m_c;
            } else {
                const double twice_real = 2.0 * z.x;
                z = DVec4(real2 - vector2, twice_real * z.y, twice_real * z.z, twice_real * z.w) + m_c;
            }
        }
        return Sample{true, 0, m_least_step};
    }

    // Hypercomplex orbit; outside, POV's step: |z_k|^2 over twice its rate of
    // descent along the ray, where POV's rate takes the product
    // z_0 g(z_1) ... g(z_(k-1)) for the derivative of z_k (g = z for sqr, with
    // 2^k; z for cube, no factor; -1/z^2 for reciprocal; f itself otherwise).
    Sample sample_hypercomplex(const DVec3& p, const DVec3& direction, bool with_step) const {
        Duplex z = to_duplex(start(p));
        Duplex product = z;
        for (int k = 0; k < m_iterations; ++k) {
            const double norm = norm4(z);
            if (!(norm <= m_bailout)) {
                Sample s{false, k, m_least_step};
                if (with_step) s.step = hypercomplex_step(z, product, k, norm, direction);
                return s;
            }
            if (with_step && k >= 1) {
                Duplex factor;
                switch (m_function) {
                case Function::Sqr:
                case Function::Cube: factor = z; break;
                case Function::Reciprocal: {
                    const Complex ia = div(1.0, z.a), ib = div(1.0, z.b);
                    factor = {-mul(ia, ia), -mul(ib, ib)};
                    break;
                }
                default: factor = {apply_inline(m_function, z.a, m_power), apply_inline(m_function, z.b, m_power)};
                }
                product = {mul(product.a, factor.a), mul(product.b, factor.b)};
            }
            z = {apply_inline(m_function, z.a, m_power) + m_c_duplex.a,
                 apply_inline(m_function, z.b, m_power) + m_c_duplex.b};
        }
        return Sample{true, 0, m_least_step};
    }

    double hypercomplex_step(const Duplex& z, const Duplex& product, int k, double norm, const DVec3& direction) const {
        // POV's gradient: the product times 1, i and j (duplex (1,1), (i,i),
        // (i,-i)), each dotted with z_k; w held fixed.
        const Complex ia = times_i(product.a), ib = times_i(product.b);
        DVec3 gradient(dot4(product, z), dot4({ia, ib}, z), dot4({ia, -ib}, z));
        if (m_function == Function::Sqr) gradient *= std::ldexp(1.0, std::max(1, k));
        double slope = glm::dot(gradient, direction);
        if (!(slope < -kDescentThreshold)) return m_least_step;
        slope *= -2.0;
        if (norm > m_least_step * slope && norm < kLongestStepInLeastSteps * m_least_step * slope) return norm / slope;
        return m_least_step;
    }

    // A crossing at u from the sphere's entry; its face is the iterate whose
    // test fails on the outside side.
    struct Bracketed {
        double u;
        int escape;
    };

    // Bisects [u_a, u_b] (states differ) down to a crossing.
    template <class PointAt>
    Bracketed refine(const PointAt& point_at, double u_a, Sample a, double u_b, Sample b) const {
        const double width = kRefineWidth * m_radius;
        for (int halving = 0; halving < 80 && u_b - u_a > width; ++halving) {
            const double mid = 0.5 * (u_a + u_b);
            if (!(mid > u_a && mid < u_b)) break;
            const Sample m = sample(point_at(mid), DVec3(0.0), false);
            if (m.inside == a.inside) {
                u_a = mid;
                a = m;
            } else {
                u_b = mid;
                b = m;
            }
        }
        return Bracketed{0.5 * (u_a + u_b), a.inside ? b.escape : a.escape};
    }

    // Exact: the gradient of |z_n|^2 in 3D. PovNormal: POV-Ray's normal,
    // the same with w held fixed (a tilted slice moves w with p) and, for
    // hypercomplex functions other than exp, f(z) standing in for f'(z).
    enum class Derivative { Exact, PovNormal };

    // |z_n|^2 and its gradient, iterating without the bailout test.
    OrbitGradient orbit_gradient(const DVec3& p, int n, Derivative kind) const {
        OrbitGradient result;
        DVec4 start_partial[3];
        for (int axis = 0; axis < 3; ++axis) {
            start_partial[axis] = m_start_partial[axis];
            if (kind == Derivative::PovNormal) start_partial[axis].w = 0.0;
        }
        if (m_algebra == Algebra::Quaternion) {
            QuaternionJet jet{start(p), {start_partial[0], start_partial[1], start_partial[2]}};
            for (int k = 0; k < n; ++k) {
                step_quaternion_jet(jet);
                if (!rescale(jet.partial, result.exponent)) return result;
            }
            result.norm = glm::dot(jet.value, jet.value);
            for (int axis = 0; axis < 3; ++axis) result.gradient[axis] = 2.0 * glm::dot(jet.value, jet.partial[axis]);
        } else {
            DuplexJet jet{to_duplex(start(p)), {}};
            for (int axis = 0; axis < 3; ++axis) jet.partial[axis] = to_duplex(start_partial[axis]);
            const bool value_for_slope = kind == Derivative::PovNormal && m_function != Function::Sqr &&
                                         m_function != Function::Cube && m_function != Function::Reciprocal;
            for (int k = 0; k < n; ++k) {
                const Complex slope_a = value_for_slope ? apply(m_function, jet.value.a, m_power)
                                                        : slope_of(m_function, jet.value.a, m_power);
                const Complex slope_b = value_for_slope ? apply(m_function, jet.value.b, m_power)
                                                        : slope_of(m_function, jet.value.b, m_power);
                jet.value = {apply(m_function, jet.value.a, m_power) + m_c_duplex.a,
                             apply(m_function, jet.value.b, m_power) + m_c_duplex.b};
                DVec4 flat[3];
                for (int axis = 0; axis < 3; ++axis) {
                    Duplex& d = jet.partial[axis];
                    d = {mul(slope_a, d.a), mul(slope_b, d.b)};
                    flat[axis] = DVec4(d.a.real(), d.a.imag(), d.b.real(), d.b.imag());
                }
                if (!rescale(flat, result.exponent)) return result;
                for (int axis = 0; axis < 3; ++axis)
                    jet.partial[axis] = {Complex(flat[axis].x, flat[axis].y), Complex(flat[axis].z, flat[axis].w)};
            }
            result.norm = norm4(jet.value);
            for (int axis = 0; axis < 3; ++axis) result.gradient[axis] = 2.0 * dot4(jet.value, jet.partial[axis]);
        }
        result.finite =
            std::isfinite(result.norm) && std::isfinite(result.gradient.x + result.gradient.y + result.gradient.z);
        return result;
    }

    void step_quaternion_jet(QuaternionJet& jet) const {
        const DVec4 z = jet.value;
        const DVec3 v(z.y, z.z, z.w);
        const double x = z.x, v2 = glm::dot(v, v);
        for (DVec4& partial : jet.partial) {
            const double dx = partial.x;
            const DVec3 dv(partial.y, partial.z, partial.w);
            const double v_dv = glm::dot(v, dv);
            if (m_function == Function::Cube) {  // (x^3 - 3x v.v, (3x^2 - v.v) v)
                const double real = 3.0 * (x * x - v2) * dx - 6.0 * x * v_dv;
                const DVec3 vector = (6.0 * x * dx - 2.0 * v_dv) * v + (3.0 * x * x - v2) * dv;
                partial = DVec4(real, vector);
            } else {  // (x^2 - v.v, 2x v)
                partial = DVec4(2.0 * x * dx - 2.0 * v_dv, 2.0 * dx * v + 2.0 * x * dv);
            }
        }
        if (m_function == Function::Cube) {
            const double vector_scale = 3.0 * x * x - v2;
            jet.value = DVec4(x * (x * x - 3.0 * v2), vector_scale * v) + m_c;
        } else {
            jet.value = DVec4(x * x - v2, 2.0 * x * v) + m_c;
        }
    }

    // Keeps derivatives within 2^+-500 by exact powers of two; false once
    // they stop being finite.
    static bool rescale(DVec4* partial, int& exponent) {
        double largest = 0.0;
        for (int axis = 0; axis < 3; ++axis)
            for (int i = 0; i < 4; ++i) largest = std::max(largest, std::fabs(partial[axis][i]));
        if (!std::isfinite(largest)) return false;
        int shift = 0;
        if (largest > 0x1p500) shift = -500;
        if (largest > 0.0 && largest < 0x1p-500) shift = 500;
        if (shift != 0) {
            for (int axis = 0; axis < 3; ++axis) partial[axis] *= std::ldexp(1.0, shift);
            exponent -= shift;
        }
        return true;
    }

    // Newton steps onto |z_k|^2 = bailout; a step that would move the point
    // further than its bisection error allows is refused.
    DVec3 polish(DVec3 p, int escape) const {
        const double reach = 1e-9 * m_radius;
        for (int step = 0; step < 2; ++step) {
            const OrbitGradient o = orbit_gradient(p, escape, Derivative::Exact);
            if (!o.finite) break;
            const double length = glm::length(o.gradient);
            if (!(length > 0.0)) break;
            // move = (norm - bailout) / |true gradient|, true = gradient 2^exponent.
            const double move = std::ldexp((o.norm - m_bailout) / length, -o.exponent);
            if (!(std::fabs(move) <= reach)) break;
            p -= move * (o.gradient / length);
        }
        return p;
    }

    Algebra m_algebra;
    Function m_function;
    Complex m_power;
    DVec4 m_c;
    Duplex m_c_duplex;
    int m_iterations;
    double m_least_step;
    DVec4 m_slice;
    double m_slice_distance;
    double m_radius = 0.0, m_bailout = 0.0;
    DVec4 m_start_partial[3];
};

}  // namespace

std::shared_ptr<const Shape> make_julia_fractal_shape(const JuliaFractalParameters& parameters) {
    const JuliaFractalParameters& p = parameters;
    const bool finite = std::isfinite(p.julia_parameter.x + p.julia_parameter.y + p.julia_parameter.z +
                                      p.julia_parameter.w + p.power.x + p.power.y + p.precision + p.slice_distance +
                                      p.slice_normal.x + p.slice_normal.y + p.slice_normal.z + p.slice_normal.w);
    if (!finite) return nullptr;
    if (p.algebra == Algebra::Quaternion && p.function != Function::Sqr && p.function != Function::Cube) return nullptr;
    const double slice2 = glm::dot(p.slice_normal, p.slice_normal);
    if (std::fabs(slice2) < 1e-10 || std::fabs(p.slice_normal.w) < 1e-10) return nullptr;
    return std::make_shared<JuliaFractalShape>(p, p.slice_normal / std::sqrt(slice2));
}

}  // namespace lancer
