// POV 3.7's pavement: the plane paved with polyforms (J. Grimbert's
// pattern). number_of_sides picks the cell (3: equilateral triangles of
// side 1, 4: unit squares, 6: hexagons of side 1), number_of_tiles how many
// cells make a tile (the polyiamonds, polyominoes, polyhexes), and pattern
// which of POV's pavings with those tiles. The value is 0 deep inside a
// tile and rises to 1 on its border; exterior shapes the tile's convex
// corners (0 sharp, 1 cut, 2 rounded; POV gives hexagons none), interior
// the points where tiles meet at a concave corner, and form the cells
// where a tile bends round a corner (squares: 0, 1 cut, 2 rounded, 3 left
// alone; triangles and hexagons: 1 cut, 2 rounded, 0 left alone).
//
// Each paving is a periodic map of tile letters: two cells are in the same
// tile when they are neighbours with the same letter. Everything else, a
// cell's border sides, its concave corners and the bends, is derived from
// its neighbours' letters. The maps are POV's pavings (the pattern numbers
// are its order), redrawn cell by cell from the tables in POV's source;
// the rules that derive the rest from them reproduce every entry of those
// tables, and the values agree with POV-Ray's own for every paving
// (tests/reference/pov/patterns/pavement*.txt holds a selection).
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iterator>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

// A periodic map of tile letters on a grid of cells (column, row): `rows`
// holds `height` rows of `width` letters, row 0 first; the block repeats
// along the columns every `width`, and the block above is shifted right
// by `shift` columns.
struct TileMap {
    int tiles, number;
    int width, height, shift;
    const char* rows;
};

std::int64_t floor_div(std::int64_t a, std::int64_t b) {
    const std::int64_t q = a / b;
    return (a % b != 0 && (a < 0) != (b < 0)) ? q - 1 : q;
}

char letter_at(const TileMap& map, std::int64_t column, std::int64_t row) {
    const std::int64_t block = floor_div(row, map.height);
    const std::int64_t r = row - block * map.height;
    std::int64_t c = (column - block * map.shift) % map.width;
    if (c < 0) c += map.width;
    return map.rows[r * map.width + c];
}

// ---- squares

