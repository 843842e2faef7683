// The pipeline every command that renders shares: parse the scene once,
// settle which integrator and parameters, compile, render through a ray
// counter. `lancer render` and `lancer trade` are built from these steps;
// each later command should be too, so a scene means the same everywhere.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "lancer/host/film.h"
#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/integrator.h"
#include "lancer/parser.h"
#include "lancer/render_scene.h"
#include "lancer/scene_graph.h"
#include "scene_input_options.h"

namespace lancer::app {

// What renders a scene that names no integrator: the one that shows what
// POV-Ray shows (shadows, mirrors, refraction) for POV's scenes.
inline constexpr const char* kDefaultIntegrator = "whitted";

// A scene parsed once and compiled, with what commands read of its graph
// after compiling consumed it.
struct JobScene {
    std::string path;
    sg::RenderSettings settings;   // the scene's render_settings
    double working_gamma = 1.0;    // POV's assumed_gamma: what the image writer decodes
    bool gamma_correction = true;  // false: POV's legacy mode, files receive the values unchanged
    std::unique_ptr<RenderScene> scene;
};

// What a command needs to parse the scene: the include path comes from
// default_include_path(). A size given here is what the scene's
// image_width and image_height read (POV's command-line size).
struct SceneRequest {
    std::string path;
    bool safe = false;
    std::optional<int> image_width, image_height;
    AnimationFrame animation;  // POV's clock and frame constants (all 0 for a still)
    SceneInputOptions inputs;  // -I and -D
    long long max_memory_bytes = ParseOptions{}.max_memory_bytes;  // --max-memory
};

// Parses the scene once, printing every diagnostic (and appending it to
// `diagnostics` when given), and keeps the graph for compile_job_scene.
// Empty when the scene has errors.
std::optional<sg::SceneGraph> parse_job_scene(const SceneRequest& request,
                                              std::vector<Diagnostic>* diagnostics = nullptr);

// Compiles the parsed graph, consuming it. Throws lancer::SceneError for
// what the user can fix (an unreadable image_map).
JobScene compile_job_scene(const std::string& path, sg::SceneGraph graph);

// The integrator a render uses and its resolved parameters. `plugin` holds
// the library the integrator's code lives in: destroy `integrator` first
// (members are destroyed in reverse order, so it is declared last).
struct JobIntegrator {
    std::string name;
    Plugin plugin;
    ParameterSet parameters;
    std::unique_ptr<Integrator> integrator;
};

// The scene's render_settings parameters belong to the scene's own
// integrator: for any other, none apply. `ignored` (when not null) is set
// to a warning, located at the render_settings block, when the scene's
// parameters are dropped for this reason.
std::map<std::string, sg::ParameterValue> scene_parameters_for(const sg::RenderSettings& settings,
                                                               const std::string& integrator,
                                                               std::optional<Diagnostic>* ignored);

// Prints what the scene means for this integrator alone: for `path`, the
// finishes that return more light than they receive.
void warn_about_scene_for(const sg::SceneGraph& scene, const std::string& integrator);
// POV-Ray's warnings that only a finished render can give (an
// isosurface's max_gradient against the slopes its rays met).
void warn_after_render(const RenderScene& scene);

// Loads `name` (empty: the scene's integrator, else kDefaultIntegrator),
// resolves its parameters (the scene's, under `assignments` from -p) and
// creates it; prints the warning of scene_parameters_for. Throws
// PluginError or SceneError (a bad parameter value).
JobIntegrator load_job_integrator(const sg::RenderSettings& settings, const std::string& name,
                                  const std::vector<std::string>& assignments);

// Renders `integrator` over `scene` into `film`: prepared and rendered
// through one counting wrapper, so stats.rays counts every query and an
// integrator that remembers its prepared scene sees the one it renders.
RenderStats render_job(const RenderScene& scene, Integrator& integrator, RenderOptions options, Film& film);

}  // namespace lancer::app
