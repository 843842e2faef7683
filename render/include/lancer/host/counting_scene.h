// A RenderScene that counts the ray queries (intersect, occluded) made
// through it and forwards everything to the scene it wraps. Prepare the
// integrator with the CountingScene and render with it, so integrators that
// remember their prepared scene see the same object:
//     CountingScene counted(*scene);
//     integrator->prepare(counted);
//     options.ray_counter = &counted;
//     render_image(counted, *integrator, options, film);  // stats.rays set
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <vector>

#include "lancer/render_scene.h"

namespace lancer {

class CountingScene final : public RenderScene {
  public:
    explicit CountingScene(const RenderScene& inner);

    bool intersect(const Ray& ray, Hit& hit) const override {
        count();
        return m_inner.intersect(ray, hit);
    }
    void intersect_batch(const Ray* rays, int count, Hit* hits, bool* found, RayCoherence coherence) const override {
        this->count(std::uint64_t(count));
        m_inner.intersect_batch(rays, count, hits, found, coherence);
    }
    bool occluded(const Ray& ray) const override {
        count();
        return m_inner.occluded(ray);
    }
    ShadowBlockers shadow_blockers(const Ray& ray) const override {
        count();
        return m_inner.shadow_blockers(ray);
    }
    ShadowBlockers shadow_crossings(const Ray& ray, SeeThroughHits& crossed) const override {
        count();
        return m_inner.shadow_crossings(ray, crossed);
    }
    // Not a ray: not counted.
    bool may_block_towards(const Vec3& origin, const Vec3& corner, const Vec3& edge1,
                           const Vec3& edge2) const override {
        return m_inner.may_block_towards(origin, corner, edge1, edge2);
    }
    const std::vector<const Light*>& lights() const override { return m_inner.lights(); }
    const std::vector<const Light*>& local_lights() const override { return m_inner.local_lights(); }
    const Camera& camera() const override { return m_inner.camera(); }
    Color background(const Ray& ray) const override { return m_inner.background(ray); }
    bool background_varies() const override { return m_inner.background_varies(); }
    float background_transparency() const override { return m_inner.background_transparency(); }
    const SceneOptions& options() const override { return m_inner.options(); }
    Bounds bounds() const override { return m_inner.bounds(); }
    bool has_media() const override { return m_inner.has_media(); }
    bool opaque_surfaces() const override { return m_inner.opaque_surfaces(); }
    MediumRegion atmosphere() const override { return m_inner.atmosphere(); }
    const SceneFog* fog() const override { return m_inner.fog(); }
    const SceneRainbows* rainbows() const override { return m_inner.rainbows(); }
    const InteriorStack& camera_interiors() const override { return m_inner.camera_interiors(); }

    // Queries so far, over every thread. Exact once the threads are idle.
    std::uint64_t rays() const;

  private:
    // One counter per thread, each on its own cache line; a slot is only
    // written by the thread that took it, so a relaxed load and store (no
    // locked instruction) suffice.
    struct alignas(64) Slot {
        std::atomic<std::uint64_t> count{0};
    };
    void count(std::uint64_t queries = 1) const;
    const RenderScene& m_inner;
    std::unique_ptr<Slot[]> m_slots;
    int m_slot_count;
    std::uint64_t m_id;                         // distinct for every CountingScene
    mutable std::atomic<int> m_slots_taken{0};  // by threads, past the shared one
};

}  // namespace lancer
