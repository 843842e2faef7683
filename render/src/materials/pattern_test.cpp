// CompiledPattern against closed forms and against POV-Ray's own values
// (tests/reference/pov/patterns/*.txt, written by
// scripts/measure-pov-patterns.sh from povray's pattern functions).
#include "materials/pattern.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iterator>
#include <map>
#include <memory>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <glm/gtc/matrix_transform.hpp>

namespace lancer {
namespace {

using Kind = sg::Pattern::Kind;
using sg::WaveType;

sg::Pattern make(Kind kind) {
    sg::Pattern p;
    p.kind = kind;
    return p;
}

// POV's `scale s` on a pattern: the pattern point is the object point / s.
glm::dmat4 pattern_scale(const glm::dvec3& s) {
    return glm::scale(glm::dmat4(1.0), 1.0 / s);
}
glm::dmat4 pattern_scale(double s) {
    return pattern_scale(glm::dvec3(s));
}

sg::Warp transform_step(const glm::dmat4& inner_from_outer) {
    sg::Warp w;
    w.kind = sg::Warp::Kind::Transform;
    w.inner_from_outer = inner_from_outer;
    return w;
}

sg::Warp repeat_step(const glm::dvec3& repeat, const glm::dvec3& flip = {}, const glm::dvec3& offset = {}) {
    sg::Warp w;
    w.kind = sg::Warp::Kind::Repeat;
    w.repeat = repeat;
    w.flip = flip;
    w.offset = offset;
    return w;
}

sg::Warp black_hole_step(const glm::dvec3& center, double radius) {
    sg::Warp w;
    w.kind = sg::Warp::Kind::BlackHole;
    w.center = center;
    w.radius = radius;
    return w;
}

double value_at(const sg::Pattern& p, const glm::dvec3& point) {
    return CompiledPattern(p, NoiseGenerator::RangeCorrected).value(point);
}

// ---------------------------------------------------------------- closed forms

TEST(Patterns, GradientIsTheDistanceAlongItsUnitVector) {
    sg::Pattern p = make(Kind::Gradient);
    EXPECT_DOUBLE_EQ(value_at(p, {0.25, 7, 7}), 0.25);
    EXPECT_DOUBLE_EQ(value_at(p, {1.75, 0, 0}), 0.75);
    EXPECT_NEAR(value_at(p, {-0.25, 0, 0}), 0.75, 1e-12);  // negative values wrap after the frequency
    EXPECT_DOUBLE_EQ(value_at(p, {1.0, 0, 0}), 1.0);       // an exact 1 stays 1 (the top of the map)
    p.vector = {0, 2, 0};                                  // normalised, as POV does
    EXPECT_DOUBLE_EQ(value_at(p, {0, 0.5, 0}), 0.5);
}

TEST(Patterns, OnionSphericalCylindricalBoxedPlanar) {
    EXPECT_NEAR(value_at(make(Kind::Onion), {1.5, 2.0, 0.0}), 0.5, 1e-12);  // radius 2.5
    EXPECT_DOUBLE_EQ(value_at(make(Kind::Spherical), {0.0, 0.6, 0.0}), 0.4);
    EXPECT_DOUBLE_EQ(value_at(make(Kind::Spherical), {0.0, 1.5, 0.0}), 0.0);
    EXPECT_DOUBLE_EQ(value_at(make(Kind::Cylindrical), {0.0, 5.0, 0.25}), 0.75);
    EXPECT_DOUBLE_EQ(value_at(make(Kind::Boxed), {0.5, -0.75, 0.25}), 0.25);
    EXPECT_DOUBLE_EQ(value_at(make(Kind::Planar), {9.0, -0.75, 9.0}), 0.25);
}

TEST(Patterns, RadialTurnsAroundY) {
    // 0.25 + (atan2(x, z) + pi) / 2 pi, wrapped at 1.00001.
    EXPECT_NEAR(value_at(make(Kind::Radial), {0, 0, 1}), 0.75, 1e-12);
    EXPECT_NEAR(value_at(make(Kind::Radial), {1, 0, 0}), 1.0, 1e-12);
    EXPECT_NEAR(value_at(make(Kind::Radial), {0, 0, -1}), 1.25 - 1.00001, 1e-12);
    EXPECT_NEAR(value_at(make(Kind::Radial), {-1, 0, 0}), 0.5, 1e-12);
}

TEST(Patterns, LeopardIsTheSquaredMeanOfSines) {
    const double s = std::sin(1.0) + std::sin(2.0) + std::sin(0.5);
    EXPECT_NEAR(value_at(make(Kind::Leopard), {1.0, 2.0, 0.5}), s * s / 9.0, 1e-12);
}

TEST(Patterns, BlockIndices) {
    CompiledPattern checker(make(Kind::Checker), NoiseGenerator::RangeCorrected);
    ASSERT_TRUE(checker.is_block());
    EXPECT_EQ(checker.block_count(), 2);
    EXPECT_EQ(checker.block_index({0.5, 0.5, 0.5}), 0);
    EXPECT_EQ(checker.block_index({1.5, 0.5, 0.5}), 1);
    EXPECT_EQ(checker.block_index({-0.5, 0.5, 0.5}), 1);
    EXPECT_EQ(checker.block_index({1.5, 1.5, 0.5}), 0);
    EXPECT_DOUBLE_EQ(checker.value({1.5, 0.5, 0.5}), 1.0);  // no frequency step on blocks

    CompiledPattern hexagon(make(Kind::Hexagon), NoiseGenerator::RangeCorrected);
    EXPECT_EQ(hexagon.block_count(), 3);
    // The hexagon around the origin is entry 0; the next ones along +z
    // (centres sqrt(3) apart) are 1 and 2, and the six around it alternate
    // 1 and 2.
    EXPECT_EQ(hexagon.block_index({0, 0, 0.1}), 0);
    EXPECT_EQ(hexagon.block_index({0, 0, std::sqrt(3.0)}), 1);
    EXPECT_EQ(hexagon.block_index({0, 0, 2 * std::sqrt(3.0)}), 2);
    EXPECT_EQ(hexagon.block_index({1.5, 0, std::sqrt(3.0) / 2}), 2);
    EXPECT_EQ(hexagon.block_index({1.5, 0, -std::sqrt(3.0) / 2}), 1);

    sg::Pattern brick_pattern = make(Kind::Brick);
    CompiledPattern brick(brick_pattern, NoiseGenerator::RangeCorrected);
    EXPECT_EQ(brick.block_count(), 2);
    EXPECT_EQ(brick.block_index({4.0, 1.5, 1.0}), 1);  // inside a brick
    EXPECT_EQ(brick.block_index({4.0, 1.5, 2.0}), 0);  // lower course, joint across z (at 2 + mortar / 2 along 4.5)
    EXPECT_EQ(brick.block_index({4.0, 2.8, 2.0}), 0);  // bed joint (y + mortar crosses 3)
    EXPECT_EQ(brick.block_index({7.7, 1.5, 1.0}), 0);  // head joint of the lower course
    EXPECT_EQ(brick.block_index({3.7, 4.5, 1.0}), 0);  // upper course's joint is offset half a brick
    EXPECT_EQ(brick.block_index({7.7, 4.5, 1.0}), 1);

    CompiledPattern cubic(make(Kind::Cubic), NoiseGenerator::RangeCorrected);
    EXPECT_EQ(cubic.block_count(), 6);
    EXPECT_EQ(cubic.block_index({1, 0.2, 0.3}), 0);
    EXPECT_EQ(cubic.block_index({0.2, 1, 0.3}), 1);
    EXPECT_EQ(cubic.block_index({0.2, 0.3, 1}), 2);
    EXPECT_EQ(cubic.block_index({-1, 0.2, 0.3}), 3);
    EXPECT_EQ(cubic.block_index({0.2, -1, 0.3}), 4);
    EXPECT_EQ(cubic.block_index({0.2, 0.3, -1}), 5);

    CompiledPattern square(make(Kind::Square), NoiseGenerator::RangeCorrected);
    EXPECT_EQ(square.block_count(), 4);
    EXPECT_EQ(square.block_index({0.5, 0, 0.5}), 0);
    EXPECT_EQ(square.block_index({0.5, 0, 1.5}), 1);
    EXPECT_EQ(square.block_index({1.5, 0, 1.5}), 2);
    EXPECT_EQ(square.block_index({1.5, 0, 0.5}), 3);

    CompiledPattern triangular(make(Kind::Triangular), NoiseGenerator::RangeCorrected);
    EXPECT_EQ(triangular.block_count(), 6);
    // Along the strip 0 < z < sqrt(3)/2 the triangles run 0, 3, 4, 5, 2, 1.
    const int strip[6] = {0, 3, 4, 5, 2, 1};
    for (int i = 0; i < 6; ++i) EXPECT_EQ(triangular.block_index({0.5 + 0.5 * i, 0, 0.3}), strip[i]) << i;
    EXPECT_FALSE(CompiledPattern(make(Kind::Gradient), NoiseGenerator::RangeCorrected).is_block());
}

TEST(Patterns, WaveTypesShapeTheRamp) {
    sg::Pattern p = make(Kind::Gradient);
    const glm::dvec3 at(0.3, 0, 0);
    p.wave = WaveType::Triangle;
    EXPECT_NEAR(value_at(p, at), 0.6, 1e-12);
    EXPECT_NEAR(value_at(p, {0.8, 0, 0}), 0.4, 1e-12);
    p.wave = WaveType::Sine;
    EXPECT_NEAR(value_at(p, at), (1.0 + std::sin(0.3 * 2 * M_PI)) / 2, 1e-9);
    p.wave = WaveType::Scallop;
    EXPECT_NEAR(value_at(p, at), std::fabs(std::sin(0.15 * 2 * M_PI)), 1e-9);
    p.wave = WaveType::Cubic;
    EXPECT_NEAR(value_at(p, at), 0.09 * (3 - 0.6), 1e-12);
    p.wave = WaveType::Poly;
    p.wave_exponent = 3;
    EXPECT_NEAR(value_at(p, at), 0.027, 1e-12);
}

TEST(Patterns, FrequencyAndPhase) {
    sg::Pattern p = make(Kind::Gradient);
    p.frequency = 3;
    p.phase = 0.25;
    EXPECT_NEAR(value_at(p, {0.3, 0, 0}), 0.15, 1e-4);  // 0.9 + 0.25 wraps at 1.00001
    p.frequency = -1;
    p.phase = 0;
    EXPECT_NEAR(value_at(p, {0.3, 0, 0}), 0.7, 1e-12);
}

TEST(Patterns, ATransformWrittenAfterAWarpActsFirst) {
    // gradient x warp { repeat x } scale 2: the repeat cell is 2 wide.
    sg::Pattern after = make(Kind::Gradient);
    after.warps = {repeat_step({1, 0, 0})};
    after.pattern_from_object = pattern_scale(2.0);
    EXPECT_NEAR(value_at(after, {1.5, 0, 0}), 0.75, 1e-12);
    EXPECT_NEAR(value_at(after, {2.5, 0, 0}), 0.25, 1e-12);
    // gradient x scale 2 warp { repeat x }: the repeat acts first, then the
    // scale, so the ramp reaches only 0.5 in each unit cell.
    sg::Pattern before = make(Kind::Gradient);
    before.warps = {transform_step(pattern_scale(2.0)), repeat_step({1, 0, 0})};
    EXPECT_NEAR(value_at(before, {1.5, 0, 0}), 0.25, 1e-12);
    EXPECT_NEAR(value_at(before, {2.5, 0, 0}), 0.25, 1e-12);
    const CompiledPattern compiled(before, NoiseGenerator::RangeCorrected);
    EXPECT_NEAR(compiled.pattern_point({2.5, 4, 6}).y, 2.0, 1e-12);
}

TEST(Patterns, RepeatFlipMirrorsOddCells) {
    sg::Pattern p = make(Kind::Gradient);
    p.warps = {repeat_step({1, 0, 0}, {1, 0, 0})};
    EXPECT_NEAR(value_at(p, {0.25, 0, 0}), 0.25, 1e-12);
    EXPECT_NEAR(value_at(p, {1.25, 0, 0}), 0.75, 1e-12);
}

TEST(Patterns, BlackHolePullsTowardsItsCentre) {
    sg::Pattern p = make(Kind::Gradient);
    p.warps = {black_hole_step({0, 0, 0}, 1.0)};
    // At 0.5 from the centre: pull (0.5)^2 of the offset towards the centre.
    EXPECT_NEAR(value_at(p, {0.5, 0, 0}), 0.625, 1e-12);
    EXPECT_NEAR(value_at(p, {1.5, 0, 0}), 0.5, 1e-12);  // outside: untouched
}

TEST(Patterns, PatternsWithoutTheirSourceThrow) {
    for (Kind kind : {Kind::Object, Kind::ImagePattern, Kind::PigmentPattern, Kind::Function}) {
        EXPECT_THROW(CompiledPattern(make(kind), NoiseGenerator::RangeCorrected), std::runtime_error);
    }
    sg::Pattern tiling = make(Kind::Tiling);
    tiling.tiling_type = 28;  // POV has 27
    EXPECT_THROW(CompiledPattern(tiling, NoiseGenerator::RangeCorrected), std::runtime_error);
}

TEST(Patterns, PavementOutsidePovsRangesThrows) {
    auto paving = [](int sides, int tiles, int number) {
        sg::Pattern p = make(Kind::Pavement);
        p.pavement_sides = sides;
        p.pavement_tiles = tiles;
        p.pavement_number = number;
        return p;
    };
    EXPECT_NO_THROW(CompiledPattern(paving(4, 6, 35), NoiseGenerator::RangeCorrected));
    EXPECT_NO_THROW(CompiledPattern(paving(6, 5, 22), NoiseGenerator::RangeCorrected));
    EXPECT_NO_THROW(CompiledPattern(paving(3, 6, 12), NoiseGenerator::RangeCorrected));
    for (const sg::Pattern& p : {paving(5, 1, 1), paving(4, 7, 1), paving(6, 6, 1), paving(4, 0, 1), paving(4, 5, 13),
                                 paving(3, 4, 4), paving(6, 3, 0)}) {
        EXPECT_THROW(CompiledPattern(p, NoiseGenerator::RangeCorrected), std::runtime_error);
    }
}

TEST(Patterns, DensityFileWithoutVoxelsIsZero) {
    EXPECT_EQ(value_at(make(Kind::DensityFile), {0.5, 0.5, 0.5}), 0.0);
}

TEST(Patterns, OwnNormals) {
    for (Kind kind :
         {Kind::Bumps, Kind::Dents, Kind::Ripples, Kind::Waves, Kind::Wrinkles, Kind::Quilted, Kind::Facets}) {
        const CompiledPattern pattern(make(kind), NoiseGenerator::RangeCorrected);
        ASSERT_TRUE(pattern.has_own_normal());
        const glm::dvec3 n = pattern.perturb_normal({0, 1, 0}, {0.3, 0.1, 0.7}, 0.5);
        EXPECT_NEAR(glm::length(n), 1.0, 1e-12);
        EXPECT_GT(n.y, 0.0);
    }
    EXPECT_FALSE(CompiledPattern(make(Kind::Gradient), NoiseGenerator::RangeCorrected).has_own_normal());
    // Quilted at a cube's centre does not tilt the normal.
    const CompiledPattern quilted(make(Kind::Quilted), NoiseGenerator::RangeCorrected);
    const glm::dvec3 n = quilted.perturb_normal({0, 1, 0}, {0.5, 0.5, 0.5}, 1.0);
    EXPECT_NEAR(n.y, 1.0, 1e-12);
}

TEST(Patterns, SlopeAndAoi) {
    sg::Pattern slope = make(Kind::Slope);
    slope.vector = {0, 1, 0};
    const CompiledPattern compiled(slope, NoiseGenerator::RangeCorrected);
    PatternContext up;
    up.normal = {0, 1, 0};
    EXPECT_NEAR(compiled.value({0, 0, 0}, up), 1.0, 1e-9);
    PatternContext side;
    side.normal = {1, 0, 0};
    EXPECT_NEAR(compiled.value({0, 0, 0}, side), 0.5, 1e-12);
    const CompiledPattern aoi(make(Kind::Aoi), NoiseGenerator::RangeCorrected);
    PatternContext facing;
    facing.normal = {0, 0, -1};
    facing.ray_direction = {0, 0, 1};
    EXPECT_NEAR(aoi.value({0, 0, 0}, facing), 1.0, 1e-4);
}

// ---------------------------------------------------------------- POV-Ray's values

struct Sample {
    glm::dvec3 point;
    double value;
};

std::vector<Sample> read_reference(const std::string& name) {
    std::ifstream in(std::string(LANCER_SOURCE_DIR) + "/tests/reference/pov/patterns/" + name + ".txt");
    std::vector<Sample> samples;
    std::string line;
    while (std::getline(in, line)) {
        if (line.empty() || line[0] == '#') continue;
        std::istringstream fields(line);
        Sample s;
        fields >> s.point.x >> s.point.y >> s.point.z >> s.value;
        samples.push_back(s);
    }
    return samples;
}

struct ReferenceCase {
    std::string name;
    std::function<sg::Pattern()> build;
    double tolerance;
};

sg::Pattern with(Kind kind, const std::function<void(sg::Pattern&)>& edit) {
    sg::Pattern p = make(kind);
    edit(p);
    return p;
}

// A df3 file committed beside the reference values, read into the
// pattern as the parser reads it (big-endian sizes, then 1, 2 or 4 byte
// voxels divided by their maximum).
sg::Pattern density_file(const std::string& file, int interpolate) {
    std::ifstream in(std::string(LANCER_SOURCE_DIR) + "/tests/reference/pov/patterns/" + file, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    auto byte = [&bytes](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(bytes.at(i))); };
    sg::Pattern p = make(Kind::DensityFile);
    p.file_interpolate = interpolate;
    p.density_size = {int(byte(0) << 8 | byte(1)), int(byte(2) << 8 | byte(3)), int(byte(4) << 8 | byte(5))};
    const std::size_t count = std::size_t(p.density_size.x) * std::size_t(p.density_size.y) * p.density_size.z;
    const std::size_t width = (bytes.size() - 6) / count;
    const double top = width == 4 ? 4294967295.0 : width == 2 ? 65535.0 : 255.0;
    auto voxels = std::make_shared<std::vector<double>>(count);
    for (std::size_t i = 0; i < count; ++i) {
        std::uint32_t v = 0;
        for (std::size_t b = 0; b < width; ++b) v = v << 8 | byte(6 + i * width + b);
        (*voxels)[i] = double(v) / top;
    }
    p.density_voxels = voxels;
    return p;
}

sg::Pattern tiling(int type) {
    sg::Pattern p = make(Kind::Tiling);
    p.tiling_type = type;
    return p;
}

// Pavement as measured: scaled by 0.3 so that the points cover a few
// repeats of each paving.
sg::Pattern pavement(int sides, int tiles, int number, int exterior, int interior, int form) {
    sg::Pattern p = make(Kind::Pavement);
    p.pavement_sides = sides;
    p.pavement_tiles = tiles;
    p.pavement_number = number;
    p.pavement_exterior = exterior;
    p.pavement_interior = interior;
    p.pavement_form = form;
    p.pattern_from_object = pattern_scale(0.3);
    return p;
}

sg::Pattern fractal(Kind kind, int iterations, int exponent = 2) {
    sg::Pattern p = make(kind);
    p.fractal_iterations = iterations;
    p.fractal_exponent = exponent;
    return p;
}

// The scenes of scripts/measure-pov-patterns.sh, built as the parser would.
std::vector<ReferenceCase> reference_cases() {
    constexpr double kExact = 1e-14;  // the same operations in the same order: equal but for printing
    constexpr double kNoise = 1e-13;  // through noise.cpp, which matches POV to the last bits
    constexpr double kColour = 2e-7;  // through a pigment's colour: single precision
    using W = sg::Warp::Kind;
    std::vector<ReferenceCase> cases = {
        {"gradient", [] { return make(Kind::Gradient); }, kExact},
        {"gradient_diagonal",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.vector = {1, 2, -1};
                 p.frequency = 2;
                 p.phase = 0.3;
             });
         },
         kExact},
        {"onion", [] { return make(Kind::Onion); }, kExact},
        {"spherical",
         [] { return with(Kind::Spherical, [](sg::Pattern& p) { p.pattern_from_object = pattern_scale(2); }); },
         kExact},
        {"cylindrical",
         [] { return with(Kind::Cylindrical, [](sg::Pattern& p) { p.pattern_from_object = pattern_scale(2); }); },
         kExact},
        {"boxed", [] { return with(Kind::Boxed, [](sg::Pattern& p) { p.pattern_from_object = pattern_scale(2); }); },
         kExact},
        {"planar", [] { return with(Kind::Planar, [](sg::Pattern& p) { p.pattern_from_object = pattern_scale(2); }); },
         kExact},
        {"radial", [] { return make(Kind::Radial); }, kExact},
        {"radial_frequency",
         [] {
             return with(Kind::Radial, [](sg::Pattern& p) {
                 p.frequency = 3;
                 p.phase = 0.2;
             });
         },
         kExact},
        {"spiral1",
         [] {
             return with(Kind::Spiral1, [](sg::Pattern& p) {
                 p.spiral_arms = 3;
                 p.wave = WaveType::Triangle;
             });
         },
         kExact},
        {"spiral2",
         [] {
             return with(Kind::Spiral2, [](sg::Pattern& p) {
                 p.spiral_arms = 2;
                 p.wave = WaveType::Triangle;
             });
         },
         kExact},
        {"leopard",
         [] { return with(Kind::Leopard, [](sg::Pattern& p) { p.pattern_from_object = pattern_scale(0.3); }); },
         kExact},
        {"marble_plain", [] { return with(Kind::Marble, [](sg::Pattern& p) { p.wave = WaveType::Triangle; }); },
         kExact},
        {"wood_plain", [] { return with(Kind::Wood, [](sg::Pattern& p) { p.wave = WaveType::Triangle; }); }, kExact},
        {"checker", [] { return make(Kind::Checker); }, 0.0},
        {"hexagon", [] { return make(Kind::Hexagon); }, 0.0},
        {"brick", [] { return with(Kind::Brick, [](sg::Pattern& p) { p.pattern_from_object = pattern_scale(0.5); }); },
         0.0},
        {"brick_sized",
         [] {
             return with(Kind::Brick, [](sg::Pattern& p) {
                 p.brick_size = {1, 0.5, 0.7};
                 p.mortar = 0.1;
             });
         },
         0.0},
        {"cubic", [] { return make(Kind::Cubic); }, 0.0},
        {"square", [] { return make(Kind::Square); }, 0.0},
        {"triangular", [] { return make(Kind::Triangular); }, 0.0},
        {"quilted",
         [] {
             return with(Kind::Quilted, [](sg::Pattern& p) {
                 p.quilted_control0 = 0.5;
                 p.quilted_control1 = 0.8;
             });
         },
         kExact},
        {"cells", [] { return with(Kind::Cells, [](sg::Pattern& p) { p.pattern_from_object = pattern_scale(0.7); }); },
         kExact},
        {"crackle", [] { return make(Kind::Crackle); }, kExact},
        {"crackle_form",
         [] {
             return with(Kind::Crackle, [](sg::Pattern& p) {
                 p.crackle_form = {1, 0, 0};
                 p.crackle_metric = 1;
                 p.crackle_offset = 0.1;
             });
         },
         kExact},
        {"crackle_metric3",
         [] {
             return with(Kind::Crackle, [](sg::Pattern& p) {
                 p.crackle_form = {0.5, 0.8, -0.3};
                 p.crackle_metric = 3;
             });
         },
         kExact},
        {"mandel", [] { return fractal(Kind::Mandel, 30); }, kExact},
        {"mandel3", [] { return fractal(Kind::Mandel, 30, 3); }, kExact},
        {"mandel4", [] { return fractal(Kind::Mandel, 30, 4); }, kExact},
        {"mandel5", [] { return fractal(Kind::Mandel, 20, 5); }, kExact},
        {"mandel_colours",
         [] {
             sg::Pattern p = fractal(Kind::Mandel, 30);
             p.exterior_type = 6;
             p.exterior_factor = 0.5;
             p.interior_type = 1;
             p.interior_factor = 2;
             return p;
         },
         kExact},
        {"mandel_types",
         [] {
             sg::Pattern p = fractal(Kind::Mandel, 40);
             p.exterior_type = 3;
             p.exterior_factor = 0.5;
             p.interior_type = 6;
             p.interior_factor = 0.5;
             return p;
         },
         kExact},
        {"julia",
         [] {
             sg::Pattern p = fractal(Kind::Julia, 30);
             p.julia_parameter = {0.3, 0.5};
             return p;
         },
         kExact},
        {"julia4",
         [] {
             sg::Pattern p = fractal(Kind::Julia, 30, 4);
             p.julia_parameter = {0.3, 0.5};
             return p;
         },
         kExact},
        {"magnet1_mandel", [] { return fractal(Kind::Magnet, 30); }, kExact},
        {"magnet1_julia",
         [] {
             sg::Pattern p = fractal(Kind::Magnet, 30);
             p.magnet_julia = true;
             p.julia_parameter = {0.3, 0.2};
             return p;
         },
         kExact},
        {"magnet2_mandel",
         [] {
             sg::Pattern p = fractal(Kind::Magnet, 30);
             p.magnet_type = 2;
             return p;
         },
         kExact},
        {"magnet2_julia",
         [] {
             sg::Pattern p = fractal(Kind::Magnet, 30);
             p.magnet_type = 2;
             p.magnet_julia = true;
             p.julia_parameter = {0.3, 0.2};
             p.interior_type = 1;
             return p;
         },
         kExact},
        {"wave_sine", [] { return with(Kind::Gradient, [](sg::Pattern& p) { p.wave = WaveType::Sine; }); }, kExact},
        {"wave_triangle",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.wave = WaveType::Triangle;
                 p.frequency = 1.5;
             });
         },
         kExact},
        {"wave_scallop", [] { return with(Kind::Gradient, [](sg::Pattern& p) { p.wave = WaveType::Scallop; }); },
         kExact},
        {"wave_cubic", [] { return with(Kind::Gradient, [](sg::Pattern& p) { p.wave = WaveType::Cubic; }); }, kExact},
        {"wave_poly",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.wave = WaveType::Poly;
                 p.wave_exponent = 2.5;
             });
         },
         kExact},
        {"frequency_negative",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.frequency = -1.5;
                 p.phase = 0.25;
             });
         },
         kExact},
        {"warp_repeat",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.warps = {repeat_step({1.5, 0, 0}, {1, 0, 0}, {0.2, 0.3, 0})};
             });
         },
         kExact},
        {"warp_repeat_y",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.vector = {1, 1, 1};
                 p.warps = {repeat_step({0, 0.8, 0}, {1, 1, 0})};
             });
         },
         kExact},
        {"warp_black_hole",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 sg::Warp w = black_hole_step({0.5, 0, 0}, 1.5);
                 w.strength = 1.5;
                 w.falloff = 3;
                 p.warps = {w};
             });
         },
         kExact},
        {"warp_black_hole_inverse",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.vector = {1, 1, 0};
                 sg::Warp w = black_hole_step({0, 0.5, 0}, 2);
                 w.inverse = true;
                 p.warps = {w};
             });
         },
         kExact},
        {"warp_black_hole_repeat",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 sg::Warp w = black_hole_step({0, 0, 0}, 0.7);
                 w.repeat = {2, 2, 2};
                 w.turbulence = {0.5, 0.4, 0.3};
                 w.strength = 0.8;
                 p.warps = {w};
             });
         },
         kExact},
        {"warp_cylindrical",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 sg::Warp w;
                 w.kind = W::Cylindrical;
                 p.warps = {w};
             });
         },
         kExact},
        {"warp_cylindrical_oriented",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 sg::Warp w;
                 w.kind = W::Cylindrical;
                 w.orientation = {0, 1, 0};
                 w.dist_exp = 1;
                 p.warps = {w};
             });
         },
         kExact},
        {"warp_spherical",
         [] {
             return with(Kind::Onion, [](sg::Pattern& p) {
                 sg::Warp w;
                 w.kind = W::Spherical;
                 w.orientation = {1, 1, 0};
                 w.dist_exp = 0.5;
                 p.warps = {w};
             });
         },
         kExact},
        {"warp_toroidal",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.vector = {0, 1, 0};
                 sg::Warp w;
                 w.kind = W::Toroidal;
                 w.major_radius = 2;
                 p.warps = {w};
             });
         },
         kExact},
        {"warp_planar",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 sg::Warp w;
                 w.kind = W::Planar;
                 w.normal = {0, 1, 0};
                 w.distance = 0.3;
                 p.warps = {w};
             });
         },
         kExact},
        {"warp_order_scale_after",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.warps = {repeat_step({1, 0, 0}, {1, 0, 0})};
                 p.pattern_from_object = pattern_scale(2);
             });
         },
         kExact},
        {"warp_order_scale_before",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 p.warps = {transform_step(pattern_scale(2)), repeat_step({1, 0, 0}, {1, 0, 0})};
             });
         },
         kExact},
        {"warp_stack",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 const glm::dmat4 unrotate = glm::rotate(glm::dmat4(1.0), glm::radians(-30.0), glm::dvec3(0, 0, 1));
                 p.warps = {transform_step(unrotate), repeat_step({1.5, 0, 0}),
                            transform_step(glm::translate(glm::dmat4(1.0), glm::dvec3(-0.3))),
                            black_hole_step({0, 0, 0}, 1)};
                 p.pattern_from_object = pattern_scale(1.5);
             });
         },
         kExact},
        // Patterns of noise, and turbulence.
        {"bozo", [] { return make(Kind::Bozo); }, kNoise},
        {"bozo_generator1", [] { return with(Kind::Bozo, [](sg::Pattern& p) { p.noise_generator = 1; }); }, kNoise},
        {"bozo_generator3", [] { return with(Kind::Bozo, [](sg::Pattern& p) { p.noise_generator = 3; }); }, kNoise},
        {"spotted",
         [] { return with(Kind::Spotted, [](sg::Pattern& p) { p.pattern_from_object = pattern_scale(0.4); }); },
         kNoise},
        {"bumps", [] { return make(Kind::Bumps); }, kNoise},
        {"dents", [] { return make(Kind::Dents); }, kNoise},
        {"granite", [] { return make(Kind::Granite); }, kNoise},
        {"granite_generator1", [] { return with(Kind::Granite, [](sg::Pattern& p) { p.noise_generator = 1; }); },
         kNoise},
        {"agate", [] { return make(Kind::Agate); }, kNoise},
        {"agate_turb",
         [] {
             return with(Kind::Agate, [](sg::Pattern& p) {
                 p.agate_turbulence = 0.5;
                 p.octaves = 4;
                 p.omega = 0.6;
                 p.lambda = 2.5;
             });
         },
         kNoise},
        {"marble",
         [] {
             return with(Kind::Marble, [](sg::Pattern& p) {
                 p.turbulence = glm::dvec3(0.5);
                 p.wave = WaveType::Triangle;
             });
         },
         kNoise},
        {"wood",
         [] {
             return with(Kind::Wood, [](sg::Pattern& p) {
                 p.turbulence = glm::dvec3(0.3);
                 p.octaves = 3;
                 p.wave = WaveType::Triangle;
             });
         },
         kNoise},
        {"wrinkles", [] { return make(Kind::Wrinkles); }, kNoise},
        {"wrinkles_generator1", [] { return with(Kind::Wrinkles, [](sg::Pattern& p) { p.noise_generator = 1; }); },
         kNoise},
        {"crackle_solid", [] { return with(Kind::Crackle, [](sg::Pattern& p) { p.crackle_solid = true; }); }, kNoise},
        {"ripples",
         [] {
             return with(Kind::Ripples, [](sg::Pattern& p) {
                 p.frequency = 2;
                 p.phase = 0.1;
             });
         },
         kNoise},
        {"waves", [] { return make(Kind::Waves); }, kNoise},
        {"waves_scaled",
         [] {
             return with(Kind::Waves, [](sg::Pattern& p) {
                 p.pattern_from_object = pattern_scale(0.3);
                 p.frequency = 1.5;
             });
         },
         kNoise},
        {"turbulence_gradient",
         [] { return with(Kind::Gradient, [](sg::Pattern& p) { p.turbulence = glm::dvec3(0.6); }); }, kNoise},
        {"turbulence_onion",
         [] {
             return with(Kind::Onion, [](sg::Pattern& p) {
                 p.turbulence = {0.3, 0.5, 0.1};
                 p.octaves = 3;
                 p.omega = 0.7;
                 p.lambda = 3;
             });
         },
         kNoise},
        {"turbulence_spiral",
         [] {
             return with(Kind::Spiral1, [](sg::Pattern& p) {
                 p.spiral_arms = 2;
                 p.turbulence = glm::dvec3(0.4);
                 p.wave = WaveType::Triangle;
             });
         },
         kNoise},
        // tiling through a pigment's 0..1 grey map: POV's colours are single precision.
        {"tiling1", [] { return tiling(1); }, kColour},
        {"tiling2", [] { return tiling(2); }, kColour},
        {"tiling3", [] { return tiling(3); }, kColour},
        {"tiling4", [] { return tiling(4); }, kColour},
        {"tiling5", [] { return tiling(5); }, kColour},
        {"tiling6", [] { return tiling(6); }, kColour},
        {"tiling7", [] { return tiling(7); }, kColour},
        {"tiling8", [] { return tiling(8); }, kColour},
        {"tiling9", [] { return tiling(9); }, kColour},
        {"tiling10", [] { return tiling(10); }, kColour},
        {"tiling11", [] { return tiling(11); }, kColour},
        {"tiling12", [] { return tiling(12); }, kColour},
        {"tiling13", [] { return tiling(13); }, kColour},
        {"tiling14", [] { return tiling(14); }, kColour},
        {"tiling15", [] { return tiling(15); }, kColour},
        {"tiling16", [] { return tiling(16); }, kColour},
        {"tiling17", [] { return tiling(17); }, kColour},
        {"tiling18", [] { return tiling(18); }, kColour},
        {"tiling19", [] { return tiling(19); }, kColour},
        {"tiling20", [] { return tiling(20); }, kColour},
        {"tiling21", [] { return tiling(21); }, kColour},
        {"tiling22", [] { return tiling(22); }, kColour},
        {"tiling23", [] { return tiling(23); }, kColour},
        {"tiling24", [] { return tiling(24); }, kColour},
        {"tiling25", [] { return tiling(25); }, kColour},
        {"tiling26", [] { return tiling(26); }, kColour},
        {"tiling27", [] { return tiling(27); }, kColour},
        // The Penrose tilings scaled down: points up to 75 from the origin
        // take several deflations.
        {"tiling25_deep",
         [] {
             sg::Pattern p = tiling(25);
             p.pattern_from_object = pattern_scale(0.04);
             return p;
         },
         kColour},
        {"tiling26_deep",
         [] {
             sg::Pattern p = tiling(26);
             p.pattern_from_object = pattern_scale(0.04);
             return p;
         },
         kColour},
        {"tiling27_deep",
         [] {
             sg::Pattern p = tiling(27);
             p.pattern_from_object = pattern_scale(0.04);
             return p;
         },
         kColour},
        // pavement (number_of_sides, number_of_tiles, pattern, exterior,
        // interior, form), through a grey map as tiling.
        {"pavement4_1", [] { return pavement(4, 1, 1, 0, 0, 0); }, kColour},
        {"pavement4_2", [] { return pavement(4, 2, 1, 0, 0, 1); }, kColour},
        {"pavement4_3_2", [] { return pavement(4, 3, 2, 1, 1, 2); }, kColour},
        {"pavement4_4_3", [] { return pavement(4, 4, 3, 2, 2, 0); }, kColour},
        {"pavement4_4_5", [] { return pavement(4, 4, 5, 2, 2, 2); }, kColour},
        {"pavement4_5_7", [] { return pavement(4, 5, 7, 2, 1, 3); }, kColour},
        {"pavement4_5_12", [] { return pavement(4, 5, 12, 1, 0, 1); }, kColour},
        {"pavement4_6_15", [] { return pavement(4, 6, 15, 0, 1, 2); }, kColour},
        {"pavement4_6_34", [] { return pavement(4, 6, 34, 1, 2, 0); }, kColour},
        {"pavement4_6_35", [] { return pavement(4, 6, 35, 2, 0, 3); }, kColour},
        {"pavement3_1", [] { return pavement(3, 1, 1, 0, 0, 0); }, kColour},
        {"pavement3_2", [] { return pavement(3, 2, 1, 1, 1, 1); }, kColour},
        {"pavement3_3", [] { return pavement(3, 3, 1, 2, 2, 2); }, kColour},
        {"pavement3_4_3", [] { return pavement(3, 4, 3, 1, 2, 1); }, kColour},
        {"pavement3_5_4", [] { return pavement(3, 5, 4, 2, 1, 2); }, kColour},
        {"pavement3_6_8", [] { return pavement(3, 6, 8, 1, 0, 0); }, kColour},
        {"pavement3_6_12", [] { return pavement(3, 6, 12, 2, 2, 2); }, kColour},
        {"pavement6_1", [] { return pavement(6, 1, 1, 0, 1, 1); }, kColour},
        {"pavement6_2", [] { return pavement(6, 2, 1, 2, 0, 2); }, kColour},
        {"pavement6_3_2", [] { return pavement(6, 3, 2, 1, 2, 0); }, kColour},
        {"pavement6_4_4", [] { return pavement(6, 4, 4, 2, 0, 1); }, kColour},
        {"pavement6_4_7", [] { return pavement(6, 4, 7, 1, 1, 2); }, kColour},
        {"pavement6_5_8", [] { return pavement(6, 5, 8, 0, 2, 0); }, kColour},
        {"pavement6_5_22", [] { return pavement(6, 5, 22, 2, 1, 2); }, kColour},
        {"tiling_scaled",
         [] {
             sg::Pattern p = tiling(5);
             p.pattern_from_object =
                 pattern_scale(0.4) * glm::rotate(glm::dmat4(1.0), glm::radians(-20.0), glm::dvec3(0, 1, 0));
             return p;
         },
         kColour},
        {"density8", [] { return density_file("density8.df3", 0); }, kExact},
        {"density8_trilinear", [] { return density_file("density8.df3", 1); }, kExact},
        {"density8_tricubic", [] { return density_file("density8.df3", 2); }, kExact},
        {"density16_trilinear", [] { return density_file("density16.df3", 1); }, kExact},
        {"density16_tricubic", [] { return density_file("density16.df3", 2); }, kExact},
        {"density32", [] { return density_file("density32.df3", 0); }, kExact},
        {"density32_tricubic", [] { return density_file("density32.df3", 2); }, kExact},
        {"warp_turbulence",
         [] {
             return with(Kind::Gradient, [](sg::Pattern& p) {
                 sg::Warp w;
                 w.kind = W::Turbulence;
                 w.turbulence = glm::dvec3(0.5);
                 w.octaves = 4;
                 p.warps = {w};
                 p.pattern_from_object = pattern_scale(0.5);
             });
         },
         kNoise},
    };
    return cases;
}

