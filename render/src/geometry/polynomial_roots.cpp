// Real roots of polynomials: the stable quadratic and isolation by
// derivatives for higher degrees (polynomial_roots.h).
#include "geometry/polynomial_roots.h"

#include <algorithm>
#include <cmath>

namespace lancer {

int solve_quadratic(double a, double b_half, double c, double roots[2]) {
    if (a == 0.0) {
        if (b_half == 0.0) return 0;
        roots[0] = -c / (2.0 * b_half);
        return 1;
    }
    const double discriminant = b_half * b_half - a * c;
    if (discriminant < 0.0) return 0;
    const double q = -(b_half + std::copysign(std::sqrt(discriminant), b_half));
    if (q == 0.0) {  // b_half = 0 and c = 0: a double root at 0
        roots[0] = roots[1] = 0.0;
        return 2;
    }
    double t0 = q / a, t1 = c / q;
    if (t0 > t1) std::swap(t0, t1);
    roots[0] = t0;
    roots[1] = t1;
    return 2;
}

namespace {

double evaluate(const double* c, int degree, double t) {
    double value = c[degree];
    for (int i = degree - 1; i >= 0; --i) value = value * t + c[i];
    return value;
}

double evaluate_with_derivative(const double* c, int degree, double t, double& derivative) {
    double value = c[degree];
    derivative = 0.0;
    for (int i = degree - 1; i >= 0; --i) {
        derivative = derivative * t + value;
        value = value * t + c[i];
    }
    return value;
}

// The root of p in [lo, hi], where p(lo) and p(hi) differ in sign.
double bracketed_root(const double* c, int degree, double lo, double hi, double p_lo) {
    double t = 0.5 * (lo + hi);
    for (int iteration = 0; iteration < 200; ++iteration) {
        double derivative;
        const double p = evaluate_with_derivative(c, degree, t, derivative);
        if (p == 0.0) return t;
        if ((p < 0.0) == (p_lo < 0.0)) {
            lo = t;
            p_lo = p;
        } else {
            hi = t;
        }
        double next = derivative != 0.0 ? t - p / derivative : lo - 1.0;
        if (!(next > lo && next < hi)) next = 0.5 * (lo + hi);
        // Converged: the step no longer moves t, or the bracket is a few ULPs.
        if (next == t || hi - lo <= 4.0 * 2.2e-16 * std::max(std::fabs(lo), std::fabs(hi))) return next;
        t = next;
    }
    return t;
}

// Roots of a polynomial already free of a zero leading coefficient.
int roots_of(const double* c, int degree, double lo, double hi, double* roots) {
    if (degree == 1) {
        const double t = -c[0] / c[1];
        if (t > lo && t < hi) {
            roots[0] = t;
            return 1;
        }
        return 0;
    }
    if (degree == 2) {
        double quadratic[2];
        const int n = solve_quadratic(c[2], 0.5 * c[1], c[0], quadratic);
        int count = 0;
        for (int i = 0; i < n; ++i)
            if (quadratic[i] > lo && quadratic[i] < hi) roots[count++] = quadratic[i];
        return count;
    }
    // The derivative's roots split (lo, hi) into intervals where p is monotonic.
    double derivative[kMaxPolynomialDegree];
    for (int i = 1; i <= degree; ++i) derivative[i - 1] = double(i) * c[i];
    double critical[kMaxPolynomialDegree + 1];
    const int critical_count = roots_of(derivative, degree - 1, lo, hi, critical);
    double ends[kMaxPolynomialDegree + 2];
    int end_count = 0;
    ends[end_count++] = lo;
    for (int i = 0; i < critical_count; ++i) ends[end_count++] = critical[i];
    ends[end_count++] = hi;
    int count = 0;
    double p_start = evaluate(c, degree, lo);
    for (int i = 0; i + 1 < end_count; ++i) {
        const double a = ends[i], b = ends[i + 1];
        const double p_end = evaluate(c, degree, b);
        if (p_start == 0.0 && i > 0) {
            // A root exactly at a critical point: a tangency (double root).
            roots[count++] = a;
        } else if (p_end != 0.0 && (p_start < 0.0) != (p_end < 0.0)) {
            roots[count++] = bracketed_root(c, degree, a, b, p_start);
        }
        p_start = p_end;
    }
    return count;
}

}  // namespace

int polynomial_roots_in(const double* coefficients, int degree, double t_lo, double t_hi, double* roots) {
    // Coefficients too small to matter against the largest are dropped
    // from the top: they would make the isolation chase roots at infinity.
    double largest = 0.0;
    for (int i = 0; i <= degree; ++i) largest = std::max(largest, std::fabs(coefficients[i]));
    if (!(largest > 0.0) || !std::isfinite(largest)) return 0;
    while (degree > 0 && std::fabs(coefficients[degree]) <= 1e-15 * largest) --degree;
    if (degree == 0) return 0;
    // Normalised (monic) so values stay in range during evaluation.
    double c[kMaxPolynomialDegree + 1];
    for (int i = 0; i <= degree; ++i) c[i] = coefficients[i] / coefficients[degree];
    if (!std::isfinite(t_lo) || !std::isfinite(t_hi)) {
        // Cauchy's bound holds every root: |t| <= 1 + max |c_i|.
        double bound = 0.0;
        for (int i = 0; i < degree; ++i) bound = std::max(bound, std::fabs(c[i]));
        bound += 1.0;
        t_lo = std::max(t_lo, -bound - 1.0);
        t_hi = std::min(t_hi, bound + 1.0);
    }
    if (!(t_lo < t_hi)) return 0;
    return roots_of(c, degree, t_lo, t_hi, roots);
}

void cubic_range(const double c[4], double s0, double s1, double& lowest, double& highest) {
    const auto value = [c](double s) { return ((c[3] * s + c[2]) * s + c[1]) * s + c[0]; };
    lowest = std::min(value(s0), value(s1));
    highest = std::max(value(s0), value(s1));
    // 3 c3 s^2 + 2 c2 s + c1 = 0, without cancellation: a curve's c3 is
    // often a rounding error away from 0.
    double turning[2];
    const int count = solve_quadratic(3.0 * c[3], c[2], c[1], turning);
    for (int i = 0; i < count; ++i)
        if (turning[i] > s0 && turning[i] < s1) {
            lowest = std::min(lowest, value(turning[i]));
            highest = std::max(highest, value(turning[i]));
        }
}

}  // namespace lancer
