// POV-Ray's triangle meshes (mesh, mesh2, triangle, smooth_triangle) as a
// Shape: the triangles as given, in the mesh's object space.
//
// Intersection: a BVH over the triangles (binned SAH, 16 bins on the
// widest centroid axis, at most 8 triangles a leaf, node boxes in float
// rounded outwards), walked near child first, and the watertight
// ray/triangle test of Woop, Benthin and Wald (JCGT 2013): the corners are
// moved to the ray's origin, sheared so the ray runs along +z, and the
// line's point in the sheared plane is tested against the three edges.
// Each corner's sheared coordinates depend on the corner alone, so two
// triangles sharing an edge evaluate that edge's function on the same
// numbers. Unlike the paper, the edge function's sign is exact (a float
// filter, then an exact expansion from fma's rounding errors) and a line
// exactly on an edge or through a corner is decided by a symbolic
// perturbation of the line (by (e, e^2) in the sheared plane), so a line
// through a shared edge or vertex crosses exactly one of the triangles
// there (or two, or none, where the surface folds over): the parity the
// inside test counts is right however the line meets the mesh. The depth
// comes from the same edge functions; no polishing is needed, as the
// crossing is one division of well-conditioned sums.
//
// Inside: POV-Ray's Mesh::Inside. With inside_vector the point is inside
// when the ray from it along that vector crosses the mesh an odd number of
// times (all crossings, not the ShapeCrossings cap); POV counts with its
// own per-triangle test, which may count a shared edge twice, lancer
// counts it once. Without inside_vector nothing is inside (POV's
// "patch objects"; a triangle or smooth_triangle alone is one too).
//
// Normals follow lancer's mesh hit completion: the geometric normal is
// cross(p1 - p0, p2 - p0) (counter-clockwise corners face the viewer; POV's
// own is the opposite, cross(p2 - p0, p1 - p0), and both renderers face it
// towards the ray for shading), a smooth face's the barycentric blend of
// its corner normals. (u, v): the blend of the face's uv vectors, else the
// barycentric weights (b1, b2) of corners 1 and 2, as Embree reports.
#include "geometry/mesh_shape.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>

namespace lancer {
namespace {

constexpr double kUnitRoundoff = 0.5 * std::numeric_limits<double>::epsilon();

// Knuth's two-sum: sum + error == a + b exactly.
inline void two_sum(double a, double b, double& sum, double& error) {
    sum = a + b;
    const double b_part = sum - a;
    const double a_part = sum - b_part;
    error = (a - a_part) + (b - b_part);
}

// The exact sign of a b - c d (barring underflow): the rounded result when
// it is clear of its error bound, else the sum of the products and their
// rounding errors (fma gives those exactly) as a Shewchuk expansion, whose
// largest nonzero component has the sum's sign.
int sign_of_product_difference(double a, double b, double c, double d, double& rounded) {
    const double ab = a * b, cd = c * d;
    rounded = ab - cd;
    const double bound = 4.0 * kUnitRoundoff * (std::fabs(ab) + std::fabs(cd));
    if (rounded > bound) return 1;
    if (rounded < -bound) return -1;
    const double terms[4] = {ab, std::fma(a, b, -ab), -cd, -std::fma(c, d, -cd)};
    double expansion[4];
    int length = 0;
    for (double term : terms) {
        double carry = term;
        for (int i = 0; i < length; ++i) two_sum(carry, expansion[i], carry, expansion[i]);
        expansion[length++] = carry;
    }
    for (int i = length - 1; i >= 0; --i)
        if (expansion[i] != 0.0) return expansion[i] > 0.0 ? 1 : -1;
    return 0;
}

// A corner in the ray's sheared frame: the line is x = y = 0, z the depth
// in units of the ray's parameter t.
struct ShearedPoint {
    double x, y, z;
};

// The line o + t d in Woop et al.'s frame, and what box tests need.
struct LineFrame {
    DVec3 origin;
    int kx = 0, ky = 1, kz = 2;
    double shear_x = 0.0, shear_y = 0.0, shear_z = 1.0;
    DVec3 inverse_direction;
    bool parallel[3] = {false, false, false};  // no usable 1/d on this axis

