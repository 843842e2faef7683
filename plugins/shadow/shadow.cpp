// shadow — the seed's second integrator ("Raycast + Occultation"): raycast
// with a shadow ray per light, hence hard shadows.
//
// The nearest hit is shaded with the same local model as `raycast`
// (emission + ambient + Σ over lights of BRDF × |cos| × incident radiance),
// but a light counts only if the shadow ray from the hit towards it is
// unobstructed. Shadow rays stop short of the light by a margin scaled to
// the magnitude of the light's position (Hit::spawn_ray_to), so a lamp lying
// on a surface does not shadow itself. Transparent objects on the way filter
// the light by their transmission colour without bending it (POV-Ray's
// filtered shadows); `no_shadow` objects cast none. POV's area_light casts
// POV-Ray's grid shadow (shading/shadow_rays.h). lancer's physical lamps and
// emitters act through their point proxy, as in the seed: hard shadows from
// the lamp's centre. Along the camera ray, POV's media (the scene's and
// those of a hollow object the camera is in), fog and rainbows show as in
// whitted, the media lit behind shadow rays.
//
// Beyond the seed, `area_samples N` (N > 0) replaces each physical lamp's proxy
// by N samples of its surface (Light::sample with the sampler's 2D values),
// each with its own shadow ray, averaged: soft shadows with penumbrae, and
// the exact direct light of the lamp as N and the pixel samples grow. Point
// and directional lights stay hard.
//
// Parameters: documented by `lancer plugins` / docs/integrators.md (from kParameters below).
//
// Deterministic when area_samples = 0 (one sample per pixel is exact).
//
// Example:
//     lancer render scenes/hard_shadows.pov -i shadow -o shadows.png
//     lancer render scenes/demo.pov -i shadow -p area_samples=16 --spp 4 -o soft.png
// or in the scene:
//     render_settings { integrator "shadow" { area_samples 16 } }
#include <iterator>
#include <stdexcept>
#include <string>

#include <lancer/integrator.h>
#include <lancer/shading/local_shading.h>
#include <lancer/shading/material_layers.h>
#include <lancer/shading/pov_media.h>

namespace {

using namespace lancer;

class ShadowIntegrator final : public Integrator {
  public:
    ShadowIntegrator(int area_samples, bool with_ambient)
        : m_area_samples(area_samples), m_with_ambient(with_ambient) {}

    Color shade_camera_hit(const Ray& ray, const Hit* found, const RenderScene& scene,
                           Sampler& sampler) const override {
        return seen_through_media(scene, ray, found, surface_radiance(ray, found, scene, sampler),
                                  MediaLighting{&sampler}, scene.camera_interiors());
    }

    bool is_deterministic() const override { return m_area_samples == 0; }

  private:
    Color surface_radiance(const Ray& ray, const Hit* found, const RenderScene& scene, Sampler& sampler) const {
        if (!found) return scene.background(ray);
        const auto own_light = [&](const ShadingContext& seen) {
            ShadingContext at = seen;
            const Hit& hit = at.hit;
            // Its shadow rays start in the objects the camera is in.
            in_interiors(at, scene.camera_interiors());
            Color radiance = surface_emission(at);
            if (m_with_ambient) radiance += opaque_ambient(scene, at);
            for (const Light* light : scene.lights()) {
                if (!light_reaches(*light, hit)) continue;  // POV's light_group
                if (m_area_samples > 0 && !light->is_delta())
                    radiance += sampled_area_light(scene, at, *light, sampler);
                else
                    radiance += reflect_simple_light(scene, at, *light, Shadows::Hard).total();
            }
            return radiance;
        };
        return shade_own_light(*found, ray, scene, own_light);
    }

    // Mean over area_samples points of the light's surface, each behind its
    // own shadow ray: the Monte Carlo estimate of the lamp's direct light.
    Color sampled_area_light(const RenderScene& scene, const ShadingContext& at, const Light& light,
                             Sampler& sampler) const {
        Color sum(0.0f);
        for (int i = 0; i < m_area_samples; ++i) {
            const LightSample sample = light.sample(at.hit.position, sampler.next_2d());
            const Color reflected = reflect_light_sample(at, sample).total();
            if (is_black(reflected)) continue;
            sum += reflected * transmittance_to(scene, at.hit, sample.point, nullptr, at.inside);
        }
        return sum / float(m_area_samples);
    }

    int m_area_samples;
    bool m_with_ambient;
};

constexpr std::int64_t kMaxAreaSamples = 1 << 16;

const ParameterDecl kParameters[] = {
    {"area_samples", ParameterType::Int, "0",
     "0: physical lamps (area_rectangle, area_sphere) and emitters through their point proxy (hard shadows); "
     "N > 0: N surface samples per lamp (soft shadows). POV's area_light always casts its grid shadow"},
    {"ambient", ParameterType::Bool, "true", "add POV's ambient term (ambient x pigment x ambient_light x opacity)"},
};

std::unique_ptr<Integrator> create(const ParameterSet& parameters) {
    const std::int64_t area_samples = parameters.get_int("area_samples", 0);
    if (area_samples < 0 || area_samples > kMaxAreaSamples)
        throw std::invalid_argument("shadow: area_samples must lie in [0, " + std::to_string(kMaxAreaSamples) +
                                    "], got " + std::to_string(area_samples));
    return std::make_unique<ShadowIntegrator>(static_cast<int>(area_samples), parameters.get_bool("ambient", true));
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion,
    "shadow",
    "raycast plus a shadow ray per light: hard shadows (soft with area_samples > 0)",
    kParameters,
    std::size(kParameters),
    &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
