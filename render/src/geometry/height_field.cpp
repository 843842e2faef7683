// POV-Ray's height_field: a grid of heights over the unit square, each
// cell two triangles split along the diagonal from (c + 1, r) to
// (c, r + 1), as POV-Ray 3.7 triangulates it (HField::intersect_pixel). In
// object space the shape spans x, z in [0, 1] and y the heights; the grid
// is columns x rows points (height_field.h). It is an open surface: POV
// draws neither sides nor a bottom, and `water_level` only clips the box
// the rays are traced in, so the surface below it vanishes, cut flat.
//
// Intersection: the ray is clipped to the bounding box, then walked front
// to back through a pyramid of min/max blocks (8 x 8 cells, then 8 x 8 of
// those, ...) with a 2-D DDA on each level; a block the ray passes wholly
// above or below is skipped. In a cell the ray is cut at the diagonal, and
// on each piece both the ray and the triangle are linear in t, so the
// height of the ray above the surface, g(t), is linear: a crossing is a
// sign change of g between the piece's ends, found by interpolation and
// polished by one Newton step. Because g is continuous along the ray and
// the value at each shared piece end is carried over rather than
// recomputed, every crossing is counted once, none twice, even through
// grid edges and corners (what CSG needs). No polynomial solver is needed.
//
// Normals: flat per triangle; with `smooth`, POV's vertex normals (the
// mean of the four neighbouring quadrant triangles' unit normals, in the
// grid's 65536-per-unit height scale, truncated to POV's 16-bit storage)
// interpolated bilinearly over the cell. POV-Ray normalizes each vertex
// normal after the whole object transform; here it is normalized in
// object space, which differs only under a non-uniform scale.
//
// (u, v): POV-Ray 3.7 gives height fields no mapping of their own (its
// default is the world x, y of the hit); lancer gives object (x, z).
// Inside (POV's HField::Inside): within the footprint (x, z in [0, 1)),
// below the top of the box and below the surface or below the bottom of
// the box (the water level), down to minus infinity.
#include <algorithm>
#include <climits>
#include <cmath>

#include "geometry/height_field.h"

namespace lancer {
namespace {

// POV-Ray pads its box by 0.001 in the grid's 65536-per-unit height scale.
constexpr double kBoxPadding = 0.001 / 65536.0;
// Slack on the block tests (object height units): far above the rounding
// of ray heights over a unit box, far below any visible detail.
constexpr double kBlockSlack = 1e-9;
constexpr int kBlockFanout = 8;

// Sign test shared by every piece: a crossing is where "above" changes.
inline bool above(double g) {
    return g > 0.0;
}

class HeightFieldShape final : public Shape {
  public:
    HeightFieldShape(HeightFieldGrid grid, bool smooth, double water_level)
        : m_columns(grid.columns),
          m_rows(grid.rows),
          m_cells_x(grid.columns - 1),
          m_cells_z(grid.rows - 1),
          m_heights(std::move(grid.heights)),
          m_smooth(smooth) {
        float lowest = m_heights[0], highest = m_heights[0];
        for (float h : m_heights) {
            lowest = std::min(lowest, h);
            highest = std::max(highest, h);
        }
        m_floor = std::max(double(lowest), water_level) - kBoxPadding;
        m_top = double(highest) + kBoxPadding;
        build_pyramid();
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        double t_lo = t_min, t_hi = t_max;
        if (!ray_box_interval(DVec3(0.0, m_floor, 0.0), DVec3(1.0, m_top, 1.0), o, d, t_lo, t_hi)) return;
        if (!(t_lo < t_hi) || !std::isfinite(t_lo) || !std::isfinite(t_hi)) return;
        // The origin moved to the box entry keeps far rays' digits; grid
        // units (one per cell) make cell indices integers.
        const DVec3 start = o + t_lo * d;
        Walk walk;
        walk.origin = DVec3(start.x * m_cells_x, start.y, start.z * m_cells_z);
        walk.direction = DVec3(d.x * m_cells_x, d.y, d.z * m_cells_z);
        walk.t_offset = t_lo;
        walk.t_min = t_min;
        walk.t_max = t_max;
        walk.out = &out;
        const Level& top = m_levels.back();
        walk_level(int(m_levels.size()), 0, 0, top.blocks_x, top.blocks_z, 0.0, t_hi - t_lo, walk);
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        int cell_x, cell_z, triangle;
        if (face >= 0 && face < 2 * m_cells_x * m_cells_z) {
            triangle = face & 1;
            cell_x = (face >> 1) % m_cells_x;
            cell_z = (face >> 1) / m_cells_x;
        } else {
            locate(p, cell_x, cell_z, triangle);
        }
        const Plane plane = triangle_plane(cell_x, cell_z, triangle);
        // The plane in object space: y = base + slope_x X + slope_z Z with
        // X, Z the cell-local grid coordinates.
        const DVec3 normal(-plane.slope_x * m_cells_x, 1.0, -plane.slope_z * m_cells_z);
        const double lx = p.x * m_cells_x - cell_x, lz = p.z * m_cells_z - cell_z;
        const double miss = p.y - (plane.base + plane.slope_x * lx + plane.slope_z * lz);
        const double length2 = glm::dot(normal, normal);
        SurfaceGeometry g;
        g.point = p - (miss / length2) * normal;
        g.normal = normal / std::sqrt(length2);
        if (m_smooth) {
            const double fx = std::clamp(g.point.x * m_cells_x - cell_x, 0.0, 1.0);
            const double fz = std::clamp(g.point.z * m_cells_z - cell_z, 0.0, 1.0);
            const DVec3 blended =
                (1.0 - fz) * ((1.0 - fx) * vertex_normal(cell_x, cell_z) + fx * vertex_normal(cell_x + 1, cell_z)) +
                fz * ((1.0 - fx) * vertex_normal(cell_x, cell_z + 1) + fx * vertex_normal(cell_x + 1, cell_z + 1));
            const double blended_length = glm::length(blended);
            if (blended_length > 1e-12 && std::isfinite(blended_length)) g.shading_normal = blended / blended_length;
        }
        g.uv = Vec2(float(g.point.x), float(g.point.z));
        return g;
    }

