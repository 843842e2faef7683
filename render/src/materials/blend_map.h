// Where a value falls in a POV-Ray map (color_map, pigment_map,
// normal_map, slope_map): the two entries around it and how far between,
// with POV's rules: at or past the last entry, the last; at or before the
// first, the first; on an entry's value exactly, that entry alone (internal
// to liblancer).
#pragma once

#include <vector>

namespace lancer {

struct BlendPair {
    std::size_t previous = 0;
    std::size_t current = 0;
    float fraction = 0.0f;  // 0 at previous, 1 at current
};

// POV keeps a map's values in single precision; so do the callers, so that
// a value on an entry's edge falls on the same side.
inline BlendPair search_blend_map(const std::vector<float>& values, double value) {
    BlendPair pair;
    const std::size_t last = values.size() - 1;
    if (value >= values[last]) {
        pair.previous = pair.current = last;
        return pair;
    }
    std::size_t current = 0;
    while (value > values[current]) ++current;
    if (current == 0 || value == values[current]) {
        pair.previous = pair.current = current;
        return pair;
    }
    pair.previous = current - 1;
    pair.current = current;
    pair.fraction = float((value - values[current - 1]) / (values[current] - values[current - 1]));
    return pair;
}

}  // namespace lancer
