// Whitted-style recursion shared by the whitted and gather integrators
// (docs/integrators.md): at each hit, emission + a local term + mirror
// reflection + refraction, followed recursively to a depth limit. The local
// term is the integrator's own (whitted: lights with shadows; gather: the
// gathered diffuse), the recursion and its weights are common.
//
// Weights at one hit, with R the material's mirror reflectance at this
// angle, T its transparency and tint its transmission tint:
//   fresnel off (the seed's fixed coefficients):
//       reflected R, transmitted T * tint; on total internal reflection
//       the whole of the light is reflected, 1, in place of R (POV-Ray's
//       TraceRefractionRay: the internal reflection is added unfiltered
//       and the finish's own reflection is skipped).
//   fresnel on (an energy-conserving dielectric), F = Fresnel reflectance of
//   the interface (1 on total internal reflection):
//       reflected max(R, T * F), transmitted T * (1 - F) * tint. The max
//       keeps a material that already writes POV's `reflection {0, 1
//       fresnel on}` from reflecting twice.
//   A finish is a sum, as POV-Ray and the seed write it (colour = rho_d C_d
//   + rho_s C_s + rho_r C_r): the reflection is added to the diffuse and
//   ambient terms. With `additive_reflection` false the mirror takes its
//   share from them instead: they are scaled by (1 - R) per channel.
//   Highlights are kept either way: the seed's specular term is the mirror
//   image of the lamps, which have no surface a reflected ray could find.
//   POV's conserve_energy scales the transmitted weight by 1 - R, and its
//   reflection exponent raises the reflected radiance to that power.
#pragma once

#include <algorithm>
#include <optional>

#include "lancer/sampler.h"
#include "lancer/shading/local_shading.h"
#include "lancer/shading/material_blend.h"
#include "lancer/shading/material_layers.h"
#include "lancer/shading/pov_media.h"

