// Compiling the scene graph into the scene data tables
// (geometry/scene_data.h); internal to liblancer.
#pragma once

#include <memory>

#include "geometry/scene_data.h"
#include "lancer/scene_graph.h"

namespace lancer {

// Throws lancer::SceneError for what the user can fix (unreadable image,
// mesh index out of range). Consumes the graph: a mesh that only the graph
// holds is moved into the scene data, not copied.
std::unique_ptr<SceneData> build_scene_data(sg::SceneGraph& graph);

// One object alone, for the parser's geometry queries (trace, inside,
// min_extent, max_extent): its scene data, and in `inside` POV's inside
// test of its solid (valid while the scene data lives).
std::unique_ptr<SceneData> build_object_scene_data(const sg::Object& object, const sg::GlobalSettings& settings,
                                                   InsideTest& inside);

}  // namespace lancer