    bool inside(const DVec3& p) const override {
        const double x = p.x * m_cells_x, z = p.z * m_cells_z;
        if (!(x >= 0.0 && x < m_cells_x && z >= 0.0 && z < m_cells_z)) return false;
        if (p.y >= m_top) return false;
        if (p.y < m_floor) return true;
        const int cell_x = std::clamp(int(x), 0, m_cells_x - 1), cell_z = std::clamp(int(z), 0, m_cells_z - 1);
        const double lx = x - cell_x, lz = z - cell_z;
        // POV raises the corners to the water level here.
        auto height = [&](int c, int r) { return std::max(double(at(c, r)), m_floor); };
        double surface;
        if (lx + lz < 1.0) {
            const double h00 = height(cell_x, cell_z);
            surface = h00 + (height(cell_x + 1, cell_z) - h00) * lx + (height(cell_x, cell_z + 1) - h00) * lz;
        } else {
            const double h11 = height(cell_x + 1, cell_z + 1);
            surface =
                h11 + (height(cell_x, cell_z + 1) - h11) * (1.0 - lx) + (height(cell_x + 1, cell_z) - h11) * (1.0 - lz);
        }
        return p.y < surface;
    }

    // POV's inside runs on below the floor, which the box stops at.
    bool inside_within_bounds() const override { return false; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = DVec3(0.0, m_floor, 0.0);
        upper = DVec3(1.0, m_top, 1.0);
        return true;
    }

  private:
    // Level k >= 1 of the pyramid: blocks of fanout^k cells, each with the
    // range of the heights at its cells' corners.
    struct Level {
        int cells_per_block = 1;
        int blocks_x = 0, blocks_z = 0;
        std::vector<float> lowest, highest;  // blocks_z x blocks_x
    };
    // One triangle as heights over its cell: base + slope_x lx + slope_z lz
    // with lx, lz the cell-local grid coordinates (0..1).
    struct Plane {
        double base, slope_x, slope_z;
    };
    // The state of one ray's walk: the ray in grid units from the box
    // entry, and the last piece end and g there, carried to the next
    // piece so a crossing on a shared end is seen exactly once.
    struct Walk {
        DVec3 origin, direction;
        double t_offset = 0.0, t_min = 0.0, t_max = 0.0;
        double last_s = NAN, last_g = 0.0;
        ShapeCrossings* out = nullptr;
        bool full() const { return out->count >= ShapeCrossings::kCapacity; }
    };

