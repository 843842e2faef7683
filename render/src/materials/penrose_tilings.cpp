// POV 3.7's Penrose tilings: tiling 25 (P1: pentagons, stars, boats and
// diamonds, a pentagon at the origin), 26 (P2: kites and darts, five darts
// at the origin) and 27 (P3: thin and thick rhombs).
//
// Each is built by deflation: the plane is cut by its five-fold symmetry
// into one wedge, scaled down by a power of the tiling's inflation factor
// until the point lies in a seed tile of size about 1, and the seed is
// then subdivided `depth` times (each step scales the point up by phi and
// moves it into the frame of the sub-tile holding it) until the leaf tile
// that holds the point is known. Its value is kind/k plus a measure from
// the leaf's edges.
//
// The edge measures scale distances by 4.46 (P2) and 5.55 (P1, P3): POV's
// source calls these empirical, and they are kept so that values agree.
#include <algorithm>
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

// The golden ratio and the trigonometry of multiples of 18 degrees,
// derived from sqrt(5): cos 36 = phi / 2, cos 72 = 1 / (2 phi),
// sin 36 = sqrt(10 - 2 sqrt5) / 4, sin 72 = sqrt(10 + 2 sqrt5) / 4.
struct GoldenConstants {
    double phi, inv_phi, sqr_phi, inv_sqr_phi;
    double cos36, sin36, cos72, sin72;
    double tan18, tan36, tan54, tan72;
    GoldenConstants() {
        const double sqrt5 = std::sqrt(5.0);
        phi = (1.0 + sqrt5) / 2.0;
        inv_phi = phi - 1.0;
        sqr_phi = phi + 1.0;
        inv_sqr_phi = 2.0 - phi;
        cos36 = phi / 2.0;
        cos72 = inv_phi / 2.0;
        sin36 = std::sqrt(10.0 - 2.0 * sqrt5) / 4.0;
        sin72 = std::sqrt(10.0 + 2.0 * sqrt5) / 4.0;
        tan18 = cos72 / sin72;
        tan36 = sin36 / cos36;
        tan54 = cos36 / sin36;
        tan72 = sin72 / cos72;
    }
};

const GoldenConstants& golden() {
    static const GoldenConstants constants;
    return constants;
}

// POV's margin keeping each kind's values off its neighbours'.
constexpr double kKindMargin = 1e-6;

// (x, z) turned by the angle whose cosine and sine are given.
void turn(double& x, double& z, double cosine, double sine) {
    const double turned_x = x * cosine - z * sine;
    const double turned_z = z * cosine + x * sine;
    x = turned_x;
    z = turned_z;
}

// The five-fold symmetry with mirrors: folds (x, z), r from the origin,
// into the wedge within 36 degrees of +x above the x axis.
void fold_into_wedge(double& x, double& z, double r) {
    const GoldenConstants& g = golden();
    z = std::fabs(z);
    if (x < r * g.cos36) {
        if (x < r * -g.cos72)
            turn(x, z, -g.cos36, -g.sin36);  // by -144 degrees
        else
            turn(x, z, g.cos72, -g.sin72);  // by -72 degrees
        z = std::fabs(z);
    }
}

double max3(double a, double b, double c) {
    return std::max(std::max(a, b), c);
}

// ---- P2 and P3: both subdivide half kites and half darts (P3 reads the
// same triangles as halves of rhombs). A half kite has its apex at the
// origin and its long side along +x with length 1; a half dart likewise.

enum class HalfTile { Kite, Dart };

