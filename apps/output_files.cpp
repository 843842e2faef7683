#include "output_files.h"

#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "lancer/host/temporary_file.h"

namespace lancer::app {
namespace fs = std::filesystem;

namespace {

// One spelling per place: ./sub/../scene.pov and scene.pov are one file.
fs::path place_of(const std::string& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    if (ec) return fs::path(path).lexically_normal();
    fs::path canonical = fs::weakly_canonical(absolute, ec);
    return ec ? absolute.lexically_normal() : canonical;
}

// The same file under two names (a hard link, a symbolic link) or one name.
bool same_file(const fs::path& a, const fs::path& b) {
    if (a == b) return true;
    std::error_code ec;
    return fs::exists(a, ec) && fs::exists(b, ec) && fs::equivalent(a, b, ec) && !ec;
}

}  // namespace

std::string check_output_files(const std::vector<OutputFile>& outputs, const std::vector<std::string>& inputs) {
    std::vector<fs::path> input_places;
    for (const std::string& input : inputs) input_places.push_back(place_of(input));
    std::vector<fs::path> output_places;
    for (const OutputFile& output : outputs) {
        if (output.path.empty()) return output.role + " needs a file name";
        const fs::path place = place_of(output.path);
        for (std::size_t i = 0; i < inputs.size(); ++i) {
            if (!same_file(place, input_places[i])) continue;
            return "refusing to write " + output.role + " to '" + output.path + "': it is " +
                   (i == 0 ? std::string("the scene file") : "'" + inputs[i] + "', which the scene reads");
        }
        for (std::size_t j = 0; j < output_places.size(); ++j)
            if (same_file(place, output_places[j]))
                return outputs[j].role + " and " + output.role + " name the same file '" + output.path + "'";
        output_places.push_back(place);
        std::error_code ec;
        const fs::path folder = place.parent_path();
        if (!fs::is_directory(folder, ec))
            return "cannot write " + output.role + " '" + output.path + "': folder '" + folder.string() +
                   "' does not exist";
        if (fs::is_directory(place, ec))
            return "cannot write " + output.role + " '" + output.path + "': it is a folder";
        // The file is written beside itself and renamed: the folder must
        // take new files.
        if (::access(folder.c_str(), W_OK) != 0)
            return "cannot write " + output.role + " '" + output.path + "': folder '" + folder.string() +
                   "' is not writable";
    }
    return {};
}

std::string check_report_folder(const std::string& folder, const std::vector<std::string>& inputs) {
    const fs::path report = place_of(folder);
    for (std::size_t i = 0; i < inputs.size(); ++i) {
        const fs::path input = place_of(inputs[i]);
        const fs::path relative = input.lexically_relative(report);
        if (relative.empty() || *relative.begin() == "..") continue;
        const std::string first = relative.begin()->string();
        const std::string name = relative.filename().string();
        const bool written = first == "renders" || first == "heatmaps" ||
                             (relative == relative.filename() &&
                              (name == "reference.png" || name == "results.csv" || name == "index.html" ||
                               (name.rfind("error_vs_time_", 0) == 0 && input.extension() == ".svg")));
        if (written)
            return "refusing to write the report into '" + folder + "': it would replace " +
                   (i == 0 ? std::string("the scene file") : "'" + inputs[i] + "', which the scene reads");
    }
    return {};
}

void write_text_file(const std::string& path, const std::string& text, const std::string& what) {
    const fs::path target(path);
    const fs::path temporary = temporary_path_for(target);
    std::error_code ignored;
    {
        std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
        out << text;
        out.close();
        if (!out) {
            fs::remove(temporary, ignored);
            throw std::runtime_error("cannot write " + what + " '" + path + "'");
        }
    }
    std::error_code renamed;
    fs::rename(temporary, target, renamed);
    if (renamed) {
        fs::remove(temporary, ignored);
        throw std::runtime_error("cannot write " + what + " '" + path + "': " + renamed.message());
    }
}

}  // namespace lancer::app
