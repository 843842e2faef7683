// CSG trees: crossings kept by POV-Ray's rules, inside tests, bounds (csg.h).
#include "geometry/csg.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "geometry/scene_data.h"

namespace lancer {
namespace {

bool box_contains(const CsgNode& node, const DVec3& p) {
    return p.x >= node.lower.x && p.x <= node.upper.x && p.y >= node.lower.y && p.y <= node.upper.y &&
           p.z >= node.lower.z && p.z <= node.upper.z;
}

// The box holding the image of [lower, upper] (sides may be infinite)
// under the affine map `to`: interval arithmetic, a zero entry of the map
// taking nothing from an infinite side.
void map_box(const DMat4& to, DVec3& lower, DVec3& upper) {
    DVec3 mapped_lower(to[3]), mapped_upper(to[3]);
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) {
            const double m = to[column][row];
            if (m == 0.0) continue;
            const double a = m * lower[column], b = m * upper[column];
            mapped_lower[row] += std::min(a, b);
            mapped_upper[row] += std::max(a, b);
        }
    lower = mapped_lower;
    upper = mapped_upper;
}

// The map a * b between two leaves' spaces, with the terms that are only
// the product's rounding cleared: where one placement is the other's
// rotation with a scale or shift, a term of 1e-17 would turn an unbounded
// side into unbounded everything. A term is cleared only below a few
// rounding errors of its own sum (a real one that small is lost to
// rounding anyway); what that leaves out is far inside the box's margin.
DMat4 relative_map(const DMat4& a, const DMat4& b) {
    DMat4 m = a * b;
    for (int row = 0; row < 3; ++row)
        for (int column = 0; column < 3; ++column) {
            double magnitude = 0.0;
            for (int k = 0; k < 4; ++k) magnitude += std::fabs(a[k][row] * b[column][k]);
            if (std::fabs(m[column][row]) <= 8.0 * 2.2e-16 * magnitude) m[column][row] = 0.0;
        }
    return m;
}

bool finite_box(const DVec3& lower, const DVec3& upper) {
    return std::isfinite(lower.x) && std::isfinite(lower.y) && std::isfinite(lower.z) && std::isfinite(upper.x) &&
           std::isfinite(upper.y) && std::isfinite(upper.z);
}

}  // namespace

void CsgTree::compute_bounds(const std::vector<Instance>& instances) {
    bound(instances, root);
}

void CsgTree::bound(const std::vector<Instance>& instances, std::uint32_t index) {
    CsgNode& node = nodes[index];
    for (std::uint32_t child : node.children) bound(instances, child);
    for (std::uint32_t clip : node.clips) bound(instances, clip);
    for (std::uint32_t bounding : node.bounds) bound(instances, bounding);
    node.bounded = false;
    node.pov_bounded = false;
    node.box_holds_solid = true;
    auto take = [&](const CsgNode& other, bool intersect) {
        if (!other.bounded) return;
        node.box_holds_solid = node.box_holds_solid && other.box_holds_solid;
        if (!node.bounded) {
            node.lower = other.lower;
            node.upper = other.upper;
            node.bounded = true;
        } else if (intersect) {
            node.lower = glm::max(node.lower, other.lower);
            node.upper = glm::min(node.upper, other.upper);
        } else {
            node.lower = glm::min(node.lower, other.lower);
            node.upper = glm::max(node.upper, other.upper);
        }
    };
    switch (node.operation) {
    case CsgNode::Operation::Leaf: {
        const Instance& leaf = instances[node.instance];
        // An inverted solid fills all space but its own; a patch object's
        // inside stays empty, so its box still holds all it keeps.
        if ((!node.inverted || !leaf.shape->solid()) && leaf.bounded) {
            node.bounded = true;
            node.lower = DVec3(leaf.bounds_lower);
            node.upper = DVec3(leaf.bounds_upper);
            node.box_holds_solid = leaf.shape->inside_within_bounds();
        }
        node.pov_bounded = node.bounded;
        break;
    }
    case CsgNode::Operation::Union:
    case CsgNode::Operation::Merge: {
        bool all_bounded = true;
        for (std::uint32_t child : node.children) all_bounded = all_bounded && nodes[child].bounded;
        if (all_bounded) {
            node.pov_bounded = true;
            for (std::uint32_t child : node.children) {
                take(nodes[child], false);
                node.pov_bounded = node.pov_bounded && nodes[child].pov_bounded;
            }
        }
        break;
    }
    case CsgNode::Operation::Intersection:
        for (std::uint32_t child : node.children) {
            take(nodes[child], true);
            node.pov_bounded = node.pov_bounded || nodes[child].pov_bounded;
        }
        if (!node.bounded) {
            narrow_intersection(instances, index, false);
            node.pov_bounded = node.bounded;
        }
        break;
    }
    for (std::uint32_t clip : node.clips) {
        take(nodes[clip], true);
        node.pov_bounded = node.pov_bounded || nodes[clip].pov_bounded;
    }
    // POV-Ray stops there; lancer also lets a leaf's clips narrow it.
    if (!node.bounded) narrow_intersection(instances, index, true);
    // POV's box of a bounded object is its bounds' (the uninverted ones')
    // where that is smaller; its inside test ignores the bounds.
    if (!node.bounds.empty()) {
        const bool own_bounded = node.bounded;
        const DVec3 own_lower = node.lower, own_upper = node.upper;
        node.bounded = false;
        for (std::uint32_t bounding : node.bounds)
            if (!nodes[bounding].inverted) {
                take(nodes[bounding], true);
                node.pov_bounded = node.pov_bounded || nodes[bounding].pov_bounded;
            }
        const auto volume = [](const DVec3& lower, const DVec3& upper) {
            const DVec3 size = glm::max(upper - lower, DVec3(0.0));
            return size.x * size.y * size.z;
        };
        if (!node.bounded || (own_bounded && !(volume(node.lower, node.upper) < volume(own_lower, own_upper)))) {
            node.bounded = own_bounded;
            node.lower = own_lower;
            node.upper = own_upper;
        }
        node.box_holds_solid = false;
    }
    if (node.bounded && (node.lower.x > node.upper.x || node.lower.y > node.upper.y || node.lower.z > node.upper.z)) {
        // Children that share no space: an empty solid, kept as a point box.
        node.upper = node.lower;
    }
}

