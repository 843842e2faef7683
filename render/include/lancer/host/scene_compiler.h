// Compiling a scene graph into the RenderScene integrators query: the
// host's step between parsing and rendering, not part of the plugin SDK.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lancer/geometry_queries.h"
#include "lancer/render_scene.h"
#include "lancer/scene_graph.h"

namespace lancer {

// Builds everything the scene uses and nothing else. Takes the graph by
// value: pass it with std::move and its meshes are moved into the render
// scene, not copied (a graph that shares a mesh with another is copied
// from). Throws lancer::SceneError (lancer/scene_error.h) with a source
// location on bad input (unreadable image, mesh index out of range).
std::unique_ptr<RenderScene> compile_scene(sg::SceneGraph graph);

// What only a finished render can tell about a scene, located where the
// scene wrote the object: POV-Ray's max_gradient advice for isosurfaces
// (holes where max_gradient was below the steepest slope rays met, or
// slowness where it was far above). Empty for a scene without isosurfaces.
struct RenderAdvice {
    sg::SourceLocation location;
    std::string message;
};
std::vector<RenderAdvice> advice_after_render(const RenderScene& scene);
// What a compiled scene shows that its text does not: a camera inside a
// solid object in a scene with fog, rainbows or media (POV-Ray draws none
// of them from there, silently; lancer says so).
std::vector<RenderAdvice> advice_before_render(const RenderScene& scene);

// What POV-Ray's functions need of the renderer (noise, patterns,
// pigments) while a scene is parsed: ParseOptions::function_natives.
std::unique_ptr<sg::FunctionNatives> make_parse_time_function_natives();

// What a scene's trace(), inside(), min_extent() and max_extent() ask of
// its objects while it is parsed: ParseOptions::geometry_queries.
std::unique_ptr<sg::GeometryQueries> make_parse_time_geometry_queries();

}  // namespace lancer
