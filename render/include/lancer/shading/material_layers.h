// POV-Ray's layered textures (texture { A } texture { B }), lit as POV-Ray
// lights them (its Trace::ComputeLightedTexture, read for the rules): each
// layer, top first, with its own pigment, finish and normal; what a layer
// shows of its own light (ambient, emission, diffuse, highlights) is dimmed
// by the filter and transmit of the layers above it (each passes
// filter * pigment + transmit, less what a conserve_energy layer reflects),
// while each layer's mirror reflection is added undimmed; the layers are
// visited while the light passing them stays above adc_bailout, and what
// passes all of them is refracted through the top layer's normal
// (lancer/shading/specular_tracing.h). A shadow ray is dimmed by every
// layer (lancer/shading/shadow_rays.h).
#pragma once

#include "lancer/shading/local_shading.h"
#include "lancer/shading/material_blend.h"

namespace lancer {

// What passes one layer towards the layers below (POV's filCol factor).
inline Color layer_passes(const ShadingContext& at) {
    Color passed = at.material.pov_transmitted(at.surface);
    if (at.material.parameters().conserve_energy) {
        const Color mirror = at.material.mirror_reflectance(at.surface, glm::dot(at.normal, at.wo), fresnel_ior(at));
        passed *= glm::clamp(Color(1.0f) - mirror, Color(0.0f), Color(1.0f));
    }
    return passed;
}

// The light of a hit whose own light (no mirror, no refraction) is
// own_light(at), `at` its shading context along the ray: summed over a
// layered texture's layers, each dimmed by the layers above it. Each
// layer's context (a pigment lookup) is made once.
template <class OwnLight>
Color shade_layers(const Hit& hit, const Ray& ray, float bailout, const OwnLight& own_light) {
    const MaterialLayers* layers = layers_to_light(hit);
    if (layers == nullptr) return own_light(make_shading_context(hit, ray));
    Color radiance(0.0f), passed(1.0f);
    for (const Material* layer : layers->top_first) {
        if (!layers_pass_enough(passed, bailout)) break;
        const Hit seen = entry_hit(hit, layer);
        const ShadingContext at = make_shading_context(seen, ray);
        radiance += passed * own_light(at);
        passed *= layer_passes(at);
    }
    return radiance;
}

// A hit's own light (no mirror, no refraction) as POV-Ray shows it, for
// integrators that light a hit by own_light(at) alone: blended between
// two texture_map entries, summed over a layered texture's layers.
template <class OwnLight>
Color shade_own_light(const Hit& hit, const Ray& ray, const RenderScene& scene, const OwnLight& own_light) {
    const float bailout = scene.options().adc_bailout;
    return shade_blended(hit, [&](const Hit& entry) { return shade_layers(entry, ray, bailout, own_light); });
}

}  // namespace lancer
