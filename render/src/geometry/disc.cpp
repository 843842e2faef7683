// POV-Ray's disc: a flat ring facing its normal. (u, v) are the point's
// coordinates in the disc's plane (POV-Ray 3.7 defines none).
#include <cmath>

#include "geometry/shape.h"

namespace lancer {
namespace {

class DiscShape final : public Shape {
  public:
    explicit DiscShape(const DiscParameters& d) : m_disc(d) {
        const DVec3 reference = std::fabs(d.normal.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 0.0, 1.0);
        m_across2 = glm::normalize(glm::cross(reference, d.normal));
        m_across1 = glm::cross(d.normal, m_across2);
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double denominator = glm::dot(m_disc.normal, d);
        if (denominator == 0.0) return;
        const double t = glm::dot(m_disc.center - o, m_disc.normal) / denominator;
        if (!(t > t_min && t < t_max)) return;
        const DVec3 in_plane = o + t * d - m_disc.center;
        const double r2 = glm::dot(in_plane, in_plane) - std::pow(glm::dot(in_plane, m_disc.normal), 2.0);
        if (r2 <= m_disc.radius * m_disc.radius && r2 >= m_disc.hole_radius * m_disc.hole_radius) out.add(t, 0);
    }

    SurfaceGeometry surface(const DVec3& p, int) const override {
        SurfaceGeometry g;
        g.normal = m_disc.normal;
        g.point = p - glm::dot(p - m_disc.center, m_disc.normal) * m_disc.normal;
        const DVec3 local = g.point - m_disc.center;
        g.uv = Vec2(float(glm::dot(local, m_across1)), float(glm::dot(local, m_across2)));
        return g;
    }

    bool inside(const DVec3& p) const override { return glm::dot(p - m_disc.center, m_disc.normal) < 0.0; }
    bool inside_within_bounds() const override { return false; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        const DVec3 spread =
            m_disc.radius * glm::sqrt(glm::max(DVec3(0.0), DVec3(1.0) - m_disc.normal * m_disc.normal));
        // POV-Ray's box is 0.001 thick either side of the disc (its
        // SMALL_TOLERANCE): a ray leaving the disc starts inside it, so a
        // CSG intersection that POV bounds by the disc's box still finds its
        // other surfaces from there, as in POV-Ray.
        const DVec3 thickness = 0.001 * glm::abs(m_disc.normal);
        lower = m_disc.center - spread - thickness;
        upper = m_disc.center + spread + thickness;
        return true;
    }

  private:
    DiscParameters m_disc;
    DVec3 m_across1{1.0, 0.0, 0.0}, m_across2{0.0, 0.0, 1.0};
};

}  // namespace

std::shared_ptr<const Shape> make_disc_shape(const DiscParameters& disc) {
    return std::make_shared<DiscShape>(disc);
}

}  // namespace lancer
