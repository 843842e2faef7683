// POV-Ray's quilted pattern and normal: each unit cube bulges like a
// cushion, shaped by a cubic with control points control0 and control1.
// (tiling and pavement are not implemented yet: CompiledPattern refuses them.)
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

// The cushion's offset from its cube's centre, scaled by the Bezier cubic
// (end points 0 and 1) of its length; 1.154700538 is POV's rounding of
// 2 / sqrt(3), which brings the cube's corner to 1.
// POV's FLOOR(): like floor() except at negative integers, which it
// takes one lower.
double pov_floor(double v) {
    return v >= 0.0 ? std::floor(v) : -std::floor(-v) - 1.0;
}

glm::dvec3 cushion(const PatternSetup& s, const glm::dvec3& p) {
    const glm::dvec3 offset(p.x - pov_floor(p.x) - 0.5, p.y - pov_floor(p.y) - 0.5, p.z - pov_floor(p.z) - 0.5);
    const double t = std::sqrt(offset.x * offset.x + offset.y * offset.y + offset.z * offset.z);
    const double it = 1.0 - t;
    const double it2 = it * it, t2 = t * t, t3 = t * t2;
    const double shaped = (t3 + 3.0 * t * it2 * s.quilted_control0 + 3.0 * t2 * it * s.quilted_control1) * 1.154700538;
    return offset * shaped;
}

}  // namespace

double quilted_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const glm::dvec3 c = cushion(s, p);
    return (std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z)) / 3.0;
}

void quilted_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal) {
    normal += amount * cushion(s, p);
}

}  // namespace lancer::pattern_detail
