// Real roots of polynomials in double precision, for the analytic shapes
// whose surfaces are the zero sets of polynomials along a ray (quadrics,
// the torus, and the higher-order shapes after them).
#pragma once

namespace lancer {

// Roots of a t^2 + 2 b_half t + c = 0, smaller first, computed without
// cancellation (the root of larger magnitude first, the other from the
// product c / a). Returns how many (0, 1 or 2); a = 0 gives the linear root.
int solve_quadratic(double a, double b_half, double c, double roots[2]);

// Every real root of the polynomial sum coefficients[i] t^i (degree at
// most kMaxPolynomialDegree) in the open interval (t_lo, t_hi), ascending.
//
// Isolation by derivatives: between two consecutive roots of p' the
// polynomial p is monotonic, so it has at most one root there, found by
// safeguarded Newton steps inside a sign-changing bracket (bisection when a
// step would leave it). The roots of p' come the same way from p''. Unlike
// closed forms (Ferrari's quartic) this loses no root to cancellation when
// roots are close together, which is where tori seen edge-on break; unlike
// a Sturm sequence it needs no division of polynomials. Double roots
// (tangent rays) are found where p touches 0 at a root of p'.
constexpr int kMaxPolynomialDegree = 16;
int polynomial_roots_in(const double* coefficients, int degree, double t_lo, double t_hi, double* roots);

// The least and greatest values of c[0] + c[1] s + c[2] s^2 + c[3] s^3
// over [s0, s1]: at the ends or where the derivative vanishes (the bounds
// of a curve segment's coordinates, which let a shape skip segments).
void cubic_range(const double c[4], double s0, double s1, double& lowest, double& highest);

}  // namespace lancer
