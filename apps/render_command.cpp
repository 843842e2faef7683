// `lancer render SCENE [-i INTEGRATOR] [-o OUT] [--width W] [--height H]
//  [--spp N] [--time SECONDS] [--noise E] [--seed S] [--threads T]
//  [--crop x0,y0,x1,y1] [-p key=value]... [--stats FILE.json]
//  [--checkpoint SECONDS] [--resume] [--quiet] [--frames A..B [--clock C0..C1]]`
//
// Settings come from three places, later ones winning: lancer's defaults,
// the scene's render_settings, the command line. Every check that can fail
// runs before the render starts, and the image is written atomically at the
// end, so an error never leaves a file behind (nor a long render wasted).
// SIGINT and SIGTERM end the render early and write the image so far (see
// docs/rendering.md). Under mpirun every process runs this command and the
// job is shared among them (distribution.h, docs/distributed.md).
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iterator>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "animation.h"
#include "cli_output.h"
#include "commands.h"
#include "distribution.h"
#include "interrupts.h"
#include "lancer/host/aov.h"
#include "lancer/host/checkpoint.h"
#include "lancer/host/counting_scene.h"
#include "lancer/host/image_io.h"
#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/host/temporary_file.h"
#include "lancer/parser.h"
#include "lancer/scene_error.h"
#include "output_files.h"
#include "preview_feed.h"
#include "preview_server.h"
#include "render_job.h"
#include "render_report.h"

