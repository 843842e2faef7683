// POV 3.7's tiling 13 to 24 (J. Grimbert's tilings of the x-z plane that
// mix polygons of several kinds or sizes). As for tiling 1 to 12, each
// folds the point by the tiling's symmetries into a small domain, decides
// which tile it lies in there, and returns kind/k plus the tile's share of
// 1/k: 0 at the tile's centre (or over a flat core) to 1/k on its edge,
// or the reverse for some kinds (POV's choice, kept). Where POV nudges a
// value off a kind boundary (2.0000001 and the like) the nudge is POV's,
// kept so that the values agree.
#include <algorithm>
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

constexpr double kSqrt3 = 1.7320508075688772935274463415059;
constexpr double kHalfSqrt3 = 0.86602540378443864676372317075294;
constexpr double kSqrt2 = 1.4142135623730950488016887242097;

// 0 over the middle half of a tile's extent [-1, 1] to 1 at its edge:
// POV's measure of its 2-unit squares and bricks along their length.
double core_to_edge(double offset) {
    return 2.0 * (std::max(std::fabs(offset), 0.5) - 0.5);
}

// 0 on the centre line of a unit band [0, 1] to 1 at its edges.
double across_band(double v) {
    return 2.0 * std::fabs(v - 0.5);
}

// ---- 13 and 14: squares of side sqrt2, each ringed by four trapezoids
// (parallel sides sqrt2 and 2 sqrt2). Scaled by sqrt2 the repeat is 4 x
// 4, a square centred at the middle of each; folded by |.| into [0, 2]^2
// the square's quarter covers [0, 1]^2 (its measure flat up to 0.5) and
// the trapezoids fill the L around it, parted along the diagonal x = z.
// A trapezoid's measure is the larger of its distance across from its
// mid-line (1.5) and its distance from the diagonal.
struct SquareInSquaresPoint {
    bool in_square;
    bool along_x;  // the trapezoid lies along x (else along z)
    double measure;
};

SquareInSquaresPoint square_in_squares(double x, double z) {
    const bool far_x = x >= 1.0, far_z = z >= 1.0;
    if (!far_x && !far_z) {
        const double across = 2.0 * std::max(std::max(x - 0.5, 0.0), std::max(z - 0.5, 0.0));
        return {true, false, across};
    }
    // Which trapezoid: the far coordinate's, or the larger when both are.
    const bool along_x = far_x && (!far_z || x > z);
    const double along = along_x ? x : z, other = along_x ? z : x;
    double measure = std::fabs(1.5 - along) * 2.0;
    if (other > 0.5) measure = std::max(measure, 1.0 - kSqrt2 * std::fabs(along - other));
    return {false, along_x, measure};
}

// 13: three kinds (the square; trapezoids along z; along x).
double square_in_squares_3(double x, double z) {
    x = std::fabs(wrap_into(x * kSqrt2, 4.0) - 2.0);
    z = std::fabs(wrap_into(z * kSqrt2, 4.0) - 2.0);
    const SquareInSquaresPoint at = square_in_squares(x, z);
    if (at.in_square) return at.measure / 3.0;
    return ((at.along_x ? 2.0 : 1.0) + at.measure) / 3.0;
}

// 14: five kinds: the trapezoids on each side of the square apart (left,
// right, below, above: the side is the sign before folding), then the
// square.
double square_in_squares_5(double x, double z) {
    x = wrap_into(x * kSqrt2, 4.0) - 2.0;
    z = wrap_into(z * kSqrt2, 4.0) - 2.0;
    const int side_x = x < 0.0 ? 1 : 0;
    const int side_z = z < 0.0 ? 2 : 3;
    const SquareInSquaresPoint at = square_in_squares(std::fabs(x), std::fabs(z));
    if (at.in_square) return (4.000001 + at.measure) / 5.0;
    return (at.measure + (at.along_x ? side_x : side_z)) / 5.0;
}

