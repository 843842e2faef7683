// A scene of a few bounded analytic shapes (the common hand-written POV
// scene: a floor, a few spheres and boxes) traced by testing each shape's
// world box in turn instead of through Embree's BVH. For so few shapes
// Embree's per-query set-up and its user-geometry callbacks cost more than
// the boxes themselves (bench/README.md, "Few shapes"). The answers are
// Embree's: the same shapes are tested over the same float t range and the
// nearest crossing wins in the same way, so the EmbreeScene completes them
// unchanged (internal to liblancer).
#pragma once

#include <cstdint>
#include <vector>

#include "geometry/scene_data.h"
#include "lancer/ray.h"

namespace lancer::embree {

struct EmbreeHit;
struct SeeThroughRecords;

class ShapeList {
  public:
    // Up to this many shapes a list traces faster than the BVH (measured,
    // bench/README.md).
    static constexpr std::size_t kMostShapes = 6;

    // Analytic instance `index`, which Embree knows as primitive
    // `primitive` of user geometry `geometry`.
    void add(const Instance& instance, std::uint32_t index, unsigned geometry, unsigned primitive);
    bool empty() const { return m_shapes.empty(); }
    std::size_t size() const { return m_shapes.size(); }

    // The nearest crossing with t in [t_near, t_far) of a traceable ray,
    // as rtcIntersect1 reports it on the same shapes: t_far lowered to its
    // float distance, the geometry and primitive ids, u the face and v the
    // CSG leaf's offset before its root. Untouched when nothing is crossed.
    void nearest(const SceneData& data, const Ray& ray, EmbreeHit& found) const;
    // Whether a shape that casts shadows crosses the ray over [t_near, t_far].
    bool occluded(const SceneData& data, const Ray& ray, float t_near, float t_far) const;
    // What occluded() finds, told apart (RenderScene::shadow_blockers);
    // with `records`, every crossing of a shape that may let light through
    // is recorded as nearest() would report it (shadow_crossings).
    ShadowBlockers shadow_blockers(const SceneData& data, const Ray& ray, float t_near, float t_far,
                                   SeeThroughRecords* records = nullptr) const;

    // Whether the box of a shape that casts shadows may come within
    // `margin` of the convex hull of `points`. Conservative: a separating
    // plane is sought only across the world axes and `axes` (the hull's
    // face normals).
    bool may_meet_hull(const DVec3* points, int point_count, const DVec3* axes, int axis_count, double margin) const;

  private:
    struct Entry {  // its world box, conservative, is its lane of m_boxes
        std::uint32_t instance;
        unsigned geometry, primitive;
        bool casts_shadow;
        bool blocks_all_light;   // Instance::blocks_all_light
        bool gathers_crossings;  // Instance::gathers_crossings
    };
    // The shapes' boxes by axis, one lane a shape, so one ray is tested
    // against all at once. The lanes past the shapes hold inverted boxes
    // (lower FLT_MAX, upper -FLT_MAX) that boxes_met's mask leaves out.
    static constexpr int kLanes = 8;
    static_assert(kMostShapes <= kLanes);
    struct Boxes {
        float lower[3][kLanes], upper[3][kLanes];
    };
    // Which boxes the ray's [t_near, t_far] meets, as bits by shape, and
    // where it enters each.
    unsigned boxes_met(const Ray& ray, float t_near, float t_far, float* entry) const;
    // `ray` in the object space of `shape`.
    static void to_object(const SceneData& data, const Entry& shape, const Ray& ray, DVec3& o, DVec3& d);
    static bool crosses(const SceneData& data, const Entry& shape, const Ray& ray, float t_near, float t_far, double& t,
                        int& face, std::uint32_t& leaf);
    std::vector<Entry> m_shapes;
    Boxes m_boxes = empty_boxes();
    static Boxes empty_boxes();
};

}  // namespace lancer::embree
