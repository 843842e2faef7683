// The one material model every integrator shares (docs/integrators.md).
//
// A surface scatters light through up to four components, each weighted by
// the finish and the pigment at the hit, with POV-Ray's values as written
// (../shared/reference/pov-3.7-semantics.md §3): under a light of colour C
// (incident radiance pi*C) a surface shows
//   - diffuse                   diffuse * pigment * cos^brilliance * C
//   - a Phong highlight         phong * max(0, R.wi)^phong_size * C
//   - a specular highlight      specular * max(0, N.H)^(1/roughness) * C
//   (highlights light-coloured, tinted towards the pigment by `metallic`),
// so the BRDF is each of these over pi*cos. Plus
//   - a perfect mirror          weight reflectance(cos) (POV's reflection{min max falloff
//                               fresnel metallic})
//   - a smooth dielectric       weight transmittance (pigment filter/transmit), Snell with ior
// plus emission (radiance = emission * pigment) and POV's ambient term
// (ambient * pigment * ambient_light; used only by integrators without
// indirect light).
//
// The values are POV's peaks, not albedos: a highlight reflects
// phong * 2 / (phong_size + 1) of the light at normal incidence (see
// phong_albedo, specular_albedo), so a finish can reflect more light than
// it receives, as in POV-Ray; every integrator evaluates the same finish
// (docs/scene-language.md says how `path` stays finite then).
#pragma once

#include <cmath>
#include <vector>

#include "lancer/hit.h"
#include "lancer/ray.h"
#include "lancer/texture.h"