    // False for a zero or non-finite direction.
    bool set(const DVec3& o, const DVec3& d) {
        if (!std::isfinite(o.x + o.y + o.z + d.x + d.y + d.z)) return false;
        const DVec3 magnitude = glm::abs(d);
        kz = magnitude.x > magnitude.y ? (magnitude.x > magnitude.z ? 0 : 2) : (magnitude.y > magnitude.z ? 1 : 2);
        if (!(magnitude[kz] > 0.0)) return false;
        kx = (kz + 1) % 3;
        ky = (kx + 1) % 3;
        origin = o;
        shear_x = d[kx] / d[kz];
        shear_y = d[ky] / d[kz];
        shear_z = 1.0 / d[kz];
        for (int axis = 0; axis < 3; ++axis) {
            inverse_direction[axis] = 1.0 / d[axis];
            parallel[axis] = !std::isfinite(inverse_direction[axis]);
        }
        return true;
    }

    ShearedPoint shear(const DVec3& p) const {
        const DVec3 a = p - origin;
        return {a[kx] - shear_x * a[kz], a[ky] - shear_y * a[kz], shear_z * a[kz]};
    }
};

// Which side of the directed edge p -> q the line passes, in the sheared
// plane: +1 left, -1 right, 0 only for an edge seen end-on. Exactly on the
// edge, the side the line moved by (e, e^2) passes (the derivative of the
// edge function along that move); swapping p and q flips every answer.
// `value` receives the rounded edge function, 0 where its sign is not the
// answer.
int edge_side(const ShearedPoint& p, const ShearedPoint& q, double& value) {
    const int sign = sign_of_product_difference(p.x, q.y, p.y, q.x, value);
    if (sign != 0) {
        if ((value > 0.0) != (sign > 0)) value = 0.0;
        return sign;
    }
    value = 0.0;
    if (p.y != q.y) return p.y > q.y ? 1 : -1;
    if (p.x != q.x) return q.x > p.x ? 1 : -1;
    return 0;
}

// The line's crossing with triangle (a, b, c), at parameter t.
bool cross_triangle(const LineFrame& line, const DVec3& a, const DVec3& b, const DVec3& c, double& t) {
    const ShearedPoint sa = line.shear(a), sb = line.shear(b), sc = line.shear(c);
    double u, v, w;  // twice the areas opposite a, b and c
    const int side = edge_side(sb, sc, u);
    if (side == 0 || edge_side(sc, sa, v) != side || edge_side(sa, sb, w) != side) return false;
    const double determinant = u + v + w;
    if (determinant == 0.0) return false;
    t = (u * sa.z + v * sb.z + w * sc.z) / determinant;
    return std::isfinite(t);
}

float round_down(double x) {
    float f = float(x);
    if (double(f) > x) f = std::nextafter(f, -std::numeric_limits<float>::infinity());
    return f;
}
float round_up(double x) {
    float f = float(x);
    if (double(f) < x) f = std::nextafter(f, std::numeric_limits<float>::infinity());
    return f;
}

struct FloatBox {
    float lower[3] = {INFINITY, INFINITY, INFINITY};
    float upper[3] = {-INFINITY, -INFINITY, -INFINITY};
    void grow(const FloatBox& other) {
        for (int k = 0; k < 3; ++k) {
            lower[k] = std::min(lower[k], other.lower[k]);
            upper[k] = std::max(upper[k], other.upper[k]);
        }
    }
    // Half the surface area (what SAH compares), 0 when empty.
    double half_area() const {
        const double x = double(upper[0]) - lower[0], y = double(upper[1]) - lower[1], z = double(upper[2]) - lower[2];
        if (!(x >= 0.0 && y >= 0.0 && z >= 0.0)) return 0.0;
        return x * y + y * z + z * x;
    }
};

struct BvhNode {
    FloatBox box;
    std::uint32_t first = 0;  // interior: the first of its two adjacent children; leaf: its first triangle
    std::uint32_t count = 0;  // triangles; 0 for an interior node
};

struct PackedTriangle {
    std::uint32_t corner[3];
    std::uint32_t face;
};

// Conservative parameter interval of the line inside `box`, clipped to
// [t_min, t_max]: the slab bounds are widened by their rounding (pbrt's
// 2 gamma(3)), so no triangle the exact test finds is culled.
bool box_interval(const FloatBox& box, const LineFrame& line, double t_min, double t_max, double& t_enter) {
    constexpr double kWiden = 4.0 * std::numeric_limits<double>::epsilon();
    double lo = t_min, hi = t_max;
    for (int axis = 0; axis < 3; ++axis) {
        const double o = line.origin[axis];
        if (line.parallel[axis]) {
            if (o < box.lower[axis] || o > box.upper[axis]) return false;
            continue;
        }
        double t0 = (double(box.lower[axis]) - o) * line.inverse_direction[axis];
        double t1 = (double(box.upper[axis]) - o) * line.inverse_direction[axis];
        if (t0 > t1) std::swap(t0, t1);
        t0 -= std::fabs(t0) * kWiden;
        t1 += std::fabs(t1) * kWiden;
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
        if (!(lo <= hi)) return false;
    }
    t_enter = lo;
    return true;
}

constexpr int kBins = 16;
constexpr std::uint32_t kMaxLeafTriangles = 8;
constexpr int kSahDepthLimit = 48;  // deeper splits halve by count, so depth stays under kStackDepth
constexpr int kStackDepth = 128;

class MeshShape final : public Shape {
  public:
    explicit MeshShape(MeshShapeParameters mesh) : m_mesh(std::move(mesh)) {
        if (m_mesh.inside_vector) {
            const DVec3 v = *m_mesh.inside_vector;
            m_has_inside = std::isfinite(v.x + v.y + v.z) && glm::dot(v, v) > 0.0;
            if (m_has_inside) m_inside_vector = v;
        }
        build();
    }

