// POV-Ray's bicubic_patch: P(u, v) = sum B_i(u) B_j(v) P_ij over the 4 x 4
// control points (i the row as written, u and v in [0, 1], B the cubic
// Bernstein polynomials). Not a solid: inside() is always false, as POV's.
//
// POV-Ray 3.7 never intersects the curved surface. It halves the patch by
// de Casteljau's rule (in u while the depth is below u_steps, in v while
// below v_steps) and stops early where a subpatch is flatter than
// `flatness`; each final subpatch becomes two triangles over its corners
// (0,0)-(0,1)-(1,1) and (0,0)-(1,1)-(1,0) in (u, v). Types 0 and 1 differ
// only in when POV does this (per ray, or once), so both build the same
// pieces here, once, under a tree of boxes that follows the subdivision
// (one node per subpatch, its children the halves): facets at small steps
// show as in POV's renders. A ray meets a piece by the plane equation and
// barycentric coordinates, exactly (no iteration, so no root polishing
// either: t is already accurate to rounding); all tolerances are relative.
//
// The normal, as POV's: the true patch normal dP/du x dP/dv at the
// triangle's three corners, interpolated barycentrically (smooth shading
// over the facets); where it is undefined (a collapsed edge) POV takes
// world +x. The patch's own orientation is kept: the host faces it to the
// ray. (u, v): the patch parameters interpolated over the triangle the same
// way, then mapped bilinearly through uv_vectors; by default the texture u
// is the patch's v and the texture v its u, as POV gives them.
#include "geometry/bicubic_patch.h"

#include <algorithm>
#include <cmath>
#include <vector>