namespace lancer {

struct SpecularOptions {
    int max_depth = 5;                 // POV's max_trace_level: the camera ray is level 1
    float min_weight = 1.0f / 255.0f;  // POV's adc_bailout on the path weight
    bool fresnel = false;              // see the header comment
    bool additive_reflection = true;   // POV-Ray's diffuse + reflection; false: see above
};

// How one hit passes light on along its mirror and refracted directions.
struct SpecularSplit {
    Color diffuse_scale{1.0f};  // applied to the diffuse lobe and the ambient term
    Color reflection{0.0f};     // weight of the radiance seen along `reflected`
    Color transmission{0.0f};   // weight of the radiance seen along `refracted`
    Vec3 reflected{0.0f};
    Vec3 refracted{0.0f};
    // irid's tint of what is seen along `reflected`, before the reflection
    // exponent (POV's ComputeReflection tints the reflected ray's colour).
    Color reflected_tint{1.0f};
    bool total_internal_reflection = false;  // the surface transmits, but the ray cannot leave
};

// POV-Ray's mirror direction about a normal { } bent one (Trace::
// ComputeReflection): a ray the bent normal would send behind the
// surface's own normal is reflected about that normal instead, if it went
// in behind the bent one too, or else reflected once more about it. Without
// a bend, the plain mirror direction.
inline Vec3 pov_mirror_direction(const ShadingContext& at) {
    const Vec3 incident = -at.wo;
    Vec3 out = reflect(incident, at.normal);
    Vec3 raw = unbent_normal(at.hit);
    if (glm::dot(raw, at.wo) < 0.0f) raw = -raw;
    const float below = glm::dot(out, raw);
    if (below < 0.0f) {
        if (glm::dot(out, at.normal) < 0.0f)
            out = reflect(incident, raw);
        else
            out -= 2.0f * below * raw;
    }
    return glm::normalize(out);
}

// The mirror direction, and irid's tint along it, where the split reflects.
inline void aim_reflection(const ShadingContext& at, SpecularSplit& split) {
    if (is_black(split.reflection)) return;
    split.reflected = pov_mirror_direction(at);
    if (at.material.has_iridescence())
        split.reflected_tint = at.material.iridescence(at.film_thickness, at.normal, at.wo, split.reflected);
}

// The mirror's weights, not yet aimed.
inline SpecularSplit unaimed_mirror(const ShadingContext& at, const SpecularOptions& options) {
    SpecularSplit split;
    const Color mirror = at.material.mirror_reflectance(at.surface, glm::dot(at.normal, at.wo), fresnel_ior(at));
    if (!options.additive_reflection) split.diffuse_scale = glm::max(Color(1.0f) - mirror, Color(0.0f));
    split.reflection = mirror;
    return split;
}

// The mirror alone: what a layer below the top of a layered texture
// reflects (POV-Ray refracts only through the top layer).
inline SpecularSplit split_mirror(const ShadingContext& at, const SpecularOptions& options) {
    SpecularSplit split = unaimed_mirror(at, options);
    aim_reflection(at, split);
    return split;
}

// `depth`: how far the ray travelled to the hit (for POV's interior fade,
// applied to what leaves through a back face). `layers_passed`: for the top
// layer of a layered texture, what passes all its layers, which is
// refracted in place of this layer's own transmitted colour; null: the
// material alone.
inline SpecularSplit split_specular(const ShadingContext& at, const SpecularOptions& options, float depth = 0.0f,
                                    const Color* layers_passed = nullptr) {
    SpecularSplit split = unaimed_mirror(at, options);
    const Vec3 incident = -at.wo;
    const float cos_i = glm::dot(at.normal, at.wo);
    const Color mirror = split.reflection;

    // POV's filCol: filter * pigment + transmit, unclamped (a negative
    // transmit subtracts what lies behind), traced while its grey passes
    // the bailout.
    const Color transmitted = layers_passed ? *layers_passed : at.material.pov_transmitted(at.surface);
    const float transparency =
        layers_pass_enough(transmitted, options.min_weight) ? std::min(1.0f, std::fabs(pov_grey(transmitted))) : 0.0f;
    if (transparency > 0.0f) {
        const float eta = refraction_eta(at);
        // A bent normal may face away from the ray: POV turns it to face
        // the ray before it refracts (Trace::TraceRefractionRay).
        const Vec3 towards_ray = glm::dot(incident, at.normal) <= 0.0f ? at.normal : -at.normal;
        const bool refracts = refract(incident, towards_ray, eta, split.refracted);
        split.total_internal_reflection = !refracts;
        if (options.fresnel) {
            const float fresnel = refracts ? fresnel_dielectric(cos_i, eta) : 1.0f;
            const float share = layers_passed ? transparency : at.material.transparency(at.surface);
            split.reflection = glm::max(mirror, Color(share * fresnel));
            if (refracts) split.transmission = (1.0f - fresnel) * transmitted;
        } else if (refracts) {
            split.transmission = transmitted;
        } else {
            split.reflection = Color(1.0f);  // total internal reflection, as POV-Ray
        }
        // POV's conserve_energy: what the finish reflects is not transmitted
        // (each layer's is in layers_passed already).
        if (at.material.parameters().conserve_energy && !layers_passed)
            split.transmission *= glm::clamp(Color(1.0f) - mirror, Color(0.0f), Color(1.0f));
        // POV's interior fade: light that crossed the inside to leave here
        // (or to be totally reflected back in) is dimmed by the distance.
        if (!at.entering) {
            const Color fade = at.material.interior_attenuation(depth);
            split.transmission *= fade;
            if (!refracts && !options.fresnel) split.reflection *= fade;
        }
    }
    aim_reflection(at, split);
    return split;
}

// Radiance along `ray` at recursion `level` (1 for a camera ray) with path
// weight `weight`, inside the objects `inside` (media, pov_media.h). `local_term(at, diffuse_scale, sampler)` returns
// the hit's diffuse (ambient included) and glossy radiance; it may skip the diffuse work when diffuse_scale is black. A
// ray past max_depth or under min_weight is not traced and counts black, as in POV-Ray.
template <class LocalTerm>
Color trace_specular(const Ray& ray, const RenderScene& scene, Sampler& sampler, const SpecularOptions& options,
                     const LocalTerm& local_term, int level, float weight, const InteriorStack& inside);

// Follows `direction` from `hit` with `path_weight` (black: not at all):
// the radiance seen there, tinted by `seen_tint`, raised to `exponent`
// (POV's reflection exponent) and weighted.
template <class LocalTerm>
Color follow_specular(const Ray& from, const Hit& hit, const Color& path_weight, const Vec3& direction, float exponent,
                      bool transmitted, const RenderScene& scene, Sampler& sampler, const SpecularOptions& options,
                      const LocalTerm& local_term, int level, float weight, const InteriorStack& inside,
                      const Color& seen_tint = Color(1.0f)) {
    if (is_black(path_weight)) return Color(0.0f);
    // POV's w1: the largest channel's magnitude (a weight may be negative).
    const float next_weight = weight * max_component(glm::abs(path_weight));
    if (level + 1 > options.max_depth || next_weight < options.min_weight) return Color(0.0f);
    Ray next = hit.spawn_ray(direction);
    // POV: a refracted ray is what its parent was; a mirror ray is a reflection.
    next.seen_as = transmitted ? from.seen_as : RaySight::Reflection;
    Color seen = trace_specular(next, scene, sampler, options, local_term, level + 1, next_weight,
                                transmitted ? inside.crossed(hit) : inside) *
                 seen_tint;
    if (exponent != 1.0f) seen = glm::pow(glm::max(seen, Color(0.0f)), Color(exponent));
    return path_weight * seen;
}

// A layered texture's layers as one ray sees them, top first: each layer's
// hit and shading context made once, though the layers are visited twice
// (what passes them all, then each one's light), since each is a pigment
// lookup (often noise with turbulence) and a normal's bend. Layers past
// the first kKept are made again each time they are asked for.
class LayerViews {
  public:
    static constexpr std::size_t kKept = 4;

