// POV-Ray's warps: how each step of warp { ... } (and each transform
// written between warps) moves the point a pattern is evaluated at.
#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

glm::dvec3 unit_or(const glm::dvec3& v, const glm::dvec3& fallback) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : fallback;
}

// acos and asin of a ratio that is at most 1 in magnitude in exact
// arithmetic; rounding (squares that underflow) can push it an ulp past.
double acos_of_ratio(double ratio) {
    return std::acos(std::clamp(ratio, -1.0, 1.0));
}

double asin_of_ratio(double ratio) {
    return std::asin(std::clamp(ratio, -1.0, 1.0));
}

// Angle around the y axis from +x towards +z, as a fraction of a turn in [0, 1).
double turn_around_y(double x, double z, double length) {
    double theta;
    if (z == 0.0) {
        theta = x > 0 ? 0.0 : M_PI;
    } else {
        theta = acos_of_ratio(x / length);
        if (z < 0.0) theta = kTwoPi - theta;
    }
    return theta / kTwoPi;
}

// The mapping warps compute (u, v, distance) as x, y, z for the default
// orientation <0, 0, 1>; another orientation swaps the axes the way POV
// does (a blend of the three axis-aligned layouts by the vector's parts).
glm::dvec3 orient(const glm::dvec3& uvw, const glm::dvec3& o) {
    if (o.x == 0.0 && o.y == 0.0 && o.z == 1.0) return uvw;
    const double x = uvw.x, y = uvw.y, z = uvw.z;
    return {o.x * z + o.y * x + o.z * x, o.x * y + o.y * -z + o.z * y, o.x * -x + o.y * y + o.z * z};
}

double distance_scale(double length, double dist_exp) {
    if (dist_exp == 1.0) return length;
    if (dist_exp != 0.0) return std::pow(length, dist_exp);
    return 1.0;
}

// A mapped coordinate (a fraction of a turn) times the distance scale,
// which overflows for a large dist_exp: on the seam (0) the point stays
// there rather than becoming 0 x infinity; elsewhere the product is held
// to the coordinate limit here, before orient() mixes it with zeros.
double scaled(double u, double scale) {
    if (u == 0.0) return 0.0;
    return std::clamp(u * scale, -kCoordinateLimit, kCoordinateLimit);
}

void cylindrical_warp(const WarpStep& w, glm::dvec3& p) {
    const double length = std::sqrt(p.x * p.x + p.z * p.z);
    if (length == 0.0) return;  // the axis stays where it is
    const double u = scaled(turn_around_y(p.x, p.z, length), distance_scale(length, w.dist_exp));
    p = orient({u, p.y, length}, w.orientation);
}

void spherical_warp(const WarpStep& w, glm::dvec3& p) {
    const double distance = std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z);
    if (distance == 0.0) return;
    const glm::dvec3 d = p / distance;
    double v = 0.5 + asin_of_ratio(d.y) / M_PI;
    const double ring = std::sqrt(d.x * d.x + d.z * d.z);
    double u = ring == 0.0 ? 0.0 : turn_around_y(d.x, d.z, ring);
    const double scale = distance_scale(distance, w.dist_exp);
    u = scaled(u, scale);
    v = scaled(v, scale);
    p = orient({u, v, distance}, w.orientation);
}

void toroidal_warp(const WarpStep& w, glm::dvec3& p) {
    const double length = std::sqrt(p.x * p.x + p.z * p.z);
    if (length == 0.0) return;
    double u = turn_around_y(p.x, p.z, length);
    // Distance from the ring of major_radius, and the angle around it.
    const double x = length - w.major_radius;
    const double tube = std::sqrt(x * x + p.y * p.y);
    // On the ring itself the angle around it is undefined: 0 there.
    double phi = tube > 0.0 ? acos_of_ratio(-x / tube) : 0.0;
    if (p.y > 0.0) phi = kTwoPi - phi;
    double v = phi / kTwoPi;
    const double scale = distance_scale(tube, w.dist_exp);
    u = scaled(u, scale);
    v = scaled(v, scale);
    p = orient({u, v, tube}, w.orientation);
}

void planar_warp(const WarpStep& w, glm::dvec3& p) {
    p = orient({p.x, p.y, w.plane_offset}, w.orientation);
}

void repeat_warp(const WarpStep& w, glm::dvec3& p) {
    const int axis = w.repeat_axis;
    if (axis < 0) return;
    // POV keeps the cell number and width in single precision, and so
    // multiplies them in single precision. A cell number beyond float's
    // range (a far point, a tiny width) has no float: the same arithmetic
    // in double precision there.
    const double cells = std::floor(p[axis] / w.repeat_width);
    double cell, cell_start;
    if (std::fabs(cells) <= double(std::numeric_limits<float>::max())) {
        cell = double(float(cells));
        cell_start = double(float(cell) * w.repeat_width);
    } else {
        cell = cells;
        cell_start = cells * double(w.repeat_width);
    }
    glm::dvec3 r = p;
    r[axis] = p[axis] - cell_start;
    if (floor_to_int(cell) & 1) {
        r *= w.repeat_flip;
        if (w.repeat_flip[axis] < 0) r[axis] = w.repeat_width + r[axis];
    }
    p = r + cell * w.repeat_offset;
}

