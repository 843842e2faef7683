// `lancer live scene.pov`: renders the scene into the live preview page
// (preview_server.h) and renders it again whenever the scene or any file it
// read is saved: a quarter-size single-sample image first, then the full
// render refining pass by pass. A scene that does not parse shows its
// located errors in the page until a save fixes them. Runs until Ctrl-C.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "cli_output.h"
#include "commands.h"
#include "interrupts.h"
#include "lancer/host/image_io.h"
#include "lancer/scene_error.h"
#include "preview_feed.h"
#include "preview_server.h"
#include "render_job.h"
#include "render_report.h"

namespace lancer::app {
namespace {

namespace fs = std::filesystem;

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;
// How often the watched files are looked at: a save shows within this.
constexpr auto kWatchInterval = std::chrono::milliseconds(150);
constexpr int kDefaultWidth = 480, kDefaultHeight = 360;
// Samples per pixel of a stochastic integrator when neither the command
// line nor the scene says: enough to look at, soon.
constexpr int kDefaultLiveSamples = 64;

struct LiveArguments {
    std::string scene;
    std::string integrator;
    std::vector<std::string> parameters;
    int width = 0, height = 0, spp = 0, port = 0, threads = 0;
    CLI::Option *width_option = nullptr, *height_option = nullptr, *spp_option = nullptr;
    bool safe = false;
    SceneInputOptions inputs;
    long long max_memory_bytes = ParseOptions{}.max_memory_bytes;
};

// What a file looked like: its time and size, or that it is missing. An
// editor that saves by writing a new file and renaming it changes both.
struct FileStamp {
    bool exists = false;
    fs::file_time_type time{};
    std::uintmax_t size = 0;
    bool operator==(const FileStamp&) const = default;
};

using Stamps = std::map<std::string, FileStamp>;

Stamps stamp(const std::vector<std::string>& files) {
    Stamps stamps;
    for (const std::string& file : files) {
        std::error_code error;
        FileStamp s;
        s.time = fs::last_write_time(file, error);
        if (!error) s.size = fs::file_size(file, error);
        s.exists = !error;
        stamps[file] = s;
    }
    return stamps;
}

// Looks at the files from a thread of its own while a render runs, and
// raises `changed` (the render's cancel flag) on a save or on Ctrl-C.
class Watcher {
  public:
    Watcher(const std::vector<std::string>& files, const Stamps& stamps, std::atomic<bool>& changed)
        : m_thread([this, files, stamps, &changed] {
              while (!m_done.load()) {
                  if (g_interrupt_requested.load() || stamp(files) != stamps) {
                      changed.store(true);
                      return;
                  }
                  std::this_thread::sleep_for(kWatchInterval);
              }
          }) {}
    ~Watcher() {
        m_done.store(true);
        m_thread.join();
    }