    LayerViews(const Hit& hit, const MaterialLayers& layers, const Ray& ray, const InteriorStack& inside)
        : m_hit(hit), m_layers(layers), m_ray(ray), m_inside(inside) {}
    LayerViews(const LayerViews&) = delete;
    LayerViews& operator=(const LayerViews&) = delete;

    // Layer k's context (its hit: at(k).hit), valid until the next call
    // for a layer past kKept.
    const ShadingContext& at(std::size_t k) {
        const std::size_t slot = std::min(k, kKept);
        if (slot == kKept || !m_at[slot]) {
            m_hits[slot] = entry_hit(m_hit, m_layers.top_first[k]);
            m_at[slot].emplace(make_shading_context(m_hits[slot], m_ray));
            in_interiors(*m_at[slot], m_inside);
        }
        return *m_at[slot];
    }

  private:
    const Hit& m_hit;
    const MaterialLayers& m_layers;
    const Ray& m_ray;
    const InteriorStack& m_inside;
    Hit m_hits[kKept + 1];
    std::optional<ShadingContext> m_at[kKept + 1];
};

// A layered texture's hit (lancer/shading/material_layers.h): each layer's
// own light dimmed by the layers above, each layer's mirror undimmed, and
// what passes every layer refracted through the top layer. On total
// internal reflection the layers whose normal is the top's reflect
// nothing more (the internal reflection is their mirror), as in POV-Ray.
template <class LocalTerm>
Color layered_surface_radiance(const Ray& ray, const Hit& hit, const MaterialLayers& layers, const RenderScene& scene,
                               Sampler& sampler, const SpecularOptions& options, const LocalTerm& local_term, int level,
                               float weight, const InteriorStack& inside) {
    LayerViews views(hit, layers, ray, inside);
    // What passes every layer the light reaches.
    Color passed(1.0f);
    std::size_t reached = 0;
    for (; reached < layers.top_first.size(); ++reached) {
        if (!layers_pass_enough(passed, options.min_weight)) break;
        passed *= layer_passes(views.at(reached));
    }
    const ShadingContext& top_at = views.at(0);
    const SpecularSplit top_split = split_specular(top_at, options, hit.t * glm::length(ray.direction), &passed);
    const Vec3 top_normal = top_at.hit.shading_normal;

    Color radiance(0.0f), above(1.0f);
    for (std::size_t k = 0; k < reached; ++k) {
        const ShadingContext& at = views.at(k);
        const SpecularSplit split = k == 0 ? top_split : split_mirror(at, options);
        const LobeRadiance local = local_term(at, split.diffuse_scale, sampler);
        radiance += above * (surface_emission(at) + split.diffuse_scale * local.diffuse + local.glossy);
        const bool reflects = k == 0 || !top_split.total_internal_reflection || at.hit.shading_normal != top_normal;
        // POV weighs a layer's reflected ray by the light reaching the layer.
        const float reaching = std::min(1.0f, std::fabs(pov_grey(above)));
        if (reflects)
            radiance += follow_specular(ray, at.hit, split.reflection, split.reflected,
                                        at.material.parameters().reflection_exponent, false, scene, sampler, options,
                                        local_term, level, weight * reaching, inside, split.reflected_tint);
        above *= layer_passes(at);
    }
    radiance += follow_specular(ray, views.at(0).hit, top_split.transmission, top_split.refracted, 1.0f, true, scene,
                                sampler, options, local_term, level, weight, inside);
    return radiance;
}

// The light leaving one material's hit towards the ray: emission, the local
// term, and what it reflects and refracts.
template <class LocalTerm>
Color specular_surface_radiance(const Ray& ray, const Hit& hit, const RenderScene& scene, Sampler& sampler,
                                const SpecularOptions& options, const LocalTerm& local_term, int level, float weight,
                                const InteriorStack& inside) {
    if (const MaterialLayers* layers = layers_to_light(hit))
        return layered_surface_radiance(ray, hit, *layers, scene, sampler, options, local_term, level, weight, inside);
    ShadingContext at = make_shading_context(hit, ray);
    in_interiors(at, inside);
    const SpecularSplit split = split_specular(at, options, hit.t * glm::length(ray.direction));

    const LobeRadiance local = local_term(at, split.diffuse_scale, sampler);
    Color radiance = surface_emission(at) + split.diffuse_scale * local.diffuse + local.glossy;

    radiance +=
        follow_specular(ray, hit, split.reflection, split.reflected, at.material.parameters().reflection_exponent,
                        false, scene, sampler, options, local_term, level, weight, inside, split.reflected_tint);
    radiance += follow_specular(ray, hit, split.transmission, split.refracted, 1.0f, true, scene, sampler, options,
                                local_term, level, weight, inside);
    return radiance;
}

// trace_specular() for a ray whose nearest hit is known (null: it escaped),
// such as a camera ray the host traced.
template <class LocalTerm>
Color shade_specular(const Ray& ray, const Hit* found, const RenderScene& scene, Sampler& sampler,
                     const SpecularOptions& options, const LocalTerm& local_term, int level, float weight,
                     const InteriorStack& inside) {
    if (found == nullptr)
        return seen_through_media(scene, ray, nullptr, scene.background(ray), MediaLighting{&sampler}, inside);
    // Between two texture_map entries each is lit and followed with its
    // own finish; as in POV-Ray, the blend does not lower the weight that
    // adc_bailout compares.
    const Color radiance = shade_blended(*found, [&](const Hit& hit) {
        return specular_surface_radiance(ray, hit, scene, sampler, options, local_term, level, weight, inside);
    });
    return seen_through_media(scene, ray, found, radiance, MediaLighting{&sampler}, inside);
}

template <class LocalTerm>
Color trace_specular(const Ray& ray, const RenderScene& scene, Sampler& sampler, const SpecularOptions& options,
                     const LocalTerm& local_term, int level, float weight, const InteriorStack& inside) {
    Hit hit;
    const bool found = scene.intersect(ray, hit);
    return shade_specular(ray, found ? &hit : nullptr, scene, sampler, options, local_term, level, weight, inside);
}

}  // namespace lancer
