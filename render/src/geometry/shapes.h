// Analytic shapes in double precision, in their own object space, and
// surfaces that can be sampled by area (internal to liblancer).
//
// Intersections run in double on the ray mapped to object space, so a ray
// leaving a surface from an origin offset by Hit::position_error (float
// ULPs) never finds that surface again, at any scale.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "lancer/hit.h"
#include "lancer/material.h"

namespace lancer {

using DVec3 = glm::dvec3;
using DMat4 = glm::dmat4;
using DMat3 = glm::dmat3;

// A rigid-or-not affine placement of an object in the world.
struct Placement {
    DMat4 world_from_object{1.0};
    DMat4 object_from_world{1.0};
    DMat3 normal_to_world{1.0};  // inverse transpose of the linear part
    // Exactly the identity (an object written in world coordinates, the
    // common case): the transforms below return their input, as the
    // products would, without a matrix product per hit.
    bool identity = true;

    static Placement from(const DMat4& world_from_object);
    DVec3 point_to_world(const DVec3& p) const { return identity ? p : DVec3(world_from_object * glm::dvec4(p, 1.0)); }
    DVec3 point_to_object(const DVec3& p) const { return identity ? p : DVec3(object_from_world * glm::dvec4(p, 1.0)); }
    DVec3 vector_to_object(const DVec3& v) const {
        return identity ? v : DVec3(object_from_world * glm::dvec4(v, 0.0));
    }
    DVec3 normal_to_world_unit(const DVec3& n) const { return glm::normalize(identity ? n : normal_to_world * n); }
    // Bound on the absolute error of point_to_world(p) rounded to float.
    Vec3 world_point_error(const DVec3& p_object, const DVec3& p_world) const;
    // True if the linear part is a rotation times a uniform scale.
    bool is_similarity() const;
    double uniform_scale() const;
};

struct AnalyticSphere {
    DVec3 center{0.0};
    double radius = 1.0;
};
struct AnalyticBox {
    DVec3 lower{-1.0};
    DVec3 upper{1.0};
};
struct AnalyticPlane {
    AnalyticPlane() : AnalyticPlane(DVec3(0.0, 1.0, 0.0), 0.0) {}
    AnalyticPlane(const DVec3& unit_normal, double distance);
    DVec3 normal;              // unit
    double distance;           // dot(p, normal) = distance
    DVec3 tangent1, tangent2;  // the (u, v) axes, made once (plane_surface)
};
// A parallelogram centre ± axis1/2 ± axis2/2 (rectangle area lights), in
// world space.
struct AnalyticRectangle {
    DVec3 center{0.0};
    DVec3 axis1{1.0, 0.0, 0.0};
    DVec3 axis2{0.0, 0.0, 1.0};
};

// Nearest root of o + t d in the open interval (t_min, t_max); `face`
// receives the box face (0..5: -x, +x, -y, +y, -z, +z).
bool intersect_sphere(const AnalyticSphere& s, const DVec3& o, const DVec3& d, double t_min, double t_max, double& t);
bool intersect_box(const AnalyticBox& b, const DVec3& o, const DVec3& d, double t_min, double t_max, double& t,
                   int& face);
bool intersect_plane(const AnalyticPlane& p, const DVec3& o, const DVec3& d, double t_min, double t_max, double& t);
// intersect_plane on the plane dot(p, normal) = distance.
inline bool cross_plane(const DVec3& normal, double distance, const DVec3& o, const DVec3& d, double t_min,
                        double t_max, double& t) {
    const double denominator = glm::dot(normal, d);
    if (denominator == 0.0) return false;
    const double candidate = (distance - glm::dot(normal, o)) / denominator;
    if (!(candidate > t_min && candidate < t_max)) return false;
    t = candidate;
    return true;
}
bool intersect_rectangle(const AnalyticRectangle& r, const DVec3& o, const DVec3& d, double t_min, double t_max,
                         double& t);

// Surface details at a point already on the shape (object space).
struct SurfaceGeometry {
    DVec3 point;   // projected exactly onto the surface
    DVec3 normal;  // unit, outward: the surface's own (a smoothed shape's facet)
    Vec2 uv;
    // Unit, for shading, where it is not `normal` (a smooth height field's
    // or mesh's interpolated normal); zero: `normal`. Rays leave along the
    // facet's, which the hit point's error box is measured across.
    DVec3 shading_normal{0.0};
};
// Without `with_uv` the (u, v) is left zero (the scene reads none).
SurfaceGeometry sphere_surface(const AnalyticSphere& s, const DVec3& p, bool with_uv = true);
SurfaceGeometry box_surface(const AnalyticBox& b, const DVec3& p, int face, bool with_uv = true);
SurfaceGeometry plane_surface(const AnalyticPlane& plane, const DVec3& p);
SurfaceGeometry rectangle_surface(const AnalyticRectangle& r, const DVec3& p);

// A point drawn on a surface for next-event estimation.
struct SurfacePoint {
    DVec3 position{0.0};  // world
    DVec3 normal{0.0};    // unit world geometric normal
    Vec2 uv{0.0f};
    double pdf_area = 0.0;  // per unit world area
    const Material* material = nullptr;
};

// Area sampling of one object's emitting surface.
class SurfaceSampler {
  public:
    virtual ~SurfaceSampler() = default;
    virtual double area() const = 0;  // world area of what sample() covers
    virtual SurfacePoint sample(const Vec2& u) const = 0;
    // Area density sample() has at `hit` (on this surface).
    virtual double pdf_area(const Hit& hit) const = 0;
    virtual DVec3 centroid() const = 0;  // area-weighted, world
    // True with the normal if every point shares one plane.
    virtual bool is_flat(DVec3& normal) const = 0;
    // Closed surfaces emit from one side only towards the outside world.
    virtual bool is_closed() const = 0;
    // A world box holding every point sample() can return.
    virtual void bounds(DVec3& lower, DVec3& upper) const = 0;
};

std::unique_ptr<SurfaceSampler> make_sphere_sampler(const AnalyticSphere& s, const Placement& placement,
                                                    const Material* material);
std::unique_ptr<SurfaceSampler> make_box_sampler(const AnalyticBox& b, const Placement& placement,
                                                 const Material* material);
// Triangles given in world space with their uvs and materials (one entry per
// triangle; degenerate triangles are dropped).
struct WorldTriangle {
    DVec3 p[3];
    Vec2 uv[3];
    const Material* material = nullptr;
};
std::unique_ptr<SurfaceSampler> make_triangle_sampler(std::vector<WorldTriangle> triangles);

}  // namespace lancer
