// `lancer check SCENE`: parse and evaluate a scene, print its diagnostics
// and a summary (objects, triangles, lights, materials, bounds, warnings).
// Exit status: 0 when the scene is valid, 1 when it has errors.
#include <cstdio>
#include <string>
#include <vector>

#include "cli_output.h"
#include "commands.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"
#include "lancer/scene_summary.h"
#include "render_job.h"
#include "scene_input_options.h"

namespace lancer::app {

namespace {

struct CheckOptions {
    std::string scene;
    SceneInputOptions inputs;
    int width = 0;
    int height = 0;
    bool safe = false;
    long long max_memory_bytes = ParseOptions{}.max_memory_bytes;
};

}  // namespace

Command add_check_command(CLI::App& app) {
    auto options = std::make_shared<CheckOptions>();
    Command command;
    command.cli = app.add_subcommand("check", "Parse and evaluate a scene, print a summary");
    command.cli->add_option("scene", options->scene, "Scene file (.pov)")->required();
    add_scene_input_options(*command.cli, options->inputs);
    command.cli->add_option("--width", options->width, "Image width seen as image_width")->check(CLI::PositiveNumber);
    command.cli->add_option("--height", options->height, "Image height seen as image_height")
        ->check(CLI::PositiveNumber);
    command.cli->add_flag("--safe", options->safe,
                          "Untrusted scene: read includes, OBJ/MTL and image files only from the scene's folder "
                          "and the include path");
    add_max_memory_option(*command.cli, options->max_memory_bytes);
    command.run = [options] {
        ParseOptions parse_options;
        parse_options.safe = options->safe;
        parse_options.include_path = default_include_path();
        std::string problem;
        if (!apply_scene_input_options(options->inputs, parse_options, problem)) {
            print_error(problem);
            return 2;
        }
        parse_options.max_memory_bytes = options->max_memory_bytes;
        if (options->width > 0 || options->height > 0) {
            // One given: keep POV's 4:3 default for the other.
            parse_options.image_width = options->width > 0 ? options->width : options->height * 4 / 3;
            parse_options.image_height = options->height > 0 ? options->height : options->width * 3 / 4;
            parse_options.image_size_from_command_line = true;
        }
        const auto natives = make_parse_time_function_natives();
        parse_options.function_natives = natives.get();
        const auto geometry = make_parse_time_geometry_queries();
        parse_options.geometry_queries = geometry.get();
        ParseResult result = parse_scene_file(options->scene, parse_options);
        int warnings = 0;
        for (const auto& diagnostic : result.diagnostics) {
            if (diagnostic.severity == Diagnostic::Severity::Warning) ++warnings;
            std::fputs(format_diagnostic(diagnostic).c_str(), stderr);
        }
        if (!result.ok()) {
            int errors = 0;
            for (const auto& diagnostic : result.diagnostics)
                if (diagnostic.severity == Diagnostic::Severity::Error) ++errors;
            std::fprintf(stderr, "%s: %d error(s), %d warning(s)\n", escape_for_terminal(options->scene).c_str(),
                         errors, warnings);
            return 1;
        }
        SceneSummary summary = summarize_scene(*result.scene);
        std::fputs(format_scene_summary(summary, *result.scene, warnings, kDefaultIntegrator).c_str(), stdout);
        return 0;
    };
    return command;
}

}  // namespace lancer::app