    bool empty() const { return m_triangles.empty(); }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const int capacity = ShapeCrossings::kCapacity - out.count;
        if (capacity <= 0 || !(t_min < t_max)) return;
        LineFrame line;
        if (!line.set(o, d)) return;
        // The nearest `capacity` crossings, sorted; once full, nothing
        // beyond the farthest kept matters, which prunes the walk.
        ShapeCrossing kept[ShapeCrossings::kCapacity];
        int count = 0;
        double limit = t_max;
        struct Entry {
            std::uint32_t node;
            double t_enter;
        };
        Entry stack[kStackDepth];
        int depth = 0;
        double t_enter;
        if (!box_interval(m_nodes[0].box, line, t_min, t_max, t_enter)) return;
        stack[depth++] = {0, t_enter};
        while (depth > 0) {
            const Entry entry = stack[--depth];
            if (entry.t_enter > limit) continue;
            const BvhNode& node = m_nodes[entry.node];
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    const PackedTriangle& triangle = m_triangles[i];
                    double t;
                    if (!cross_at(line, triangle, t) || !(t > t_min && t < limit)) continue;
                    int slot = count < capacity ? count++ : capacity - 1;
                    while (slot > 0 && kept[slot - 1].t > t) {
                        kept[slot] = kept[slot - 1];
                        --slot;
                    }
                    kept[slot] = ShapeCrossing{t, int(triangle.face)};
                    if (count == capacity) limit = kept[capacity - 1].t;
                }
                continue;
            }
            double near_t, far_t;
            std::uint32_t near_child = node.first, far_child = node.first + 1;
            const bool near_hit = box_interval(m_nodes[near_child].box, line, t_min, limit, near_t);
            const bool far_hit = box_interval(m_nodes[far_child].box, line, t_min, limit, far_t);
            if (near_hit && far_hit) {
                if (far_t < near_t) {
                    std::swap(near_child, far_child);
                    std::swap(near_t, far_t);
                }
                stack[depth++] = {far_child, far_t};
                stack[depth++] = {near_child, near_t};
            } else if (near_hit) {
                stack[depth++] = {near_child, near_t};
            } else if (far_hit) {
                stack[depth++] = {far_child, far_t};
            }
        }
        for (int i = 0; i < count; ++i) out.add(kept[i].t, kept[i].face);
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        SurfaceGeometry g;
        g.point = p;
        g.normal = DVec3(0.0, 1.0, 0.0);
        g.uv = Vec2(0.0f);
        if (face < 0 || std::size_t(face) >= m_mesh.faces.size()) return g;
        const MeshShapeParameters::Face& f = m_mesh.faces[std::size_t(face)];
        for (int k = 0; k < 3; ++k)
            if (f.position[k] < 0 || std::size_t(f.position[k]) >= m_mesh.positions.size()) return g;
        const DVec3& p0 = m_mesh.positions[std::size_t(f.position[0])];
        const DVec3& p1 = m_mesh.positions[std::size_t(f.position[1])];
        const DVec3& p2 = m_mesh.positions[std::size_t(f.position[2])];
        const DVec3 edge1 = p1 - p0, edge2 = p2 - p0;
        const DVec3 area_normal = glm::cross(edge1, edge2);
        const double area2 = glm::dot(area_normal, area_normal);
        if (!(area2 > 0.0) || !std::isfinite(area2)) return g;
        const DVec3 normal = area_normal / std::sqrt(area2);
        g.point = p - glm::dot(p - p0, normal) * normal;
        g.normal = normal;
        // Barycentric weights of the projected point (clamped onto the
        // triangle: the point is on it up to rounding).
        const DVec3 offset = g.point - p0;
        double b1 = glm::dot(glm::cross(offset, edge2), area_normal) / area2;
        double b2 = glm::dot(glm::cross(edge1, offset), area_normal) / area2;
        b1 = std::clamp(b1, 0.0, 1.0);
        b2 = std::clamp(b2, 0.0, 1.0 - b1);
        const double weight[3] = {1.0 - b1 - b2, b1, b2};
        if (f.normal[0] >= 0) {
            DVec3 blended(0.0);
            for (int k = 0; k < 3; ++k) {
                const int n = f.normal[k];
                if (n >= 0 && std::size_t(n) < m_mesh.normals.size())
                    blended += weight[k] * m_mesh.normals[std::size_t(n)];
            }
            const double length = glm::length(blended);
            if (length > 0.0 && std::isfinite(length)) g.shading_normal = blended / length;
        }
        if (f.uv[0] >= 0) {
            glm::dvec2 uv(0.0);
            for (int k = 0; k < 3; ++k) {
                const int index = f.uv[k];
                if (index >= 0 && std::size_t(index) < m_mesh.uvs.size())
                    uv += weight[k] * m_mesh.uvs[std::size_t(index)];
            }
            g.uv = Vec2(uv);
        } else {
            g.uv = Vec2(float(b1), float(b2));
        }
        return g;
    }

    bool solid() const override { return m_has_inside; }

    bool inside(const DVec3& p) const override {
        if (!m_has_inside) return false;
        LineFrame line;
        if (!line.set(p, m_inside_vector)) return false;
        // Every crossing at t > 0 counts: no ordering, no cap.
        constexpr double kForever = std::numeric_limits<double>::infinity();
        std::uint32_t stack[kStackDepth];
        int depth = 0;
        double t_enter;
        if (!box_interval(m_nodes[0].box, line, 0.0, kForever, t_enter)) return false;
        stack[depth++] = 0;
        bool odd = false;
        while (depth > 0) {
            const BvhNode& node = m_nodes[stack[--depth]];
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i) {
                    double t;
                    if (cross_at(line, m_triangles[i], t) && t > 0.0) odd = !odd;
                }
                continue;
            }
            for (std::uint32_t child = node.first; child < node.first + 2; ++child)
                if (box_interval(m_nodes[child].box, line, 0.0, kForever, t_enter)) stack[depth++] = child;
        }
        return odd;
    }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = m_lower;
        upper = m_upper;
        return true;
    }

  private:
    bool cross_at(const LineFrame& line, const PackedTriangle& triangle, double& t) const {
        return cross_triangle(line, m_mesh.positions[triangle.corner[0]], m_mesh.positions[triangle.corner[1]],
                              m_mesh.positions[triangle.corner[2]], t);
    }

    void build();

    MeshShapeParameters m_mesh;
    bool m_has_inside = false;
    DVec3 m_inside_vector{0.0};
    std::vector<PackedTriangle> m_triangles;  // in leaf order
    std::vector<BvhNode> m_nodes;             // root first
    DVec3 m_lower{0.0}, m_upper{0.0};
};

