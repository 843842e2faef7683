// POV-Ray's blob: the surface where the summed field of its components
// equals the threshold; inside where the field exceeds it (POV's
// Blob::Inside). A component of strength s and radius R adds
// s (1 - r^2 / R^2)^2 within distance R of its centre (a sphere) or of its
// segment (a cylinder, whose ends are hemispheres), as POV's field.
//
// Along a ray each component's reach is one or three stretches (a sphere;
// a cylinder's side and its two end caps) on which r^2 is a quadratic in t,
// so the field is a quartic there. Between consecutive stretch ends the
// field is one polynomial: its roots, less the threshold, come from
// polynomial_roots_in (isolation by derivatives: POV's `sturm` asks for no
// more). Components carry their own transforms (an ellipsoidal component
// is a scaled sphere); the ray is mapped into each. POV-Ray 3.7 gives
// blobs no (u, v): lancer gives (0, 0).
//
// As POV-Ray's blob `hierarchy` (on by default), the components' boxes form
// a tree, so a ray or a point visits only the components it may reach: a
// blob of a few thousand spheres (advanced/biscuit.pov's logo) would
// otherwise cost them all at every ray. The components found are taken in
// their written order, so the sums are the same as without the tree.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "geometry/polynomial_roots.h"
#include "geometry/shape.h"

namespace lancer {
namespace {

// A stretch of the ray on which r^2 = a t^2 + b t + c.
struct Stretch {
    double enter, exit;
    double a, b, c;
    double strength, radius2;
};

// The t interval (enter, exit) where a t^2 + b t + c < limit; false if none.
bool below(double a, double b, double c, double limit, double& enter, double& exit) {
    double roots[2];
    const int n = solve_quadratic(a, 0.5 * b, c - limit, roots);
    if (n < 2 || !(a > 0.0)) return false;
    enter = roots[0];
    exit = roots[1];
    return enter < exit;
}

// An axis-aligned box in blob space.
struct Box {
    DVec3 lower{INFINITY}, upper{-INFINITY};
    void add(const Box& other) {
        lower = glm::min(lower, other.lower);
        upper = glm::max(upper, other.upper);
    }
    bool holds(const DVec3& p) const {
        return p.x >= lower.x && p.x <= upper.x && p.y >= lower.y && p.y <= upper.y && p.z >= lower.z && p.z <= upper.z;
    }
    // Whether o + t d meets the box for some t in [t_min, t_max]; the far
    // distances widened by their rounding, so no box the ray meets is missed.
    bool met_by(const DVec3& o, const DVec3& d, double t_min, double t_max) const {
        for (int axis = 0; axis < 3; ++axis) {
            if (d[axis] == 0.0) {
                if (o[axis] < lower[axis] || o[axis] > upper[axis]) return false;
                continue;
            }
            double near = (lower[axis] - o[axis]) / d[axis], far = (upper[axis] - o[axis]) / d[axis];
            if (near > far) std::swap(near, far);
            const double slack = 1e-12 * (std::fabs(near) + std::fabs(far)) + 1e-300;
            t_min = std::max(t_min, near - slack);
            t_max = std::min(t_max, far + slack);
            if (t_min > t_max) return false;
        }
        return true;
    }
};

// A binary tree of the components' boxes: each node's box holds its
// children's; a leaf lists a few components.
class ComponentTree {
  public:
    static constexpr std::size_t kLeafSize = 4;

    explicit ComponentTree(const std::vector<Box>& boxes) : m_boxes(boxes) {
        m_order.resize(boxes.size());
        for (std::size_t i = 0; i < boxes.size(); ++i) m_order[i] = std::uint32_t(i);
        if (boxes.empty()) return;
        m_nodes.resize(1);
        build(0, 0, boxes.size(), 0);
    }

    // The components whose boxes `accept` takes (a function of a Box),
    // sorted by index, into `found`.
    template <class Accept>
    void collect(const Accept& accept, std::vector<std::uint32_t>& found) const {
        found.clear();
        if (m_nodes.empty()) return;
        std::uint32_t stack[64];
        int top = 0;
        stack[top++] = 0;
        while (top > 0) {
            const Node& node = m_nodes[stack[--top]];
            if (!accept(node.box)) continue;
            if (node.count > 0) {
                for (std::uint32_t i = node.first; i < node.first + node.count; ++i)
                    if (accept(m_boxes[m_order[i]])) found.push_back(m_order[i]);
            } else if (top + 2 <= 64) {
                stack[top++] = node.first;
                stack[top++] = node.first + 1;
            }
        }
        std::sort(found.begin(), found.end());
    }

