// The compiled, world-space scene integrators query: geometry (Embree behind
// the scenes), materials, lights with their proxies, camera, background.
// The host compiles it once per render (lancer/host/scene_compiler.h);
// integrators only query it. Immutable and thread-safe.
#pragma once

#include <cstddef>
#include <memory>
#include <new>
#include <string>
#include <type_traits>
#include <vector>

#include "lancer/camera.h"
#include "lancer/fog.h"
#include "lancer/hit.h"
#include "lancer/interior_stack.h"
#include "lancer/light.h"
#include "lancer/material.h"
#include "lancer/medium.h"
#include "lancer/rainbow.h"

namespace lancer {

struct Bounds {
    Vec3 lower{kInfinity};
    Vec3 upper{-kInfinity};
    bool empty() const { return lower.x > upper.x; }
};

struct SceneOptions {
    int max_trace_level = 5;  // global_settings max_trace_level
    float adc_bailout = 1.0f / 255.0f;
    Color ambient_light{1.0f};
};

enum class RayCoherence { Incoherent, Coherent };

// What lies on a shadow ray (RenderScene::shadow_blockers).
enum class ShadowBlockers { None, SeeThrough, Opaque };

// The surfaces on a shadow ray that may let light through, nearest first,
// each the hit intersect() gives there (RenderScene::shadow_crossings).
class SeeThroughHits {
  public:
    static constexpr int kMost = 16;
    int count = -1;  // -1: not gathered; walk them with intersect()

    // Surface k, for k < count.
    const Hit& operator[](int k) const {
        return *std::launder(reinterpret_cast<const Hit*>(m_storage + std::size_t(k) * sizeof(Hit)));
    }
    // Surface k made anew, for the scene to fill.
    Hit& make(int k) { return *::new (static_cast<void*>(m_storage + std::size_t(k) * sizeof(Hit))) Hit(); }

  private:
    static_assert(std::is_trivially_destructible_v<Hit>);
    // Left unset until made: every shadow ray of a scene without media
    // carries one, and most gather nothing.
    alignas(Hit) unsigned char m_storage[kMost * sizeof(Hit)];
};

class RenderScene {
  public:
    virtual ~RenderScene() = default;

    // Nearest hit along the ray within [t_min, t_max]; false if none.
    virtual bool intersect(const Ray& ray, Hit& hit) const = 0;
    // intersect() for `count` rays at once; found[i] tells whether hits[i]
    // was filled. The results are intersect()'s, bit for bit. Coherent rays
    // (neighbouring camera rays, nearly parallel) are traced in packets,
    // which is faster than one by one; incoherent ones (bounces) one by one.
    virtual void intersect_batch(const Ray* rays, int count, Hit* hits, bool* found, RayCoherence coherence) const {
        for (int i = 0; i < count; ++i) found[i] = intersect(rays[i], hits[i]);
    }
    // True if any shadow-casting surface lies within [t_min, t_max]. Area
    // lights are not occluders of themselves: a shadow ray aimed at a point
    // on a light stops short of it (Hit::spawn_ray_to).
    virtual bool occluded(const Ray& ray) const = 0;
    // What occluded() found, told apart: nothing; only surfaces that may
    // let light through somewhere; or a shadow-casting surface that lets
    // none through anywhere (every pigment it may show, or a layer of each,
    // has no filter or transmit: POV-Ray's opaque objects). An Opaque
    // answer needs no walk through the surfaces to know the shadow is
    // black, unless the blocker is the light's own surface. The default
    // tells them apart only in a scene of opaque surfaces.
    virtual ShadowBlockers shadow_blockers(const Ray& ray) const {
        if (!occluded(ray)) return ShadowBlockers::None;
        return opaque_surfaces() ? ShadowBlockers::Opaque : ShadowBlockers::SeeThrough;
    }
    // shadow_blockers(), and for a SeeThrough answer the surfaces on the
    // way, gathered by the same query when the scene can (crossed.count >=
    // 0): a shadow ray through glass then costs one traversal, not one per
    // surface and one more. Not gathered (count -1) where the scene cannot,
    // where two of them nearly coincide, or past kMost of them. The default
    // gathers none.
    virtual ShadowBlockers shadow_crossings(const Ray& ray, SeeThroughHits& crossed) const {
        crossed.count = -1;
        return shadow_blockers(ray);
    }
    // Conservative: false only when no shadow-casting surface can cross a
    // segment from `origin` to any point corner + s * edge1 + t * edge2 of
    // a parallelogram (s, t in [0, 1]), so that shadow rays from `origin`
    // to such points need not be traced (an area light's grid seen from a
    // point with nothing near the way). True whenever the scene cannot
    // tell cheaply.
    virtual bool may_block_towards(const Vec3& origin, const Vec3& corner, const Vec3& edge1, const Vec3& edge2) const {
        return true;
    }

    // Every light for next-event estimation: point, directional, rectangle,
    // sphere and emissive objects.
    virtual const std::vector<const Light*>& lights() const = 0;
    // The seed's simple-model lights: point and directional lights plus the
    // proxy of every area light and emitter.
    virtual const std::vector<const Light*>& local_lights() const = 0;

    virtual const Camera& camera() const = 0;
    // Radiance of a ray that escapes the scene.
    virtual Color background(const Ray& ray) const = 0;
    // Whether background() changes with the direction (a sky_sphere): worth
    // importance sampling (lancer/shading/environment_light.h).
    virtual bool background_varies() const { return false; }
    // The share of the background an image's alpha channel sees through
    // (POV's background transmit, with +UA): 0 is opaque.
    virtual float background_transparency() const { return 0.0f; }
    virtual const SceneOptions& options() const = 0;
    virtual Bounds bounds() const = 0;  // of all finite geometry

    // Participating media (lancer/medium.h): whether any object's interior
    // or the scene has media (false: no integrator looks for them), and the
    // scene-level medium, the atmosphere (empty region: none).
    virtual bool has_media() const { return false; }
    virtual MediumRegion atmosphere() const { return {}; }
    // POV's fog (lancer/fog.h); null: none, and no integrator looks for it.
    virtual const SceneFog* fog() const { return nullptr; }
    // POV's rainbows (lancer/rainbow.h); null: none.
    virtual const SceneRainbows* rainbows() const { return nullptr; }
    // The objects that contain the camera's location, where a camera ray
    // starts (POV's containing interiors): they decide the media, fog and
    // rainbow of its first stretch. Empty in a scene without any of those.
    virtual const InteriorStack& camera_interiors() const {
        static const InteriorStack kNone;
        return kNone;
    }
    // True when no surface lets light through anywhere (no filter or
    // transmit in any pigment): a shadow ray blocked by anything is then
    // black, and need not find what blocked it. False whenever the scene
    // cannot tell.
    virtual bool opaque_surfaces() const { return false; }
};

}  // namespace lancer
