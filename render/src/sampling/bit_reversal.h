// A 32-bit word's bits in reverse order: the base-2 radical inverse that
// Hammersley and Sobol' points are built on (internal to liblancer).
#pragma once

#include <cstdint>

namespace lancer {

inline std::uint32_t reverse_bits(std::uint32_t x) {
    x = ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 8) & 0x00ff00ffu) | ((x & 0x00ff00ffu) << 8);
    return (x >> 16) | (x << 16);
}

// The base-2 radical inverse of `index` in [0, 1).
inline double radical_inverse_base2(std::uint32_t index) {
    return double(reverse_bits(index)) * 0x1p-32;
}

}  // namespace lancer
