// What a render did, in the three forms a user meets it: the --stats JSON
// file, the output image's metadata, and the one-line terminal summary.
#pragma once

#include <map>
#include <string>
#include <utility>
#include <vector>

#include "lancer/host/renderer.h"

namespace lancer {

struct RenderReport {
    std::string scene;                                            // scene file as given
    std::string output;                                           // image file
    std::string integrator;                                       // plugin name
    std::vector<std::pair<std::string, std::string>> parameters;  // resolved, name -> value
    int width = 0;
    int height = 0;
    std::uint64_t seed = 0;
    // The requested stopping rule; 0 where not used.
    int samples_per_pixel = 0;
    double time_budget_seconds = 0.0;
    double noise_target = 0.0;
    double total_seconds = 0.0;  // process work: parse, build, render, write
    RenderStats stats;
};

// `text` as a JSON string, quotes included.
std::string json_string(const std::string& text);

// The --stats document (a JSON object; fields in docs/rendering.md).
std::string stats_json(const RenderReport& report);
// Writes stats_json atomically (temporary file, then rename). Throws
// std::runtime_error naming the path on failure.
void write_stats_json(const RenderReport& report, const std::string& path);
// The same facts as flat key/value pairs for the image metadata.
std::map<std::string, std::string> stats_metadata(const RenderReport& report);
// "lancer: 640x480, path, 16.0 spp (16-16), 2.31 s, 12.4 Mrays/s, rel. error ~0.042 -> out.png"
std::string summary_line(const RenderReport& report);

}  // namespace lancer
