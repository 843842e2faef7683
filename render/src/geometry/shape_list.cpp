// Tracing a few shapes without a BVH (see shape_list.h).
#include "geometry/shape_list.h"

#include <algorithm>
#include <cfloat>
#include <utility>

#include "geometry/embree_scene.h"

namespace lancer::embree {
namespace {

// Whether the ray's [t_near, t_far] meets the box: the slab test with the
// far distance widened by the rounding of its own computation (pbrt's
// 1 + 2 gamma(3)), so it never rejects a box that the exact ray meets. A
// direction component of zero gives infinite slab distances, or NaN for an
// origin on the slab's plane, which the comparisons then leave out.
bool meets_box(const Vec3& origin, const Vec3& inverse_direction, const Vec3& lower, const Vec3& upper, float t_near,
               float t_far) {
    constexpr float kWiden = 1.0f + 2.0f * (3.0f * FLT_EPSILON * 0.5f) / (1.0f - 3.0f * FLT_EPSILON * 0.5f);
    for (int axis = 0; axis < 3; ++axis) {
        float entry = (lower[axis] - origin[axis]) * inverse_direction[axis];
        float exit = (upper[axis] - origin[axis]) * inverse_direction[axis];
        if (entry > exit) std::swap(entry, exit);
        exit *= kWiden;
        t_near = entry > t_near ? entry : t_near;
        t_far = exit < t_far ? exit : t_far;
        if (t_near > t_far) return false;
    }
    return true;
}

}  // namespace

void ShapeList::add(const Instance& instance, std::uint32_t index, unsigned geometry, unsigned primitive) {
    m_shapes.push_back(
        Entry{instance.bounds_lower, instance.bounds_upper, index, geometry, primitive, instance.casts_shadow});
}

// The nearest crossing of one listed shape over [t_near, t_far], as
// Embree's user-geometry callbacks compute it.
bool ShapeList::crosses(const SceneData& data, const Entry& shape, const Ray& ray, float t_near, float t_far, double& t,
                        int& face, std::uint32_t& leaf) {
    const float org[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const float dir[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    DVec3 o, d;
    ray_to_object(data.instances[shape.instance], org, dir, o, d);
    return intersect_analytic(data, shape.instance, o, d, t_near, t_far, t, face, leaf);
}

void ShapeList::nearest(const SceneData& data, const Ray& ray, EmbreeHit& found) const {
    const Vec3 inverse_direction = 1.0f / ray.direction;
    for (const Entry& shape : m_shapes) {
        if (!meets_box(ray.origin, inverse_direction, shape.lower, shape.upper, found.tnear, found.tfar)) continue;
        double t;
        int face;
        std::uint32_t leaf;
        if (!crosses(data, shape, ray, found.tnear, found.tfar, t, face, leaf)) continue;
        const float t_float = float(t);
        if (!(t_float < found.tfar)) continue;
        found.tfar = t_float;
        found.geometry = shape.geometry;
        found.primitive = shape.primitive;
        found.u = float(face);
        found.v = float(shape.instance - leaf);
    }
}

bool ShapeList::occluded(const SceneData& data, const Ray& ray, float t_near, float t_far) const {
    const Vec3 inverse_direction = 1.0f / ray.direction;
    for (const Entry& shape : m_shapes) {
        if (!shape.casts_shadow || !meets_box(ray.origin, inverse_direction, shape.lower, shape.upper, t_near, t_far))
            continue;
        double t;
        int face;
        std::uint32_t leaf;
        if (crosses(data, shape, ray, t_near, t_far, t, face, leaf)) return true;
    }
    return false;
}

bool ShapeList::may_meet_hull(const DVec3* points, int point_count, const DVec3* axes, int axis_count,
                              double margin) const {
    DVec3 hull_lower(points[0]), hull_upper(points[0]);
    for (int i = 1; i < point_count; ++i) {
        hull_lower = glm::min(hull_lower, points[i]);
        hull_upper = glm::max(hull_upper, points[i]);
    }
    // The hull's extent along each axis, the same for every shape.
    constexpr int kMostAxes = 8;
    double hull_min[kMostAxes], hull_max[kMostAxes];
    axis_count = std::min(axis_count, kMostAxes);  // fewer axes: still conservative
    for (int a = 0; a < axis_count; ++a) {
        hull_min[a] = hull_max[a] = glm::dot(points[0], axes[a]);
        for (int i = 1; i < point_count; ++i) {
            const double x = glm::dot(points[i], axes[a]);
            hull_min[a] = std::min(hull_min[a], x);
            hull_max[a] = std::max(hull_max[a], x);
        }
    }
    for (const Entry& shape : m_shapes) {
        if (!shape.casts_shadow) continue;
        const DVec3 lower = DVec3(shape.lower) - margin, upper = DVec3(shape.upper) + margin;
        // The world axes: the two boxes.
        if (glm::any(glm::lessThan(hull_upper, lower)) || glm::any(glm::lessThan(upper, hull_lower))) continue;
        const DVec3 centre = 0.5 * (lower + upper), half = 0.5 * (upper - lower);
        bool separated = false;
        for (int a = 0; a < axis_count && !separated; ++a) {
            const double box_middle = glm::dot(centre, axes[a]);
            const double box_reach = glm::dot(half, glm::abs(axes[a]));
            separated = hull_max[a] < box_middle - box_reach || box_middle + box_reach < hull_min[a];
        }
        if (!separated) return true;
    }
    return false;
}

}  // namespace lancer::embree