    float at(int column, int row) const { return m_heights[std::size_t(row) * m_columns + column]; }

    void build_pyramid() {
        // Level 1 straight from the heights, each further level from the one below.
        int cells_per_block = kBlockFanout;
        for (;;) {
            Level level;
            level.cells_per_block = cells_per_block;
            level.blocks_x = (m_cells_x + cells_per_block - 1) / cells_per_block;
            level.blocks_z = (m_cells_z + cells_per_block - 1) / cells_per_block;
            const std::size_t count = std::size_t(level.blocks_x) * level.blocks_z;
            level.lowest.assign(count, INFINITY);
            level.highest.assign(count, -INFINITY);
            if (m_levels.empty()) {
                for (int row = 0; row < m_rows; ++row) {
                    // A point on a block border belongs to the blocks on both sides.
                    const int bz_lo = row == 0 ? 0 : (row - 1) / cells_per_block;
                    const int bz_hi = std::min(row / cells_per_block, level.blocks_z - 1);
                    for (int column = 0; column < m_columns; ++column) {
                        const int bx_lo = column == 0 ? 0 : (column - 1) / cells_per_block;
                        const int bx_hi = std::min(column / cells_per_block, level.blocks_x - 1);
                        const float h = at(column, row);
                        for (int bz = bz_lo; bz <= bz_hi; ++bz)
                            for (int bx = bx_lo; bx <= bx_hi; ++bx) {
                                const std::size_t index = std::size_t(bz) * level.blocks_x + bx;
                                level.lowest[index] = std::min(level.lowest[index], h);
                                level.highest[index] = std::max(level.highest[index], h);
                            }
                    }
                }
            } else {
                const Level& below = m_levels.back();
                for (int bz = 0; bz < below.blocks_z; ++bz)
                    for (int bx = 0; bx < below.blocks_x; ++bx) {
                        const std::size_t from = std::size_t(bz) * below.blocks_x + bx;
                        const std::size_t to =
                            std::size_t(bz / kBlockFanout) * level.blocks_x + std::size_t(bx / kBlockFanout);
                        level.lowest[to] = std::min(level.lowest[to], below.lowest[from]);
                        level.highest[to] = std::max(level.highest[to], below.highest[from]);
                    }
            }
            const bool single = level.blocks_x == 1 && level.blocks_z == 1;
            m_levels.push_back(std::move(level));
            if (single) break;
            cells_per_block *= kBlockFanout;
        }
    }

    // Walks the ray over [s0, s1] through the blocks [bx0, bx1) x [bz0, bz1)
    // of `level` (0: cells; k: m_levels[k - 1]), front to back.
    void walk_level(int level, int bx0, int bz0, int bx1, int bz1, double s0, double s1, Walk& walk) const {
        const int size = level == 0 ? 1 : m_levels[std::size_t(level) - 1].cells_per_block;
        const DVec3& o = walk.origin;
        const DVec3& d = walk.direction;
        auto block_of = [&](double coordinate, int lo, int hi) {
            const double index = std::floor(coordinate / size);
            return int(std::clamp(index, double(lo), double(hi - 1)));
        };
        // The start block from just inside the interval, not its end: an
        // end on a block border belongs to the block the ray goes into.
        const double s_probe = s0 + 1e-9 * (s1 - s0);
        int bx = block_of(o.x + s_probe * d.x, bx0, bx1);
        int bz = block_of(o.z + s_probe * d.z, bz0, bz1);
        const int step_x = d.x > 0.0 ? 1 : -1, step_z = d.z > 0.0 ? 1 : -1;
        double sa = s0;
        // Each step moves to a neighbouring block, so this bounds the walk.
        for (int steps = (bx1 - bx0) + (bz1 - bz0) + 2; steps > 0 && !walk.full(); --steps) {
            const double sx = d.x == 0.0 ? INFINITY : ((bx + (step_x > 0 ? 1 : 0)) * double(size) - o.x) / d.x;
            const double sz = d.z == 0.0 ? INFINITY : ((bz + (step_z > 0 ? 1 : 0)) * double(size) - o.z) / d.z;
            const double sb = std::max(sa, std::min({sx, sz, s1}));
            if (level == 0) {
                cell(bx, bz, sa, sb, walk);
            } else {
                const Level& blocks = m_levels[std::size_t(level) - 1];
                const std::size_t index = std::size_t(bz) * blocks.blocks_x + bx;
                const double ya = o.y + sa * d.y, yb = o.y + sb * d.y;
                if (std::max(ya, yb) >= blocks.lowest[index] - kBlockSlack &&
                    std::min(ya, yb) <= blocks.highest[index] + kBlockSlack) {
                    const int below_x = level == 1 ? m_cells_x : m_levels[std::size_t(level) - 2].blocks_x;
                    const int below_z = level == 1 ? m_cells_z : m_levels[std::size_t(level) - 2].blocks_z;
                    walk_level(level - 1, bx * kBlockFanout, bz * kBlockFanout,
                               std::min((bx + 1) * kBlockFanout, below_x), std::min((bz + 1) * kBlockFanout, below_z),
                               sa, sb, walk);
                }
            }
            if (sb >= s1) break;
            const bool cross_x = sx <= sz, cross_z = sz <= sx;
            if (cross_x) bx += step_x;
            if (cross_z) bz += step_z;
            if (bx < bx0 || bx >= bx1 || bz < bz0 || bz >= bz1) break;
            sa = sb;
        }
    }

