// The rule for every file lancer writes itself (image, stats, checkpoint,
// reports): never the scene, nor any file the scene read, never two outputs
// at one path, and every path checked before any work starts, so a render
// that cannot write its results fails before it begins and never after it
// has replaced an existing file.
#pragma once

#include <string>
#include <vector>

namespace lancer::app {

struct OutputFile {
    std::string role;  // what it is, for messages: "the image (-o)", "--stats"
    std::string path;
};

// The first broken rule as a message naming the path, or empty. `inputs`:
// the scene file and every file it read (sg::SceneGraph::input_files).
std::string check_output_files(const std::vector<OutputFile>& outputs, const std::vector<std::string>& inputs);

// The first of `inputs` that lies where `lancer trade` writes its report in
// `folder` (reference.png, results.csv, index.html, error_vs_time_*.svg,
// renders/, heatmaps/), as a message, or empty.
std::string check_report_folder(const std::string& folder, const std::vector<std::string>& inputs);

// Writes `text` to `path` whole or not at all (a temporary beside it, then
// rename). Throws std::runtime_error naming `what` and the path.
void write_text_file(const std::string& path, const std::string& text, const std::string& what);

}  // namespace lancer::app
