// The pieces CompiledPattern is built from: the settings a pattern keeps
// after construction, POV-Ray's pattern functions grouped by family (one
// .cpp each), the warps, and the small helpers they share (internal to the
// pattern files; everything else uses materials/pattern.h).
#pragma once

#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "lancer/scene_graph.h"
#include "materials/noise.h"

namespace lancer::pattern_detail {

// POV's EPSILON (1e-10): the nudges its block and cell patterns add so
// that points exactly on a cell boundary fall on a definite side.
inline constexpr double kPovEpsilon = 1.0e-10;
inline constexpr double kTwoPi = 6.283185307179586476925286766559;

// (int)v as POV writes it, defined for every double: truncated toward 0,
// held inside int's range, 0 for NaN (points far out, or not finite, must
// not be undefined behaviour).
inline int truncated_int(double v) {
    if (!(v == v)) return 0;
    if (v >= 2147483647.0) return 2147483647;
    if (v <= -2147483648.0) return -2147483647 - 1;
    return int(v);
}

// The same for the 64-bit cell counts of the pavings, kept within 2^61 so
// doubling them cannot overflow.
inline std::int64_t truncated_int64(double v) {
    constexpr double kLimit = 2305843009213693952.0;  // 2^61
    if (!(v == v)) return 0;
    if (v >= kLimit) return std::int64_t(1) << 61;
    if (v <= -kLimit) return -(std::int64_t(1) << 61);
    return std::int64_t(v);
}

// POV's cycloidal(): sin(2 pi v) of v's fraction, the fraction rounded
// through 50000ths as POV does, so values agree to the last bit.
inline double cycloidal(double v) {
    if (v >= 0.0) return std::sin(((v - std::floor(v)) * 50000.0) / 50000.0 * kTwoPi);
    return -std::sin(((-(v + std::floor(-v))) * 50000.0) / 50000.0 * kTwoPi);
}

// POV's Triangle_Wave(): 0 -> 1 -> 0 over each unit interval.
inline double triangle_wave(double v) {
    const double offset = v >= 0.0 ? v - std::floor(v) : v + 1.0 + std::floor(std::fabs(v));
    return offset >= 0.5 ? 2.0 * (1.0 - offset) : 2.0 * offset;
}

// POV's COORDINATE_LIMIT: warped points are clamped to it, so that far-off
// points stay finite.
inline constexpr double kCoordinateLimit = 1.0e17;
inline glm::dvec3 clamp_to_coordinate_limit(const glm::dvec3& p) {
    return glm::clamp(p, glm::dvec3(-kCoordinateLimit), glm::dvec3(kCoordinateLimit));
}

// floor(v) as an int, for the cell numbers of the block, cell and warp
// patterns. POV casts with (int), which has no defined value once floor(v)
// leaves int's range (|v| >= 2^31, reached by far points of a finely
// scaled pattern: pattern points go up to 1e17). There the result is
// floor(v) modulo 2^32 (exact: such a double is an integer), so a cell's
// parity and its number modulo 4096 (all the hashes and block patterns
// use) stay those of floor(v). An infinite or NaN v, which no pattern
// point is, gives 0.
inline int floor_to_int(double v) {
    const double f = std::floor(v);
    if (f >= -2147483648.0 && f < 2147483648.0) return int(f);
    if (!std::isfinite(f)) return 0;
    return int(std::uint32_t(std::int64_t(std::fmod(f, 4294967296.0))));
}

// v reduced into [0, period) as POV reduces it (v - floor(v / period) *
// period), which rounds just outside that range when v lies an ulp under a
// multiple of the period or is so large that the product is inexact; then
// the exact remainder (fmod) instead.
inline double wrap_into(double v, double period) {
    double r = v - std::floor(v / period) * period;
    if (r >= 0.0 && r < period) return r;
    r = std::fmod(v, period);
    if (r < 0.0) r += period;
    return r < period ? r : 0.0;  // an ulp under 0 wraps to the period itself: 0
}

// POV's density-style falloff (spherical, cylindrical, boxed, planar):
// 1 at distance 0 falling to 0 at distance 1, and 0 beyond.
inline double density_falloff(double distance) {
    if (distance < 0.0) return 1.0;
    if (distance > 1.0) return 0.0;
    return 1.0 - distance;
}

// POV keeps several pattern parameters in single precision (frequency,
// phase, omega, lambda, ...); the fields below that are float hold them the
// same way, so that values agree with POV's to the last bits. (Held as
// float rather than rounded through double(float(x)): GCC 12.2 at -O2
// drops such round trips when it vectorises neighbouring ones.)

// Classic turbulence's parameters (`turbulence`, `octaves`, `omega`,
// `lambda` written in the pattern, or inside warp { turbulence }).
struct TurbulenceSettings {
    glm::dvec3 amount{0.0};
    int octaves = 6;
    float omega = 0.5f;
    float lambda = 2.0f;
    bool present() const { return amount != glm::dvec3(0.0); }
};

// One warp step, its parameters put the way POV evaluates them.
struct WarpStep {
    sg::Warp::Kind kind = sg::Warp::Kind::Transform;
    glm::dmat4 inner_from_outer{1.0};  // Transform
    TurbulenceSettings turbulence;     // Turbulence
    int repeat_axis = -1;              // Repeat: the axis, its cell width, the offset per cell and
    float repeat_width = 0.0f;         // the sign flips (-1 on the flipped axes, as POV stores them)
    glm::dvec3 repeat_offset{0.0};
    glm::dvec3 repeat_flip{1.0};
    glm::dvec3 center{0.0};  // BlackHole
    double radius = 1.0;
    double falloff = 2.0;
    double strength = 1.0;
    bool inverse = false;
    glm::dvec3 hole_repeat{0.0};
    glm::dvec3 hole_jitter{0.0};
    bool hole_repeats = false;
    bool hole_jitters = false;
    glm::dvec3 orientation{0.0, 0.0, 1.0};  // Cylindrical, Spherical, Toroidal, Planar (unit)
    double dist_exp = 0.0;
    double major_radius = 1.0;
    double plane_offset = 0.0;  // Planar
};

// Throws std::runtime_error when a turbulence's octave amplitudes or
// frequencies (omega^i, lambda^i for i below octaves, in single precision
// as POV keeps them) overflow: POV sums infinities and NaNs then.
void check_turbulence(const TurbulenceSettings& turbulence);
// Throws std::runtime_error for a warp lancer cannot evaluate (a repeat
// width outside single precision, a turbulence that overflows).
WarpStep make_warp_step(const sg::Warp& warp);
// Moves p through one warp step (POV's Warp_EPoint for that step).
void apply_warp(const WarpStep& step, glm::dvec3& p, NoiseGenerator generator);
// Classic turbulence applied to the point (the displacement of DTurbulence
// scaled by the turbulence vector).
glm::dvec3 turbulence_displacement(const glm::dvec3& p, const TurbulenceSettings& turbulence, NoiseGenerator generator);

// Everything the pattern functions read, fixed at construction.
struct PatternSetup {
    sg::Pattern::Kind kind = sg::Pattern::Kind::Gradient;
    NoiseGenerator generator = NoiseGenerator::RangeCorrected;
    TurbulenceSettings turbulence;       // classic turbulence (present() when written)
    glm::dvec3 gradient{1.0, 0.0, 0.0};  // unit
    float agate_turbulence = 1.0f;
    glm::dvec3 brick_size{8.0, 3.0, 4.5};
    float brick_mortar = 0.5f;  // as POV stores it: written minus 2 EPSILON, in single precision
    glm::dvec3 crackle_form{-1.0, 1.0, 0.0};
    double crackle_metric = 2.0;
    double crackle_offset = 0.0;
    bool crackle_solid = false;
    double facets_size = 0.1;
    double facets_coords = 0.0;
    double facets_metric = 2.0;
    int fractal_iterations = 0;
    glm::dvec2 julia_parameter{0.0};
    int fractal_exponent = 2;
    int magnet_type = 1;
    bool magnet_julia = false;
    std::vector<int> binomial;  // row fractal_exponent of Pascal's triangle (general exponents)
    int exterior_type = 1;
    double exterior_factor = 1.0;
    int interior_type = 0;
    double interior_factor = 1.0;
    float quilted_control0 = 1.0f;
    float quilted_control1 = 1.0f;
    int spiral_arms = 1;
    // slope: unit direction (or the point of point_at), the share of slope
    // and altitude, their ranges as (low, high - low), and the altitude
    // direction (unit).
    glm::dvec3 slope_direction{0.0, 1.0, 0.0};
    bool slope_point_at = false;
    double slope_share = 1.0;
    double altitude_share = 0.0;
    glm::dvec2 slope_range{0.0, 0.0};
    glm::dvec2 altitude_range{0.0, 0.0};
    glm::dvec3 altitude_direction{0.0};
    // ripples and waves: the pattern's own frequency and phase (used inside
    // the functions as well as after them) and POV's wave sources.
    float frequency = 1.0f;
    float phase = 0.0f;
    std::vector<glm::dvec3> wave_sources;
    std::vector<double> wave_frequencies;
    // tiling N (1..27); pavement's sides, tiles, pattern, exterior,
    // interior and form (as POV keeps them after parsing).
    int tiling_type = 1;
    int pavement_sides = 3, pavement_tiles = 1, pavement_number = 1;
    int pavement_exterior = 0, pavement_interior = 0, pavement_form = 0;
    // density_file: the voxels (normalised, x fastest), the grid's size
    // and interpolate's value.
    std::shared_ptr<const std::vector<double>> density_voxels;
    glm::ivec3 density_size{0};
    int density_interpolation = 0;
};

// ---- POV's random tables (pattern_random.cpp)
// POV's Hash3d(): a hash of a cell in 0..4095 (each coordinate taken mod 4096).
int pov_hash3d(int ix, int iy, int iz);
// POV's pattern random table (PatternRands, and the identical WarpRands):
// a value in [0, 1) per index.
double pov_pattern_random(std::size_t index);
// POV's Initialize_Waves(): wave sources and frequencies.
void make_wave_sources(int count, NoiseGenerator generator, std::vector<glm::dvec3>& sources,
                       std::vector<double>& frequencies);

// ---- gradient_patterns.cpp
double gradient_pattern(const PatternSetup& s, const glm::dvec3& p);
double onion_pattern(const glm::dvec3& p);
double spherical_pattern(const glm::dvec3& p);
double cylindrical_pattern(const glm::dvec3& p);
double boxed_pattern(const glm::dvec3& p);
double planar_pattern(const glm::dvec3& p);
double radial_pattern(const glm::dvec3& p);
double spiral1_pattern(const PatternSetup& s, const glm::dvec3& p);
double spiral2_pattern(const PatternSetup& s, const glm::dvec3& p);

// ---- block_patterns.cpp: the entry index of each block pattern
int checker_block(const glm::dvec3& p);
int hexagon_block(const glm::dvec3& p);
int brick_block(const PatternSetup& s, const glm::dvec3& p);
int cubic_block(const glm::dvec3& p);
int square_block(const glm::dvec3& p);
int triangular_block(const glm::dvec3& p);

// ---- noise_patterns.cpp
double dents_pattern(const PatternSetup& s, const glm::dvec3& p);
double granite_pattern(const PatternSetup& s, const glm::dvec3& p);
double agate_pattern(const PatternSetup& s, const glm::dvec3& p);
double marble_pattern(const PatternSetup& s, const glm::dvec3& p);
double wood_pattern(const PatternSetup& s, const glm::dvec3& p);
double wrinkles_pattern(const PatternSetup& s, const glm::dvec3& p);
double leopard_pattern(const glm::dvec3& p);
// Own normals: add the perturbation to the (pattern-space) normal.
void bumps_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal);
void dents_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal);
void wrinkles_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal);

