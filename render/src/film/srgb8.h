// 8-bit sRGB codes of linear values from a table: exactly the code the PNG
// encoder gives linear_to_srgb(x) (rounded to nearest), without a pow per
// sample, which was a twentieth of a simple render's CPU time (internal to
// liblancer).
#pragma once

#include <cstddef>
#include <cstdint>

namespace lancer {

// round(255 · linear_to_srgb(x)), 0 for NaN and x <= 0, 255 for x >= 1.
std::uint8_t linear_to_srgb8(float linear);

// The same codes for `count` values at once (an image row's channels).
void linear_to_srgb8(const float* linear, std::uint8_t* codes, std::size_t count);

}  // namespace lancer
