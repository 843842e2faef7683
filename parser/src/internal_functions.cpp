// POV-Ray's internal functions (see lancer/internal_functions.h). The
// formulas are POV-Ray 3.7's (source/backend/vm/fnintern.cpp, read for the
// facts; the comments in functions.inc name the parameters), including its
// quirks, each marked "POV:" where it is one; tests/reference/pov/
// internal_functions.txt holds POV's own values they are checked against.
#include "lancer/internal_functions.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <string>
#include <utility>

#include "lancer/function.h"

namespace lancer::sg {
namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kTwoPi = 2.0 * kPi;
constexpr double kRadiansPerDegree = kPi / 180.0;
constexpr double kSqrt2 = 1.41421356237309504880;
constexpr double kSqrt3 = 1.73205080756887729353;

// The parameters after x, y, z of each internal function, by number.
constexpr int kParameterCounts[kLastInternalFunction + 1] = {
    5, 5, 5, 5, 2,  2, 5, 4, 2, 1, 4, 1, 1, 1, 1, 6, 6, 3, 1, 4,  // 0-19
    3, 6, 1, 1, 10, 7, 7, 1, 1, 6, 1, 3, 4, 3, 6, 1, 1, 4, 1, 6,  // 20-39
    5, 1, 1, 1, 4,  1, 3, 0, 1, 1, 7, 5, 6, 1, 1, 1, 3, 0, 6, 6,  // 40-59
    4, 1, 5, 4, 6,  1, 4, 7, 2, 0, 2, 3, 1, 1, 2, 6, 0, 0, 1,     // 60-78
};

// Loops whose length a parameter sets (octaves, tubes) stop here, so that a
// wild parameter cannot hang the render; POV's own uses stay far below.
constexpr double kMaxRepetitions = 1000.0;

// An internal function's inputs: the point and its parameters, 0 where the
// caller passed fewer.
constexpr int kArgumentSlots = 13;
struct Arguments {
    double x, y, z;
    double p[kArgumentSlots - 3];
};
static_assert(sizeof(Arguments) == kArgumentSlots * sizeof(double));

// POV's C cast of a parameter to int, made safe where C's is undefined
// (out of range: 0, which is what x86 gives once masked with & 3).
int truncated(double value) {
    return std::fabs(value) < 2147483647.0 ? int(value) : 0;
}

// The noise generator a parameter names, as POV's Noise reads it: 2 range
// corrected, 3 Perlin, anything else (0 and 1) the original.
int noise_generator(double parameter) {
    const int bits = truncated(parameter) & 3;
    return bits == 0 ? 1 : bits;
}

double noise(const FunctionNatives* natives, const glm::dvec3& p, int generator) {
    if (!natives) throw FunctionError("POV-Ray's noise functions need the renderer's noise");
    return natives->noise(p, generator);
}

// POV's clamp min(limit, max(value, -limit)), which for a negative limit
// gives the limit itself.
double limited(double value, double limit) {
    return std::min(limit, std::max(value, -limit));
}

// Most algebraic surfaces: the polynomial r times the field strength,
// limited to ±10 so that the isosurface's gradient stays bounded.
double field(double strength, double r) {
    return limited(strength * r, 10.0);
}

// The point in the plane of a `_2d` curve. With a positive "SOR switch" the
// curve (drawn in x-y) is swept around the y axis: x becomes the distance
// from the axis less the offset, then (x, y) turns by the angle.
struct CurvePoint {
    double x, y;    // the point in the curve's plane
    double x2, y2;  // their squares
};

CurvePoint curve_point(const Arguments& a, double sor_switch, double offset, double angle_degrees) {
    CurvePoint c{a.x, a.y, a.x * a.x, a.y * a.y};
    if (sor_switch > 0.0) {
        const double radial = std::sqrt(c.x2 + a.z * a.z) - offset;
        const double angle = angle_degrees * kRadiansPerDegree;
        if (angle != 0.0) {
            c.x = radial * std::cos(angle) - a.y * std::sin(angle);
            c.y = radial * std::sin(angle) + a.y * std::cos(angle);
        } else {
            c.x = radial;
        }
        c.x2 = c.x * c.x;
        c.y2 = c.y * c.y;
    }
    return c;
}

// The three ellipsoids f_cross_ellipsoids, f_flange_cover,
// f_isect_ellipsoids and f_spikes combine: Gaussian blobs stretched along x,
// y and z in turn (p0 the eccentricity, p1 the inverse size).
struct Ellipsoids {
    double along_z, along_y, along_x;
};

Ellipsoids ellipsoids(const Arguments& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    const double e = a.p[0], k = a.p[1];
    return {std::exp(-(x2 * e + y2 * e + z2) * k), std::exp(-(x2 * e + y2 + z2 * e) * k),
            std::exp(-(x2 + y2 * e + z2 * e) * k)};
}

// The cross section f_helix1, f_helix2 and f_spiral share, of offsets (u, v)
// from the tube's centre: 1 a circle, 0 a square, else the superellipse of
// exponent 2 / shape. `exponent_of_sum` is POV's exponent of the sum in the
// superellipse case (shape / 2 for the helices, 1 / exponent for f_spiral:
// the same number, written as POV writes each).
double cross_section(double u, double v, double shape, double exponent_of_sum) {
    if (shape == 1.0) return std::sqrt(u * u + v * v);
    if (shape == 0.0) return std::max(std::fabs(u), std::fabs(v));
    const double exponent = 2.0 / shape;
    return std::pow(std::pow(std::fabs(u), exponent) + std::pow(std::fabs(v), exponent), exponent_of_sum);
}

[[gnu::always_inline]] inline double algebraic_cylinder(int number, const Arguments& a) {
    const CurvePoint c = curve_point(a, a.p[2], a.p[3], a.p[4]);
    const double x = c.x, y = c.y, x2 = c.x2, y2 = c.y2;
    switch (number) {
    case 0: return -limited(a.p[0] * -(x2 * std::fabs(x) - x2 + y2), a.p[1]);
    case 1: return limited(a.p[0] * -(2 * x2 * x2 - 3 * x2 * y + y2 - 2 * y2 * y + y2 * y2), a.p[1]);
    case 2: return limited(a.p[0] * -(x2 * x2 + x2 * y2 - 2 * x2 * y - x * y2 + y2), a.p[1]);
    default: return limited(a.p[0] * -(x2 * x2 + y2 * y2 + 2 * x2 * y2 + 3 * x2 * y - y2 * y), a.p[1]);
    }
}

double boy_surface(const Arguments& a) {
    const double x = a.x, y = a.y, z = a.z, x2 = x * x, y2 = y * y, z2 = z * z;
    const double w = 1 - z, q = x2 + y2;
    const double r =
        64 * w * w * w * z2 * z - 48 * w * w * z2 * (3 * x2 + 3 * y2 + 2 * z2) +
        12 * w * z * (27 * q * q - 24 * z2 * q + 36 * kSqrt2 * y * z * (y2 - 3 * x2) + 4 * z2 * z2) +
        (9 * x2 + 9 * y2 - 2 * z2) * (-81 * q * q - 72 * z2 * q + 108 * kSqrt2 * x * z * (x2 - 3 * y2) + 4 * z2 * z2);
    return field(a.p[0], a.p[1] * r);
}

double comma(Arguments a) {
    const double s = a.p[0];
    if (a.x == 0.0 && a.z == 0.0) a.x = 0.0001;  // POV: keeps atan2 off the origin
    const double angle = std::atan2(a.z, a.x);
    const double around = std::sqrt((a.x + s * 0.25) * (a.x + s * 0.25) + a.z * a.z);
    const double tail = std::min(
        a.z, std::cos(angle * 0.5) * s * 0.5 - std::sqrt((around - s * 0.75) * (around - s * 0.75) + a.y * a.y));
    const double head = s * 0.5 - std::sqrt((a.x - s * 0.5) * (a.x - s * 0.5) + a.z * a.z + a.y * a.y);
    return -std::max(tail, head);
}

double dupin_cyclid(const Arguments& a) {
    const double x = a.x, y = a.y, x2 = x * x, y2 = y * y, z2 = a.z * a.z;
    const double inversion2 = a.p[5] * a.p[5], minor2 = a.p[2] * a.p[2], dy2 = a.p[4] * a.p[4];
    const double dx2 = a.p[3] * a.p[3], major2 = a.p[1] * a.p[1];
    const double c1 = minor2 - dy2 - (a.p[3] + a.p[1]) * (a.p[3] + a.p[1]);
    const double c2 = minor2 - dy2 - (a.p[3] - a.p[1]) * (a.p[3] - a.p[1]);
    const double r =
        -(c1 * c2 * (x2 * x2 + y2 * y2 + z2 * z2) + 2 * (c1 * c2 * (x2 * y2 + x2 * z2 + y2 * z2)) +
          2 * inversion2 *
              ((-dy2 - dx2 + minor2 + major2) * (2 * x * a.p[3] + 2 * y * a.p[4] - inversion2) -
               4 * a.p[4] * minor2 * y) *
              (x2 + y2 + z2) +
          4 * inversion2 * inversion2 * (a.p[3] * x + a.p[4] * y) * (-inversion2 + a.p[4] * y + a.p[3] * x) +
          4 * inversion2 * inversion2 * major2 * y2 + inversion2 * inversion2 * inversion2 * inversion2);
    return field(a.p[0], r);
}

double enneper(const Arguments& a) {
    const double x2 = a.x * a.x, y2 = a.y * a.y, z2 = a.z * a.z;
    // POV: z is kept off 0 by clamping |z| < 0.2 to +0.2 (after squaring),
    // and its integer divisions 2/3, 1/4, 8/9 and 2/9 are 0, dropping the
    // terms they scale.
    const double z = std::fabs(a.z) < 0.2 ? 0.2 : a.z;
    const double u = (y2 - x2) / (2 * z) + 2 * z2 / 9;
    const double v = (y2 - x2) / (4 * z);
    return field(a.p[0], -(u * u * u - 6 * v * v));
}

double helical_torus(Arguments a) {
    const double* p = a.p;
    const double distance_from_axis = std::sqrt(a.x * a.x + a.z * a.z);
    if (a.x == 0.0 && a.z == 0.0) a.x = 0.000001;
    const double around = std::atan2(a.x, a.z);
    const double in_tube = std::sqrt((distance_from_axis - p[0]) * (distance_from_axis - p[0]) + a.y * a.y);
    double winding = std::fmod(around * p[1] + std::atan2(distance_from_axis - p[0], a.y) * p[2], kTwoPi);
    if (winding < 0) winding += kTwoPi;
    double groove = std::atan2((winding - kPi) * p[8], in_tube - p[5]);
    groove = std::cos(groove * p[7] + around * p[9]) * p[3] + p[4];
    const double column = p[4] + p[5] - p[0] - distance_from_axis;
    winding -= kPi;
    groove -= std::min(std::sqrt((in_tube - p[5]) * (in_tube - p[5]) + winding * winding * p[6]), in_tube + p[5]);
    return -std::max(column, groove);
}

double helix1(Arguments a) {
    const double* p = a.p;  // helices, period, minor radius, major radius, shape, section, section angle
    const double distance_from_axis = std::sqrt(a.x * a.x + a.z * a.z);
    if (a.x == 0.0 && a.z == 0.0) a.x = 0.000001;
    double phase = std::fmod(std::atan2(a.z, a.x) * p[0] + a.y * p[1] * p[0], kTwoPi);
    if (phase < 0) phase += kTwoPi;
    double v = (phase - kPi) / p[4] / (p[1] * p[0]);
    double u = distance_from_axis - p[3];
    double section;
    if (p[5] == 1.0) {
        section = std::sqrt(u * u + v * v);
    } else {
        if (p[6] != 0.0) {
            const double c = std::cos(p[6] * kRadiansPerDegree), s = std::sin(p[6] * kRadiansPerDegree);
            const double turned_u = u * c - v * s;
            v = u * s + v * c;
            u = turned_u;
        }
        section = cross_section(u, v, p[5], p[5] * 0.5);
    }
    return -p[2] + std::min(p[3] + distance_from_axis, section);
}

double helix2(const Arguments& a) {
    const double* p = a.p;  // -, period, minor radius, major radius, -, section, -
    const double angle = a.y * p[1];
    const double c = std::cos(angle), s = std::sin(angle);
    const double dx = a.x - p[3] * c, dz = a.z - p[3] * s;
    const double u = dx * c + dz * s, v = -dx * s + dz * c;
    return cross_section(u, v, p[5], p[5] * 0.5) - p[2];
}

// f_hex_x (27) and f_hex_y (28): distances in a hexagonal tiling of the
// x-y plane, cells √3 wide and 3 high.
[[gnu::always_inline]] inline double hexagonal(int number, const Arguments& a) {
    double u = std::fabs(std::fmod(std::fabs(a.x), kSqrt3) - kSqrt3 / 2);
    double v = std::fabs(std::fmod(std::fabs(a.y), 3.0) - 1.5);
    const double other_u = kSqrt3 / 2 - u, other_v = 1.5 - v;
    if (u * u + v * v > other_u * other_u + other_v * other_v) {
        u = other_u;
        v = other_v;
    }
    const bool near_x_axis = std::atan2(v, u) < kPi / 6;
    if (number == 27) return near_x_axis ? u : std::cos(kPi / 3) * u + std::sin(kPi / 3) * v;
    return near_x_axis ? v : std::fabs(-std::sin(kPi / 3) * u + std::cos(kPi / 3) * v);
}

// f_hetero_mf: a heterogeneous multifractal; p0 H, p1 lacunarity, p2
// octaves (the fraction weighs one more), p3 offset, p4 the power of the
// signal scaling each increment, p5 the noise generator.
double hetero_multifractal(const Arguments& a, const FunctionNatives* natives) {
    const double* p = a.p;
    const int generator = noise_generator(p[5]);
    const int signal_power = truncated(std::min(p[4], kMaxRepetitions));
    const double octaves = std::min(p[2], kMaxRepetitions);
    glm::dvec3 at(a.x, a.y, a.z);
    double signal = noise(natives, at, generator) * 2.0 - 1.0 + p[3];
    at *= p[1];
    const double octave_weight = std::pow(p[1], -p[0]);
    double weight = octave_weight;
    for (int i = 1; i < octaves; ++i) {
        double increment = (noise(natives, at, generator) * 2.0 - 1.0 + p[3]) * weight;
        for (int k = 0; k < signal_power; ++k) increment *= signal;
        signal += increment;
        at *= p[1];
        weight *= octave_weight;
    }
    const double fraction = octaves - truncated(octaves);
    if (fraction != 0.0) signal += fraction * ((noise(natives, at, generator) * 2.0 - 1.0 + p[3]) * weight) * signal;
    return signal;
}

// f_ridge: p0 lambda, p1 octaves (the fraction weighs one more), p2 omega,
// p3 offset, p4 ridge, p5 the noise generator.
double ridge(const Arguments& a, const FunctionNatives* natives) {
    const double* p = a.p;
    const int generator = noise_generator(p[5]);
    const double octaves = std::min(p[1], kMaxRepetitions);
    const int whole_octaves = truncated(octaves);
    const double ridge_scale = 1.0 / std::max(p[4], 1.0 - p[4]);
    const double offset_scale = 1.0 / std::max(p[3], 1.0 - p[3]);
    const glm::dvec3 at(a.x, a.y, a.z);
    auto folded = [&](double frequency) {
        return std::fabs(noise(natives, at * frequency, generator) - p[4]) * ridge_scale;
    };
    double value = std::fabs(noise(natives, at, generator) - p[4]) * ridge_scale - p[3];
    double total_weight = 1.0, frequency = p[0], weight = p[2];
    for (int i = 2; i <= whole_octaves; ++i) {
        value += weight * (folded(frequency) - p[3]);
        total_weight += weight;
        frequency *= p[0];
        weight *= p[2];
    }
    const double fraction = octaves - whole_octaves;
    if (fraction != 0.0) {
        value += weight * (folded(frequency) - p[3]) * fraction;
        total_weight += weight * fraction;
    }
    return value * offset_scale / total_weight;
}

// f_ridged_mf: Musgrave's ridged multifractal; p0 H, p1 lacunarity, p2
// octaves, p3 offset, p4 gain, p5 the noise generator. POV: it keeps the
// octave weights of its first call for all later ones (whatever H and
// lacunarity those pass); lancer computes them from each call's.
double ridged_multifractal(const Arguments& a, const FunctionNatives* natives) {
    const double* p = a.p;
    const int generator = noise_generator(p[5]);
    const double octaves = std::min(p[2], kMaxRepetitions);
    glm::dvec3 at(a.x, a.y, a.z);
    auto ridged = [&] {
        const double s = p[3] - std::fabs(noise(natives, at, generator) * 2.0 - 1.0);
        return s * s;
    };
    double signal = ridged();
    double result = signal, frequency = 1.0;
    for (int i = 1; i < octaves; ++i) {
        at *= p[1];
        frequency *= p[1];
        const double weight = std::clamp(signal * p[4], 0.0, 1.0);
        signal = ridged() * weight;
        result += signal * std::pow(frequency, -p[0]);
    }
    return result;
}

double mesh(const Arguments& a) {
    const double* p = a.p;  // x spacing, z spacing, thickness in x and z, weave amplitude, thickness in y
    // The distance (scaled by p2) of `coordinate` from the nearest thread
    // at odd multiples of `spacing`.
    auto across = [&](double coordinate, double spacing) {
        double m = std::fmod(coordinate, spacing * 2);
        if (m < 0) m += spacing * 2;
        return std::fabs(m - spacing) * p[2];
    };
    auto thread = [&](double sideways, double height) { return -std::sqrt(height * height + sideways * sideways); };
    const double weave_x = std::cos(a.z * (kPi / p[1])) * p[3], weave_z = std::cos(a.x * (kPi / p[0])) * p[3];
    double nearest = thread(across(a.x, p[0]), (a.y - weave_x) * p[4]);
    nearest = std::max(thread(across(a.x - p[0], p[0]), (a.y + weave_x) * p[4]), nearest);
    nearest = std::max(thread(across(a.z, p[1]), (a.y + weave_z) * p[4]), nearest);
    return -std::max(thread(across(a.z - p[1], p[1]), (a.y - weave_z) * p[4]), nearest);
}

double polytubes(const Arguments& a) {
    const double* p = a.p;  // tubes, then the radius's polynomial in y
    const double y2 = a.y * a.y;
    const double radius = p[1] + p[2] * a.y + p[3] * y2 + p[4] * y2 * a.y + p[5] * y2 * y2;
    const int tubes = truncated(std::min(p[0], kMaxRepetitions));
    double nearest = -10000;
    for (int i = 0; i < tubes; ++i) {
        const double dx = a.x - radius * std::sin(kTwoPi / p[0] * i), dz = a.z - radius * std::cos(kTwoPi / p[0] * i);
        nearest = std::max(nearest, -std::sqrt(dx * dx + dz * dz));
    }
    return -nearest;
}

double quantum(Arguments a) {
    if (a.x == 0.0 && a.z == 0.0) a.x = 1e-6;
    const double distance_from_axis = std::sqrt(a.x * a.x + a.z * a.z);
    const double c = std::cos(std::atan2(distance_from_axis, a.y));
    const double r = std::sqrt(distance_from_axis * distance_from_axis + a.y * a.y) * 2.0;
    const double wave = r * r * std::exp(-r * 0.33333333) * (3.0 * c * c - 1);  // POV: 1/3 to 8 digits
    return (wave * wave - 12.0) * -0.1;
}

double spiral(Arguments a) {
    const double* p = a.p;  // winding distance, thickness, outer diameter, -, -, section
    const double distance_from_axis = std::sqrt(a.x * a.x + a.z * a.z);
    if (a.x == 0.0 && a.z == 0.0) a.x = 0.000001;
    const double unwound = distance_from_axis + p[0] * std::atan2(a.z, a.x) / kTwoPi;
    const double u = std::fmod(unwound, p[0]) - p[0] * 0.5;
    const double section = cross_section(u, a.y, p[5], 1.0 / (2.0 / p[5]));
    const double r = std::sqrt(a.x * a.x + a.y * a.y + a.z * a.z);
    return -std::min(p[2] - r, p[1] - std::min(section, r));
}

double superellipsoid(const Arguments& a) {
    const double e = a.p[0], n = a.p[1];
    const double xy = std::pow(std::pow(std::fabs(a.x), 2.0 / e) + std::pow(std::fabs(a.y), 2.0 / e), e * (1 / n));
    return 1.0 - std::pow(xy + std::pow(std::fabs(a.z), 2.0 * (1 / n)), n * 0.5);
}

double rounded_box(const Arguments& a) {
    const double radius = a.p[0];
    // How far the point lies outside the box shrunk by the radius, per axis.
    auto outside = [&](double v, double half_size) {
        return std::max(v > radius - half_size ? 0.0 : radius - half_size - v,
                        v < half_size - radius ? 0.0 : v - (half_size - radius));
    };
    const double ox = outside(a.x, a.p[1]), oy = outside(a.y, a.p[2]), oz = outside(a.z, a.p[3]);
    return -radius + std::sqrt(ox * ox + oy * oy + oz * oz) - 1e-6;
}

// The algebraic surfaces: a polynomial of the point, through field() with
// p0 the field strength.
[[gnu::always_inline]] inline double algebraic_surface(int number, const Arguments& a) {
    const double* p = a.p;
    const double x = a.x, y = a.y, z = a.z, x2 = x * x, y2 = y * y, z2 = z * z, s = x2 + y2 + z2;
    switch (number) {
    case 4: {  // f_bicorn
        const double k = p[1] * p[1], q = x2 + z2 + 2 * p[1] * y - k;
        return field(p[0], y2 * (k - (x2 + z2)) - q * q);
    }
    case 5: return field(p[0], -(s * s - p[1] * (x2 + z2) * y));  // f_bifolia
    case 11: return field(p[0], x2 * z2 - y);                     // f_crossed_trough
    case 12: return field(p[0], -(x2 * x - y2 * y - z));          // f_cubic_saddle
    case 13:                                                      // f_cushion
    case 43:                                                      // f_odd: POV's formula is f_cushion's
        return field(p[0], z2 * x2 - z2 * z2 - 2 * z * x2 + 2 * z2 * z + x2 - z2 - (x2 - z) * (x2 - z) - y2 * y2 -
                               2 * x2 * y2 - y2 * z2 + 2 * y2 * z + y2);
    case 14:
        return field(p[0], -(x2 * x2 + 2 * x2 * z2 - 0.36 * x2 - y2 * y2 + 0.25 * y2 + z2 * z2));  // f_devils_curve
    case 20: return field(p[0], (y2 + z2) * (1 + (p[2] - 4 * p[1]) * x) + x2 * (1 + p[2]));        // f_folium_surface
    case 22: return field(p[0], 0.5 * x2 * x2 * x + 0.5 * x2 * x2 - (y2 + z2));                    // f_glob
    case 23: {                                                                                     // f_heart
        const double q = 2 * x2 + y2 + z2 - 1;
        return field(p[0], -(q * q * q - 0.1 * x2 * z2 * z - y2 * z2 * z));
    }
    case 30: {  // f_hunt_surface
        const double q = s - 13, t = 3 * x2 + y2 - 4 * z2 - 12;
        return field(p[0], -(4 * q * q * q + 27 * t * t));
    }
    case 31: {  // f_hyperbolic_torus
        const double m = p[1] * p[1], n = p[2] * p[2];
        return field(p[0], -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z2 - 2 * (m + n) * x2 + y2 * y2 - 2 * y2 * z2 +
                             2 * (m - n) * y2 + z2 * z2 + 2 * (m + n) * z2 + (m - n) * (m - n)));
    }
    case 33:  // f_kampyle_of_eudoxus
        return field(p[0], -((y2 + z2) - p[2] * p[2] * x2 * x2 + p[2] * p[2] * p[1] * p[1] * x2));
    case 35: {  // f_klein_bottle
        const double u = s + 2 * y - 1, v = s - 2 * y - 1;
        return field(p[0], -(u * (v * v - 8 * z2) + 16 * x * z * v));
    }
    case 36:  // f_kummer_surface_v1
        return field(p[0], -(x2 * x2 + y2 * y2 + z2 * z2 - x2 - y2 - z2 - x2 * y2 - x2 * z2 - y2 * z2 + 1));
    case 37:  // f_kummer_surface_v2
        return field(p[0], -(x2 * x2 + y2 * y2 + z2 * z2 + p[1] * s + p[2] * (x2 * y2 + x2 * z2 + y2 * z2) +
                             p[3] * x * y * z - 1));
    case 38: return field(p[0], -(x2 * x2 - x2 + y2 + z2));           // f_lemniscate_of_gerono
    case 41: return field(p[0], -(4 * x2 * s - y2 * (1 - y2 - z2)));  // f_mitre
    case 42: return field(p[0], -(y2 * y + z2 * z - 6 * y * z));      // f_nodal_cubic
    case 44: {                                                        // f_ovals_of_cassini
        const double q = s + p[1] * p[1];
        return field(p[0], -(q * q - p[3] * p[1] * p[1] * (x2 + z2) - p[2] * p[2]));
    }
    case 45: return field(p[0], -(x2 - y + z2));  // f_paraboloid
    case 46: {                                    // f_parabolic_torus
        const double m = p[1] * p[1], n = p[2] * p[2];
        return field(p[0], -(x2 * x2 + 2 * x2 * y2 - 2 * x2 * z - (m + n) * x2 + y2 * y2 - 2 * y2 * z + (m - n) * y2 +
                             z2 + (m + n) * z + (m - n) * (m - n)));
    }
    case 48: return field(p[0], x2 * x2 + y2 * y2 + z2 * z2 - s);  // f_pillow
    case 49: return -field(p[0], -(x2 * x2 - x2 * x + y2 + z2));   // f_piriform
    case 54: return field(p[0], -(x2 * x2 + z2 * z2 - y));         // f_quartic_paraboloid
    case 55: return field(p[0], -(x2 * x2 - z2 * z2 - y));         // f_quartic_saddle
    case 56:                                                       // f_quartic_cylinder
        return field(p[0], -((x2 + z2) * y2 + p[2] * p[2] * (x2 + z2) - p[2] * p[2] * p[1] * p[1]));
    case 65: return field(p[0], -(x2 * y2 + x2 * z2 + y2 * z2 + x * y * z));  // f_steiners_roman
    case 66: {                                                                // f_strophoid
        const double k = p[3] * p[3];
        return field(p[0], -((p[2] - x) * (y2 + z2) - k * p[1] * x2 - k * x2 * x));
    }
    case 71: {  // f_torus2
        const double m = p[1] * p[1], n = p[2] * p[2];
        return field(p[0], -(x2 * x2 + y2 * y2 + z2 * z2 + 2 * x2 * y2 + 2 * x2 * z2 + 2 * y2 * z2 - 2 * (m + n) * x2 +
                             2 * (m - n) * y2 - 2 * (m + n) * z2 + (m - n) * (m - n)));
    }
    case 72: {  // f_torus_gumdrop
        const double q = y2 + z2;
        return field(p[0], -(4 * (x2 * x2 + q * q) + 17 * x2 * q - 20 * s + 17));
    }
    case 73: return field(p[0], -(x2 - y * z2));                     // f_umbrella
    default: return field(p[0], -(p[1] * (y - 1) + (x2 + z2) * y));  // 74, f_witch_of_agnesi
    }
}

