// POV-Ray's quilted pattern and normal: each unit cube bulges like a
// cushion, shaped by a cubic with control points control0 and control1;
// and POV 3.7's tiling N (J. Grimbert's tilings of the x-z plane): each
// tiling folds the point into one tile by its symmetries, then gives the
// tile's kind and how far the point is from the tile's centre towards its
// edge (a single kind: 0 inside to 1 on the edge; k kinds: kind/k plus
// that share). Tilings 13 to 24 are in polygon_tilings.cpp, 25 to 27 in
// penrose_tilings.cpp.
#include <algorithm>
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

// The cushion's offset from its cube's centre, scaled by the Bezier cubic
// (end points 0 and 1) of its length; 1.154700538 is POV's rounding of
// 2 / sqrt(3), which brings the cube's corner to 1.
// POV's FLOOR(): like floor() except at negative integers, which it
// takes one lower.
double pov_floor(double v) {
    return v >= 0.0 ? std::floor(v) : -std::floor(-v) - 1.0;
}

glm::dvec3 cushion(const PatternSetup& s, const glm::dvec3& p) {
    const glm::dvec3 offset(p.x - pov_floor(p.x) - 0.5, p.y - pov_floor(p.y) - 0.5, p.z - pov_floor(p.z) - 0.5);
    const double t = std::sqrt(offset.x * offset.x + offset.y * offset.y + offset.z * offset.z);
    const double it = 1.0 - t;
    const double it2 = it * it, t2 = t * t, t3 = t * t2;
    const double shaped = (t3 + 3.0 * t * it2 * s.quilted_control0 + 3.0 * t2 * it * s.quilted_control1) * 1.154700538;
    return offset * shaped;
}

}  // namespace

double quilted_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const glm::dvec3 c = cushion(s, p);
    return (std::fabs(c.x) + std::fabs(c.y) + std::fabs(c.z)) / 3.0;
}

void quilted_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal) {
    normal += amount * cushion(s, p);
}