// ---- 15: squares of side 1 and 2 (the Pythagorean tiling). Its lattice
// is spanned by (2, 1) and (-1, 2), so it repeats over 5 x 5: the small
// squares sit on the unit cells (i, j) with i = 2j mod 5, and the large
// ones are centred on the corners (i, j) with i = 2j + 2 mod 5. A unit
// cell not a small square lies in the large square centred on one of its
// four corners. (Small squares: 0 to 1/2; large ones: 1/2 to 1.)
bool on_lattice(int i, int j, int shift) {
    return ((i - 2 * j - shift) % 5 + 5) % 5 == 0;
}

double two_squares(double x, double z) {
    x = wrap_into(x, 5.0);
    z = wrap_into(z, 5.0);
    const int i = truncated_int(x), j = truncated_int(z);
    if (on_lattice(i, j, 0)) return std::max(across_band(x - i), across_band(z - j)) / 2.0;
    for (int corner = 0; corner < 4; ++corner) {
        const int ci = i + (corner & 1), cj = j + (corner >> 1);
        if (on_lattice(ci, cj, 2)) {
            return std::max(core_to_edge(x - ci), core_to_edge(z - cj)) / 2.0 + 0.50000001;
        }
    }
    return 0.0;  // i or j rounded to 5: POV's switch moves nothing here either
}

// ---- 16 and 17: hexagons, squares and triangles (the rhombitrihexagonal
// tiling 3.4.6.4), hexagons of side 1. The repeat (3 + sqrt3) x 2(1 +
// sqrt3) holds two hexagons, the second a glide of the first; then
// mirrors about both axes of the hexagon and a turn by 60 degrees about
// its centre bring every point into [0, 1 + sqrt3/2]^2 with the hexagon's
// centre at the upper right, half a square at the lower right and half
// a triangle at the lower left. The turn and mirrors are tracked, as the
// six-kind version tells the squares and triangles apart by them.
struct HexSquareTrianglePoint {
    double x, z;
    int mirrored_x = 0, mirrored_z = 0, turned = 0;
};

HexSquareTrianglePoint fold_hex_square_triangle(double x, double z) {
    constexpr double kHalfWidth = kHalfSqrt3 + 1.5;  // half the repeat's width
    constexpr double kHalfHeight = kSqrt3 + 1.0;     // half its height
    constexpr double kCentreX = 1.0 + kHalfSqrt3;    // the hexagon's centre
    constexpr double kCentreZ = 0.5 + kHalfSqrt3;
    HexSquareTrianglePoint folded;
    x = wrap_into(x + 0.5, 3.0 + kSqrt3);
    z = wrap_into(z, 2.0 * kHalfHeight);
    if (x > kHalfWidth) {
        x -= kHalfWidth;
        z += z < kHalfHeight ? kCentreZ : -kCentreZ;
    }
    if (z > kHalfHeight) z -= kHalfHeight;
    if (z > kCentreZ) {
        z = kHalfHeight - z;
        folded.mirrored_z = 1;
    }
    if (x > kCentreX) {
        x = kSqrt3 + 2.0 - x;
        folded.mirrored_x = 1;
    }
    // Left of the hexagon's lower-left side and of the square: the other
    // square and triangle, which a turn about the centre brings here.
    if (kSqrt3 * x + z < kHalfSqrt3 + 2.0 && x < 0.5 + kHalfSqrt3) {
        const double dx = x - kCentreX, dz = z - kCentreZ;
        x = dx / 2.0 - dz * kHalfSqrt3 + kCentreX;
        z = std::fabs(dz / 2.0 + dx * kHalfSqrt3 + kCentreZ);
        folded.turned = 1;
        if (x > kCentreX) {
            x = kSqrt3 + 2.0 - x;
            folded.mirrored_x ^= 1;
            folded.mirrored_z ^= 1;
        }
    }
    folded.x = x;
    folded.z = z;
    return folded;
}

enum class HexSquareTriangleShape { Hexagon, Square, Triangle, None };

