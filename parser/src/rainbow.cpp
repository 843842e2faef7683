// POV-Ray's rainbow block: building sg::Rainbow from the grammar's edits,
// with POV's checks (parstxtr.cpp Parse_Rainbow) as located errors.
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {

std::function<void(sg::Rainbow&)> Evaluator::rainbow_angle(bool arc, const Value& v, const SourceRange& where) {
    const double degrees = to_float(v, where, arc ? "an arc_angle" : "a falloff_angle");
    if (degrees < 0.0 || degrees > 360.0) {
        error(where.begin, std::string(arc ? "arc_angle" : "falloff_angle") + " must lie between 0 and 360 degrees");
        return [](sg::Rainbow&) {};
    }
    // POV keeps half the angle, in radians: the arc spans it either side of up.
    const double half = degrees * M_PI / 360.0;
    if (arc)
        return [half](sg::Rainbow& r) {
            r.arc_angle = half;
            r.arc_angle_given = true;
        };
    return [half](sg::Rainbow& r) {
        r.falloff_angle = half;
        r.falloff_angle_given = true;
    };
}

std::shared_ptr<sg::Rainbow> Evaluator::build_rainbow(const Edits<sg::Rainbow>& edits, const sg::SourceLocation& at) {
    auto rainbow = std::make_shared<sg::Rainbow>();
    for (const auto& edit : edits) edit(*rainbow);
    rainbow->location = at;
    sg::Rainbow& r = *rainbow;
    if (r.arc_angle_given && !r.falloff_angle_given) r.falloff_angle = r.arc_angle;
    if (r.arc_angle < r.falloff_angle) error(at, "the rainbow's arc_angle is smaller than its falloff_angle");
    if (glm::dot(r.direction, r.direction) < 1e-10) {
        error(at, "the rainbow needs a direction (the antisolar direction, not zero)");
        return rainbow;
    }
    if (glm::dot(r.up, r.up) < 1e-10) {
        error(at, "the rainbow's up vector is zero");
        return rainbow;
    }
    if (std::abs(1.0 - std::abs(glm::dot(glm::normalize(r.up), glm::normalize(r.direction)))) < 1e-10)
        error(at, "the rainbow's up and direction vectors are co-linear");
    if (!r.color_map) warning(at, "a rainbow without a color_map shows nothing, as in POV-Ray");
    return rainbow;
}

}  // namespace lancer::parse