double penrose_leaf(HalfTile tile, double x, double z, bool rhombs) {
    const GoldenConstants& g = golden();
    if (tile == HalfTile::Kite) {
        if (rhombs) {
            // The half kite splits into half a thick rhomb (kind 1) and
            // part of a thin one.
            if (z < (x - g.inv_phi) * g.tan72) {
                const double d1 = std::fabs(g.sin72 * (x - g.inv_phi) - g.cos72 * z) * 5.55;
                const double d2 = std::fabs(g.sin72 * (x - 1.0) + g.cos72 * z) * 5.55;
                return max3(1.0 - d1 / 2, 1.0 - d2 / 2, 0.5 + kKindMargin);
            }
            const double d1 = std::fabs(z) * 5.55;
            const double d2 = std::fabs(g.sin72 * (x - g.inv_phi) - g.cos72 * z) * 5.55;
            return std::min(max3(0.5 - d1 / 2, 0.5 - d2 / 2, 0.0), 0.5 - kKindMargin);
        }
        const double d1 = std::fabs(g.sin36 * x - g.cos36 * z) * 4.46;
        const double d2 = std::fabs(g.sin72 * (x - 1.0) + g.cos72 * z) * 4.46;
        return std::min(max3(0.5 - d1 / 2, 0.5 - d2 / 2, 0.0), 0.5 - kKindMargin);
    }
    if (rhombs) {
        const double d1 = std::fabs(g.sin36 * x - g.cos36 * z) * 5.55;
        const double d2 = std::fabs(g.sin36 * (x - 1.0) + g.cos36 * z) * 5.55;
        return std::min(max3(0.5 - d1 / 2, 0.5 - d2 / 2, 0.0), 0.5 - kKindMargin);
    }
    const double d1 = std::fabs(z) * 4.46;
    const double d2 = std::fabs(g.sin36 * (x - 1.0) + g.cos36 * z) * 4.46;
    return max3(1.0 - d1 / 2, 1.0 - d2 / 2, 0.5 + kKindMargin);
}

double subdivide_half_tiles(HalfTile tile, double x, double z, int depth, bool rhombs) {
    const GoldenConstants& g = golden();
    for (; depth > 0; --depth) {
        z = std::fabs(z);
        if (tile == HalfTile::Kite) {
            // A half kite holds a half dart at its far end and a smaller
            // half kite (turned by 108 degrees about its side's midpoint).
            if (z < (x - g.inv_phi) * -g.tan36) {
                tile = HalfTile::Dart;
            } else {
                x -= g.cos36;
                z -= g.sin36;
                turn(x, z, -g.cos72, g.sin72);
            }
        } else {
            // A half dart holds a half kite (turned by -36 degrees) and a
            // smaller half dart (turned by -144 about its far corner).
            if (z < (x - g.inv_phi) * -g.tan72) {
                turn(x, z, g.cos36, -g.sin36);
                tile = HalfTile::Kite;
            } else {
                x -= 1.0;
                turn(x, z, -g.cos36, -g.sin36);
            }
        }
        x *= g.phi;
        z *= g.phi;
    }
    return penrose_leaf(tile, x, std::fabs(z), rhombs);
}

double kites_and_rhombs(double x, double z, bool rhombs) {
    const GoldenConstants& g = golden();
    const double r = std::sqrt(x * x + z * z);
    if (r <= kPovEpsilon) return 1.0;
    fold_into_wedge(x, z, r);
    if (rhombs) {
        x *= g.inv_phi;
        z *= g.inv_phi;
    }
    // Deflate by phi^2 (two subdivisions) until the point is inside the
    // seed kite, whose outer side is at distance cos 18 from the origin.
    const double reach = std::fabs(g.sin72 * x + g.cos72 * z) / g.sin72;
    int steps = std::max(0, truncated_int(std::ceil(std::log(reach) / std::log(g.sqr_phi))));
    const double shrink = std::pow(g.inv_sqr_phi, steps);
    x *= shrink;
    z *= shrink;
    // An odd number of phi^2 deflations leaves the seed turned by 36
    // degrees.
    if (steps % 2) {
        turn(x, z, g.cos36, -g.sin36);
        z = std::fabs(z);
    }
    return subdivide_half_tiles(HalfTile::Kite, x, z, 2 * steps, rhombs);
}

