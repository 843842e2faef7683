// The compiled, world-space scene integrators query: geometry (Embree behind
// the scenes), materials, lights with their proxies, camera, background.
// Built once per render from the scene graph; immutable and thread-safe.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lancer/camera.h"
#include "lancer/hit.h"
#include "lancer/light.h"
#include "lancer/material.h"

namespace lancer {

namespace sg {
struct SceneGraph;
}

struct Bounds {
    Vec3 lower{kInfinity};
    Vec3 upper{-kInfinity};
    bool empty() const { return lower.x > upper.x; }
};

struct SceneOptions {
    int max_trace_level = 5;      // global_settings max_trace_level
    float adc_bailout = 1.0f / 255.0f;
    Color ambient_light{1.0f};
};

class RenderScene {
public:
    // Builds everything the scene uses and nothing else. Throws
    // lancer::SceneError (render/errors.h) with a source location on bad
    // input (unreadable image, degenerate geometry that cannot be rendered).
    static std::unique_ptr<RenderScene> compile(const sg::SceneGraph& graph);
    virtual ~RenderScene() = default;

    // Nearest hit along the ray within [t_min, t_max]; false if none.
    virtual bool intersect(const Ray& ray, Hit& hit) const = 0;
    // intersect() for `count` rays at once; found[i] tells whether hits[i]
    // was filled. Coherent rays (neighbouring camera rays) are traced
    // together, which is faster than one by one; the results are the same.
    // The default asks intersect() ray by ray.
    virtual void intersect_coherent(const Ray* rays, int count, Hit* hits, bool* found) const {
        for (int i = 0; i < count; ++i) found[i] = intersect(rays[i], hits[i]);
    }
    // True if any shadow-casting surface lies within [t_min, t_max]. Area
    // lights are not occluders of themselves: a shadow ray aimed at a point
    // on a light stops short of it (Hit::spawn_ray_to).
    virtual bool occluded(const Ray& ray) const = 0;

    // Every light for next-event estimation: point, directional, rectangle,
    // sphere and emissive objects.
    virtual const std::vector<const Light*>& lights() const = 0;
    // The seed's simple-model lights: point and directional lights plus the
    // proxy of every area light and emitter.
    virtual const std::vector<const Light*>& local_lights() const = 0;

    virtual const Camera& camera() const = 0;
    // Radiance of a ray that escapes the scene.
    virtual Color background(const Ray& ray) const = 0;
    virtual const SceneOptions& options() const = 0;
    virtual Bounds bounds() const = 0;  // of all finite geometry
};

}  // namespace lancer
