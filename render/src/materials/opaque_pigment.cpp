#include "opaque_pigment.h"

namespace lancer {
namespace {

bool colour_is_opaque(const sg::Color& colour) {
    return colour.filter == 0.0 && colour.transmit == 0.0;
}

}  // namespace

bool pigment_is_opaque(const sg::Pigment& pigment) {
    switch (pigment.kind) {
    case sg::Pigment::Kind::Solid: return colour_is_opaque(pigment.color);
    case sg::Pigment::Kind::Image: return false;
    case sg::Pigment::Kind::Patterned:
    case sg::Pigment::Kind::Average: break;
    }
    const bool has_values = (pigment.color_map && !pigment.color_map->empty()) || !pigment.pigment_map.empty() ||
                            !pigment.block_pigments.empty();
    if (!has_values) return false;  // nothing to go by
    if (pigment.color_map)
        for (const sg::ColorMapEntry& entry : *pigment.color_map)
            if (!colour_is_opaque(entry.color)) return false;
    for (const sg::PigmentMapEntry& entry : pigment.pigment_map)
        if (!entry.pigment || !pigment_is_opaque(*entry.pigment)) return false;
    for (const sg::PigmentRef& block : pigment.block_pigments)
        if (!block || !pigment_is_opaque(*block)) return false;
    return true;
}

}  // namespace lancer