  private:
    struct Node {
        Box box;
        std::uint32_t first = 0;  // leaf: first of m_order; inner: the first child's node
        std::uint32_t count = 0;  // leaf: components; 0 for an inner node
    };

    // Fills node `index` for m_order[begin, end), split at the median along
    // its box's longest axis into two children made next to each other.
    void build(std::uint32_t index, std::size_t begin, std::size_t end, int depth) {
        Box box;
        for (std::size_t i = begin; i < end; ++i) box.add(m_boxes[m_order[i]]);
        m_nodes[index].box = box;
        // A tree at most 31 deep: the traversal's stack holds two per level.
        if (end - begin <= kLeafSize || depth >= 30) {
            m_nodes[index].first = std::uint32_t(begin);
            m_nodes[index].count = std::uint32_t(end - begin);
            return;
        }
        const DVec3 extent = box.upper - box.lower;
        const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
        const std::size_t middle = begin + (end - begin) / 2;
        std::nth_element(m_order.begin() + std::ptrdiff_t(begin), m_order.begin() + std::ptrdiff_t(middle),
                         m_order.begin() + std::ptrdiff_t(end), [&](std::uint32_t a, std::uint32_t b) {
                             return m_boxes[a].lower[axis] + m_boxes[a].upper[axis] <
                                    m_boxes[b].lower[axis] + m_boxes[b].upper[axis];
                         });
        const std::uint32_t children = std::uint32_t(m_nodes.size());
        m_nodes.resize(m_nodes.size() + 2);
        m_nodes[index].first = children;
        build(children, begin, middle, depth + 1);
        build(children + 1, middle, end, depth + 1);
    }

    std::vector<Box> m_boxes;
    std::vector<std::uint32_t> m_order;
    std::vector<Node> m_nodes;
};

// The box in blob space of a component's reach: its placed corners.
Box placed_box_of(const BlobComponent& c) {
    Box box;
    const DVec3 r(c.radius);
    const DVec3 ends[2] = {c.center, c.kind == BlobComponent::Kind::Cylinder ? c.apex : c.center};
    for (const DVec3& end : ends)
        for (int corner = 0; corner < 8; ++corner) {
            const DVec3 local = end + DVec3(corner & 1 ? r.x : -r.x, corner & 2 ? r.y : -r.y, corner & 4 ? r.z : -r.z);
            const DVec3 p(c.blob_from_component * glm::dvec4(local, 1.0));
            box.lower = glm::min(box.lower, p);
            box.upper = glm::max(box.upper, p);
        }
    return box;
}

// The same, grown by the corners' own rounding, for the tree.
Box reach_of(const BlobComponent& c) {
    Box box = placed_box_of(c);
    const DVec3 margin = 1e-9 * (glm::abs(box.lower) + glm::abs(box.upper) + DVec3(1e-300));
    box.lower -= margin;
    box.upper += margin;
    return box;
}

std::vector<Box> reaches_of(const std::vector<BlobComponent>& components) {
    std::vector<Box> boxes;
    boxes.reserve(components.size());
    for (const BlobComponent& c : components) boxes.push_back(reach_of(c));
    return boxes;
}

class BlobShape final : public Shape {
  public:
    explicit BlobShape(BlobParameters blob) : m_blob(std::move(blob)), m_tree(reaches_of(m_blob.components)) {
        for (const BlobComponent& c : m_blob.components) {
            Placed placed;
            placed.component = c;
            placed.component_from_blob = glm::inverse(c.blob_from_component);
            m_placed.push_back(placed);
        }
    }

    double field(const DVec3& p) const {
        double sum = 0.0;
        std::vector<std::uint32_t>& near = scratch();
        m_tree.collect([&](const Box& box) { return box.holds(p); }, near);
        for (const std::uint32_t index : near) {
            const Placed& placed = m_placed[index];
            const double r2 = distance2(placed, DVec3(placed.component_from_blob * glm::dvec4(p, 1.0)));
            const double R2 = placed.component.radius * placed.component.radius;
            if (r2 < R2) sum += placed.component.strength * std::pow(1.0 - r2 / R2, 2.0);
        }
        return sum;
    }