namespace lancer {

class Medium;
class Material;

// POV-Ray's patterned textures (texture_map, a block pattern's list of
// textures, material_map, average): each entry is a material of its own,
// and the scene picks those that hold at a hit. Where more than one does,
// the hit keeps the mix (lancer/hit.h) and an integrator lights each entry
// (lancer/shading/material_blend.h).
class MaterialMix {
  public:
    struct Part {
        const Material* material = nullptr;
        float weight = 0.0f;
    };
    // Nested maps and `average` may mix more; the lightest then give way.
    static constexpr int kMostParts = 32;
    virtual ~MaterialMix() = default;
    // The entries at the hit (its unbent shading normal read by patterns
    // such as slope), heaviest first, shares summing to 1; their number,
    // at least 1.
    virtual int parts(const Hit& hit, Part* out) const = 0;
};

// POV-Ray's layered texture: its layers, top first, each a material of its
// own, lit one by one (lancer/shading/material_layers.h).
struct MaterialLayers {
    std::vector<const Material*> top_first;
};

// Everything a material needs to know about one hit, with the pigment
// already looked up.
struct SurfaceSample {
    Color pigment{0.0f};    // rgb of the pigment at the hit (linear)
    float filter = 0.0f;    // pigment's filter at the hit
    float transmit = 0.0f;  // pigment's transmit at the hit
};

// POV-Ray's normal { }: bends the shading normal at a hit by a pattern.
// The scene applies it when a ray finds the surface, so every integrator
// shades the same bumps; the geometric normal is left as it was.
class NormalPerturbation {
  public:
    virtual ~NormalPerturbation() = default;
    // The perturbed unit shading normal at the hit (world space, on the
    // side of `shading_normal`).
    virtual Vec3 perturb(const Hit& hit, const Vec3& shading_normal) const = 0;
};

struct MaterialParameters {
    const Texture* pigment = nullptr;            // never null after compilation
    const NormalPerturbation* normal = nullptr;  // null: the surface's own normal
    Color ambient{0.1f};
    Color emission{0.0f};
    float diffuse = 0.6f;
    float brilliance = 1.0f;
    float specular = 0.0f;
    float roughness = 0.05f;
    float phong = 0.0f;
    float phong_size = 40.0f;
    float metallic = 0.0f;
    Color reflection_min{0.0f};
    Color reflection_max{0.0f};
    float reflection_falloff = 1.0f;
    bool reflection_fresnel = false;
    float reflection_metallic = 0.0f;  // tints the mirror towards the pigment, as POV's
    // POV's reflection exponent: the reflected radiance is raised to it
    // (whitted, gather; a non-linear map that `path` cannot estimate
    // without bias, so path ignores it).
    float reflection_exponent = 1.0f;
    bool conserve_energy = false;  // transmitted light is scaled by 1 - mirror reflectance
    // POV's `diffuse a, b`: b is the diffuse share of light arriving from
    // behind the surface (translucency). POV's irid { }: the light the
    // surface reflects from each light is tinted by a thin film's
    // interference, per channel 1 + irid cos(2 pi thickness (|N.L| + |N.V|)
    // / wavelength), the thickness varied by turbulence at the hit. Both are
    // POV's local lighting, kept by raycast, shadow, whitted and gather;
    // path, a physical model, leaves them out.
    float diffuse_back = 0.0f;
    float crand = 0.0f;  // POV's crand: grain taken from the diffuse light (classic integrators)
    float irid = 0.0f;
    float irid_thickness = 0.0f;
    float irid_turbulence = 0.0f;
    Color irid_wavelengths{0.70f, 0.52f, 0.48f};  // global_settings irid_wavelength
    int noise_generator = 2;                      // global_settings noise_generator (irid's turbulence)
    // POV-Ray before 3.7 (and a scene with no #version): a filtering
    // surface's own light is scaled by 1 - (filter * max(pigment) +
    // transmit) rather than 1 - filter - transmit (POV's LegacyOpacity).
    bool legacy_opacity = false;
    float ior = 1.0f;
    // POV's fake caustics, as the exponent it uses: 45 times the
    // interior's `caustics` (0: none). A shadow ray crossing the surface
    // at cosine c to its normal carries 1 + c^caustics times the light.
    float caustics = 0.0f;
    // POV's interior fade (docs/scene-language.md): fade_distance 0 is none.
    float fade_distance = 0.0f;
    float fade_power = 0.0f;
    Color fade_color{0.0f};
    // POV's `hollow` on the object (the atmosphere fills it) and its
    // interior's media, kept only for a hollow object as POV shows them
    // (lancer/medium.h); null: none.
    bool hollow = false;
    const Medium* medium = nullptr;
    // The pigment neither filters nor transmits at any hit (POV's opaque
    // texture, known before the render): a shadow ray it meets is blocked
    // without a lookup.
    bool pigment_opaque = false;
    // No light passes any hit on this material: its pigment is opaque, or
    // one of its layers' is (the light through the layers is their
    // product), or every entry of its texture_map blocks light.
    bool blocks_light = false;
    // A patterned texture: the scene picks the entries that hold at each
    // hit (a hit an integrator sees never has a material with entries,
    // except on a light's surface, which keeps the one material its light
    // was made from).
    const MaterialMix* entries = nullptr;
    // A layered texture: this material is the layers composited into one
    // (for what cannot light each: path, an emitter); null: not layered.
    const MaterialLayers* layers = nullptr;
};

// The share of light a highlight of peak 1 reflects at normal incidence
// (POV-Ray's `albedo` keyword divides by it): 2 / (n + 1) for Phong, and
// for the specular lobe (k = 1/roughness) 8 (1 - 2^-(k+2)/2) / (k + 2).
inline float phong_albedo(float phong_size) {
    return 2.0f / (phong_size + 1.0f);
}
float specular_albedo(float exponent);

// The diffuse lobe's weight on the pigment: diffuse * opacity / pi * shape
// (shape is brilliance's cos^(brilliance-1)). The one copy of the
// arithmetic, shared by Material::diffuse_brdf and lane-parallel shading
// (plugins/raycast), so they agree bit for bit.
inline float diffuse_lobe_weight(float diffuse, float opacity, float shape) {
    return diffuse * opacity * (1.0f / kPi) * shape;
}

class Material {
  public:
    explicit Material(const MaterialParameters& parameters);

    const MaterialParameters& parameters() const { return m_params; }

