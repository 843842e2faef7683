// Importance sampling of the shared material model (material.h): warps from
// [0,1)^2 to directions with their densities, the individual lobe samplers,
// and Bsdf, which samples a whole material at one hit the way the path
// tracer needs it. Bsdf evaluates through Material::brdf, so sampling can
// never disagree with what the other integrators shade; only the densities
// live here.
//
// Densities are per unit solid angle (sr^-1) unless a name says otherwise.
// Every direction is unit length. A sampler that can fail (a lobe direction
// falling below the surface) reports it and the caller treats the sample as
// carrying zero weight; the densities stay normalised over the whole sphere,
// so failures cost variance, never bias.
#pragma once

#include <optional>

#include "lancer/material.h"

namespace lancer {

// An orthonormal basis with `n` as its z axis; local (x, y, z) = (s, t, n).
struct Frame {
    Vec3 s{1.0f, 0.0f, 0.0f};
    Vec3 t{0.0f, 1.0f, 0.0f};
    Vec3 n{0.0f, 0.0f, 1.0f};

    // Any right-handed basis around unit `n` (continuous except at n.z = -1).
    static Frame from_normal(const Vec3& n);
    Vec3 to_world(const Vec3& local) const { return local.x * s + local.y * t + local.z * n; }
    Vec3 to_local(const Vec3& world) const { return Vec3(glm::dot(world, s), glm::dot(world, t), glm::dot(world, n)); }
};

// ------------------------------------------------------------------ warps
// Local-frame warps: z is the axis of symmetry.

// Uniform point on the unit disk, Shirley–Chiu concentric map (low distortion,
// keeps the stratification of low-discrepancy points).
Vec2 sample_concentric_disk(const Vec2& u);
// Density cos(theta)/pi on the upper hemisphere (Malley's method).
Vec3 sample_cosine_hemisphere(const Vec2& u);
float cosine_hemisphere_pdf(float cos_theta);
// Density 1/(4 pi) on the sphere.
Vec3 sample_uniform_sphere(const Vec2& u);
float uniform_sphere_pdf();
// Uniform inside the cone cos(theta) >= cos_max around +z: 1/(2 pi (1 - cos_max)).
Vec3 sample_uniform_cone(const Vec2& u, float cos_max);
float uniform_cone_pdf(float cos_max);
// Density (e+1)/(2 pi) cos^e(theta) on the upper hemisphere, e >= 0.
Vec3 sample_power_cosine(const Vec2& u, float exponent);
float power_cosine_pdf(float cos_theta, float exponent);

// ------------------------------------------------------------------ lobes
// n: unit normal on the side of wo; wo: unit, pointing away from the surface.

// Diffuse: cosine-weighted about n.
Vec3 sample_diffuse_lobe(const Vec3& n, const Vec2& u);
float diffuse_lobe_pdf(const Vec3& n, const Vec3& wi);
// Phong: cos^e about the mirror direction R of wo, density (e+1)/(2 pi)
// max(0, R.wi)^e over the whole sphere. Directions below the surface are
// returned as they are; the caller rejects them.
Vec3 sample_phong_lobe(const Vec3& n, const Vec3& wo, float exponent, const Vec2& u);
float phong_lobe_pdf(const Vec3& n, const Vec3& wo, const Vec3& wi, float exponent);
// Blinn: the half vector h is drawn with density (k+1)/(2 pi) (n.h)^k and wo
// reflected about it, so p(wi) = p(h) / (4 |wo.h|). Empty when wo.h <= 0
// (the reflected direction would have a different half vector).
std::optional<Vec3> sample_blinn_lobe(const Vec3& n, const Vec3& wo, float exponent, const Vec2& u);
float blinn_lobe_pdf(const Vec3& n, const Vec3& wo, const Vec3& wi, float exponent);

// ------------------------------------------------------------------ material

// One draw from a Bsdf.
struct BsdfSample {
    Vec3 wi{0.0f};  // unit, from the surface towards where light comes from
    // f * |cos| / pdf for smooth lobes; the component's reflectance or
    // transmittance over its choice probability for delta ones. Black: failed.
    Color weight{0.0f};
    // Smooth lobes: the full solid-angle density of wi under pdf(). Delta
    // components: the discrete probability of the choice (not a density;
    // never combine it with a solid-angle density in MIS).
    float pdf = 0.0f;
    bool is_delta = false;
    bool is_transmission = false;  // wi crossed the surface
    bool valid() const { return !is_black(weight); }
};

// The scattering function of one material at one hit, seen from wo.
//
// Components, chosen discretely in proportion to a rough albedo (so dark
// components cost few samples; every component that can contribute keeps a
// positive probability, so the choice never biases):
//   smooth    (1 - transparency) * ((1 - rho_r) * diffuse + phong + blinn),
//             from Material::diffuse_brdf and glossy_brdf, sampled as a
//             one-sample mixture of the three lobes weighted by their
//             albedos (diffuse * luminance(pigment), phong, specular). The
//             (1 - rho_r) per channel is whitted's "a mirror has no diffuse"
//             (docs/integrators.md); additive_reflection drops it (POV's sum);
//   mirror    max(rho_r, T * F) per channel, direction reflect(-wo, n):
//             rho_r = Material::mirror_reflectance, T = transparency, F the
//             Fresnel reflectance of the ior at wo (1 under total internal
//             reflection), so a `reflection { fresnel on }` glass does not
//             reflect twice — as whitted with fresnel=true;
//   refraction T * (1 - F) * transmission_tint, Snell's direction (straight
//             through for ior 1), radiance scaled by (eta_wo/eta_wi)^2
//             (radiance is not symmetric across an interface; pbrt's
//             TransportMode::Radiance).
class Bsdf {
  public:
    // `wo` unit, pointing away from the hit (towards the previous vertex).
    // `relative_eta`: n on wo's side over n beyond, from the objects the
    // path is in (InteriorStack::refraction_eta); 0 judges by the face
    // (a back face leaves into ior 1).
    Bsdf(const Material& material, const SurfaceSample& surface, const Hit& hit, const Vec3& wo,
         bool additive_reflection = false, float relative_eta = 0.0f);

