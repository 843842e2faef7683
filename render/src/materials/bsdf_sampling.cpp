// Warps, lobe samplers and the material sampler; see bsdf_sampling.h.
#include "lancer/shading/bsdf_sampling.h"

#include <algorithm>
#include <cmath>

namespace lancer {

namespace {

constexpr float kInvPi = 1.0f / kPi;
constexpr float kInv2Pi = 0.5f / kPi;

// sqrt that tolerates the tiny negative arguments rounding produces.
float safe_sqrt(float x) {
    return std::sqrt(std::max(0.0f, x));
}

}  // namespace

Frame Frame::from_normal(const Vec3& n) {
    // Duff et al., "Building an orthonormal basis, revisited" (JCGT 2017):
    // branch-free and continuous except at the south pole.
    const float sign = std::copysign(1.0f, n.z);
    const float a = -1.0f / (sign + n.z);
    const float b = n.x * n.y * a;
    Frame f;
    f.s = Vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
    f.t = Vec3(b, sign + n.y * n.y * a, -n.y);
    f.n = n;
    return f;
}

// ------------------------------------------------------------------ warps

Vec2 sample_concentric_disk(const Vec2& u) {
    const Vec2 o = 2.0f * u - Vec2(1.0f);
    if (o.x == 0.0f && o.y == 0.0f) return Vec2(0.0f);
    float r, theta;
    if (std::abs(o.x) > std::abs(o.y)) {
        r = o.x;
        theta = 0.25f * kPi * (o.y / o.x);
    } else {
        r = o.y;
        theta = 0.5f * kPi - 0.25f * kPi * (o.x / o.y);
    }
    return r * Vec2(std::cos(theta), std::sin(theta));
}

Vec3 sample_cosine_hemisphere(const Vec2& u) {
    const Vec2 d = sample_concentric_disk(u);
    return Vec3(d.x, d.y, safe_sqrt(1.0f - d.x * d.x - d.y * d.y));
}

float cosine_hemisphere_pdf(float cos_theta) {
    return cos_theta > 0.0f ? cos_theta * kInvPi : 0.0f;
}

Vec3 sample_uniform_sphere(const Vec2& u) {
    const float z = 1.0f - 2.0f * u.x;
    const float r = safe_sqrt(1.0f - z * z);
    const float phi = 2.0f * kPi * u.y;
    return Vec3(r * std::cos(phi), r * std::sin(phi), z);
}

float uniform_sphere_pdf() {
    return 0.25f * kInvPi;
}

Vec3 sample_uniform_cone(const Vec2& u, float cos_max) {
    // cos(theta) uniform in [cos_max, 1] gives uniform solid angle.
    const float cos_theta = (1.0f - u.x) + u.x * cos_max;
    const float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    const float phi = 2.0f * kPi * u.y;
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

float uniform_cone_pdf(float cos_max) {
    return 1.0f / (2.0f * kPi * (1.0f - cos_max));
}

Vec3 sample_power_cosine(const Vec2& u, float exponent) {
    // The CDF of cos(theta) is cos^(e+1); invert with 1 - u so u = 0 maps to
    // the pole and stratification is kept.
    const float cos_theta = std::pow(1.0f - u.x, 1.0f / (exponent + 1.0f));
    const float sin_theta = safe_sqrt(1.0f - cos_theta * cos_theta);
    const float phi = 2.0f * kPi * u.y;
    return Vec3(sin_theta * std::cos(phi), sin_theta * std::sin(phi), cos_theta);
}

float power_cosine_pdf(float cos_theta, float exponent) {
    if (cos_theta <= 0.0f) return 0.0f;
    return (exponent + 1.0f) * kInv2Pi * std::pow(cos_theta, exponent);
}

// ------------------------------------------------------------------ lobes

Vec3 sample_diffuse_lobe(const Vec3& n, const Vec2& u) {
    return glm::normalize(Frame::from_normal(n).to_world(sample_cosine_hemisphere(u)));
}

float diffuse_lobe_pdf(const Vec3& n, const Vec3& wi) {
    return cosine_hemisphere_pdf(glm::dot(n, wi));
}

Vec3 sample_phong_lobe(const Vec3& n, const Vec3& wo, float exponent, const Vec2& u) {
    const Vec3 r = reflect(-wo, n);
    return glm::normalize(Frame::from_normal(r).to_world(sample_power_cosine(u, exponent)));
}

float phong_lobe_pdf(const Vec3& n, const Vec3& wo, const Vec3& wi, float exponent) {
    return power_cosine_pdf(glm::dot(reflect(-wo, n), wi), exponent);
}

std::optional<Vec3> sample_blinn_lobe(const Vec3& n, const Vec3& wo, float exponent, const Vec2& u) {
    const Vec3 h = glm::normalize(Frame::from_normal(n).to_world(sample_power_cosine(u, exponent)));
    const float wo_h = glm::dot(wo, h);
    if (wo_h <= 0.0f) return std::nullopt;
    return glm::normalize(2.0f * wo_h * h - wo);
}

float blinn_lobe_pdf(const Vec3& n, const Vec3& wo, const Vec3& wi, float exponent) {
    const Vec3 sum = wo + wi;
    const float len2 = glm::dot(sum, sum);
    if (len2 <= 0.0f) return 0.0f;
    const Vec3 h = sum / std::sqrt(len2);
    const float wo_h = glm::dot(wo, h);
    if (wo_h <= 0.0f) return 0.0f;
    return power_cosine_pdf(glm::dot(n, h), exponent) / (4.0f * wo_h);
}

// ------------------------------------------------------------------ material

Bsdf::Bsdf(const Material& material, const SurfaceSample& surface, const Hit& hit, const Vec3& wo,
           bool additive_reflection, float relative_eta)
    : m_material(material), m_surface(surface), m_wo(wo) {
    const MaterialParameters& p = material.parameters();
    m_n = hit.facing_normal(wo);
    m_entering = hit.is_front_face(wo);
    const float cos_o = std::max(0.0f, glm::dot(m_n, wo));

    // Mirror (POV's reflection block) and, unless reflection adds to it as
    // in POV-Ray, the diffuse share it takes away (whitted's "a mirror has
    // no diffuse").
    const float face_ior = glm::max(p.ior, 1e-6f);
    const Color rho_r =
        material.has_mirror()
            ? glm::clamp(material.mirror_reflectance(surface, cos_o, m_entering ? face_ior : 1.0f / face_ior),
                         Color(0.0f), Color(1.0f))
            : Color(0.0f);
    m_diffuse_scale = additive_reflection ? Color(1.0f) : Color(1.0f) - rho_r;
    m_mirror = rho_r;

    // Smooth lobes: probabilities by albedo. The diffuse lobe is scaled by
    // the opacity, the highlights are not (POV-Ray's rule,
    // Material::glossy_brdf).
    m_transparency = std::clamp(material.transparency(surface), 0.0f, 1.0f);
    const float opacity = 1.0f - m_transparency;
    const float w_diffuse =
        p.diffuse > 0.0f ? opacity * p.diffuse * std::max(0.0f, luminance(surface.pigment * m_diffuse_scale)) : 0.0f;
    const float w_phong = std::max(0.0f, material.phong_reflectance());
    const float w_blinn = std::max(0.0f, material.specular_reflectance());
    const float w_smooth = w_diffuse + w_phong + w_blinn;
    if (w_smooth > 0.0f) {
        m_p_diffuse = w_diffuse / w_smooth;
        m_p_phong = w_phong / w_smooth;
        m_p_blinn = w_blinn / w_smooth;
    }
    m_phong_exponent = std::max(0.0f, p.phong_size);
    m_blinn_exponent = 1.0f / std::max(p.roughness, 1e-4f);

    // Dielectric: Fresnel at wo, the refracted direction, TIR. Its
    // reflected share T*F joins the mirror as max(rho_r, T*F) per channel,
    // so a material that already says `reflection { fresnel on }` is not
    // reflected twice (whitted's fresnel=true does the same).
    Color transmitted(0.0f);
    if (m_transparency > 0.0f) {
        m_tint = material.transmission_tint(surface);
        const float ior = p.ior > 0.0f ? p.ior : 1.0f;
        const float eta = relative_eta > 0.0f ? relative_eta : m_entering ? 1.0f / ior : ior;
        float fresnel = 0.0f;
        if (std::abs(eta - 1.0f) < 1e-6f) {
            m_eta = 1.0f;
            m_refracted = -wo;
        } else {
            m_eta = eta;
            if (refract(-wo, m_n, m_eta, m_refracted)) {
                fresnel = std::clamp(fresnel_dielectric(cos_o, m_eta), 0.0f, 1.0f);
                m_refracted = glm::normalize(m_refracted);
            } else {
                fresnel = 1.0f;  // total internal reflection
            }
        }
        m_mirror = glm::max(m_mirror, Color(m_transparency * fresnel));
        // Radiance is compressed by (eta_wo / eta_wi)^2 crossing into the
        // denser medium (m_eta = eta_wo / eta_wi).
        transmitted = m_tint * (m_transparency * (1.0f - fresnel) * m_eta * m_eta);
        // POV's conserve_energy: what the finish reflects is not transmitted.
        if (p.conserve_energy) transmitted *= glm::clamp(Color(1.0f) - rho_r, Color(0.0f), Color(1.0f));
    }
    m_transmitted = transmitted;

    // Component probabilities.
    const float s = w_smooth;
    const float m = std::max(0.0f, luminance(m_mirror));
    const float t = std::max(0.0f, luminance(m_transmitted));
    const float total = s + m + t;
    if (total > 0.0f && std::isfinite(total)) {
        m_p_smooth = s / total;
        m_p_mirror = m / total;
        m_p_dielectric = t / total;
    }
}

Color Bsdf::eval(const Vec3& wi) const {
    const float cos_i = glm::dot(m_n, wi);
    if (cos_i <= 0.0f || m_p_smooth <= 0.0f) return Color(0.0f);
    const Color diffuse =
        m_material.diffuse_brdf_at_opacity(m_surface, m_n, wi, 1.0f - m_transparency) * m_diffuse_scale;
    // Most surfaces have no highlight: glossy_brdf would only say 0.
    if (!m_material.has_glossy()) return diffuse * cos_i;
    return (diffuse + m_material.glossy_brdf(m_surface, m_n, m_wo, wi)) * cos_i;
}

float Bsdf::smooth_pdf(const Vec3& wi) const {
    float pdf = 0.0f;
    if (m_p_diffuse > 0.0f) pdf += m_p_diffuse * diffuse_lobe_pdf(m_n, wi);
    if (m_p_phong > 0.0f) pdf += m_p_phong * phong_lobe_pdf(m_n, m_wo, wi, m_phong_exponent);
    if (m_p_blinn > 0.0f) pdf += m_p_blinn * blinn_lobe_pdf(m_n, m_wo, wi, m_blinn_exponent);
    return pdf;
}

float Bsdf::pdf(const Vec3& wi) const {
    if (m_p_smooth <= 0.0f || glm::dot(m_n, wi) <= 0.0f) return 0.0f;
    return m_p_smooth * smooth_pdf(wi);
}

BsdfSample Bsdf::sample(float u_choice, const Vec2& u) const {
    BsdfSample out;
    // Smooth lobes: pick one by albedo, then weigh by the whole mixture's
    // density (one-sample MIS over the lobes, balance heuristic).
    if (u_choice < m_p_smooth) {
        const float v = std::min(u_choice / m_p_smooth, 0x1.fffffep-1f);
        Vec3 wi;
        if (v < m_p_diffuse) {
            wi = sample_diffuse_lobe(m_n, u);
        } else if (v < m_p_diffuse + m_p_phong) {
            wi = sample_phong_lobe(m_n, m_wo, m_phong_exponent, u);
        } else {
            const std::optional<Vec3> h = sample_blinn_lobe(m_n, m_wo, m_blinn_exponent, u);
            if (!h) return out;
            wi = *h;
        }
        const float pdf = this->pdf(wi);
        if (!(pdf > 0.0f)) return out;
        out.wi = wi;
        out.pdf = pdf;
        out.weight = eval(wi) / pdf;
        return out;
    }
    u_choice -= m_p_smooth;

    // Mirror.
    if (u_choice < m_p_mirror) {
        out.wi = glm::normalize(reflect(-m_wo, m_n));
        out.pdf = m_p_mirror;
        out.is_delta = true;
        out.weight = m_mirror / m_p_mirror;
        return out;
    }
    u_choice -= m_p_mirror;

    // Dielectric refraction (or straight through with ior 1).
    if (m_p_dielectric > 0.0f) {
        out.wi = m_refracted;
        out.is_delta = true;
        out.is_transmission = true;
        out.pdf = m_p_dielectric;
        out.weight = m_transmitted / m_p_dielectric;
    }
    return out;
}

}  // namespace lancer