void PrintTo(const ReferenceCase& c, std::ostream* os) {
    *os << c.name;
}

class PovPatternValues : public ::testing::TestWithParam<ReferenceCase> {};

TEST_P(PovPatternValues, MatchPovRay) {
    const ReferenceCase& c = GetParam();
    const std::vector<Sample> samples = read_reference(c.name);
    ASSERT_EQ(samples.size(), 150u) << c.name;
    const CompiledPattern pattern(c.build(), NoiseGenerator::RangeCorrected);
    int mismatches = 0;
    for (const Sample& s : samples) {
        const double ours = pattern.value(s.point);
        // POV's values wrap at 1.00001: a value within that sliver of 0 or 1
        // may land on the other end after a last-bit difference.
        const double difference = std::fabs(ours - s.value);
        const double scale = std::max(1.0, std::fabs(s.value));
        if (difference > c.tolerance * scale && std::fabs(difference - 1.00001) > 1e-6) {
            if (++mismatches <= 5)
                ADD_FAILURE() << c.name << " at (" << s.point.x << ", " << s.point.y << ", " << s.point.z << "): ours "
                              << ours << ", POV " << s.value;
        }
    }
    EXPECT_EQ(mismatches, 0) << c.name;
}

INSTANTIATE_TEST_SUITE_P(Pov, PovPatternValues, ::testing::ValuesIn(reference_cases()),
                         [](const ::testing::TestParamInfo<ReferenceCase>& info) { return info.param.name; });

// crackle keeps the random points around a thread's last few cubes: the
// values must not depend on the order the points are asked in, however
// many cubes the asking moves between (POV's layered stones ask several
// crackle patterns at once).
TEST(Pattern, CrackleValuesDoNotDependOnTheOrderAsked) {
    const CompiledPattern crackle(with(Kind::Crackle,
                                       [](sg::Pattern& p) {
                                           p.crackle_form = {-1, 1, 0};
                                       }),
                                  NoiseGenerator::RangeCorrected);
    std::mt19937 random(17);
    std::uniform_real_distribution<double> coordinate(-6.0, 6.0);
    std::vector<glm::dvec3> points(400);
    for (glm::dvec3& point : points) point = {coordinate(random), coordinate(random), coordinate(random)};
    std::vector<double> in_order;
    for (const glm::dvec3& point : points) in_order.push_back(crackle.value(point));
    std::vector<std::size_t> order(points.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
    std::shuffle(order.begin(), order.end(), random);
    for (const std::size_t i : order) {
        crackle.value(points[i] + glm::dvec3(40.0 * double(i % 13), 0.0, 0.0));  // another cube between
        EXPECT_EQ(crackle.value(points[i]), in_order[i]) << i;
    }
}

}  // namespace
}  // namespace lancer