    void crossings(const DVec3& o_in, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        const double dd = glm::dot(d, d);
        if (!(dd > 0.0)) return;
        const double shift = -glm::dot(o_in, d) / dd;
        const DVec3 o = o_in + shift * d;
        const double lo = t_min - shift, hi = t_max - shift;
        std::vector<std::uint32_t>& near = scratch();
        m_tree.collect([&](const Box& box) { return box.met_by(o, d, lo, hi); }, near);
        // Components the ray meets only outside [lo, hi] change no root
        // inside it (the polynomial between two stretch ends is the sum of
        // the stretches over it), so the ones the tree leaves out are none.
        std::vector<Stretch> stretches;
        for (const std::uint32_t index : near) add_stretches(m_placed[index], o, d, stretches);
        if (stretches.empty()) return;
        std::vector<double> events;
        for (const Stretch& s : stretches) {
            events.push_back(s.enter);
            events.push_back(s.exit);
        }
        std::sort(events.begin(), events.end());
        for (std::size_t e = 0; e + 1 < events.size(); ++e) {
            const double a = std::max(events[e], lo), b = std::min(events[e + 1], hi);
            if (!(a < b)) continue;
            const double mid = 0.5 * (events[e] + events[e + 1]);
            // field(t) - threshold on (a, b): sum of s (1 - r^2/R^2)^2.
            double c[5] = {-m_blob.threshold, 0.0, 0.0, 0.0, 0.0};
            bool any = false;
            for (const Stretch& s : stretches) {
                if (!(s.enter <= mid && mid <= s.exit)) continue;
                any = true;
                // q(t) = 1 - r^2 / R^2 = q2 t^2 + q1 t + q0; field term s q^2.
                const double q2 = -s.a / s.radius2, q1 = -s.b / s.radius2, q0 = 1.0 - s.c / s.radius2;
                c[4] += s.strength * q2 * q2;
                c[3] += s.strength * 2.0 * q2 * q1;
                c[2] += s.strength * (q1 * q1 + 2.0 * q2 * q0);
                c[1] += s.strength * 2.0 * q1 * q0;
                c[0] += s.strength * q0 * q0;
            }
            if (!any) continue;
            double roots[kMaxPolynomialDegree];
            const int n = polynomial_roots_in(c, 4, a, b, roots);
            add_shifted_roots(roots, n, shift, t_min, t_max, 0, out);
        }
    }

    SurfaceGeometry surface(const DVec3& p, int) const override {
        SurfaceGeometry g;
        g.point = project_onto_level(
            p, [this](const DVec3& q) { return field(q); }, [this](const DVec3& q) { return field_gradient(q); },
            m_blob.threshold);
        // The field grows inwards: the outward normal is against its gradient.
        const DVec3 gradient = field_gradient(g.point);
        const double length = glm::length(gradient);
        g.normal = length > 0.0 && std::isfinite(length) ? -gradient / length : DVec3(0.0, 1.0, 0.0);
        g.uv = Vec2(0.0f);
        return g;
    }

    bool inside(const DVec3& p) const override { return field(p) > m_blob.threshold - 1e-10; }

    bool bounds(DVec3& lower, DVec3& upper) const override {
        Box all;
        for (const Placed& placed : m_placed) all.add(placed_box_of(placed.component));
        lower = all.lower;
        upper = all.upper;
        // A threshold at or below 0 makes all space outside the components inside.
        return m_blob.threshold > 0.0 && lower.x <= upper.x;
    }

  private:
    struct Placed {
        BlobComponent component;
        DMat4 component_from_blob{1.0};
    };

    // Squared distance from the component's centre or segment.
    static double distance2(const Placed& placed, const DVec3& q) {
        const BlobComponent& c = placed.component;
        if (c.kind == BlobComponent::Kind::Sphere) return glm::dot(q - c.center, q - c.center);
        const DVec3 axis = c.apex - c.center;
        const double h = std::clamp(glm::dot(q - c.center, axis) / glm::dot(axis, axis), 0.0, 1.0);
        const DVec3 nearest = c.center + h * axis;
        return glm::dot(q - nearest, q - nearest);
    }

    DVec3 field_gradient(const DVec3& p) const {
        DVec3 gradient(0.0);
        std::vector<std::uint32_t>& near = scratch();
        m_tree.collect([&](const Box& box) { return box.holds(p); }, near);
        for (const std::uint32_t index : near) {
            const Placed& placed = m_placed[index];
            const BlobComponent& c = placed.component;
            const DVec3 q(placed.component_from_blob * glm::dvec4(p, 1.0));
            const double R2 = c.radius * c.radius;
            const double r2 = distance2(placed, q);
            if (!(r2 < R2)) continue;
            // d(r^2)/dq: twice the offset from the nearest point of the centre or segment.
            DVec3 nearest = c.center;
            if (c.kind == BlobComponent::Kind::Cylinder) {
                const DVec3 axis = c.apex - c.center;
                nearest += std::clamp(glm::dot(q - c.center, axis) / glm::dot(axis, axis), 0.0, 1.0) * axis;
            }
            const DVec3 dr2_dq = 2.0 * (q - nearest);
            const DVec3 dr2_dp = glm::transpose(DMat3(placed.component_from_blob)) * dr2_dq;
            gradient += c.strength * 2.0 * (1.0 - r2 / R2) * (-1.0 / R2) * dr2_dp;
        }
        return gradient;
    }

