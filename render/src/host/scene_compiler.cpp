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

}  // namespace lancer
