// Analytic shapes in double precision and area samplers for emitters.
#include "geometry/shapes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <numeric>

namespace lancer {
namespace {

constexpr double kPiD = 3.141592653589793238463;

DMat3 linear_part(const DMat4& m) { return DMat3(m); }

// Orthonormal tangents of a unit normal: for +y they are +x and +z, which
// makes a y-plane's (u,v) its (x,z).
void tangent_frame(const DVec3& n, DVec3& t1, DVec3& t2) {
    DVec3 reference = std::fabs(n.x) < 0.9 ? DVec3(1.0, 0.0, 0.0) : DVec3(0.0, 0.0, 1.0);
    t2 = glm::normalize(glm::cross(reference, n));
    t1 = glm::cross(n, t2);
    if (std::fabs(n.x) >= 0.9) std::swap(t1, t2);
}

}  // namespace

// ------------------------------------------------------------- placement

Placement Placement::from(const DMat4& world_from_object) {
    Placement p;
    p.world_from_object = world_from_object;
    p.object_from_world = glm::inverse(world_from_object);
    p.normal_to_world = glm::transpose(glm::inverse(linear_part(world_from_object)));
    return p;
}

Vec3 Placement::world_point_error(const DVec3& p_object, const DVec3& p_world) const {
    // Rounding the double result to float (half an ULP, taken as two for
    // safety) plus the double arithmetic of the transform.
    const DMat3 a = linear_part(world_from_object);
    DVec3 magnitude(0.0);
    for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) magnitude[row] += std::fabs(a[col][row]) * std::fabs(p_object[col]);
    magnitude += glm::abs(DVec3(world_from_object[3]));
    const DVec3 error = 2.0 * double(FLT_EPSILON) * glm::abs(p_world) + 16.0 * DBL_EPSILON * magnitude;
    return Vec3(error);
}

bool Placement::is_similarity() const {
    const DMat3 a = linear_part(world_from_object);
    const double s0 = glm::length(a[0]), s1 = glm::length(a[1]), s2 = glm::length(a[2]);
    const double s = std::max({s0, s1, s2});
    if (!(s > 0.0)) return false;
    const double tolerance = 1e-9 * s * s;
    return std::fabs(s0 - s1) < 1e-9 * s && std::fabs(s0 - s2) < 1e-9 * s &&
           std::fabs(glm::dot(a[0], a[1])) < tolerance && std::fabs(glm::dot(a[0], a[2])) < tolerance &&
           std::fabs(glm::dot(a[1], a[2])) < tolerance;
}

double Placement::uniform_scale() const { return glm::length(linear_part(world_from_object)[0]); }

// ------------------------------------------------------------ intersections

bool intersect_sphere(const AnalyticSphere& s, const DVec3& o, const DVec3& d, double t_min, double t_max,
                      double& t) {
    const DVec3 oc = o - s.center;
    const double a = glm::dot(d, d);
    if (!(a > 0.0)) return false;
    const double b = glm::dot(oc, d);
    // Discriminant from the closest approach of the line to the centre
    // (pbrt-v4): no cancellation when the origin is far from a small sphere.
    const DVec3 closest = oc - (b / a) * d;
    const double r2 = s.radius * s.radius;
    const double discriminant = a * (r2 - glm::dot(closest, closest));
    if (discriminant < 0.0) return false;
    const double root = std::sqrt(discriminant);
    const double q = -(b + std::copysign(root, b));
    // c is accurate exactly when the origin is near the surface, which is
    // when t1 = c / q is the small root.
    const double c = glm::dot(oc, oc) - r2;
    double t0 = q / a;
    double t1 = q != 0.0 ? c / q : t0;
    if (t0 > t1) std::swap(t0, t1);
    if (t0 > t_min && t0 < t_max) {
        t = t0;
        return true;
    }
    if (t1 > t_min && t1 < t_max) {
        t = t1;
        return true;
    }
    return false;
}

