// CompiledPattern: POV-Ray 3.7's Warp_EPoint + Evaluate_TPat (the point
// through pattern_from_object, the warps from the last written to the
// first and classic turbulence; the pattern function; frequency, phase and
// the wave type) and Perturb_Normal for the patterns with normals of their
// own. The pattern functions live in the *_patterns.cpp files beside this.
#include "materials/pattern.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "materials/pattern_functions.h"

namespace lancer {

using namespace pattern_detail;
using Kind = sg::Pattern::Kind;

namespace {

bool is_block_kind(Kind kind) {
    switch (kind) {
    case Kind::Checker:
    case Kind::Hexagon:
    case Kind::Brick:
    case Kind::Cubic:
    case Kind::Square:
    case Kind::Triangular: return true;
    default: return false;
    }
}

const char* unsupported_name(Kind kind) {
    switch (kind) {
    case Kind::Object: return "object";
    case Kind::ImagePattern: return "image_pattern";
    case Kind::PigmentPattern: return "pigment_pattern";
    case Kind::Function: return "function";
    default: return nullptr;
    }
}

// Row n of Pascal's triangle with the signs of i^k folded in (negative
// where k is 2 or 3 mod 4), so (a + bi)^n is a plain sum of the terms.
std::vector<int> binomial_row(int n) {
    std::vector<long long> row(std::size_t(n) + 1, 1);
    for (int k = 1; k < n; ++k) row[std::size_t(k)] = row[std::size_t(k) - 1] * (n - k + 1) / k;
    std::vector<int> signed_row(row.size());
    for (std::size_t k = 0; k < row.size(); ++k) signed_row[k] = int((k & 2) ? -row[k] : row[k]);
    return signed_row;
}

// POV's limits on pavement: number_of_sides 3, 4 or 6; number_of_tiles
// 1..6 (1..5 for hexagons); pattern 1 to the count of distinct pavings.
void check_pavement(const PatternSetup& s) {
    static const int kinds3[] = {1, 1, 1, 3, 4, 12};
    static const int kinds4[] = {1, 1, 2, 5, 12, 35};
    static const int kinds6[] = {1, 1, 3, 7, 22};
    const int* kinds = s.pavement_sides == 3 ? kinds3 : s.pavement_sides == 4 ? kinds4 : kinds6;
    const int max_tiles = s.pavement_sides == 6 ? 5 : 6;
    if (s.pavement_sides != 3 && s.pavement_sides != 4 && s.pavement_sides != 6)
        throw std::runtime_error("pavement number_of_sides must be 3, 4 or 6, not " + std::to_string(s.pavement_sides));
    if (s.pavement_tiles < 1 || s.pavement_tiles > max_tiles)
        throw std::runtime_error("pavement number_of_tiles must be 1 to " + std::to_string(max_tiles) + ", not " +
                                 std::to_string(s.pavement_tiles));
    const int count = kinds[s.pavement_tiles - 1];
    if (s.pavement_number < 1 || s.pavement_number > count)
        throw std::runtime_error("pavement pattern must be 1 to " + std::to_string(count) + " with " +
                                 std::to_string(s.pavement_tiles) + " tiles of " + std::to_string(s.pavement_sides) +
                                 " sides, not " + std::to_string(s.pavement_number));
}

// mandel, julia and magnet: every sample inside the set runs all the
// iterations, so lancer caps them (POV-Ray caps nothing); and exterior
// types 7 and 8 take the iteration count modulo the factor (7) or the
// factor + 1 (8), as an unsigned int, then divide by the factor: POV
// divides by zero below those factors.
constexpr int kMaxFractalIterations = 100000;
// ripples and waves: global_settings' number_of_waves.
constexpr int kMaxWaves = 100000;

void check_fractal(const PatternSetup& s) {
    if (s.fractal_iterations > kMaxFractalIterations)
        throw std::runtime_error("a fractal pattern's iterations are limited to " +
                                 std::to_string(kMaxFractalIterations) + " (lancer's limit), got " +
                                 std::to_string(s.fractal_iterations));
    const double f = s.exterior_factor;
    if (s.exterior_type == 7 && !(f >= 1.0 && f < 4294967296.0))
        throw std::runtime_error("exterior 7 needs a factor from 1 to 2^32 (the number of bands), got " +
                                 std::to_string(f));
    if (s.exterior_type == 8 && !(f > 0.0 && f + 1.0 < 4294967296.0))
        throw std::runtime_error("exterior 8 needs a factor above 0 and under 2^32 - 1, got " + std::to_string(f));
}

PatternSetup make_setup(const sg::Pattern& pattern, NoiseGenerator generator) {
    PatternSetup s;
    s.kind = pattern.kind;
    s.generator = generator;
    s.turbulence = {pattern.turbulence, pattern.octaves, float(pattern.omega), float(pattern.lambda)};
    check_turbulence(s.turbulence);
    // POV normalises gradient's vector when it reads it.
    const double gradient_length = glm::length(pattern.vector);
    s.gradient = gradient_length > 0.0 ? pattern.vector / gradient_length : pattern.vector;
    s.agate_turbulence = float(pattern.agate_turbulence);
    s.brick_size = pattern.brick_size;
    s.brick_mortar = float(pattern.mortar - 2.0 * kPovEpsilon);
    s.crackle_form = pattern.crackle_form;
    s.crackle_metric = pattern.crackle_metric;
    s.crackle_offset = pattern.crackle_offset;
    s.crackle_solid = pattern.crackle_solid;
    s.facets_size = pattern.facets_size;
    s.facets_coords = pattern.facets_coords;
    s.facets_metric = pattern.facets_metric;
    s.fractal_iterations = pattern.fractal_iterations;
    s.julia_parameter = pattern.julia_parameter;
    s.fractal_exponent = pattern.fractal_exponent;
    s.magnet_type = pattern.magnet_type;
    s.magnet_julia = pattern.magnet_julia;
    s.exterior_type = pattern.exterior_type;
    s.exterior_factor = pattern.exterior_factor;
    s.interior_type = pattern.interior_type;
    s.interior_factor = pattern.interior_factor;
    s.quilted_control0 = float(pattern.quilted_control0);
    s.quilted_control1 = float(pattern.quilted_control1);
    s.spiral_arms = pattern.spiral_arms;
    s.frequency = float(pattern.frequency);
    s.phase = float(pattern.phase);
    s.tiling_type = pattern.tiling_type;
    s.pavement_sides = pattern.pavement_sides;
    s.pavement_tiles = pattern.pavement_tiles;
    s.pavement_number = pattern.pavement_number;
    // POV keeps these modulo 3 (form modulo 4 with four sides, else 3).
    s.pavement_exterior = pattern.pavement_exterior % 3;
    s.pavement_interior = pattern.pavement_interior % 3;
    s.pavement_form = pattern.pavement_form % (pattern.pavement_sides == 4 ? 4 : 3);
    s.density_voxels = pattern.density_voxels;
    s.density_size = pattern.density_size;
    s.density_interpolation = pattern.file_interpolate;

    if (s.kind == Kind::Mandel || s.kind == Kind::Julia) {
        if (s.fractal_exponent < 2 || s.fractal_exponent > 33)
            throw std::runtime_error("mandel/julia exponent must be 2..33, not " + std::to_string(s.fractal_exponent));
        s.binomial = binomial_row(s.fractal_exponent);
    }
    if (s.kind == Kind::Tiling && (s.tiling_type < 1 || s.tiling_type > 27))
        throw std::runtime_error("tiling number must be 1 to 27, not " + std::to_string(s.tiling_type));
    if (s.kind == Kind::Pavement) check_pavement(s);
    if (s.kind == Kind::Magnet && s.magnet_type != 1 && s.magnet_type != 2)
        throw std::runtime_error("magnet type must be 1 or 2, not " + std::to_string(s.magnet_type));
    if (s.kind == Kind::Mandel || s.kind == Kind::Julia || s.kind == Kind::Magnet) check_fractal(s);

    if (s.kind == Kind::Slope) {
        // POV's reading of slope { direction, lo, hi altitude <a>, lo, hi }:
        // unit vectors, their lengths as the shares of slope and altitude,
        // and the ranges as (low, high - low) (none when high equals low).
        s.slope_point_at = pattern.slope_point_at;
        const double slope_length = s.slope_point_at ? 1.0 : glm::length(pattern.vector);
        const double altitude_length =
            (s.slope_point_at || !pattern.slope_has_altitude) ? 0.0 : glm::length(pattern.slope_altitude);
        s.slope_direction = (s.slope_point_at || slope_length == 0.0) ? pattern.vector : pattern.vector / slope_length;
        s.altitude_direction =
            altitude_length == 0.0 ? pattern.slope_altitude : pattern.slope_altitude / altitude_length;
        const double total = slope_length + altitude_length;
        if (total == 0.0) throw std::runtime_error("slope: zero length for both slope and altitude");
        s.slope_share = slope_length / total;
        s.altitude_share = 1.0 - s.slope_share;
        auto range = [](const glm::dvec2& lo_hi) {
            if (lo_hi.y != 0.0 && lo_hi.y == lo_hi.x) return glm::dvec2(0.0);
            return glm::dvec2(lo_hi.x, lo_hi.y - lo_hi.x);
        };
        s.slope_range = range(pattern.slope_range);
        s.altitude_range = range(pattern.altitude_range);
    }

    if (s.kind == Kind::Ripples || s.kind == Kind::Waves) {
        // Every sample sums every wave, and each is stored: lancer caps the
        // count (POV-Ray caps nothing).
        if (pattern.number_of_waves > kMaxWaves)
            throw std::runtime_error("number_of_waves is limited to " + std::to_string(kMaxWaves) +
                                     " (lancer's limit), got " + std::to_string(pattern.number_of_waves));
        make_wave_sources(std::max(pattern.number_of_waves, 1), generator, s.wave_sources, s.wave_frequencies);
    }
    return s;
}

}  // namespace

// The pattern with another kind: a value source keeps the transforms,
// warps and waves and replaces the function.
static sg::Pattern with_kind(sg::Pattern pattern, Kind kind) {
    pattern.kind = kind;
    return pattern;
}

struct CompiledPattern::State {
    PatternSetup setup;
    CompiledPattern::ValueSource source;  // replaces the pattern function when set
    bool source_gives_blocks = false;     // source is a list pattern's block index
    glm::dmat4 pattern_from_object{1.0};
    std::vector<WarpStep> warps;  // in the order they act: the last written first
    // Classic turbulence moves the point before every pattern function but
    // marble's and wood's, which take it on their value.
    bool turbulence_on_point = false;
    // Block patterns and quilted skip POV's frequency step unless a
    // frequency other than 1 is written (POV sets theirs to 0).
    bool apply_frequency = true;
    sg::WaveType wave = sg::WaveType::Ramp;
    float wave_exponent = 1.0f;  // single precision, as POV keeps it
    // Normals to and from pattern space through the transforms alone
    // (POV's Warp_Normal / UnWarp_Normal skip the other warps).
    glm::dmat3 normal_to_pattern{1.0};
    glm::dmat3 normal_from_pattern{1.0};
};

CompiledPattern::CompiledPattern(const sg::Pattern& pattern, NoiseGenerator global_generator, ValueSource source)
    : CompiledPattern(with_kind(pattern, Kind::Gradient), global_generator) {
    m_state->source = std::move(source);
}

CompiledPattern::CompiledPattern(const sg::Pattern& pattern, NoiseGenerator global_generator, BlockSource source)
    : CompiledPattern(with_kind(pattern, Kind::Gradient), global_generator) {
    m_state->source = std::move(source.index);
    m_state->source_gives_blocks = true;
}

CompiledPattern::CompiledPattern(const sg::Pattern& pattern, NoiseGenerator global_generator)
    : m_state(std::make_unique<State>()) {
    if (const char* name = unsupported_name(pattern.kind))
        throw std::runtime_error(std::string(name) + " is not supported yet");
    const NoiseGenerator generator = (pattern.noise_generator >= 1 && pattern.noise_generator <= 3)
                                         ? NoiseGenerator(pattern.noise_generator)
                                         : global_generator;
    State& st = *m_state;
    st.setup = make_setup(pattern, generator);
    st.pattern_from_object = pattern.pattern_from_object;
    glm::dmat3 points_linear(pattern.pattern_from_object);
    for (auto it = pattern.warps.rbegin(); it != pattern.warps.rend(); ++it) {
        st.warps.push_back(make_warp_step(*it));
        if (it->kind == sg::Warp::Kind::Transform) points_linear = glm::dmat3(it->inner_from_outer) * points_linear;
    }
    st.turbulence_on_point =
        st.setup.turbulence.present() && pattern.kind != Kind::Marble && pattern.kind != Kind::Wood;
    st.apply_frequency = pattern.frequency != 0.0;
    if ((is_block_kind(pattern.kind) || pattern.kind == Kind::Quilted) && pattern.frequency == 1.0)
        st.apply_frequency = false;
    st.wave = pattern.wave;
    // POV raises the value (in [0, 1]) to any exponent: a negative one
    // makes 0 infinite, past every map, and the normals' slopes NaN.
    if (pattern.wave == sg::WaveType::Poly && !(pattern.wave_exponent >= 0.0))
        throw std::runtime_error("poly_wave's exponent must not be negative (0 raised to it is infinite), got " +
                                 std::to_string(pattern.wave_exponent));
    st.wave_exponent = float(pattern.wave_exponent);
    st.normal_to_pattern = glm::transpose(glm::inverse(points_linear));
    st.normal_from_pattern = glm::transpose(points_linear);
}

CompiledPattern::~CompiledPattern() = default;
CompiledPattern::CompiledPattern(CompiledPattern&&) noexcept = default;
CompiledPattern& CompiledPattern::operator=(CompiledPattern&&) noexcept = default;

glm::dvec3 CompiledPattern::pattern_point(const glm::dvec3& object_point) const {
    const State& st = *m_state;
    glm::dvec3 p(st.pattern_from_object * glm::dvec4(object_point, 1.0));
    // POV clamps the point to its coordinate limit after the last warp;
    // lancer after each, so that no warp meets an infinite point (the
    // same points wherever the warps stay within the limit).
    for (const WarpStep& step : st.warps) {
        apply_warp(step, p, st.setup.generator);
        p = clamp_to_coordinate_limit(p);
    }
    if (st.turbulence_on_point) p += turbulence_displacement(p, st.setup.turbulence, st.setup.generator);
    return clamp_to_coordinate_limit(p);
}

namespace {

// The pattern function at a pattern-space point (POV's Evaluate_TPat
// before frequency).
double raw_value(const PatternSetup& s, const glm::dvec3& p, const PatternContext& context) {
    switch (s.kind) {
    case Kind::Agate: return agate_pattern(s, p);
    case Kind::Aoi: return aoi_pattern(context.normal, context.ray_direction);
    case Kind::Boxed: return boxed_pattern(p);
    case Kind::Brick: return brick_block(s, p);
    case Kind::Bozo:
    case Kind::Spotted:
    case Kind::Bumps: return pov_noise(p, s.generator);
    case Kind::Cells: return cells_pattern(p);
    case Kind::Checker: return checker_block(p);
    case Kind::Crackle: return crackle_pattern(s, p);
    case Kind::Cubic: return cubic_block(p);
    case Kind::Cylindrical: return cylindrical_pattern(p);
    case Kind::DensityFile: return density_file_pattern(s, p);
    case Kind::Tiling: return tiling_pattern(s, p);
    case Kind::Pavement: return pavement_pattern(s, p);
    case Kind::Dents: return dents_pattern(s, p);
    // facets is a normal only; as a value POV would refuse it. 0 keeps a
    // pigment usable.
    case Kind::Facets: return 0.0;
    case Kind::Mandel:
    case Kind::Julia:
    case Kind::Magnet: return fractal_pattern(s, p);
    case Kind::Gradient: return gradient_pattern(s, p);
    case Kind::Granite: return granite_pattern(s, p);
    case Kind::Hexagon: return hexagon_block(p);
    case Kind::Leopard: return leopard_pattern(p);
    case Kind::Marble: return marble_pattern(s, p);
    case Kind::Onion: return onion_pattern(p);
    case Kind::Planar: return planar_pattern(p);
    case Kind::Quilted: return quilted_pattern(s, p);
    case Kind::Radial: return radial_pattern(p);
    case Kind::Ripples: return ripples_pattern(s, p);
    case Kind::Slope: return slope_pattern(s, p, context.normal, context.hit_point);
    case Kind::Spherical: return spherical_pattern(p);
    case Kind::Spiral1: return spiral1_pattern(s, p);
    case Kind::Spiral2: return spiral2_pattern(s, p);
    case Kind::Square: return square_block(p);
    case Kind::Triangular: return triangular_block(p);
    case Kind::Waves: return waves_pattern(s, p);
    case Kind::Wood: return wood_pattern(s, p);
    case Kind::Wrinkles: return wrinkles_pattern(s, p);
    default: return 0.0;  // the kinds the constructor refuses
    }
}

}  // namespace

double CompiledPattern::value(const glm::dvec3& object_point, const PatternContext& context) const {
    return value_at_pattern_point(pattern_point(object_point), context);
}

double CompiledPattern::value_at_pattern_point(const glm::dvec3& point, const PatternContext& context) const {
    const State& st = *m_state;
    // Values that grow with the point (gradient, marble, wood, spirals) or
    // with a turbulence's amount are held to the coordinate limit, as the
    // point is: beyond it an infinity would become NaN in the frequency
    // step. (A NaN passes, so that a bug shows.)
    const double raw = st.source ? st.source(point, context) : raw_value(st.setup, point, context);
    double v = std::clamp(raw, -kCoordinateLimit, kCoordinateLimit);
    if (st.apply_frequency) {
        // POV wraps at 1.00001, not 1, so that a value of exactly 1 (the end
        // of a ramp) keeps the top of the map.
        v = std::fmod(v * st.setup.frequency + st.setup.phase, 1.00001);
    }
    if (v < 0.0) v -= std::floor(v);
    switch (st.wave) {
    case sg::WaveType::Ramp: break;
    case sg::WaveType::Triangle: v = triangle_wave(v); break;
    case sg::WaveType::Sine: v = (1.0 + cycloidal(v)) * 0.5; break;
    case sg::WaveType::Scallop: v = std::fabs(cycloidal(v * 0.5)); break;
    case sg::WaveType::Cubic: v = v * v * (-2.0 * v + 3.0); break;
    case sg::WaveType::Poly: v = std::pow(v, st.wave_exponent); break;
    }
    return v;
}

bool CompiledPattern::is_block() const {
    return is_block_kind(m_state->setup.kind);
}

int CompiledPattern::block_count() const {
    switch (m_state->setup.kind) {
    case Kind::Checker:
    case Kind::Brick: return 2;
    case Kind::Hexagon: return 3;
    case Kind::Square: return 4;
    case Kind::Cubic:
    case Kind::Triangular: return 6;
    default: return 0;
    }
}

int CompiledPattern::block_index(const glm::dvec3& object_point) const {
    const PatternSetup& s = m_state->setup;
    const glm::dvec3 p = pattern_point(object_point);
    if (m_state->source_gives_blocks) return int(m_state->source(p, {}));
    switch (s.kind) {
    case Kind::Checker: return checker_block(p);
    case Kind::Hexagon: return hexagon_block(p);
    case Kind::Brick: return brick_block(s, p);
    case Kind::Cubic: return cubic_block(p);
    case Kind::Square: return square_block(p);
    case Kind::Triangular: return triangular_block(p);
    default: return 0;
    }
}

bool CompiledPattern::has_own_normal() const {
    switch (m_state->setup.kind) {
    case Kind::Bumps:
    case Kind::Dents:
    case Kind::Ripples:
    case Kind::Waves:
    case Kind::Wrinkles:
    case Kind::Quilted:
    case Kind::Facets: return true;
    default: return false;
    }
}

glm::dvec3 CompiledPattern::perturb_normal(const glm::dvec3& object_normal, const glm::dvec3& object_point,
                                           double amount) const {
    const State& st = *m_state;
    const PatternSetup& s = st.setup;
    // Perturbed in pattern space, so that scaling a pattern scales its bumps.
    glm::dvec3 n = glm::normalize(st.normal_to_pattern * glm::normalize(object_normal));
    const float bump_size = float(amount);  // single precision, as POV keeps it
    const glm::dvec3 p = pattern_point(object_point);
    switch (s.kind) {
    case Kind::Bumps: bumps_normal(s, p, bump_size, n); break;
    case Kind::Dents: dents_normal(s, p, bump_size, n); break;
    case Kind::Ripples: ripples_normal(s, p, bump_size, n); break;
    case Kind::Waves: waves_normal(s, p, bump_size, n); break;
    case Kind::Wrinkles: wrinkles_normal(s, p, bump_size, n); break;
    case Kind::Quilted: quilted_normal(s, p, bump_size, n); break;
    case Kind::Facets: facets_normal(s, p, n); break;
    default: return glm::normalize(object_normal);
    }
    const glm::dvec3 back = st.normal_from_pattern * n;
    const double length = glm::length(back);
    return length > 0.0 ? back / length : glm::normalize(object_normal);
}

namespace {
glm::dvec3 unit_or(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double length = glm::length(v);
    return length > 0.0 && std::isfinite(length) ? v / length : fallback;
}
}  // namespace

glm::dvec3 CompiledPattern::normal_to_pattern_space(const glm::dvec3& normal) const {
    return unit_or(m_state->normal_to_pattern * normal, normal);
}

glm::dvec3 CompiledPattern::normal_from_pattern_space(const glm::dvec3& normal) const {
    return unit_or(m_state->normal_from_pattern * normal, normal);
}

}  // namespace lancer