void MeshShape::build() {
    // The usable triangles, each with its box and centroid.
    const std::size_t position_count = m_mesh.positions.size();
    std::vector<PackedTriangle> usable;
    std::vector<FloatBox> boxes;
    std::vector<glm::vec3> centroids;
    usable.reserve(m_mesh.faces.size());
    m_lower = DVec3(INFINITY);
    m_upper = DVec3(-INFINITY);
    for (std::size_t face = 0; face < m_mesh.faces.size() && face < std::size_t(INT32_MAX); ++face) {
        const int* corner = m_mesh.faces[face].position;
        bool valid = true;
        for (int k = 0; k < 3; ++k) valid = valid && corner[k] >= 0 && std::size_t(corner[k]) < position_count;
        if (!valid) continue;
        const DVec3& p0 = m_mesh.positions[std::size_t(corner[0])];
        const DVec3& p1 = m_mesh.positions[std::size_t(corner[1])];
        const DVec3& p2 = m_mesh.positions[std::size_t(corner[2])];
        if (!std::isfinite(p0.x + p0.y + p0.z + p1.x + p1.y + p1.z + p2.x + p2.y + p2.z)) continue;
        const DVec3 area_normal = glm::cross(p1 - p0, p2 - p0);
        if (!(glm::dot(area_normal, area_normal) > 0.0)) continue;
        const DVec3 lower = glm::min(p0, glm::min(p1, p2)), upper = glm::max(p0, glm::max(p1, p2));
        m_lower = glm::min(m_lower, lower);
        m_upper = glm::max(m_upper, upper);
        FloatBox box;
        for (int k = 0; k < 3; ++k) {
            box.lower[k] = round_down(lower[k]);
            box.upper[k] = round_up(upper[k]);
        }
        usable.push_back(PackedTriangle{{std::uint32_t(corner[0]), std::uint32_t(corner[1]), std::uint32_t(corner[2])},
                                        std::uint32_t(face)});
        boxes.push_back(box);
        centroids.push_back(glm::vec3(0.5 * (lower + upper)));
    }
    if (usable.empty()) return;

    // Binned SAH, top-down; a node's two children sit side by side.
    std::vector<std::uint32_t> order(usable.size());
    for (std::size_t i = 0; i < order.size(); ++i) order[i] = std::uint32_t(i);
    m_nodes.reserve(2 * usable.size() / 3 + 1);
    m_nodes.emplace_back();
    struct Task {
        std::uint32_t node, begin, end;
        int depth;
    };
    std::vector<Task> tasks{{0, 0, std::uint32_t(usable.size()), 0}};
    while (!tasks.empty()) {
        const Task task = tasks.back();
        tasks.pop_back();
        FloatBox box;
        glm::vec3 centroid_lower(INFINITY), centroid_upper(-INFINITY);
        for (std::uint32_t i = task.begin; i < task.end; ++i) {
            box.grow(boxes[order[i]]);
            centroid_lower = glm::min(centroid_lower, centroids[order[i]]);
            centroid_upper = glm::max(centroid_upper, centroids[order[i]]);
        }
        m_nodes[task.node].box = box;
        const std::uint32_t count = task.end - task.begin;
        auto make_leaf = [&] {
            m_nodes[task.node].first = task.begin;
            m_nodes[task.node].count = count;
        };
        if (count <= 2) {
            make_leaf();
            continue;
        }
        const glm::vec3 extent = centroid_upper - centroid_lower;
        const int axis = extent.x > extent.y ? (extent.x > extent.z ? 0 : 2) : (extent.y > extent.z ? 1 : 2);
        std::uint32_t middle = task.begin;
        if (!(extent[axis] > 0.0f)) {
            // Every centroid in one place: no plane separates them.
            if (count <= kMaxLeafTriangles) {
                make_leaf();
                continue;
            }
            middle = task.begin + count / 2;
        } else if (task.depth >= kSahDepthLimit) {
            middle = task.begin + count / 2;
            std::nth_element(order.begin() + task.begin, order.begin() + middle, order.begin() + task.end,
                             [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
        } else {
            const float scale = float(kBins) / extent[axis] * (1.0f - 1e-6f);
            auto bin_of = [&](std::uint32_t triangle) {
                const int bin = int((centroids[triangle][axis] - centroid_lower[axis]) * scale);
                return std::clamp(bin, 0, kBins - 1);
            };
            FloatBox bin_box[kBins];
            std::uint32_t bin_count[kBins] = {};
            for (std::uint32_t i = task.begin; i < task.end; ++i) {
                const int bin = bin_of(order[i]);
                bin_box[bin].grow(boxes[order[i]]);
                ++bin_count[bin];
            }
            // Cost of splitting after bin i: left and right areas times counts.
            double right_cost[kBins] = {};
            FloatBox right;
            std::uint32_t right_count = 0;
            for (int i = kBins - 1; i > 0; --i) {
                right.grow(bin_box[i]);
                right_count += bin_count[i];
                right_cost[i - 1] = right.half_area() * right_count;
            }
            FloatBox left;
            std::uint32_t left_count = 0;
            double best_cost = INFINITY;
            int best_bin = -1;
            for (int i = 0; i < kBins - 1; ++i) {
                left.grow(bin_box[i]);
                left_count += bin_count[i];
                if (left_count == 0 || left_count == count) continue;
                const double cost = left.half_area() * left_count + right_cost[i];
                if (cost < best_cost) {
                    best_cost = cost;
                    best_bin = i;
                }
            }
            // SAH with a traversal step costing one triangle test.
            const double area = box.half_area();
            const double split_cost = area > 0.0 ? 1.0 + best_cost / area : INFINITY;
            if (best_bin < 0 || (count <= kMaxLeafTriangles && split_cost >= double(count))) {
                if (count <= kMaxLeafTriangles) {
                    make_leaf();
                    continue;
                }
                middle = task.begin + count / 2;
                std::nth_element(
                    order.begin() + task.begin, order.begin() + middle, order.begin() + task.end,
                    [&](std::uint32_t a, std::uint32_t b) { return centroids[a][axis] < centroids[b][axis]; });
            } else {
                middle =
                    std::uint32_t(std::partition(order.begin() + task.begin, order.begin() + task.end,
                                                 [&](std::uint32_t triangle) { return bin_of(triangle) <= best_bin; }) -
                                  order.begin());
                if (middle == task.begin || middle == task.end) middle = task.begin + count / 2;
            }
        }
        const std::uint32_t left_child = std::uint32_t(m_nodes.size());
        m_nodes.emplace_back();
        m_nodes.emplace_back();
        m_nodes[task.node].first = left_child;
        m_nodes[task.node].count = 0;
        tasks.push_back({left_child, task.begin, middle, task.depth + 1});
        tasks.push_back({left_child + 1, middle, task.end, task.depth + 1});
    }
    m_triangles.resize(usable.size());
    for (std::size_t i = 0; i < order.size(); ++i) m_triangles[i] = usable[order[i]];
}

}  // namespace

std::shared_ptr<const Shape> make_mesh_shape(MeshShapeParameters mesh) {
    auto shape = std::make_shared<MeshShape>(std::move(mesh));
    if (shape->empty()) return nullptr;
    return shape;
}

std::vector<DVec3> mesh_positions_from_xyz(const std::vector<float>& xyz) {
    std::vector<DVec3> positions(xyz.size() / 3);
    for (std::size_t i = 0; i < positions.size(); ++i) positions[i] = DVec3(xyz[3 * i], xyz[3 * i + 1], xyz[3 * i + 2]);
    return positions;
}

}  // namespace lancer
