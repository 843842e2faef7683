// raycast — the seed's first integrator: nearest hit, local lighting, no shadows.
//
// For each camera ray, the nearest surface is shaded with the simple local
// model: for every light of the scene's local model (point and directional
// lights, plus the point-light proxy of every area light and emitter), the
// surface's BRDF (diffuse, Phong and Blinn lobes) times |cos| between the
// shading normal and the light, times the light's incident radiance; no
// shadow rays, so every light reaches every surface facing it. POV-Ray's
// ambient term and the surface's own emission (an area light's, when the
// ray hits the lamp) are added; a ray that hits nothing returns the
// background. The model is local_shading.h's, shared with shadow, whitted
// and gather, so all four agree wherever nothing is occluded. Along the
// camera ray, POV's media (the scene's and those of a hollow object the
// camera is in), fog and rainbows show as in whitted, the media lit
// without shadow rays. No randomness: one sample per pixel is exact (more
// only anti-alias); a medium's jitter is left out.
//
// Parameters: documented by `lancer plugins` / docs/integrators.md (from kParameters below).
//
// Example:
//     lancer render scenes/demo.pov -i raycast -p specular=false -o demo_diffuse.png
// or in the scene:
//     render_settings { integrator "raycast" { ambient off } }
#include <iterator>

#include <lancer/integrator.h>
#include <lancer/shading/local_shading.h>
#include <lancer/shading/material_layers.h>
#include <lancer/shading/pov_media.h>
#include "diffuse_point_lanes.h"

namespace {

using namespace lancer;

class RaycastIntegrator final : public Integrator {
  public:
    RaycastIntegrator(bool with_ambient, bool with_specular)
        : m_with_ambient(with_ambient), m_with_specular(with_specular) {}

    Color shade_camera_hit(const Ray& ray, const Hit* found, const RenderScene& scene, Sampler&) const override {
        return shade(ray, found, scene, SceneLighting(scene));
    }
    // No random numbers, so no sample's stream is asked for, and a batch is
    // shaded in one loop with the scene's lights and ambient light looked
    // up once. Hits of the most common kind (one colour, default finish,
    // point lights) go lane-parallel through DiffusePointLanes, bit for bit
    // the same as shade().
    void shade_camera_hits(const CameraHits& batch, const RenderScene& scene, Color* radiance) const override {
        const SceneLighting lighting(scene);
        const DiffusePointLanes lanes(lighting.lights, lighting.ambient_light, m_with_ambient);
        constexpr int kLanes = DiffusePointLanes::kLanes;
        const Ray* lane_ray[kLanes];
        const Hit* lane_hit[kLanes];
        int lane_sample[kLanes];
        int waiting = 0;
        auto shade_lanes = [&] {
            Color lane_radiance[kLanes];
            bool shaded[kLanes];
            lanes.shade(lane_ray, lane_hit, waiting, lane_radiance, shaded);
            for (int k = 0; k < waiting; ++k)
                radiance[lane_sample[k]] = shaded[k]
                                               ? seen_through_media(scene, *lane_ray[k], lane_hit[k], lane_radiance[k],
                                                                    kMediaLighting, scene.camera_interiors())
                                               : shade(*lane_ray[k], lane_hit[k], scene, lighting);
            waiting = 0;
        };
        for (int i = 0; i < batch.count(); ++i) {
            const Hit* hit = batch.hit(i);
            if (!lanes.usable() || !hit || !DiffusePointLanes::covers(*hit)) {
                radiance[i] = shade(batch.ray(i), hit, scene, lighting);
                continue;
            }
            lane_ray[waiting] = &batch.ray(i);
            lane_hit[waiting] = hit;
            lane_sample[waiting++] = i;
            if (waiting == kLanes) shade_lanes();
        }
        if (waiting > 0) shade_lanes();
    }

    bool is_deterministic() const override { return true; }

  private:
    // Media along camera rays as the surfaces are lit: no shadow rays, and
    // no random numbers (a medium's jitter is left out).
    static constexpr MediaLighting kMediaLighting{nullptr, false};

    struct SceneLighting {
        explicit SceneLighting(const RenderScene& scene)
            : lights(scene.lights()), ambient_light(scene.options().ambient_light) {}
        const std::vector<const Light*>& lights;
        Color ambient_light;
    };

    Color shade(const Ray& ray, const Hit* found, const RenderScene& scene, const SceneLighting& lighting) const {
        return seen_through_media(scene, ray, found, surface_radiance(ray, found, scene, lighting), kMediaLighting,
                                  scene.camera_interiors());
    }

    Color surface_radiance(const Ray& ray, const Hit* found, const RenderScene& scene,
                           const SceneLighting& lighting) const {
        if (!found) return scene.background(ray);
        // The same local model as shadow/whitted/gather (local_shading.h),
        // without shadow rays, so the integrators agree where nothing occludes.
        const auto own_light = [&](const ShadingContext& at) {
            Color radiance = surface_emission(at);
            if (m_with_ambient) radiance += opaque_ambient(lighting.ambient_light, at);
            const LobeRadiance reflected = simple_direct_light(scene, lighting.lights, at, Shadows::None);
            radiance += m_with_specular ? reflected.total() : reflected.diffuse;
            return radiance;
        };
        return shade_own_light(*found, ray, scene, own_light);
    }

    bool m_with_ambient;
    bool m_with_specular;
};

const ParameterDecl kParameters[] = {
    {"ambient", ParameterType::Bool, "true", "add POV's ambient term (ambient x pigment x ambient_light x opacity)"},
    {"specular", ParameterType::Bool, "true", "include the glossy lobes (phong, specular); false: diffuse only"},
};

std::unique_ptr<Integrator> create(const ParameterSet& parameters) {
    return std::make_unique<RaycastIntegrator>(parameters.get_bool("ambient", true),
                                               parameters.get_bool("specular", true));
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion,
    "raycast",
    "nearest hit, direct light from every light (area lights via proxies), no shadows",
    kParameters,
    std::size(kParameters),
    &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