// The `_2d` curves: a polynomial of the point in the curve's plane (see
// curve_point), through field() with p0 the field strength.
[[gnu::always_inline]] inline double plane_curve(int number, const Arguments& a) {
    const double* p = a.p;
    switch (number) {
    case 15: {  // f_devils_curve_2d
        const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
        return field(p[0], -(c.x2 * (c.x2 - p[1] * p[1]) - c.y2 * (c.y2 - p[2] * p[2])));
    }
    case 21: {  // f_folium_surface_2d
        const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
        return field(p[0], -(c.y2 * (1 + (p[2] - 4 * p[1]) * c.x) + c.x2 * (1 + p[2])));
    }
    case 34: {  // f_kampyle_of_eudoxus_2d; POV: p1 * p2 where the 3-D one has p1 * p1
        const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
        return field(p[0], -(c.y2 - p[2] * p[2] * c.x2 * c.x2 + p[2] * p[2] * p[1] * p[2] * c.x2));
    }
    case 39: {  // f_lemniscate_of_gerono_2d
        const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
        return field(p[0], -(c.y2 - p[2] * p[2] * p[1] * p[1] * c.x2 + p[2] * p[2] * c.x2 * c.x2));
    }
    case 50: {  // f_piriform_2d
        const CurvePoint c = curve_point(a, p[4], p[5], p[6]);
        return field(p[0], -(c.y2 - p[1] * p[3] * p[3] * c.x2 * c.x - p[2] * p[3] * p[3] * c.x2 * c.x2));
    }
    case 67: {  // f_strophoid_2d
        const CurvePoint c = curve_point(a, p[4], p[5], p[6]);
        const double k = p[3] * p[3];
        return field(p[0], -((p[2] - c.x) * c.y2 - k * p[1] * c.x2 - k * c.x2 * c.x));
    }
    default: {  // 75, f_witch_of_agnesi_2d
        const CurvePoint c = curve_point(a, p[3], p[4], p[5]);
        return field(p[0], -(p[1] * p[1] * c.y + c.x2 * c.y - p[2]));
    }
    }
}

