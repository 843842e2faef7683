// results.csv, the plots and index.html for `lancer trade`.
#include "trade_report.h"

#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

#include "image_metrics.h"
#include "report_plot.h"
#include "trade_verdict.h"

namespace lancer::app {
namespace {

std::string format(const char* pattern, double value) {
    char text[64];
    std::snprintf(text, sizeof text, pattern, value);
    return text;
}

// A CSV field: quoted when it holds a comma or quote.
std::string csv_field(const std::string& text) {
    if (text.find_first_of(",\"\n") == std::string::npos) return text;
    std::string quoted = "\"";
    for (char c : text) quoted += c == '"' ? std::string("\"\"") : std::string(1, c);
    return quoted + "\"";
}

double metric_value(const TradeResult& result, const std::string& metric) {
    if (metric == "rmse") return result.rmse;
    if (metric == "rel_mse") return result.rel_mse;
    return 1.0 - result.ssim;
}

// The ramp of the heat maps as a CSS gradient, for the legend.
std::string heat_map_gradient() {
    std::string stops;
    for (int i = 0; i <= 10; ++i) {
        const double error = kHeatMapMinimum * std::pow(kHeatMapMaximum / kHeatMapMinimum, i / 10.0);
        const Color c = heat_map_colour(error);
        char stop[48];
        std::snprintf(stop, sizeof stop, "%srgb(%d,%d,%d)", i ? "," : "", int(c.r * 255 + 0.5f), int(c.g * 255 + 0.5f),
                      int(c.b * 255 + 0.5f));
        stops += stop;
    }
    return "linear-gradient(to right," + stops + ")";
}

constexpr const char* kStyle = R"(
body { font-family: sans-serif; margin: 1.5em; color: #222; max-width: 1400px; }
h1 { font-size: 1.5em; } h2 { margin-top: 1.6em; border-bottom: 1px solid #ccc; }
.plots img { max-width: 100%; margin: 0.3em; border: 1px solid #ddd; }
.row { display: flex; flex-wrap: wrap; gap: 0.8em; }
figure { margin: 0; padding: 0.4em; border: 1px solid #ddd; background: #fafafa; }
figure img { image-rendering: pixelated; display: block; }
.pair { display: flex; gap: 0.3em; }
figcaption { font-size: 0.85em; margin-top: 0.3em; }
table { border-collapse: collapse; font-size: 0.9em; }
td, th { border: 1px solid #ccc; padding: 0.2em 0.6em; text-align: right; }
td:first-child, td:nth-child(2), th { text-align: left; }
.ramp { display: inline-block; width: 240px; height: 12px; vertical-align: middle; }
code { background: #f2f2f2; padding: 0 0.2em; }
)";

}  // namespace

const std::vector<std::string>& trade_integrator_order() {
    static const std::vector<std::string> order = {"raycast", "shadow", "whitted", "gather", "path", "path --noise"};
    return order;
}

std::string integrator_colour(const std::string& integrator) {
    static const std::map<std::string, std::string> colours = {{"raycast", "#7f7f7f"}, {"shadow", "#1f77b4"},
                                                               {"whitted", "#2ca02c"}, {"gather", "#ff7f0e"},
                                                               {"path", "#d62728"},    {"path --noise", "#9467bd"}};
    const auto found = colours.find(integrator);
    return found != colours.end() ? found->second : "#8c564b";
}

std::string results_csv(const TradeRun& run) {
    std::ostringstream csv;
    csv << "integrator,setting,seconds,rays,rmse,rel_mse,ssim,cpu_seconds,mean_spp,estimated_rel_rmse\n";
    for (const TradeResult& r : run.results) {
        csv << csv_field(r.integrator) << ',' << csv_field(r.setting) << ',' << format("%.6g", r.seconds) << ','
            << r.rays << ',' << format("%.6g", r.rmse) << ',' << format("%.6g", r.rel_mse) << ','
            << format("%.6g", r.ssim) << ',' << format("%.6g", r.cpu_seconds) << ',' << format("%.6g", r.mean_spp)
            << ',' << format("%.6g", r.estimated_rel_rmse) << '\n';
    }
    return csv.str();
}

std::string error_plot_svg(const TradeRun& run, const std::string& metric) {
    LogLogPlot plot;
    const std::string name = metric == "rmse"      ? "RMSE (linear RGB)"
                             : metric == "rel_mse" ? "relative MSE"
                                                   : "1 - SSIM (luma, sRGB)";
    plot.title = name + " against render time";
    plot.x_label = "render time (seconds, wall clock)";
    plot.y_label = name + " vs reference";
    for (const std::string& integrator : trade_integrator_order()) {
        PlotSeries series;
        series.name = integrator;
        series.colour = integrator_colour(integrator);
        for (const TradeResult& r : run.results)
            if (r.curve == integrator) series.points.push_back({r.seconds, metric_value(r, metric), r.setting});
        if (!series.points.empty()) plot.series.push_back(std::move(series));
    }
    // Below the reference's own noise a render's error cannot be measured.
    const double floor = metric == "rmse"      ? run.reference.noise_rmse
                         : metric == "rel_mse" ? run.reference.noise_rel_mse
                                               : 0.0;
    if (floor > 0.0) plot.levels.push_back({floor, "reference noise"});
    return render_svg(plot);
}

std::string report_html(const TradeRun& run, const std::vector<std::string>& plot_files) {
    std::ostringstream html;
    const std::string title = "lancer trade: " + run.scene;
    html << "<!DOCTYPE html>\n<html lang=\"en\"><head><meta charset=\"utf-8\"><title>" << escape_xml(title)
         << "</title>\n<style>" << kStyle << "</style></head><body>\n";
    html << "<h1>" << escape_xml(title) << "</h1>\n";
    html << "<p>" << run.width << "&times;" << run.height << " pixels, seed " << run.seed << ", budget "
         << format("%.0f", run.budget_seconds) << " s. Produced by <code>" << escape_xml(run.command)
         << "</code>.</p>\n";
    const TradeReference& ref = run.reference;
    html << "<p>Reference: <code>path</code> at " << ref.samples_per_pixel << " samples per pixel, "
         << (ref.cached ? std::string("cached (") + escape_xml(ref.cache_file) + ")"
                        : format("%.1f s", ref.seconds) + ", stored in " + escape_xml(ref.cache_file))
         << ". Its own noise, from its per-pixel variance, is an RMSE of about " << format("%.3g", ref.noise_rmse)
         << " (relative MSE " << format("%.3g", ref.noise_rel_mse)
         << ", the dashed lines): errors near that are the reference's, not the render's.</p>\n";

    // The verdict first: which setting to use, and for what budget.
    const TradeVerdict verdict = decide_trade(run);
    html << "<h2>Verdict</h2>\n";
    if (verdict.recommended >= 0)
        html << "<p class=\"recommended\">Recommended: <code>" << escape_xml(verdict.recommended_command)
             << "</code></p>\n<p>" << escape_xml(verdict.recommended_reason) << "</p>\n";
    html << "<p>For each time budget, the setting with the lowest error that fits in it (read off the Pareto "
            "fronts of the plots below: the settings no other beats in both time and error).</p>\n"
            "<table class=\"verdict\"><tr><th>budget</th>";
    for (TradeMetric metric : trade_metrics()) html << "<th>lowest " << metric_label(metric) << "</th>";
    html << "<th>the metrics</th></tr>\n";
    for (const BudgetVerdict& row : verdict.budgets) {
        html << "<tr><td>" << format("%.3g s", row.budget_seconds) << "</td>";
        for (std::size_t m = 0; m < row.best.size(); ++m) {
            html << "<td>";
            if (row.best[m] >= 0) {
                const TradeResult& r = run.results[row.best[m]];
                html << escape_xml(r.integrator + " " + r.setting) << " ("
                     << format("%.3g", metric_error(r, trade_metrics()[m])) << ")";
            }
            html << "</td>";
        }
        html << "<td>"
             << (!row.disagreement.empty() ? escape_xml(row.disagreement)
                 : row.tie                 ? std::string("a tie: their picks differ by less than one seed can tell")
                                           : std::string("agree"))
             << "</td></tr>\n";
    }
    html << "</table>\n";
    if (!verdict.anomalies.empty()) {
        html << "<p>More time, more error:</p>\n<ul>";
        for (const std::string& anomaly : verdict.anomalies) html << "<li>" << escape_xml(anomaly) << "</li>";
        html << "</ul>\n";
    }

    // The plots: they show the whole trade behind the verdict.
    html << "<h2>Error against time</h2>\n<p>Lower and further left is better. Each point is one setting "
            "(hover for its name); a curve that flattens has reached its integrator's bias.</p>\n"
            "<div class=\"plots\">";
    for (const std::string& file : plot_files)
        html << "<a href=\"" << escape_xml(file) << "\"><img src=\"" << escape_xml(file) << "\" alt=\""
             << escape_xml(file) << "\"></a>";
    html << "</div>\n";

    // Images: the reference, then each integrator's ladder as render | heat map.
    html << "<h2>Renders and error heat maps</h2>\n<p>Heat maps show each pixel's relative error "
            "sqrt(mean<sub>c</sub> (x&minus;r)&sup2; / (r&sup2; + 0.01)) on a log scale: "
         << format("%g", kHeatMapMinimum) << " <span class=\"ramp\" style=\"background:" << heat_map_gradient()
         << "\"></span> " << format("%g", kHeatMapMaximum) << " and above.</p>\n";
    html << "<div class=\"row\"><figure><img src=\"" << escape_xml(ref.image) << "\" width=\"" << run.width * 2
         << "\" alt=\"reference\"><figcaption>reference: path, " << ref.samples_per_pixel
         << " spp</figcaption></figure></div>\n";
    for (const std::string& integrator : trade_integrator_order()) {
        bool any = false;
        for (const TradeResult& r : run.results) any = any || r.curve == integrator;
        if (!any) continue;
        html << "<h3 style=\"color:" << integrator_colour(integrator) << "\">" << escape_xml(integrator)
             << "</h3>\n<div class=\"row\">\n";
        for (const TradeResult& r : run.results) {
            if (r.curve != integrator) continue;
            html << "<figure><div class=\"pair\"><img src=\"" << escape_xml(r.image) << "\" width=\"" << run.width
                 << "\" alt=\"render\"><img src=\"" << escape_xml(r.heat_map) << "\" width=\"" << run.width
                 << "\" alt=\"heat map\"></div><figcaption><b>" << escape_xml(r.setting)
                 << "</b>: " << format("%.3g s", r.seconds) << ", RMSE " << format("%.3g", r.rmse) << ", relMSE "
                 << format("%.3g", r.rel_mse) << ", SSIM " << format("%.3f", r.ssim) << "</figcaption></figure>\n";
        }
        html << "</div>\n";
    }

    // The table, as in results.csv.
    html << "<h2>Numbers</h2>\n<p>Also in <a href=\"results.csv\">results.csv</a>. Rays count every "
            "intersection and shadow query. The estimated relative RMSE is the renderer's own, from each pixel's "
            "variance (what <code>--noise</code> steers by); the true one is sqrt(rel MSE) against the "
            "reference.</p>\n<table><tr><th>integrator</th><th>setting</th><th>seconds</th>"
            "<th>rays</th><th>RMSE</th><th>rel MSE</th><th>SSIM</th><th>CPU seconds</th><th>mean spp</th>"
            "<th>estimated rel. RMSE</th><th>true rel. RMSE</th></tr>\n";
    for (const TradeResult& r : run.results)
        html << "<tr><td>" << escape_xml(r.integrator) << "</td><td>" << escape_xml(r.setting) << "</td><td>"
             << format("%.3f", r.seconds) << "</td><td>" << r.rays << "</td><td>" << format("%.4g", r.rmse)
             << "</td><td>" << format("%.4g", r.rel_mse) << "</td><td>" << format("%.4f", r.ssim) << "</td><td>"
             << format("%.3f", r.cpu_seconds) << "</td><td>" << format("%.1f", r.mean_spp) << "</td><td>"
             << format("%.4g", r.estimated_rel_rmse) << "</td><td>" << format("%.4g", std::sqrt(r.rel_mse))
             << "</td></tr>\n";
    html << "</table>\n</body></html>\n";
    return html.str();
}

}  // namespace lancer::app
