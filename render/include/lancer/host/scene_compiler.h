// Compiling a scene graph into the RenderScene integrators query: the
// host's step between parsing and rendering, not part of the plugin SDK.
#pragma once

#include <memory>

#include "lancer/render_scene.h"
#include "lancer/scene_graph.h"

namespace lancer {

// Builds everything the scene uses and nothing else. Takes the graph by
// value: pass it with std::move and its meshes are moved into the render
// scene, not copied (a graph that shares a mesh with another is copied
// from). Throws lancer::SceneError (lancer/scene_error.h) with a source
// location on bad input (unreadable image, mesh index out of range).
std::unique_ptr<RenderScene> compile_scene(sg::SceneGraph graph);

// What POV-Ray's functions need of the renderer (noise, patterns,
// pigments) while a scene is parsed: ParseOptions::function_natives.
std::unique_ptr<sg::FunctionNatives> make_parse_time_function_natives();

}  // namespace lancer
