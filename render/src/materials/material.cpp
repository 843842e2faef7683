// The shared material model documented in lancer/material.h.
#include "lancer/material.h"

#include <cmath>

#include "lancer/texture.h"
#include "materials/noise.h"

namespace lancer {
namespace {

constexpr float kInvPi = 1.0f / kPi;

// POV-Ray's empirical Fresnel-like curve for `metallic` (texture.cpp), x is
// the angle from the normal over pi/2.
float metallic_curve(float cos_angle) {
    const float x = std::acos(glm::clamp(cos_angle, -1.0f, 1.0f)) / (0.5f * kPi);
    const float f = 0.014567225f / ((x - 1.12f) * (x - 1.12f)) - 0.011612903f;
    return glm::clamp(f, 0.0f, 1.0f);
}

// Blinn exponent k = 1/roughness; roughness 0 means an arbitrarily sharp lobe.
float blinn_exponent(float roughness) {
    return 1.0f / glm::max(roughness, 1e-4f);
}

}  // namespace

Color Material::transmission_tint(const SurfaceSample& surface) const {
    const float total = surface.filter + surface.transmit;
    if (!(total > 0.0f)) return Color(0.0f);
    return (surface.filter * surface.pigment + Color(surface.transmit)) / total;
}

// With wo = N, N.H = cos(theta_i / 2); substituting x = cos(theta_i / 2)
// turns (1/pi) * 2 pi * int x^k sin(theta) dtheta into 8 * int_{1/sqrt 2}^{1}
// x^(k+1) dx: POV's own rescaling for `specular albedo` (parstxtr.cpp).
float specular_albedo(float exponent) {
    const double k = exponent;
    return float(8.0 * (1.0 - std::pow(2.0, -(k + 2.0) / 2.0)) / (k + 2.0));
}

Material::Material(const MaterialParameters& parameters)
    : m_params(parameters), m_specular_albedo(specular_albedo(blinn_exponent(parameters.roughness))) {
    if (const TextureSample* constant = parameters.pigment ? parameters.pigment->constant() : nullptr) {
        m_constant_pigment = SurfaceSample{constant->rgb, constant->filter, constant->transmit};
        m_pigment_is_constant = true;
    }
}

float Material::film_thickness(const Vec3& position) const {
    if (m_params.irid_turbulence == 0.0f) return m_params.irid_thickness;
    // POV's: turbulence of 5 octaves (omega 0.5, lambda 2) at the hit, from
    // [0, 1] to 1 +- irid_turbulence times the thickness.
    const int generator = glm::clamp(m_params.noise_generator, 1, 3);
    const double noise = pov_turbulence(glm::dvec3(position), 0.5, 2.0, 5, NoiseGenerator(generator));
    return m_params.irid_thickness * float(1.0 + (2.0 * noise - 1.0) * m_params.irid_turbulence);
}

Color Material::glossy_brdf(const SurfaceSample& surface, const Vec3& n, const Vec3& wo, const Vec3& wi) const {
    const float cos_i = glm::dot(n, wi);
    if (!(cos_i > 0.0f) || !has_glossy()) return Color(0.0f);
    // POV's highlight terms, each a fraction of the light's colour.
    float highlight = 0.0f;
    if (m_params.phong > 0.0f) {
        // Phong: around the mirror direction of wo.
        const Vec3 mirror = reflect(-wo, n);
        const float c = glm::dot(mirror, wi);
        if (c > 0.0f) highlight += m_params.phong * std::pow(c, m_params.phong_size);
    }
    if (m_params.specular > 0.0f) {
        // Blinn: about the half vector.
        const Vec3 half_sum = wo + wi;
        const float length = glm::length(half_sum);
        if (length > 0.0f) {
            const float c = glm::dot(n, half_sum / length);
            if (c > 0.0f) highlight += m_params.specular * std::pow(c, blinn_exponent(m_params.roughness));
        }
    }
    if (!(highlight > 0.0f)) return Color(0.0f);
    // Unlike the diffuse term, POV-Ray's highlights are not scaled by the
    // surface's opacity (ComputeOneDiffuseLight): clear glass shows them.
    Color tint(1.0f);
    if (m_params.metallic > 0.0f) {
        // POV's metallic highlight: tinted towards the pigment away from grazing.
        const float f = metallic_curve(cos_i);
        tint = Color(1.0f) + m_params.metallic * (1.0f - f) * (surface.pigment - Color(1.0f));
    }
    // Light of colour C arrives as radiance pi*C over |cos|: the BRDF that
    // gives highlight * C. The floor on the cosine only keeps the quotient
    // finite; times the cosine it is below highlight / pi.
    return highlight / (kPi * glm::max(cos_i, 1e-20f)) * tint;
}

Color Material::brdf(const SurfaceSample& surface, const Vec3& n, const Vec3& wo, const Vec3& wi) const {
    return diffuse_brdf(surface, n, wo, wi) + glossy_brdf(surface, n, wo, wi);
}

Color Material::mirror_reflectance(const SurfaceSample& surface, float cos_i, float relative_ior) const {
    if (!has_mirror()) return Color(0.0f);
    cos_i = glm::clamp(cos_i, 0.0f, 1.0f);
    const Color& r_min = m_params.reflection_min;
    const Color& r_max = m_params.reflection_max;
    if (m_params.reflection_fresnel) {
        // POV's Fresnel (ComputeReflectivity) with the relative index.
        const float n = relative_ior;
        const float radicand = n * n + cos_i * cos_i - 1.0f;
        if (!(radicand > 0.0f)) return r_max;
        const float g = std::sqrt(radicand);
        const float a = (g - cos_i) / (g + cos_i);
        const float b = (cos_i * (g + cos_i) - 1.0f) / (cos_i * (g - cos_i) + 1.0f);
        const float fresnel = glm::clamp(0.5f * a * a * (1.0f + b * b), 0.0f, 1.0f);
        return metallic_reflection(surface, cos_i, fresnel * r_max + (1.0f - fresnel) * r_min);
    }
    // A plain `reflection R` has no range to fall off over (and POV's
    // default falloff, 1, needs no pow): every mirror hit asks.
    if (r_min == r_max) return metallic_reflection(surface, cos_i, r_max);
    const float falloff = m_params.reflection_falloff;
    const float w = falloff == 1.0f ? 1.0f - cos_i : std::pow(1.0f - cos_i, falloff);
    return metallic_reflection(surface, cos_i, w * r_max + (1.0f - w) * r_min);
}

Color Material::metallic_reflection(const SurfaceSample& surface, float cos_i, const Color& reflectance) const {
    if (m_params.reflection_metallic == 0.0f) return reflectance;
    // POV's ComputeMetallic: the same curve as the highlights'.
    const float f = metallic_curve(cos_i);
    return reflectance * (Color(1.0f) + m_params.reflection_metallic * (1.0f - f) * (surface.pigment - Color(1.0f)));
}

bool Material::has_mirror() const {
    return max_component(m_params.reflection_max) > 0.0f || max_component(m_params.reflection_min) > 0.0f;
}

bool refract(const Vec3& d, const Vec3& n, float eta, Vec3& transmitted) {
    const float cos_i = -glm::dot(d, n);
    const float sin2_t = eta * eta * glm::max(0.0f, 1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) return false;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    transmitted = glm::normalize(eta * d + (eta * cos_i - cos_t) * n);
    return true;
}

float fresnel_dielectric(float cos_i, float eta) {
    // eta = n_incident / n_transmitted; cos_i measured on the incident side.
    cos_i = glm::clamp(std::fabs(cos_i), 0.0f, 1.0f);
    const float sin2_t = eta * eta * (1.0f - cos_i * cos_i);
    if (sin2_t >= 1.0f) return 1.0f;
    const float cos_t = std::sqrt(1.0f - sin2_t);
    const float r_parallel = (cos_i - eta * cos_t) / (cos_i + eta * cos_t);
    const float r_perpendicular = (eta * cos_i - cos_t) / (eta * cos_i + cos_t);
    return 0.5f * (r_parallel * r_parallel + r_perpendicular * r_perpendicular);
}

}  // namespace lancer