// ---- P1: six kinds of piece, in value order: the three pentagon
// placements, the star, the boat and the diamond. The pentagons and the
// pieces carry a side flag POV tracks (inside a quadrilateral or a wedge
// of the parent, or which side of a diamond).

enum class P1Piece { Pentagon1, Pentagon2, Pentagon3, Star, Boat, Diamond };

struct P1Constants {
    double apothem;       // a unit pentagon's: 0.5 / tan 36
    double circumradius;  // 0.5 / sin 36
    double wedge_offset;  // inv_phi * 0.5 * cos72 / sin36
    double small_offset;  // inv_sqr_phi * 0.5 * cos72 / sin36
    double small_radius;  // inv_sqr_phi * 0.5 / sin36
    double star_tip;      // phi * 0.5 / sin36
    P1Constants() {
        const GoldenConstants& g = golden();
        apothem = 0.5 / g.tan36;
        circumradius = 0.5 / g.sin36;
        wedge_offset = g.inv_phi * 0.5 * g.cos72 / g.sin36;
        small_offset = g.inv_sqr_phi * 0.5 * g.cos72 / g.sin36;
        small_radius = g.inv_sqr_phi * 0.5 / g.sin36;
        star_tip = g.phi * 0.5 / g.sin36;
    }
};

const P1Constants& p1() {
    static const P1Constants constants;
    return constants;
}

void fold_into_wedge(double& x, double& z) {
    fold_into_wedge(x, z, std::sqrt(x * x + z * z));
}

double pentagon_edge_distance(double x) {
    return std::fabs(x - p1().apothem) * 5.55 * golden().inv_phi;
}

// Distance from a star's (or boat's) spike side.
double spike_edge_distance(double x, double z) {
    const GoldenConstants& g = golden();
    return std::fabs(g.cos72 * (x - p1().star_tip) + g.sin72 * z) * 5.55 * g.inv_phi;
}

// `kind`/6 less the distance share, within its sixth.
double within_kind(int kind, double measure) {
    const double top = kind / 6.0, bottom = (kind - 1) / 6.0;
    return std::min(std::max(top - measure / 6, kind == 1 ? 0.0 : bottom + kKindMargin), top - kKindMargin);
}

double p1_leaf(P1Piece piece, double x, double z) {
    const GoldenConstants& g = golden();
    switch (piece) {
    case P1Piece::Pentagon1:
    case P1Piece::Pentagon2:
        fold_into_wedge(x, z);
        return within_kind(piece == P1Piece::Pentagon1 ? 1 : 2, pentagon_edge_distance(x));
    case P1Piece::Pentagon3: fold_into_wedge(x, z); return within_kind(3, pentagon_edge_distance(x));
    case P1Piece::Star: return within_kind(4, spike_edge_distance(x, z));
    case P1Piece::Boat: {
        const double from_back = std::fabs(x - p1().wedge_offset) * 5.55 * g.inv_phi;
        x = -x;
        fold_into_wedge(x, z);
        const double from_spike = spike_edge_distance(x, z);
        return within_kind(5, std::min(from_back, from_spike));
    }
    case P1Piece::Diamond: {
        const double d = std::fabs(g.cos72 * (x + g.inv_phi * 0.5 / g.sin36) - g.sin72 * z) * 5.55 * g.inv_phi;
        return within_kind(6, d);
    }
    }
    return 0.0;
}