// Which tile the folded point is in, and its measure there.
HexSquareTriangleShape hex_square_triangle_shape(const HexSquareTrianglePoint& folded, double& measure) {
    const double x = folded.x, z = folded.z;
    if (!(kSqrt3 * x + z < kHalfSqrt3 + 2.0) && !(z < 0.5)) {
        const double dz = std::fabs(z - 0.5), dx = std::fabs(x - kHalfSqrt3);
        measure = std::min(2.0 * dz * kSqrt3, (kSqrt3 * dx + dz) * kSqrt3 - 1.5);
        return HexSquareTriangleShape::Hexagon;
    }
    if (!(z < 0.5)) return HexSquareTriangleShape::None;
    const double dx = x - (kHalfSqrt3 + 0.5);
    if (dx > 0.0) {
        const double from_hexagon = std::max(1.0 + (z - 0.5) * 2.0 * kSqrt3, 0.0);
        const double from_middle = std::max(1.0 - dx * 2.0 * kSqrt3, 0.0);
        measure = std::max(from_hexagon, from_middle);
        return HexSquareTriangleShape::Square;
    }
    const double across = std::fabs(dx);
    measure = std::max(2.0 - across * 2.0 * kSqrt3, (kSqrt3 * z + across) * kSqrt3 + 0.5);
    return HexSquareTriangleShape::Triangle;
}

// 16: three kinds (squares, triangles, hexagons; the triangle's measure
// runs from 1, its centre, and the hexagon's down to 2 at its edge).
double hex_square_triangle_3(double x, double z) {
    double measure = 0.0;
    switch (hex_square_triangle_shape(fold_hex_square_triangle(x, z), measure)) {
    case HexSquareTriangleShape::Hexagon: return std::max(3.0 - measure, 2.0000001) / 3.0;
    case HexSquareTriangleShape::Square:
    case HexSquareTriangleShape::Triangle: return measure / 3.0;
    case HexSquareTriangleShape::None: break;
    }
    return 0.0;
}

// 17: six kinds: the three square orientations, the two triangle ones,
// then the hexagon.
double hex_square_triangle_6(double x, double z) {
    const HexSquareTrianglePoint folded = fold_hex_square_triangle(x, z);
    double measure = 0.0;
    switch (hex_square_triangle_shape(folded, measure)) {
    case HexSquareTriangleShape::Hexagon: return std::max(6.0 - measure, 5.000001) / 6.0;
    case HexSquareTriangleShape::Square:
        return (measure + folded.turned * (1.000001 + (folded.mirrored_x + folded.mirrored_z) % 2)) / 6.0;
    case HexSquareTriangleShape::Triangle:
        return (((folded.turned + folded.mirrored_x) % 2 ? 2.0 : 3.0) + measure) / 6.0;
    case HexSquareTriangleShape::None: break;
    }
    return 0.0;
}

// ---- 18: 2 x 1 bricks in pairs, the pairs in a checkerboard of 2 x 2
// blocks: on even blocks the pair lies along z (kind 1, 1/2 to 1), on odd
// ones along x (kind 0).
double brick_pairs(double x, double z) {
    x = wrap_into(x, 4.0);
    z = wrap_into(z, 4.0);
    const int i = truncated_int(x), j = truncated_int(z);
    double across, along, kind;
    if ((i / 2 + j / 2) % 2 == 0) {
        across = across_band(x - i);
        along = core_to_edge(z - (j / 2 * 2 + 1));
        kind = 1.0;
    } else {
        across = across_band(z - j);
        along = core_to_edge(x - (i / 2 * 2 + 1));
        kind = 0.0;
    }
    return std::fabs((std::max(across, along) + kind) / 2.0);
}

// The measure of POV's triangle tiles of side 1 (as tiling 3): folds
// (x, z) into the half triangle by the triangle lattice's symmetries,
// toggling `kind` at each mirror that swaps up and down triangles.
double triangle_tile_measure(double x, double z, int& kind) {
    x -= std::floor(x);
    z = wrap_into(z, kSqrt3);
    if (z > kHalfSqrt3) {
        z = kSqrt3 - z;
        kind ^= 1;
    }
    if (x > 0.5) x = 1.0 - x;
    if (x == 0.0 || z / x > kSqrt3) {
        z = kHalfSqrt3 - z;
        x = x == 0.0 ? 0.5 : 0.5 - x;
        kind ^= 1;
    }
    const double from_base = 1.0 - z * 2.0 * kSqrt3;
    const double from_side = 1.0 - (kSqrt3 * x - z) * kSqrt3;
    return std::max(from_base, from_side);
}