    static void add_stretches(const Placed& placed, const DVec3& o_blob, const DVec3& d_blob,
                              std::vector<Stretch>& out) {
        const BlobComponent& c = placed.component;
        const DVec3 o(placed.component_from_blob * glm::dvec4(o_blob, 1.0));
        const DVec3 d(placed.component_from_blob * glm::dvec4(d_blob, 0.0));
        const double R2 = c.radius * c.radius;
        auto sphere_about = [&](const DVec3& centre, double& a, double& b, double& k) {
            const DVec3 offset = o - centre;
            a = glm::dot(d, d);
            b = 2.0 * glm::dot(offset, d);
            k = glm::dot(offset, offset);
        };
        double a, b, k, enter, exit;
        if (c.kind == BlobComponent::Kind::Sphere) {
            sphere_about(c.center, a, b, k);
            if (below(a, b, k, R2, enter, exit)) out.push_back(Stretch{enter, exit, a, b, k, c.strength, R2});
            return;
        }
        // Cylinder: the side, where the nearest point of the segment is inside it ...
        const DVec3 axis = c.apex - c.center;
        const double length2 = glm::dot(axis, axis);
        const double h0 = glm::dot(o - c.center, axis) / length2, dh = glm::dot(d, axis) / length2;
        double slab_enter = -INFINITY, slab_exit = INFINITY;
        if (dh != 0.0) {
            slab_enter = std::min(-h0 / dh, (1.0 - h0) / dh);
            slab_exit = std::max(-h0 / dh, (1.0 - h0) / dh);
        } else if (h0 < 0.0 || h0 > 1.0) {
            slab_enter = INFINITY;
            slab_exit = -INFINITY;
        }
        const DVec3 radial_o = o - c.center - h0 * axis, radial_d = d - dh * axis;
        a = glm::dot(radial_d, radial_d);
        b = 2.0 * glm::dot(radial_o, radial_d);
        k = glm::dot(radial_o, radial_o);
        if (a > 0.0) {
            if (below(a, b, k, R2, enter, exit)) {
                enter = std::max(enter, slab_enter);
                exit = std::min(exit, slab_exit);
                if (enter < exit) out.push_back(Stretch{enter, exit, a, b, k, c.strength, R2});
            }
        } else if (k < R2 && slab_enter < slab_exit) {
            out.push_back(Stretch{slab_enter, slab_exit, 0.0, 0.0, k, c.strength, R2});
        }
        // ... and the hemispheres beyond each end.
        for (int end = 0; end < 2; ++end) {
            sphere_about(end == 0 ? c.center : c.apex, a, b, k);
            if (!below(a, b, k, R2, enter, exit)) continue;
            // Beyond the end: h < 0 at the base, h > 1 at the apex.
            double beyond_enter = -INFINITY, beyond_exit = INFINITY;
            if (dh != 0.0) {
                const double t_end = ((end == 0 ? 0.0 : 1.0) - h0) / dh;
                const bool beyond_after = (end == 0) == (dh < 0.0);
                if (beyond_after)
                    beyond_enter = t_end;
                else
                    beyond_exit = t_end;
            } else if ((end == 0 && h0 >= 0.0) || (end == 1 && h0 <= 1.0)) {
                continue;
            }
            enter = std::max(enter, beyond_enter);
            exit = std::min(exit, beyond_exit);
            if (enter < exit) out.push_back(Stretch{enter, exit, a, b, k, c.strength, R2});
        }
    }

    // The per-thread list of components a query found (no allocation per ray).
    static std::vector<std::uint32_t>& scratch() {
        thread_local std::vector<std::uint32_t> found;
        return found;
    }

    BlobParameters m_blob;
    ComponentTree m_tree;
    std::vector<Placed> m_placed;
};

}  // namespace

std::shared_ptr<const Shape> make_blob_shape(BlobParameters blob) {
    if (blob.components.empty()) return nullptr;
    return std::make_shared<BlobShape>(std::move(blob));
}

}  // namespace lancer
