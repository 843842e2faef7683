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

}  // namespace lancer::app
