// POV-Ray's cellular patterns: cells (a random value per unit cube),
// crackle (distances to the random points of nearby cubes, Worley style)
// and facets' normal. The random point of cube c is c plus three
// consecutive entries of POV's pattern random table, starting at the
// cube's hash (pattern_random.cpp).
#include <algorithm>
#include <array>
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

glm::dvec3 cube_point(int ix, int iy, int iz) {
    const std::size_t seed = std::size_t(pov_hash3d(ix, iy, iz));
    return {ix + pov_pattern_random(seed), iy + pov_pattern_random(seed + 1), iz + pov_pattern_random(seed + 2)};
}

// The cubes within a "3D knight move" of a cube (offsets -2..2, at most
// one of them +-2): the nearest random points always lie among them. In
// POV's order, which decides ties.
struct KnightOffsets {
    std::array<glm::ivec3, 81> offsets{};
    KnightOffsets() {
        std::size_t n = 0;
        for (int x = -2; x <= 2; ++x)
            for (int y = -2; y <= 2; ++y)
                for (int z = -2; z <= 2; ++z)
                    if ((std::abs(x) == 2) + (std::abs(y) == 2) + (std::abs(z) == 2) <= 1) offsets[n++] = {x, y, z};
    }
};

const KnightOffsets& knight_offsets() {
    static const KnightOffsets instance;
    return instance;
}

// The random points around one cube (81 hashes and 243 table reads to
// make). Each thread keeps the last few cubes': neighbouring samples mostly
// fall in the same cube, and a layered texture (POV's stones) asks several
// crackle patterns, each in a cube of its own, for every sample.
struct CrackleNeighbourhood {
    glm::ivec3 cube{0};
    bool valid = false;
    std::array<glm::dvec3, 81> points{};
};

struct CrackleCache {
    static constexpr std::size_t kEntries = 8;
    std::array<CrackleNeighbourhood, kEntries> entries{};
    std::size_t next = 0;  // the entry replaced next (oldest first)
};

// a + b with int's wrap-around (a cube number from floor_to_int may lie at
// the end of int's range).
int wrapping_add(int a, int b) {
    return int(unsigned(a) + unsigned(b));
}

const CrackleNeighbourhood& neighbourhood(const glm::ivec3& cube) {
    thread_local CrackleCache cache;
    for (const CrackleNeighbourhood& entry : cache.entries)
        if (entry.valid && entry.cube == cube) return entry;
    CrackleNeighbourhood& entry = cache.entries[cache.next];
    cache.next = (cache.next + 1) % CrackleCache::kEntries;
    const auto& offsets = knight_offsets().offsets;
    for (std::size_t i = 0; i < offsets.size(); ++i) {
        const glm::ivec3& o = offsets[i];
        entry.points[i] = cube_point(wrapping_add(cube.x, o.x), wrapping_add(cube.y, o.y), wrapping_add(cube.z, o.z));
    }
    entry.cube = cube;
    entry.valid = true;
    return entry;
}

// Crackle's distance measure, before the root: squared distance for
// metric 2, the sum of |d| for 1, the sum of |d|^metric otherwise.
double metric_sum(const glm::dvec3& d, double metric) {
    if (metric == 2.0) return d.x * d.x + d.y * d.y + d.z * d.z;
    if (metric == 1.0) return std::fabs(d.x) + std::fabs(d.y) + std::fabs(d.z);
    return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) + std::pow(std::fabs(d.z), metric);
}

double metric_root(double sum, double metric) {
    if (metric == 2.0) return std::sqrt(sum);
    if (metric == 1.0) return sum;
    return std::pow(sum, 1.0 / metric);
}

}  // namespace

double cells_pattern(const glm::dvec3& p) {
    const int seed =
        pov_hash3d(floor_to_int(p.x + kPovEpsilon), floor_to_int(p.y + kPovEpsilon), floor_to_int(p.z + kPovEpsilon));
    return std::min(pov_pattern_random(std::size_t(seed)), 1.0);
}

