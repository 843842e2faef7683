// Patterns, warps and noise at the extremes fuzz_patterns reaches
// (tests/fuzz/fuzz_patterns.cc, docs/robustness.md): far points, huge and
// tiny parameters, points on a warp's axis or ring. Values stay finite and
// defined (the sanitizer stage runs these under UBSan), and parameters
// lancer cannot evaluate are refused with a message.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "materials/noise.h"
#include "materials/pattern.h"
#include "materials/pattern_functions.h"

namespace lancer {
namespace {

using Kind = sg::Pattern::Kind;
using pattern_detail::floor_to_int;
using pattern_detail::wrap_into;

sg::Pattern make(Kind kind) {
    sg::Pattern p;
    p.kind = kind;
    return p;
}

std::string refusal(const sg::Pattern& pattern) {
    try {
        CompiledPattern compiled(pattern, NoiseGenerator::RangeCorrected);
    } catch (const std::runtime_error& error) {
        return error.what();
    }
    return "";
}

TEST(PatternExtremes, FloorToIntKeepsParityAndTheHashCellBeyondInt) {
    EXPECT_EQ(floor_to_int(-0.5), -1);
    EXPECT_EQ(floor_to_int(2147483647.5), 2147483647);
    EXPECT_EQ(floor_to_int(-2147483648.0), -2147483647 - 1);
    for (const double v : {3.0e9, -3.0e9 - 1.0, 1.0e17, -1.0e17 + 16.0, 0x1p60 + 4096.0 * 3.0 + 4096.0}) {
        const int cell = floor_to_int(v);
        EXPECT_EQ(cell & 1, int(std::fmod(std::fabs(v), 2.0))) << v;
        EXPECT_EQ(cell & 0xFFF, int(std::fmod(std::fmod(v, 4096.0) + 4096.0, 4096.0))) << v;
    }
    EXPECT_EQ(floor_to_int(std::numeric_limits<double>::infinity()), 0);
    EXPECT_EQ(floor_to_int(std::nan("")), 0);
}

TEST(PatternExtremes, WrapIntoStaysInItsPeriod) {
    const double under_six = std::nextafter(6.0, 0.0);
    EXPECT_LT(wrap_into(under_six, 6.0), 6.0);
    EXPECT_GE(wrap_into(-std::nextafter(0.0, 1.0), 6.0), 0.0);
    EXPECT_EQ(wrap_into(7.5, 6.0), 1.5);  // POV's reduction where it is exact
    for (const double v : {2.0e17, -2.0e17, 1.0e300}) {
        const double r = wrap_into(v, std::sqrt(3.0));
        EXPECT_GE(r, 0.0) << v;
        EXPECT_LT(r, std::sqrt(3.0)) << v;
    }
}

// A finely scaled pattern reaches the 1e17 coordinate limit: every block,
// cell and noise pattern must give a finite value and a block index in
// range there (their cell numbers no longer fit an int).
TEST(PatternExtremes, FarPointsGiveFiniteValuesAndBlocksInRange) {
    const Kind kinds[] = {Kind::Checker, Kind::Hexagon,  Kind::Brick, Kind::Cubic,   Kind::Square, Kind::Triangular,
                          Kind::Cells,   Kind::Crackle,  Kind::Bozo,  Kind::Granite, Kind::Agate,  Kind::Wood,
                          Kind::Marble,  Kind::Wrinkles, Kind::Dents, Kind::Leopard, Kind::Facets, Kind::Gradient};
    for (const Kind kind : kinds) {
        sg::Pattern p = make(kind);
        p.pattern_from_object = glm::dmat4(1.0e30);
        p.pattern_from_object[3][3] = 1.0;
        const CompiledPattern compiled(p, NoiseGenerator::RangeCorrected);
        for (const glm::dvec3 point :
             {glm::dvec3(3.0e9, -7.0e9, 2.5), glm::dvec3(1.0, -1.0, 0.25), glm::dvec3(-0.1, 2.0e-13, 5.0e-21)}) {
            EXPECT_TRUE(std::isfinite(compiled.value(point))) << int(kind);
            if (compiled.is_block()) {
                const int index = compiled.block_index(point);
                EXPECT_GE(index, 0) << int(kind);
                EXPECT_LT(index, compiled.block_count()) << int(kind);
            }
        }
        if (kind == Kind::Facets) {
            const glm::dvec3 n = compiled.perturb_normal(glm::dvec3(0.0, 1.0, 0.0), glm::dvec3(3.0e9, 1.0, 2.0), 0.5);
            EXPECT_NEAR(glm::length(n), 1.0, 1e-9);
        }
    }
}

TEST(PatternExtremes, NoiseBeyondInt64IsDefined) {
    for (const NoiseGenerator generator :
         {NoiseGenerator::Original, NoiseGenerator::RangeCorrected, NoiseGenerator::Perlin}) {
        for (const double x : {1.0e19, -1.0e300, std::numeric_limits<double>::infinity()}) {
            EXPECT_TRUE(std::isfinite(pov_noise(glm::dvec3(x, 0.5, 0.25), generator))) << x;
            const glm::dvec3 d = pov_dnoise(glm::dvec3(0.5, x, 0.25), generator);
            EXPECT_TRUE(std::isfinite(d.x + d.y + d.z)) << x;
        }
        // NaN is not hidden.
        EXPECT_TRUE(std::isnan(pov_noise(glm::dvec3(std::nan(""), 0.5, 0.25), generator)));
    }
}

// fuzz_patterns: cylindrical_dist_exp_overflow.patterns and
// toroidal_dist_exp_overflow.patterns. length^dist_exp overflowed, and the
// infinite coordinate times the orientation's zeros (or a point on the
// seam, 0 x infinity) made the point NaN.
TEST(PatternExtremes, MappingWarpsWithAHugeDistanceExponentStayFinite) {
    for (const auto kind : {sg::Warp::Kind::Cylindrical, sg::Warp::Kind::Spherical, sg::Warp::Kind::Toroidal}) {
        sg::Pattern p = make(Kind::Onion);
        sg::Warp warp;
        warp.kind = kind;
        warp.dist_exp = 1.0e6;
        warp.orientation = glm::dvec3(0.0, 1.0, 0.0);
        p.warps = {warp, warp};
        const CompiledPattern compiled(p, NoiseGenerator::RangeCorrected);
        for (const glm::dvec3 point :
             {glm::dvec3(3.0, 0.0, 0.0), glm::dvec3(1.5, 2.0, -4.0), glm::dvec3(1.0, 0.0, 0.0)})
            EXPECT_TRUE(std::isfinite(compiled.value(point))) << int(kind);
    }
}

// On a toroidal warp's ring the angle around it is undefined (0/0 in POV).
TEST(PatternExtremes, ToroidalWarpOnItsRing) {
    sg::Pattern p = make(Kind::Gradient);
    sg::Warp warp;
    warp.kind = sg::Warp::Kind::Toroidal;
    warp.major_radius = 1.0;
    p.warps = {warp};
    const CompiledPattern compiled(p, NoiseGenerator::RangeCorrected);
    EXPECT_TRUE(std::isfinite(compiled.value(glm::dvec3(1.0, 0.0, 0.0))));
}

TEST(PatternExtremes, RepeatWidthsOutsideSinglePrecisionAreRefused) {
    sg::Pattern p = make(Kind::Checker);
    sg::Warp warp;
    warp.kind = sg::Warp::Kind::Repeat;
    warp.repeat = glm::dvec3(1.0e-50, 0.0, 0.0);
    p.warps = {warp};
    EXPECT_NE(refusal(p).find("single precision"), std::string::npos);
    p.warps[0].repeat.x = 1.0e-30;  // tiny, but a float: far cells have no float number
    const CompiledPattern compiled(p, NoiseGenerator::RangeCorrected);
    EXPECT_TRUE(std::isfinite(compiled.value(glm::dvec3(1.0e10, 0.5, 0.5))));
    EXPECT_GE(compiled.block_index(glm::dvec3(1.0e10, 0.5, 0.5)), 0);
}

TEST(PatternExtremes, OverflowingTurbulenceIsRefused) {
    sg::Pattern p = make(Kind::Bozo);
    p.turbulence = glm::dvec3(0.5);
    p.octaves = 10;
    p.lambda = 1.0e38;
    EXPECT_NE(refusal(p).find("turbulence"), std::string::npos);
    p.lambda = 2.0;
    p.omega = 1.0e38;
    EXPECT_NE(refusal(p).find("turbulence"), std::string::npos);
    p.omega = 1.0e30;  // 1e270 after 9 octaves: finite
    EXPECT_EQ(refusal(p), "");
}

TEST(PatternExtremes, FractalLimitsAndExteriorFactors) {
    sg::Pattern p = make(Kind::Mandel);
    p.fractal_iterations = 100001;
    EXPECT_NE(refusal(p).find("limited to 100000"), std::string::npos);
    p.fractal_iterations = 30;
    p.exterior_type = 7;
    p.exterior_factor = 0.5;  // POV: iterations % 0
    EXPECT_NE(refusal(p).find("exterior 7"), std::string::npos);
    p.exterior_type = 8;
    p.exterior_factor = -0.5;  // POV: % 0 again
    EXPECT_NE(refusal(p).find("exterior 8"), std::string::npos);
    p.exterior_factor = 1.0e20;  // beyond unsigned
    EXPECT_NE(refusal(p).find("exterior 8"), std::string::npos);
    p.exterior_factor = 3.0;
    EXPECT_EQ(refusal(p), "");
}

// The magnet map's denominator vanishes at c = 2 (mandel form, z = 0):
// POV divides by zero; lancer counts the point as escaped.
TEST(PatternExtremes, MagnetPoleEscapes) {
    sg::Pattern p = make(Kind::Magnet);
    p.fractal_iterations = 20;
    p.exterior_type = 2;
    const CompiledPattern compiled(p, NoiseGenerator::RangeCorrected);
    EXPECT_TRUE(std::isfinite(compiled.value(glm::dvec3(2.0, 0.0, 0.0))));
}

// Each ripples or waves pattern stores every wave and sums them all per sample.
TEST(PatternExtremes, NumberOfWavesIsLimited) {
    sg::Pattern p = make(Kind::Ripples);
    p.number_of_waves = 2000000000;
    EXPECT_NE(refusal(p).find("number_of_waves is limited to 100000"), std::string::npos);
    p.number_of_waves = 0;  // POV's minimum of one wave
    EXPECT_EQ(refusal(p), "");
}

TEST(PatternExtremes, NegativePolyWaveExponentIsRefused) {
    sg::Pattern p = make(Kind::Gradient);
    p.wave = sg::WaveType::Poly;
    p.wave_exponent = -2.0;
    EXPECT_NE(refusal(p).find("poly_wave"), std::string::npos);
    p.wave_exponent = 0.0;
    EXPECT_EQ(refusal(p), "");
}

}  // namespace
}  // namespace lancer
