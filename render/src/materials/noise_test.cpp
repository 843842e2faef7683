// lancer's noise against POV-Ray 3.7's own output: samples that
// scripts/measure-pov-noise.sh wrote from Debian's povray 3.7.0.10
// (tests/reference/pov/noise/), at random points of every scale and sign and
// on and beside lattice corners. Every table was recovered exactly (or, for
// generator 3's gradients, to ~1e-14), so the tolerances are those of POV's
// printed digits and of those fits; nothing here needs to be statistical.
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "materials/noise.h"

namespace lancer {
namespace {

// The samples' rows: the numbers of each line that is not a # comment.
std::vector<std::vector<double>> read_samples(const std::string& name) {
    const std::string path = std::string(LANCER_SOURCE_DIR) + "/tests/reference/pov/noise/" + name;
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << "cannot read " << path;
    std::vector<std::vector<double>> rows;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        std::vector<double> row;
        double v;
        while (fields >> v) row.push_back(v);
        rows.push_back(row);
    }
    return rows;
}

NoiseGenerator generator_number(int n) {
    return static_cast<NoiseGenerator>(n);
}

// Generators 1 and 2 and the vector noise agree with POV to the 17 decimals
// it prints (their tables are exact; 1e-15 leaves room for a compiler that
// fuses multiply-adds); generator 3's gradients come from fits, good to ~1e-14.
constexpr double kExactTolerance = 1e-15;
constexpr double kGenerator3Tolerance = 1e-13;

void expect_noise_matches(int generator) {
    const auto rows = read_samples("noise_generator" + std::to_string(generator) + ".txt");
    ASSERT_GE(rows.size(), 1000u);
    double worst = 0;
    for (const auto& r : rows) {
        const double mine = pov_noise({r[0], r[1], r[2]}, generator_number(generator));
        worst = std::max(worst, std::fabs(mine - r[3]));
        ASSERT_NEAR(mine, r[3], generator == 3 ? kGenerator3Tolerance : kExactTolerance)
            << "generator " << generator << " at " << r[0] << " " << r[1] << " " << r[2];
    }
    ::testing::Test::RecordProperty("max_abs_difference", std::to_string(worst));
}

TEST(PovNoise, Generator1MatchesPovRay) {
    expect_noise_matches(1);
}
TEST(PovNoise, Generator2MatchesPovRay) {
    expect_noise_matches(2);
}
TEST(PovNoise, Generator3MatchesPovRay) {
    expect_noise_matches(3);
}

TEST(PovNoise, StaysInTheUnitIntervalAndIsContinuousAcrossCells) {
    for (int generator = 1; generator <= 3; ++generator) {
        for (double x = -3.0; x <= 3.0; x += 0.5) {
            // Just either side of a cell boundary (and of POV's 1e-10
            // rounding tolerance for negative coordinates).
            const double below = pov_noise({x - 1e-9, 0.3, -0.7}, generator_number(generator));
            const double above = pov_noise({x + 1e-9, 0.3, -0.7}, generator_number(generator));
            const double at = pov_noise({x, 0.3, -0.7}, generator_number(generator));
            EXPECT_NEAR(below, above, 1e-7);
            EXPECT_NEAR(at, above, 1e-7);
            EXPECT_GE(at, 0.0);
            EXPECT_LE(at, 1.0);
        }
    }
}

// vturbulence(lambda, omega, octaves, p) is POV's DTurbulence; with one
// octave, DNoise (which ignores the noise generator).
TEST(PovNoise, VectorNoiseAndTurbulenceMatchPovRay) {
    const auto rows = read_samples("dturbulence.txt");
    ASSERT_GE(rows.size(), 1500u);
    int one_octave = 0;
    for (const auto& r : rows) {
        const int octaves = static_cast<int>(r[0]);
        const glm::dvec3 p(r[3], r[4], r[5]);
        const glm::dvec3 pov(r[6], r[7], r[8]);
        const glm::dvec3 mine = pov_dturbulence(p, r[1], r[2], octaves, NoiseGenerator::RangeCorrected);
        for (int axis = 0; axis < 3; ++axis)
            ASSERT_NEAR(mine[axis], pov[axis], kExactTolerance)
                << octaves << " octaves at " << p.x << " " << p.y << " " << p.z;
        if (octaves == 1) {
            ++one_octave;
            const glm::dvec3 noise = pov_dnoise(p, NoiseGenerator::Perlin);
            for (int axis = 0; axis < 3; ++axis) ASSERT_NEAR(noise[axis], pov[axis], kExactTolerance);
        }
    }
    EXPECT_GE(one_octave, 500);
}

// POV's scalar Turbulence(), read back from a marble pattern whose value is
// x + 0.01 * Turbulence(p): good to ~2e-10 (x's rounding in POV's sum, at
// coordinates up to 3e4, divided by 0.01).
TEST(PovNoise, TurbulenceMatchesPovRay) {
    const auto rows = read_samples("turbulence.txt");
    ASSERT_GE(rows.size(), 2000u);
    bool seen[4] = {};
    for (const auto& r : rows) {
        const int generator = static_cast<int>(r[0]);
        seen[generator] = true;
        const double mine =
            pov_turbulence({r[4], r[5], r[6]}, r[2], r[3], static_cast<int>(r[1]), generator_number(generator));
        ASSERT_NEAR(mine, r[7], 1e-8) << "generator " << generator << ", " << r[1] << " octaves at " << r[4] << " "
                                      << r[5] << " " << r[6];
    }
    EXPECT_TRUE(seen[1] && seen[2] && seen[3]);
}

}  // namespace
}  // namespace lancer