// ---- 19 and 20: hexagons of side 1 among triangles (the snub hexagonal
// tiling 3.3.3.3.6, right or left handed). Rows of height 3 sqrt3/2 are
// sheared by half a unit each (`hand` +1 or -1) to make a rectangular
// repeat of width 7; three translations (which differ by hand) bring its
// hexagon's pieces together over [0, 2.5] x [0, 3 sqrt3/2], where a
// mirror about the hexagon's centre row leaves the lower half: the
// hexagon's two rows of triangles' worth, else triangles. Kinds: the two
// triangle orientations, then the hexagon.
double snub_hexagons(double x, double z, int hand) {
    int row = truncated_int(z / kHalfSqrt3) / 3;  // POV's own truncating count
    if (z < 0.0) row -= 1;
    x += hand * (row / 2.0);
    z = wrap_into(z, 3.0 * kHalfSqrt3);
    x = wrap_into(x + 7.0, 7.0);
    if (hand > 0) {
        if (x > 4.5 && z > kSqrt3) {
            x -= 4.5;
            z -= kHalfSqrt3;
        }
        if (x > 5.0 && z < kHalfSqrt3) {
            x -= 5.0;
            z += kSqrt3;
        }
        if (x > 2.5 && z < kSqrt3) {
            x -= 2.5;
            z += kHalfSqrt3;
        }
    } else {
        if (x > 2.0 && z < kHalfSqrt3) {
            x -= 2.0;
            z += kSqrt3;
        }
        if (x > 4.5 && z < kSqrt3) {
            x -= 4.5;
            z += kHalfSqrt3;
        }
        if (x > 2.5 && z > kSqrt3) {
            x -= 2.5;
            z -= kHalfSqrt3;
        }
    }
    int kind = 0;
    int band = truncated_int(z / kHalfSqrt3);
    if (band == 2) {
        band = 1;
        z = 2.0 * kSqrt3 - z;
        kind = 1;
    }
    const bool in_hexagon = band != 0 && x <= 2.0 && !(z + kSqrt3 * x < kSqrt3) && !(kSqrt3 * x - z > kSqrt3);
    if (!in_hexagon) return (triangle_tile_measure(x, z, kind) + kind) / 3.0;
    z -= kHalfSqrt3;
    if (x > 1.0) x = 2.0 - x;
    const double from_side = 2.0 + 2.0 * (z * kSqrt3);
    const double from_slant = 2.0 + 2.0 * (kSqrt3 * x + z - kHalfSqrt3) * kHalfSqrt3;
    return std::max(5.0 - std::min(from_side, from_slant), 2.000001) / 3.0;
}

