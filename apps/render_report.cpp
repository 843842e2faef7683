// The --stats JSON, image metadata and summary line from one RenderReport,
// so the three never disagree.
#include "render_report.h"

#include "output_files.h"

#include <unistd.h>

#include <atomic>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace lancer {
namespace {

namespace fs = std::filesystem;

// JSON has no NaN or infinity: those become null.
std::string number(double value) {
    if (!std::isfinite(value)) return "null";
    char text[32];
    std::snprintf(text, sizeof text, "%.9g", value);
    return text;
}

std::string number(std::uint64_t value) {
    return std::to_string(value);
}

const char* mode_name(const RenderReport& report) {
    if (report.noise_target > 0.0) return report.time_budget_seconds > 0.0 ? "noise+time" : "noise";
    if (report.time_budget_seconds > 0.0) return "time";
    return "fixed";
}

std::string joined_parameters(const RenderReport& report) {
    std::string joined;
    for (const auto& [name, value] : report.parameters) {
        if (!joined.empty()) joined += ' ';
        joined += name + "=" + value;
    }
    return joined;
}

}  // namespace

std::string json_string(const std::string& text) {
    std::string out = "\"";
    for (const unsigned char c : text) {
        switch (c) {
        case '"': out += "\\\""; break;
        case '\\': out += "\\\\"; break;
        case '\n': out += "\\n"; break;
        case '\t': out += "\\t"; break;
        case '\r': out += "\\r"; break;
        default:
            if (c < 0x20) {
                char escaped[8];
                std::snprintf(escaped, sizeof escaped, "\\u%04x", c);
                out += escaped;
            } else {
                out += char(c);
            }
        }
    }
    return out + "\"";
}

std::string stats_json(const RenderReport& report) {
    const RenderStats& s = report.stats;
    std::string parameters;
    for (const auto& [name, value] : report.parameters) {
        if (!parameters.empty()) parameters += ", ";
        parameters += json_string(name) + ": " + json_string(value);
    }
    std::string json = "{\n";
    json += "  \"scene\": " + json_string(report.scene) + ",\n";
    json += "  \"output\": " + json_string(report.output) + ",\n";
    json += "  \"integrator\": " + json_string(report.integrator) + ",\n";
    json += "  \"parameters\": {" + parameters + "},\n";
    json += "  \"width\": " + std::to_string(report.width) + ",\n";
    json += "  \"height\": " + std::to_string(report.height) + ",\n";
    json += "  \"seed\": " + number(report.seed) + ",\n";
    json += "  \"mode\": " + json_string(mode_name(report)) + ",\n";
    json += "  \"requested\": {\"spp\": " + std::to_string(report.samples_per_pixel) +
            ", \"time_seconds\": " + number(report.time_budget_seconds) +
            ", \"noise\": " + number(report.noise_target) + "},\n";
    json += "  \"samples\": {\"mean\": " + number(s.mean_samples_per_pixel) +
            ", \"min\": " + std::to_string(s.min_samples_per_pixel) +
            ", \"max\": " + std::to_string(s.max_samples_per_pixel) + ", \"taken\": " + number(s.samples) + "},\n";
    json += "  \"passes\": " + std::to_string(s.passes) + ",\n";
    json +=
        "  \"seconds\": {\"total\": " + number(report.total_seconds) + ", \"render\": " + number(s.seconds) + "},\n";
    json += "  \"rays\": " + number(s.rays) + ",\n";
    json += "  \"rays_per_second\": " + number(s.rays_per_second) + ",\n";
    json += "  \"nonfinite_samples\": " + number(s.nonfinite_samples) + ",\n";
    json += "  \"estimated_rel_rmse\": " + number(s.estimated_rel_rmse) + ",\n";
    json += std::string("  \"interrupted\": ") + (s.interrupted ? "true" : "false") + "\n";
    json += "}\n";
    return json;
}

void write_stats_json(const RenderReport& report, const std::string& path) {
    app::write_text_file(path, stats_json(report), "stats");
}

std::map<std::string, std::string> stats_metadata(const RenderReport& report) {
    const RenderStats& s = report.stats;
    std::map<std::string, std::string> metadata = {
        {"scene", report.scene},
        {"integrator", report.integrator},
        {"parameters", joined_parameters(report)},
        {"seed", std::to_string(report.seed)},
        {"mode", mode_name(report)},
        {"spp", number(s.mean_samples_per_pixel)},
        {"spp_min", std::to_string(s.min_samples_per_pixel)},
        {"spp_max", std::to_string(s.max_samples_per_pixel)},
        {"passes", std::to_string(s.passes)},
        {"seconds", number(report.total_seconds)},
        {"render_seconds", number(s.seconds)},
        {"rays", number(s.rays)},
        {"rays_per_second", number(s.rays_per_second)},
        {"nonfinite_samples", number(s.nonfinite_samples)},
        {"interrupted", s.interrupted ? "true" : "false"},
    };
    // Only an estimate there is: 0 would read as an image without noise
    // where the film kept no variance (a fixed count without --stats, or
    // a deterministic integrator).
    if (s.estimated_rel_rmse > 0.0) metadata["estimated_rel_rmse"] = number(s.estimated_rel_rmse);
    return metadata;
}

std::string summary_line(const RenderReport& report) {
    const RenderStats& s = report.stats;
    char spp[64];
    if (s.min_samples_per_pixel == s.max_samples_per_pixel)
        std::snprintf(spp, sizeof spp, "%u spp", s.max_samples_per_pixel);
    else
        std::snprintf(spp, sizeof spp, "%.1f spp (%u-%u)", s.mean_samples_per_pixel, s.min_samples_per_pixel,
                      s.max_samples_per_pixel);
    char line[512];
    std::snprintf(line, sizeof line, "lancer: %dx%d, %s, %s, %.2f s (render %.2f s), %.2f Mrays/s", report.width,
                  report.height, spp, report.integrator.c_str(), report.total_seconds, s.seconds,
                  s.rays_per_second / 1e6);
    std::string text = line;
    if (s.estimated_rel_rmse > 0.0) {
        char error[64];
        std::snprintf(error, sizeof error, ", est. rel. error %.4f", s.estimated_rel_rmse);
        text += error;
    }
    if (s.interrupted) text += ", INTERRUPTED";
    return text + " -> " + report.output;
}

}  // namespace lancer