void black_hole_warp(const WarpStep& w, glm::dvec3& p) {
    glm::dvec3 center = w.center;
    if (w.hole_repeats) {
        int block[3] = {0, 0, 0};
        for (int i = 0; i < 3; ++i) {
            if (w.hole_repeat[i] >= kPovEpsilon) block[i] = floor_to_int(p[i] / w.hole_repeat[i]);
        }
        if (w.hole_jitters) {
            // The same random table as the cell patterns, at the block's hash.
            const std::size_t seed = std::size_t(pov_hash3d(block[0], block[1], block[2]));
            for (int i = 0; i < 3; ++i) center[i] += pov_pattern_random(seed + std::size_t(i)) * w.hole_jitter[i];
        }
        for (int i = 0; i < 3; ++i) center[i] += w.hole_repeat[i] * block[i];
    }
    glm::dvec3 delta = p - center;
    const double length = std::sqrt(delta.x * delta.x + delta.y * delta.y + delta.z * delta.z);
    if (length >= w.radius) return;
    // 1 at the centre, 0 at the rim; the pull is capped so a point never
    // moves past the centre.
    const double depth = (w.radius - length) / w.radius;
    double strength = std::pow(depth, w.falloff) * w.strength;
    if (strength > 1.0) strength = 1.0;
    delta *= w.inverse ? -strength : strength;
    p += delta;
}

}  // namespace

void check_turbulence(const TurbulenceSettings& t) {
    double amplitude = 1.0, frequency = 1.0;
    for (int octave = 2; octave <= t.octaves; ++octave) {
        amplitude *= double(t.omega);
        frequency *= double(t.lambda);
    }
    if (!std::isfinite(amplitude) || !std::isfinite(frequency) || !std::isfinite(t.omega) || !std::isfinite(t.lambda))
        throw std::runtime_error("turbulence: omega and lambda raised to octaves - 1 must stay finite (omega " +
                                 std::to_string(t.omega) + ", lambda " + std::to_string(t.lambda) + ", octaves " +
                                 std::to_string(t.octaves) + ")");
}

WarpStep make_warp_step(const sg::Warp& warp) {
    WarpStep step;
    step.kind = warp.kind;
    step.inner_from_outer = warp.inner_from_outer;
    step.turbulence = {warp.turbulence, warp.octaves, float(warp.omega), float(warp.lambda)};
    if (warp.kind == sg::Warp::Kind::Turbulence) check_turbulence(step.turbulence);
    // repeat <v>: the one non-zero axis of v is the axis, its value the width.
    for (int i = 0; i < 3; ++i) {
        if (warp.repeat[i] != 0.0 && step.repeat_axis < 0) {
            step.repeat_axis = i;
            step.repeat_width = float(warp.repeat[i]);  // single precision, as POV keeps it
        }
    }
    // A width that single precision cannot hold: under 1e-45 it would be 0
    // (every point divided by zero), over 3.4e38 infinite.
    if (warp.kind == sg::Warp::Kind::Repeat && step.repeat_axis >= 0 &&
        !(std::isfinite(step.repeat_width) && step.repeat_width != 0.0f))
        throw std::runtime_error(
            "warp { repeat }: the width must lie within single precision's range, "
            "1e-45 to 3.4e38 (POV keeps it as a float)");
    step.repeat_offset = warp.offset;
    for (int i = 0; i < 3; ++i) step.repeat_flip[i] = warp.flip[i] != 0.0 ? -1.0 : 1.0;
    step.center = warp.center;
    step.radius = warp.radius;
    step.falloff = warp.falloff;
    step.strength = warp.strength;
    step.inverse = warp.inverse;
    step.hole_repeat = warp.repeat;
    step.hole_jitter = warp.turbulence;
    step.hole_repeats = warp.repeat != glm::dvec3(0.0);
    step.hole_jitters = warp.turbulence != glm::dvec3(0.0);
    if (step.kind == sg::Warp::Kind::BlackHole && step.hole_repeats) {
        // POV's sanity rules for a repeated black hole, per repeated axis: the
        // centre lies at least a radius into the cell, and the cell holds the
        // hole and its jitter.
        for (int i = 0; i < 3; ++i) {
            if (step.hole_repeat[i] <= 0.0) continue;
            step.center[i] = std::max(step.center[i], step.radius);
            step.hole_repeat[i] = std::max(step.hole_repeat[i], step.center[i] + step.radius + step.hole_jitter[i]);
            if (step.hole_repeat[i] < kPovEpsilon) step.hole_repeat[i] = 0.0;
        }
    }
    step.orientation =
        unit_or(warp.kind == sg::Warp::Kind::Planar ? warp.normal : warp.orientation, glm::dvec3(0.0, 0.0, 1.0));
    step.dist_exp = warp.dist_exp;
    step.major_radius = warp.major_radius;
    step.plane_offset = warp.distance;
    return step;
}

glm::dvec3 turbulence_displacement(const glm::dvec3& p, const TurbulenceSettings& t, NoiseGenerator generator) {
    return pov_dturbulence(p, t.omega, t.lambda, t.octaves, generator) * t.amount;
}

void apply_warp(const WarpStep& step, glm::dvec3& p, NoiseGenerator generator) {
    switch (step.kind) {
    case sg::Warp::Kind::Transform: p = glm::dvec3(step.inner_from_outer * glm::dvec4(p, 1.0)); break;
    case sg::Warp::Kind::Turbulence:
        if (step.turbulence.present()) p += turbulence_displacement(p, step.turbulence, generator);
        break;
    case sg::Warp::Kind::Repeat: repeat_warp(step, p); break;
    case sg::Warp::Kind::BlackHole: black_hole_warp(step, p); break;
    case sg::Warp::Kind::Cylindrical: cylindrical_warp(step, p); break;
    case sg::Warp::Kind::Spherical: spherical_warp(step, p); break;
    case sg::Warp::Kind::Toroidal: toroidal_warp(step, p); break;
    case sg::Warp::Kind::Planar: planar_warp(step, p); break;
    }
}

}  // namespace lancer::pattern_detail
