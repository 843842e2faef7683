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
        break;
    }
    case CsgNode::Operation::Union:
    case CsgNode::Operation::Merge: {
        bool all_bounded = true;
        for (std::uint32_t child : node.children) all_bounded = all_bounded && nodes[child].bounded;
        if (all_bounded)
            for (std::uint32_t child : node.children) take(nodes[child], false);
        break;
    }
    case CsgNode::Operation::Intersection:
        for (std::uint32_t child : node.children) take(nodes[child], true);
        break;
    }
    for (std::uint32_t clip : node.clips) take(nodes[clip], true);
    // POV's box of a bounded object is its bounds' (the uninverted ones')
    // where that is smaller; its inside test ignores the bounds.
    if (!node.bounds.empty()) {
        const bool own_bounded = node.bounded;
        const DVec3 own_lower = node.lower, own_upper = node.upper;
        node.bounded = false;
        for (std::uint32_t bounding : node.bounds)
            if (!nodes[bounding].inverted) take(nodes[bounding], true);
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
                     double t_min, double t_max, std::vector<CsgCrossing>& out) const {
    const CsgNode& node = nodes[index];
    if (node.bounded) {
        double lo = t_min, hi = t_max;
        if (!ray_box_interval(node.lower, node.upper, o, d, lo, hi)) return;
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
        leaf.shape->crossings(o_object, d_object, t_min, t_max, crossings);
        for (int i = 0; i < crossings.count; ++i)
            out.push_back(CsgCrossing{crossings.items[i].t, node.instance, crossings.items[i].face});
        break;
    }
    case CsgNode::Operation::Union:
        for (std::uint32_t child : node.children) gather(instances, child, o, d, t_min, t_max, out);
        break;
    case CsgNode::Operation::Merge:
    case CsgNode::Operation::Intersection: {
        const bool merge = node.operation == CsgNode::Operation::Merge;
        for (std::uint32_t child : node.children) {
            const std::size_t child_start = out.size();
            gather(instances, child, o, d, t_min, t_max, out);
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
    gather(instances, index, o, d, t_min, std::numeric_limits<double>::infinity(), scratch);
    const bool met = scratch.size() > start;
    scratch.resize(start);
    return met;
}

bool CsgTree::nearest(const std::vector<Instance>& instances, const DVec3& o, const DVec3& d, double t_min,
                      double t_max, CsgCrossing& hit) const {
    if (const CsgNode* top = lone_leaf()) {
        const Instance& leaf = instances[top->instance];
        ShapeCrossing crossing;
        if (!leaf.shape->nearest(leaf.placement.point_to_object(o), leaf.placement.vector_to_object(d), t_min, t_max,
                                 crossing))
            return false;
        hit = CsgCrossing{crossing.t, top->instance, crossing.face};
        return true;
    }
    // One list per thread, reused: Embree calls this for every ray.
    thread_local std::vector<CsgCrossing> crossings;
    crossings.clear();
    gather(instances, root, o, d, t_min, t_max, crossings);
    if (crossings.empty()) return false;
    hit = *std::min_element(crossings.begin(), crossings.end(),
                            [](const CsgCrossing& a, const CsgCrossing& b) { return a.t < b.t; });
    return true;
}

}  // namespace lancer
