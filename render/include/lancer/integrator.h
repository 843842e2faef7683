// The integrator plugin ABI. A plugin is one shared library exporting
//     extern "C" const lancer::IntegratorDescriptor* lancer_integrator_descriptor();
// (write LANCER_EXPORT_INTEGRATOR(descriptor) at the end of the .cpp). The
// host owns the pixel loop, film, threads, progress and output; a plugin
// only supplies the radiance carried by one camera ray.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "lancer/parameters.h"
#include "lancer/ray.h"
#include "lancer/render_scene.h"
#include "lancer/sampler.h"

namespace lancer {

// Bump whenever a header a plugin compiles against changes layout or
// virtual tables; the host refuses any other version.
inline constexpr std::uint32_t kPluginAbiVersion = 4;

// One camera sample: its pixel and its index among the pixel's samples
// (which selects its random stream).
struct CameraSample {
    int x = 0, y = 0;
    std::uint32_t index = 0;
};

// Camera samples whose nearest hits the host found together: sample i's
// ray is rays[i], and its hit hits[i] when found[i] (else it escaped).
struct CameraHits {
    int count = 0;
    const CameraSample* samples = nullptr;
    const Ray* rays = nullptr;
    const Hit* hits = nullptr;
    const bool* found = nullptr;
    bool camera_drew_jitter = false;  // the camera took one next_2d() of each stream

    const Hit* hit(int i) const { return found[i] ? &hits[i] : nullptr; }
    // Positions `sampler` where radiance() would find sample i's stream:
    // started, and past the camera's jitter.
    void position(Sampler& sampler, int i) const {
        sampler.start_sample(samples[i].x, samples[i].y, samples[i].index);
        if (camera_drew_jitter) sampler.next_2d();
    }
};

class Integrator {
public:
    virtual ~Integrator() = default;
    // Once per render, before any radiance() call (precomputation).
    virtual void prepare(const RenderScene& scene) {}
    // Radiance arriving at the camera along `ray`. Called concurrently from
    // many threads: must not mutate the integrator. Use only `sampler` for
    // randomness.
    virtual Color radiance(const Ray& ray, const RenderScene& scene, Sampler& sampler) const = 0;
    // Opt-in for integrators whose radiance() begins by finding the ray's
    // nearest hit: when true, the host finds the camera rays' hits itself,
    // tracing neighbouring rays together (RenderScene::intersect_coherent,
    // faster than one by one), and calls radiance_from_hit() instead of
    // radiance(). radiance() must still work and give the same result.
    virtual bool shades_camera_hits() const { return false; }
    // Radiance arriving at the camera along `ray`, given its nearest hit
    // (null: the ray hit nothing). The sampler is positioned exactly as it
    // would be for radiance(). Same threading rules as radiance().
    virtual Color radiance_from_hit(const Ray& ray, const Hit* hit, const RenderScene& scene,
                                    Sampler& sampler) const {
        return radiance(ray, scene, sampler);
    }
    // What the host calls for a batch of camera hits (up to a tile's):
    // radiance[i] for sample i. The default positions the sampler and calls
    // radiance_from_hit() for each; an integrator that draws no random
    // numbers may override it to shade the batch in one loop, with no
    // virtual call or sampler positioning per hit. The result must equal
    // radiance_from_hit()'s bit for bit.
    virtual void radiance_from_hits(const CameraHits& batch, const RenderScene& scene, Sampler& sampler,
                                    Color* radiance) const {
        for (int i = 0; i < batch.count; ++i) {
            batch.position(sampler, i);
            radiance[i] = radiance_from_hit(batch.rays[i], batch.hit(i), scene, sampler);
        }
    }
    // True if radiance() uses no randomness: at one sample per pixel the host
    // then traces the pixel centre; more samples antialias.
    virtual bool is_deterministic() const { return false; }
    // The sampler the host gives radiance(); one per thread, cloned.
    virtual std::unique_ptr<Sampler> make_sampler(std::uint64_t seed) const {
        return make_independent_sampler(seed);
    }
};

// Base for integrators that shade the camera ray's nearest hit: radiance()
// is intersect() then radiance_from_hit(), so the host's batched path and
// the ray-by-ray path agree by construction. Implement radiance_from_hit().
class FirstHitIntegrator : public Integrator {
public:
    Color radiance(const Ray& ray, const RenderScene& scene, Sampler& sampler) const final {
        Hit hit;
        const bool found = scene.intersect(ray, hit);
        return radiance_from_hit(ray, found ? &hit : nullptr, scene, sampler);
    }
    bool shades_camera_hits() const override { return true; }
    Color radiance_from_hit(const Ray& ray, const Hit* hit, const RenderScene& scene,
                            Sampler& sampler) const override = 0;
};

struct IntegratorDescriptor {
    std::uint32_t abi_version;
    const char* name;         // what `-i NAME` selects; also the library's file name
    const char* description;  // one line
    const ParameterDecl* parameters;
    std::size_t parameter_count;
    // Creates the integrator; parameters are validated and carry defaults.
    std::unique_ptr<Integrator> (*create)(const ParameterSet& parameters);
};

}  // namespace lancer

#define LANCER_EXPORT_INTEGRATOR(descriptor)                                                  \
    extern "C" __attribute__((visibility("default"))) const ::lancer::IntegratorDescriptor*  \
    lancer_integrator_descriptor() {                                                         \
        return &(descriptor);                                                                \
    }