bool intersect_box(const AnalyticBox& b, const DVec3& o, const DVec3& d, double t_min, double t_max, double& t,
                   int& face) {
    double t_enter = -INFINITY, t_exit = INFINITY;
    int face_enter = -1, face_exit = -1;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (o[axis] < b.lower[axis] || o[axis] > b.upper[axis]) return false;
            continue;
        }
        const double inverse = 1.0 / d[axis];
        double t_lower = (b.lower[axis] - o[axis]) * inverse;
        double t_upper = (b.upper[axis] - o[axis]) * inverse;
        int f_lower = 2 * axis, f_upper = 2 * axis + 1;
        if (t_lower > t_upper) {
            std::swap(t_lower, t_upper);
            std::swap(f_lower, f_upper);
        }
        if (t_lower > t_enter) {
            t_enter = t_lower;
            face_enter = f_lower;
        }
        if (t_upper < t_exit) {
            t_exit = t_upper;
            face_exit = f_upper;
        }
        if (t_enter > t_exit) return false;
    }
    if (t_enter > t_min && t_enter < t_max && face_enter >= 0) {
        t = t_enter;
        face = face_enter;
        return true;
    }
    if (t_exit > t_min && t_exit < t_max && face_exit >= 0) {
        t = t_exit;
        face = face_exit;
        return true;
    }
    return false;
}

bool intersect_plane(const AnalyticPlane& p, const DVec3& o, const DVec3& d, double t_min, double t_max,
                     double& t) {
    const double denominator = glm::dot(p.normal, d);
    if (denominator == 0.0) return false;
    const double candidate = (p.distance - glm::dot(p.normal, o)) / denominator;
    if (!(candidate > t_min && candidate < t_max)) return false;
    t = candidate;
    return true;
}

bool intersect_rectangle(const AnalyticRectangle& r, const DVec3& o, const DVec3& d, double t_min,
                         double t_max, double& t) {
    const DVec3 normal = glm::cross(r.axis1, r.axis2);
    const double denominator = glm::dot(normal, d);
    if (denominator == 0.0) return false;
    const double candidate = glm::dot(r.center - o, normal) / denominator;
    if (!(candidate > t_min && candidate < t_max)) return false;
    const DVec3 local = o + candidate * d - r.center;
    const double s1 = glm::dot(local, r.axis1) / glm::dot(r.axis1, r.axis1);
    const double s2 = glm::dot(local, r.axis2) / glm::dot(r.axis2, r.axis2);
    if (std::fabs(s1) > 0.5 || std::fabs(s2) > 0.5) return false;
    t = candidate;
    return true;
}

// ------------------------------------------------------- surface geometry

SurfaceGeometry sphere_surface(const AnalyticSphere& s, const DVec3& p) {
    SurfaceGeometry g;
    DVec3 offset = p - s.center;
    const double length = glm::length(offset);
    g.normal = length > 0.0 ? offset / length : DVec3(0.0, 1.0, 0.0);
    g.point = s.center + s.radius * g.normal;
    // POV's spherical map: u from +x towards +z, v from the south pole.
    const double horizontal = std::sqrt(g.normal.x * g.normal.x + g.normal.z * g.normal.z);
    double u = horizontal > 0.0 ? std::atan2(g.normal.z, g.normal.x) / (2.0 * kPiD) : 0.0;
    if (u < 0.0) u += 1.0;
    const double v = 0.5 + std::atan2(g.normal.y, horizontal) / kPiD;
    g.uv = Vec2(float(u), float(v));
    return g;
}

SurfaceGeometry box_surface(const AnalyticBox& b, const DVec3& p, int face) {
    SurfaceGeometry g;
    const int axis = face / 2;
    const bool upper = face % 2 == 1;
    g.point = glm::clamp(p, b.lower, b.upper);
    g.point[axis] = upper ? b.upper[axis] : b.lower[axis];
    g.normal = DVec3(0.0);
    g.normal[axis] = upper ? 1.0 : -1.0;
    // Per face: x faces map (z, y), y faces (x, z), z faces (x, y); each
    // spans [0,1]^2 over the face.
    const int u_axis = axis == 0 ? 2 : 0;
    const int v_axis = axis == 1 ? 2 : 1;
    const DVec3 extent = b.upper - b.lower;
    auto fraction = [&](int a) {
        return extent[a] > 0.0 ? (g.point[a] - b.lower[a]) / extent[a] : 0.0;
    };
    g.uv = Vec2(float(fraction(u_axis)), float(fraction(v_axis)));
    return g;
}