namespace {

constexpr double kSqrt3 = 1.7320508075688772935274463415059;
constexpr double kHalfSqrt3 = 0.86602540378443864676372317075294;
constexpr double kSqrt2 = 1.4142135623730950488016887242097;
constexpr double kHalfSqrt2 = 0.70710678118654752440084436210485;

// v modulo period, in [0, period).
double wrap(double v, double period) {
    return v - period * std::floor(v / period);
}

// 0 at the centre line of a unit band to 1 at its edges.
double band(double v) {
    return 2.0 * std::fabs(v - 0.5);
}

// 1: squares of side 1.
double squares(double x, double z) {
    x = std::fabs(x);
    z = std::fabs(z);
    return std::max(band(x - std::floor(x)), band(z - std::floor(z)));
}

// 2: hexagons of side 1, a vertex on the x axis.
double hexagons(double x, double z) {
    x = wrap(x + 0.5, 3.0);
    z = wrap(z, kSqrt3);
    if (z > kHalfSqrt3) z = kSqrt3 - z;
    if (x > 1.5) {
        x -= 1.5;
        z = kHalfSqrt3 - z;
    }
    // [0, 1.5] x [0, sqrt3/2]: a neighbour's corner at the lower left.
    if (kSqrt3 * x + z < kHalfSqrt3) {
        x = 0.5 - x;
        z = kHalfSqrt3 - z;
    }
    if (x > 1.0) x = 2.0 - x;
    const double across = 1.0 - z / kHalfSqrt3;
    const double slanted = 1.0 - (kSqrt3 * x + z - kHalfSqrt3) / kSqrt3;
    return std::clamp(std::max(across, slanted), 0.0, 1.0);
}

// Folds (x, z) in the strip [0, 0.5] x [0, sqrt3/2] across the side of
// the triangle with its apex at (0.5, sqrt3/2): true when it did.
bool fold_triangle(double& x, double& z) {
    if (x != 0.0 ? z / x > kSqrt3 : true) {
        z = kHalfSqrt3 - z;
        x = 0.5 - x;
        return true;
    }
    return false;
}

// 3: equilateral triangles of side 1, up and down (two kinds).
double triangles(double x, double z) {
    int kind = 0;
    x -= std::floor(x);
    z = wrap(z, kSqrt3);
    if (z > kHalfSqrt3) {
        z = kSqrt3 - z;
        kind = 1 - kind;
    }
    if (x > 0.5) x = 1.0 - x;
    if (x != 0.0) {
        if (fold_triangle(x, z)) kind = 1 - kind;
    } else {
        z = kHalfSqrt3 - z;
        x = 0.5;
    }
    const double base = 1.0 - z * 2 * kSqrt3;
    const double side = 1.0 - (kSqrt3 * x - z) * kSqrt3;
    return kind / 2.0 + 0.5 * std::max(base, side);
}

// The lozenge (60 degree rhombus) measure shared by tilings 4 and 5 on a
// point in [0, 1] x [0, sqrt3/2] (x may be shifted by up to 1.5).
double lozenge_measure(double x, double z) {
    if (2.0 * z > kHalfSqrt3) {
        z = kHalfSqrt3 - z;
        x = 1.5 - x;
    }
    if (x > 0.75) x -= 1.0;
    if (x != 0.0) fold_triangle(x, z);
    const double across = 1.0 - z * 4.0 * kSqrt3 / 3.0;
    const double slanted = 1.0 - std::fabs(kSqrt3 * x - z) * kSqrt3 * 2.0 / 3.0;
    return std::max(across, slanted);
}

// 4: lozenges, all the same way.
double lozenges(double x, double z) {
    x -= std::floor(x);
    z = wrap(z, kSqrt3);
    if (z > kHalfSqrt3) {
        z -= kHalfSqrt3;
        x += 0.5;
    }
    return lozenge_measure(x, z);
}

// 5: lozenges three ways round (a cube's faces seen along its diagonal):
// three kinds.
double rhombuses(double x, double z) {
    int kind = 0;
    x = wrap(x + 0.5, 3.0);
    z = wrap(z, kSqrt3);
    if (z > kHalfSqrt3) {
        z = kSqrt3 - z;
        kind = 2 - kind;
    }
    if (x > 1.5) {
        x -= 1.5;
        z = kHalfSqrt3 - z;
        kind = 2 - kind;
    }
    if (x < 0.5) {
        x = 1.0 - x;
        kind = 2 - kind;
    }
    x -= 0.5;
    // The upright lozenge, turned onto the horizontal one at its right.
    if (x != 0.0 ? z / x > kSqrt3 : true) {
        const double turned_x = x / 2.0 + z * kHalfSqrt3;
        const double turned_z = z / 2.0 - x * kHalfSqrt3;
        x = turned_x;
        z = turned_z;
        kind = 1;
    }
    const double answer = lozenge_measure(x, z) / 3.0 + kind / 3.0;
    return std::clamp(answer, 0.0, 1.0);
}

// 6: 2 x 1 bricks in a basket weave, lying along x (kind 1) or z (kind 0),
// laid out on a 4 x 4 repeat.
double rectangles(double x, double z) {
    x = wrap(x, 4.0);
    z = wrap(z, 4.0);
    // Per unit cell of the 4 x 4 square (row z, column x): the offset that
    // brings its brick to the origin, and whether it lies along x.
    struct Cell {
        double dx, dz;
        bool along_x;
    };
    static constexpr Cell kCells[16] = {
        {0, 1, true},  {2, 0, false}, {2, 0, false}, {3, 0, true},   // row 0
        {0, 1, true},  {1, 2, true},  {3, 1, false}, {3, 1, false},  // row 1
        {0, 2, false}, {1, 2, true},  {2, 3, true},  {4, 2, false},  // row 2
        {1, 3, false}, {1, 3, false}, {2, 3, true},  {3, 4, true},   // row 3
    };
    // (x or z rounds to 4 just below a multiple of 4: POV's switch then
    // matches no cell and moves nothing.)
    static constexpr Cell kNoCell = {0, 0, true};
    const int column = truncated_int(x), row = truncated_int(z);
    const Cell& cell = column < 4 && row < 4 ? kCells[column + row * 4] : kNoCell;
    x -= cell.dx;
    z -= cell.dz;
    double along, across;
    if (cell.along_x) {
        across = band(x);
        along = 2 * (std::max(std::fabs(z), 0.5) - 0.5);
    } else {
        across = 2 * (std::max(std::fabs(x), 0.5) - 0.5);
        along = band(z);
    }
    return std::fabs(std::max(across, along) / 2.0 + (cell.along_x ? 0.5 : 0.0));
}

// 7: octagons and squares (side sqrt2/2... the octagon's side 1).
double octagons_squares(double x, double z) {
    const double period = kSqrt2 + 1.0;
    x = std::fabs(wrap(x, period) - (kHalfSqrt2 + 0.5));
    z = std::fabs(wrap(z, period) - (kHalfSqrt2 + 0.5));
    if (z > x) std::swap(x, z);
    if (x + z < kHalfSqrt2) return (x + z) / kSqrt2;  // the square
    const double across = 1.0 - z;
    const double slanted = (kSqrt2 + kHalfSqrt2 - (x + z)) / kSqrt2;
    return std::max(0.500000000001, std::max(across, slanted));
}

// 8: rows of squares between rows of triangles (three kinds: the two
// triangles, then the square).
double squares_triangles(double x, double z) {
    int kind = 0;
    x -= std::floor(x);
    z = wrap(z, 2.0 + kSqrt3);
    if (z > kHalfSqrt3 + 1.0) {
        z -= kHalfSqrt3 + 1.0;
        x += x > 0.5 ? -0.5 : 0.5;
    }
    if (x > 0.5) x = 1.0 - x;
    z -= 1.0;
    if (z > 0.0) {
        if (x != 0.0) {
            if (fold_triangle(x, z)) kind = 1 - kind;
        } else {
            z = kHalfSqrt3 - z;
            x = 0.5;
            kind = 1 - kind;
        }
        const double base = 1.0 - 2 * z * kSqrt3;
        const double side = 1.0 - (kSqrt3 * x - z) * kSqrt3;
        return (kind + std::max(base, side)) / 3.0;
    }
    if (z < -0.5) z = -1.0 - z;
    if (x > 0.5) x = 1.0 - x;
    const double from_x = std::min(2 + 2 * kSqrt3 * std::fabs(x), 3.0);
    const double from_z = std::min(2 + 2 * kSqrt3 * std::fabs(z), 3.0);
    return (5.0000001 - std::min(from_x, from_z)) / 3.0;
}

// 9: hexagons with triangles between (three kinds: two triangles, then
// the hexagon).
double hexagons_triangles(double x, double z) {
    int kind = 0;
    x = wrap(x + 0.5, 2.0);
    z = wrap(z, 2.0 * kSqrt3);
    if (z > kSqrt3) {
        z -= kSqrt3;
        x += x < 1.0 ? 1.0 : -1.0;
    }
    if (z > kHalfSqrt3) {
        z = kSqrt3 - z;
        kind = 1 - kind;
    }
    if (x > 1.0) x = 2.0 - x;
    // [0, 1] x [0, sqrt3/2]: the triangle at the lower left, the hexagon's
    // centre at the upper right.
    if (kSqrt3 * x + z < kHalfSqrt3) {
        const double base = 1.0 - z * 2 * kSqrt3;
        const double side = 1.0 + (kSqrt3 * x + z - kHalfSqrt3) * kSqrt3;
        return (kind + std::max(base, side)) / 3.0;
    }
    const double across = 2 + 2 * (z * kSqrt3);
    const double slanted = 2 + 2 * (kSqrt3 * x + z - kHalfSqrt3) * kHalfSqrt3;
    return std::max(5.0 - std::min(across, slanted), 2.0000001) / 3.0;
}

// 10: squares, each row shifted by half a square.
double squares_offset(double x, double z) {
    z = wrap(z, 2.0);
    if (z > 1.0) {
        x += 0.5;
        z -= 1.0;
    }
    x -= std::floor(x);
    return std::max(band(x), band(z));
}

// 11 and 12: a unit square ringed by four 2 x 1 bricks, on a 3 x 3
// repeat (three kinds: the square, bricks along z, bricks along x); x and
// z are in [0, 3] (12 mirrors the repeat, so they may reach 3: the index
// then runs past the nine cells as POV's does, and moves nothing).
double square_in_bricks(double x, double z) {
    enum Shape { Square, AlongZ, AlongX };
    struct Cell {
        double dx, dz;
        Shape shape;
    };
    static constexpr Cell kCells[9] = {
        {0, 1, AlongX}, {2, 0, AlongZ}, {2, 0, AlongZ},  // row 0
        {0, 1, AlongX}, {1, 1, Square}, {2, 2, AlongX},  // row 1
        {1, 2, AlongZ}, {1, 2, AlongZ}, {2, 2, AlongX},  // row 2
    };
    static constexpr Cell kNoCell = {0, 0, AlongX};
    const int index = truncated_int(x) + truncated_int(z) * 3;
    const Cell& cell = index < 9 ? kCells[index] : kNoCell;
    x -= cell.dx;
    z -= cell.dz;
    switch (cell.shape) {
    case AlongZ:
        x = 2.0 * (std::max(std::fabs(x), 0.5) - 0.5);
        z = 2.0 * std::fabs(z - 0.5);
        break;
    case AlongX:
        x = 2.0 * std::fabs(x - 0.5);
        z = 2.0 * (std::max(std::fabs(z), 0.5) - 0.5);
        break;
    case Square:
        x = 2.0 * std::fabs(x - 0.5);
        z = 2.0 * std::fabs(z - 0.5);
        break;
    }
    return (std::max(x, z) + double(cell.shape)) / 3.0;
}

}  // namespace

double tiling_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const double x = p.x, z = p.z;
    switch (s.tiling_type) {
    case 2: return hexagons(x, z);
    case 3: return triangles(x, z);
    case 4: return lozenges(x, z);
    case 5: return rhombuses(x, z);
    case 6: return rectangles(x, z);
    case 7: return octagons_squares(x, z);
    case 8: return squares_triangles(x, z);
    case 9: return hexagons_triangles(x, z);
    case 10: return squares_offset(x, z);
    case 11: return square_in_bricks(wrap(x, 3.0), wrap(z, 3.0));
    case 12: return square_in_bricks(std::fabs(wrap(x, 6.0) - 3.0), std::fabs(wrap(z, 6.0) - 3.0));
    case 13:
    case 14:
    case 15:
    case 16:
    case 17:
    case 18:
    case 19:
    case 20:
    case 21:
    case 22:
    case 23:
    case 24: return polygon_tiling(s.tiling_type, x, z);
    case 25:
    case 26:
    case 27: return penrose_tiling(s.tiling_type, x, z);
    default: return squares(x, z);
    }
}

}  // namespace lancer::pattern_detail