    Plane triangle_plane(int cell_x, int cell_z, int triangle) const {
        if (triangle == 0) {
            const double h00 = at(cell_x, cell_z);
            return {h00, at(cell_x + 1, cell_z) - h00, at(cell_x, cell_z + 1) - h00};
        }
        // The far triangle about (1, 1): h11 + (h01 - h11)(1 - lx) + (h10 - h11)(1 - lz).
        const double h11 = at(cell_x + 1, cell_z + 1), h01 = at(cell_x, cell_z + 1), h10 = at(cell_x + 1, cell_z);
        const double slope_x = h11 - h01, slope_z = h11 - h10;
        return {h11 - slope_x - slope_z, slope_x, slope_z};
    }

    // The ray's height over one triangle's plane at s.
    static double gap(const Plane& plane, double lx0, double lz0, const DVec3& o, const DVec3& d, double s) {
        return o.y + s * d.y - (plane.base + plane.slope_x * (lx0 + s * d.x) + plane.slope_z * (lz0 + s * d.z));
    }

    // The crossings of the ray over [sa, sb] inside cell (cell_x, cell_z).
    void cell(int cell_x, int cell_z, double sa, double sb, Walk& walk) const {
        const DVec3& o = walk.origin;
        const DVec3& d = walk.direction;
        const float h00 = at(cell_x, cell_z), h10 = at(cell_x + 1, cell_z);
        const float h01 = at(cell_x, cell_z + 1), h11 = at(cell_x + 1, cell_z + 1);
        const double ya = o.y + sa * d.y, yb = o.y + sb * d.y;
        if (std::max(ya, yb) < std::min({h00, h10, h01, h11}) - kBlockSlack ||
            std::min(ya, yb) > std::max({h00, h10, h01, h11}) + kBlockSlack)
            return;
        // Cell-local coordinates of the origin.
        const double lx0 = o.x - cell_x, lz0 = o.z - cell_z;
        // Where the ray meets the diagonal lx + lz = 1.
        const double qa = lx0 + lz0 + sa * (d.x + d.z) - 1.0, qb = lx0 + lz0 + sb * (d.x + d.z) - 1.0;
        double ends[3] = {sa, sb, sb};
        int pieces = 1;
        if ((qa < 0.0 && qb > 0.0) || (qa > 0.0 && qb < 0.0)) {
            ends[1] = std::clamp(sa + (sb - sa) * (qa / (qa - qb)), sa, sb);
            pieces = 2;
        }
        for (int piece = 0; piece < pieces && !walk.full(); ++piece) {
            const double a = ends[piece], b = ends[piece + 1];
            const double s_mid = 0.5 * (a + b);
            const int triangle = lx0 + lz0 + s_mid * (d.x + d.z) - 1.0 <= 0.0 ? 0 : 1;
            const Plane plane = triangle_plane(cell_x, cell_z, triangle);
            const bool carried = a == walk.last_s;
            double ga = carried ? walk.last_g : gap(plane, lx0, lz0, o, d, a);
            // A piece of no length must not see a second sign at its one point.
            const double gb = b == a ? ga : gap(plane, lx0, lz0, o, d, b);
            // A fresh start exactly on the surface (an origin on it, a ray
            // touching the rim as it enters) is no crossing.
            if (!carried && ga == 0.0) ga = gb;
            walk.last_s = b;
            walk.last_g = gb;
            if (above(ga) == above(gb)) continue;
            double s = std::clamp(a + (b - a) * (ga / (ga - gb)), a, b);
            // One Newton step on the exact plane: the interpolation carries
            // the rounding of both ends.
            const double slope = d.y - (plane.slope_x * d.x + plane.slope_z * d.z);
            if (slope != 0.0) {
                const double polished = s - gap(plane, lx0, lz0, o, d, s) / slope;
                if (polished >= a && polished <= b) s = polished;
            }
            const double t = walk.t_offset + s;
            if (t > walk.t_min && t < walk.t_max) walk.out->add(t, 2 * (cell_z * m_cells_x + cell_x) + triangle);
        }
    }