SurfaceGeometry plane_surface(const AnalyticPlane& plane, const DVec3& p) {
    SurfaceGeometry g;
    g.normal = plane.normal;
    g.point = p - (glm::dot(plane.normal, p) - plane.distance) * plane.normal;
    DVec3 t1, t2;
    tangent_frame(plane.normal, t1, t2);
    g.uv = Vec2(float(glm::dot(g.point, t1)), float(glm::dot(g.point, t2)));
    return g;
}

SurfaceGeometry rectangle_surface(const AnalyticRectangle& r, const DVec3& p) {
    SurfaceGeometry g;
    const DVec3 normal = glm::cross(r.axis1, r.axis2);
    g.normal = glm::normalize(normal);
    g.point = p - glm::dot(p - r.center, g.normal) * g.normal;
    const DVec3 local = g.point - r.center;
    g.uv = Vec2(float(glm::dot(local, r.axis1) / glm::dot(r.axis1, r.axis1) + 0.5),
                float(glm::dot(local, r.axis2) / glm::dot(r.axis2, r.axis2) + 0.5));
    return g;
}

// --------------------------------------------------------------- samplers

namespace {

// Area element ratio world/object at a point with world normal n.
double area_jacobian(const Placement& placement, const DVec3& world_normal) {
    const DMat3 a = linear_part(placement.world_from_object);
    const double det = std::fabs(glm::determinant(a));
    const double projected = glm::length(glm::transpose(a) * world_normal);
    return projected > 0.0 ? det / projected : 0.0;
}

class SphereSampler final : public SurfaceSampler {
public:
    SphereSampler(const AnalyticSphere& s, const Placement& placement, const Material* material)
        : m_sphere(s), m_placement(placement), m_material(material) {
        const double object_area = 4.0 * kPiD * s.radius * s.radius;
        // World area: exact for similarities, a fixed stratified estimate otherwise.
        if (placement.is_similarity()) {
            const double k = placement.uniform_scale();
            m_area = object_area * k * k;
        } else {
            double sum = 0.0;
            const int n = 64;
            for (int i = 0; i < n; ++i)
                for (int j = 0; j < n; ++j)
                    sum += area_jacobian(m_placement, sample(Vec2((i + 0.5f) / n, (j + 0.5f) / n)).normal);
            m_area = object_area * sum / double(n * n);
        }
    }
    double area() const override { return m_area; }
    SurfacePoint sample(const Vec2& u) const override {
        const double z = 1.0 - 2.0 * double(u.x);
        const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
        const double phi = 2.0 * kPiD * double(u.y);
        const DVec3 direction(r * std::cos(phi), z, r * std::sin(phi));
        const SurfaceGeometry g = sphere_surface(m_sphere, m_sphere.center + m_sphere.radius * direction);
        SurfacePoint point;
        point.position = m_placement.point_to_world(g.point);
        point.normal = m_placement.normal_to_world_unit(g.normal);
        point.uv = g.uv;
        const double object_area = 4.0 * kPiD * m_sphere.radius * m_sphere.radius;
        const double jacobian = area_jacobian(m_placement, point.normal);
        point.pdf_area = jacobian > 0.0 && object_area > 0.0 ? 1.0 / (object_area * jacobian) : 0.0;
        point.material = m_material;
        return point;
    }
    double pdf_area(const Hit& hit) const override {
        const double object_area = 4.0 * kPiD * m_sphere.radius * m_sphere.radius;
        const double jacobian = area_jacobian(m_placement, DVec3(hit.geometric_normal));
        return jacobian > 0.0 && object_area > 0.0 ? 1.0 / (object_area * jacobian) : 0.0;
    }
    DVec3 centroid() const override { return m_placement.point_to_world(m_sphere.center); }
    bool is_flat(DVec3&) const override { return false; }
    bool is_closed() const override { return true; }

private:
    AnalyticSphere m_sphere;
    Placement m_placement;
    const Material* m_material;
    double m_area = 0.0;
};

// Parallelograms (box faces) or triangles, sampled by world area.
class PolygonSampler final : public SurfaceSampler {
public:
    struct Polygon {
        DVec3 origin, edge1, edge2;  // triangle: origin + b1 e1 + b2 e2, b1+b2 <= 1
        Vec2 uv0, uv1, uv2;          // uv at origin, origin+e1, origin+e2
        bool parallelogram = false;
        const Material* material = nullptr;
    };
    PolygonSampler(std::vector<Polygon> polygons, bool closed) : m_closed(closed) {
        for (Polygon& p : polygons) {
            const double area = glm::length(glm::cross(p.edge1, p.edge2)) * (p.parallelogram ? 1.0 : 0.5);
            if (!(area > 0.0) || !std::isfinite(area)) continue;
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
        point.normal = glm::normalize(glm::cross(p.edge1, p.edge2));
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
        const DVec3 n0 = glm::normalize(glm::cross(m_polygons[0].edge1, m_polygons[0].edge2));
        double size = 0.0;
        for (const Polygon& p : m_polygons) size = std::max(size, glm::length(p.edge1) + glm::length(p.edge2));
        for (const Polygon& p : m_polygons) {
            const DVec3 n = glm::normalize(glm::cross(p.edge1, p.edge2));
            if (std::fabs(glm::dot(n, n0)) < 1.0 - 1e-9) return false;
            if (std::fabs(glm::dot(p.origin - m_polygons[0].origin, n0)) > 1e-9 * (size + glm::length(p.origin)))
                return false;
        }
        normal = n0;
        return true;
    }
    bool is_closed() const override { return m_closed; }

private:
    std::vector<Polygon> m_polygons;
    std::vector<double> m_cdf;
    double m_total = 0.0;
    DVec3 m_centroid{0.0};
    bool m_closed;
};

}  // namespace

std::unique_ptr<SurfaceSampler> make_sphere_sampler(const AnalyticSphere& s, const Placement& placement,
                                                    const Material* material) {
    return std::make_unique<SphereSampler>(s, placement, material);
}

std::unique_ptr<SurfaceSampler> make_box_sampler(const AnalyticBox& b, const Placement& placement,
                                                 const Material* material) {
    std::vector<PolygonSampler::Polygon> faces;
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const int u_axis = axis == 0 ? 2 : 0;
        const int v_axis = axis == 1 ? 2 : 1;
        DVec3 corner = b.lower;
        corner[axis] = face % 2 == 1 ? b.upper[axis] : b.lower[axis];
        DVec3 along_u(0.0), along_v(0.0);
        along_u[u_axis] = b.upper[u_axis] - b.lower[u_axis];
        along_v[v_axis] = b.upper[v_axis] - b.lower[v_axis];
        PolygonSampler::Polygon p;
        p.origin = placement.point_to_world(corner);
        p.edge1 = placement.point_to_world(corner + along_u) - p.origin;
        p.edge2 = placement.point_to_world(corner + along_v) - p.origin;
        p.uv0 = Vec2(0.0f, 0.0f);
        p.uv1 = Vec2(1.0f, 0.0f);
        p.uv2 = Vec2(0.0f, 1.0f);
        p.parallelogram = true;
        p.material = material;
        faces.push_back(p);
    }
    return std::make_unique<PolygonSampler>(std::move(faces), true);
}

std::unique_ptr<SurfaceSampler> make_triangle_sampler(std::vector<WorldTriangle> triangles) {
    std::vector<PolygonSampler::Polygon> polygons;
    polygons.reserve(triangles.size());
    for (const WorldTriangle& t : triangles) {
        PolygonSampler::Polygon p;
        p.origin = t.p[0];
        p.edge1 = t.p[1] - t.p[0];
        p.edge2 = t.p[2] - t.p[0];
        p.uv0 = t.uv[0];
        p.uv1 = t.uv[1];
        p.uv2 = t.uv[2];
        p.material = t.material;
        polygons.push_back(p);
    }
    return std::make_unique<PolygonSampler>(std::move(polygons), false);
}

}  // namespace lancer