// ---- 21: squares and triangles (the snub square tiling 3.3.4.3.4), side
// 1, repeat 1 + sqrt3 square. Mirrors about the repeat's middle lines
// leave a quarter, where the square at the middle of the repeat's corner
// cell is turned by a quarter (two ways) or a half onto the square at the
// quarter's lower left; the mirrors and turn pick the kind: four triangle
// orientations (0 to 4/6), then the two square orientations.
double snub_squares(double x, double z) {
    constexpr double kHalf = 0.5 + kHalfSqrt3;  // half the repeat
    int flips = 0;                              // mirrors taken, mod 2
    bool mirrored_x = false;
    x = wrap_into(x, 1.0 + kSqrt3);
    z = wrap_into(z, 1.0 + kSqrt3);
    if (z > kHalf) {
        z = 1.0 + kSqrt3 - z;
        flips ^= 1;
    }
    if (x > kHalf) {
        x = 1.0 + kSqrt3 - x;
        flips ^= 1;
        mirrored_x = true;
    }
    // The two lines through the quarter that part the four turned copies.
    const bool past_x = 2.0 * x + (kSqrt3 - 1.0) * 2.0 * z / (kSqrt3 + 1.0) > kSqrt3;
    const bool past_z = 2.0 * z * kSqrt3 + (kSqrt3 - 3.0) * 2.0 * x / (kSqrt3 + 1.0) > kSqrt3;
    int triangle_kind = 0;
    if (past_x && past_z) {
        triangle_kind = mirrored_x ? 0 : 2;
        x = kHalf - x;
        z = kHalf - z;
    } else if (past_x) {
        triangle_kind = mirrored_x ? 1 + 2 * flips : 3 - 2 * flips;
        const double old_x = x;
        x = z;
        z = kHalf - old_x;
    } else if (past_z) {
        triangle_kind = mirrored_x ? 3 - 2 * flips : 1 + 2 * flips;
        const double old_z = z;
        z = x;
        x = kHalf - old_z;
    } else {
        triangle_kind = mirrored_x ? 2 : 0;
    }
    if (x == 0.0) z = 0.0;
    // Signed distance (scaled) from the side the triangle and square share.
    const double shared_side = (z * 2.0 * kSqrt3) - kSqrt3 + x * 2.0;
    if (shared_side < 0.0) {
        const double measure = std::min(-1.5 / kSqrt3 * shared_side, 2.0 * x * kSqrt3);
        return (triangle_kind + 1.0 - measure) / 6.0;
    }
    const double measure = std::min(shared_side * (1.5 / kSqrt3), 1.0);
    if (flips) return std::min(std::max((6.0 - measure) / 6.0, 5.000001 / 6.0), 1.0);
    return std::max(std::min((5.0 - measure) / 6.0, 5.0 / 6.0), 4.000001 / 6.0);
}

// ---- 22: dodecagons and triangles (the truncated hexagonal tiling
// 3.12.12), side 1. The repeat (2 + sqrt3) x (3 + 2 sqrt3) holds two
// dodecagons (the second shifted by half the repeat); mirrors leave a
// quarter dodecagon with a triangle at its lower left, and points beyond
// the dodecagon's 30-degree side are turned onto the side below. Kinds:
// the two triangle orientations (0 to 2/3, measured from their edge),
// then the dodecagon.
double dodecagons_triangles(double x, double z) {
    x = wrap_into(x, 2.0 + kSqrt3);
    z = wrap_into(z, 3.0 + 2.0 * kSqrt3);
    int kind = 0;
    if (z > kSqrt3 + 1.5) {
        z -= kSqrt3 + 1.5;
        x += (x < 1.0 + kHalfSqrt3 ? 1.0 : -1.0) * (1.0 + kHalfSqrt3);
    }
    if (x > 1.0 + kHalfSqrt3) x = 2.0 + kSqrt3 - x;
    if (z > 1.0 + kHalfSqrt3) {
        z = 2.0 + kSqrt3 - z;
        kind = 1;
    }
    double from_slanted = x - kHalfSqrt3 - 0.5 + z * kSqrt3;
    if (from_slanted < 0.0) {
        // The reflection across that side's line (60 degrees).
        const double old_x = x, old_z = z;
        x = (1.0 + kSqrt3) / 4.0 + 0.5 * old_x - kHalfSqrt3 * old_z;
        z = (3.0 + kSqrt3) / 4.0 - kHalfSqrt3 * old_x - 0.5 * old_z;
        from_slanted = -from_slanted;
    }
    const double from_bottom = z * 3.0;
    const double from_triangle = (z - kHalfSqrt3 - 0.5 + x * kSqrt3) * kSqrt3;
    const double from_vertical = x * 3.0;
    if (from_triangle < 0.0) return (std::max(from_triangle, -1.0) + 1.0 + kind) / 3.0;
    const double inside = std::min({from_bottom, from_slanted * kSqrt3, from_triangle, from_vertical, 1.0});
    return (3.0000001 - inside) / 3.0;
}