// The polyomino pavings, by number_of_tiles and pattern.
constexpr TileMap kSquarePavings[] = {
    // 1 square
    {1, 1, 2, 2, 0,
     "ab"
     "cd"},
    // 2 squares
    {2, 1, 2, 4, 0,
     "ab"
     "ab"
     "cd"
     "cd"},
    // 3 squares
    {3, 1, 6, 2, 0,
     "aaabbb"
     "cccddd"},
    {3, 2, 3, 4, 0,
     "abb"
     "aab"
     "cdd"
     "ccd"},
    // 4 squares
    {4, 1, 8, 2, 0,
     "aaaabbbb"
     "ccccdddd"},
    {4, 2, 4, 4, 0,
     "abbb"
     "aaab"
     "cddd"
     "cccd"},
    {4, 3, 8, 2, 4,
     "aaabcccd"
     "badddcbb"},
    {4, 4, 4, 4, 0,
     "aabb"
     "aabb"
     "ccdd"
     "ccdd"},
    {4, 5, 4, 2, 1,
     "abba"
     "bbaa"},
    // 5 squares
    {5, 1, 10, 2, 0,
     "aaaaabbbbb"
     "cccccddddd"},
    {5, 2, 5, 4, 0,
     "abbbb"
     "aaaab"
     "cdddd"
     "ccccd"},
    {5, 3, 5, 2, 2,
     "abbaa"
     "bbbaa"},
    {5, 4, 10, 2, 6,
     "aaaabccccd"
     "bbaddddcbb"},
    {5, 5, 10, 1, 3, "aaababbbab"},
    {5, 6, 20, 1, 9, "abaaacccdcbabbbdddcd"},
    {5, 7, 20, 1, 9, "abccbbddaadcbbccaadd"},
    {5, 8, 20, 1, 7, "aaabcbcdddbbbadadccc"},
    {5, 9, 10, 2, 8,
     "abbbacdddc"
     "aaabdcccdb"},
    {5, 10, 5, 4, 4,
     "abbbc"
     "aaabd"
     "dacdd"
     "dbccc"},
    {5, 11, 5, 2, 1,
     "abbba"
     "bbaaa"},
    {5, 12, 10, 2, 4,
     "aaabbbcabd"
     "cadddcccbd"},
    // 6 squares
    {6, 1, 12, 2, 0,
     "aaaaaabbbbbb"
     "ccccccdddddd"},
    {6, 2, 6, 4, 0,
     "aaaaab"
     "abbbbb"
     "cccccd"
     "cddddd"},
    {6, 3, 6, 4, 0,
     "aaaaab"
     "babbbb"
     "cccccd"
     "dcdddd"},
    {6, 4, 6, 4, 0,
     "aaaaab"
     "bbabbb"
     "cccccd"
     "ddcddd"},
    {6, 5, 12, 2, 2,
     "aabbbbccdddd"
     "cbbaaaaddccc"},
    {6, 6, 6, 4, 0,
     "aaaabb"
     "aabbbb"
     "ccccdd"
     "ccdddd"},
    {6, 7, 6, 4, 0,
     "abbaaa"
     "bbbbaa"
     "cddccc"
     "ddddcc"},
    {6, 8, 12, 2, 2,
     "aaabbbcccddd"
     "cbbbaaadddcc"},
    {6, 9, 6, 4, 0,
     "abbbaa"
     "bbbaaa"
     "cdddcc"
     "dddccc"},
    {6, 10, 6, 4, 0,
     "aaabbb"
     "aaabbb"
     "cccddd"
     "cccddd"},
    {6, 11, 4, 6, 0,
     "abbb"
     "aabb"
     "aaab"
     "cddd"
     "ccdd"
     "cccd"},
    {6, 12, 12, 2, 10,
     "aaabbacccddc"
     "bbaabdddccdb"},
    {6, 13, 8, 3, 0,
     "aaaabbbb"
     "cacadbdb"
     "ccccdddd"},
    {6, 14, 6, 4, 0,
     "aaabbb"
     "caddbc"
     "caadbb"
     "ccdddc"},
    {6, 15, 6, 4, 2,
     "aaabbb"
     "caadbb"
     "cdddcc"
     "cbddac"},
    {6, 16, 12, 2, 8,
     "abbbaacdddcc"
     "aabbdcccddba"},
    {6, 17, 12, 2, 5,
     "aaaabcddddcb"
     "dabbbbadcccc"},
    {6, 18, 12, 2, 5,
     "abccccbadddd"
     "aaaadcbbbbcd"},
    {6, 19, 12, 2, 10,
     "abbbabcdddcd"
     "aaabadcccdcb"},
    {6, 20, 12, 2, 2,
     "abbbbacddddc"
     "dbaaaabdcccc"},
    {6, 21, 12, 2, 2,
     "abaaaacdcccc"
     "dbabbbbdcddd"},
    {6, 22, 8, 3, 0,
     "aaaabbbb"
     "acdabdcb"
     "ccddddcc"},
    {6, 23, 4, 6, 0,
     "abbb"
     "aaab"
     "cadb"
     "cddd"
     "cccd"
     "acbd"},
    {6, 24, 6, 4, 4,
     "aabbbc"
     "daaabb"
     "daccdd"
     "ddbccc"},
    {6, 25, 4, 3, 0,
     "aabb"
     "baab"
     "bbaa"},
    {6, 26, 4, 6, 0,
     "aabb"
     "aabb"
     "baab"
     "ccdd"
     "ccdd"
     "dccd"},
    {6, 27, 4, 6, 0,
     "aabb"
     "abba"
     "aabb"
     "ccdd"
     "cddc"
     "ccdd"},
    {6, 28, 12, 2, 10,
     "abbbaacdddcc"
     "aaabbdcccddb"},
    {6, 29, 6, 4, 4,
     "aababb"
     "caaacc"
     "ccddcd"
     "bbbddd"},
    {6, 30, 6, 4, 0,
     "abccca"
     "bbbcdd"
     "ddbbad"
     "dccaaa"},
    {6, 31, 12, 2, 3,
     "aaaabcddddcb"
     "abbbbadccccd"},
    {6, 32, 12, 2, 4,
     "abccccbadddd"
     "aadcbbbbcdaa"},
    {6, 33, 6, 4, 0,
     "aaabbb"
     "ccaddb"
     "caadbb"
     "cccddd"},
    {6, 34, 24, 1, 5, "aaaabcadccccddddcbdabbbb"},
    {6, 35, 4, 6, 0,
     "abbb"
     "aaab"
     "acdb"
     "ccdc"
     "dcdd"
     "acdb"},
};