// The value of function `number` (a supported one). Inlined into each of
// the bodies below with its number fixed, so each is its own small
// function and the switch folds away.
[[gnu::always_inline]] inline double evaluate(int number, const Arguments& a, const FunctionNatives* natives) {
    const double* p = a.p;
    const double x = a.x, y = a.y, z = a.z;
    switch (number) {
    case 0:
    case 1:
    case 2:
    case 3: return algebraic_cylinder(number, a);
    case 6: {  // f_blob: two blob components p0 apart on x
        const double h = p[0] * 0.5, y2 = y * y, z2 = z * z;
        const double d1 = std::min(1.0, ((x + h) * (x + h) + y2 + z2) * p[2] * p[2]);
        const double d2 = std::min(1.0, ((x - h) * (x - h) + y2 + z2) * p[4] * p[4]);
        return -(p[1] * (1 - d1) * (1 - d1) + p[3] * (1 - d2) * (1 - d2));
    }
    case 7: {  // f_blob2
        const double y2 = y * y, z2 = z * z;
        const double sum = std::exp(-(x * x + y2 + z2) * p[1]) + std::exp(-((x - p[0]) * (x - p[0]) + y2 + z2) * p[1]);
        return p[3] - sum * p[2];
    }
    case 8: return boy_surface(a);
    case 9: return comma(a);
    case 10: {  // f_cross_ellipsoids
        const Ellipsoids e = ellipsoids(a);
        return p[3] - std::max(std::max(e.along_z, e.along_y), e.along_x) * p[2];
    }
    case 16: return dupin_cyclid(a);
    case 17: return std::sqrt(x * x * p[0] * p[0] + y * y * p[1] * p[1] + z * z * p[2] * p[2]);  // f_ellipsoid
    case 18: return enneper(a);
    case 19: {  // f_flange_cover
        const Ellipsoids e = ellipsoids(a);
        return p[3] - (e.along_z + e.along_y + e.along_x) * p[2];
    }
    case 24: return helical_torus(a);
    case 25: return helix1(a);
    case 26: return helix2(a);
    case 27:
    case 28: return hexagonal(number, a);
    case 29: return hetero_multifractal(a, natives);
    case 32: {  // f_isect_ellipsoids
        const Ellipsoids e = ellipsoids(a);
        return p[3] - std::min(std::min(e.along_z, e.along_y), e.along_x) * p[2];
    }
    case 40: return mesh(a);
    case 47: return std::atan2(std::sqrt(x * x + z * z), y);  // f_ph
    case 51: {                                                // f_poly4: a radius polynomial in y
        const double y2 = y * y;
        const double radius = std::max(-5.0, p[0] + p[1] * y + p[2] * y2 + p[3] * y2 * y + p[4] * y2 * y2);
        return -radius + std::sqrt(x * x + z * z);
    }
    case 52: return polytubes(a);
    case 53: return quantum(a);
    case 57: return std::sqrt(x * x + y * y + z * z);  // f_r
    case 58: return ridge(a, natives);
    case 59: return ridged_multifractal(a, natives);
    case 60: return rounded_box(a);
    case 61: return -p[0] + std::sqrt(x * x + y * y + z * z);  // f_sphere
    case 62: {                                                 // f_spikes
        const Ellipsoids e = ellipsoids(a);
        const double core = std::exp(-(x * x + y * y + z * z) * p[3]) * p[4];
        return -(core - e.along_z - e.along_y - e.along_x) * p[2];
    }
    case 63:  // f_spikes_2d
        return -(p[0] * std::cos(p[1] * x) * std::cos(p[2] * z) * std::exp(-p[3] * (x * x + z * z)) - y);
    case 64: return spiral(a);
    case 68: return superellipsoid(a);
    case 69: return std::atan2(x, z);  // f_th
    case 70: {                         // f_torus: major p0, minor p1
        const double ring = std::sqrt(x * x + z * z) - p[0];
        return -p[1] + std::sqrt(ring * ring + y * y);
    }
    case 15:
    case 21:
    case 34:
    case 39:
    case 50:
    case 67:
    case 75: return plane_curve(number, a);
    case 76: return noise(natives, glm::dvec3(x, y, z), 0);  // f_noise3d: the scene's generator
    case 78: return noise(natives, glm::dvec3(x, y, z), noise_generator(p[0]));
    default: return algebraic_surface(number, a);
    }
}

