// POV-Ray 3.7's fixed random numbers behind cells, crackle, facets,
// black_hole's jitter, ripples and waves. They are not tables to copy: each
// comes from a standard generator with a fixed seed, checked against
// povray's own values (scripts/measure-pov-patterns.sh writes
// tests/reference/pov/patterns/cells.txt, crackle*.txt,
// warp_black_hole_repeat.txt, ripples.txt and waves*.txt; pattern_test.cpp
// compares).
//  - The cell hash is POV's Hash3d over a permutation of 0..4095 shuffled
//    (from the top index down) by the ANSI C style LCG
//    x = x * 1812433253 + 12345 seeded with 0, taking bits 16..30 mod 4096.
//  - PatternRands/WarpRands: successive outputs of MT19937 with its default
//    seed, divided by 2^32 (Boost's uniform_real over a 32-bit engine).
//  - The waves: source i is the unit DNoise vector at <i, 0, 0>; frequency i
//    comes from the same LCG seeded with -560851967, bits 16..30 / 32767 +
//    0.01.
#include <array>
#include <cstdint>
#include <random>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {
namespace {

constexpr int kHashSize = 4096;
constexpr std::size_t kRandomCount = 32768;

struct LcgStep {
    std::uint32_t state;
    // The next value in 0..32767, as POV's POV_RAND() yields it.
    int next() {
        state = state * 1812433253u + 12345u;
        return int(state >> 16) & 0x7FFF;
    }
};

struct RandomTables {
    std::array<std::uint16_t, kHashSize> permutation{};
    std::array<double, kRandomCount> pattern_random{};

    RandomTables() {
        for (int i = 0; i < kHashSize; ++i) permutation[std::size_t(i)] = std::uint16_t(i);
        LcgStep lcg{0u};
        for (int i = kHashSize - 1; i >= 0; --i) {
            const int j = lcg.next() % kHashSize;
            std::swap(permutation[std::size_t(i)], permutation[std::size_t(j)]);
        }
        std::mt19937 engine;  // default seed 5489, as POV's generator
        for (double& value : pattern_random) value = double(engine()) / 4294967296.0;
    }
};

const RandomTables& tables() {
    static const RandomTables instance;
    return instance;
}

}  // namespace

int pov_hash3d(int ix, int iy, int iz) {
    const auto& h = tables().permutation;
    const int a = h[std::size_t(ix & 0xFFF)];
    const int b = h[std::size_t((a ^ (iy & 0xFFF)) & 0xFFF)];
    return h[std::size_t((b ^ (iz & 0xFFF)) & 0xFFF)];
}

double pov_pattern_random(std::size_t index) {
    return tables().pattern_random[index % kRandomCount];
}

void make_wave_sources(int count, NoiseGenerator generator, std::vector<glm::dvec3>& sources,
                       std::vector<double>& frequencies) {
    sources.clear();
    frequencies.clear();
    LcgStep lcg{std::uint32_t(-560851967)};
    for (int i = 0; i < count; ++i) {
        const glm::dvec3 d = pov_dnoise(glm::dvec3(double(i), 0.0, 0.0), generator);
        const double length = glm::length(d);
        sources.push_back(length > 0.0 ? d / length : d);
        frequencies.push_back(double(lcg.next()) * 0.000030518509476 + 0.01);
    }
}

}  // namespace lancer::pattern_detail
