// POV-Ray's geometric ramps: gradient, onion, spherical, cylindrical,
// boxed, planar, radial and the two spirals (values as POV's pattern
// functions give them, before frequency, phase and the wave type).
#include <algorithm>
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

double gradient_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const double along = glm::dot(p, s.gradient);
    // Only values above 1 wrap here; negative ones wrap after the frequency.
    return along > 1.0 ? std::fmod(along, 1.0) : along;
}

double onion_pattern(const glm::dvec3& p) {
    return std::fmod(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z), 1.0);
}

double spherical_pattern(const glm::dvec3& p) {
    return density_falloff(std::sqrt(p.x * p.x + p.y * p.y + p.z * p.z));
}

double cylindrical_pattern(const glm::dvec3& p) {
    return density_falloff(std::sqrt(p.x * p.x + p.z * p.z));
}

double boxed_pattern(const glm::dvec3& p) {
    return density_falloff(std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z))));
}

double planar_pattern(const glm::dvec3& p) {
    return density_falloff(std::fabs(p.y));
}

double radial_pattern(const glm::dvec3& p) {
    // On the y axis the angle is undefined; POV gives the value at angle 0.
    if (std::fabs(p.x) < 0.001 && std::fabs(p.z) < 0.001) return 0.25;
    // Starts at 0.25 and so runs past 1; the frequency step wraps it.
    return 0.25 + (std::atan2(p.x, p.z) + M_PI) / kTwoPi;
}

namespace {

// The spirals' turbulence is on the value (as well as on the point, which
// the pipeline does): the turbulence's x times POV's Turbulence().
double spiral_turbulence(const PatternSetup& s, const glm::dvec3& p) {
    if (!s.turbulence.present()) return 0.0;
    return s.turbulence.amount.x *
           pov_turbulence(p, s.turbulence.omega, s.turbulence.lambda, s.turbulence.octaves, s.generator);
}

// Angle around the z axis in [0, 2 pi), measured as POV does (from -y).
double spiral_angle(double x, double y, double radius) {
    if (radius == 0.0) return 0.0;
    return x < 0.0 ? 3.0 * M_PI_2 - std::asin(y / radius) : M_PI_2 + std::asin(y / radius);
}

}  // namespace

double spiral1_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const double turbulence = spiral_turbulence(s, p);
    const double radius = std::sqrt(p.x * p.x + p.y * p.y);
    const double angle = spiral_angle(p.x, p.y, radius);
    return p.z + radius + double(s.spiral_arms) * angle / kTwoPi + turbulence;
}

double spiral2_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const double turbulence = spiral_turbulence(s, p);
    const double radius = std::sqrt(p.x * p.x + p.y * p.y);
    const double angle = spiral_angle(p.x, p.y, radius);
    const double arms = triangle_wave(p.z + radius + double(s.spiral_arms) * angle / kTwoPi + turbulence);
    return triangle_wave(radius) + arms;
}

}  // namespace lancer::pattern_detail
