// Objects that stop every shadow ray (see light_blockers.h).
#include "geometry/light_blockers.h"

namespace lancer {
namespace {

// The walk lights a surface's layers and texture_map entries one by one,
// except on a light's surface (lancer/shading/material_blend.h:
// layers_to_light), which it sees through that material's own pigment.
bool material_blocks(const Material* material, bool on_a_light) {
    if (material == nullptr) return false;
    const MaterialParameters& parameters = material->parameters();
    return on_a_light ? parameters.pigment_opaque : parameters.blocks_light;
}

bool surface_blocks(const Instance& instance) {
    if (!instance.casts_shadow) return false;
    const bool on_a_light = instance.light != nullptr || instance.emitter != nullptr;
    if (!material_blocks(instance.material, on_a_light)) return false;
    if (instance.interior_material && !material_blocks(instance.interior_material, on_a_light)) return false;
    for (const Material* face : instance.face_materials)
        if (face && !material_blocks(face, on_a_light)) return false;
    return true;
}

}  // namespace

bool blocks_all_light(const SceneData& data, const Instance& instance) {
    if (instance.kind != ShapeKind::Csg) return surface_blocks(instance);
    if (!instance.casts_shadow || instance.csg == nullptr) return false;
    for (const CsgNode& node : instance.csg->nodes)
        if (node.operation == CsgNode::Operation::Leaf &&
            (node.instance >= data.instances.size() || !surface_blocks(data.instances[node.instance])))
            return false;
    return true;
}

bool gathers_crossings(const SceneData& data, const Instance& instance) {
    if (instance.kind == ShapeKind::Csg) {
        if (instance.csg == nullptr) return false;
        for (const CsgNode& node : instance.csg->nodes)
            if (node.operation == CsgNode::Operation::Leaf &&
                (node.instance >= data.instances.size() || !gathers_crossings(data, data.instances[node.instance])))
                return false;
        return true;
    }
    return instance.shape == nullptr || instance.shape->finds_crossings_past_t_min();
}

}  // namespace lancer