namespace lancer {
namespace {

// POV's thresholds: sin^2 of the angle below which a triangle or a normal
// is degenerate, and a ray grazes a piece (relative to |d|).
constexpr double kDegenerate = 1e-10;
// POV's absolute distance under which two corners coincide (flatness test).
constexpr double kCornerEpsilon = 1e-10;

using ControlNet = std::array<DVec3, 16>;  // [4 * i + j], i along u

// One final subpatch: its four corners P(u0,v0), P(u0,v1), P(u1,v1),
// P(u1,v0) and its parameter ranges (dyadic, so exact in float).
struct Piece {
    DVec3 corner[4];
    float u0, u1, v0, v1;
    bool usable[2];  // the triangles (0,1,2) and (0,2,3) are not degenerate
};

// A box over a subpatch's pieces: leaf (piece >= 0) or children at
// [first_child, first_child + child_count).
struct Node {
    DVec3 lower{INFINITY}, upper{-INFINITY};
    int first_child = 0;
    int child_count = 0;
    int piece = -1;
};

// The corners of triangle `which` of a piece, in order, with their (u, v).
void triangle_of(const Piece& piece, int which, DVec3 (&v)[3], glm::dvec2 (&uv)[3]) {
    const int second = which == 0 ? 1 : 2;
    const int third = which == 0 ? 2 : 3;
    const glm::dvec2 corner_uv[4] = {
        {piece.u0, piece.v0}, {piece.u0, piece.v1}, {piece.u1, piece.v1}, {piece.u1, piece.v0}};
    v[0] = piece.corner[0];
    v[1] = piece.corner[second];
    v[2] = piece.corner[third];
    uv[0] = corner_uv[0];
    uv[1] = corner_uv[second];
    uv[2] = corner_uv[third];
}

// Splits the net at the middle of u (split_u) or v into two halves.
void split(const ControlNet& net, bool split_u, ControlNet& low, ControlNet& high) {
    for (int line = 0; line < 4; ++line) {
        // The four points of one curve along the split direction.
        const auto at = [&](int k) { return split_u ? 4 * k + line : 4 * line + k; };
        const DVec3 p0 = net[at(0)], p1 = net[at(1)], p2 = net[at(2)], p3 = net[at(3)];
        const DVec3 a = 0.5 * (p0 + p1), middle = 0.5 * (p1 + p2), b = 0.5 * (p2 + p3);
        const DVec3 c = 0.5 * (a + middle), e = 0.5 * (middle + b);
        const DVec3 centre = 0.5 * (c + e);
        low[at(0)] = p0, low[at(1)] = a, low[at(2)] = c, low[at(3)] = centre;
        high[at(0)] = centre, high[at(1)] = e, high[at(2)] = b, high[at(3)] = p3;
    }
}

// POV's flatness measure of a net (its points already in world space): the
// largest distance of a control point from the plane through three
// corners, chosen as POV chooses them; negative where the corners it
// tries coincide or line up (such a net is never flat enough).
double flatness_of(const ControlNet& net) {
    const auto apart = [](const DVec3& a, const DVec3& b) { return glm::length(a - b) >= kCornerEpsilon; };
    DVec3 first = net[0], second = net[3], third;
    if (!apart(first, second)) {
        second = net[15];
        third = net[12];
        if (!apart(first, second) || !apart(second, third)) return -1.0;
    } else {
        third = net[12];
        if (!apart(second, third)) return -1.0;
    }
    const DVec3 to_first = first - second, to_third = third - second;
    DVec3 normal = glm::cross(to_first, to_third);
    const double length2 = glm::dot(normal, normal);
    if (!(length2 > kDegenerate * glm::dot(to_first, to_first) * glm::dot(to_third, to_third))) return -1.0;
    normal /= std::sqrt(length2);
    double distance = 0.0;
    for (const DVec3& p : net) distance = std::max(distance, std::fabs(glm::dot(p - first, normal)));
    return distance;
}

class BicubicPatchShape final : public Shape {
  public:
    explicit BicubicPatchShape(const BicubicPatchParameters& patch)
        : m_u_steps(std::clamp(patch.u_steps, 0, kMaxBicubicPatchSteps)),
          m_v_steps(std::clamp(patch.v_steps, 0, kMaxBicubicPatchSteps)),
          m_flatness(patch.flatness),
          m_world_from_object(patch.world_from_object),
          m_uv_corners(patch.uv_corners) {
        std::copy(patch.points.begin(), patch.points.end(), m_net.begin());
        for (const DVec3& p : m_net) {
            m_lower = glm::min(m_lower, p);
            m_upper = glm::max(m_upper, p);
        }
        // World +x seen from object space: the object normal the host's
        // inverse-transpose maps onto +x.
        const DVec3 fallback = glm::transpose(DMat3(m_world_from_object)) * DVec3(1.0, 0.0, 0.0);
        const double fallback_length = glm::length(fallback);
        m_fallback_normal =
            fallback_length > 0.0 && std::isfinite(fallback_length) ? fallback / fallback_length : DVec3(1.0, 0.0, 0.0);
        // Boxes are padded by a hair of the patch's size so that rounding in
        // the slab test never loses a piece seen edge-on.
        const DVec3 extent = m_upper - m_lower;
        m_box_padding = 1e-9 * std::max({extent.x, extent.y, extent.z});
        const int pieces_expected = 1 << (m_u_steps + m_v_steps);  // with flatness 0
        m_pieces.reserve(pieces_expected);
        m_nodes.reserve(pieces_expected + pieces_expected / 2 + 1);
        m_nodes.emplace_back();
        build(0, m_net, 0.0, 1.0, 0.0, 1.0, 0);
    }

    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        if (!(glm::dot(d, d) > 0.0)) return;
        const int first_new = out.count;
        // Depth-first over the box tree; each level pushes at most 4 children.
        int stack[4 * (kMaxBicubicPatchSteps + 2)];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = m_nodes[stack[--top]];
            if (!ray_meets_box(node, o, d, t_min, t_max)) continue;
            if (node.piece < 0) {
                for (int c = 0; c < node.child_count; ++c) stack[top++] = node.first_child + c;
                continue;
            }
            const Piece& piece = m_pieces[node.piece];
            for (int which = 0; which < 2; ++which) {
                double t;
                if (!piece.usable[which] || !ray_meets_triangle(piece, which, o, d, t_min, t_max, t)) continue;
                // A ray through an edge two pieces share meets both: once.
                bool seen = false;
                for (int k = first_new; k < out.count && !seen; ++k)
                    seen = std::fabs(out.items[k].t - t) <= 1e-9 * std::max(std::fabs(t), std::fabs(out.items[k].t));
                if (!seen) out.add(t, 2 * node.piece + which);
            }
        }
    }

    SurfaceGeometry surface(const DVec3& p, int face) const override {
        SurfaceGeometry g;
        const int piece_index = std::clamp(face / 2, 0, int(m_pieces.size()) - 1);
        DVec3 v[3];
        glm::dvec2 uv[3];
        triangle_of(m_pieces[piece_index], face & 1, v, uv);
        const DVec3 edge1 = v[1] - v[0], edge2 = v[2] - v[0];
        const DVec3 plane_normal = glm::cross(edge1, edge2);
        const double area2 = glm::dot(plane_normal, plane_normal);
        // Barycentric weights of the point projected onto the piece's plane.
        double a = 0.0, b = 0.0;
        g.point = p;
        if (area2 > 0.0) {
            g.point = p - (glm::dot(p - v[0], plane_normal) / area2) * plane_normal;
            const DVec3 q = g.point - v[0];
            a = std::clamp(glm::dot(q, glm::cross(edge2, plane_normal)) / area2, 0.0, 1.0);
            b = std::clamp(glm::dot(q, glm::cross(plane_normal, edge1)) / area2, 0.0, 1.0 - a);
        }
        const double r = 1.0 - a - b;
        const DVec3 normal = r * patch_normal(uv[0]) + a * patch_normal(uv[1]) + b * patch_normal(uv[2]);
        const double normal_length2 = glm::dot(normal, normal);
        g.normal = normal_length2 > kDegenerate ? normal / std::sqrt(normal_length2) : m_fallback_normal;
        const glm::dvec2 patch_uv = r * uv[0] + a * uv[1] + b * uv[2];
        g.uv = texture_uv(patch_uv.x, patch_uv.y);
        return g;
    }