    // f(wo, wi) * |cos(n, wi)| of the smooth components; 0 below the surface.
    Color eval(const Vec3& wi) const;
    // Solid-angle density with which sample() returns wi through a smooth
    // lobe, including the probability of choosing the smooth component.
    float pdf(const Vec3& wi) const;
    // u_choice picks the component (and lobe, and Fresnel branch); u warps.
    BsdfSample sample(float u_choice, const Vec2& u) const;

    bool has_smooth() const { return m_p_smooth > 0.0f; }
    // n on wo's side over n beyond the surface (1: index-matched).
    float eta() const { return m_eta; }
    bool is_black() const { return m_p_smooth + m_p_mirror + m_p_dielectric <= 0.0f; }
    // The shading normal turned towards wo.
    const Vec3& normal() const { return m_n; }

  private:
    float smooth_pdf(const Vec3& wi) const;  // mixture density alone

    const Material& m_material;
    SurfaceSample m_surface;
    Vec3 m_wo;
    Vec3 m_n;                // shading normal facing wo
    bool m_entering = true;  // wo is on the geometric normal's side
    float m_transparency = 0.0f;
    Color m_tint{0.0f};
    Color m_diffuse_scale{1.0f};  // 1 - rho_r, or 1 with additive reflection
    Color m_mirror{0.0f};         // delta reflectance
    Color m_transmitted{0.0f};    // delta transmittance, radiance-scaled
    float m_eta = 1.0f;           // n on wo's side / n on the far side
    Vec3 m_refracted{0.0f};
    // Component and lobe probabilities (each group sums to 1 or is all 0).
    float m_p_smooth = 0.0f, m_p_mirror = 0.0f, m_p_dielectric = 0.0f;
    float m_p_diffuse = 0.0f, m_p_phong = 0.0f, m_p_blinn = 0.0f;
    float m_phong_exponent = 0.0f, m_blinn_exponent = 0.0f;
};

// Power heuristic (beta = 2) weight of a strategy with density `pdf_this`
// against one with `pdf_other`, both per the same measure, one sample each.
inline float power_heuristic(float pdf_this, float pdf_other) {
    // Written as a ratio so large densities (tiny lights) cannot overflow.
    if (!(pdf_this > 0.0f)) return 0.0f;
    const float r = pdf_other / pdf_this;
    return 1.0f / (1.0f + r * r);
}

}  // namespace lancer
