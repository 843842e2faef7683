// raycast — the seed's first integrator: nearest hit, local lighting, no shadows.
//
// For each camera ray, the nearest surface is shaded with the simple local
// model: for every light of the scene's local model (point and directional
// lights, plus the point-light proxy of every area light and emitter), the
// surface's BRDF (diffuse, Phong and Blinn lobes) times |cos| between the
// shading normal and the light, times the light's incident radiance; no
// shadow rays, so every light reaches every surface facing it. POV-Ray's
// ambient term and the surface's own emission are added; a ray that hits
// nothing returns the background. No randomness: one sample per pixel is
// exact (more samples only anti-alias).
//
// | parameter  | type | default | meaning                                          |
// |------------|------|---------|--------------------------------------------------|
// | `ambient`  | bool | true    | add POV's ambient term (ambient × pigment × ambient_light) |
// | `specular` | bool | true    | include the glossy lobes (phong, specular); false: diffuse only |
//
// Example:
//     lancer render scenes/demo.pov -i raycast -p specular=false -o demo_diffuse.png
// or in the scene:
//     render_settings { integrator "raycast" ambient off }
#include <cmath>
#include <iterator>

#include <lancer/integrator.h>

namespace {

using namespace lancer;

class RaycastIntegrator final : public Integrator {
public:
    RaycastIntegrator(bool with_ambient, bool with_specular)
        : m_with_ambient(with_ambient), m_with_specular(with_specular) {}

    Color radiance(const Ray& ray, const RenderScene& scene, Sampler&) const override {
        Hit hit;
        if (!scene.intersect(ray, hit)) return scene.background(ray);

        const Material& material = *hit.material;
        const SurfaceSample surface = material.sample_surface(hit);
        const Vec3 wo = -glm::normalize(ray.direction);
        const Vec3 n = hit.facing_normal(wo);

        Color radiance = material.emitted(surface);
        if (m_with_ambient) radiance += material.ambient(surface, scene.options().ambient_light);

        // Every local light is a point or directional light (proxies stand
        // in for area lights), so one sample at any u is exact.
        for (const Light* light : scene.local_lights()) {
            const LightSample incident = light->sample(hit.position, Vec2(0.5f));
            if (incident.pdf <= 0.0f || is_black(incident.radiance)) continue;
            const Color f = m_with_specular ? material.brdf(surface, n, wo, incident.wi)
                                            : material.diffuse_brdf(surface, n, wo, incident.wi);
            radiance += f * std::abs(glm::dot(n, incident.wi)) * incident.radiance / incident.pdf;
        }
        return radiance;
    }

    bool is_deterministic() const override { return true; }

private:
    bool m_with_ambient;
    bool m_with_specular;
};

const ParameterDecl kParameters[] = {
    {"ambient", ParameterType::Bool, "true",
     "add POV's ambient term (ambient x pigment x ambient_light)"},
    {"specular", ParameterType::Bool, "true",
     "include the glossy lobes (phong, specular); false: diffuse only"},
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
