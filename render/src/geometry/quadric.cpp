// POV-Ray's quadric: A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y
// + I z + J = 0, written as p^T M p + 2 N.p + J with M symmetric. Inside is
// where the value is not positive (POV's Inside_Quadric). Unbounded unless M
// is positive definite (an ellipsoid), whose box is exact. POV-Ray 3.7
// defines no (u, v) for it: lancer gives (0, 0).
#include <algorithm>
#include <cmath>

#include "geometry/polynomial_roots.h"
#include "geometry/shape.h"

namespace lancer {
namespace {

class QuadricShape final : public Shape {
  public:
    explicit QuadricShape(const QuadricParameters& q) : m_constant(q.constant) {
        const DVec3 s = q.square_terms, m = q.mixed_terms;
        // Columns of the symmetric matrix (GLM is column-major).
        m_matrix =
            DMat3(DVec3(s.x, 0.5 * m.x, 0.5 * m.y), DVec3(0.5 * m.x, s.y, 0.5 * m.z), DVec3(0.5 * m.y, 0.5 * m.z, s.z));
        m_linear = 0.5 * q.linear_terms;
    }

    double value(const DVec3& p) const { return glm::dot(p, m_matrix * p) + 2.0 * glm::dot(m_linear, p) + m_constant; }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double dd = glm::dot(d, d);
        if (!(dd > 0.0)) return;
        // From the point of the line nearest the origin: a far origin's
        // large terms would cancel in c.
        const double shift = -glm::dot(o, d) / dd;
        const DVec3 p = o + shift * d;
        const double a = glm::dot(d, m_matrix * d);
        const double b_half = glm::dot(d, m_matrix * p + m_linear);
        const double c = value(p);
        double roots[2];
        const int n = solve_quadratic(a, b_half, c, roots);
        add_shifted_roots(roots, n, shift, t_min, t_max, 0, out);
    }

    SurfaceGeometry surface(const DVec3& p, int) const override {
        SurfaceGeometry g;
        g.point = project_onto_level(
            p, [this](const DVec3& q) { return value(q); },
            [this](const DVec3& q) { return 2.0 * (m_matrix * q + m_linear); }, 0.0);
        const DVec3 gradient = m_matrix * g.point + m_linear;
        const double length = glm::length(gradient);
        g.normal = length > 0.0 ? gradient / length : DVec3(0.0, 1.0, 0.0);
        g.uv = Vec2(0.0f);
        return g;
    }

    bool inside(const DVec3& p) const override { return value(p) <= 0.0; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        // Positive definite (Sylvester's criterion): an ellipsoid about
        // c = -M^-1 N, (p - c)^T M (p - c) <= k, spanning sqrt(k (M^-1)_ii).
        const DMat3& m = m_matrix;
        const double minor2 = m[0][0] * m[1][1] - m[1][0] * m[1][0];
        const double det = glm::determinant(m);
        if (!(m[0][0] > 0.0 && minor2 > 0.0 && det > 0.0)) return false;
        const DMat3 inverse = glm::inverse(m);
        const DVec3 centre = -(inverse * m_linear);
        const double k = glm::dot(centre, m * centre) - m_constant;
        if (!(k > 0.0)) {
            lower = upper = centre;  // a point, or nothing
            return true;
        }
        const DVec3 half(std::sqrt(k * inverse[0][0]), std::sqrt(k * inverse[1][1]), std::sqrt(k * inverse[2][2]));
        lower = centre - half;
        upper = centre + half;
        return true;
    }

    // Without mixed terms the quadric is a sum over the axes,
    //     sum_i a_i (p_i + h_i)^2 + sum_{a_i = 0} 2 n_i p_i + c' <= 0,
    // so each axis with a_i > 0 is held within what the others' least
    // values over the box leave it (a cylinder's across its axis, a
    // hyperboloid's between two planes), and each linear one on one side.
    void narrow_box(DVec3& lower, DVec3& upper, bool inverted) const override {
        const DMat3& m = m_matrix;
        if (inverted || m[0][1] != 0.0 || m[0][2] != 0.0 || m[1][2] != 0.0) return;
        if (lower.x > upper.x || lower.y > upper.y || lower.z > upper.z) return;  // empty already
        double shift[3] = {0.0, 0.0, 0.0};
        double constant = m_constant;
        for (int i = 0; i < 3; ++i)
            if (m[i][i] != 0.0) {
                shift[i] = m_linear[i] / m[i][i];
                constant -= m_linear[i] * shift[i];
            }
        // The least value of axis i's term over [lower_i, upper_i]
        // (-infinity where it has none).
        const auto least_term = [&](int i) {
            const double a = m[i][i];
            if (a > 0.0) {
                const double nearest = std::clamp(-shift[i], lower[i], upper[i]) + shift[i];
                return a * nearest * nearest;
            }
            if (a < 0.0) {
                const double farthest = std::max(std::fabs(lower[i] + shift[i]), std::fabs(upper[i] + shift[i]));
                return a * farthest * farthest;
            }
            const double n = 2.0 * m_linear[i];
            return n > 0.0 ? n * lower[i] : n < 0.0 ? n * upper[i] : 0.0;
        };
        for (int i = 0; i < 3; ++i) {
            double room = -constant;  // what axis i's term may reach
            for (int j = 0; j < 3; ++j)
                if (j != i) room -= least_term(j);
            if (std::isnan(room) || room == INFINITY) continue;
            const double a = m[i][i];
            if (a > 0.0) {
                const double half = std::sqrt(std::max(room, 0.0) / a);
                lower[i] = std::max(lower[i], -shift[i] - half);
                upper[i] = std::min(upper[i], -shift[i] + half);
            } else if (a == 0.0 && m_linear[i] != 0.0) {
                const double edge = room / (2.0 * m_linear[i]);
                if (m_linear[i] > 0.0)
                    upper[i] = std::min(upper[i], edge);
                else
                    lower[i] = std::max(lower[i], edge);
            }
        }
    }

  private:
    DMat3 m_matrix{1.0};
    DVec3 m_linear{0.0};
    double m_constant;
};

}  // namespace

std::shared_ptr<const Shape> make_quadric_shape(const QuadricParameters& quadric) {
    return std::make_shared<QuadricShape>(quadric);
}

}  // namespace lancer
