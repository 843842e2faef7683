// POV-Ray's parametric, searched as POV-Ray 3.7 searches it (its
// fpmetric.cpp, read for the method):
//
// - The ray's chord through the container is [enter + 4 accuracy, exit]
//   (a box's chord starts at the ray's origin at the earliest; a sphere's
//   may start behind it).
// - The (u, v) rectangle is halved across its longer side, the lower half
//   searched first. In a piece, each coordinate function is bounded from
//   its four corners, widened by max_gradient times the piece's size (and
//   shifted by -accuracy, as POV-Ray shifts it); the ray's parameter range
//   inside each coordinate's slab must overlap the chord and the other
//   coordinates' ranges, or the piece is dropped.
// - A piece smaller than `accuracy` in (u, v), or whose slabs the ray
//   crosses in less than `accuracy`, is a crossing at the ray's entry into
//   the last coordinate slab; the nearest one wins.
// - The normal is the cross product of the forward differences one
//   accuracy step along u and along v at the piece's lower corner.
//
// One crossing per ray, as POV-Ray reports one; a search stops after
// kMostPiecesPerSearch pieces with the nearest crossing found so far. A piece is named by its
// place in the halving (1 the whole rectangle, 2n and 2n + 1 the lower and
// upper halves of piece n): that number is the crossing's face, from which
// surface() finds the piece's corner again.
#include "geometry/parametric.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace lancer {

namespace {

constexpr double kParallel = 1e-10;  // POV's EPSILON: a direction component this small is parallel
// Pieces are halved at most this often (a piece number then still fits a
// face number); POV-Ray's own stack holds 32.
constexpr int kDeepestLevel = 30;
// A ray's search gives up after looking at this many pieces (POV-Ray has
// no limit): bounds that stay loose (a huge max_gradient over a wide range
// of (u, v)) would otherwise have it visit millions of pieces per ray. A
// sphere at the default accuracy takes about a thousand.
constexpr long kMostPiecesPerSearch = 1L << 16;

struct Range {
    double low = 0.0, high = 0.0;
};

// POV's bound on a function along an edge of length `span` whose ends have
// the values a and b, if its slope is at most `gradient`.
Range edge_bound(double span, double a, double b, double gradient) {
    const double widen = std::max(0.0, (gradient * span - std::fabs(a - b)) / 2.0);
    return {std::min(a, b) - widen, std::max(a, b) + widen};
}

struct Piece {
    glm::dvec2 low, high;
    std::uint32_t number;
};

int level_of(std::uint32_t number) {
    int level = 0;
    while (number > 1) {
        number >>= 1;
        ++level;
    }
    return level;
}

class ParametricShape final : public Shape {
  public:
    explicit ParametricShape(const ParametricParameters& p) : m_p(p) { precompute(); }

    bool finds_crossings_past_t_min() const override { return false; }
    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        double enter = 0.0, exit = 0.0;
        // A chord of no length (a flat box, a ray along an edge) holds no
        // crossing: POV-Ray searches such a ray from its origin instead,
        // which finds the surface outside the container.
        if (!container_chord(o, d, enter, exit)) return;
        enter += 4.0 * m_p.accuracy;
        if (enter > exit) return;