// ---- wave_patterns.cpp
double ripples_pattern(const PatternSetup& s, const glm::dvec3& p);
double waves_pattern(const PatternSetup& s, const glm::dvec3& p);
void ripples_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal);
void waves_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal);

// ---- cell_patterns.cpp
double cells_pattern(const glm::dvec3& p);
double crackle_pattern(const PatternSetup& s, const glm::dvec3& p);
// Replaces the normal (facets sets it rather than adding to it).
void facets_normal(const PatternSetup& s, const glm::dvec3& p, glm::dvec3& normal);

// ---- fractal_patterns.cpp (mandel, julia, magnet)
double fractal_pattern(const PatternSetup& s, const glm::dvec3& p);

// ---- tiling_patterns.cpp
// POV's tiling N: the tile's kind and the distance from its edge, in [0, 1].
double tiling_pattern(const PatternSetup& s, const glm::dvec3& p);
// ---- polygon_tilings.cpp: tiling 13 to 24 at (x, z)
double polygon_tiling(int type, double x, double z);
// ---- penrose_tilings.cpp: tiling 25 to 27 at (x, z)
double penrose_tiling(int type, double x, double z);
double quilted_pattern(const PatternSetup& s, const glm::dvec3& p);
void quilted_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal);

// ---- pavement_pattern.cpp
// POV's pavement: 0 inside a tile to 1 on its border.
double pavement_pattern(const PatternSetup& s, const glm::dvec3& p);

// ---- density_pattern.cpp
double density_file_pattern(const PatternSetup& s, const glm::dvec3& p);

// ---- surface_patterns.cpp
// normal and hit_point in the space POV takes them from (world space);
// p, the pattern point, only for the altitude.
double slope_pattern(const PatternSetup& s, const glm::dvec3& p, const glm::dvec3& normal, const glm::dvec3& hit_point);
double aoi_pattern(const glm::dvec3& normal, const glm::dvec3& ray_direction);

}  // namespace lancer::pattern_detail