const TileMap* find_map(const TileMap* maps, std::size_t count, int tiles, int number) {
    for (std::size_t i = 0; i < count; ++i)
        if (maps[i].tiles == tiles && maps[i].number == number) return &maps[i];
    return nullptr;
}

// A square cell's relation to its neighbours, corner by corner: corner k
// is at (k & 1, k >> 1) in the cell's unit square (x, z).
struct SquareCell {
    bool border_x[2] = {};  // the side x = 0, x = 1 is the tile's border
    bool border_z[2] = {};  // the side z = 0, z = 1
    bool concave[4] = {};   // both sides at the corner open, the diagonal cell another tile's
};

SquareCell square_cell(const TileMap& map, std::int64_t cx, std::int64_t cz) {
    const char own = letter_at(map, cx, cz);
    auto other = [&](int dx, int dz) { return letter_at(map, cx + dx, cz + dz) != own; };
    SquareCell cell;
    for (int side = 0; side < 2; ++side) {
        const int step = side ? 1 : -1;
        cell.border_x[side] = other(step, 0);
        cell.border_z[side] = other(0, step);
    }
    for (int k = 0; k < 4; ++k) {
        const int kx = k & 1, kz = k >> 1;
        cell.concave[k] = !cell.border_x[kx] && !cell.border_z[kz] && other(kx ? 1 : -1, kz ? 1 : -1);
    }
    return cell;
}

// The point's distances (in units of the half cell: 0 at the corner, 1
// at the cell's middle line) from corner k's two sides.
struct CornerDistances {
    double u, v;
};

CornerDistances from_corner(int k, double x, double z) {
    const double dx = (k & 1) ? 1.0 - x : x;
    const double dz = (k >> 1) ? 1.0 - z : z;
    return {2.0 * dx, 2.0 * dz};
}

double square_pavement(const PatternSetup& s, const glm::dvec3& p) {
    const TileMap* map = find_map(kSquarePavings, std::size(kSquarePavings), s.pavement_tiles, s.pavement_number);
    if (!map) return 0.0;
    const double fx = std::floor(p.x), fz = std::floor(p.z);
    const SquareCell cell = square_cell(*map, truncated_int64(fx), truncated_int64(fz));
    const double x = p.x - fx, z = p.z - fz;

    // A tile turning through this cell: bordered on the two sides away
    // from a concave corner, the cell is a bend around that corner.
    if (s.pavement_form >= 0 && s.pavement_form <= 2) {
        for (int k = 0; k < 4; ++k) {
            if (!cell.concave[k] || !cell.border_x[1 - (k & 1)] || !cell.border_z[1 - (k >> 1)]) continue;
            const CornerDistances d = from_corner(k, x, z);
            switch (s.pavement_form) {
            case 2: return std::min(std::fabs(std::sqrt(d.u * d.u + d.v * d.v) - 1.0), 1.0);
            case 1: return std::min(std::fabs(d.u + d.v - 1.0), 1.0);
            default: return std::max({d.u - 1.0, d.v - 1.0, std::min(1.0 - d.u, 1.0 - d.v)});
            }
        }
    }

    double value = 0.0;
    for (int side = 0; side < 2; ++side) {
        if (cell.border_x[side]) value = std::max(value, side ? 2.0 * x - 1.0 : 1.0 - 2.0 * x);
        if (cell.border_z[side]) value = std::max(value, side ? 2.0 * z - 1.0 : 1.0 - 2.0 * z);
    }
    for (int k = 0; k < 4; ++k) {
        if (!cell.concave[k]) continue;
        const CornerDistances d = from_corner(k, x, z);
        switch (s.pavement_interior) {
        case 2: value = std::max(value, 1.0 - std::sqrt(d.u * d.u + d.v * d.v)); break;
        case 1: value = std::max(value, 1.0 - (d.u + d.v)); break;
        default: value = std::max(value, std::min(1.0 - d.u, 1.0 - d.v)); break;
        }
    }
    // Convex corners: both sides at the corner are borders.
    for (int k = 0; k < 4; ++k) {
        if (!cell.border_x[k & 1] || !cell.border_z[k >> 1]) continue;
        const CornerDistances d = from_corner(k, x, z);
        if (s.pavement_exterior == 1) {
            value = std::max(value, std::min(2.0 - (d.u + d.v), 1.0));
        } else if (s.pavement_exterior == 2 && d.u <= 1.0 && d.v <= 1.0) {
            const double ox = 2.0 * x - 1.0, oz = 2.0 * z - 1.0;
            value = std::max(value, std::min(std::sqrt(ox * ox + oz * oz), 1.0));
        }
    }
    return value;
}

