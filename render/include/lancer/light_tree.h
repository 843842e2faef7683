// Choosing one light among many by its likely contribution at a shading
// point, in time logarithmic in the number of lights: a binary tree over
// the lights' bounds, each node holding its lights' box, power and the cone
// of directions they emit in; a walk from the root picks each child in
// proportion to a bound on what it can send to the point (the importance of
// Conty Estevez and Kulla, "Importance Sampling of Many Lights with
// Adaptive Tree Splitting", 2018, in the form pbrt-v4 gives it).
//
// POV-Ray's point lights without fade light every distance alike and have
// no finite power: a tree of its own holds them (Falloff::None), weighing
// each by its colour and the cosines alone. Parallel lights and the sky
// have no position: can_bound() says no, and the caller chooses among
// those otherwise.
//
// Unbiased for a one-sample estimate: a light gets probability 0 at a
// point only where its bounds show it sends nothing there (behind a
// one-sided emitter, outside a spotlight's cone).
#pragma once

#include <cstdint>
#include <unordered_map>
#include <vector>

#include "lancer/light.h"

namespace lancer {

class LightTree {
  public:
    enum class Falloff {
        InverseSquare,  // lamps, emitters, POV lights with fade: weighed by power / distance^2
        None,           // POV point lights without fade: by power alone
    };
    // Whether a tree of `falloff` can hold `light`: it has a position or a
    // box, and its light falls off with distance (InverseSquare) or not at
    // all (None).
    static bool can_bound(const Light& light, Falloff falloff = Falloff::InverseSquare);

    // `lights`: each one can_bound with `falloff`. Their power weighs them
    // (90%, with 10% spread evenly, so a light whose power() underestimates
    // it still gets chosen; evenly if a power is not finite).
    explicit LightTree(const std::vector<const Light*>& lights, Falloff falloff = Falloff::InverseSquare);

    bool empty() const { return m_nodes.empty(); }

    struct Choice {
        const Light* light = nullptr;  // null: no light can reach the point
        float probability = 0.0f;
    };
    // One light for the point p with normal n (n = 0: a point in a medium,
    // lit from every side); u uniform in [0, 1).
    Choice sample(const Vec3& p, const Vec3& n, float u) const;
    // The probability sample(p, n, .) chooses `light` (0 for one not in the
    // tree).
    float probability(const Vec3& p, const Vec3& n, const Light* light) const;

    // What the tree is built from, per light or node.
    struct Bounds {
        Vec3 lower{0.0f}, upper{0.0f};
        float power = 0.0f;
        Vec3 axis{0.0f, 0.0f, 1.0f};  // the cone of emitted normals: its axis
        float cos_spread = -1.0f;     // its half-angle's cosine (-1: every way)
        float cos_emission = 0.0f;    // beyond the normals, how far light leaves (cos 90 degrees: a surface)
        bool two_sided = false;       // emits along -axis too
    };
    // A bound on what a node of these bounds sends to p (0: nothing).
    static float importance(const Bounds& bounds, const Vec3& p, const Vec3& n,
                            Falloff falloff = Falloff::InverseSquare);

  private:
    struct Node {
        Bounds bounds;
        std::uint32_t children[2] = {0, 0};  // interior
        const Light* light = nullptr;        // leaf
    };
    // The first child's share of a node's choice at p (-1: neither child
    // can reach p); sample() and probability() both walk by it.
    float left_share(const Node& node, const Vec3& p, const Vec3& n) const;
    std::uint32_t build(std::vector<std::pair<const Light*, Bounds>>& lights, std::size_t begin, std::size_t end,
                        std::uint64_t trail, int depth);

    Falloff m_falloff;
    std::vector<Node> m_nodes;  // the root first
    // Each light's path from the root: bit k says which child at depth k
    // (the walk ends at the light's leaf).
    std::unordered_map<const Light*, std::uint64_t> m_trails;
};

}  // namespace lancer
