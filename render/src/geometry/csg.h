// POV-Ray's CSG (internal to liblancer): intersection, difference, merge,
// inverse and clipped_by over analytic shapes, as one Embree primitive.
//
// POV-Ray's rules (csg.cpp there), which a tree of nodes follows here: a
// union keeps every crossing of its children; a merge keeps a child's
// crossing only where no other child is solid; an intersection only where
// every other child is; a difference is the intersection of its first
// child with the inverse of the others; clipped_by keeps a crossing only
// inside every clipping object, and an object's inside test includes its
// clips. Inversions are pushed down to the leaves when the tree is built
// (De Morgan, as POV's Invert: an inverted union is the intersection of the
// inverted children, an inverted intersection or merge the merge of them),
// so a leaf knows whether its solid and normal are flipped.
//
// Each leaf is an Instance of its own (material, placement, texture space,
// object id), listed in no acceleration structure; the tree's root is the
// Instance Embree sees. Hits name the leaf they landed on.
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/shape.h"

namespace lancer {

struct Instance;

struct CsgNode {
    enum class Operation { Leaf, Union, Merge, Intersection };
    Operation operation = Operation::Leaf;
    std::uint32_t instance = 0;  // Leaf: the Instance whose shape it is
    bool inverted = false;       // Leaf: solid and normal flipped
    std::vector<std::uint32_t> children;
    std::vector<std::uint32_t> clips;  // roots of clipped_by trees, in this tree
    // Roots of bounded_by trees. Their box is the node's where it is the
    // smaller (POV's parser); with `rays_must_meet_bounds` a ray must also
    // meet or start in each (POV's Ray_In_Bound, which POV drops for a cheap
    // object outside CSG: "unnecessary bounding object removed").
    std::vector<std::uint32_t> bounds;
    bool rays_must_meet_bounds = false;
    // World box holding the node's surface, when finite, as POV-Ray bounds
    // it: an intersection's is the overlap of its children's (a disc's flat,
    // so POV culls the rays that miss it, and so does lancer).
    bool bounded = false;
    DVec3 lower{0.0}, upper{0.0};
    // Whether that box holds the solid too, for the inside test: a disc's
    // inside is POV's half-space behind it.
    bool box_holds_solid = true;
    // Whether POV-Ray bounds the node too (min_extent and max_extent report
    // its box): not where only a leaf's clips narrow it, which POV-Ray
    // does not do (POV's Helix: a quartic clipped by a cylinder and planes).
    bool pov_bounded = false;
};

struct CsgCrossing {
    double t = 0.0;
    std::uint32_t instance = 0;  // the leaf crossed
    int face = 0;
};

class CsgTree {
  public:
    std::vector<CsgNode> nodes;
    std::uint32_t root = 0;

    // Computes each node's bounds from its leaves' instances (after all
    // nodes are added).
    void compute_bounds(const std::vector<Instance>& instances);
    // The nearest crossing of the world ray o + t d kept by the tree, for t
    // in (t_min, t_max).
    bool nearest(const std::vector<Instance>& instances, const DVec3& o, const DVec3& d, double t_min, double t_max,
                 CsgCrossing& hit) const;
    // The leaf of a tree that is one shape and nothing else (no clips, no
    // bounds): the object a shape made CSG by `inverse` alone is, a room's
    // walls. Its every crossing is kept, so the tree's nearest crossing is
    // the shape's own. Null otherwise.
    const CsgNode* lone_leaf() const {
        const CsgNode& top = nodes[root];
        return top.operation == CsgNode::Operation::Leaf && top.clips.empty() && top.bounds.empty() ? &top : nullptr;
    }
    // The nearest crossing of the world ray o + t d with the shape of
    // `leaf` (instance `index`), every crossing kept: a lone leaf's answer.
    static bool leaf_nearest(const Instance& leaf, std::uint32_t index, const DVec3& o, const DVec3& d, double t_min,
                             double t_max, CsgCrossing& hit);
    // POV's Inside_Object for node `node` at world point p.
    bool inside(const std::vector<Instance>& instances, std::uint32_t node, const DVec3& p) const;

  private:
    // The crossings the tree under `node` keeps of the ray o + t d, t in
    // (t_min, t_max), which boxes and bounds cull by; shapes are searched
    // only in (search_min, search_max), what the boxes above that hold
    // their solids leave of it.
    void gather(const std::vector<Instance>& instances, std::uint32_t node, const DVec3& o, const DVec3& d,
                double t_min, double t_max, double search_min, double search_max, std::vector<CsgCrossing>& out) const;
    // POV's Ray_In_Bound for one bound: the ray from o + t_min d on meets
    // the tree under `node` or starts inside it (`scratch` is left as it was).
    bool ray_meets(const std::vector<Instance>& instances, std::uint32_t node, const DVec3& o, const DVec3& d,
                   double t_min, std::vector<CsgCrossing>& scratch) const;
    void bound(const std::vector<Instance>& instances, std::uint32_t node);
    // The box of a node left unbounded by its children and clips, from what
    // the leaves among its children (and with_clips, among its clips and
    // the node itself, a leaf) leave of each other (Shape::narrow_box).
    void narrow_intersection(const std::vector<Instance>& instances, std::uint32_t node, bool with_clips);
};

}  // namespace lancer
