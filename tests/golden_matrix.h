// The corpus x integrator golden matrix (tests/golden/matrix.txt) and what
// the golden tests need around it: parsing the matrix, rendering one entry,
// reading and writing golden EXRs. Test-only; see docs/testing.md.
#pragma once

#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include "lancer/host/film.h"
#include "stat_compare.h"

namespace lancer::golden {

// One row of tests/golden/matrix.txt: a scene of scenes/ rendered by one
// integrator with fixed parameters.
struct MatrixEntry {
    std::string scene;                              // path under scenes/ without ".pov", e.g. "language/meshes"
    std::string integrator;                         // plugin name
    std::map<std::string, std::string> parameters;  // integrator parameters (key=value)
    // Harness options (":key=value" in the matrix); 0 means the default.
    int test_spp = 0;                 // stochastic: samples per pixel of the test render
    int golden_spp = 0;               // stochastic: samples per pixel of the golden
    int block = 0;                    // stochastic: block size of the z-test
    double absolute_tolerance = 0.0;  // stochastic: see stat_compare.h
    int line = 0;                     // in matrix.txt, for messages

    // "cornell_box/path" or "cornell_box/shadow.area_samples-4": the golden's
    // path under tests/golden/ without ".exr", and the test's name.
    std::string id() const;
    std::string golden_path() const;  // absolute
};

// Image sizes: small, so the whole matrix runs in seconds. Stochastic
// entries are smaller still, since they trace many samples per pixel.
inline constexpr int kDeterministicWidth = 96, kDeterministicHeight = 72;
inline constexpr int kStochasticWidth = 64, kStochasticHeight = 48;
// Seeds: the golden and the test render draw independent samples, as the
// z-test assumes.
inline constexpr std::uint64_t kGoldenSeed = 0x601de2;
inline constexpr std::uint64_t kTestSeed = 1;
inline constexpr std::uint64_t kReferenceSeed = 0x5eed5;

std::string source_dir();
std::string golden_dir();   // <source>/tests/golden
std::string failure_dir();  // <build>/golden_failures

// Throws std::runtime_error naming matrix.txt:line on a malformed row.
std::vector<MatrixEntry> load_matrix();

// Every scenes/**/*.pov as "name" or "folder/name" (no extension), sorted.
std::vector<std::string> corpus_scenes();
// Integrators named on the scene's "Suits:" line(s) of its header comment
// (the leading // comment block); empty if it has none.
std::vector<std::string> suited_integrators(const std::string& scene);

struct RenderResult {
    Film film{1, 1};
    bool deterministic = false;
};
// Renders the entry's scene with its integrator at the given size, spp and
// seed, on every core.
RenderResult render_entry(const MatrixEntry& entry, int width, int height, int spp, std::uint64_t seed);

// Goldens: a float EXR, linear. Deterministic ones hold R,G,B; stochastic
// ones add var.R, var.G, var.B, the variance of each pixel's mean.
struct GoldenFile {
    test::PixelStatistics statistics;  // variance all zero for deterministic goldens
    bool has_variance = false;
    std::map<std::string, std::string> metadata;
};
GoldenFile read_golden(const std::string& path);
void write_golden(const std::string& path, const Film& film, bool with_variance,
                  const std::map<std::string, std::string>& metadata);

// render | golden | |difference| x gain, sRGB-encoded, as one PNG; returns
// its path (under failure_dir()).
std::string write_failure_image(const std::string& id, const test::PixelStatistics& render,
                                const test::PixelStatistics& golden, float gain);

// True when LANCER_REGENERATE_GOLDENS=1.
bool regenerating();

}  // namespace lancer::golden
