// A 32-bit word's bits in reverse order: the base-2 radical inverse that
// Hammersley and Sobol' points are built on (internal to liblancer).
#pragma once

#include <cstdint>

namespace lancer {

inline std::uint32_t reverse_bits(std::uint32_t x) {
    // The bytes in one instruction, then the bits within each byte.
    x = __builtin_bswap32(x);
    x = ((x >> 4) & 0x0f0f0f0fu) | ((x & 0x0f0f0f0fu) << 4);
    x = ((x >> 2) & 0x33333333u) | ((x & 0x33333333u) << 2);
    return ((x >> 1) & 0x55555555u) | ((x & 0x55555555u) << 1);
}

// The base-2 radical inverse of `index` in [0, 1).
inline double radical_inverse_base2(std::uint32_t index) {
    return double(reverse_bits(index)) * 0x1p-32;
}

}  // namespace lancer