// ---- 23 and 24: dodecagons, hexagons and squares (the truncated
// trihexagonal tiling 4.6.12), side 1. The repeat (3 + sqrt3) x (3 + 3
// sqrt3) holds two dodecagons (a half-repeat shift apart); mirrors leave
// a quarter dodecagon at the upper right, and the part beyond its lower
// slanted side turns onto the upper part. Outside the dodecagon: the
// square above, the hexagon at the left or below, or the slanted square.
// 23 has three kinds (hexagons, squares, dodecagons); 24 has five, as
// the squares above the dodecagon (kind 1) and the slanted squares of
// each slant (kinds 2 and 3, told apart by the mirrors) differ.
double dodecagons_hexagons_squares(double x, double z, int kinds) {
    x = wrap_into(x, 3.0 + kSqrt3);
    z = wrap_into(z, 3.0 + 3.0 * kSqrt3);
    int mirrors = 0;
    if (z > 1.5 * kSqrt3 + 1.5) {
        z -= 1.5 * kSqrt3 + 1.5;
        x += (x < 1.5 + kHalfSqrt3 ? 1.0 : -1.0) * (1.5 + kHalfSqrt3);
    }
    if (x > 1.5 + kHalfSqrt3) {
        x = 3.0 + kSqrt3 - x;
        mirrors ^= 1;
    }
    if (z > 1.0 + kSqrt3) {
        z = 2.0 + 2.0 * kSqrt3 - z;
        mirrors ^= 1;
    }
    if (x - kHalfSqrt3 - 1.5 + z * kSqrt3 < 0.0) {
        const double old_x = x, old_z = z;
        x = (3.0 + kSqrt3) / 4.0 + 0.5 * old_x - kHalfSqrt3 * old_z;
        z = (3.0 + 3.0 * kSqrt3) / 4.0 - kHalfSqrt3 * old_x - 0.5 * old_z;
    }
    // Signed distances (scaled) from the dodecagon's sides in this domain.
    const double slanted = x - kHalfSqrt3 - 2.5 + z * kSqrt3;
    const double bottom = (z * 2.0) - kSqrt3;
    const double steep = z - 1.5 * kSqrt3 - 0.5 + x * kSqrt3;
    const double vertical = (x - 0.5) * 2.0;
    const double top_kind = kinds == 5 ? 5.000001 : 3.000001;
    double answer;
    if (slanted >= 0.0 && bottom >= 0.0 && steep >= 0.0 && vertical >= 0.0) {
        answer = top_kind - std::min({bottom, slanted, steep, vertical, 1.0});
    } else {
        const double above = 2.0 * z - 2.0 * kSqrt3 - 1.0;
        if (above >= 0.0) {
            answer = 2.0 - std::min(above, -vertical);
        } else {
            const double left = kSqrt3 * x - z - kHalfSqrt3 + 0.5;
            const double right = left - 2.0;
            if (left < 0.0 && !(right >= 0.0)) {  // the hexagon at the left
                answer = 1.0 - std::min({-left, -steep, -above, 1.0});
            } else if (left >= 0.0 && right >= 0.0) {  // the hexagon below
                answer = 1.0 - std::min({right, -bottom, 1.0});
            } else {  // the slanted square
                const double measure = std::min({left, -slanted, -right});
                answer = kinds == 5 ? mirrors + 3.0 - measure : 2.0 - measure;
            }
        }
    }
    return answer / kinds;
}

}  // namespace

double polygon_tiling(int type, double x, double z) {
    switch (type) {
    case 13: return square_in_squares_3(x, z);
    case 14: return square_in_squares_5(x, z);
    case 15: return two_squares(x, z);
    case 16: return hex_square_triangle_3(x, z);
    case 17: return hex_square_triangle_6(x, z);
    case 18: return brick_pairs(x, z);
    case 19: return snub_hexagons(x, z, 1);
    case 20: return snub_hexagons(x, z, -1);
    case 21: return snub_squares(x, z);
    case 22: return dodecagons_triangles(x, z);
    case 23: return dodecagons_hexagons_squares(x, z, 3);
    case 24: return dodecagons_hexagons_squares(x, z, 5);
    default: return 0.0;
    }
}

}  // namespace lancer::pattern_detail