    bool inside(const DVec3&) const override { return false; }
    bool solid() const override { return false; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        lower = m_lower;
        upper = m_upper;
        return true;
    }

  private:
    // Fills m_nodes[index] with the subpatch `net` over [u0,u1] x [v0,v1].
    void build(int index, const ControlNet& net, double u0, double u1, double v0, double v1, int depth) {
        const bool split_u = depth < m_u_steps, split_v = depth < m_v_steps;
        if ((!split_u && !split_v) || flat_enough(net)) {
            add_piece(index, net, u0, u1, v0, v1);
            return;
        }
        // The halves (or quarters) with their parameter ranges.
        ControlNet parts[4];
        double ranges[4][4];
        int count = 0;
        const double u_mid = 0.5 * (u0 + u1), v_mid = 0.5 * (v0 + v1);
        if (split_u) {
            ControlNet low, high;
            split(net, true, low, high);
            if (split_v) {
                split(low, false, parts[0], parts[1]);
                split(high, false, parts[2], parts[3]);
                const double r[4][4] = {
                    {u0, u_mid, v0, v_mid}, {u0, u_mid, v_mid, v1}, {u_mid, u1, v0, v_mid}, {u_mid, u1, v_mid, v1}};
                std::copy(&r[0][0], &r[0][0] + 16, &ranges[0][0]);
                count = 4;
            } else {
                parts[0] = low, parts[1] = high;
                const double r[2][4] = {{u0, u_mid, v0, v1}, {u_mid, u1, v0, v1}};
                std::copy(&r[0][0], &r[0][0] + 8, &ranges[0][0]);
                count = 2;
            }
        } else {
            split(net, false, parts[0], parts[1]);
            const double r[2][4] = {{u0, u1, v0, v_mid}, {u0, u1, v_mid, v1}};
            std::copy(&r[0][0], &r[0][0] + 8, &ranges[0][0]);
            count = 2;
        }
        const int first = int(m_nodes.size());
        m_nodes.resize(m_nodes.size() + count);
        for (int c = 0; c < count; ++c)
            build(first + c, parts[c], ranges[c][0], ranges[c][1], ranges[c][2], ranges[c][3], depth + 1);
        Node& node = m_nodes[index];
        node.first_child = first;
        node.child_count = count;
        for (int c = 0; c < count; ++c) {
            node.lower = glm::min(node.lower, m_nodes[first + c].lower);
            node.upper = glm::max(node.upper, m_nodes[first + c].upper);
        }
    }

    bool flat_enough(const ControlNet& net) const {
        if (!(m_flatness > 0.0)) return false;  // POV: distance < flatness, never true at 0
        ControlNet world;
        for (int k = 0; k < 16; ++k) world[k] = DVec3(m_world_from_object * glm::dvec4(net[k], 1.0));
        const double distance = flatness_of(world);
        return distance >= 0.0 && distance < m_flatness;
    }

    void add_piece(int index, const ControlNet& net, double u0, double u1, double v0, double v1) {
        Piece piece;
        piece.corner[0] = net[0];
        piece.corner[1] = net[3];
        piece.corner[2] = net[15];
        piece.corner[3] = net[12];
        piece.u0 = float(u0), piece.u1 = float(u1), piece.v0 = float(v0), piece.v1 = float(v1);
        Node& node = m_nodes[index];
        for (int which = 0; which < 2; ++which) {
            DVec3 v[3];
            glm::dvec2 uv[3];
            triangle_of(piece, which, v, uv);
            const DVec3 edge1 = v[1] - v[0], edge2 = v[2] - v[0];
            const DVec3 n = glm::cross(edge1, edge2);
            piece.usable[which] = glm::dot(n, n) > kDegenerate * glm::dot(edge1, edge1) * glm::dot(edge2, edge2);
        }
        for (const DVec3& c : piece.corner) {
            node.lower = glm::min(node.lower, c - m_box_padding);
            node.upper = glm::max(node.upper, c + m_box_padding);
        }
        node.piece = int(m_pieces.size());
        m_pieces.push_back(piece);
    }

