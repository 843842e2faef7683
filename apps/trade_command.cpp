// `lancer trade SCENE --out DIR [--budget SECONDS] [--quick] [--width W
//  --height H] [--seed S] [--threads T] [--cache FOLDER]`
//
// What each integrator's settings buy on the user's own scene: a reference
// rendered by `path` (cached by scene content and settings), then every
// integrator at a ladder of settings, each timed and compared with the
// reference (RMSE, relative MSE, SSIM). Writes results.csv, error-versus-
// time plots and index.html into DIR.
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <set>
#include <string>
#include <vector>

#include "cli_output.h"
#include "commands.h"
#include "image_metrics.h"
#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/rgb_image.h"
#include "lancer/parser.h"
#include "lancer/scene_error.h"
#include "output_files.h"
#include "reference_cache.h"
#include "render_job.h"
#include "trade_ladder.h"
#include "trade_report.h"
#include "trade_verdict.h"

namespace lancer::app {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

constexpr const char* kLancerVersion = "0.1.0";  // as `lancer --version`; part of the cache key
constexpr double kQuickBudgetSeconds = 50.0;
constexpr double kDefaultBudgetSeconds = 120.0;
constexpr double kQuickPixels = 160 * 120;  // --quick: about this many pixels, the scene's aspect
constexpr int kMaxDefaultWidth = 320;
// Shares of the budget: the reference, then the ladders (split per
// integrator by ladder_budget_share).
constexpr double kReferenceShare = 0.5;
constexpr double kLadderShare = 0.5;
// The reference uses path's Owen-scrambled Sobol sampler: unbiased like the
// default, and its error falls faster (docs/integrators.md: slope −0.78
// against −0.48), so the same seconds buy a cleaner reference.
const std::vector<std::string> kReferenceParameters = {"sampler=sobol"};
// The reference gets at least this many samples per pixel whatever the budget...
constexpr int kMinReferenceSpp = 64;
constexpr int kMaxReferenceSpp = 16384;
// ...and path's ladder stops this many times below it: measured against a
// reference with 4× the samples, a render's RMSE reads at most ~12 % high.
constexpr int kReferenceSppOverLadder = 4;
// The reference's samples come from a stream no ladder render uses, so
// their noise is independent.
constexpr std::uint64_t kReferenceSeedOffset = 0x9e3779b97f4a7c15ull;

constexpr int kExitBadInput = 1;
constexpr int kExitUsage = 2;

struct TradeArguments {
    std::string scene;
    std::string out;
    double budget = 0.0;
    bool quick = false;
    int width = 0;
    int height = 0;
    std::uint64_t seed = 0;
    int threads = 0;
    std::string cache;
    SceneInputOptions inputs;
    long long max_memory_bytes = ParseOptions{}.max_memory_bytes;  // --max-memory
    CLI::Option* budget_option = nullptr;
    CLI::Option* width_option = nullptr;
    CLI::Option* height_option = nullptr;
    CLI::Option* seed_option = nullptr;
};

// CPU time of the whole process, every thread.
double process_cpu_seconds() {
    timespec now{};
    ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &now);
    return double(now.tv_sec) + 1e-9 * double(now.tv_nsec);
}

// One line per step when stdout is not a terminal (logs, CI), else a bar
// redrawn in place that counts steps and shows the time spent.
class TradeProgress {
  public:
    explicit TradeProgress(int total_steps) : m_total(total_steps), m_terminal(::isatty(::fileno(stdout))) {}

    // A step that was planned but will not run (over budget) still counts.
    void skip(int steps) { m_done += steps; }

    void starting(const std::string& what) {
        if (!m_terminal) return;
        draw(what);
    }
    void finished(const std::string& what, const std::string& outcome) {
        ++m_done;
        if (m_terminal) {
            draw(what + ": " + outcome);
        } else {
            std::printf("trade: [%d/%d] %s: %s\n", m_done, m_total, what.c_str(), outcome.c_str());
            std::fflush(stdout);
        }
    }
    void note(const std::string& line) {
        if (m_terminal) std::printf("\r\033[K");
        std::printf("%s\n", line.c_str());
        std::fflush(stdout);
    }
    void close() {
        if (m_terminal) std::printf("\r\033[K");
        std::fflush(stdout);
    }

  private:
    void draw(const std::string& what) {
        constexpr int kWidth = 30;
        const int filled = m_total > 0 ? std::min(kWidth, kWidth * m_done / m_total) : kWidth;
        const double elapsed = std::chrono::duration<double>(Clock::now() - m_start).count();
        std::printf("\r\033[K[%s%s] %d/%d %5.1f s  %s", std::string(filled, '#').c_str(),
                    std::string(kWidth - filled, '.').c_str(), m_done, m_total, elapsed, what.c_str());
        std::fflush(stdout);
    }
    int m_total;
    int m_done = 0;
    bool m_terminal;
    Clock::time_point m_start = Clock::now();
};

