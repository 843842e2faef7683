// POV-Ray's poly, cubic and quartic: the zero set of a polynomial in x, y, z
// of order n (coefficients in POV's order, see shape.h), inside where it is
// negative (POV's Inside_Poly). Along a ray o + t d each term x^i y^j z^k
// expands into a polynomial in t (binomially, per axis), and the sum's real
// roots come from polynomial_roots_in (isolation by derivatives, robust
// where roots crowd: POV's `sturm` asks for that, so it changes nothing
// here). The origin is first moved to the line's point nearest the object's
// origin. Unbounded, as POV's: bound it with clipped_by or CSG. POV-Ray 3.7
// gives it no (u, v): lancer gives (0, 0).
#include <cmath>
#include <vector>

#include "geometry/polynomial_roots.h"
#include "geometry/shape.h"

#if defined(__GNUC__) && !defined(__clang__)
#define LANCER_NO_VECTORIZE __attribute__((optimize("no-tree-vectorize")))
#else
#define LANCER_NO_VECTORIZE
#endif

namespace lancer {
namespace {

struct Term {
    int power[3];
    double coefficient;
};

class PolynomialShape final : public Shape {
  public:
    PolynomialShape(int order, std::vector<Term> terms) : m_order(order), m_terms(std::move(terms)) {}

    double value(const DVec3& p) const {
        double sum = 0.0;
        for (const Term& term : m_terms)
            sum += term.coefficient * std::pow(p.x, term.power[0]) * std::pow(p.y, term.power[1]) *
                   std::pow(p.z, term.power[2]);
        return sum;
    }

    DVec3 gradient(const DVec3& p) const {
        DVec3 g(0.0);
        for (const Term& term : m_terms)
            for (int axis = 0; axis < 3; ++axis) {
                if (term.power[axis] == 0) continue;
                double product = term.coefficient * term.power[axis];
                for (int other = 0; other < 3; ++other)
                    product *= std::pow(p[other], term.power[other] - (other == axis ? 1 : 0));
                g[axis] += product;
            }
        return g;
    }

    // Not vectorised: the terms' sums overlap in c one place apart, and the
    // two-lane loads of what the last two-lane store half wrote stall at
    // every step (GCC; a third of POV's advanced/pawns.pov).
    LANCER_NO_VECTORIZE void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max,
                                       ShapeCrossings& out) const override {
        const double dd = glm::dot(d, d);
        if (!(dd > 0.0)) return;
        const double shift = -glm::dot(o, d) / dd;
        const DVec3 p = o + shift * d;
        // (p_a + t d_a)^m for every axis a and power m, as coefficients in t
        // (entries l <= m <= order only: zeroing the whole table, 7 KB, cost
        // more than a quartic's roots).
        // The axes' numbers in arrays: glm's operator[] is a switch.
        double expansion[3][kMaxPolynomialDegree + 1][kMaxPolynomialDegree + 1];
        const double start[3] = {p.x, p.y, p.z}, step[3] = {d.x, d.y, d.z};
        for (int axis = 0; axis < 3; ++axis) {
            const double pa = start[axis], da = step[axis];
            expansion[axis][0][0] = 1.0;
            for (int m = 1; m <= m_order; ++m) {
                const double* below = expansion[axis][m - 1];
                double* row = expansion[axis][m];
                row[0] = pa * below[0];
                for (int l = 1; l < m; ++l) row[l] = pa * below[l] + da * below[l - 1];
                row[m] = da * below[m - 1];
            }
        }
        double c[kMaxPolynomialDegree + 1] = {};
        for (const Term& term : m_terms) {
            const double* ex = expansion[0][term.power[0]];
            const double* ey = expansion[1][term.power[1]];
            const double* ez = expansion[2][term.power[2]];
            for (int a = 0; a <= term.power[0]; ++a)
                for (int b = 0; b <= term.power[1]; ++b) {
                    const double ab = term.coefficient * ex[a] * ey[b];
                    if (ab == 0.0) continue;
                    for (int k = 0; k <= term.power[2]; ++k) c[a + b + k] += ab * ez[k];
                }
        }
        double roots[kMaxPolynomialDegree];
        const int n = polynomial_roots_in(c, m_order, t_min - shift, t_max - shift, roots);
        add_shifted_roots(roots, n, shift, t_min, t_max, 0, out);
    }

    SurfaceGeometry surface(const DVec3& p, int) const override {
        SurfaceGeometry g;
        g.point = project_onto_level(
            p, [this](const DVec3& q) { return value(q); }, [this](const DVec3& q) { return gradient(q); }, 0.0);
        const DVec3 n = gradient(g.point);
        const double length = glm::length(n);
        g.normal = length > 0.0 && std::isfinite(length) ? n / length : DVec3(0.0, 1.0, 0.0);
        g.uv = Vec2(0.0f);
        return g;
    }

    bool inside(const DVec3& p) const override { return value(p) < 0.0; }
    bool bounds(DVec3&, DVec3&) const override { return false; }

  private:
    int m_order;
    std::vector<Term> m_terms;
};

}  // namespace

int polynomial_term_count(int order) {
    return (order + 1) * (order + 2) * (order + 3) / 6;
}

std::shared_ptr<const Shape> make_polynomial_shape(int order, const std::vector<double>& coefficients) {
    if (order < 1 || order > kMaxPolynomialShapeOrder ||
        coefficients.size() != std::size_t(polynomial_term_count(order)))
        return nullptr;
    // POV's order: x's power from n down, then y's, then z's.
    std::vector<Term> terms;
    std::size_t index = 0;
    for (int i = order; i >= 0; --i)
        for (int j = order - i; j >= 0; --j)
            for (int k = order - i - j; k >= 0; --k) {
                const double coefficient = coefficients[index++];
                if (coefficient != 0.0) terms.push_back(Term{{i, j, k}, coefficient});
            }
    if (terms.empty()) return nullptr;
    return std::make_shared<PolynomialShape>(order, std::move(terms));
}

}  // namespace lancer
