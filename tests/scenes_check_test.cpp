// Every scene under scenes/ must parse and evaluate without errors.
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lancer/parser.h"

namespace {

namespace fs = std::filesystem;

std::vector<fs::path> scene_files() {
    std::vector<fs::path> files;
    fs::path root = fs::path(LANCER_SOURCE_DIR) / "scenes";
    std::error_code ec;
    if (!fs::is_directory(root, ec)) return files;
    for (const auto& entry : fs::recursive_directory_iterator(root, ec)) {
        if (entry.is_regular_file() && entry.path().extension() == ".pov") files.push_back(entry.path());
    }
    return files;
}

TEST(SceneCorpus, EverySceneChecksWithoutErrors) {
    auto files = scene_files();
    ASSERT_FALSE(files.empty()) << "no scenes found under scenes/";
    for (const auto& file : files) {
        lancer::ParseOptions options;
        options.include_path = lancer::default_include_path();
        lancer::ParseResult result = lancer::parse_scene_file(file.string(), options);
        std::string diagnostics;
        for (const auto& d : result.diagnostics) diagnostics += lancer::format_diagnostic(d);
        EXPECT_TRUE(result.ok()) << file << "\n" << diagnostics;
    }
}

}  // namespace
