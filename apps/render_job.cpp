#include "render_job.h"

#include <stdexcept>
#include <utility>

#include "cli_output.h"
#include "lancer/finish_balance.h"
#include "lancer/host/counting_scene.h"
#include "lancer/host/scene_compiler.h"

namespace lancer::app {

std::optional<sg::SceneGraph> parse_job_scene(const SceneRequest& request, std::vector<Diagnostic>* diagnostics) {
    ParseOptions options;
    options.include_path = default_include_path();
    options.safe = request.safe;
    options.animation = request.animation;
    std::string problem;
    if (!apply_scene_input_options(request.inputs, options, problem)) {
        print_error(problem);
        if (diagnostics) {
            Diagnostic error;
            error.message = problem;
            diagnostics->push_back(error);
        }
        return std::nullopt;
    }
    options.max_memory_bytes = request.max_memory_bytes;
    if (request.image_width && request.image_height) {
        options.image_width = *request.image_width;
        options.image_height = *request.image_height;
        options.image_size_from_command_line = true;
    }
    const auto natives = make_parse_time_function_natives();
    options.function_natives = natives.get();
    const auto geometry = make_parse_time_geometry_queries();
    options.geometry_queries = geometry.get();
    ParseResult parsed = parse_scene_file(request.path, options);
    for (const Diagnostic& diagnostic : parsed.diagnostics) print_diagnostic(diagnostic);
    if (diagnostics) diagnostics->insert(diagnostics->end(), parsed.diagnostics.begin(), parsed.diagnostics.end());
    if (!parsed.ok()) return std::nullopt;
    return std::move(parsed.scene);
}

namespace {

void print_advice(const std::vector<RenderAdvice>& advice) {
    for (const RenderAdvice& item : advice) {
        Diagnostic warning;
        warning.severity = Diagnostic::Severity::Warning;
        warning.location = item.location;
        warning.message = item.message;
        print_diagnostic(warning);
    }
}

}  // namespace

JobScene compile_job_scene(const std::string& path, sg::SceneGraph graph) {
    JobScene job;
    job.path = path;
    job.settings = graph.render;
    job.working_gamma = graph.global.assumed_gamma;
    job.gamma_correction = graph.global.gamma_correction;
    job.scene = compile_scene(std::move(graph));
    print_advice(advice_before_render(*job.scene));
    return job;
}

std::map<std::string, sg::ParameterValue> scene_parameters_for(const sg::RenderSettings& settings,
                                                               const std::string& integrator,
                                                               std::optional<Diagnostic>* ignored) {
    if (!settings.integrator || *settings.integrator == integrator) return settings.parameters;
    if (ignored && !settings.parameters.empty()) {
        Diagnostic warning;
        warning.severity = Diagnostic::Severity::Warning;
        warning.location = settings.location;
        warning.message = "render_settings parameters are for integrator '" + *settings.integrator +
                          "'; ignored for '" + integrator + "'";
        *ignored = warning;
    }
    return {};
}

// The first object (depth first) that sets double_illuminate on, or null.
const sg::Object* first_double_illuminated(const std::vector<sg::Object>& objects) {
    for (const sg::Object& object : objects) {
        if (object.double_illuminate.value_or(false)) return &object;
        if (const auto* group = std::get_if<sg::Group>(&object.shape))
            if (const sg::Object* inside = first_double_illuminated(group->children)) return inside;
    }
    return nullptr;
}

void warn_about_scene_for(const sg::SceneGraph& scene, const std::string& integrator) {
    // Only path follows light bounce after bounce: whitted's and gather's
    // recursions end, so a bright finish there is just bright, as in POV.
    if (integrator != "path") return;
    for (const Diagnostic& warning : energy_gaining_finishes(scene)) print_diagnostic(warning);
    // POV-Ray's fog and rainbow are effects the classic integrators add
    // along camera and reflected rays, not light in a volume: path, the
    // physical reference, has no such effect to add.
    const auto ignored = [](const sg::SourceLocation& location, const std::string& what) {
        Diagnostic warning;
        warning.severity = Diagnostic::Severity::Warning;
        warning.location = location;
        warning.message = "path ignores " + what +
                          " (a POV-Ray effect of raycast, shadow, whitted and gather, not light in a volume); for "
                          "path, fill the scene with a scattering media";
        print_diagnostic(warning);
    };
    if (!scene.fogs.empty()) ignored(scene.fogs.front().location, scene.fogs.size() > 1 ? "every fog" : "fog");
    if (!scene.rainbows.empty())
        ignored(scene.rainbows.front().location, scene.rainbows.size() > 1 ? "every rainbow" : "rainbow");
    if (const sg::Object* object = first_double_illuminated(scene.objects)) {
        Diagnostic warning;
        warning.severity = Diagnostic::Severity::Warning;
        warning.location = object->location;
        warning.message =
            "path ignores double_illuminate (POV-Ray's light from behind a surface, which raycast, shadow, whitted "
            "and gather show); in path light passes a surface only through what it transmits";
        print_diagnostic(warning);
    }
}

void warn_after_render(const RenderScene& scene) {
    print_advice(advice_after_render(scene));
}

JobIntegrator load_job_integrator(const sg::RenderSettings& settings, const std::string& name,
                                  const std::vector<std::string>& assignments) {
    JobIntegrator job;
    job.name = !name.empty() ? name : settings.integrator.value_or(kDefaultIntegrator);
    std::optional<Diagnostic> ignored;
    const auto scene_parameters = scene_parameters_for(settings, job.name, &ignored);
    if (ignored) print_diagnostic(*ignored);
    job.plugin = load_plugin(job.name);
    job.parameters = resolve_parameters(*job.plugin.descriptor, scene_parameters, assignments);
    job.integrator = job.plugin.descriptor->create(job.parameters);
    if (!job.integrator) throw PluginError("plugin '" + job.plugin.path + "' created no integrator");
    return job;
}

RenderStats render_job(const RenderScene& scene, Integrator& integrator, RenderOptions options, Film& film) {
    CountingScene counted(scene);
    integrator.prepare(counted);
    options.ray_counter = &counted;
    return render_image(counted, integrator, options, film);
}

}  // namespace lancer::app