double crackle_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const glm::ivec3 cube(floor_to_int(p.x - kPovEpsilon), floor_to_int(p.y - kPovEpsilon),
                          floor_to_int(p.z - kPovEpsilon));
    const CrackleNeighbourhood& around = neighbourhood(cube);
    const double metric = s.crackle_metric;

    // The three smallest distances, and which point is nearest.
    double d1 = metric_sum(around.points[0] - p, metric);
    double d2 = metric_sum(around.points[1] - p, metric);
    double d3 = metric_sum(around.points[2] - p, metric);
    std::size_t nearest = 0;
    if (d2 < d1) {
        std::swap(d1, d2);
        nearest = 1;
    }
    if (d3 < d1) {
        std::swap(d1, d3);
        nearest = 2;
    }
    if (d3 < d2) std::swap(d2, d3);
    for (std::size_t i = 3; i < around.points.size(); ++i) {
        const double d = metric_sum(around.points[i] - p, metric);
        if (d < d1) {
            d3 = d2;
            d2 = d1;
            d1 = d;
            nearest = i;
        } else if (d < d2) {
            d3 = d2;
            d2 = d;
        } else if (d < d3) {
            d3 = d;
        }
    }

    if (s.crackle_offset != 0.0) {
        const double offset = metric == 2.0   ? s.crackle_offset * s.crackle_offset
                              : metric == 1.0 ? s.crackle_offset
                                              : std::pow(s.crackle_offset, metric);
        d1 += offset;
        d2 += offset;
        d3 += offset;
    }

    double value;
    if (s.crackle_solid) {
        value = pov_noise(around.points[nearest], s.generator);
    } else {
        value = s.crackle_form.x * metric_root(d1, metric) + s.crackle_form.y * metric_root(d2, metric) +
                s.crackle_form.z * metric_root(d3, metric);
    }
    return std::max(std::min(value, 1.0), 0.0);
}

void facets_normal(const PatternSetup& s, const glm::dvec3& p, glm::dvec3& normal) {
    normal = glm::normalize(normal);
    const double scale = s.facets_size < 1e-6 ? 1e6 : 1.0 / s.facets_size;
    // Without coords the facet depends on the normal's direction alone.
    const glm::dvec3 cell_point = (s.facets_coords != 0.0 ? p : normal) * scale;
    const double metric = s.facets_metric;
    auto distance = [metric](const glm::dvec3& d) {
        if (metric == 2.0) return d.x * d.x + d.y * d.y + d.z * d.z;
        if (metric == 1.0) return d.x + d.y + d.z;  // POV's, signed
        return std::pow(std::fabs(d.x), metric) + std::pow(std::fabs(d.y), metric) + std::pow(std::fabs(d.z), metric);
    };
    glm::dvec3 nearest(0.0);
    double nearest_distance = 0.0;
    bool first = true;
    for (const glm::ivec3& offset : knight_offsets().offsets) {
        const glm::dvec3 shifted = cell_point + glm::dvec3(offset);
        const glm::dvec3 point =
            cube_point(floor_to_int(shifted.x - kPovEpsilon), floor_to_int(shifted.y - kPovEpsilon),
                       floor_to_int(shifted.z - kPovEpsilon));
        const double d = distance(point - cell_point);
        if (first || d < nearest_distance) {
            nearest = point;
            nearest_distance = d;
            first = false;
        }
    }
    if (s.facets_coords != 0.0) {
        // Tilt by the noise gradient at the nearest point, less its part
        // along the normal.
        glm::dvec3 tilt = pov_dnoise(nearest, s.generator);
        tilt -= normal * glm::dot(tilt, normal);
        normal += s.facets_coords * tilt;
    } else {
        normal = nearest;
    }
}

}  // namespace lancer::pattern_detail