        double nearest = HUGE_VAL;
        std::uint32_t nearest_piece = 0;
        Piece stack[kDeepestLevel + 2];
        int top = 0;
        stack[0] = {m_p.uv_min, m_p.uv_max, 1};
        for (long visited = 0; top >= 0 && visited < kMostPiecesPerSearch; ++visited) {
            const Piece piece = stack[top];
            const glm::dvec2 size = piece.high - piece.low;
            double length = size.x;
            bool split_v = false;
            if (size.y > length) {
                length = size.y;
                split_v = true;
            }
            // The ray's parameter range in each coordinate's slab, checked
            // against the chord, the nearest crossing so far and the other
            // coordinates' ranges as POV checks them.
            Range slab[3];
            bool parallel[3];
            double entry = 0.0, widest = 0.0;
            bool dropped = false;
            for (int axis = 0; axis < 3 && !dropped; ++axis) {
                const Range bound = coordinate_bound(axis, piece);
                parallel[axis] = std::fabs(d[axis]) < kParallel;
                if (parallel[axis]) {
                    dropped = bound.high < o[axis] || bound.low > o[axis];
                    continue;
                }
                double a = (bound.high - o[axis]) / d[axis], b = (bound.low - o[axis]) / d[axis];
                if (a > b) std::swap(a, b);
                slab[axis] = {a, b};
                entry = a;
                dropped = a > exit || b < enter || a > nearest;
                for (int other = 0; other < axis && !dropped; ++other)
                    if (!parallel[other]) dropped = a > slab[other].high || b < slab[other].low;
                widest = std::max(widest, b - a);
            }
            if (dropped) {
                --top;
                continue;
            }
            if (length > widest) length = widest;
            if (length < m_p.accuracy || level_of(piece.number) >= kDeepestLevel) {
                if (nearest > entry && entry > enter) {
                    nearest = entry;
                    nearest_piece = piece.number;
                }
                --top;
                continue;
            }
            // The upper half stays where the piece was; the lower half goes
            // on top, searched first.
            const int axis = split_v ? 1 : 0;
            const double middle = (piece.high[axis] + piece.low[axis]) / 2.0;
            Piece lower = piece, upper = piece;
            lower.high[axis] = middle;
            lower.number = piece.number * 2;
            upper.low[axis] = middle;
            upper.number = piece.number * 2 + 1;
            stack[top] = upper;
            stack[++top] = lower;
        }
        if (nearest < exit && nearest > t_min && nearest < t_max) out.add(nearest, int(nearest_piece));
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        const glm::dvec2 uv = piece_corner(std::uint32_t(std::max(face, 1)));
        const DVec3 here = position(uv);
        const double h = m_p.accuracy;
        const DVec3 along_u = position(uv + glm::dvec2(h, 0.0)) - here;
        const DVec3 along_v = position(uv + glm::dvec2(0.0, h)) - here;
        DVec3 normal = glm::cross(along_u, along_v);
        // Scaled first, so tiny or huge differences still normalise.
        const double largest = std::max({std::fabs(normal.x), std::fabs(normal.y), std::fabs(normal.z)});
        if (largest > 0.0 && std::isfinite(largest)) normal /= largest;
        const double length = glm::length(normal);
        SurfaceGeometry g;
        g.point = p;
        g.normal =
            largest > 0.0 && std::isfinite(largest) && std::isfinite(length) ? normal / length : DVec3(0.0, 1.0, 0.0);
        g.uv = Vec2(float(uv.x), float(uv.y));
        return g;
    }

    bool inside(const DVec3&) const override { return false; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        m_p.container.bounds(lower, upper);
        return true;
    }

    bool solid() const override { return false; }

  private:
    double coordinate(int axis, const glm::dvec2& uv) const {
        const double arguments[3] = {uv.x, uv.y, 0.0};
        return sg::evaluate_function(*m_p.functions[std::size_t(axis)], arguments, 3,
                                     m_p.natives[std::size_t(axis)].get());
    }

    DVec3 position(const glm::dvec2& uv) const { return {coordinate(0, uv), coordinate(1, uv), coordinate(2, uv)}; }

    // POV's bound on one coordinate over a piece: along its two v edges,
    // then across u between those bounds; the values shifted by -accuracy.
    Range interval(int axis, const glm::dvec2& low, const glm::dvec2& high) const {
        const double shift = m_p.accuracy;
        const double f00 = coordinate(axis, low) - shift;
        const double f01 = coordinate(axis, {low.x, high.y}) - shift;
        const double f10 = coordinate(axis, {high.x, low.y}) - shift;
        const double f11 = coordinate(axis, high) - shift;
        const double gradient = m_p.max_gradient;
        const Range left = edge_bound(high.y - low.y, f00, f01, gradient);
        const Range right = edge_bound(high.y - low.y, f10, f11, gradient);
        return {edge_bound(high.x - low.x, left.low, right.low, gradient).low,
                edge_bound(high.x - low.x, left.high, right.high, gradient).high};
    }

    Range coordinate_bound(int axis, const Piece& piece) const {
        const std::vector<Range>& stored = m_precomputed[std::size_t(axis)];
        if (piece.number < stored.size()) return stored[piece.number];
        return interval(axis, piece.low, piece.high);
    }

    // precompute DEPTH: the bounds of pieces 1 .. 2^DEPTH - 1, each the
    // union of its halves' down to the pieces at level DEPTH - 1, which are
    // bounded as any piece is.
    void precompute() {
        if (m_p.precompute_depth < 1 || m_p.precompute_axes == 0) return;
        const std::size_t count = std::size_t(1) << m_p.precompute_depth;
        for (int axis = 0; axis < 3; ++axis)
            if (m_p.precompute_axes & (1 << axis)) m_precomputed[std::size_t(axis)].resize(count);
        precompute_piece(1, m_p.uv_min, m_p.uv_max, count / 2);
    }