// ---- triangles and hexagons: both evaluated on the grid of equilateral
// triangles of side 1 (a hexagon is the six triangles round its centre).
// A triangle cell is (column, row): row r spans z in [r, r + 1] sqrt3/2,
// and the cell points up when column + row is even, its base then
// running from x = column / 2 to column / 2 + 1. Grid vertices are
// (2x, row) pairs (doubled x keeps them integral).

constexpr double kSqrt3 = 1.7320508075688772935274463415059;
constexpr double kHalfSqrt3 = 0.86602540378443864676372317075294;

// The polyiamond pavings, by number_of_tiles and pattern: maps of
// triangle cells.
constexpr TileMap kTrianglePavings[] = {
    // 1 triangle
    {1, 1, 4, 2, 2,
     "abcd"
     "efgh"},
    // 2 triangles
    {2, 1, 4, 2, 2,
     "abba"
     "ccdd"},
    // 3 triangles
    {3, 1, 6, 2, 0,
     "aaabbb"
     "cccddd"},
    // 4 triangles
    {4, 1, 8, 2, 6,
     "abbbbaaa"
     "ccccdddd"},
    {4, 2, 8, 2, 6,
     "aaabcccd"
     "ddcbbbad"},
    {4, 3, 8, 4, 4,
     "aaabcccd"
     "dabbbcdd"
     "efggghee"
     "fffghhhe"},
    // 5 triangles
    {5, 1, 10, 2, 0,
     "aaaaabbbbb"
     "cccccddddd"},
    {5, 2, 20, 2, 10,
     "aaaabbbbcdeeeeffffgh"
     "hhhafggggddddebcccch"},
    {5, 3, 20, 1, 5, "abbbcccddccdddaaabba"},
    {5, 4, 20, 1, 7, "aaaabcddddbbbbadcccc"},
    // 6 triangles
    {6, 1, 12, 2, 2,
     "aaaaaabbbbbb"
     "cddddddccccc"},
    {6, 2, 12, 2, 2,
     "abbbbbcddddd"
     "cbaaaaadcccc"},
    {6, 3, 12, 2, 6,
     "abbbbbcddddd"
     "cccbaaaaadcc"},
    {6, 4, 12, 4, 8,
     "aaaaabcccccd"
     "dddabbbbbcdd"
     "eeefggggghee"
     "hefffffghhhh"},
    {6, 5, 6, 4, 2,
     "aaaabb"
     "baabbb"
     "ccddcc"
     "cddddc"},
    {6, 6, 6, 4, 0,
     "aabbbb"
     "baaaab"
     "ccdddd"
     "dccccd"},
    {6, 7, 8, 3, 1,
     "aaaabbbb"
     "ccaaddbb"
     "ccccdddd"},
    {6, 8, 8, 3, 1,
     "aaaabbbb"
     "aaccbbdd"
     "ccccdddd"},
    {6, 9, 6, 4, 2,
     "aaabbb"
     "baaabb"
     "cdddcc"
     "ccdddc"},
    {6, 10, 12, 2, 2,
     "aaabbbcccddd"
     "cbbbaaadddcc"},
    {6, 11, 12, 2, 6,
     "aaabbbcccddd"
     "aaadddcccbbb"},
    {6, 12, 12, 2, 6,
     "aaabbbcccddd"
     "cccbbbaaaddd"},
};

