// POV-Ray's block patterns: which entry of the pattern's list (0-based)
// holds at a point, for checker (2), hexagon (3), brick (2: mortar, brick),
// cubic (6), square (4) and triangular (6).
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

int checker_block(const glm::dvec3& p) {
    // The parity of the sum of the cell numbers (unsigned: the sum wraps).
    const unsigned sum = unsigned(floor_to_int(p.x + kPovEpsilon)) + unsigned(floor_to_int(p.y + kPovEpsilon)) +
                         unsigned(floor_to_int(p.z + kPovEpsilon));
    return int(sum & 1u);
}

namespace {

// Hexagon: the x-z plane is cut into a 6 x 6 grid of half-width by
// triangle-height blocks; each block holds one colour or is split
// diagonally between two.
constexpr double kHexBlockWidth = 0.5;
constexpr double kHexBlockHeight = 0.866025404;  // sqrt(3)/2, POV's rounding
constexpr double kHexGridHeight = 5.196152424;   // six block heights, POV's rounding

// The colour of a block in columns 0/5 and 2/3, by its row.
constexpr int kHexEdgeColumns[6] = {0, 1, 1, 2, 2, 0};
constexpr int kHexMiddleColumns[6] = {2, 2, 0, 0, 1, 1};
// Split blocks (columns 1 and 4): below and above the diagonal, by row.
constexpr int kHexBelowDiagonal[6] = {0, 2, 1, 0, 2, 1};
constexpr int kHexAboveDiagonal[6] = {2, 1, 0, 2, 1, 0};

}  // namespace

int hexagon_block(const glm::dvec3& p) {
    const double x = std::fabs(p.x);
    // Negative z is moved up a whole grid rather than mirrored.
    const double z = p.z < 0.0 ? kHexGridHeight - std::fabs(p.z) : p.z;
    const double xs = wrap_into(x / kHexBlockWidth, 6.0);
    const double zs = wrap_into(z / kHexBlockHeight, 6.0);
    const int column = int(std::floor(xs)) % 6;
    const int row = int(std::floor(zs)) % 6;
    switch (column) {
    case 0:
    case 5: return kHexEdgeColumns[row];
    case 2:
    case 3: return kHexMiddleColumns[row];
    default: break;
    }
    double xl = xs - column;
    const double zl = zs - row;
    // Blocks whose diagonal falls to the right are flipped to rise.
    if ((column + row) % 2 == 1) xl = 1.0 - xl;
    if (xl == 0.0) xl = 0.0001;
    return zl / xl < 1.0 ? kHexBelowDiagonal[row] : kHexAboveDiagonal[row];
}

namespace {

// POV's v - (int)v, wrapped into [0, 1); trunc keeps it defined beyond int.
double fraction(double v) {
    v -= std::trunc(v);
    return v < 0.0 ? v + 1.0 : v;
}

}  // namespace

int brick_block(const PatternSetup& s, const glm::dvec3& p) {
    // Index 0 is the mortar, 1 the brick.
    const double nudge = kPovEpsilon + s.brick_mortar;
    const double x = p.x + nudge, y = p.y + nudge, z = p.z + nudge;
    const glm::dvec3 size = s.brick_size;
    const double mortar = s.brick_mortar;
    // Bed joints between the courses.
    if (fraction(y / size.y) <= mortar / size.y) return 0;
    // Odd and even courses: head joints offset by half a brick.
    const bool upper_course = fraction(y / size.y * 0.5) > 0.5;
    const double mortar_x = mortar / size.x, mortar_z = mortar / size.z;
    if (!upper_course && fraction(x / size.x) <= mortar_x) return 0;
    if (upper_course && fraction(x / size.x + 0.5) <= mortar_x) return 0;
    if (upper_course && fraction(z / size.z) <= mortar_z) return 0;
    if (!upper_course && fraction(z / size.z + 0.5) <= mortar_z) return 0;
    return 1;
}

int cubic_block(const glm::dvec3& p) {
    const double ax = std::fabs(p.x), ay = std::fabs(p.y), az = std::fabs(p.z);
    if (p.x >= 0 && p.x >= ay && p.x >= az) return 0;
    if (p.y >= 0 && p.y >= ax && p.y >= az) return 1;
    if (p.z >= 0 && p.z >= ax && p.z >= ay) return 2;
    if (p.x < 0 && p.x <= -ay && p.x <= -az) return 3;
    if (p.y < 0 && p.y <= -ax && p.y <= -az) return 4;
    return 5;
}

int square_block(const glm::dvec3& p) {
    const bool odd_x = floor_to_int(p.x) & 1;
    const bool odd_z = floor_to_int(p.z) & 1;
    if (odd_x) return odd_z ? 2 : 3;
    return odd_z ? 1 : 0;
}

int triangular_block(const glm::dvec3& p) {
    constexpr double kSqrt3 = 1.7320508075688772935274463415059;
    constexpr double kHalfSqrt3 = 0.86602540378443864676372317075294;
    // Fold into the 3 x sqrt(3) rectangle that repeats, then mirror its
    // upper half onto the lower.
    double xs = wrap_into(p.x, 3.0);
    double zs = wrap_into(p.z, kSqrt3);
    const int column = int(std::floor(xs));
    xs -= column;
    const bool upper = zs >= kHalfSqrt3;
    if (upper) zs = kSqrt3 - zs;
    // Which of the three triangles of the unit-wide strip: 0 the upright
    // one in the middle, 1 left of it, 3 right of it.
    int triangle = 1;
    const double rest = 1.0 - xs;
    if (xs != 0.0 && rest != 0.0) {
        const bool below_left = zs / xs < kSqrt3;
        const bool below_right = zs / rest < kSqrt3;
        if (below_left && below_right)
            triangle = 0;
        else if (below_right)
            triangle = 1;
        else if (below_left)
            triangle = 3;
        else
            triangle = 0;  // unreachable but for rounding; POV leaves it unset
    }
    double index =
        (triangle & 1) ? std::fmod(triangle + 2.0 * column, 6.0) : std::fmod(6.0 + triangle - 2.0 * column, 6.0);
    if (upper) index = 5.0 - index;
    return int(index);
}

}  // namespace lancer::pattern_detail