    // The cell and triangle under p (for a face number that names none).
    void locate(const DVec3& p, int& cell_x, int& cell_z, int& triangle) const {
        const double x = std::clamp(p.x * m_cells_x, 0.0, double(m_cells_x));
        const double z = std::clamp(p.z * m_cells_z, 0.0, double(m_cells_z));
        cell_x = std::min(int(x), m_cells_x - 1);
        cell_z = std::min(int(z), m_cells_z - 1);
        triangle = (x - cell_x) + (z - cell_z) <= 1.0 ? 0 : 1;
    }

    // POV's smoothed normal at grid point (c, r), in object space, unit:
    // the four quadrant triangles about it (those inside the grid), each
    // unit and facing up, in grid units with heights at 65536 per unit;
    // summed, made unit, truncated to POV's 16-bit store.
    DVec3 vertex_normal(int c, int r) const {
        const int neighbours[4][4] = {{1, 0, 0, 1}, {0, 1, -1, 0}, {-1, 0, 0, -1}, {0, -1, 1, 0}};
        const DVec3 v0(c, 65536.0 * at(c, r), r);
        DVec3 sum(0.0);
        for (const auto& q : neighbours) {
            const int c1 = c + q[0], r1 = r + q[1], c2 = c + q[2], r2 = r + q[3];
            if (std::min({c1, r1, c2, r2}) < 0 || std::max(c1, c2) > m_cells_x || std::max(r1, r2) > m_cells_z)
                continue;
            const DVec3 v1(c1, 65536.0 * at(c1, r1), r1), v2(c2, 65536.0 * at(c2, r2), r2);
            DVec3 n = glm::cross(v2 - v0, v1 - v0);
            n /= glm::length(n);
            if (n.y < 0.0) n = -n;
            sum += n;
        }
        sum /= glm::length(sum);
        const DVec3 stored(double(short(32767.0 * sum.x)), double(short(32767.0 * sum.y)),
                           double(short(32767.0 * sum.z)));
        // From grid to object space: normals scale by the inverse.
        const DVec3 object(stored.x * m_cells_x, stored.y * 65536.0, stored.z * m_cells_z);
        const double length = glm::length(object);
        return length > 0.0 ? object / length : DVec3(0.0, 1.0, 0.0);
    }

    int m_columns, m_rows, m_cells_x, m_cells_z;
    std::vector<float> m_heights;
    bool m_smooth;
    double m_floor = 0.0, m_top = 1.0;  // the box POV traces in
    std::vector<Level> m_levels;
};

}  // namespace

std::shared_ptr<const Shape> make_height_field_shape(HeightFieldGrid grid, bool smooth, double water_level) {
    if (grid.columns < 2 || grid.rows < 2) return nullptr;
    const double cells = double(grid.columns - 1) * double(grid.rows - 1);
    if (2.0 * cells > double(INT_MAX)) return nullptr;
    if (grid.heights.size() != std::size_t(grid.columns) * std::size_t(grid.rows)) return nullptr;
    for (float h : grid.heights)
        if (!std::isfinite(h)) return nullptr;
    if (!std::isfinite(water_level)) water_level = 0.0;
    return std::make_shared<HeightFieldShape>(std::move(grid), smooth, water_level);
}

}  // namespace lancer
