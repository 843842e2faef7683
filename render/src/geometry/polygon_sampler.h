// Sampling a set of parallelograms or triangles by world area: box faces
// and emissive meshes (internal to liblancer).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

#include "geometry/shapes.h"

namespace lancer {

// Parallelograms (box faces) or triangles, sampled by world area.
class PolygonSampler final : public SurfaceSampler {
  public:
    struct Polygon {
        DVec3 origin, edge1, edge2;  // triangle: origin + b1 e1 + b2 e2, b1+b2 <= 1
        Vec2 uv0, uv1, uv2;          // uv at origin, origin+e1, origin+e2
        bool parallelogram = false;
        const Material* material = nullptr;
        DVec3 normal{0.0};  // unit, set by the sampler
    };
    PolygonSampler(std::vector<Polygon> polygons, bool closed) : m_closed(closed) {
        for (Polygon& p : polygons) {
            const double area = glm::length(glm::cross(p.edge1, p.edge2)) * (p.parallelogram ? 1.0 : 0.5);
            if (!(area > 0.0) || !std::isfinite(area)) continue;
            p.normal = glm::normalize(glm::cross(p.edge1, p.edge2));
            m_polygons.push_back(p);
            m_total += area;
            m_cdf.push_back(m_total);
            m_centroid += area * (p.origin + (p.parallelogram ? 0.5 : 1.0 / 3.0) * (p.edge1 + p.edge2));
        }
        if (m_total > 0.0) m_centroid /= m_total;
    }
    double area() const override { return m_total; }
    SurfacePoint sample(const Vec2& u) const override {
        SurfacePoint point;
        if (m_polygons.empty()) return point;
        // Pick a polygon by area, then reuse u.x's remainder within it.
        const double target = double(u.x) * m_total;
        std::size_t index = std::upper_bound(m_cdf.begin(), m_cdf.end(), target) - m_cdf.begin();
        index = std::min(index, m_polygons.size() - 1);
        const double lower = index == 0 ? 0.0 : m_cdf[index - 1];
        const double width = m_cdf[index] - lower;
        const double ux = width > 0.0 ? std::clamp((target - lower) / width, 0.0, 1.0 - 1e-16) : 0.5;
        const double uy = double(u.y);
        const Polygon& p = m_polygons[index];
        double b1, b2;
        if (p.parallelogram) {
            b1 = ux;
            b2 = uy;
        } else {
            const double s = std::sqrt(ux);
            b1 = 1.0 - s;
            b2 = uy * s;
        }
        point.position = p.origin + b1 * p.edge1 + b2 * p.edge2;
        point.normal = p.normal;
        const float fb1 = float(b1), fb2 = float(b2);
        point.uv = p.parallelogram ? p.uv0 + fb1 * (p.uv1 - p.uv0) + fb2 * (p.uv2 - p.uv0)
                                   : (1.0f - fb1 - fb2) * p.uv0 + fb1 * p.uv1 + fb2 * p.uv2;
        point.pdf_area = 1.0 / m_total;
        point.material = p.material;
        return point;
    }
    double pdf_area(const Hit&) const override { return m_total > 0.0 ? 1.0 / m_total : 0.0; }
    DVec3 centroid() const override { return m_centroid; }
    bool is_flat(DVec3& normal) const override {
        if (m_closed || m_polygons.empty()) return false;
        const DVec3 n0 = m_polygons[0].normal;
        double size = 0.0;
        for (const Polygon& p : m_polygons) size = std::max(size, glm::length(p.edge1) + glm::length(p.edge2));
        for (const Polygon& p : m_polygons) {
            if (std::fabs(glm::dot(p.normal, n0)) < 1.0 - 1e-9) return false;
            if (std::fabs(glm::dot(p.origin - m_polygons[0].origin, n0)) > 1e-9 * (size + glm::length(p.origin)))
                return false;
        }
        normal = n0;
        return true;
    }
    bool is_closed() const override { return m_closed; }
    void bounds(DVec3& lower, DVec3& upper) const override {
        lower = DVec3(std::numeric_limits<double>::infinity());
        upper = -lower;
        for (const Polygon& p : m_polygons)
            for (const DVec3& corner : {p.origin, p.origin + p.edge1, p.origin + p.edge2,
                                        p.origin + p.edge1 + (p.parallelogram ? p.edge2 : DVec3(0.0))}) {
                lower = glm::min(lower, corner);
                upper = glm::max(upper, corner);
            }
    }

  private:
    std::vector<Polygon> m_polygons;
    std::vector<double> m_cdf;
    double m_total = 0.0;
    DVec3 m_centroid{0.0};
    bool m_closed;
};

}  // namespace lancer
