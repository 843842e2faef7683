// What `lancer trade` measured, and the files that show it: results.csv,
// error-versus-time plots (SVG) and index.html with every image side by
// side. Pure formatting: the measuring lives in trade_command.cpp.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace lancer::app {

// One render of the ladder and its errors against the reference.
struct TradeResult {
    std::string curve;  // the plot's series: the integrator, or "path --noise"
    std::string integrator;
    std::string setting;  // "n=64 spp=4"
    // What reproduces it with `lancer render` (trade_verdict.h's render_options).
    std::vector<std::string> parameters;  // key=value
    int spp = 0;                          // samples per pixel, or the cap when adaptive
    double noise_target = 0.0;            // > 0: adaptive
    double seconds = 0.0;                 // wall clock, what the user waits
    double cpu_seconds = 0.0;             // over every thread: steadier on a shared machine
    std::uint64_t rays = 0;               // ray queries (intersect and occluded)
    // The renderer's own estimate of the relative RMSE (as --noise uses it);
    // compare with sqrt(rel_mse), the true one. 0 for deterministic renders.
    double estimated_rel_rmse = 0.0;
    double mean_spp = 0.0;  // samples per pixel taken (adaptive: the mean)
    double rmse = 0.0;
    double rel_mse = 0.0;
    double ssim = 0.0;
    std::string image;     // PNG, relative to the output folder
    std::string heat_map;  // PNG, relative to the output folder
};

struct TradeReference {
    std::string image;  // PNG, relative to the output folder
    int samples_per_pixel = 0;
    double seconds = 0.0;  // 0 when cached
    bool cached = false;
    double noise_rmse = 0.0;     // the reference's own noise (RMSE of its mean)
    double noise_rel_mse = 0.0;  // the same as a relative MSE
    std::string cache_file;
};

struct TradeRun {
    std::string scene;
    std::string command;  // the command line that produced it
    int width = 0;
    int height = 0;
    std::uint64_t seed = 0;
    double budget_seconds = 0.0;
    TradeReference reference;
    std::vector<TradeResult> results;
};

// The integrators in the order every table, plot and legend uses; "path
// --noise" is path with adaptive sampling, shown as its own curve.
const std::vector<std::string>& trade_integrator_order();
std::string integrator_colour(const std::string& integrator);

// One header line, then one line per result: integrator, setting, seconds,
// rays, rmse, rel_mse, ssim, then cpu_seconds, mean_spp and
// estimated_rel_rmse (last, so readers of the first seven are unaffected).
std::string results_csv(const TradeRun& run);

// Error against time, one curve per integrator; `metric` is "rmse",
// "rel_mse" or "1-ssim".
std::string error_plot_svg(const TradeRun& run, const std::string& metric);

// The page: summary, plots, the reference, every render beside its heat
// map, the table. `plot_files` are the SVGs written beside it.
std::string report_html(const TradeRun& run, const std::vector<std::string>& plot_files);

}  // namespace lancer::app
