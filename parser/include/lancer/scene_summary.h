// A summary of a scene graph: what `lancer check` prints, and what tests
// use to assert that a scene produced the expected things.
#pragma once

#include <map>
#include <optional>
#include <string>

#include "lancer/scene_graph.h"

namespace lancer {

struct SceneSummary {
    // Every object node, unions and their descendants included, by the
    // scene-language keyword that made it ("sphere", "mesh2", "union" ...).
    std::map<std::string, int> objects_by_kind;
    int object_count = 0;
    long long triangles = 0;  // over all mesh-like objects, instances counted
    std::map<std::string, int>
        lights_by_kind;  // "point", "directional", "area_light" (POV's), "area_rectangle", "area_sphere"
    int light_count = 0;
    int materials = 0;  // distinct materials (textures, per-face and MTL materials)
    // World-space bounds of the finite objects; planes are unbounded and
    // only counted.
    std::optional<std::pair<sg::Vec3, sg::Vec3>> bounds;
    int unbounded_objects = 0;
};

SceneSummary summarize_scene(const sg::SceneGraph& scene);

// Human-readable, several lines; `warnings` is the diagnostic count to report.
// `default_integrator`: what a render of a scene that names no integrator
// uses, printed as such (empty: nothing is printed for such a scene).
std::string format_scene_summary(const SceneSummary& summary, const sg::SceneGraph& scene, int warnings,
                                 const std::string& default_integrator = "");

const char* object_kind_name(sg::Object::Kind kind);
const char* light_kind_name(sg::Light::Kind kind);

}  // namespace lancer