    void precompute_piece(std::size_t number, const glm::dvec2& low, const glm::dvec2& high, std::size_t first_leaf) {
        if (number >= first_leaf) {
            for (int axis = 0; axis < 3; ++axis)
                if (!m_precomputed[std::size_t(axis)].empty())
                    m_precomputed[std::size_t(axis)][number] = interval(axis, low, high);
            return;
        }
        const int split = high.x - low.x < high.y - low.y ? 1 : 0;
        glm::dvec2 middle_high = high, middle_low = low;
        middle_high[split] = middle_low[split] = (low[split] + high[split]) / 2.0;
        precompute_piece(2 * number, low, middle_high, first_leaf);
        precompute_piece(2 * number + 1, middle_low, high, first_leaf);
        for (std::vector<Range>& stored : m_precomputed) {
            if (stored.empty()) continue;
            const Range a = stored[2 * number], b = stored[2 * number + 1];
            stored[number] = {std::min(a.low, b.low), std::max(a.high, b.high)};
        }
    }

    // The lower corner of a piece, from its number: the halvings replayed.
    glm::dvec2 piece_corner(std::uint32_t number) const {
        glm::dvec2 low = m_p.uv_min, high = m_p.uv_max;
        for (int bit = level_of(number) - 1; bit >= 0; --bit) {
            const int axis = high.y - low.y > high.x - low.x ? 1 : 0;
            const double middle = (high[axis] + low[axis]) / 2.0;
            if ((number >> bit) & 1u)
                low[axis] = middle;
            else
                high[axis] = middle;
        }
        return low;
    }

    // POV's chord: a box's from the ray's origin at the earliest, a
    // sphere's from where the line enters it (behind the origin when the
    // origin is inside).
    bool container_chord(const DVec3& o, const DVec3& d, double& enter, double& exit) const {
        if (m_p.container.sphere) {
            const double length = glm::length(d);
            if (!(length > 0.0)) return false;
            const DVec3 unit = d / length;
            const DVec3 to_center = m_p.container.sphere_center - o;
            const double distance2 = glm::dot(to_center, to_center);
            const double closest = glm::dot(to_center, unit);
            const double radius2 = m_p.container.sphere_radius * m_p.container.sphere_radius;
            if (distance2 >= radius2 && closest < kParallel) return false;
            const double half2 = radius2 - distance2 + closest * closest;
            if (!(half2 > kParallel)) return false;
            const double half = std::sqrt(half2);
            enter = (closest - half) / length;
            exit = (closest + half) / length;
            return true;
        }
        enter = 0.0;
        exit = HUGE_VAL;
        for (int axis = 0; axis < 3; ++axis) {
            const double lower = m_p.container.box_lower[axis], upper = m_p.container.box_upper[axis];
            if (std::fabs(d[axis]) < kParallel) {
                if (o[axis] < lower || o[axis] > upper) return false;
                continue;
            }
            double a = (lower - o[axis]) / d[axis], b = (upper - o[axis]) / d[axis];
            if (a > b) std::swap(a, b);
            enter = std::max(enter, a);
            exit = std::min(exit, b);
            if (enter > exit) return false;
        }
        return true;
    }

    ParametricParameters m_p;
    std::array<std::vector<Range>, 3> m_precomputed;
};

}  // namespace

std::shared_ptr<const Shape> make_parametric_shape(const ParametricParameters& parameters) {
    const ParametricParameters& p = parameters;
    for (const auto& function : p.functions)
        if (!function) return nullptr;
    if (!p.container.usable() || !(p.accuracy > 0.0) || !std::isfinite(p.accuracy) || !(p.max_gradient > 0.0) ||
        !std::isfinite(p.max_gradient) || !std::isfinite(p.uv_min.x + p.uv_min.y + p.uv_max.x + p.uv_max.y))
        return nullptr;
    if (p.precompute_axes != 0 && (p.precompute_depth < 1 || p.precompute_depth > 20)) return nullptr;
    ParametricParameters kept = p;
    kept.container = p.container.ordered();
    kept.uv_min = glm::min(p.uv_min, p.uv_max);
    kept.uv_max = glm::max(p.uv_min, p.uv_max);
    return std::make_shared<ParametricShape>(kept);
}

}  // namespace lancer
