// POV-Ray 3.7's solid noise, rebuilt from measurements of POV-Ray itself.
//
// Every number below the structure (the lattice hash tables, the value
// table, the gradients of generator 3, the range constants) was recovered by
// scripts/measure-pov-noise.sh from Debian's povray 3.7.0.10 and lives in
// pov_noise_tables.inc; docs/noise.md tells how. This file only holds the
// structure, and follows POV's order of floating-point operations so that
// the results agree with POV's to the last bit or two, not just to 1e-6.
#include "materials/noise.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <cmath>
#include <cstdint>

namespace lancer {
namespace {

#include "materials/pov_noise_tables.inc"

// POV's smoothstep weight, 3t^2 - 2t^3, written as POV evaluates it.
inline double s_curve(double t) {
    return t * t * (3.0 - 2.0 * t);
}

// --- Generators 1 and 2 (and the vector noise): a lattice of value + gradient
// coefficients. ---

// One axis of the lattice: which cell a coordinate falls in (as POV's hash
// indexes it, 12 bits) and where in the cell it lies. POV rounds negative
// coordinates down with a 1e-10 tolerance (a coordinate within 1e-10 under
// an integer counts as that integer's cell, with a slightly negative offset);
// the noise is continuous there, so this only matters for bit-exactness.
struct LatticeAxis {
    int cell;       // (floor + 10000) & 0xFFF: POV's hash index of the cell
    double offset;  // coordinate - floor, in [0, 1) (or just under 0, see above)
};

// Beyond 2^62 (a turbulence octave's lambda^i times a far point) a double
// is an integer: its cell is the coordinate itself, taken modulo 4096
// exactly, at offset 0. An infinite coordinate counts as cell 0 at offset
// 0; NaN stays NaN (in the offset), so the value shows it.
inline bool lattice_far(double coordinate) {
    return !(std::fabs(coordinate) < 0x1p62);
}

inline double far_cell(double coordinate, double cells) {
    return std::isfinite(coordinate) ? std::fmod(coordinate, cells) : 0.0;
}

inline double far_offset(double coordinate) {
    return std::isnan(coordinate) ? coordinate : 0.0;
}

inline LatticeAxis lattice_axis(double coordinate) {
    if (lattice_far(coordinate)) {
        const auto cell = static_cast<std::int64_t>(far_cell(coordinate, 4096.0));
        return {static_cast<int>((cell + kLatticeHashOrigin) & 0xFFF), far_offset(coordinate)};
    }
    constexpr double kNegativeRoundingTolerance = 1.0e-10;
    // int64 instead of POV's int: the same cells wherever POV's int does not
    // overflow (|coordinate| < 2^31), and defined behaviour beyond.
    const std::int64_t floor_value = coordinate >= 0.0
                                         ? static_cast<std::int64_t>(coordinate)
                                         : static_cast<std::int64_t>(coordinate - (1.0 - kNegativeRoundingTolerance));
    const int cell = static_cast<int>((floor_value + kLatticeHashOrigin) & 0xFFF);
    return {cell, coordinate - static_cast<double>(floor_value)};
}

// The contribution of one corner to one component: its weight times its value
// plus the dot product of its gradient with the offset from the corner. A
// corner's value is half its table entry (measured; halving is exact, so the
// sum is POV's to the bit).
inline double corner_term(int start, double weight, double dx, double dy, double dz) {
    return weight * ((kLatticeValues[start] * 0.5 + kLatticeValues[start + 1] * dx) + kLatticeValues[start + 2] * dy +
                     kLatticeValues[start + 3] * dz);
}

// The weights and offsets of the eight corners around a point.
struct LatticeCell {
    int x, y, z;                            // hash indices of the lower corner
    double fx, fy, fz;                      // offsets from the lower corner
    double w_x0y0, w_x1y0, w_x0y1, w_x1y1;  // products of the x and y weights
    double w_z0, w_z1;                      // the z weights
};

inline LatticeCell lattice_cell(const glm::dvec3& p) {
    const LatticeAxis ax = lattice_axis(p.x), ay = lattice_axis(p.y), az = lattice_axis(p.z);
    const double sx = s_curve(ax.offset), sy = s_curve(ay.offset), sz = s_curve(az.offset);
    const double tx = 1.0 - sx, ty = 1.0 - sy, tz = 1.0 - sz;
    return {ax.cell, ay.cell, az.cell, ax.offset, ay.offset, az.offset, tx * ty, sx * ty, tx * sy, sx * sy, tz, sz};
}

// The start (in kLatticeValues) of the coefficients of each of the cell's
// eight corners, [x][y][z] for the lower (0) or upper (1) corner on each
// axis: POV's hash of the corner's indices (the upper may be 4096, which
// wraps to 0), each table read once.
struct CornerStarts {
    int at[2][2][2];
};

inline CornerStarts corner_starts(const LatticeCell& c) {
    CornerStarts s;
    for (int i = 0; i < 2; ++i) {
        const int x = kLatticeHashX[(c.x + i) & 0xFFF];
        for (int j = 0; j < 2; ++j) {
            const int xy = kLatticeHashY[(x ^ (c.y + j)) & 0xFFF];
            for (int k = 0; k < 2; ++k) s.at[i][j][k] = kLatticeHashZ[(xy ^ (c.z + k)) & 0xFFF];
        }
    }
    return s;
}

// The lattice sum of generators 1 and 2 before POV shifts and clamps it, in
// POV's order of the eight corners.
double lattice_sum(const glm::dvec3& p) {
    const LatticeCell c = lattice_cell(p);
    const CornerStarts s = corner_starts(c);
    const double gx = c.fx - 1.0, gy = c.fy - 1.0, gz = c.fz - 1.0;
#if defined(__SSE2__)
    // The lower and upper corner on x side by side (SSE2: each lane rounds
    // as corner_term does, multiply and add apart), then the eight terms
    // summed one by one in POV's order, so the sum is the scalar one's.
    const __m128d half = _mm_set1_pd(0.5);
    const __m128d dx = _mm_set_pd(gx, c.fx);
    const auto pair = [&](int lower, int upper, double w_lower, double w_upper, double dy, double dz) {
        const double* a = &kLatticeValues[lower];
        const double* b = &kLatticeValues[upper];
        const __m128d a01 = _mm_loadu_pd(a), a23 = _mm_loadu_pd(a + 2);
        const __m128d b01 = _mm_loadu_pd(b), b23 = _mm_loadu_pd(b + 2);
        __m128d term =
            _mm_add_pd(_mm_mul_pd(_mm_unpacklo_pd(a01, b01), half), _mm_mul_pd(_mm_unpackhi_pd(a01, b01), dx));
        term = _mm_add_pd(term, _mm_mul_pd(_mm_unpacklo_pd(a23, b23), _mm_set1_pd(dy)));
        term = _mm_add_pd(term, _mm_mul_pd(_mm_unpackhi_pd(a23, b23), _mm_set1_pd(dz)));
        return _mm_mul_pd(_mm_set_pd(w_upper, w_lower), term);
    };
    const __m128d y0z0 = pair(s.at[0][0][0], s.at[1][0][0], c.w_x0y0 * c.w_z0, c.w_x1y0 * c.w_z0, c.fy, c.fz);
    const __m128d y1z0 = pair(s.at[0][1][0], s.at[1][1][0], c.w_x0y1 * c.w_z0, c.w_x1y1 * c.w_z0, gy, c.fz);
    const __m128d y0z1 = pair(s.at[0][0][1], s.at[1][0][1], c.w_x0y0 * c.w_z1, c.w_x1y0 * c.w_z1, c.fy, gz);
    const __m128d y1z1 = pair(s.at[0][1][1], s.at[1][1][1], c.w_x0y1 * c.w_z1, c.w_x1y1 * c.w_z1, gy, gz);
    alignas(16) double terms[8];
    _mm_store_pd(terms, y0z0);
    _mm_store_pd(terms + 2, y1z0);
    _mm_store_pd(terms + 4, y0z1);
    _mm_store_pd(terms + 6, y1z1);
    double sum = terms[0];
    for (int i = 1; i < 8; ++i) sum += terms[i];
    return sum;
#else
    double sum = corner_term(s.at[0][0][0], c.w_x0y0 * c.w_z0, c.fx, c.fy, c.fz);
    sum += corner_term(s.at[1][0][0], c.w_x1y0 * c.w_z0, gx, c.fy, c.fz);
    sum += corner_term(s.at[0][1][0], c.w_x0y1 * c.w_z0, c.fx, gy, c.fz);
    sum += corner_term(s.at[1][1][0], c.w_x1y1 * c.w_z0, gx, gy, c.fz);
    sum += corner_term(s.at[0][0][1], c.w_x0y0 * c.w_z1, c.fx, c.fy, gz);
    sum += corner_term(s.at[1][0][1], c.w_x1y0 * c.w_z1, gx, c.fy, gz);
    sum += corner_term(s.at[0][1][1], c.w_x0y1 * c.w_z1, c.fx, gy, gz);
    sum += corner_term(s.at[1][1][1], c.w_x1y1 * c.w_z1, gx, gy, gz);
    return sum;
#endif
}

double clamp_unit(double value) {
    if (value < 0.0) return 0.0;
    if (value > 1.0) return 1.0;
    return value;
}

// --- Generator 3: a gradient lattice (zero at its corners) on a grid of 2048
// cells per axis, shifted by a non-integer offset. ---

struct SolidAxis {
    int cell;       // index of the lower corner, 11 bits
    double offset;  // from the lower corner, in [0, 1)
};

inline SolidAxis solid_axis(double coordinate) {
    // The large offset also sets how the coordinate is rounded (to 2^-29 near
    // 1e7), which the measured offset reproduces.
    const double shifted = coordinate + kSolidLatticeOffset;
    if (lattice_far(shifted)) {
        const auto cell = static_cast<std::int64_t>(far_cell(shifted, 2048.0));
        return {static_cast<int>(cell & 2047), far_offset(shifted)};
    }
    const double floor_value = std::floor(shifted);
    return {static_cast<int>(static_cast<std::int64_t>(floor_value) & 2047), shifted - floor_value};
}

inline const double* solid_gradient(int x, int y, int z) {
    const int xy = kSolidHashY[(kSolidHashX[x & 2047] + y) & 2047];
    return &kSolidGradients[((xy + z) & 2047) * 3];
}

inline double solid_corner(const double* g, double dx, double dy, double dz) {
    return dx * g[0] + dy * g[1] + dz * g[2];
}

inline double lerp(double t, double a, double b) {
    return a + t * (b - a);
}

double solid_noise(const glm::dvec3& p) {
    const SolidAxis ax = solid_axis(p.x), ay = solid_axis(p.y), az = solid_axis(p.z);
    const double x0 = ax.offset, y0 = ay.offset, z0 = az.offset;
    const double x1 = x0 - 1.0, y1 = y0 - 1.0, z1 = z0 - 1.0;
    const double sx = s_curve(x0), sy = s_curve(y0), sz = s_curve(z0);
    const int x = ax.cell, y = ay.cell, z = az.cell;

    double a = lerp(sx, solid_corner(solid_gradient(x, y, z), x0, y0, z0),
                    solid_corner(solid_gradient(x + 1, y, z), x1, y0, z0));
    double b = lerp(sx, solid_corner(solid_gradient(x, y + 1, z), x0, y1, z0),
                    solid_corner(solid_gradient(x + 1, y + 1, z), x1, y1, z0));
    const double near_z = lerp(sy, a, b);
    a = lerp(sx, solid_corner(solid_gradient(x, y, z + 1), x0, y0, z1),
             solid_corner(solid_gradient(x + 1, y, z + 1), x1, y0, z1));
    b = lerp(sx, solid_corner(solid_gradient(x, y + 1, z + 1), x0, y1, z1),
             solid_corner(solid_gradient(x + 1, y + 1, z + 1), x1, y1, z1));
    const double far_z = lerp(sy, a, b);
    return clamp_unit(kSolidNoiseMidpoint + lerp(sz, near_z, far_z));
}

// Turbulence's terms for generators 2 and 3 stretch the noise about its
// middle (2n - 0.5); generator 1 uses the noise as it is.
inline double turbulence_term(double noise, NoiseGenerator generator) {
    return generator == NoiseGenerator::Original ? noise : 2.0 * noise - 0.5;
}

// POV keeps a turbulence's omega and lambda in single precision (measured:
// omega 0.7 and lambda 2.5 agree to 1e-16 only when rounded to float first).
inline double as_pov_stores_it(double turbulence_parameter) {
    return static_cast<double>(static_cast<float>(turbulence_parameter));
}

}  // namespace

double pov_noise(const glm::dvec3& p, NoiseGenerator generator) {
    switch (generator) {
    case NoiseGenerator::Perlin: return solid_noise(p);
    case NoiseGenerator::RangeCorrected: {
        double sum = lattice_sum(p);
        sum += kRangeCorrectedShift;
        sum *= kRangeCorrectedScale;
        return clamp_unit(sum);
    }
    case NoiseGenerator::Original:
    default: return clamp_unit(lattice_sum(p) + 0.5);
    }
}

glm::dvec3 pov_dnoise(const glm::dvec3& p, NoiseGenerator /*generator: POV's DNoise has none*/) {
    const LatticeCell c = lattice_cell(p);
    const double gx = c.fx - 1.0, gy = c.fy - 1.0, gz = c.fz - 1.0;
#if defined(__SSE2__)
    // The x and y components share two-lane arithmetic (SSE2: each lane
    // rounds as the scalar code would, multiply and add apart), z is
    // scalar; the sums are POV's, term by term, in POV's order.
    __m128d xy = _mm_setzero_pd();
    double z = 0.0;
    const __m128d half = _mm_set1_pd(0.5);
    const auto add_corner = [&](int start, double weight, double dx, double dy, double dz) {
        const double* v = &kLatticeValues[start];
        const __m128d a01 = _mm_loadu_pd(v), a23 = _mm_loadu_pd(v + 2);
        const __m128d b01 = _mm_loadu_pd(v + 4), b23 = _mm_loadu_pd(v + 6);
        __m128d sum = _mm_add_pd(_mm_mul_pd(_mm_unpacklo_pd(a01, b01), half),
                                 _mm_mul_pd(_mm_unpackhi_pd(a01, b01), _mm_set1_pd(dx)));
        sum = _mm_add_pd(sum, _mm_mul_pd(_mm_unpacklo_pd(a23, b23), _mm_set1_pd(dy)));
        sum = _mm_add_pd(sum, _mm_mul_pd(_mm_unpackhi_pd(a23, b23), _mm_set1_pd(dz)));
        xy = _mm_add_pd(xy, _mm_mul_pd(_mm_set1_pd(weight), sum));
        z += corner_term(start + 8, weight, dx, dy, dz);
    };
#else
    glm::dvec3 result(0.0);
    const auto add_corner = [&](int start, double weight, double dx, double dy, double dz) {
        result.x += corner_term(start, weight, dx, dy, dz);
        result.y += corner_term(start + 4, weight, dx, dy, dz);
        result.z += corner_term(start + 8, weight, dx, dy, dz);
    };
#endif
    const CornerStarts s = corner_starts(c);
    // POV's DNoise visits the corners in this order (round the bottom face,
    // then back round the top one); kept for bit-exact sums.
    add_corner(s.at[0][0][0], c.w_x0y0 * c.w_z0, c.fx, c.fy, c.fz);
    add_corner(s.at[1][0][0], c.w_x1y0 * c.w_z0, gx, c.fy, c.fz);
    add_corner(s.at[1][1][0], c.w_x1y1 * c.w_z0, gx, gy, c.fz);
    add_corner(s.at[0][1][0], c.w_x0y1 * c.w_z0, c.fx, gy, c.fz);
    add_corner(s.at[0][1][1], c.w_x0y1 * c.w_z1, c.fx, gy, gz);
    add_corner(s.at[1][1][1], c.w_x1y1 * c.w_z1, gx, gy, gz);
    add_corner(s.at[1][0][1], c.w_x1y0 * c.w_z1, gx, c.fy, gz);
    add_corner(s.at[0][0][1], c.w_x0y0 * c.w_z1, c.fx, c.fy, gz);
#if defined(__SSE2__)
    alignas(16) double lanes[2];
    _mm_store_pd(lanes, xy);
    return glm::dvec3(lanes[0], lanes[1], z);
#else
    return result;
#endif
}

double pov_turbulence(const glm::dvec3& p, double omega, double lambda, int octaves, NoiseGenerator generator) {
    omega = as_pov_stores_it(omega);
    lambda = as_pov_stores_it(lambda);
    double value = turbulence_term(pov_noise(p, generator), generator);
    // Only the first octave is clamped (measured: later ones can push the sum
    // below 0 for generators 2 and 3).
    if (generator != NoiseGenerator::Original) value = clamp_unit(value);
    double frequency = lambda, amplitude = omega;
    for (int octave = 2; octave <= octaves; ++octave) {
        value += amplitude * turbulence_term(pov_noise(p * frequency, generator), generator);
        frequency *= lambda;
        amplitude *= omega;
    }
    return value;
}

glm::dvec3 pov_dturbulence(const glm::dvec3& p, double omega, double lambda, int octaves, NoiseGenerator generator) {
    omega = as_pov_stores_it(omega);
    lambda = as_pov_stores_it(lambda);
    glm::dvec3 result = pov_dnoise(p, generator);
    double frequency = lambda, amplitude = omega;
    for (int octave = 2; octave <= octaves; ++octave) {
        const glm::dvec3 value = pov_dnoise(p * frequency, generator);
        result.x += amplitude * value.x;
        result.y += amplitude * value.y;
        result.z += amplitude * value.z;
        frequency *= lambda;
        amplitude *= omega;
    }
    return result;
}

}  // namespace lancer
