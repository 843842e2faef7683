// The shapes outside the BVH (planes, unbounded quadrics and trees, and
// objects reaching past Embree's range), tested on every ray after it, in
// the order the scene lists them. A plane is kept as its world normal and
// distance beside the list, so testing it costs a division rather than an
// instance lookup, a ray mapped to object space and a dispatch on the
// shape's kind: about a fifth of all the work on a scene of mirror planes
// (bench/README.md). A room's walls (`box { ... inverse }`) skip the
// tree's dispatch the same way. A plane written in world coordinates (a floor, a
// wall, a mirror) gives intersect_plane's answers bit for bit; a placed
// one the same up to the rounding of its world plane (internal to
// liblancer).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/scene_data.h"
#include "lancer/ray.h"

namespace lancer::embree {

class UnboundedShapes {
  public:
    void add(const Instance& instance, std::uint32_t index);
    bool empty() const { return m_shapes.empty(); }
    std::size_t size() const { return m_shapes.size(); }
    // The k-th shape's instance index, in the scene's order.
    std::uint32_t instance(std::size_t k) const { return m_shapes[k].instance; }

    // The nearest crossing of `ray` with t in (t_min, t_max): t_max lowered
    // to it, with the instance, its CSG leaf and face. The first listed
    // shape wins a tie. False if none is crossed.
    bool nearest(const SceneData& data, const Ray& ray, double t_min, double& t_max, std::uint32_t& instance,
                 std::uint32_t& leaf, int& face) const;
    // Whether a shape that casts shadows crosses `ray` over (t_min, t_max).
    bool occluded(const SceneData& data, const Ray& ray, double t_min, double t_max) const;
    // What occluded() finds, told apart (RenderScene::shadow_blockers).
    ShadowBlockers shadow_blockers(const SceneData& data, const Ray& ray, double t_min, double t_max) const;

  private:
    struct Entry {
        DVec3 normal{0.0};  // a world plane's: dot(p, normal) = distance
        double distance = 0.0;
        std::uint32_t instance = 0;
        bool world_plane = false;  // else tested through the instance (a flattened plane, any other shape)
        // An object that is one shape made inverse (CsgTree::lone_leaf): its
        // leaf is tested directly, without the tree's dispatch.
        bool lone_leaf = false;
        std::uint32_t leaf = 0;
        bool casts_shadow = true;
        bool blocks_all_light = false;  // Instance::blocks_all_light
    };
    // Whether `shape` is crossed over (t_min, t_max): a world plane on the
    // world ray (origin, direction), any other shape in its own space.
    static bool crosses(const SceneData& data, const Entry& shape, const Ray& ray, const DVec3& origin,
                        const DVec3& direction, double t_min, double t_max, double& t, std::uint32_t& leaf, int& face);
    static bool crosses_instance(const SceneData& data, std::uint32_t index, const Ray& ray, double t_min, double t_max,
                                 double& t, std::uint32_t& leaf, int& face);
    std::vector<Entry> m_shapes;
};

}  // namespace lancer::embree
