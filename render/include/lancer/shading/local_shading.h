// The seed's simple local lighting model, shared by the shadow, whitted and
// gather integrators (docs/integrators.md): at one surface hit, the light
// reflected from every light of the simple model (POV's point, spot,
// parallel and area lights, and the point proxy of every physical lamp and
// emitter), the
// surface's emission and POV's ambient term, with or without shadow rays.
// Header-only: the plugins inline it, liblancer's ABI is untouched.
#pragma once

#include <cmath>
#include <cstring>
#include <vector>

#include "lancer/render_scene.h"
#include "lancer/shading/point_hash.h"
#include "lancer/shading/shadow_rays.h"

namespace lancer {

// One surface hit as seen along one ray, with the pigment looked up once.
struct ShadingContext {
    const Hit& hit;
    const Material& material;
    SurfaceSample surface;
    Vec3 wo;                      // unit, from the hit towards where the ray came from
    Vec3 normal;                  // unit shading normal on the side of wo (surfaces are two-sided)
    bool entering;                // the ray arrives on the front face (from outside a closed object)
    float film_thickness = 0.0f;  // irid's, at this hit
    // The objects the ray is in, which decide the indices across the
    // surface and which its shadow rays start in; null: judged by the face
    // (outside is ior 1). Set by in_interiors().
    const InteriorStack* inside = nullptr;
};

inline ShadingContext make_shading_context(const Hit& hit, const Ray& ray) {
    const Vec3 wo = -glm::normalize(ray.direction);
    ShadingContext at{hit, *hit.material,         hit.material->sample_surface(hit),
                      wo,  hit.facing_normal(wo), hit.is_front_face(wo)};
    if (at.material.has_iridescence()) at.film_thickness = at.material.film_thickness(hit.position);
    return at;
}

// POV-Ray's indices across the surface, read from the objects the ray is
// in (InteriorStack) rather than from the face it meets: a ray in water
// that enters a glass holding it bends by 1.5/1.33, not by 1.5.
inline ShadingContext& in_interiors(ShadingContext& at, const InteriorStack& inside) {
    at.inside = &inside;
    return at;
}

// n1/n2 for the ray refracted at `at`.
inline float refraction_eta(const ShadingContext& at) {
    const float ior = glm::max(at.material.parameters().ior, 1e-6f);
    if (at.inside) return at.inside->refraction_eta(at.hit, ior);
    return at.entering ? 1.0f / ior : ior;
}

// n2/n1 for POV's Fresnel reflection at `at`.
inline float fresnel_ior(const ShadingContext& at) {
    const float ior = glm::max(at.material.parameters().ior, 1e-6f);
    if (at.inside) return at.inside->fresnel_ior(at.hit, ior);
    return at.entering ? ior : 1.0f / ior;
}

// Reflected radiance split by lobe, so an integrator can weight or replace
// one lobe (whitted takes diffuse away from mirrors, gather replaces it).
struct LobeRadiance {
    Color diffuse{0.0f};
    Color glossy{0.0f};