namespace lancer::app {
namespace {

namespace fs = std::filesystem;

constexpr int kDefaultWidth = 640;
constexpr int kDefaultHeight = 480;

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

// Time kept back from a --time budget for writing the image, per pixel and
// fixed (measured: a 640x480 PNG takes about 30 ms to encode).
constexpr double kOutputReserveSeconds = 0.05;
constexpr double kOutputReserveSecondsPerPixel = 1e-7;

struct RenderArguments {
    std::string scene;
    std::string integrator;
    std::string output;
    int width = 0;
    int height = 0;
    int spp = 0;
    double time_budget = 0.0;
    double noise = 0.0;
    std::string stats;
    double checkpoint_interval = 0.0;
    bool resume = false;
    std::uint64_t seed = 0;
    int threads = 0;
    std::string crop;
    std::vector<std::string> parameters;
    bool quiet = false;
    bool safe = false;   // --safe: files only from the scene's folder and the include path
    std::string frames;  // --frames A..B: an animation, one image per frame
    std::string clock;   // --clock C0..C1 (default 0..1)
    std::string aov;     // --aov albedo,normal,...: layers in the EXR beside the beauty
    bool alpha = false;  // --alpha (POV's +UA): an alpha channel
    int png_bits = 8;    // --bits
    int jpeg_quality = 90;
    SceneInputOptions inputs;
    long long max_memory_bytes = ParseOptions{}.max_memory_bytes;  // --max-memory
    // Which options the user gave (CLI11 leaves the others untouched).
    CLI::Option* output_option = nullptr;
    CLI::Option* stats_option = nullptr;
    CLI::Option* width_option = nullptr;
    CLI::Option* height_option = nullptr;
    CLI::Option* spp_option = nullptr;
    CLI::Option* seed_option = nullptr;
    CLI::Option* time_option = nullptr;
    CLI::Option* noise_option = nullptr;
    CLI::Option* checkpoint_option = nullptr;
    CLI::Option* frames_option = nullptr;
    CLI::Option* clock_option = nullptr;
    CLI::Option* aov_option = nullptr;
    CLI::Option* bits_option = nullptr;
    CLI::Option* quality_option = nullptr;
    bool preview = false;  // --preview: a live page of the render
    int port = 0;          // --port: the page's port (0: any free one)
    CLI::Option* port_option = nullptr;
};

// One image to make: a still, or one frame of an animation with its own
// clock and numbered files.
struct FrameJob {
    AnimationFrame animation;
    std::string output;
    std::string stats;
    bool animated = false;
    // One of several processes mpirun started (docs/distributed.md): an
    // interrupted render writes no image (a rank that died ends the job, and
    // only a whole image may be left), and signal handlers are the caller's.
    bool distributed = false;
    // This frame's part of the animation's progress.
    ProgressShare progress;
    // --preview: the page that shows the render as it refines.
    PreviewServer* preview = nullptr;
};

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

// The layers --aov names, and whether the image has an alpha channel
// (--alpha, or alpha among the layers: either way the A channel).
struct OutputLayers {
    std::vector<Aov> layers;
    bool alpha = false;
};

OutputLayers output_layers(const RenderArguments& arguments) {
    OutputLayers out;
    out.alpha = arguments.alpha;
    if (arguments.aov_option->count()) {
        std::string ignored;
        for (Aov aov : parse_aov_list(arguments.aov, ignored)) {
            if (aov == Aov::Alpha)
                out.alpha = true;
            else
                out.layers.push_back(aov);
        }
    }
    return out;
}

// --aov, --alpha, --bits and --quality against the output's format.
int check_output_format(const RenderArguments& arguments) {
    const std::string output = arguments.output.empty() ? std::string("image.png") : arguments.output;
    const std::string shown = arguments.output.empty() ? std::string("the default .png output") : "'" + output + "'";
    if (arguments.aov_option->count()) {
        std::string problem;
        parse_aov_list(arguments.aov, problem);
        if (!problem.empty()) {
            print_error("--aov: " + problem);
            return kExitUsage;
        }
    }
    const OutputLayers wanted = output_layers(arguments);
    if (!wanted.layers.empty() && !image_format_has_layers(output)) {
        print_error("--aov writes its layers into one multi-layer EXR beside the beauty: use -o NAME.exr, not " +
                    shown);
        return kExitUsage;
    }
    if (wanted.alpha && !image_format_has_alpha(output)) {
        print_error("an alpha channel (--alpha, +UA) needs a format that holds one (.png, .exr, .tif), not " + shown);
        return kExitUsage;
    }
    if (arguments.bits_option->count()) {
        if (arguments.png_bits != 8 && arguments.png_bits != 16) {
            print_error("--bits must be 8 or 16, got " + std::to_string(arguments.png_bits));
            return kExitUsage;
        }
        if (fs::path(output).extension() != ".png" && fs::path(output).extension() != ".PNG") {
            print_error("--bits chooses a PNG's depth (TIFF is 16-bit, EXR float), not for " + shown);
            return kExitUsage;
        }
    }
    if (arguments.quality_option->count()) {
        if (arguments.jpeg_quality < 1 || arguments.jpeg_quality > 100) {
            print_error("--quality must be 1 to 100, got " + std::to_string(arguments.jpeg_quality));
            return kExitUsage;
        }
        const std::string ext = fs::path(output).extension().string();
        if (ext != ".jpg" && ext != ".jpeg" && ext != ".JPG" && ext != ".JPEG") {
            print_error("--quality is a JPEG's (-o NAME.jpg), not for " + shown);
            return kExitUsage;
        }
    }
    return 0;
}

// Checks that need nothing but the arguments; returns an exit status, or 0.
int check_arguments(const RenderArguments& arguments) {
    if (arguments.port_option->count() && !arguments.preview) {
        print_error("--port is the preview's: add --preview");
        return kExitUsage;
    }
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
    if (arguments.time_option->count() && !(arguments.time_budget > 0.0 && std::isfinite(arguments.time_budget))) {
        print_error("--time must be a positive, finite number of seconds");
        return kExitUsage;
    }
    if (arguments.noise_option->count() && !(arguments.noise > 0.0 && std::isfinite(arguments.noise))) {
        print_error("--noise must be a positive relative error, e.g. 0.05");
        return kExitUsage;
    }
    if (arguments.checkpoint_option->count() &&
        !(arguments.checkpoint_interval > 0.0 && std::isfinite(arguments.checkpoint_interval))) {
        print_error("--checkpoint must be a positive number of seconds");
        return kExitUsage;
    }
    if (arguments.threads < 0) {
        print_error("--threads must be 0 (every core) or positive, got " + std::to_string(arguments.threads));
        return kExitUsage;
    }
    CropWindow crop{};
    if (!arguments.crop.empty() && !parse_crop(arguments.crop, crop)) {
        print_error("--crop expects four integers x0,y0,x1,y1 (pixels, x1 and y1 excluded), got '" + arguments.crop +
                    "'");
        return kExitUsage;
    }
    for (const auto& assignment : arguments.parameters) {
        const auto equals = assignment.find('=');
        if (equals == std::string::npos || equals == 0) {
            print_error("-p expects key=value, got '" + assignment + "'");
            return kExitUsage;
        }
    }
    if (arguments.output_option->count() && arguments.output.empty()) {
        print_error("-o needs a file name (without -o the image is <scene name>.png here)");
        return kExitUsage;
    }
    if (arguments.stats_option->count() && arguments.stats.empty()) {
        print_error("--stats needs a file name");
        return kExitUsage;
    }
    // Not a file named "-" where standard output was meant.
    if (arguments.stats == "-") {
        print_error("--stats writes a file; '-' (standard output) is not offered: name a file such as stats.json");
        return kExitUsage;
    }
    if (!arguments.output.empty() && !is_supported_image_extension(arguments.output)) {
        print_error("cannot write '" + arguments.output +
                    "': unknown image extension (use .png, .jpg, .exr, .hdr, .tif or .tiff)");
        return kExitUsage;
    }
    // A format other than PNG needs the image module: loaded now, so that a
    // --time budget counts its loading before the render, not after it.
    try {
        prepare_image_writer(arguments.output.empty() ? std::string("image.png") : arguments.output);
    } catch (const std::runtime_error& error) {
        print_error(error.what());
        return kExitBadInput;
    }
    return check_output_format(arguments);
}

std::vector<std::pair<std::string, std::string>> parameter_list(const ParameterSet& parameters) {
    std::vector<std::pair<std::string, std::string>> list;
    for (const auto& [name, value] : parameters.values()) list.emplace_back(name, value);
    return list;
}

// What a checkpoint must agree on to be resumed: everything that decides
// which samples each pixel takes and what they are, but not the time
// budget (a resumed render gets a budget of its own).
CheckpointIdentity checkpoint_identity(const RenderArguments& arguments, const RenderOptions& options,
                                       const std::string& integrator_name, const ParameterSet& parameters,
                                       Film::Storage storage) {
    std::string joined;
    for (const auto& [name, value] : parameters.values()) joined += name + "=" + value + ";";
    const CropWindow crop = options.crop.value_or(CropWindow{0, 0, options.width, options.height});
    return {
        {"scene_hash", content_hash_of_file(arguments.scene)},
        {"width", std::to_string(options.width)},
        {"height", std::to_string(options.height)},
        {"seed", std::to_string(options.seed)},
        {"integrator", integrator_name},
        {"parameters", joined},
        {"crop", std::to_string(crop.x0) + "," + std::to_string(crop.y0) + "," + std::to_string(crop.x1) + "," +
                     std::to_string(crop.y1)},
        {"spp", std::to_string(options.samples_per_pixel)},
        {"max_spp", std::to_string(options.max_samples_per_pixel)},
        {"noise", std::to_string(options.noise_target)},
        {"min_samples", std::to_string(options.min_samples)},
        {"film", storage == Film::Storage::Totals ? "double totals"
                 : storage == Film::Storage::Sums ? "float sums (without --stats)"
                                                  : "one sample"},
    };
}

// Seconds since the process started, from the kernel's record of its start
// time: loading lancer's ~260 shared libraries and their static
// initialisers takes a measurable part of a second before main() runs, and a
// --time budget is wall time as the user measures it. 0 if unknown.
double process_age_seconds() {
    std::ifstream stat_file("/proc/self/stat");
    std::string stat((std::istreambuf_iterator<char>(stat_file)), std::istreambuf_iterator<char>());
    const auto name_end = stat.rfind(')');
    std::ifstream uptime_file("/proc/uptime");
    double uptime = 0.0;
    if (name_end == std::string::npos || !(uptime_file >> uptime)) return 0.0;
    // Fields after the command name start at field 3; starttime is field 22.
    std::istringstream fields(stat.substr(name_end + 1));
    std::string field;
    for (int index = 3; index <= 22 && (fields >> field); ++index) {
        if (index == 22) {
            const double ticks = std::strtod(field.c_str(), nullptr);
            const double age = uptime - ticks / double(::sysconf(_SC_CLK_TCK));
            return std::clamp(age, 0.0, 60.0);
        }
    }
    return 0.0;
}

// Size, seed, threads, progress and crop: the command line, then the
// scene's render_settings, then defaults. Returns an exit status on error.
int settle_image_options(const RenderArguments& arguments, const sg::RenderSettings& settings, RenderOptions& options) {
    options.width = arguments.width_option->count() ? arguments.width : settings.width.value_or(kDefaultWidth);
    options.height = arguments.height_option->count() ? arguments.height : settings.height.value_or(kDefaultHeight);
    options.seed = arguments.seed_option->count() ? arguments.seed : settings.seed.value_or(0);
    options.threads = arguments.threads;
    options.progress = arguments.quiet ? ProgressMode::Quiet : ProgressMode::Auto;
    if (options.width <= 0 || options.height <= 0) {
        Diagnostic diagnostic;
        diagnostic.location = settings.location;
        diagnostic.message =
            "image size must be positive, got " + std::to_string(options.width) + "x" + std::to_string(options.height);
        print_diagnostic(diagnostic);
        return kExitBadInput;
    }
    if (!arguments.crop.empty()) {
        CropWindow crop{};
        parse_crop(arguments.crop, crop);
        if (crop.x0 < 0 || crop.y0 < 0 || crop.x1 > options.width || crop.y1 > options.height || crop.x0 >= crop.x1 ||
            crop.y0 >= crop.y1) {
            print_error("--crop " + arguments.crop + " is not a non-empty rectangle inside the " +
                        std::to_string(options.width) + "x" + std::to_string(options.height) +
                        " image (x0 < x1 <= width, y0 < y1 <= height)");
            return kExitUsage;
        }
        options.crop = crop;
    }
    return 0;
}

// Memory before anything is allocated: the film's totals per pixel (at
// most what film_storage_for will choose: 24 bytes with the plan of a
// checkpointed fixed count, 64 with a variance and the planning of --noise
// or --time) and the float RGBA copy that writing some formats needs.
// Refuses what the machine cannot hold; announces a big one
// (docs/robustness.md).
int check_film_fits(const RenderOptions& options, bool keeps_variance) {
    const double film_bytes = keeps_variance ? 64.0 : 24.0;
    const double bytes = double(options.width) * double(options.height) * (film_bytes + 4 * sizeof(float));
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
    return 0;
}

// Samples: a fixed count, or with --time/--noise the per-pixel cap (only if
// --spp says so). A deterministic integrator is exact with one sample per
// pixel and ignores --time and --noise. Returns an exit status on error.
int settle_samples(const RenderArguments& arguments, const sg::RenderSettings& settings, bool deterministic,
                   RenderOptions& options) {
    const bool progressive = arguments.time_option->count() || arguments.noise_option->count();
    options.samples_per_pixel =
        arguments.spp_option->count() ? arguments.spp : settings.samples.value_or(deterministic ? 1 : 16);
    if (options.samples_per_pixel <= 0) {
        Diagnostic diagnostic;
        diagnostic.location = settings.location;
        diagnostic.message = "samples must be at least 1, got " + std::to_string(options.samples_per_pixel);
        print_diagnostic(diagnostic);
        return kExitBadInput;
    }
    if (progressive && arguments.spp_option->count()) options.max_samples_per_pixel = arguments.spp;
    if (arguments.noise_option->count()) options.noise_target = arguments.noise;
    return 0;
}

RenderReport make_report(const RenderArguments& arguments, const std::string& output, const JobIntegrator& chosen,
                         const RenderOptions& options, const RenderStats& stats) {
    const bool progressive = arguments.time_option->count() || arguments.noise_option->count();
    RenderReport report;
    report.scene = arguments.scene;
    report.output = output;
    report.integrator = chosen.name;
    report.parameters = parameter_list(chosen.parameters);
    report.width = options.width;
    report.height = options.height;
    report.seed = options.seed;
    report.samples_per_pixel = progressive ? options.max_samples_per_pixel : options.samples_per_pixel;
    report.time_budget_seconds = arguments.time_option->count() ? arguments.time_budget : 0.0;
    report.noise_target = options.noise_target;
    report.stats = stats;
    return report;
}

// Parses, builds, renders and writes one image (a still or a frame);
// `seconds_so_far` is what the --time budget has spent. With `shared_still`
// every process of the job runs this and renders a share of the still; rank
// 0 writes the files.
int render_frame(const RenderArguments& arguments, const FrameJob& job, const std::function<double()>& seconds_so_far,
                 Distribution* shared_still = nullptr) {
    const bool writes_files = !shared_still || shared_still->coordinates();
    // Parse once; the command line's size is what POV's image_width/height read.
    SceneRequest request;
    request.path = arguments.scene;
    request.safe = arguments.safe;
    request.animation = job.animation;
    request.inputs = arguments.inputs;
    request.max_memory_bytes = arguments.max_memory_bytes;
    if (arguments.width_option->count() && arguments.height_option->count()) {
        request.image_width = arguments.width;
        request.image_height = arguments.height;
    }
    std::vector<Diagnostic> diagnostics;
    std::optional<sg::SceneGraph> graph = parse_job_scene(request, job.preview ? &diagnostics : nullptr);
    if (!graph) {
        if (job.preview) job.preview->publish_status(preview_errors(arguments.scene, diagnostics));
        return kExitBadInput;
    }
    const sg::RenderSettings settings = graph->render;

    RenderOptions options;
    if (const int status = settle_image_options(arguments, settings, options)) return status;
    options.progress_share = job.progress;

    // Whether the film may keep double totals (film_storage_for): before the
    // integrator is known, the sample count may yet come from the scene, and
    // focal blur may ask for more samples.
    const bool focal_blur = graph->camera && graph->camera->aperture != 0.0 && graph->camera->blur_samples > 0;
    const int most_samples = std::max(arguments.spp_option->count() ? arguments.spp : settings.samples.value_or(16),
                                      focal_blur ? graph->camera->blur_samples : 0);
    const bool keeps_variance = arguments.time_option->count() || arguments.noise_option->count() ||
                                !job.stats.empty() || focal_blur || most_samples > kMostFloatSummedSamples;
    if (const int status = check_film_fits(options, keeps_variance)) return status;

    // Output: the scene's stem in the current folder unless named. Every
    // file this render writes is checked now, before any work: none may be
    // the scene or a file it read, none may share a path with another.
    const std::string& output = job.output;
    {
        std::vector<std::string> inputs{arguments.scene};
        inputs.insert(inputs.end(), graph->input_files.begin(), graph->input_files.end());
        std::vector<OutputFile> outputs{{"the image (-o)", output}, {"the checkpoint", checkpoint_path_for(output)}};
        if (!job.stats.empty()) outputs.push_back({"--stats", job.stats});
        const std::string refused = check_output_files(outputs, inputs);
        if (!refused.empty() && writes_files) {
            print_error(refused);
            return kExitBadInput;
        }
        // What an earlier render killed mid-write (no handler runs on
        // SIGKILL) left beside these files.
        if (writes_files)
            for (const OutputFile& file : outputs) remove_stale_temporaries(file.path);
    }

    // The integrator and its parameters (the scene's only for the scene's
    // own integrator: -i choosing another one warns that they are dropped).
    JobIntegrator chosen;
    try {
        chosen = load_job_integrator(settings, arguments.integrator, arguments.parameters);
    } catch (const SceneError& error) {
        print_scene_error(error);
        return kExitBadInput;
    } catch (const std::exception& error) {
        print_error(error.what());
        return kExitBadInput;
    }
    const std::string& integrator_name = chosen.name;
    warn_about_scene_for(*graph, integrator_name);
    const ParameterSet& parameters = chosen.parameters;
    Integrator* const integrator = chosen.integrator.get();

    try {
        if (const int status = settle_samples(arguments, settings, integrator->is_deterministic(), options))
            return status;

        const std::string checkpoint_path = checkpoint_path_for(output);
        const JobScene scene = compile_job_scene(arguments.scene, std::move(*graph));
        graph.reset();
        // The budget is set below, once parsing's share of it is known; the
        // film's storage only asks whether there is one.
        RenderOptions as_planned = options;
        if (arguments.time_option->count()) as_planned.time_budget_seconds = arguments.time_budget;
        // The error estimate of a fixed sample count costs 36 bytes a
        // pixel: kept when --stats will report it.
        Film film(options.width, options.height,
                  film_storage_for(*scene.scene, *integrator, as_planned, !job.stats.empty()));
        // A checkpoint resumes into the storage that wrote it: float sums
        // continued as double ones (or the reverse) would round otherwise
        // than the uninterrupted render, and variances would be missing.
        const CheckpointIdentity identity =
            checkpoint_identity(arguments, options, integrator_name, parameters, film.storage());
        // A render killed before its first checkpoint has nothing to resume:
        // it starts over, so `--resume` after a kill at any moment works.
        // Only the process that writes the files resumes: the others' film
        // is scratch, and rank 0 may be replacing the checkpoint already.
        const bool resume = arguments.resume && writes_files;
        if (resume && !fs::exists(checkpoint_path)) {
            std::fprintf(stderr, "lancer: note: no checkpoint '%s' yet; rendering from the start\n",
                         checkpoint_path.c_str());
        } else if (resume) {
            try {
                read_checkpoint(checkpoint_path, identity, film);
            } catch (const CheckpointError& error) {
                print_error(error.what());
                return kExitBadInput;
            }
        }
        const bool checkpointing = arguments.checkpoint_option->count() > 0;
        if (checkpointing) {
            options.checkpoint_interval_seconds = arguments.checkpoint_interval;
            options.on_checkpoint = [&](const Film& state) { write_checkpoint(checkpoint_path, identity, state); };
        }
        // The budget covers the whole command: what parsing and building
        // took, and what writing the image will take, come out of it.
        if (arguments.time_option->count()) {
            const double reserve =
                kOutputReserveSeconds + kOutputReserveSecondsPerPixel * double(options.width) * options.height;
            options.time_budget_seconds = std::max(arguments.time_budget - seconds_so_far() - reserve, 1e-3);
        }

        if (job.preview) {
            ImageWriteOptions look;
            look.working_gamma = scene.working_gamma;
            look.gamma_correction = scene.gamma_correction;
            feed_preview(*job.preview, arguments.scene,
                         integrator_name + ", " + std::to_string(options.width) + "x" + std::to_string(options.height),
                         look, options);
        }

        std::optional<InterruptHandlers> handlers;
        if (!job.distributed || (shared_still && shared_still->coordinates())) handlers.emplace();
        options.cancel = &g_interrupt_requested;
        RenderStats stats;
        if (shared_still) {
            // Rank 0 checkpoints the combined film as tiles come back.
            auto last_checkpoint = std::chrono::steady_clock::now();
            const auto on_tile = [&](const Film& state) {
                const auto now = std::chrono::steady_clock::now();
                if (!checkpointing ||
                    std::chrono::duration<double>(now - last_checkpoint).count() < arguments.checkpoint_interval)
                    return;
                write_checkpoint(checkpoint_path, identity, state);
                last_checkpoint = now;
            };
            options.on_checkpoint = nullptr;
            stats = shared_still->render_still(*scene.scene, *integrator, options, film, on_tile);
            if (!shared_still->coordinates()) return 0;
        } else {
            stats = render_job(*scene.scene, *integrator, options, film);
        }
        const int signal_number = g_interrupt_signal.load();
        if (stats.interrupted && job.distributed) {
            // Said first: mpirun kills what is still running soon after.
            const char* name = signal_number == SIGINT ? "SIGINT" : "SIGTERM";
            std::fprintf(
                stderr,
                "lancer: error: the job was stopped by %s (mpirun stops every process when one fails or is "
                "interrupted); %s not written%s%s%s\n",
                name, output.c_str(), checkpointing || arguments.resume ? "; progress saved in " : "",
                checkpointing || arguments.resume ? checkpoint_path.c_str() : "",
                checkpointing || arguments.resume ? ": continue with --resume, with any number of processes" : "");
            std::fflush(stderr);
            if (checkpointing || arguments.resume) write_checkpoint(checkpoint_path, identity, film);
            return 128 + (signal_number > 0 ? signal_number : SIGTERM);
        }

        // Report and write: image (with per-pixel sample counts in EXR when
        // they vary), stats, and on interruption a checkpoint to resume.
        RenderReport report = make_report(arguments, output, chosen, options, stats);
        ImageWriteOptions write_options;
        write_options.sample_count_channel =
            stats.interrupted || stats.min_samples_per_pixel != stats.max_samples_per_pixel;
        write_options.working_gamma = scene.working_gamma;
        write_options.gamma_correction = scene.gamma_correction;
        write_options.png_bits = arguments.png_bits;
        write_options.jpeg_quality = arguments.jpeg_quality;
        const OutputLayers wanted = output_layers(arguments);
        if (!wanted.layers.empty() || wanted.alpha) {
            std::vector<Aov> passes = wanted.layers;
            if (wanted.alpha) passes.push_back(Aov::Alpha);
            std::vector<ImageLayer> rendered =
                render_aovs(*scene.scene, *integrator, passes, options, aov_samples_for(stats.mean_samples_per_pixel));
            if (wanted.alpha) {
                write_options.alpha = std::move(rendered.back().values);
                rendered.pop_back();
            }
            write_options.layers = std::move(rendered);
        }
        report.total_seconds = seconds_so_far();
        write_options.metadata = stats_metadata(report);
        write_image(film, output, write_options);
        warn_after_render(*scene.scene);
        if (stats.interrupted && (checkpointing || arguments.resume)) write_checkpoint(checkpoint_path, identity, film);
        report.total_seconds = seconds_so_far();
        if (!job.stats.empty()) write_stats_json(report, job.stats);

        if (stats.nonfinite_samples > 0) {
            std::fprintf(stderr, "lancer: warning: %llu non-finite samples (NaN or infinite radiance) were dropped\n",
                         static_cast<unsigned long long>(stats.nonfinite_samples));
        }
        if (stats.interrupted) {
            const char* name = signal_number == SIGTERM ? "SIGTERM" : "SIGINT";
            if (job.preview) {
                PreviewStatus stopped;
                stopped.state = "interrupted";
                stopped.scene = arguments.scene;
                stopped.message = summary_line(report);
                job.preview->publish_status(stopped);
            }
            std::fprintf(stderr,
                         "lancer: interrupted by %s after %.1f s: wrote the image so far (%.1f spp, %u-%u) to %s%s\n",
                         name, report.total_seconds, stats.mean_samples_per_pixel, stats.min_samples_per_pixel,
                         stats.max_samples_per_pixel, output.c_str(),
                         checkpointing || arguments.resume ? "; continue with --resume" : "");
            return 128 + (signal_number > 0 ? signal_number : SIGINT);
        }
        std::error_code ignored;
        fs::remove(checkpoint_path, ignored);
        if (!arguments.quiet) std::printf("%s\n", summary_line(report).c_str());
        if (job.preview) {
            PreviewStatus done;
            done.state = "done";
            done.scene = arguments.scene;
            done.progress = 1.0;
            done.message = summary_line(report);
            job.preview->publish_status(done);
        }
    } catch (const SceneError& error) {
        print_scene_error(error);
        if (job.preview) job.preview->publish_status(preview_failure(arguments.scene, error));
        return kExitBadInput;
    } catch (const std::exception& error) {
        print_error(error.what());
        if (job.preview) job.preview->publish_status(preview_failure(arguments.scene, error));
        return kExitBadInput;
    }
    return 0;
}

// An animation over the processes of an mpirun job: rank 0 hands out the
// frames still to make, each process renders its frames whole and writes
// them, and only rank 0 reports (a line per frame).
int render_frames_distributed(const RenderArguments& arguments, const AnimationRange& range, const std::string& output,
                              const std::string& stats, Distribution& distribution) {
    std::vector<int> frames;
    const auto job_for = [&](int frame) {
        return FrameJob{range.frame(frame),
                        frame_file_name(output, frame, range.final_frame),
                        stats.empty() ? std::string() : frame_file_name(stats, frame, range.final_frame),
                        true,
                        true,
                        ProgressShare{}};
    };
    for (int frame = range.initial_frame; frame <= range.final_frame; ++frame) {
        const FrameJob job = job_for(frame);
        if (arguments.resume && fs::exists(job.output) && !fs::exists(checkpoint_path_for(job.output))) continue;
        frames.push_back(frame);
    }
    RenderArguments quiet = arguments;
    quiet.quiet = true;
    std::optional<InterruptHandlers> handlers;
    if (distribution.coordinates()) handlers.emplace();
    return distribution.render_frames(
        frames,
        [&](int frame) {
            const auto started = std::chrono::steady_clock::now();
            const auto seconds_so_far = [&] {
                return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            };
            return render_frame(quiet, job_for(frame), seconds_so_far);
        },
        &g_interrupt_requested);
}

// The still or the frames, in one process or in every process of an
// mpirun job (`distribution` not null: a still shared among them, frames
// handed out), each shown in `preview` when there is one.
int render_all(const RenderArguments& arguments, Distribution* distribution, PreviewServer* preview) {
    const std::string output =
        arguments.output_option->count() ? arguments.output : fs::path(arguments.scene).stem().string() + ".png";
    const std::string stats = arguments.stats_option->count() ? arguments.stats : std::string();
    if (!arguments.frames_option->count()) {
        if (arguments.clock_option->count()) {
            print_error("--clock needs --frames (a still has no clock)");
            return kExitUsage;
        }
        const auto started = std::chrono::steady_clock::now();
        const double age_at_start = process_age_seconds();
        const auto seconds_so_far = [&] {
            return age_at_start + std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        };
        return render_frame(
            arguments,
            FrameJob{AnimationFrame{}, output, stats, false, distribution != nullptr, ProgressShare{}, preview},
            seconds_so_far, distribution);
    }
    std::string problem;
    std::optional<AnimationRange> range = parse_frame_range(arguments.frames, problem);
    if (range && arguments.clock_option->count() && !parse_clock_range(arguments.clock, *range, problem)) range.reset();
    if (!range) {
        print_error(problem);
        return kExitUsage;
    }
    if (distribution) return render_frames_distributed(arguments, *range, output, stats, *distribution);
    const int frame_count = range->final_frame - range->initial_frame + 1;
    const auto animation_started = std::chrono::steady_clock::now();
    for (int frame = range->initial_frame; frame <= range->final_frame; ++frame) {
        FrameJob job{range->frame(frame),
                     frame_file_name(output, frame, range->final_frame),
                     stats.empty() ? std::string() : frame_file_name(stats, frame, range->final_frame),
                     true,
                     false,
                     ProgressShare{},
                     preview};
        // --resume goes on from the frame that was stopped: frames written
        // whole (an image and no checkpoint beside it) are not made again.
        if (arguments.resume && fs::exists(job.output) && !fs::exists(checkpoint_path_for(job.output))) continue;
        job.progress =
            ProgressShare{frame - range->initial_frame, frame_count,
                          std::chrono::duration<double>(std::chrono::steady_clock::now() - animation_started).count(),
                          "frame " + std::to_string(frame)};
        if (!arguments.quiet) {
            std::printf("lancer: frame %d of %d..%d (clock %g) -> %s\n", frame, range->initial_frame,
                        range->final_frame, job.animation.clock, job.output.c_str());
            std::fflush(stdout);
        }
        // Each frame has the whole --time budget, counted from its start.
        const auto started = std::chrono::steady_clock::now();
        const auto seconds_so_far = [&] {
            return std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
        };
        if (const int status = render_frame(arguments, job, seconds_so_far)) return status;
    }
    return 0;
}

// Serves the page until the user presses Ctrl-C, after a render that ended
// on its own: the last image stays to look at.
void keep_preview_open(const PreviewServer& preview) {
    std::fprintf(stderr, "lancer: preview: the render is done; the page stays at %s until Ctrl-C\n",
                 preview.url().c_str());
    std::fflush(stderr);
    InterruptHandlers handlers;
    while (!g_interrupt_requested.load()) std::this_thread::sleep_for(std::chrono::milliseconds(100));
}

// `lancer render`: checks the arguments, opens the preview if asked, renders.
int render_command(const RenderArguments& arguments, Distribution* distribution) {
    if (const int status = check_arguments(arguments)) return status;
    std::unique_ptr<PreviewServer> preview_server;
    if (arguments.preview) {
        if (distribution) {
            print_error("--preview is not offered under mpirun (each process would serve its own page)");
            return kExitUsage;
        }
        preview_server = std::make_unique<PreviewServer>();
        std::string problem;
        if (!preview_server->start(arguments.port, problem)) {
            print_error(problem);
            return kExitUsage;
        }
        std::fprintf(stderr, "lancer: preview: %s\n", preview_server->url().c_str());
        std::fflush(stderr);
    }
    PreviewServer* const preview = preview_server.get();
    const int status = render_all(arguments, distribution, preview);
    if (preview && status == 0) keep_preview_open(*preview);
    return status;
}

int run_render(const RenderArguments& arguments) {
    std::string problem;
    const std::unique_ptr<Distribution> distribution = join_distributed_job(problem);
    if (!problem.empty()) {
        print_error(problem);
        return kExitUsage;
    }
    const int status = render_command(arguments, distribution.get());
    // A process that fails ends the whole job: the others may be waiting
    // for it.
    if (distribution && status != 0) distribution->abort(status);
    return status;
}

}  // namespace

Command add_render_command(CLI::App& app) {
    auto arguments = std::make_shared<RenderArguments>();
    CLI::App* render = app.add_subcommand("render", "Render a scene to an image with an integrator plugin");
    render->add_option("scene", arguments->scene, "Scene file (.pov)")->required();
    render->add_option("-i,--integrator", arguments->integrator,
                       "Integrator plugin (default: the scene's, else whitted; see `lancer plugins`)");
    arguments->output_option = render->add_option(
        "-o,--output", arguments->output, "Image file: .png, .exr, .hdr, .tif (default: <scene name>.png here)");
    arguments->width_option = render->add_option("--width", arguments->width, "Image width in pixels");
    arguments->height_option = render->add_option("--height", arguments->height, "Image height in pixels");
    arguments->spp_option = render->add_option(
        "--spp", arguments->spp, "Samples per pixel (default: the scene's, else 1 for deterministic integrators, 16)");
    arguments->time_option = render->add_option(
        "--time", arguments->time_budget,
        "Render in passes until SECONDS have passed, counting parsing and writing (--spp then caps samples)");
    arguments->noise_option = render->add_option(
        "--noise", arguments->noise,
        "Adaptive: a pixel stops when its estimated relative error is under E, e.g. 0.05 (--spp caps, default 4096)");
    arguments->stats_option = render->add_option("--stats", arguments->stats, "Write what the render did to FILE.json");
    arguments->checkpoint_option = render->add_option(
        "--checkpoint", arguments->checkpoint_interval,
        "Save progress every SECONDS to <output>.lancer-checkpoint (removed when the render completes)");
    render->add_flag(
        "--resume", arguments->resume,
        "Continue from <output>.lancer-checkpoint (same scene and settings required); without one, start over");
    arguments->seed_option = add_seed_option(*render, arguments->seed);
    add_max_memory_option(*render, arguments->max_memory_bytes);
    render->add_option("--threads", arguments->threads, "Worker threads (default 0: every core)");
    render->add_option("--crop", arguments->crop, "Render only pixels x0 <= x < x1, y0 <= y < y1");
    CLI::Option* parameter_option =
        render
            ->add_option("-p,--parameter", arguments->parameters,
                         "Integrator parameter key=value (repeatable); overrides the scene's")
            ->allow_extra_args(false);
    render->add_flag("-q,--quiet", arguments->quiet, "No progress and no summary line");
    add_scene_input_options(*render, arguments->inputs);
    arguments->frames_option = render->add_option(
        "--frames", arguments->frames,
        "Animation: render frames A..B (POV's +KFI/+KFF), one image each, numbered as POV names them");
    arguments->clock_option = render->add_option(
        "--clock", arguments->clock, "Animation: clock from C0 at the first frame to C1 at the last (default 0..1)");
    arguments->aov_option = render->add_option(
        "--aov", arguments->aov,
        "Also write these layers into the EXR: albedo, normal, depth, position, alpha (comma-separated)");
    render->add_flag("--alpha", arguments->alpha,
                     "An alpha channel (POV's +UA): the background's transmit shows through (PNG, EXR, TIFF)");
    arguments->bits_option = render->add_option("--bits", arguments->png_bits, "Bits per channel of a PNG: 8 or 16");
    arguments->quality_option =
        render->add_option("--quality", arguments->jpeg_quality, "JPEG quality, 1 to 100 (default 90)");
    render->add_flag("--preview", arguments->preview,
                     "Show the render refining in a browser: serves a page on 127.0.0.1 (its address is printed), "
                     "kept after the render until Ctrl-C");
    arguments->port_option =
        render->add_option("--port", arguments->port, "The preview's port (default 0: any free port)");
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