using Body = double (*)(const Arguments&, const FunctionNatives*);

template <int Number>
double body(const Arguments& a, const FunctionNatives* natives) {
    return evaluate(Number, a, natives);
}

// One entry per number 0 .. kLastInternalFunction (77's is never called).
template <int... Numbers>
constexpr std::array<Body, sizeof...(Numbers)> make_bodies(std::integer_sequence<int, Numbers...>) {
    return {body<Numbers>...};
}
constexpr auto kBodies = make_bodies(std::make_integer_sequence<int, kLastInternalFunction + 1>());

}  // namespace

glm::dvec3 FunctionNatives::turbulence_vector(const glm::dvec3&, double, double, int) const {
    throw FunctionError("vturbulence() needs the renderer's noise");
}

int internal_function_parameter_count(int number) {
    return internal_function_supported(number) ? kParameterCounts[number] : -1;
}

double internal_function(int number, const double* arguments, int count, const FunctionNatives* natives) {
    if (!internal_function_supported(number))
        throw FunctionError("POV-Ray 3.7 has no internal function " + std::to_string(number));
    // Filled element by element, in place: zeroing the struct first costs a
    // `rep stos`, and copying a filled array into it a stalled store
    // forwarding, each measured as much as f_torus itself.
    const int used = std::min(count, 3 + kParameterCounts[number]);
    Arguments a;
    a.x = used > 0 ? arguments[0] : 0.0;
    a.y = used > 1 ? arguments[1] : 0.0;
    a.z = used > 2 ? arguments[2] : 0.0;
    for (int i = 0; i < kArgumentSlots - 3; ++i) a.p[i] = 3 + i < used ? arguments[3 + i] : 0.0;
    return kBodies[number](a, natives);
}

}  // namespace lancer::sg
