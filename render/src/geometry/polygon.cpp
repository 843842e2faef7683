// POV-Ray's polygon: flat loops of points in one plane, filled by the
// even-odd rule across all loops (a loop closes where a point repeats its
// first point, as POV's Parse_Polygon reads them). Not a solid: its inside
// test is always false, as POV's. (u, v) are the point's coordinates in
// the plane's frame.
#include <cmath>
#include <vector>

#include "geometry/shape.h"

namespace lancer {
namespace {

class PolygonShape final : public Shape {
  public:
    PolygonShape(const DVec3& origin, const DVec3& normal, const DVec3& axis_u, const DVec3& axis_v,
                 std::vector<std::vector<glm::dvec2>> loops, const DVec3& lower, const DVec3& upper)
        : m_origin(origin),
          m_normal(normal),
          m_axis_u(axis_u),
          m_axis_v(axis_v),
          m_loops(std::move(loops)),
          m_lower(lower),
          m_upper(upper) {}

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double denominator = glm::dot(m_normal, d);
        if (denominator == 0.0) return;
        const double t = glm::dot(m_origin - o, m_normal) / denominator;
        if (!(t > t_min && t < t_max)) return;
        const DVec3 local = o + t * d - m_origin;
        if (contains(glm::dvec2(glm::dot(local, m_axis_u), glm::dot(local, m_axis_v)))) out.add(t, 0);
    }

    SurfaceGeometry surface(const DVec3& p, int) const override {
        SurfaceGeometry g;
        g.normal = m_normal;
        g.point = p - glm::dot(p - m_origin, m_normal) * m_normal;
        const DVec3 local = g.point - m_origin;
        g.uv = Vec2(float(glm::dot(local, m_axis_u)), float(glm::dot(local, m_axis_v)));
        return g;
    }

    bool inside(const DVec3&) const override { return false; }
    bool solid() const override { return false; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = m_lower;
        upper = m_upper;
        return true;
    }

  private:
    // Even-odd: a ray from q along +u crosses the edges an odd number of times.
    bool contains(const glm::dvec2& q) const {
        bool inside = false;
        for (const auto& loop : m_loops) {
            for (std::size_t i = 0, j = loop.size() - 1; i < loop.size(); j = i++) {
                const glm::dvec2& a = loop[i];
                const glm::dvec2& b = loop[j];
                if ((a.y > q.y) != (b.y > q.y) && q.x < a.x + (q.y - a.y) * (b.x - a.x) / (b.y - a.y)) inside = !inside;
            }
        }
        return inside;
    }

    DVec3 m_origin, m_normal, m_axis_u, m_axis_v;
    std::vector<std::vector<glm::dvec2>> m_loops;
    DVec3 m_lower, m_upper;
};

}  // namespace

std::shared_ptr<const Shape> make_polygon_shape(const std::vector<DVec3>& points) {
    // Loops: a point equal to its loop's first point closes the loop.
    std::vector<std::vector<DVec3>> loops(1);
    bool open_loop = false;
    for (std::size_t i = 0; i < points.size(); ++i) {
        if (open_loop && points[i] == loops.back().front()) {
            open_loop = false;
            if (i + 1 < points.size()) loops.emplace_back();
            continue;
        }
        open_loop = true;
        loops.back().push_back(points[i]);
    }
    // The plane: Newell's normal of the loop enclosing the most area.
    DVec3 normal(0.0);
    for (const auto& loop : loops) {
        DVec3 n(0.0);
        for (std::size_t i = 0; i < loop.size(); ++i) {
            const DVec3& a = loop[i];
            const DVec3& b = loop[(i + 1) % loop.size()];
            n += DVec3((a.y - b.y) * (a.z + b.z), (a.z - b.z) * (a.x + b.x), (a.x - b.x) * (a.y + b.y));
        }
        if (glm::length(n) > glm::length(normal)) normal = n;
    }
    const double length = glm::length(normal);
    if (!(length > 0.0) || !std::isfinite(length)) return nullptr;
    normal /= length;
    const DVec3 reference = std::fabs(normal.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 1.0, 0.0);
    const DVec3 axis_v = glm::normalize(glm::cross(normal, reference));
    const DVec3 axis_u = glm::cross(axis_v, normal);
    const DVec3 origin = points[0];
    // Points off the plane count where they project onto it (and so do the bounds).
    std::vector<std::vector<glm::dvec2>> flat;
    DVec3 lower(INFINITY), upper(-INFINITY);
    for (const auto& loop : loops) {
        if (loop.size() < 3) continue;
        flat.emplace_back();
        for (const DVec3& p : loop) {
            const glm::dvec2 q(glm::dot(p - origin, axis_u), glm::dot(p - origin, axis_v));
            flat.back().push_back(q);
            const DVec3 on_plane = origin + q.x * axis_u + q.y * axis_v;
            lower = glm::min(lower, on_plane);
            upper = glm::max(upper, on_plane);
        }
    }
    if (flat.empty()) return nullptr;
    return std::make_shared<PolygonShape>(origin, normal, axis_u, axis_v, std::move(flat), lower, upper);
}

}  // namespace lancer