    Color total() const { return diffuse + glossy; }
    bool is_black() const { return lancer::is_black(diffuse) && lancer::is_black(glossy); }
    LobeRadiance& operator+=(const LobeRadiance& other) {
        diffuse += other.diffuse;
        glossy += other.glossy;
        return *this;
    }
    LobeRadiance& operator*=(const Color& weight) {
        diffuse *= weight;
        glossy *= weight;
        return *this;
    }
};

inline bool is_finite(const Color& c) {
    return std::isfinite(c.r) && std::isfinite(c.g) && std::isfinite(c.b);
}

// Radiance the surface reflects towards wo from one light sample, without
// occlusion: brdf * |cos| * radiance / pdf. Black for an empty sample and
// for a degenerate one (a proxy lying on the shading point itself gives
// 0/0), so a lamp's own surface never turns NaN.
inline LobeRadiance reflect_light_sample(const ShadingContext& at, const LightSample& sample) {
    if (!(sample.pdf > 0.0f) || lancer::is_black(sample.radiance)) return {};
    // Delta lights have pdf 1: dividing by it is exact, and skipping the
    // division takes it off the critical path of direct lighting.
    const float cosine = std::abs(glm::dot(at.normal, sample.wi));
    const Color incident = sample.radiance * (sample.pdf == 1.0f ? cosine : cosine / sample.pdf);
    LobeRadiance reflected;
    if (const float facing = glm::dot(at.normal, sample.wi); facing > 0.0f) {
        reflected.diffuse = at.material.diffuse_brdf(at.surface, at.normal, at.wo, sample.wi) * incident;
        if (at.material.has_glossy())
            reflected.glossy = at.material.glossy_brdf(at.surface, at.normal, at.wo, sample.wi) * incident;
    } else if (at.hit.double_illuminate) {
        // POV's double_illuminate: the front's diffuse, by |cos|, as if the
        // light were mirrored in front. POV's highlights from behind need a
        // half vector or mirror direction within a right angle of a light
        // below the surface: left out.
        const Vec3 mirrored = sample.wi - 2.0f * facing * at.normal;
        reflected.diffuse = at.material.diffuse_brdf(at.surface, at.normal, at.wo, mirrored) * incident;
    } else {
        // POV lights a surface from behind only through diffuse backside.
        reflected.diffuse = at.material.backside_diffuse_brdf(at.surface, at.normal, sample.wi) * incident;
    }
    if (const float crand = at.material.parameters().crand; crand > 0.0f) {
        // POV's crand takes a random share of crand * pigment * light from
        // each light's diffuse: a grain, here a hash of point and light.
        std::uint32_t direction;
        std::memcpy(&direction, &sample.wi.x, sizeof direction);
        const float grain = float(point_hash(at.hit.position, direction));
        reflected.diffuse -= (crand * grain / (kPi * sample.pdf)) * at.surface.pigment * sample.radiance;
    }
    if (at.material.has_iridescence())
        reflected *= at.material.iridescence(at.film_thickness, at.normal, at.wo, sample.wi);
    if (!is_finite(reflected.diffuse) || !is_finite(reflected.glossy)) return {};
    return reflected;
}

enum class Shadows {
    None,  // every light reaches every surface facing it (raycast, gather's secondary hits)
    Hard,  // one shadow ray per light towards its (proxy) position
};

// The light that stands in for `light` in the simple model: itself for point
// and directional lights, its proxy for area lights and emitters.
inline const Light& simple_model_light(const Light& light) {
    return light.is_delta() ? light : light.proxy();
}

enum class Lobes {
    All,
    GlossyOnly,  // the caller accounts for the diffuse light otherwise (gather)
};

// POV's area light: lit from its centre (or, with area_illumination, from
// each grid point in turn, freshly jittered), in shadow by POV's grid.
inline LobeRadiance reflect_pov_area_light(const RenderScene& scene, const ShadingContext& at, const Light& light,
                                           const PovAreaLightParameters& area, const LightSample& centre,
                                           Shadows shadows, Lobes lobes) {
    LobeRadiance reflected;
    Color colour = centre.radiance * (1.0f / kPi);  // POV's units, for the adaptive threshold
    if (area.area_illumination) {
        colour = area.center.intensity * (1.0f / kPi);
        const float weight = 1.0f / float(area.size1 * area.size2);
        for (int i = 0; i < area.size1; ++i)
            for (int j = 0; j < area.size2; ++j) {
                Vec2 u(0.5f);
                if (area.size1 > 1) u.x = float(i) / float(area.size1 - 1);
                if (area.size2 > 1) u.y = float(j) / float(area.size2 - 1);
                reflected += reflect_light_sample(at, light.sample(at.hit.position, u));
            }
        reflected *= Color(weight);
    } else {
        reflected = reflect_light_sample(at, centre);
    }
    if (lobes == Lobes::GlossyOnly) reflected.diffuse = Color(0.0f);
    if (!light.casts_shadows()) reflected.glossy = Color(0.0f);  // see reflect_simple_light
    if (shadows == Shadows::Hard && light.casts_shadows() && !reflected.is_black())
        reflected *= PovAreaShadow(scene, at.hit, light, area, centre.wi, colour, at.inside).visibility();
    return reflected;
}

// Reflected light from one light of the simple model (see simple_model_light).
// No shadow ray is cast for light the requested lobes do not reflect.
inline LobeRadiance reflect_simple_light(const RenderScene& scene, const ShadingContext& at, const Light& light,
                                         Shadows shadows, Lobes lobes = Lobes::All) {
    if (!light_reaches(light, at.hit)) return {};  // POV's light_group
    const Light& stand_in = simple_model_light(light);
    // Point and directional lights ignore u: one sample is exact.
    const LightSample sample = stand_in.sample(at.hit.position, Vec2(0.5f));
    if (const auto* area = stand_in.parameters<PovAreaLightParameters>())
        return reflect_pov_area_light(scene, at, stand_in, *area, sample, shadows, lobes);
    LobeRadiance reflected = reflect_light_sample(at, sample);
    if (lobes == Lobes::GlossyOnly) reflected.diffuse = Color(0.0f);
    // POV-Ray's shadowless light is a fill light: it makes no highlights
    // (no phong, no specular).
    if (!light.casts_shadows()) reflected.glossy = Color(0.0f);
    if (shadows == Shadows::Hard && light.casts_shadows() && !reflected.is_black())
        reflected *= transmittance_to(scene, at.hit, sample.point, &light, at.inside);
    return reflected;
}

// Direct light from every light of the simple model. Iterates scene.lights()
// and takes each one's stand-in, which is exactly scene.local_lights() but
// keeps the identity of the area light a proxy stands for (for shadows).
inline LobeRadiance simple_direct_light(const RenderScene& scene, const std::vector<const Light*>& lights,
                                        const ShadingContext& at, Shadows shadows) {
    LobeRadiance total;
    for (const Light* light : lights) total += reflect_simple_light(scene, at, *light, shadows);
    return total;
}
inline LobeRadiance simple_direct_light(const RenderScene& scene, const ShadingContext& at, Shadows shadows) {
    return simple_direct_light(scene, scene.lights(), at, shadows);
}

// Radiance the surface emits towards wo: the light's own emission when the
// hit lies on an area light or emitter, else the material's; scaled by the
// surface's opacity as POV-Ray scales a finish's emission (a filtering or
// transmitting surface shows that much less of its own light).
inline Color surface_emission(const ShadingContext& at) {
    const Color emitted =
        at.hit.emitter != nullptr ? at.hit.emitter->emitted(at.hit, at.wo) : at.material.emitted(at.surface);
    return at.material.opacity(at.surface) * emitted;
}

// POV's ambient term, scaled by the surface's opacity as POV-Ray does: the
// light of a transparent surface is what passes through it, so a fully
// transmitting object shows no ambient (nor diffuse, nor highlights).
inline Color opaque_ambient(const Color& ambient_light, const ShadingContext& at) {
    const float opacity = at.material.opacity(at.surface);
    return opacity * at.material.ambient(at.surface, ambient_light);
}
inline Color opaque_ambient(const RenderScene& scene, const ShadingContext& at) {
    return opaque_ambient(scene.options().ambient_light, at);
}

}  // namespace lancer
