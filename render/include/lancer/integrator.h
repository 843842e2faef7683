// The integrator plugin ABI. A plugin is one shared library exporting
//     extern "C" const lancer::IntegratorDescriptor* lancer_integrator_descriptor();
// (write LANCER_EXPORT_INTEGRATOR(descriptor) at the end of the .cpp). The
// host owns the pixel loop, film, threads, progress and output; it traces
// the camera rays and hands the plugin their hits, in batches; the plugin
// supplies the radiance each camera ray carries (docs/plugins.md).
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
inline constexpr std::uint32_t kPluginAbiVersion = 21;

// The random numbers of one camera sample, which the host positions: each
// sample has a stream of its own (a function of seed, pixel and sample
// index only), already past the host's own draws for the film point.
class CameraSampleStreams {
  public:
    virtual Sampler& stream(int sample) const = 0;

  protected:
    ~CameraSampleStreams() = default;
};

// Camera rays the host traced together, with their nearest hits: sample i
// looks along ray(i) and finds hit(i), null when the ray escaped.
class CameraHits {
  public:
    CameraHits(int count, const Ray* rays, const Hit* hits, const bool* found, const CameraSampleStreams& streams)
        : m_count(count), m_rays(rays), m_hits(hits), m_found(found), m_streams(&streams) {}

    int count() const { return m_count; }
    const Ray& ray(int i) const { return m_rays[i]; }
    const Hit* hit(int i) const { return m_found[i] ? &m_hits[i] : nullptr; }
    // Sample i's random numbers. Positioning a stream costs a hash: an
    // integrator that draws no random numbers should not ask for it.
    Sampler& sampler(int i) const { return m_streams->stream(i); }

  private:
    int m_count;
    const Ray* m_rays;
    const Hit* m_hits;
    const bool* m_found;
    const CameraSampleStreams* m_streams;
};

class Integrator {
  public:
    virtual ~Integrator() = default;
    // Once per render, before any shading (precomputation). The scene is the
    // one every later call receives.
    virtual void prepare(const RenderScene& scene) {}
    // Radiance arriving at the camera along `ray`, whose nearest hit the
    // host found (null: the ray escaped). Called concurrently from many
    // threads: must not mutate the integrator. Use only `sampler` for
    // randomness.
    virtual Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene,
                                   Sampler& sampler) const = 0;
    // What the host calls: radiance[i] for each sample of a batch of camera
    // hits (up to a few hundred neighbouring samples). The default is
    // shade_camera_hit() for each, with its own stream. An integrator may
    // override it to shade the batch in one loop (raycast shades many hits
    // lane by lane); the result must equal shade_camera_hit()'s bit for bit.
    virtual void shade_camera_hits(const CameraHits& batch, const RenderScene& scene, Color* radiance) const {
        for (int i = 0; i < batch.count(); ++i)
            radiance[i] = shade_camera_hit(batch.ray(i), batch.hit(i), scene, batch.sampler(i));
    }
    // True if shading uses no randomness: at one sample per pixel the host
    // then traces the pixel centre; more samples antialias.
    virtual bool is_deterministic() const { return false; }
    // The kind of sampler behind every stream; one per thread, cloned.
    virtual std::unique_ptr<Sampler> make_sampler(std::uint64_t seed) const { return make_independent_sampler(seed); }
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

#define LANCER_EXPORT_INTEGRATOR(descriptor)                                                \
    extern "C" __attribute__((visibility("default"))) const ::lancer::IntegratorDescriptor* \
    lancer_integrator_descriptor() {                                                        \
        return &(descriptor);                                                               \
    }