  private:
    std::atomic<bool> m_done{false};
    std::thread m_thread;
};

std::string size_text(const RenderOptions& options) {
    return std::to_string(options.width) + "x" + std::to_string(options.height);
}

// One round: parse, build, render coarse then full. Updates `watched` to
// the scene and every file it read (on a parse error, the files named in
// the errors are added to those known). Returns early, with the preview
// showing what it got to, when `changed` rises.
void render_round(const LiveArguments& arguments, PreviewServer& preview, std::vector<std::string>& watched,
                  std::atomic<bool>& changed) {
    PreviewStatus parsing;
    parsing.scene = arguments.scene;
    preview.publish_status(parsing);

    SceneRequest request;
    request.path = arguments.scene;
    request.safe = arguments.safe;
    request.inputs = arguments.inputs;
    request.max_memory_bytes = arguments.max_memory_bytes;
    if (arguments.width_option->count() && arguments.height_option->count()) {
        request.image_width = arguments.width;
        request.image_height = arguments.height;
    }
    std::vector<Diagnostic> diagnostics;
    std::optional<sg::SceneGraph> graph = parse_job_scene(request, &diagnostics);
    if (!graph) {
        for (const Diagnostic& diagnostic : diagnostics)
            if (diagnostic.location.file &&
                std::find(watched.begin(), watched.end(), *diagnostic.location.file) == watched.end())
                watched.push_back(*diagnostic.location.file);
        preview.publish_status(preview_errors(arguments.scene, diagnostics));
        return;
    }
    watched = {arguments.scene};
    watched.insert(watched.end(), graph->input_files.begin(), graph->input_files.end());
    const sg::RenderSettings settings = graph->render;

    try {
        JobIntegrator chosen = load_job_integrator(settings, arguments.integrator, arguments.parameters);
        const JobScene scene = compile_job_scene(arguments.scene, std::move(*graph));
        RenderOptions options;
        options.width = arguments.width_option->count() ? arguments.width : settings.width.value_or(kDefaultWidth);
        options.height = arguments.height_option->count() ? arguments.height : settings.height.value_or(kDefaultHeight);
        options.seed = settings.seed.value_or(0);
        options.threads = arguments.threads;
        options.progress = ProgressMode::Quiet;
        options.cancel = &changed;
        const bool deterministic = chosen.integrator->is_deterministic();
        options.samples_per_pixel = arguments.spp_option->count()
                                        ? arguments.spp
                                        : settings.samples.value_or(deterministic ? 1 : kDefaultLiveSamples);
        if (options.width <= 0 || options.height <= 0 || options.samples_per_pixel <= 0)
            throw std::runtime_error("the image size and samples per pixel must be positive, got " +
                                     size_text(options) + " at " + std::to_string(options.samples_per_pixel) + " spp");
        ImageWriteOptions look;
        look.working_gamma = scene.working_gamma;
        look.gamma_correction = scene.gamma_correction;

        // Coarse: a quarter of the size, one sample, shown at once.
        RenderOptions coarse = options;
        coarse.width = std::max(1, options.width / 4);
        coarse.height = std::max(1, options.height / 4);
        coarse.samples_per_pixel = 1;
        feed_preview(preview, arguments.scene, chosen.name + ", " + size_text(coarse) + " (coarse)", look, coarse);
        Film coarse_film(coarse.width, coarse.height);
        render_job(*scene.scene, *chosen.integrator, coarse, coarse_film);
        if (changed.load()) return;

        feed_preview(preview, arguments.scene, chosen.name + ", " + size_text(options), look, options);
        Film film(options.width, options.height);
        const RenderStats stats = render_job(*scene.scene, *chosen.integrator, options, film);
        if (changed.load()) return;
        PreviewStatus done;
        done.state = "done";
        done.scene = arguments.scene;
        done.progress = 1.0;
        char line[160];
        std::snprintf(line, sizeof line, "%s, %s, %.1f spp, %.2f s, %.2f Mrays/s", chosen.name.c_str(),
                      size_text(options).c_str(), stats.mean_samples_per_pixel, stats.seconds,
                      stats.rays_per_second / 1e6);
        done.message = line;
        preview.publish_status(done);
    } catch (const SceneError& error) {
        print_scene_error(error);
        preview.publish_status(preview_failure(arguments.scene, error));
    } catch (const std::exception& error) {
        print_error(error.what());
        preview.publish_status(preview_failure(arguments.scene, error));
    }
}

int run_live(const LiveArguments& arguments) {
    if (arguments.width_option->count() != arguments.height_option->count()) {
        print_error("--width and --height go together");
        return kExitUsage;
    }
    if (!fs::is_regular_file(arguments.scene)) {
        print_error("cannot read '" + arguments.scene + "': no such file");
        return kExitBadInput;
    }
    PreviewServer preview;
    std::string problem;
    if (!preview.start(arguments.port, problem)) {
        print_error(problem);
        return kExitUsage;
    }
    std::fprintf(stderr, "lancer: live: %s (watching %s and what it reads; Ctrl-C stops)\n", preview.url().c_str(),
                 arguments.scene.c_str());
    std::fflush(stderr);

    InterruptHandlers handlers;
    std::vector<std::string> watched{arguments.scene};
    while (!g_interrupt_requested.load()) {
        // Stamped before parsing: a save during the round starts another.
        Stamps before = stamp(watched);
        std::atomic<bool> changed{false};
        {
            Watcher watcher(watched, before, changed);
            render_round(arguments, preview, watched, changed);
        }
        // The round may have learnt of more files; a change to one of them
        // since the round began is a change too.
        for (const auto& [file, now] : stamp(watched))
            if (!before.count(file)) before[file] = now;
        while (!changed.load() && !g_interrupt_requested.load() && stamp(watched) == before)
            std::this_thread::sleep_for(kWatchInterval);
        if (!g_interrupt_requested.load()) std::fprintf(stderr, "lancer: live: a file changed; rendering again\n");
    }
    std::fprintf(stderr, "lancer: live: stopped\n");
    return 0;
}

}  // namespace

Command add_live_command(CLI::App& app) {
    auto arguments = std::make_shared<LiveArguments>();
    CLI::App* live = app.add_subcommand(
        "live", "Render a scene into a page in the browser, again on every save of it or of a file it reads");
    live->add_option("scene", arguments->scene, "Scene file (.pov)")->required();
    live->add_option("-i,--integrator", arguments->integrator,
                     "Integrator plugin (default: the scene's, else whitted)");
    live->add_option("-p,--parameter", arguments->parameters, "Integrator parameter key=value (repeatable)")
        ->allow_extra_args(false);
    arguments->width_option = live->add_option("--width", arguments->width, "Image width in pixels (default 480)");
    arguments->height_option = live->add_option("--height", arguments->height, "Image height in pixels (default 360)");
    arguments->spp_option = live->add_option(
        "--spp", arguments->spp, "Samples per pixel (default: the scene's, else 1 deterministic, 64 otherwise)");
    live->add_option("--port", arguments->port, "The page's port on 127.0.0.1 (default 0: any free port)");
    live->add_option("--threads", arguments->threads, "Worker threads (default 0: every core)");
    add_max_memory_option(*live, arguments->max_memory_bytes);
    add_scene_input_options(*live, arguments->inputs);
    live->add_flag("--safe", arguments->safe,
                   "Untrusted scene: read includes, OBJ/MTL and image files only from the scene's folder and the "
                   "include path");
    Command command;
    command.cli = live;
    command.run = [arguments] { return run_live(*arguments); };
    return command;
}

}  // namespace lancer::app
