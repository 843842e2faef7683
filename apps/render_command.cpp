// `lancer render SCENE [-i INTEGRATOR] [-o OUT] [--width W] [--height H]
//  [--spp N] [--seed S] [--threads T] [--crop x0,y0,x1,y1] [-p key=value]...
//  [--quiet]`
//
// Settings come from three places, later ones winning: lancer's defaults,
// the scene's render_settings, the command line. Every check that can fail
// runs before the render starts, and the image is written atomically at the
// end, so an error never leaves a file behind (nor a long render wasted).
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "commands.h"
#include "lancer/image_io.h"
#include "lancer/parser.h"
#include "lancer/plugin_host.h"
#include "lancer/renderer.h"
#include "lancer/scene_error.h"

namespace lancer::app {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDefaultIntegrator = "raycast";
constexpr int kDefaultWidth = 640;
constexpr int kDefaultHeight = 480;

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

struct RenderArguments {
    std::string scene;
    std::string integrator;
    std::string output;
    int width = 0;
    int height = 0;
    int spp = 0;
    std::uint64_t seed = 0;
    int threads = 0;
    std::string crop;
    std::vector<std::string> parameters;
    bool quiet = false;
    bool safe = false;  // --safe: files only from the scene's folder and the include path
    // Which options the user gave (CLI11 leaves the others untouched).
    CLI::Option* width_option = nullptr;
    CLI::Option* height_option = nullptr;
    CLI::Option* spp_option = nullptr;
    CLI::Option* seed_option = nullptr;
};

void print_error(const std::string& message) {
    std::fprintf(stderr, "lancer: error: %s\n", message.c_str());
}

// Located diagnostics in the parser's format; one without a file (a setting
// that came from no scene text) as a plain "lancer: error:" line.
void print_diagnostic(const Diagnostic& diagnostic) {
    if (!diagnostic.location.file) {
        const char* severity = diagnostic.severity == Diagnostic::Severity::Error     ? "error"
                               : diagnostic.severity == Diagnostic::Severity::Warning ? "warning"
                                                                                      : "note";
        std::fprintf(stderr, "lancer: %s: %s\n", severity, diagnostic.message.c_str());
        return;
    }
    std::string text = format_diagnostic(diagnostic);
    if (text.empty() || text.back() != '\n') text += '\n';
    std::fputs(text.c_str(), stderr);
}

// A SceneError from any stage after parsing, shown like a parser diagnostic.
void print_scene_error(const SceneError& error) {
    Diagnostic diagnostic;
    diagnostic.severity = Diagnostic::Severity::Error;
    diagnostic.location = error.location();
    diagnostic.message = error.what();
    print_diagnostic(diagnostic);
}

// "x0,y0,x1,y1" as four integers, nothing else.
bool parse_crop(const std::string& text, CropWindow& crop) {
    std::istringstream stream(text);
    int values[4];
    char comma = 0;
    for (int i = 0; i < 4; ++i) {
        if (!(stream >> values[i])) return false;
        if (i < 3 && (!(stream >> comma) || comma != ',')) return false;
    }
    stream >> std::ws;
    if (!stream.eof()) return false;
    crop = {values[0], values[1], values[2], values[3]};
    return true;
}

// Checks that need nothing but the arguments; returns an exit status, or 0.
int check_arguments(const RenderArguments& arguments) {
    if (arguments.width_option->count() && arguments.width <= 0) {
        print_error("--width must be a positive number of pixels, got " + std::to_string(arguments.width));
        return kExitUsage;
    }
    if (arguments.height_option->count() && arguments.height <= 0) {
        print_error("--height must be a positive number of pixels, got " + std::to_string(arguments.height));
        return kExitUsage;
    }
    if (arguments.spp_option->count() && arguments.spp <= 0) {
        print_error("--spp must be at least 1, got " + std::to_string(arguments.spp));
        return kExitUsage;
    }
    if (arguments.threads < 0) {
        print_error("--threads must be 0 (every core) or positive, got " + std::to_string(arguments.threads));
        return kExitUsage;
    }
    CropWindow crop{};
    if (!arguments.crop.empty() && !parse_crop(arguments.crop, crop)) {
        print_error("--crop expects four integers x0,y0,x1,y1 (pixels, x1 and y1 excluded), got '" +
                    arguments.crop + "'");
        return kExitUsage;
    }
    for (const auto& assignment : arguments.parameters) {
        const auto equals = assignment.find('=');
        if (equals == std::string::npos || equals == 0) {
            print_error("-p expects key=value, got '" + assignment + "'");
            return kExitUsage;
        }
    }
    if (!arguments.output.empty() && !is_supported_image_extension(arguments.output)) {
        print_error("cannot write '" + arguments.output +
                    "': unknown image extension (use .png, .exr, .hdr, .tif or .tiff)");
        return kExitUsage;
    }
    return 0;
}

std::string join_parameters(const ParameterSet& parameters) {
    std::string joined;
    for (const auto& [name, value] : parameters.values()) {
        if (!joined.empty()) joined += ' ';
        joined += name + "=" + value;
    }
    return joined;
}

int run_render(const RenderArguments& arguments) {
    if (const int status = check_arguments(arguments)) return status;

    // Parse; the command line's size is what POV's image_width/height read.
    ParseOptions parse_options;
    parse_options.include_path = default_include_path();
    parse_options.safe = arguments.safe;
    if (arguments.width_option->count() && arguments.height_option->count()) {
        parse_options.image_width = arguments.width;
        parse_options.image_height = arguments.height;
        parse_options.image_size_from_command_line = true;
    }
    ParseResult parsed = parse_scene_file(arguments.scene, parse_options);
    for (const auto& diagnostic : parsed.diagnostics) print_diagnostic(diagnostic);
    if (!parsed.ok()) return kExitBadInput;
    const sg::SceneGraph& graph = *parsed.scene;
    const sg::RenderSettings& settings = graph.render;

    // Settings: command line, then the scene's render_settings, then defaults.
    RenderOptions options;
    options.width = arguments.width_option->count() ? arguments.width : settings.width.value_or(kDefaultWidth);
    options.height =
        arguments.height_option->count() ? arguments.height : settings.height.value_or(kDefaultHeight);
    options.seed = arguments.seed_option->count() ? arguments.seed : settings.seed.value_or(0);
    options.threads = arguments.threads;
    options.progress = arguments.quiet ? ProgressMode::Quiet : ProgressMode::Auto;
    if (options.width <= 0 || options.height <= 0) {
        Diagnostic diagnostic;
        diagnostic.location = settings.location;
        diagnostic.message = "image size must be positive, got " + std::to_string(options.width) + "x" +
                             std::to_string(options.height);
        print_diagnostic(diagnostic);
        return kExitBadInput;
    }
    if (!arguments.crop.empty()) {
        CropWindow crop{};
        parse_crop(arguments.crop, crop);
        if (crop.x0 < 0 || crop.y0 < 0 || crop.x1 > options.width || crop.y1 > options.height ||
            crop.x0 >= crop.x1 || crop.y0 >= crop.y1) {
            print_error("--crop " + arguments.crop + " is not a non-empty rectangle inside the " +
                        std::to_string(options.width) + "x" + std::to_string(options.height) +
                        " image (x0 < x1 <= width, y0 < y1 <= height)");
            return kExitUsage;
        }
        options.crop = crop;
    }

    // Memory before anything is allocated: the film holds one Accumulator per
    // pixel and writing the image needs a float RGBA copy. Refuse what the
    // machine cannot hold; announce a big one (docs/robustness.md).
    {
        const double bytes = double(options.width) * double(options.height) *
                             double(sizeof(Film::Accumulator) + 4 * sizeof(float));
        const double physical = double(sysconf(_SC_PHYS_PAGES)) * double(sysconf(_SC_PAGESIZE));
        const double gib = double(1ull << 30);
        char estimate[160];
        std::snprintf(estimate, sizeof estimate, "render needs ~%.1f GiB for the film (%dx%d pixels)", bytes / gib,
                      options.width, options.height);
        if (physical > 0 && bytes > 0.8 * physical) {
            char machine[80];
            std::snprintf(machine, sizeof machine, ", more than this machine's %.1f GiB of memory allows", physical / gib);
            print_error(std::string(estimate) + machine);
            return kExitBadInput;
        }
        if (bytes >= double(256ull << 20)) std::fprintf(stderr, "lancer: %s\n", estimate);
    }

    // Output: the scene's stem in the current folder unless named.
    const std::string output =
        arguments.output.empty() ? fs::path(arguments.scene).stem().string() + ".png" : arguments.output;
    const fs::path output_folder = fs::absolute(output).parent_path();
    if (!fs::is_directory(output_folder)) {
        print_error("cannot write '" + output + "': folder '" + output_folder.string() + "' does not exist");
        return kExitBadInput;
    }

    // The integrator and its parameters. Scene parameters belong to the
    // scene's integrator; if -i picks another one they do not apply.
    const std::string integrator_name =
        !arguments.integrator.empty() ? arguments.integrator : settings.integrator.value_or(kDefaultIntegrator);
    std::map<std::string, sg::ParameterValue> scene_parameters = settings.parameters;
    if (settings.integrator && *settings.integrator != integrator_name && !scene_parameters.empty()) {
        Diagnostic warning;
        warning.severity = Diagnostic::Severity::Warning;
        warning.location = settings.location;
        warning.message = "render_settings parameters are for integrator '" + *settings.integrator +
                          "'; ignored because -i chose '" + integrator_name + "'";
        print_diagnostic(warning);
        scene_parameters.clear();
    }
    // `plugin` must outlive `integrator`: its code lives in the plugin's library.
    Plugin plugin;
    ParameterSet parameters;
    try {
        plugin = load_plugin(integrator_name);
        parameters = resolve_parameters(*plugin.descriptor, scene_parameters, arguments.parameters);
    } catch (const SceneError& error) {
        print_scene_error(error);
        return kExitBadInput;
    } catch (const PluginError& error) {
        print_error(error.what());
        return kExitBadInput;
    }

    try {
        std::unique_ptr<Integrator> integrator = plugin.descriptor->create(parameters);
        if (!integrator) {
            print_error("plugin '" + plugin.path + "' created no integrator");
            return kExitBadInput;
        }
        // A deterministic integrator is exact with one sample per pixel.
        options.samples_per_pixel = arguments.spp_option->count()
                                        ? arguments.spp
                                        : settings.samples.value_or(integrator->is_deterministic() ? 1 : 16);
        if (options.samples_per_pixel <= 0) {
            Diagnostic diagnostic;
            diagnostic.location = settings.location;
            diagnostic.message = "samples must be at least 1, got " + std::to_string(options.samples_per_pixel);
            print_diagnostic(diagnostic);
            return kExitBadInput;
        }

        const std::unique_ptr<RenderScene> scene = RenderScene::compile(graph);
        integrator->prepare(*scene);
        Film film(options.width, options.height);
        const RenderStats stats = render_image(*scene, *integrator, options, film);
        // What the host actually took: a deterministic integrator gets one
        // sample per pixel whatever --spp asks.
        const std::uint64_t pixels = options.crop ? std::uint64_t(options.crop->x1 - options.crop->x0) *
                                                        std::uint64_t(options.crop->y1 - options.crop->y0)
                                                  : std::uint64_t(options.width) * std::uint64_t(options.height);
        const std::uint64_t spp_taken = pixels > 0 ? stats.samples / pixels : 0;

        ImageWriteOptions write_options;
        // write_image stores each key as "lancer:<key>".
        write_options.metadata = {
            {"scene", arguments.scene},
            {"integrator", integrator_name},
            {"parameters", join_parameters(parameters)},
            {"spp", std::to_string(spp_taken)},
            {"seed", std::to_string(options.seed)},
            {"seconds", std::to_string(stats.seconds)},
        };
        write_image(film, output, write_options);

        if (stats.nonfinite_samples > 0) {
            std::fprintf(stderr, "lancer: warning: %llu non-finite samples (NaN or infinite radiance) were dropped\n",
                         static_cast<unsigned long long>(stats.nonfinite_samples));
        }
        if (!arguments.quiet) {
            std::printf("lancer: %dx%d, %llu spp, %s, %.2f s -> %s\n", options.width, options.height,
                        static_cast<unsigned long long>(spp_taken), integrator_name.c_str(), stats.seconds,
                        output.c_str());
        }
    } catch (const SceneError& error) {
        print_scene_error(error);
        return kExitBadInput;
    } catch (const std::exception& error) {
        print_error(error.what());
        return kExitBadInput;
    }
    return 0;
}

}  // namespace