std::string join(const std::vector<std::string>& parts, const char* separator) {
    std::string joined;
    for (const std::string& part : parts) joined += (joined.empty() ? "" : separator) + part;
    return joined;
}

std::string join_parameters(const ParameterSet& parameters) {
    std::vector<std::string> parts;
    for (const auto& [name, value] : parameters.values()) parts.push_back(name + "=" + value);
    return join(parts, " ");
}

std::string seconds_text(double seconds) {
    char text[32];
    std::snprintf(text, sizeof text, seconds < 10 ? "%.2f s" : "%.1f s", seconds);
    return text;
}

// The largest power of two not above `value` (at least 1).
int power_of_two_floor(double value) {
    int result = 1;
    while (result * 2.0 <= value && result < (1 << 30)) result *= 2;
    return result;
}

// The scene, parsed and compiled once for every render of the trade.
struct PreparedScene {
    JobScene job;
    int width = 0;
    int height = 0;
};

// Size: --width/--height, else the scene's aspect at about 160x120 pixels
// for --quick or at most 320 wide otherwise (trade renders dozens of
// images). The scene is parsed once: with --width/--height its
// image_width/image_height read them, as `lancer render`'s do; otherwise
// they read the scene's own size, whose aspect trade keeps.
bool prepare_scene(const TradeArguments& arguments, PreparedScene& prepared) {
    SceneRequest request;
    request.path = arguments.scene;
    request.inputs = arguments.inputs;
    request.max_memory_bytes = arguments.max_memory_bytes;
    if (arguments.width_option->count()) {
        request.image_width = arguments.width;
        request.image_height = arguments.height;
    }
    std::optional<sg::SceneGraph> graph = parse_job_scene(request);
    if (!graph) return false;
    const int scene_width = graph->render.width.value_or(640);
    const int scene_height = graph->render.height.value_or(480);
    if (arguments.width_option->count()) {
        prepared.width = arguments.width;
        prepared.height = arguments.height;
    } else {
        const double aspect = double(scene_width) / double(scene_height);
        prepared.width = arguments.quick ? int(std::lround(std::sqrt(kQuickPixels * aspect)))
                                         : std::min(scene_width, kMaxDefaultWidth);
        prepared.height = std::max(1, int(std::lround(prepared.width / aspect)));
    }
    std::vector<std::string> inputs{arguments.scene};
    inputs.insert(inputs.end(), graph->input_files.begin(), graph->input_files.end());
    if (const std::string refused = check_report_folder(arguments.out, inputs); !refused.empty()) {
        print_error(refused);
        return false;
    }
    warn_about_scene_for(*graph, "path");  // the reference every trade is measured against
    prepared.job = compile_job_scene(arguments.scene, std::move(*graph));
    return true;
}

// The plugin's parameters: the scene's (when the scene names this
// integrator, the rule `lancer render` follows) under `parameters`.
ParameterSet resolve_for(const PreparedScene& prepared, const Plugin& plugin,
                         const std::vector<std::string>& parameters) {
    const auto scene_parameters = scene_parameters_for(prepared.job.settings, plugin.descriptor->name, nullptr);
    return resolve_parameters(*plugin.descriptor, scene_parameters, parameters);
}

// One render with resolve_for's parameters, timed from prepare() on.
struct TimedRender {
    RgbImage image;
    double seconds = 0.0;
    double cpu_seconds = 0.0;
    std::uint64_t rays = 0;
    double mean_spp = 0.0;
    double estimated_rel_rmse = 0.0;
    ReferenceNoise noise;    // the film's own noise, were it a reference
    std::string parameters;  // as resolved
};

