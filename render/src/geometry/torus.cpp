// POV-Ray's torus: the points at distance minor_radius from the circle of
// radius major_radius about the y axis in the plane y = 0.
//
// Along a ray the surface is a quartic in t. Its roots come from
// polynomial_roots_in (isolation by derivatives, see there), which keeps
// close root pairs apart: a torus seen edge-on gives two nearly equal roots
// where closed-form quartics lose both. POV's `sturm` asks for the same
// robustness, so it changes nothing here. The origin is first moved along
// the ray to a sphere holding the torus, and the quartic is solved over
// the stretch of the ray inside that sphere only, so far origins lose no
// digits. (u, v) are POV-Ray's (Torus::CalcUV).
#include <algorithm>
#include <cmath>

#include "geometry/polynomial_roots.h"
#include "geometry/shape.h"

namespace lancer {
namespace {

class TorusShape final : public Shape {
  public:
    TorusShape(double major, double minor) : m_major(major), m_minor(minor) {}

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double length = glm::length(d);
        if (!(length > 0.0)) return;
        const DVec3 direction = d / length;
        // The stretch inside a sphere amply holding the torus (POV's, R + 2r:
        // a root on the tight sphere would sit on the interval's open end),
        // in unit-direction distance.
        const double bound = m_major + 2.0 * m_minor;
        const double along = -glm::dot(o, direction);
        const DVec3 closest = o + along * direction;
        const double miss = bound * bound - glm::dot(closest, closest);
        if (miss < 0.0) return;
        const double half_chord = std::sqrt(miss);
        const double s_lo = std::max(along - half_chord, t_min * length);
        const double s_hi = std::min(along + half_chord, t_max * length);
        if (!(s_lo < s_hi)) return;
        // Origin moved to the chord's start: coefficients of size ~bound^4.
        const double shift = along - half_chord;
        const DVec3 p = o + shift * direction;
        const double R2 = m_major * m_major, r2 = m_minor * m_minor;
        const double k1 = glm::dot(p, p) - R2 - r2;
        const double k2 = glm::dot(p, direction);
        // (|p + s D|^2 - R^2 - r^2)^2 + 4 R^2 ((p.y + s D.y)^2 - r^2) with |D| = 1.
        double c[5];
        c[4] = 1.0;
        c[3] = 4.0 * k2;
        c[2] = 2.0 * k1 + 4.0 * k2 * k2 + 4.0 * R2 * direction.y * direction.y;
        c[1] = 4.0 * k1 * k2 + 8.0 * R2 * p.y * direction.y;
        c[0] = k1 * k1 + 4.0 * R2 * (p.y * p.y - r2);
        double roots[kMaxPolynomialDegree];
        const int n = polynomial_roots_in(c, 4, s_lo - shift, s_hi - shift, roots);
        for (int i = 0; i < n; ++i) {
            // The quartic's coefficients span R^4 to R^2 r^2: for a thin
            // torus (r << R) they lose digits, and a root may be off or
            // spurious. Newton steps on the distance to the tube's centre
            // circle, which is well conditioned, polish each root; one that
            // does not land on the surface is dropped.
            double s_root = roots[i];
            bool on_surface = false;
            for (int step = 0; step < 4; ++step) {
                const DVec3 q = p + s_root * direction;
                const double ring = std::sqrt(q.x * q.x + q.z * q.z);
                const DVec3 centre =
                    ring > 0.0 ? m_major * DVec3(q.x / ring, 0.0, q.z / ring) : DVec3(m_major, 0.0, 0.0);
                const DVec3 offset = q - centre;
                const double distance = glm::length(offset);
                const double miss = distance - m_minor;
                on_surface = std::fabs(miss) <= 1e-9 * (m_major + m_minor);
                const double slope = distance > 0.0 ? glm::dot(offset, direction) / distance : 0.0;
                if (on_surface || std::fabs(slope) < 1e-12) break;
                s_root -= miss / slope;
            }
            if (!on_surface) continue;
            const double t = (s_root + shift) / length;
            if (t > t_min && t < t_max) out.add(t, 0);
        }
    }

    SurfaceGeometry surface(const DVec3& p, int) const override { return surface_at(p, true); }
    SurfaceGeometry surface_without_uv(const DVec3& p, int) const override { return surface_at(p, false); }

    SurfaceGeometry surface_at(const DVec3& p, bool with_uv) const {
        SurfaceGeometry g;
        const double ring = std::sqrt(p.x * p.x + p.z * p.z);
        const DVec3 towards = ring > 0.0 ? DVec3(p.x / ring, 0.0, p.z / ring) : DVec3(1.0, 0.0, 0.0);
        const DVec3 tube_centre = m_major * towards;
        const DVec3 offset = p - tube_centre;
        const double distance = glm::length(offset);
        g.normal = distance > 0.0 ? offset / distance : DVec3(0.0, 1.0, 0.0);
        g.point = tube_centre + m_minor * g.normal;
        g.uv = Vec2(0.0f);
        if (!with_uv) return g;
        const double u = 1.0 - (std::atan2(g.point.z, g.point.x) + kPiD) / (2.0 * kPiD);
        const double v = (std::atan2(g.point.y, ring - m_major) + kPiD) / (2.0 * kPiD);
        g.uv = Vec2(float(u), float(v));
        return g;
    }

    bool inside(const DVec3& p) const override {
        const double ring = std::sqrt(p.x * p.x + p.z * p.z) - m_major;
        return ring * ring + p.y * p.y <= m_minor * m_minor;
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        const double outer = m_major + m_minor;
        lower = DVec3(-outer, -m_minor, -outer);
        upper = DVec3(outer, m_minor, outer);
        return true;
    }

  private:
    double m_major, m_minor;
};

}  // namespace

std::shared_ptr<const Shape> make_torus_shape(double major_radius, double minor_radius) {
    return std::make_shared<TorusShape>(major_radius, minor_radius);
}

}  // namespace lancer