// The polyhex pavings: maps of hexagons (i, j), the hexagon centred on
// the grid vertex (2 + 3i, i + 2j), i.e. at x = 1 + 1.5i, z = (i + 2j)
// sqrt3/2; (i +- 1, j), (i, j +- 1) and (i + 1, j - 1), (i - 1, j + 1) are
// its neighbours.
constexpr TileMap kHexagonPavings[] = {
    // 1 hexagon
    {1, 1, 2, 2, 0,
     "ab"
     "cd"},
    // 2 hexagons
    {2, 1, 4, 2, 0,
     "abcd"
     "badc"},
    // 3 hexagons
    {3, 1, 6, 2, 2,
     "abacdb"
     "dbacdc"},
    {3, 2, 12, 1, 2, "abaaccdcddbb"},
    {3, 3, 6, 2, 0,
     "abbcdd"
     "baadcc"},
    // 4 hexagons
    {4, 1, 16, 1, 6, "abacdbacdcdbacdb"},
    {4, 2, 4, 4, 0,
     "aabb"
     "cddc"
     "ddcc"
     "baab"},
    {4, 3, 8, 2, 0,
     "aabbccdd"
     "bbaaddcc"},
    {4, 4, 2, 8, 0,
     "ab"
     "cd"
     "dc"
     "dc"
     "dc"
     "ba"
     "ab"
     "ab"},
    {4, 5, 4, 4, 0,
     "abcd"
     "dbbd"
     "aacc"
     "dabc"},
    {4, 6, 4, 4, 0,
     "abcd"
     "bbdd"
     "aacc"
     "abcd"},
    {4, 7, 4, 4, 0,
     "abcd"
     "bddb"
     "badc"
     "acca"},
    // 5 hexagons
    {5, 1, 10, 2, 6,
     "abacdbacdb"
     "dbacdbacdc"},
    {5, 2, 2, 10, 0,
     "ab"
     "ba"
     "ba"
     "ba"
     "ba"
     "cd"
     "dc"
     "dc"
     "dc"
     "dc"},
    {5, 3, 20, 1, 8, "abccabdcaadcbbdcabdd"},
    {5, 4, 20, 1, 8, "abccabddabdcbbdcaadc"},
    {5, 5, 2, 10, 0,
     "ab"
     "ba"
     "ba"
     "ba"
     "cd"
     "cd"
     "dc"
     "dc"
     "dc"
     "ab"},
    {5, 6, 20, 1, 8, "abccbacdaadcbbcdbadd"},
    {5, 7, 20, 1, 8, "aabbccbdaaddccbbcadd"},
    {5, 8, 20, 1, 7, "abcddaabcdcdabbccdab"},
    {5, 9, 20, 1, 4, "aaabcdbbdcdddcbaccab"},
    {5, 10, 4, 5, 0,
     "abcd"
     "bddb"
     "dcba"
     "dcba"
     "caac"},
    {5, 11, 20, 1, 4, "abcaaacccadcbdddbbbd"},
    {5, 12, 10, 2, 2,
     "abcdddcbaa"
     "bbadcccdab"},
    {5, 13, 10, 2, 4,
     "aabbcaabbd"
     "caddccbddc"},
    {5, 14, 10, 2, 8,
     "abcccbaddd"
     "cbbbcdaaad"},
    {5, 15, 10, 2, 8,
     "abcbbbadaa"
     "cbcccdaddd"},
    {5, 16, 20, 1, 4, "aaabbbabcdcccdddcdab"},
    {5, 17, 10, 2, 2,
     "abbcdcdcda"
     "bababccdda"},
    {5, 18, 20, 1, 4, "abbacacacddccdbdbdba"},
    {5, 19, 10, 2, 4,
     "abcddcbcba"
     "abbadccdad"},
    {5, 20, 20, 1, 8, "abcccdbaaadcbbbacddd"},
    {5, 21, 10, 2, 8,
     "abccbbadda"
     "cbbccdaadd"},
    {5, 22, 20, 1, 4, "abbcdaabdacddabccdbc"},
};

// A point's triangle cell and its place in the cell, seen with the cell
// turned point up: (x, z) in the triangle (0, 0), (1, 0), (1/2, sqrt3/2).
// Down cells are turned by half a turn about the middle of the side they
// share with an up cell, so their top side is the local base.
struct TrianglePoint {
    std::int64_t column, row;
    double x, z;
};

