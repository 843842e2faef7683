// The host's compile step: scene graph -> scene data tables -> Embree scene.
#include "lancer/host/scene_compiler.h"

#include "geometry/embree_scene.h"
#include "host/scene_builder.h"

namespace lancer {

std::unique_ptr<RenderScene> compile_scene(sg::SceneGraph graph) {
    return make_embree_scene(build_scene_data(graph));
}

std::vector<RenderAdvice> advice_after_render(const RenderScene& scene) {
    std::vector<RenderAdvice> advice;
    const auto* compiled = dynamic_cast<const embree::EmbreeScene*>(&scene);
    if (!compiled) return advice;
    for (const SceneData::IsosurfaceRecord& record : compiled->data().isosurfaces)
        if (auto message = isosurface_gradient_advice(record.parameters, *record.gradients))
            advice.push_back({record.location, "isosurface: " + *message});
    return advice;
}

std::vector<RenderAdvice> advice_before_render(const RenderScene& scene) {
    std::vector<RenderAdvice> advice;
    const auto* compiled = dynamic_cast<const embree::EmbreeScene*>(&scene);
    if (!compiled || !(scene.has_media() || scene.fog() || scene.rainbows())) return advice;
    const InteriorStack& inside = scene.camera_interiors();
    for (int i = 0; i < inside.size; ++i) {
        const InteriorStack::Entry& entry = inside.entries[std::size_t(i)];
        if (entry.material->parameters().hollow) continue;
        advice.push_back({compiled->data().instances[entry.object_id].location,
                          "the camera is inside this object, which is not hollow: as in POV-Ray, a ray inside a solid "
                          "object shows no fog, rainbow or media, so the camera sees none of them (make the object "
                          "hollow to see them)"});
        break;
    }
    return advice;
}

}  // namespace lancer