void CsgTree::narrow_intersection(const std::vector<Instance>& instances, std::uint32_t index, bool with_clips) {
    // The leaves whose solids all hold the node's: an intersection's
    // children, and with_clips a leaf itself and its clips.
    CsgNode& node = nodes[index];
    std::vector<const CsgNode*> leaves;
    if (node.operation == CsgNode::Operation::Intersection)
        for (std::uint32_t child : node.children)
            if (nodes[child].operation == CsgNode::Operation::Leaf) leaves.push_back(&nodes[child]);
    if (with_clips) {
        if (node.operation == CsgNode::Operation::Leaf) leaves.push_back(&node);
        for (std::uint32_t clip : node.clips)
            if (nodes[clip].operation == CsgNode::Operation::Leaf) leaves.push_back(&nodes[clip]);
    }
    if (leaves.empty()) return;
    // Each leaf narrows the box the others left (planes across the axes,
    // quadrics between them) in its own space; a second round lets what the
    // first found narrow the rest. Another child only holds the solid
    // tighter, so leaving it out is safe. The box is kept in the first
    // leaf's space, not the world's: the pieces of one object share its
    // rotation, so there their slabs stay square to the axes and meet in a
    // finite box, where turned into the world they would not.
    const CsgNode* first = leaves.front();
    const Placement& frame = instances[first->instance].placement;
    DVec3 lower(-INFINITY), upper(INFINITY);
    for (int round = 0; round < 2; ++round)
        for (const CsgNode* leaf_node_pointer : leaves) {
            const CsgNode& leaf_node = *leaf_node_pointer;
            const Instance& leaf = instances[leaf_node.instance];
            DVec3 object_lower = lower, object_upper = upper;
            const bool same_space = &leaf == &instances[first->instance] || (leaf.placement.identity && frame.identity);
            if (!same_space)
                map_box(relative_map(leaf.placement.object_from_world, frame.world_from_object), object_lower,
                        object_upper);
            leaf.shape->narrow_box(object_lower, object_upper, leaf_node.inverted);
            if (!same_space)
                map_box(relative_map(frame.object_from_world, leaf.placement.world_from_object), object_lower,
                        object_upper);
            lower = glm::max(lower, object_lower);
            upper = glm::min(upper, object_upper);
        }
    if (!finite_box(lower, upper)) return;
    if (!frame.identity) map_box(frame.world_from_object, lower, upper);
    // The square roots and placements round, and the BVH keeps the box in
    // float: a margin of some float steps keeps every surface point inside.
    const DVec3 margin = 1e-6 * (glm::abs(lower) + glm::abs(upper)) + 1e-9;
    node.bounded = true;
    node.lower = lower - margin;
    node.upper = upper + margin;
    node.box_holds_solid = true;
}

bool CsgTree::inside(const std::vector<Instance>& instances, std::uint32_t index, const DVec3& p) const {
    const CsgNode& node = nodes[index];
    if (node.bounded && node.box_holds_solid && !box_contains(node, p)) return false;
    bool result = false;
    switch (node.operation) {
    case CsgNode::Operation::Leaf: {
        const Instance& leaf = instances[node.instance];
        result = leaf.shape->solid() && leaf.shape->inside(leaf.placement.point_to_object(p)) != node.inverted;
        break;
    }
    case CsgNode::Operation::Union:
    case CsgNode::Operation::Merge:
        for (std::uint32_t child : node.children)
            if (inside(instances, child, p)) {
                result = true;
                break;
            }
        break;
    case CsgNode::Operation::Intersection:
        result = true;
        for (std::uint32_t child : node.children)
            if (!inside(instances, child, p)) {
                result = false;
                break;
            }
        break;
    }
    if (!result) return false;
    for (std::uint32_t clip : node.clips)
        if (!inside(instances, clip, p)) return false;
    return true;
}

