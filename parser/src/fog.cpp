// POV-Ray's fog block: building sg::Fog from the grammar's edits, with
// POV's checks (parstxtr.cpp Parse_Fog) as warnings or errors at the value.
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {

std::shared_ptr<sg::Fog> Evaluator::build_fog(const Edits<sg::Fog>& edits, const sg::SourceLocation& at) {
    auto fog = std::make_shared<sg::Fog>();
    for (const auto& edit : edits) edit(*fog);
    fog->location = at;
    // POV normalises the up vector once its transforms are applied.
    fog->up = glm::normalize(fog->up);
    if (std::abs(fog->distance) <= 1e-10)
        warning(at, "fog without a distance (or distance 0) shows nothing, as in POV-Ray");
    if (fog->type == sg::Fog::Type::Ground && fog->alt <= 0.0) {
        // POV divides by fog_alt: 0 makes the fog a wall at fog_offset and
        // its edge a NaN; a negative value turns the fog upside down.
        error(at, "fog_type 2 needs a positive fog_alt (the height over which the ground fog thins)");
    }
    return fog;
}

std::function<void(sg::Fog&)> Evaluator::fog_value(const Value& v, const SourceRange& where) {
    if (v.kind == Value::Kind::Float) {
        warning(where.begin, "a fog's distance should follow the distance keyword (as POV-Ray warns)");
        const double d = v.v[0];
        return [d](sg::Fog& f) { f.distance = d; };
    }
    const sg::Color c = to_color(v, where);
    return [c](sg::Fog& f) { f.color = c; };
}

std::function<void(sg::Fog&)> Evaluator::fog_type(const Value& v, const SourceRange& where) {
    const int type = to_int(v, where);
    if (type != 1 && type != 2) {
        error(where.begin, "fog_type must be 1 (constant) or 2 (ground fog), got " + std::to_string(type));
        return [](sg::Fog&) {};
    }
    return [type](sg::Fog& f) { f.type = sg::Fog::Type(type); };
}

std::function<void(sg::Fog&)> Evaluator::fog_octaves(const Value& v, const SourceRange& where) {
    int octaves = to_int(v, where);
    // POV clamps them to 1..10 silently; say so.
    if (octaves < 1 || octaves > 10) {
        const int clamped = std::clamp(octaves, 1, 10);
        warning(where.begin, "fog octaves " + std::to_string(octaves) + " taken as " + std::to_string(clamped) +
                                 " (POV-Ray's range is 1 to 10)");
        octaves = clamped;
    }
    return [octaves](sg::Fog& f) {
        f.turbulent = true;
        f.octaves = octaves;
    };
}

std::function<void(sg::Fog&)> Evaluator::fog_transform(const sg::Mat4& transform, const SourceRange& where) {
    if (transform[3][0] != 0.0 || transform[3][1] != 0.0 || transform[3][2] != 0.0)
        warning(where.begin, "a fog's up vector can't be translated; the translation is ignored (as in POV-Ray)");
    return [transform](sg::Fog& f) { f.up = sg::Vec3(transform * glm::dvec4(f.up, 0.0)); };
}

}  // namespace lancer::parse
