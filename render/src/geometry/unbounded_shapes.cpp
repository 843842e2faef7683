// Shapes outside the BVH (see unbounded_shapes.h).
#include "geometry/unbounded_shapes.h"

#include <cmath>

#include "geometry/csg.h"
#include "geometry/embree_scene.h"

namespace lancer::embree {

namespace {

// The plane of a plane instance in world coordinates. Written in world
// coordinates it is the instance's own, so the test is the same
// arithmetic as through ray_to_object. Placed, the object's plane
// dot(n, A p + b) = D (A, b: the placement's object_from_world) is
// dot(A^T n, p) = D - dot(n, b) in the world: the same t up to the
// rounding of these products, far below the float error bound that
// offsets the rays leaving a hit. False if the placement flattens it.
bool world_plane_of(const Instance& instance, DVec3& normal, double& distance) {
    if (instance.placement.identity) {
        normal = instance.plane.normal;
        distance = instance.plane.distance;
        return true;
    }
    const DMat4& to_object = instance.placement.object_from_world;
    const DVec3 n = instance.plane.normal;
    const DVec3 world_normal = glm::transpose(DMat3(to_object)) * n;
    const double length = glm::length(world_normal);
    const double world_distance = instance.plane.distance - glm::dot(n, DVec3(to_object[3]));
    if (!(length > 0.0) || !std::isfinite(length) || !std::isfinite(world_distance)) return false;
    normal = world_normal / length;
    distance = world_distance / length;
    return std::isfinite(distance);
}

}  // namespace

void UnboundedShapes::add(const Instance& instance, std::uint32_t index) {
    Entry entry;
    entry.instance = index;
    entry.casts_shadow = instance.casts_shadow;
    entry.blocks_all_light = instance.blocks_all_light;
    if (instance.kind == ShapeKind::Plane) entry.world_plane = world_plane_of(instance, entry.normal, entry.distance);
    // A tree's root is placed at the identity (its leaves carry the world
    // placements), so the world ray is the tree's.
    if (instance.kind == ShapeKind::Csg && instance.placement.identity)
        if (const CsgNode* leaf = instance.csg->lone_leaf()) {
            entry.lone_leaf = true;
            entry.leaf = leaf->instance;
        }
    m_shapes.push_back(entry);
}

// Any shape other than a world plane, in its own space.
bool UnboundedShapes::crosses_instance(const SceneData& data, std::uint32_t index, const Ray& ray, double t_min,
                                       double t_max, double& t, std::uint32_t& leaf, int& face) {
    const float org[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const float dir[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    DVec3 o, d;
    ray_to_object(data.instances[index], org, dir, o, d);
    return intersect_analytic(data, index, o, d, t_min, t_max, t, face, leaf);
}

// Inline: a world plane's test is a division, cheaper than a call.
inline bool UnboundedShapes::crosses(const SceneData& data, const Entry& shape, const Ray& ray, const DVec3& origin,
                                     const DVec3& direction, double t_min, double t_max, double& t, std::uint32_t& leaf,
                                     int& face) {
    leaf = shape.instance;
    face = 0;
    if (shape.world_plane) return cross_plane(shape.normal, shape.distance, origin, direction, t_min, t_max, t);
    if (shape.lone_leaf) {
        CsgCrossing crossing;
        if (!CsgTree::leaf_nearest(data.instances[shape.leaf], shape.leaf, origin, direction, t_min, t_max, crossing))
            return false;
        t = crossing.t;
        leaf = crossing.instance;
        face = crossing.face;
        return true;
    }
    return crosses_instance(data, shape.instance, ray, t_min, t_max, t, leaf, face);
}

bool UnboundedShapes::nearest(const SceneData& data, const Ray& ray, double t_min, double& t_max,
                              std::uint32_t& instance, std::uint32_t& leaf, int& face) const {
    const DVec3 origin(ray.origin), direction(ray.direction);
    bool found = false;
    for (const Entry& shape : m_shapes) {
        double t;
        std::uint32_t shape_leaf;
        int shape_face;
        if (!crosses(data, shape, ray, origin, direction, t_min, t_max, t, shape_leaf, shape_face)) continue;
        t_max = t;
        instance = shape.instance;
        leaf = shape_leaf;
        face = shape_face;
        found = true;
    }
    return found;
}

bool UnboundedShapes::occluded(const SceneData& data, const Ray& ray, double t_min, double t_max) const {
    const DVec3 origin(ray.origin), direction(ray.direction);
    for (const Entry& shape : m_shapes) {
        if (!shape.casts_shadow) continue;
        double t;
        std::uint32_t leaf;
        int face;
        if (crosses(data, shape, ray, origin, direction, t_min, t_max, t, leaf, face)) return true;
    }
    return false;
}

ShadowBlockers UnboundedShapes::shadow_blockers(const SceneData& data, const Ray& ray, double t_min,
                                                double t_max) const {
    const DVec3 origin(ray.origin), direction(ray.direction);
    bool see_through = false;
    for (const Entry& shape : m_shapes) {
        // Once one surface that may let light through is found, only an
        // opaque one changes the answer.
        if (!shape.casts_shadow || (see_through && !shape.blocks_all_light)) continue;
        double t;
        std::uint32_t leaf;
        int face;
        if (!crosses(data, shape, ray, origin, direction, t_min, t_max, t, leaf, face)) continue;
        if (shape.blocks_all_light) return ShadowBlockers::Opaque;
        see_through = true;
    }
    return see_through ? ShadowBlockers::SeeThrough : ShadowBlockers::None;
}

}  // namespace lancer::embree