    // Pigment colour, filter and transmit at the hit (texture lookup).
    SurfaceSample sample_surface(const Hit& hit) const {
        if (m_pigment_is_constant) return m_constant_pigment;
        if (m_params.pigment == nullptr) return {};
        const TextureSample texel = m_params.pigment->evaluate(hit);
        return SurfaceSample{texel.rgb, texel.filter, texel.transmit};
    }

    // Fraction of light that passes through the surface: filter + transmit,
    // in [0, 1]. Diffuse and glossy lobes are scaled by (1 - it).
    float transparency(const SurfaceSample& surface) const {
        return glm::clamp(surface.filter + surface.transmit, 0.0f, 1.0f);
    }
    // The share of the surface's own light it shows (diffuse, ambient), as
    // POV-Ray weighs it: 1 - filter - transmit, or POV 3.6's rule
    // (MaterialParameters::legacy_opacity). Neither is clamped, as in POV:
    // `transmit 100` makes it -99, which scenes use to raise the contrast of
    // what lies behind (POV's advanced/bwstripe.pov).
    float opacity(const SurfaceSample& surface) const {
        if (!m_params.legacy_opacity) return 1.0f - surface.filter - surface.transmit;
        const float pigment_peak = glm::max(surface.pigment.r, glm::max(surface.pigment.g, surface.pigment.b));
        return 1.0f - (surface.filter * pigment_peak + surface.transmit);
    }
    // Colour of transmitted light per unit transparency: filter tints by the
    // pigment, transmit does not.
    Color transmission_tint(const SurfaceSample& surface) const;
    // POV-Ray's transmitted colour, filter * pigment + transmit: the same as
    // transparency() * transmission_tint() while filter + transmit <= 1,
    // and neither scaled down beyond (POV passes more light than arrives
    // where a scene asks for it, e.g. `filter all` on a palette image's
    // clear entries) nor clamped at 0 (a negative transmit subtracts what
    // lies behind, in refraction and shadows alike: POV's
    // advanced/transmitfx.pov). For the classic integrators; `path` keeps
    // the scaled form.
    Color pov_transmitted(const SurfaceSample& surface) const {
        return surface.filter * surface.pigment + Color(surface.transmit);
    }

    // Radiance emitted towards the viewer (two-sided).
    Color emitted(const SurfaceSample& surface) const { return m_params.emission * surface.pigment; }
    // POV's ambient term, ambient * pigment * ambient_light.
    Color ambient(const SurfaceSample& surface, const Color& ambient_light) const {
        return m_params.ambient * surface.pigment * ambient_light;
    }

    // The non-delta BRDF (diffuse times opacity, + phong + specular) for
    // light arriving from wi and leaving towards wo. All vectors unit; n is
    // the shading normal facing wo. Returns 0 when wi is below the surface.
    Color brdf(const SurfaceSample& surface, const Vec3& n, const Vec3& wo, const Vec3& wi) const;
    // The diffuse part alone (gather replaces only this term).
    Color diffuse_brdf(const SurfaceSample& surface, const Vec3& n, const Vec3& wo, const Vec3& wi) const {
        return diffuse_brdf_at_opacity(surface, n, wi, opacity(surface));
    }
    // The same for a given opacity (path's physical one, in [0, 1]).
    Color diffuse_brdf_at_opacity(const SurfaceSample& surface, const Vec3& n, const Vec3& wi, float opacity) const {
        const float cos_i = glm::dot(n, wi);
        if (!(cos_i > 0.0f) || m_params.diffuse == 0.0f) return Color(0.0f);
        float shape = 1.0f;
        if (m_params.brilliance != 1.0f) shape = std::pow(cos_i, m_params.brilliance - 1.0f);
        return diffuse_lobe_weight(m_params.diffuse, opacity, shape) * surface.pigment;
    }
    // POV's backside diffuse for light arriving from behind (wi below the
    // surface, n facing wo); black when the finish has none.
    Color backside_diffuse_brdf(const SurfaceSample& surface, const Vec3& n, const Vec3& wi) const {
        const float cos_i = -glm::dot(n, wi);
        if (!(cos_i > 0.0f) || m_params.diffuse_back == 0.0f) return Color(0.0f);
        const float opacity = this->opacity(surface);
        float shape = 1.0f;
        if (m_params.brilliance != 1.0f) shape = std::pow(cos_i, m_params.brilliance - 1.0f);
        return diffuse_lobe_weight(m_params.diffuse_back, opacity, shape) * surface.pigment;
    }
    bool has_iridescence() const { return m_params.irid != 0.0f; }
    // The film's thickness at a world position (turbulence varies it).
    float film_thickness(const Vec3& position) const;
    // irid's tint of the light reflected from wi towards wo.
    Color iridescence(float film_thickness, const Vec3& n, const Vec3& wo, const Vec3& wi) const {
        const float phase = 2.0f * kPi * film_thickness * (std::abs(glm::dot(n, wi)) + std::abs(glm::dot(n, wo)));
        const Color& w = m_params.irid_wavelengths;
        return Color(1.0f) + m_params.irid * Color(std::cos(phase / w.r), std::cos(phase / w.g), std::cos(phase / w.b));
    }
    // The glossy part alone (phong + specular), POV's highlights.
    Color glossy_brdf(const SurfaceSample& surface, const Vec3& n, const Vec3& wo, const Vec3& wi) const;

