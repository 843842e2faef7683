// A reproducible uniform number in [0, 1) from a shading point and a salt:
// where POV-Ray draws at random (area light jitter, crand), lancer hashes,
// so a render repeats. Header-only, for the plugins.
#pragma once

#include <cstdint>
#include <cstring>

#include "lancer/ray.h"

namespace lancer {

inline double point_hash(const Vec3& point, std::uint64_t salt) {
    std::uint32_t bits[3];
    std::memcpy(bits, &point, sizeof bits);
    std::uint64_t h =
        (std::uint64_t(bits[0]) << 32 | bits[1]) ^ (std::uint64_t(bits[2]) << 16) ^ salt * 0x9e3779b97f4a7c15ull;
    // splitmix64's finaliser
    h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
    h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
    h ^= h >> 31;
    return double(h >> 11) * 0x1.0p-53;
}

}  // namespace lancer
