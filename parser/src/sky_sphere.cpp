// POV-Ray's sky_sphere block: building sg::SkySphere from the grammar's
// edits, with POV's check (parstxtr.cpp Parse_Skysphere) as an error.
#include "evaluator.h"

namespace lancer::parse {

std::shared_ptr<sg::SkySphere> Evaluator::build_sky_sphere(const Edits<sg::SkySphere>& edits,
                                                           const sg::SourceLocation& at) {
    auto sky = std::make_shared<sg::SkySphere>();
    for (const auto& edit : edits) edit(*sky);
    sky->location = at;
    // POV rejects it too ("Empty sky_sphere statement"): a sky without a
    // pigment would hide nothing and is surely a mistake.
    if (sky->pigments.empty()) error(at, "sky_sphere needs at least one pigment");
    return sky;
}

}  // namespace lancer::parse
