// `lancer check SCENE`: parse and evaluate a scene, print its diagnostics
// and a summary (objects, triangles, lights, materials, bounds, warnings).
// Exit status: 0 when the scene is valid, 1 when it has errors.
#include <cstdio>
#include <string>
#include <vector>

#include "commands.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"
#include "lancer/scene_summary.h"
#include "render_job.h"

namespace lancer::app {

namespace {

struct CheckOptions {
    std::string scene;
    std::vector<std::string> include_path;
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
    command.cli
        ->add_option("-I,--include-path", options->include_path,
                     "Folder searched for #include files (repeatable); searched before LANCER_INCLUDE_PATH")
        ->take_last()
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
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
        parse_options.max_memory_bytes = options->max_memory_bytes;
        parse_options.include_path = options->include_path;
        for (const auto& dir : default_include_path()) parse_options.include_path.push_back(dir);
        if (options->width > 0 || options->height > 0) {
            // One given: keep POV's 4:3 default for the other.
            parse_options.image_width = options->width > 0 ? options->width : options->height * 4 / 3;
            parse_options.image_height = options->height > 0 ? options->height : options->width * 3 / 4;
            parse_options.image_size_from_command_line = true;
        }
        const auto natives = make_parse_time_function_natives();
        parse_options.function_natives = natives.get();
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