TrianglePoint locate_triangle(double px, double pz) {
    const double fx = std::floor(px), fz = std::floor(pz / kSqrt3);
    double x = px - fx, z = pz - kSqrt3 * fz;
    std::int64_t column = 2 * truncated_int64(fx), row = 2 * truncated_int64(fz);
    if (z > kHalfSqrt3) {  // the upper row of the band, half a cell along
        z -= kHalfSqrt3;
        if (x > 0.5) {
            x -= 0.5;
            ++column;
        } else {
            x += 0.5;
            --column;
        }
        ++row;
    }
    if (x == 0.0 || z / x > kSqrt3) {  // the down cell at the left
        z = kHalfSqrt3 - z;
        x = 0.5 - x;
        --column;
    }
    if (x == 1.0 || z / (1.0 - x) > kSqrt3) {  // the down cell at the right
        z = kHalfSqrt3 - z;
        x = 1.5 - x;
        ++column;
    }
    return {column, row, x, z};
}

struct GridVertex {
    std::int64_t x2, row;
};

// In a cell's local frame the corners are 0: (0, 0), 1: (1, 0) and 2: the
// apex (1/2, sqrt3/2); side 0 joins corners 0 and 2, side 1 corners 1 and
// 2, side 2 (the base) corners 0 and 1.
constexpr int kSideCorners[3][2] = {{0, 2}, {1, 2}, {0, 1}};

int side_joining(int corner_a, int corner_b) {
    for (int side = 0; side < 3; ++side) {
        const int* ends = kSideCorners[side];
        if ((ends[0] == corner_a && ends[1] == corner_b) || (ends[0] == corner_b && ends[1] == corner_a)) return side;
    }
    return 2;
}

bool touches(int side, int corner) {
    return kSideCorners[side][0] == corner || kSideCorners[side][1] == corner;
}

bool points_up(std::int64_t column, std::int64_t row) {
    return ((column + row) & 1) == 0;
}

GridVertex cell_corner(std::int64_t column, std::int64_t row, int corner) {
    if (points_up(column, row)) {
        switch (corner) {
        case 0: return {column, row};
        case 1: return {column + 2, row};
        default: return {column + 1, row + 1};
        }
    }
    switch (corner) {
    case 0: return {column + 2, row + 1};
    case 1: return {column, row + 1};
    default: return {column + 1, row};
    }
}

// The cell across the side.
void across_side(std::int64_t& column, std::int64_t& row, int side) {
    const bool up = points_up(column, row);
    switch (side) {
    case 0: column += up ? -1 : 1; break;
    case 1: column += up ? 1 : -1; break;
    default: row += up ? -1 : 1; break;
    }
}

// The six cells round a grid vertex.
constexpr int kRoundVertex[6][2] = {{0, 0}, {-2, 0}, {-1, 0}, {-1, -1}, {0, -1}, {-2, -1}};

// The tile letter of a triangle cell, from the paving's map of cells or
// of hexagons.
struct TriangleGridPaving {
    const TileMap* map;
    bool hexagons;
    char letter(std::int64_t column, std::int64_t row) const {
        if (!hexagons) return letter_at(*map, column, row);
        // The corner of the cell that is a hexagon's centre.
        for (int corner = 0; corner < 3; ++corner) {
            const GridVertex v = cell_corner(column, row, corner);
            if ((v.x2 - 2 - 3 * v.row) % 6 != 0) continue;
            const std::int64_t i = (v.x2 - 2) / 3;
            return letter_at(*map, i, (v.row - i) / 2);
        }
        return 0;
    }
};

// A triangle cell's relation to its tile: which sides are the tile's
// border, how many of the six cells round each corner are in the tile,
// and from these: the corners where the tile meets others while both the
// cell's sides there are open (marked by interior), and the sides across
// which the tile bends round a corner (rounded by form: the corner at one
// end of the side is the tile's only cells there, the other is the
// bend's centre).
struct TriangleCell {
    bool border[3] = {};
    int tile_cells_round[3] = {};
    bool marked[3] = {};
    int bend_centre_near[3] = {-1, -1, -1};  // per corner: the centre of the bend seen there, or -1
};