void CsgTree::gather(const std::vector<Instance>& instances, std::uint32_t index, const DVec3& o, const DVec3& d,
                     double t_min, double t_max, double search_min, double search_max,
                     std::vector<CsgCrossing>& out) const {
    const CsgNode& node = nodes[index];
    if (node.bounded) {
        double lo = t_min, hi = t_max;
        if (!ray_box_interval(node.lower, node.upper, o, d, lo, hi)) return;
        // A box that holds the node's solid (not a disc's flat one, nor one
        // bounded_by set) holds every crossing the node keeps: a shape
        // searched along the line, such as a polynomial for its roots, is
        // asked for that stretch alone, widened by more than its rounding.
        // The boxes and bounds below still cull by the whole ray, as POV's.
        if (node.box_holds_solid && node.bounds.empty()) {
            const double widening = 1e-6 * (hi - lo) + 1e-9 * (std::fabs(lo) + std::fabs(hi));
            search_min = std::max(search_min, lo - widening);
            search_max = std::min(search_max, hi + widening);
        }
    }
    if (node.rays_must_meet_bounds)
        for (std::uint32_t bounding : node.bounds)
            if (!ray_meets(instances, bounding, o, d, t_min, out)) return;
    const std::size_t start = out.size();
    switch (node.operation) {
    case CsgNode::Operation::Leaf: {
        const Instance& leaf = instances[node.instance];
        const DVec3 o_object = leaf.placement.point_to_object(o);
        const DVec3 d_object = leaf.placement.vector_to_object(d);
        ShapeCrossings crossings;
        leaf.shape->crossings(o_object, d_object, search_min, search_max, crossings);
        for (int i = 0; i < crossings.count; ++i)
            out.push_back(CsgCrossing{crossings.items[i].t, node.instance, crossings.items[i].face});
        break;
    }
    case CsgNode::Operation::Union:
        for (std::uint32_t child : node.children)
            gather(instances, child, o, d, t_min, t_max, search_min, search_max, out);
        break;
    case CsgNode::Operation::Merge:
    case CsgNode::Operation::Intersection: {
        const bool merge = node.operation == CsgNode::Operation::Merge;
        for (std::uint32_t child : node.children) {
            const std::size_t child_start = out.size();
            gather(instances, child, o, d, t_min, t_max, search_min, search_max, out);
            auto rejected = [&](const CsgCrossing& crossing) {
                const DVec3 p = o + crossing.t * d;
                for (std::uint32_t sibling : node.children) {
                    if (sibling == child) continue;
                    if (inside(instances, sibling, p) == merge) return true;
                }
                return false;
            };
            out.erase(std::remove_if(out.begin() + std::ptrdiff_t(child_start), out.end(), rejected), out.end());
        }
        break;
    }
    }
    if (!node.clips.empty()) {
        auto clipped = [&](const CsgCrossing& crossing) {
            const DVec3 p = o + crossing.t * d;
            for (std::uint32_t clip : node.clips)
                if (!inside(instances, clip, p)) return true;
            return false;
        };
        out.erase(std::remove_if(out.begin() + std::ptrdiff_t(start), out.end(), clipped), out.end());
    }
}

bool CsgTree::ray_meets(const std::vector<Instance>& instances, std::uint32_t index, const DVec3& o, const DVec3& d,
                        double t_min, std::vector<CsgCrossing>& scratch) const {
    if (inside(instances, index, o + t_min * d)) return true;
    const std::size_t start = scratch.size();
    const double t_max = std::numeric_limits<double>::infinity();
    gather(instances, index, o, d, t_min, t_max, t_min, t_max, scratch);
    const bool met = scratch.size() > start;
    scratch.resize(start);
    return met;
}

bool CsgTree::leaf_nearest(const Instance& leaf, std::uint32_t index, const DVec3& o, const DVec3& d, double t_min,
                           double t_max, CsgCrossing& hit) {
    ShapeCrossing crossing;
    if (!leaf.shape->nearest(leaf.placement.point_to_object(o), leaf.placement.vector_to_object(d), t_min, t_max,
                             crossing))
        return false;
    hit = CsgCrossing{crossing.t, index, crossing.face};
    return true;
}

bool CsgTree::nearest(const std::vector<Instance>& instances, const DVec3& o, const DVec3& d, double t_min,
                      double t_max, CsgCrossing& hit) const {
    if (const CsgNode* top = lone_leaf())
        return leaf_nearest(instances[top->instance], top->instance, o, d, t_min, t_max, hit);
    // One list per thread, reused: Embree calls this for every ray.
    thread_local std::vector<CsgCrossing> crossings;
    crossings.clear();
    gather(instances, root, o, d, t_min, t_max, t_min, t_max, crossings);
    if (crossings.empty()) return false;
    hit = *std::min_element(crossings.begin(), crossings.end(),
                            [](const CsgCrossing& a, const CsgCrossing& b) { return a.t < b.t; });
    return true;
}

}  // namespace lancer
