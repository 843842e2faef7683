// POV-Ray's patterns of the surface rather than the point: slope (how far
// the normal turns towards a direction, optionally blended with altitude
// along another) and aoi (the angle between the normal and the ray).
#include <algorithm>
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

// POV's wrap of slope values into [0, 1): an exact 1 stays just below 1
// rather than wrapping to 0.
double wrap_slope(double v, bool exact_one_only) {
    if (exact_one_only ? v == 1.0 : (v - 1.0 < kPovEpsilon && v >= 1.0)) return v - kPovEpsilon;
    return v < 0.0 ? 1.0 + std::fmod(v, 1.0) : std::fmod(v, 1.0);
}

}  // namespace

double slope_pattern(const PatternSetup& s, const glm::dvec3& p, const glm::dvec3& normal,
                     const glm::dvec3& hit_point) {
    double along;
    if (s.slope_point_at) {
        along = glm::dot(normal, glm::normalize(s.slope_direction - hit_point));
    } else {
        along = glm::dot(normal, s.slope_direction);
    }
    along = std::clamp(along, -1.0, 1.0);
    // The angle from the plane perpendicular to the direction, -90..90
    // degrees, mapped onto 0..1.
    double slope = (std::asin(along) / M_PI * 2.0 + 1.0) * 0.5;
    if (s.slope_range.y != 0.0) slope = (slope - s.slope_range.x) / s.slope_range.y;
    if (s.altitude_share == 0.0) return wrap_slope(slope, true);

    double altitude = glm::dot(p, s.altitude_direction);
    if (s.altitude_range.y != 0.0) altitude = (altitude - s.altitude_range.x) / s.altitude_range.y;
    return wrap_slope(s.slope_share * slope + s.altitude_share * altitude, false);
}

double aoi_pattern(const glm::dvec3& normal, const glm::dvec3& ray_direction) {
    const double cosine = std::clamp(glm::dot(glm::normalize(normal), glm::normalize(ray_direction)), -1.0, 1.0);
    return std::acos(cosine) / M_PI;
}

}  // namespace lancer::pattern_detail