    // Mirror reflectance for cos_i = dot(n, wo) (POV's reflection block; with
    // fresnel, Fresnel of ior scaled between min and max). Zero: no mirror.
    Color mirror_reflectance(const SurfaceSample& surface, float cos_i, float relative_ior) const;
    bool has_mirror() const;
    const NormalPerturbation* normal_perturbation() const { return m_params.normal; }
    const MaterialMix* entries() const { return m_params.entries; }
    const MaterialLayers* layers() const { return m_params.layers; }
    // POV's interior fade over a distance travelled inside the object: what
    // light leaving through (or totally reflected at) a back face is
    // multiplied by. 1 when the interior has no fade.
    Color interior_attenuation(float depth) const {
        const MaterialParameters& p = m_params;
        if (p.fade_distance == 0.0f) return Color(1.0f);
        const float relative = depth / p.fade_distance;
        if (p.fade_power >= 1000.0f) return glm::exp(-(Color(1.0f) - p.fade_color) * relative);
        return p.fade_color + (Color(1.0f) - p.fade_color) / (1.0f + std::pow(std::fabs(relative), p.fade_power));
    }
    // sample_surface() is the same at every hit.
    bool pigment_is_constant() const { return m_pigment_is_constant; }
    // What sample_surface() returns at every hit when pigment_is_constant().
    const SurfaceSample& constant_surface() const { return m_constant_pigment; }
    bool has_glossy() const { return m_params.phong > 0.0f || m_params.specular > 0.0f; }
    bool is_emissive() const { return max_component(m_params.emission) > 0.0f; }

    // Share of light reflected at normal incidence by each highlight, for
    // choosing among lobes.
    float phong_reflectance() const { return m_params.phong * phong_albedo(m_params.phong_size); }
    float specular_reflectance() const { return m_params.specular * m_specular_albedo; }

  private:
    Color metallic_reflection(const SurfaceSample& surface, float cos_i, const Color& reflectance) const;
    MaterialParameters m_params;
    float m_specular_albedo;
    // A pigment that does not vary, looked up once: sample_surface then
    // needs no virtual call.
    bool m_pigment_is_constant = false;
    SurfaceSample m_constant_pigment;
};

// Reflect `d` (pointing at the surface) about unit normal n.
inline Vec3 reflect(const Vec3& d, const Vec3& n) {
    return d - 2.0f * glm::dot(d, n) * n;
}
// Refract `d` (unit, pointing at the surface) through unit n (facing against
// d) with eta = n_incident / n_transmitted. False on total internal reflection.
bool refract(const Vec3& d, const Vec3& n, float eta, Vec3& transmitted);
// Unpolarised Fresnel reflectance of a dielectric interface.
float fresnel_dielectric(float cos_i, float eta);

}  // namespace lancer