TriangleCell triangle_cell(const TriangleGridPaving& paving, std::int64_t column, std::int64_t row) {
    const char own = paving.letter(column, row);
    TriangleCell cell;
    for (int side = 0; side < 3; ++side) {
        std::int64_t c = column, r = row;
        across_side(c, r, side);
        cell.border[side] = paving.letter(c, r) != own;
    }
    for (int corner = 0; corner < 3; ++corner) {
        const GridVertex v = cell_corner(column, row, corner);
        int count = 0;
        for (const auto& step : kRoundVertex)
            if (paving.letter(v.x2 + step[0], v.row + step[1]) == own) ++count;
        cell.tile_cells_round[corner] = count;
    }
    for (int corner = 0; corner < 3; ++corner) {
        bool both_open = true;
        for (int side = 0; side < 3; ++side)
            if (touches(side, corner) && cell.border[side]) both_open = false;
        // Six cells of one tile round a corner: it is inside the tile.
        cell.marked[corner] = both_open && cell.tile_cells_round[corner] < 6;
    }
    for (int side = 0; side < 3; ++side) {
        if (cell.border[side]) continue;
        const int a = kSideCorners[side][0], b = kSideCorners[side][1];
        if (cell.tile_cells_round[a] == 2) cell.bend_centre_near[a] = b;
        if (cell.tile_cells_round[b] == 2) cell.bend_centre_near[b] = a;
    }
    return cell;
}

// Where the point is along each side of the local triangle: 1 at the
// side's first corner to -1 at its second (side 0: corner 0 to 2, side 1:
// corner 1 to 2, side 2: corner 0 to 1). Their signs tell which corner's
// third of the triangle (cut by the perpendiculars through the sides'
// middles) holds the point.
struct TriangleMeasures {
    double along0, along1, along2;
    TriangleMeasures(double x, double z)
        : along0(1.0 - std::fabs(kSqrt3 * z + x)),
          along1(1.0 - std::fabs(kSqrt3 * z - x + 1.0)),
          along2(1.0 - x * 2.0) {}
    // The third of the triangle nearest a corner (boundaries excluded).
    bool near(int corner) const {
        switch (corner) {
        case 0: return along0 > 0.0 && along2 > 0.0;
        case 1: return along2 < 0.0 && along1 > 0.0;
        default: return along0 < 0.0 && along1 < 0.0;
        }
    }
    double along(int side) const { return side == 0 ? along0 : side == 1 ? along1 : along2; }
};

constexpr double kCornerX[3] = {0.0, 1.0, 0.5};
constexpr double kCornerZ[3] = {0.0, 0.0, kHalfSqrt3};

double distance_to_corner(int corner, double x, double z) {
    const double dx = x - kCornerX[corner], dz = z - kCornerZ[corner];
    return std::sqrt(dx * dx + dz * dz);
}

