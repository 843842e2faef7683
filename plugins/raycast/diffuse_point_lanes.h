// The seed's simple local model (local_shading.h) without shadows, for many
// hits at once, in its most common case: a surface of one colour with
// POV's default finish (diffuse, ambient, no highlight, brilliance 1) lit
// by point lights without fade. Computed lane by lane (structure of
// arrays) so the compiler evaluates several hits per instruction: one hit's
// shading is a long chain of square roots and divisions, and lanes side by
// side hide its latency. Every lane's result is, bit for bit, what
// make_shading_context, surface_emission, opaque_ambient and
// simple_direct_light(..., Shadows::None) give for it: the same operations
// in the same order. Header-only: plugins inline it.
#pragma once

#include <cmath>
#include <cstdint>
#include <vector>

#include "lancer/shading/local_shading.h"

namespace lancer {

class DiffusePointLanes {
  public:
    static constexpr int kLanes = 16;
    static constexpr int kMaxLights = 8;

    DiffusePointLanes(const std::vector<const Light*>& lights, const Color& ambient_light, bool with_ambient)
        : m_ambient_light(ambient_light), m_with_ambient(with_ambient) {
        m_usable = lights.size() <= std::size_t(kMaxLights);
        for (std::size_t i = 0; m_usable && i < lights.size(); ++i) {
            const auto* point = lights[i]->parameters<PointLightParameters>();
            // A light_group's light reaches only its group: the general path.
            m_usable = point != nullptr && point->is_plain() && lights[i]->light_group() < 0;
            if (!m_usable) break;
            m_position[i] = point->position;
            m_intensity[i] = point->intensity;
            m_falloff[i] = point->falloff;
            ++m_lights;
        }
    }

    // False when a light of the scene is not a plain point light: then no
    // hit takes this path.
    bool usable() const { return m_usable; }

    // Whether `hit` is of the kind this path shades.
    static bool covers(const Hit& hit) {
        const Material& material = *hit.material;
        return hit.emitter == nullptr && hit.mix == nullptr && material.layers() == nullptr &&
               hit.lit_by_global_lights && !hit.double_illuminate && material.pigment_is_constant() &&
               !material.has_glossy() && material.parameters().brilliance == 1.0f &&
               material.parameters().diffuse_back == 0.0f && material.parameters().crand == 0.0f &&
               !material.has_iridescence();
    }

    // Radiance towards rays[k] from hits[k] (covered hits), k < count <=
    // kLanes, into out[k]. shaded[k] is false for a lane whose distance to
    // a light leaves the float range where the light samples in float: the
    // caller shades it the general way.
    void shade(const Ray* const* rays, const Hit* const* hits, int count, Color* out, bool* shaded) const {
        float px[kLanes], py[kLanes], pz[kLanes];        // hit point
        float nx[kLanes], ny[kLanes], nz[kLanes];        // shading normal, facing wo
        float red[kLanes], green[kLanes], blue[kLanes];  // pigment
        float opacity[kLanes], diffuse[kLanes];
        float sum_r[kLanes], sum_g[kLanes], sum_b[kLanes];  // emission + ambient
        for (int k = 0; k < count; ++k) {
            const Hit& hit = *hits[k];
            const Material& material = *hit.material;
            const MaterialParameters& parameters = material.parameters();
            const Vec3 wo = -glm::normalize(rays[k]->direction);
            const Vec3 normal = hit.facing_normal(wo);
            const SurfaceSample surface = material.sample_surface(hit);
            px[k] = hit.position.x, py[k] = hit.position.y, pz[k] = hit.position.z;
            nx[k] = normal.x, ny[k] = normal.y, nz[k] = normal.z;
            red[k] = surface.pigment.r, green[k] = surface.pigment.g, blue[k] = surface.pigment.b;
            opacity[k] = material.opacity(surface);
            diffuse[k] = parameters.diffuse;
            Color sum = opacity[k] * material.emitted(surface);  // POV scales emission by opacity
            if (m_with_ambient) sum += opacity[k] * material.ambient(surface, m_ambient_light);
            sum_r[k] = sum.r, sum_g[k] = sum.g, sum_b[k] = sum.b;
        }
        float lit_r[kLanes] = {}, lit_g[kLanes] = {}, lit_b[kLanes] = {};
        // As wide as a float, so the loop below vectorises.
        std::int32_t in_range[kLanes];
        for (int k = 0; k < count; ++k) in_range[k] = 1;
        for (int light = 0; light < m_lights; ++light) {
            const Vec3 at = m_position[light];
            const Color intensity = m_intensity[light];
            const PointFalloff falloff_kind = m_falloff[light];
            for (int k = 0; k < count; ++k) {
                // PointLight::sample's float path.
                const float tx = at.x - px[k], ty = at.y - py[k], tz = at.z - pz[k];
                const float distance_squared = (tx * tx + ty * ty) + tz * tz;
                in_range[k] &= in_plain_point_range(distance_squared);
                const PointIncidence incidence = plain_point_incidence(distance_squared, falloff_kind);
                const float inverse_distance = incidence.inverse_distance;
                const float falloff = incidence.falloff;
                const float radiance_r = intensity.r * falloff, radiance_g = intensity.g * falloff,
                            radiance_b = intensity.b * falloff;
                const float wx = tx * inverse_distance, wy = ty * inverse_distance, wz = tz * inverse_distance;
                // reflect_light_sample with Material::diffuse_brdf.
                const float cos_i = (nx[k] * wx + ny[k] * wy) + nz[k] * wz;
                const float cosine = std::fabs(cos_i);
                const float incident_r = radiance_r * cosine, incident_g = radiance_g * cosine,
                            incident_b = radiance_b * cosine;
                const float shape = diffuse_lobe_weight(diffuse[k], opacity[k], 1.0f);
                const bool lit = cos_i > 0.0f && diffuse[k] != 0.0f;
                const float reflected_r = (lit ? shape * red[k] : 0.0f) * incident_r;
                const float reflected_g = (lit ? shape * green[k] : 0.0f) * incident_g;
                const float reflected_b = (lit ? shape * blue[k] : 0.0f) * incident_b;
                const bool black = radiance_r == 0.0f && radiance_g == 0.0f && radiance_b == 0.0f;
                const bool finite =
                    std::isfinite(reflected_r) && std::isfinite(reflected_g) && std::isfinite(reflected_b);
                const bool counts = !black && finite;
                lit_r[k] += counts ? reflected_r : 0.0f;
                lit_g[k] += counts ? reflected_g : 0.0f;
                lit_b[k] += counts ? reflected_b : 0.0f;
            }
        }
        for (int k = 0; k < count; ++k) {
            // LobeRadiance::total(): the glossy lobe's sum is +0.
            out[k] = Color(sum_r[k] + (lit_r[k] + 0.0f), sum_g[k] + (lit_g[k] + 0.0f), sum_b[k] + (lit_b[k] + 0.0f));
            shaded[k] = in_range[k] != 0;
        }
    }

  private:
    Vec3 m_position[kMaxLights];
    Color m_intensity[kMaxLights];
    PointFalloff m_falloff[kMaxLights];
    int m_lights = 0;
    Color m_ambient_light;
    bool m_with_ambient;
    bool m_usable = false;
};

}  // namespace lancer
