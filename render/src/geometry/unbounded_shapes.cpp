// Shapes outside the BVH (see unbounded_shapes.h).
#include "geometry/unbounded_shapes.h"

#include "geometry/embree_scene.h"

namespace lancer::embree {

void UnboundedShapes::add(const Instance& instance, std::uint32_t index) {
    Entry entry;
    entry.instance = index;
    entry.casts_shadow = instance.casts_shadow;
    // In world coordinates ray_to_object maps nothing, so the plane's own
    // test on the world ray is the same arithmetic.
    entry.world_plane = instance.kind == ShapeKind::Plane && instance.placement.identity;
    if (entry.world_plane) {
        entry.normal = instance.plane.normal;
        entry.distance = instance.plane.distance;
    }
    m_shapes.push_back(entry);
    m_instances.push_back(index);
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

bool UnboundedShapes::nearest(const SceneData& data, const Ray& ray, double t_min, double& t_max,
                              std::uint32_t& instance, std::uint32_t& leaf, int& face) const {
    const DVec3 origin(ray.origin), direction(ray.direction);
    bool found = false;
    for (const Entry& shape : m_shapes) {
        double t;
        std::uint32_t shape_leaf = shape.instance;
        int shape_face = 0;
        if (!(shape.world_plane ? cross_plane(shape.normal, shape.distance, origin, direction, t_min, t_max, t)
                                : crosses_instance(data, shape.instance, ray, t_min, t_max, t, shape_leaf, shape_face)))
            continue;
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
        if (shape.world_plane ? cross_plane(shape.normal, shape.distance, origin, direction, t_min, t_max, t)
                              : crosses_instance(data, shape.instance, ray, t_min, t_max, t, leaf, face))
            return true;
    }
    return false;
}

}  // namespace lancer::embree