double subdivide_p1(double x, double z, int depth) {
    const GoldenConstants& g = golden();
    const P1Constants& c = p1();
    P1Piece piece = P1Piece::Pentagon1;
    bool inner = false;  // Pentagon2: inside the quadrilateral; Pentagon3, Boat: inside the wedge; Diamond: side A
    for (; depth > 0; --depth) {
        z = std::fabs(z);
        switch (piece) {
        case P1Piece::Pentagon1:
            // A pentagon holds five pentagons (one per side, here the one
            // at +x) and a star between them.
            fold_into_wedge(x, z);
            if (z < (x - c.apothem) * g.tan54 + 0.5) {
                x = x - c.apothem - c.wedge_offset;
                piece = P1Piece::Pentagon2;
                inner = false;
            } else {
                turn(x, z, g.cos36, -g.sin36);
                piece = P1Piece::Star;
            }
            break;
        case P1Piece::Pentagon2:
            if (inner) {
                if (z < (x - c.small_radius) * g.tan54) {
                    x -= c.circumradius;
                    piece = P1Piece::Pentagon1;
                } else if (z < (x - c.small_radius) * -g.tan18) {
                    x = -x;
                    piece = P1Piece::Diamond;
                    inner = true;
                } else {
                    turn(x, z, -g.cos72, g.sin72);
                    x += g.inv_phi * 0.5 / g.sin36;
                }
            } else if (z < (x + c.circumradius) * g.tan18) {
                x = x + c.circumradius - c.small_radius;
                piece = P1Piece::Diamond;
                inner = false;
            } else {
                turn(x, z, g.cos36, -g.sin36);
                x = -x - g.cos72 * c.circumradius;
                z -= g.sin72 * c.circumradius;
                piece = P1Piece::Pentagon3;
                inner = false;
            }
            break;
        case P1Piece::Pentagon3:
            if (inner && x > c.small_offset) {
                x = -(x - c.small_offset - g.inv_phi * c.apothem);
                piece = P1Piece::Pentagon2;
                inner = true;
            } else if (!inner && x < -g.cos72 * c.circumradius) {
                turn(x, z, -g.cos36, -g.sin36);
                x -= c.circumradius;
                piece = P1Piece::Pentagon2;
                inner = false;
            } else if (!inner && z > (x - c.small_radius) * -g.tan54) {
                turn(x, z, g.cos36, g.sin36);
                x = -x - g.cos72 * c.circumradius;
                z -= g.sin72 * c.circumradius;
            } else {
                piece = P1Piece::Boat;
            }
            break;
        case P1Piece::Star:
            if (x < g.inv_phi * c.apothem) {
                piece = P1Piece::Pentagon1;
            } else {
                x = -(x - g.inv_phi / g.tan36);
                piece = P1Piece::Pentagon3;
                inner = true;
            }
            break;
        case P1Piece::Boat:
            if (inner && x > -c.star_tip * g.cos72) {
                x = -x;
                piece = P1Piece::Pentagon1;
            } else {
                if (!inner) turn(x, z, g.cos72, g.sin72);
                x += c.circumradius;
                piece = P1Piece::Pentagon3;
                inner = true;
            }
            break;
        case P1Piece::Diamond:
            piece = inner ? P1Piece::Pentagon1 : P1Piece::Pentagon3;
            inner = true;
            break;
        }
        x *= g.phi;
        z *= g.phi;
    }
    return p1_leaf(piece, x, std::fabs(z));
}

double pentagons(double x, double z) {
    const GoldenConstants& g = golden();
    const double r = std::sqrt(x * x + z * z);
    if (r <= kPovEpsilon) return 1.0;
    fold_into_wedge(x, z, r);
    // Deflate by phi^4 (four subdivisions) until inside the seed pentagon.
    const double reach = x * 2 * g.tan36;
    const int steps = std::max(0, truncated_int(std::ceil(std::log(reach) / std::log(g.sqr_phi * g.sqr_phi))));
    const double shrink = std::pow(g.inv_sqr_phi * g.inv_sqr_phi, steps);
    return subdivide_p1(x * shrink, z * shrink, 4 * steps);
}

}  // namespace

double penrose_tiling(int type, double x, double z) {
    switch (type) {
    case 25: return pentagons(x, z);
    case 26: return kites_and_rhombs(x, z, false);
    case 27: return kites_and_rhombs(x, z, true);
    default: return 0.0;
    }
}

}  // namespace lancer::pattern_detail
