// Objects containing a point (geometry/containing_objects.h).
#include "geometry/containing_objects.h"

#include <algorithm>
#include <limits>
#include <vector>

#include "geometry/mesh_shape.h"

namespace lancer {
namespace {

bool box_holds(const Instance& instance, const DVec3& p) {
    return !instance.bounded || (p.x >= double(instance.bounds_lower.x) && p.x <= double(instance.bounds_upper.x) &&
                                 p.y >= double(instance.bounds_lower.y) && p.y <= double(instance.bounds_upper.y) &&
                                 p.z >= double(instance.bounds_lower.z) && p.z <= double(instance.bounds_upper.z));
}

bool shape_holds(const Shape& shape, const Instance& instance, const DVec3& p) {
    return shape.solid() && shape.inside(instance.placement.point_to_object(p));
}

// A mesh has an inside only with POV's inside_vector. The camera's test is
// made once a scene, so the mesh is built as a Shape for it alone.
bool mesh_holds(const Instance& instance, const DVec3& p) {
    const MeshData* mesh = instance.mesh;
    if (mesh == nullptr || !mesh->inside_vector) return false;
    MeshShapeParameters parameters;
    parameters.positions = mesh_positions_from_xyz(mesh->object_positions);
    parameters.faces.resize(mesh->indices.size() / 3);
    for (std::size_t t = 0; t < parameters.faces.size(); ++t)
        for (int k = 0; k < 3; ++k) parameters.faces[t].position[k] = int(mesh->indices[3 * t + std::size_t(k)]);
    parameters.inside_vector = instance.placement.vector_to_object(DVec3(*mesh->inside_vector));
    const std::shared_ptr<const Shape> shape = make_mesh_shape(std::move(parameters));
    return shape && shape_holds(*shape, instance, p);
}

// The instance whose interior a point inside `instance` is in, if any:
// itself, or for a CSG object the (uninverted) leaf that holds the point.
const Instance* container_at(const SceneData& data, const Instance& instance, const DVec3& p) {
    if (instance.csg_leaf || instance.light != nullptr || !box_holds(instance, p)) return nullptr;
    switch (instance.kind) {
    case ShapeKind::Sphere: return shape_holds(*make_sphere_shape(instance.sphere), instance, p) ? &instance : nullptr;
    case ShapeKind::Box: return shape_holds(*make_box_shape(instance.box), instance, p) ? &instance : nullptr;
    case ShapeKind::Plane: return shape_holds(*make_plane_shape(instance.plane), instance, p) ? &instance : nullptr;
    case ShapeKind::Analytic: return shape_holds(*instance.shape, instance, p) ? &instance : nullptr;
    case ShapeKind::Csg: {
        const CsgTree& tree = *instance.csg;
        if (!tree.inside(data.instances, tree.root, p)) return nullptr;
        // The object's own leaves, not its clips' or bounds'.
        const Instance* first_leaf = nullptr;
        std::vector<std::uint32_t> pending{tree.root};
        while (!pending.empty()) {
            const CsgNode& node = tree.nodes[pending.back()];
            pending.pop_back();
            if (node.operation != CsgNode::Operation::Leaf) {
                pending.insert(pending.end(), node.children.rbegin(), node.children.rend());
                continue;
            }
            const Instance& leaf = data.instances[node.instance];
            if (first_leaf == nullptr) first_leaf = &leaf;
            if (!node.inverted && shape_holds(*leaf.shape, leaf, p)) return &leaf;
        }
        return first_leaf;
    }
    case ShapeKind::Mesh: return mesh_holds(instance, p) ? &instance : nullptr;
    case ShapeKind::Rectangle: return nullptr;
    }
    return nullptr;
}

double box_volume(const Instance& instance) {
    if (!instance.bounded) return std::numeric_limits<double>::infinity();
    const glm::dvec3 size = glm::dvec3(instance.bounds_upper) - glm::dvec3(instance.bounds_lower);
    return size.x * size.y * size.z;
}

}  // namespace

InteriorStack objects_containing(const SceneData& data, const Vec3& p) {
    struct Found {
        double volume;
        InteriorStack::Entry entry;
    };
    std::vector<Found> found;
    const DVec3 point(p);
    for (const Instance& instance : data.instances) {
        const Instance* container = container_at(data, instance, point);
        if (container == nullptr || container->material == nullptr) continue;
        const auto object_id = std::uint32_t(container - data.instances.data());
        found.push_back({box_volume(instance), {container->material, object_id, container->interior_id}});
    }
    std::stable_sort(found.begin(), found.end(), [](const Found& a, const Found& b) { return a.volume > b.volume; });
    InteriorStack stack;
    for (const Found& f : found) stack.push(f.entry);
    return stack;
}

}  // namespace lancer
