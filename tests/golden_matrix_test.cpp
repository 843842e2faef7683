// The golden matrix is complete: a scene cannot land in scenes/ without a
// row per integrator its header says suits it, a row cannot land without
// its golden, and no golden outlives its row.
#include <algorithm>
#include <filesystem>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "golden_matrix.h"
#include "lancer/host/plugin_host.h"

namespace lancer::golden {
namespace {

namespace fs = std::filesystem;

// Guards against: a malformed matrix silently instantiating no golden test.
TEST(GoldenMatrix, Loads) {
    std::vector<MatrixEntry> entries;
    ASSERT_NO_THROW(entries = load_matrix());
    EXPECT_GE(entries.size(), 40u);
}

// Guards against: a row naming a scene that was renamed or an integrator
// that does not exist (its golden test would fail for the wrong reason).
TEST(GoldenMatrix, EveryRowNamesASceneAndAnIntegrator) {
    const auto scenes = corpus_scenes();
    for (const MatrixEntry& entry : load_matrix()) {
        EXPECT_TRUE(std::binary_search(scenes.begin(), scenes.end(), entry.scene))
            << "matrix.txt:" << entry.line << ": no scenes/" << entry.scene << ".pov";
        EXPECT_NO_THROW(load_plugin(entry.integrator)) << "matrix.txt:" << entry.line;
    }
}

// Guards against: a new scene landing without goldens, or without saying
// which integrators suit it.
TEST(GoldenMatrix, EverySceneHasAGoldenForEachIntegratorItsHeaderNames) {
    std::set<std::pair<std::string, std::string>> rows;
    for (const MatrixEntry& entry : load_matrix()) rows.insert({entry.scene, entry.integrator});
    for (const std::string& scene : corpus_scenes()) {
        const auto suits = suited_integrators(scene);
        EXPECT_FALSE(suits.empty()) << "scenes/" << scene
                                    << ".pov: its header comment has no \"Suits: <integrators>.\" line";
        for (const std::string& integrator : suits)
            EXPECT_TRUE(rows.count({scene, integrator}))
                << "scenes/" << scene << ".pov suits " << integrator << " but tests/golden/matrix.txt has no row '"
                << scene << " " << integrator << "' (add it, then scripts/regenerate-goldens.sh)";
    }
}

// Guards against: a row landing without its image (the golden test would
// fail, but this says what to do).
TEST(GoldenMatrix, EveryRowHasItsGolden) {
    for (const MatrixEntry& entry : load_matrix())
        EXPECT_TRUE(fs::is_regular_file(entry.golden_path()))
            << "matrix.txt:" << entry.line << ": missing " << entry.golden_path() << " (scripts/regenerate-goldens.sh '"
            << entry.id() << "')";
}

// Guards against: stale goldens of deleted rows, and goldens kept outside
// tests/golden/ (the former plugins/*/golden/) that nothing checks.
TEST(GoldenMatrix, NoGoldenWithoutARow) {
    std::set<std::string> expected;
    for (const MatrixEntry& entry : load_matrix()) expected.insert(fs::path(entry.golden_path()).lexically_normal());
    for (const auto& item : fs::recursive_directory_iterator(golden_dir())) {
        if (item.is_regular_file() && item.path().extension() == ".exr") {
            EXPECT_TRUE(expected.count(item.path().lexically_normal()))
                << item.path() << " belongs to no row of tests/golden/matrix.txt";
        }
    }
    for (const auto& item : fs::directory_iterator(source_dir() + "/plugins"))
        EXPECT_FALSE(fs::exists(item.path() / "golden")) << item.path() / "golden"
                                                         << ": goldens live in tests/golden/ (docs/testing.md)";
}

// The header parser reads the corpus' own phrasing.
TEST(GoldenMatrix, SuitsLineParsing) {
    EXPECT_EQ(suited_integrators("glass"), (std::vector<std::string>{"whitted", "path"}));
    EXPECT_EQ(suited_integrators("sphere_lights"), (std::vector<std::string>{"path", "gather", "shadow"}));
    EXPECT_EQ(suited_integrators("hard_shadows"), (std::vector<std::string>{"shadow", "whitted", "path", "raycast"}));
}

}  // namespace
}  // namespace lancer::golden
