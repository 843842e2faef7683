// The next float up or down (std::nextafter towards +/- infinity) on the
// bits: the same floats, zeros and infinities included, without a libm call,
// for the paths that take one per hit (internal to liblancer).
#pragma once

#include <bit>
#include <cstdint>
#include <limits>

namespace lancer {

inline float next_float_up(float x) {
    if (x == std::numeric_limits<float>::infinity() || x != x) return x;
    if (x == 0.0f) return std::bit_cast<float>(std::uint32_t(1));  // -0 too
    const auto bits = std::bit_cast<std::uint32_t>(x);
    return std::bit_cast<float>(x > 0.0f ? bits + 1 : bits - 1);
}

inline float next_float_down(float x) {
    return -next_float_up(-x);
}

}  // namespace lancer