// `noise_target` > 0 renders adaptively, at most `spp` samples per pixel.
TimedRender render_setting(const PreparedScene& prepared, const Plugin& plugin,
                           const std::vector<std::string>& parameters, int spp, std::uint64_t seed, int threads,
                           double noise_target = 0.0) {
    const ParameterSet resolved = resolve_for(prepared, plugin, parameters);

    const Clock::time_point start = Clock::now();
    const double cpu_start = process_cpu_seconds();
    std::unique_ptr<Integrator> integrator = plugin.descriptor->create(resolved);
    if (!integrator) throw PluginError("plugin '" + plugin.path + "' created no integrator");
    // Rendered as `lancer render` renders (render_job): rays are counted
    // and the cost includes the counting.
    RenderOptions options;
    options.width = prepared.width;
    options.height = prepared.height;
    options.samples_per_pixel = spp;
    if (noise_target > 0.0) {
        options.noise_target = noise_target;
        options.max_samples_per_pixel = spp;
    }
    options.seed = seed;
    options.threads = threads;
    options.progress = ProgressMode::Quiet;
    Film film(prepared.width, prepared.height);
    const RenderStats stats = render_job(*prepared.job.scene, *integrator, options, film);

    TimedRender render;
    render.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    render.cpu_seconds = process_cpu_seconds() - cpu_start;
    render.image = image_from_film(film);
    render.parameters = join_parameters(resolved);
    render.rays = stats.rays;
    render.mean_spp = stats.mean_samples_per_pixel;
    render.estimated_rel_rmse = stats.estimated_rel_rmse;
    double variance = 0.0, relative_variance = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Color v = film.variance_of_mean(x, y);
            const Color m = film.mean(x, y);
            for (int k = 0; k < 3; ++k) {
                variance += v[k] / 3.0;
                relative_variance += v[k] / (double(m[k]) * m[k] + kRelativeErrorEpsilon) / 3.0;
            }
        }
    const double pixels = double(film.width()) * film.height();
    render.noise.rmse = std::sqrt(variance / pixels);
    render.noise.rel_mse = relative_variance / pixels;
    return render;
}

std::string metrics_text(const TradeResult& result) {
    char text[128];
    std::snprintf(text, sizeof text, "%s, %.1f spp, RMSE %.4g, relMSE %.4g, SSIM %.4f",
                  seconds_text(result.seconds).c_str(), result.mean_spp, result.rmse, result.rel_mse, result.ssim);
    return text;
}

std::string command_line(const TradeArguments& arguments, const PreparedScene& prepared, double budget,
                         std::uint64_t seed) {
    char text[64];
    std::snprintf(text, sizeof text, "%g", budget);
    std::string command = "lancer trade " + arguments.scene + " --out " + arguments.out + " --budget " + text;
    if (arguments.quick) command += " --quick";
    command += " --width " + std::to_string(prepared.width) + " --height " + std::to_string(prepared.height);
    return command + " --seed " + std::to_string(seed);
}

