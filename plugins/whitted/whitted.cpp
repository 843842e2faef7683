// whitted — the seed's third integrator ("Ajout de la Réflexion"): hard
// shadows plus mirror reflection and refraction, recursively.
//
// At each hit the colour is
//     emission + (1 - ρr)·(ambient + C_diffuse) + C_specular
//              + ρr · trace(mirror direction) + T·tint · trace(refracted direction)
// where C_diffuse and C_specular are the direct light of every light of the
// simple model (point and directional lights, the proxies of area lights),
// each behind a shadow ray as in the `shadow` integrator; ρr is the
// material's mirror reflectance (POV's `reflection`, with its min/max,
// falloff and `fresnel on`), T its transparency (pigment filter + transmit)
// and tint its transmission colour. The reflected direction S is the mirror
// of the incoming ray R about the normal N; the refracted direction follows
// Snell's law with the ratio of indices POV-Ray reads from the objects the
// ray is in (InteriorStack::refraction_eta), and total internal reflection
// sends the transmitted share into the reflection.
//
// A finish is a sum, as POV-Ray and the seed write it: colour = ρd·C_diffuse
// + ρs·C_specular + ρr·C_reflected; `reflection` adds to the diffuse term.
// `additive_reflection=false` makes the mirror take its share from the
// diffuse and ambient terms instead (scaled by 1 - ρr per channel).
// Highlights (phong, specular) are kept either way.
//
// Recursion follows POV-Ray's limits: the camera ray is level 1, a ray of a
// level above `max_depth` is not traced and counts black, and a ray whose
// path weight (product of the weights that led to it) falls under the
// scene's adc_bailout is not traced either.
//
// Parameters: documented by `lancer plugins` / docs/integrators.md (from kParameters below).
//
// Deterministic: one sample per pixel is exact (more only anti-alias).
//
// Example:
//     lancer render scenes/glass.pov -i whitted -p fresnel=true -o glass.png
// or in the scene:
//     render_settings { integrator "whitted" { fresnel true max_depth 8 } }
#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

#include <lancer/integrator.h>
#include <lancer/shading/specular_tracing.h>

namespace {

using namespace lancer;

// POV-Ray's own limit on max_trace_level; also bounds the recursion's stack.
constexpr std::int64_t kMaxDepth = 256;

class WhittedIntegrator final : public Integrator {
  public:
    WhittedIntegrator(int max_depth, bool fresnel, bool additive_reflection) : m_requested_depth(max_depth) {
        m_options.fresnel = fresnel;
        m_options.additive_reflection = additive_reflection;
    }

    void prepare(const RenderScene& scene) override {
        const int depth = m_requested_depth > 0 ? m_requested_depth : scene.options().max_trace_level;
        m_options.max_depth = int(std::clamp<std::int64_t>(depth, 1, kMaxDepth));
        m_options.min_weight = scene.options().adc_bailout;
    }

    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene, Sampler& sampler) const override {
        const auto lights_with_shadows = [&scene](const ShadingContext& at, const Color& diffuse_scale, Sampler&) {
            // A perfect mirror without highlights needs no shadow rays.
            if (is_black(diffuse_scale) && !at.material.has_glossy()) return LobeRadiance{};
            LobeRadiance local = simple_direct_light(scene, at, Shadows::Hard);
            local.diffuse += opaque_ambient(scene, at);
            return local;
        };
        return shade_specular(ray, hit, scene, sampler, m_options, lights_with_shadows, 1, 1.0f,
                              scene.camera_interiors());
    }

    bool is_deterministic() const override { return true; }

  private:
    int m_requested_depth;
    SpecularOptions m_options;
};

const ParameterDecl kParameters[] = {
    {"max_depth", ParameterType::Int, "0",
     "deepest ray level (camera ray = 1), at most 256; 0: the scene's max_trace_level"},
    {"fresnel", ParameterType::Bool, "false",
     "Fresnel split of transparent surfaces (reflect F, transmit 1-F); false: fixed coefficients"},
    {"additive_reflection", ParameterType::Bool, "true",
     "POV-Ray's sum: reflection added to the diffuse term; false: a mirror takes its share from the diffuse"},
};

std::unique_ptr<Integrator> create(const ParameterSet& parameters) {
    const std::int64_t max_depth = parameters.get_int("max_depth", 0);
    if (max_depth < 0 || max_depth > kMaxDepth)
        throw std::invalid_argument("whitted: max_depth must lie in [0, " + std::to_string(kMaxDepth) + "], got " +
                                    std::to_string(max_depth));
    return std::make_unique<WhittedIntegrator>(static_cast<int>(max_depth), parameters.get_bool("fresnel", false),
                                               parameters.get_bool("additive_reflection", true));
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion,
    "whitted",
    "hard shadows, mirror reflection and refraction, recursively to max_depth",
    kParameters,
    std::size(kParameters),
    &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