double triangle_grid_pavement(const PatternSetup& s, const glm::dvec3& p, const TriangleGridPaving& paving) {
    const TrianglePoint at = locate_triangle(p.x, p.z);
    const TriangleCell cell = triangle_cell(paving, at.column, at.row);
    const double x = at.x, z = at.z;
    const TriangleMeasures m(x, z);

    double value = 0.0;
    // Distance from each border side: 1 on the side to 0 a third of the
    // way to the opposite corner.
    const double from_side[3] = {1.0 - (std::fabs(kSqrt3 * x - z) * kSqrt3),
                                 1.0 - (std::fabs(kSqrt3 * (1.0 - x) - z) * kSqrt3), 1.0 - (z * 2.0 * kSqrt3)};
    for (int side = 0; side < 3; ++side)
        if (cell.border[side]) value = std::max(value, from_side[side]);

    for (int corner = 0; corner < 3; ++corner) {
        if (!cell.marked[corner]) continue;
        switch (s.pavement_interior) {
        case 1:
            if (!m.near(corner)) break;
            if (corner == 2) {
                value = std::max(value, std::min(3.0 / 2.0 * (std::fabs(kSqrt3 * z + x)) - 2.0,
                                                 3.0 / 2.0 * (std::fabs(kSqrt3 * z - x + 1.0)) - 2.0));
            } else if (corner == 0) {
                value = std::max(value, std::min(1.0 - 3.0 / 2.0 * (std::fabs(kSqrt3 * z + x)), 1.0 - (x * 3.0)));
            } else {
                value = std::max(value, std::min(1.0 - 3.0 / 2.0 * (std::fabs(kSqrt3 * z - x + 1.0)), (x * 3.0) - 2.0));
            }
            break;
        case 2: value = std::max(value, 1.0 - distance_to_corner(corner, x, z) * 3.0); break;
        default: {
            const double towards[3] = {1.0 - (std::fabs(kSqrt3 * x + z) * kSqrt3),
                                       1.0 - (std::fabs(kSqrt3 * (x - 1.0) - z) * kSqrt3),
                                       1.0 - ((kHalfSqrt3 - z) * 2.0 * kSqrt3)};
            value = std::max(value, towards[corner]);
            break;
        }
        }
    }

    // Exterior (triangle pavings only): the tile's convex corners, where
    // both the cell's sides at a corner are borders, replace the value.
    if (!paving.hexagons && s.pavement_exterior != 0) {
        auto convex = [&](int corner) {
            for (int side = 0; side < 3; ++side)
                if (touches(side, corner) && !cell.border[side]) return false;
            return true;
        };
        const double cx = x - 0.5, cz = z - kHalfSqrt3 / 3.0;  // from the centroid
        if (s.pavement_exterior == 2) {
            const bool rounded = (convex(2) && m.along0 <= 0.0 && m.along1 <= 0.0) ||
                                 (convex(1) && m.along1 >= 0.0 && m.along2 <= 0.0) ||
                                 (convex(0) && m.along0 >= 0.0 && m.along2 >= 0.0);
            if (rounded) value = std::min(1.0, 2 * kSqrt3 * std::sqrt(cx * cx + cz * cz));
        } else {
            // Cut across, parallel to the opposite side, within a third
            // of the height of both sides at the corner.
            if (convex(2) && from_side[0] >= 0.0 && from_side[1] >= 0.0)
                value = std::min(1.0, std::fabs(cz * 2.0 * kSqrt3));
            if (convex(1) && from_side[1] >= 0.0 && from_side[2] >= 0.0)
                value = std::min(1.0, std::fabs(kSqrt3 * cx - cz) * kSqrt3);
            if (convex(0) && from_side[0] >= 0.0 && from_side[2] >= 0.0)
                value = std::min(1.0, std::fabs(kSqrt3 * cx + cz) * kSqrt3);
        }
    }

    // Form: in the third of the cell near the corner where the tile bends,
    // the tile's edge follows an arc (2) or a cut (1) round the bend's
    // centre instead.
    if (s.pavement_form == 1 || s.pavement_form == 2) {
        for (int corner = 0; corner < 3; ++corner) {
            const int centre = cell.bend_centre_near[corner];
            if (centre < 0 || !m.near(corner)) continue;
            if (s.pavement_form == 2) {
                const double arc = 2.0 * kSqrt3 * (distance_to_corner(centre, x, z) - kSqrt3 / 3.0);
                return std::min(std::max(arc, 0.0), 1.0);
            }
            return std::min(std::fabs(m.along(side_joining(corner, centre))) * 2.0, 1.0);
        }
    }
    return value;
}

}  // namespace

double pavement_pattern(const PatternSetup& s, const glm::dvec3& point) {
    // Cell numbers are 64-bit integers: keep them exact (POV's `long`s
    // overflow far sooner).
    const glm::dvec3 p = clamp_to_coordinate_limit(point);
    switch (s.pavement_sides) {
    case 4: return square_pavement(s, p);
    case 3:
    case 6: {
        const bool hexagons = s.pavement_sides == 6;
        const TileMap* map =
            hexagons ? find_map(kHexagonPavings, std::size(kHexagonPavings), s.pavement_tiles, s.pavement_number)
                     : find_map(kTrianglePavings, std::size(kTrianglePavings), s.pavement_tiles, s.pavement_number);
        if (!map) return 0.0;
        return triangle_grid_pavement(s, p, TriangleGridPaving{map, hexagons});
    }
    default: return 0.0;
    }
}

}  // namespace lancer::pattern_detail