int run_trade(const TradeArguments& arguments) {
    // Arguments.
    if (arguments.budget_option->count() && !(arguments.budget > 0.0)) {
        print_error("--budget must be a positive number of seconds");
        return kExitUsage;
    }
    if (arguments.width_option->count() != arguments.height_option->count()) {
        print_error("--width and --height go together");
        return kExitUsage;
    }
    if (arguments.width_option->count() && (arguments.width <= 0 || arguments.height <= 0)) {
        print_error("--width and --height must be positive");
        return kExitUsage;
    }
    if (arguments.threads < 0) {
        print_error("--threads must be 0 (every core) or positive");
        return kExitUsage;
    }
    const double budget = arguments.budget_option->count() ? arguments.budget
                          : arguments.quick                ? kQuickBudgetSeconds
                                                           : kDefaultBudgetSeconds;
    const Clock::time_point run_start = Clock::now();

    try {
        PreparedScene prepared;
        if (!prepare_scene(arguments, prepared)) return kExitBadInput;
        // The scene's parameters apply to its own integrator only, as in
        // `lancer render`; say so once rather than for every other rung.
        if (const sg::RenderSettings& settings = prepared.job.settings;
            settings.integrator && !settings.parameters.empty()) {
            Diagnostic note;
            note.severity = Diagnostic::Severity::Warning;
            note.location = settings.location;
            note.message = "render_settings parameters are for integrator '" + *settings.integrator +
                           "'; trade applies them to it only";
            print_diagnostic(note);
        }
        const std::uint64_t seed =
            arguments.seed_option->count() ? arguments.seed : prepared.job.settings.seed.value_or(0);
        const fs::path out(arguments.out);
        fs::create_directories(out / "renders");
        fs::create_directories(out / "heatmaps");

        TradeRun run;
        run.scene = arguments.scene;
        run.width = prepared.width;
        run.height = prepared.height;
        run.seed = seed;
        run.budget_seconds = budget;
        run.command = command_line(arguments, prepared, budget, seed);

        // Every planned step, for the progress bar: the reference and each rung.
        std::vector<std::vector<TradeSetting>> ladders;
        int total_steps = 1;
        for (const std::string& integrator : trade_integrator_order()) {
            ladders.push_back(trade_ladder(integrator, arguments.quick));
            total_steps += int(ladders.back().size());
        }
        TradeProgress progress(total_steps);
        progress.note("trade: " + arguments.scene + " at " + std::to_string(prepared.width) + "x" +
                      std::to_string(prepared.height) + ", budget " + seconds_text(budget));

        // The reference: path with as many samples as its share of the
        // budget buys, unless the cache holds one for the same scene and
        // settings. A cached one is kept unless this budget would spend
        // over four times what it cost: the decision depends on budgets,
        // not on timings, so a rerun reuses it however loaded the machine.
        const Plugin path_plugin = load_plugin("path");
        const std::uint64_t reference_seed = seed + kReferenceSeedOffset;
        const double reference_seconds = kReferenceShare * budget;
        const std::string settings_text = std::string("lancer ") + kLancerVersion + " size " +
                                          std::to_string(prepared.width) + "x" + std::to_string(prepared.height) +
                                          " seed " + std::to_string(reference_seed) + " path " +
                                          join_parameters(resolve_for(prepared, path_plugin, kReferenceParameters)) +
                                          describe_scene_input_options(arguments.inputs);
        std::vector<std::string> include_folders = arguments.inputs.include_path;
        for (const auto& folder : default_include_path()) include_folders.push_back(folder);
        const std::string key = reference_key(arguments.scene, include_folders, settings_text);
        const ReferenceCache cache(arguments.cache.empty() ? default_reference_cache_folder(out / "reference-cache")
                                                           : fs::path(arguments.cache));
        std::optional<CachedReference> reference = cache.find(key);
        if (reference && reference->render_seconds * 4.0 < reference_seconds &&
            reference->samples_per_pixel < kMaxReferenceSpp)
            reference.reset();
        if (reference) {
            run.reference.cached = true;
            progress.finished("reference", "cached, " + std::to_string(reference->samples_per_pixel) + " spp");
            progress.note("reference: cached (" + reference->file.string() + ")");
        } else {
            // A one-sample pilot sets the count; twice, keeping the faster,
            // since a process's first render pays for warming up.
            progress.starting("reference: pilot");
            double pilot_seconds = 1e30;
            for (int i = 0; i < 2; ++i)
                pilot_seconds = std::min(pilot_seconds, render_setting(prepared, path_plugin, kReferenceParameters, 1,
                                                                       reference_seed, arguments.threads)
                                                            .seconds);
            const int wanted_spp = std::clamp(power_of_two_floor(reference_seconds / std::max(pilot_seconds, 1e-6)),
                                              kMinReferenceSpp, kMaxReferenceSpp);
            progress.starting("reference: path " + std::to_string(wanted_spp) + " spp");
            const TimedRender rendered = render_setting(prepared, path_plugin, kReferenceParameters, wanted_spp,
                                                        reference_seed, arguments.threads);
            reference = cache.store(key, rendered.image, wanted_spp, rendered.noise, rendered.seconds);
            run.reference.seconds = rendered.seconds;
            progress.finished("reference",
                              "path " + std::to_string(wanted_spp) + " spp, " + seconds_text(rendered.seconds));
            progress.note("reference: rendered, path " + std::to_string(wanted_spp) + " spp in " +
                          seconds_text(rendered.seconds) + " (cached in " + reference->file.string() + ")");
        }
        run.reference.samples_per_pixel = reference->samples_per_pixel;
        run.reference.noise_rmse = reference->noise.rmse;
        run.reference.noise_rel_mse = reference->noise.rel_mse;
        run.reference.cache_file = reference->file.string();
        run.reference.image = "reference.png";
        write_rgb_image(reference->image, (out / run.reference.image).string());

        // The ladders. Each integrator may spend its share of the budget plus
        // whatever the ones before it left; a rung whose predicted time
        // (the last rung's, scaled by cost) does not fit is skipped with all
        // the dearer ones after it. The first rung always runs.
        const double ladder_budget = kLadderShare * budget;
        double carried = 0.0;
        for (std::size_t i = 0; i < ladders.size(); ++i) {
            const std::string& integrator = trade_integrator_order()[i];
            const double allowance = ladder_budget_share(integrator) * ladder_budget + carried;
            if (ladders[i].empty()) continue;
            const Plugin plugin = load_plugin(ladders[i].front().integrator);
            double spent = 0.0;
            const TradeSetting* previous = nullptr;
            double previous_seconds = 0.0;
            for (std::size_t rung = 0; rung < ladders[i].size(); ++rung) {
                const TradeSetting& setting = ladders[i][rung];
                const std::string what = integrator + " " + setting.label();
                const bool beyond_reference =
                    integrator == "path" &&
                    setting.samples_per_pixel * kReferenceSppOverLadder > run.reference.samples_per_pixel;
                // Adaptive rungs may spend up to what the reference can measure.
                const int spp = setting.noise_target > 0.0
                                    ? std::max(16, run.reference.samples_per_pixel / kReferenceSppOverLadder)
                                    : setting.samples_per_pixel;
                const double predicted = previous ? previous_seconds * setting.cost / previous->cost : 0.0;
                if (previous && (beyond_reference || spent + predicted > allowance)) {
                    progress.skip(int(ladders[i].size() - rung));
                    break;
                }
                progress.starting(what);
                const TimedRender rendered = render_setting(prepared, plugin, setting.parameters, spp, seed,
                                                            arguments.threads, setting.noise_target);
                TradeResult result;
                result.curve = integrator;
                result.integrator = setting.integrator;
                result.setting = setting.label();
                result.parameters = setting.parameters;
                result.spp = spp;
                result.noise_target = setting.noise_target;
                result.seconds = rendered.seconds;
                result.cpu_seconds = rendered.cpu_seconds;
                result.rays = rendered.rays;
                result.mean_spp = rendered.mean_spp;
                result.estimated_rel_rmse = rendered.estimated_rel_rmse;
                result.rmse = rmse(rendered.image, reference->image);
                result.rel_mse = relative_mse(rendered.image, reference->image);
                result.ssim = ssim(rendered.image, reference->image);
                const std::string stem = setting.integrator + "_" + setting.slug();
                result.image = "renders/" + stem + ".png";
                result.heat_map = "heatmaps/" + stem + ".png";
                write_rgb_image(rendered.image, (out / result.image).string());
                write_rgb_image(error_heat_map(rendered.image, reference->image), (out / result.heat_map).string());
                progress.finished(what, metrics_text(result));
                run.results.push_back(result);
                spent += rendered.seconds;
                previous = &setting;
                previous_seconds = rendered.seconds;
            }
            carried = std::max(0.0, allowance - spent);
        }
        progress.close();

        // The report.
        write_text_file((out / "results.csv").string(), results_csv(run), "the results");
        std::vector<std::string> plots;
        for (const std::string metric : {"rmse", "rel_mse", "1-ssim"}) {
            const std::string file = "error_vs_time_" + std::string(metric == "1-ssim" ? "ssim" : metric) + ".svg";
            write_text_file((out / file).string(), error_plot_svg(run, metric), "a plot");
            plots.push_back(file);
        }
        write_text_file((out / "index.html").string(), report_html(run, plots), "the report");

        const double total = std::chrono::duration<double>(Clock::now() - run_start).count();
        std::set<std::string> integrators;
        for (const TradeResult& result : run.results) integrators.insert(result.integrator);
        std::printf("trade: %zu renders of %zu integrators in %s; wrote %s, %s and %s\n", run.results.size(),
                    integrators.size(), seconds_text(total).c_str(), (out / "results.csv").c_str(),
                    (out / plots.front()).c_str(), (out / "index.html").c_str());
        const TradeVerdict verdict = decide_trade(run);
        if (verdict.recommended >= 0)
            std::printf("trade: recommended: %s\n  %s\n", verdict.recommended_command.c_str(),
                        verdict.recommended_reason.c_str());
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

Command add_trade_command(CLI::App& app) {
    auto arguments = std::make_shared<TradeArguments>();
    CLI::App* trade = app.add_subcommand(
        "trade", "Measure speed against accuracy: every integrator at a ladder of settings against a path reference");
    trade->add_option("scene", arguments->scene, "Scene file (.pov)")->required();
    add_scene_input_options(*trade, arguments->inputs);
    trade->add_option("-o,--out", arguments->out, "Folder for results.csv, the plots, index.html and images")
        ->required();
    arguments->budget_option = trade->add_option("--budget", arguments->budget,
                                                 "Seconds for the whole run, roughly (default 120; 50 with --quick)");
    trade->add_flag("--quick", arguments->quick, "Small images (about 160x120) and short ladders: about a minute");
    arguments->width_option = trade->add_option("--width", arguments->width, "Image width (with --height)");
    arguments->height_option = trade->add_option("--height", arguments->height, "Image height (with --width)");
    arguments->seed_option = add_seed_option(*trade, arguments->seed);
    add_max_memory_option(*trade, arguments->max_memory_bytes);
    trade->add_option("--threads", arguments->threads, "Worker threads (default 0: every core)");
    trade->add_option("--cache", arguments->cache,
                      "Reference cache folder (default $XDG_CACHE_HOME/lancer/references or ~/.cache/...)");
    Command command;
    command.cli = trade;
    command.run = [arguments] { return run_trade(*arguments); };
    return command;
}

}  // namespace lancer::app