Command add_render_command(CLI::App& app) {
    auto arguments = std::make_shared<RenderArguments>();
    CLI::App* render = app.add_subcommand("render", "Render a scene to an image with an integrator plugin");
    render->add_option("scene", arguments->scene, "Scene file (.pov)")->required();
    render->add_option("-i,--integrator", arguments->integrator,
                       "Integrator plugin (default: the scene's, else raycast; see `lancer plugins`)");
    render->add_option("-o,--output", arguments->output,
                       "Image file: .png, .exr, .hdr, .tif (default: <scene name>.png here)");
    arguments->width_option = render->add_option("--width", arguments->width, "Image width in pixels");
    arguments->height_option = render->add_option("--height", arguments->height, "Image height in pixels");
    arguments->spp_option = render->add_option(
        "--spp", arguments->spp, "Samples per pixel (default: the scene's, else 1 for deterministic integrators, 16)");
    arguments->seed_option = render->add_option("--seed", arguments->seed, "Random seed (default: the scene's, else 0)");
    render->add_option("--threads", arguments->threads, "Worker threads (default 0: every core)");
    render->add_option("--crop", arguments->crop, "Render only pixels x0 <= x < x1, y0 <= y < y1");
    CLI::Option* parameter_option = render->add_option("-p,--parameter", arguments->parameters,
                       "Integrator parameter key=value (repeatable); overrides the scene's")
        ->allow_extra_args(false);
    render->add_flag("-q,--quiet", arguments->quiet, "No progress and no summary line");
    render->add_flag("--safe", arguments->safe,
                     "Untrusted scene: read includes, OBJ/MTL and image files only from the scene's folder and the "
                     "include path");
    // A repeated option takes its last value, so a script can append overrides.
    for (CLI::Option* option : render->get_options()) {
        if (option->get_expected_max() == 1 && option != parameter_option) {
            option->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
        }
    }

    Command command;
    command.cli = render;
    command.run = [arguments] { return run_render(*arguments); };
    return command;
}

}  // namespace lancer::app
