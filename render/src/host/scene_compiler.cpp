// The host's compile step: scene graph -> scene data tables -> Embree scene.
#include "lancer/host/scene_compiler.h"

#include "geometry/embree_scene.h"
#include "host/scene_builder.h"

namespace lancer {

std::unique_ptr<RenderScene> compile_scene(sg::SceneGraph graph) {
    return make_embree_scene(build_scene_data(graph));
}

}  // namespace lancer