    // Slab test of o + t d against the node's box within [t_min, t_max].
    static bool ray_meets_box(const Node& node, const DVec3& o, const DVec3& d, double t_min, double t_max) {
        double near = t_min, far = t_max;
        for (int axis = 0; axis < 3; ++axis) {
            if (d[axis] == 0.0) {
                if (o[axis] < node.lower[axis] || o[axis] > node.upper[axis]) return false;
                continue;
            }
            const double inverse = 1.0 / d[axis];
            double t0 = (node.lower[axis] - o[axis]) * inverse, t1 = (node.upper[axis] - o[axis]) * inverse;
            if (t0 > t1) std::swap(t0, t1);
            near = std::max(near, t0);
            far = std::min(far, t1);
            if (!(near <= far)) return false;
        }
        return true;
    }

    static bool ray_meets_triangle(const Piece& piece, int which, const DVec3& o, const DVec3& d, double t_min,
                                   double t_max, double& t) {
        DVec3 v[3];
        glm::dvec2 uv[3];
        triangle_of(piece, which, v, uv);
        const DVec3 edge1 = v[1] - v[0], edge2 = v[2] - v[0];
        const DVec3 n = glm::cross(edge1, edge2);
        const double n2 = glm::dot(n, n);
        const double facing = glm::dot(d, n);
        // POV skips pieces the ray runs along (|cos| below 1e-10).
        if (!(std::fabs(facing) >= kDegenerate * std::sqrt(glm::dot(d, d) * n2))) return false;
        t = glm::dot(v[0] - o, n) / facing;
        if (!(t > t_min && t < t_max)) return false;
        // Barycentric weights by the dual basis of the edges, edges
        // included (and a rounding's width more, so no ray slips between two
        // pieces that share an edge; the double is dropped in crossings()).
        const DVec3 q = o + t * d - v[0];
        const double a = glm::dot(q, glm::cross(edge2, n)) / n2;
        const double b = glm::dot(q, glm::cross(n, edge1)) / n2;
        constexpr double kSlack = 1e-12;
        return a >= -kSlack && b >= -kSlack && a + b <= 1.0 + kSlack;
    }

    // POV's normal of the patch at (u, v): unit dP/du x dP/dv, or the
    // fallback where that vanishes against the tangents' lengths.
    DVec3 patch_normal(const glm::dvec2& at) const {
        double bu[4], bv[4], du[4], dv[4];
        bernstein(at.x, bu, du);
        bernstein(at.y, bv, dv);
        DVec3 along_u(0.0), along_v(0.0);
        for (int i = 0; i < 4; ++i)
            for (int j = 0; j < 4; ++j) {
                along_u += (du[i] * bv[j]) * m_net[4 * i + j];
                along_v += (bu[i] * dv[j]) * m_net[4 * i + j];
            }
        const DVec3 n = glm::cross(along_u, along_v);
        const double n2 = glm::dot(n, n);
        if (n2 > kDegenerate * glm::dot(along_u, along_u) * glm::dot(along_v, along_v)) return n / std::sqrt(n2);
        return m_fallback_normal;
    }

    // The cubic Bernstein polynomials at s and their derivatives.
    static void bernstein(double s, double (&b)[4], double (&db)[4]) {
        const double r = 1.0 - s;
        b[0] = r * r * r, b[1] = 3.0 * s * r * r, b[2] = 3.0 * s * s * r, b[3] = s * s * s;
        db[0] = -3.0 * r * r, db[1] = 3.0 * r * (r - 2.0 * s), db[2] = 3.0 * s * (2.0 * r - s), db[3] = 3.0 * s * s;
    }

    // POV's Compute_Texture_UV: bilinear through the uv_vectors corners,
    // the patch's v across the first edge and u along the second.
    Vec2 texture_uv(double u, double v) const {
        const glm::dvec2 near_edge = m_uv_corners[0] + v * (m_uv_corners[1] - m_uv_corners[0]);
        const glm::dvec2 far_edge = m_uv_corners[3] + v * (m_uv_corners[2] - m_uv_corners[3]);
        const glm::dvec2 t = near_edge + u * (far_edge - near_edge);
        return Vec2(float(t.x), float(t.y));
    }

    int m_u_steps, m_v_steps;
    double m_flatness;
    DMat4 m_world_from_object;
    std::array<glm::dvec2, 4> m_uv_corners;
    ControlNet m_net;
    DVec3 m_lower{INFINITY}, m_upper{-INFINITY};
    DVec3 m_fallback_normal{1.0, 0.0, 0.0};
    double m_box_padding = 0.0;
    std::vector<Piece> m_pieces;
    std::vector<Node> m_nodes;  // [0] is the whole patch
};

}  // namespace

std::shared_ptr<const Shape> make_bicubic_patch_shape(const BicubicPatchParameters& patch) {
    if (patch.type < 0) return nullptr;
    for (const DVec3& p : patch.points)
        if (!std::isfinite(p.x + p.y + p.z)) return nullptr;
    return std::make_shared<BicubicPatchShape>(patch);
}

}  // namespace lancer
