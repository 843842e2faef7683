// POV-Ray's media at a point, and its phase functions (lancer/medium.h).
#include "lancer/medium.h"

#include <algorithm>
#include <cmath>

namespace lancer {

namespace {

// POV's constants in front of each shape (media.cpp,
// ComputeMediaScatteringAttenuation).
constexpr float kPovHazy = 0.576655375f;
constexpr float kPovMurky = 0.495714547f;
constexpr float kPovRayleigh = 0.799372013f;

// The shape of each phase function without POV's constant, and the shape's
// integral over the sphere: 2 pi times its integral over cos in [-1, 1]
// (with u = (1 + cos) / 2, the integral of u^n over cos is 2 / (n + 1)).
float phase_shape(PhaseType type, float g, float cos_theta) {
    switch (type) {
    case PhaseType::MieHazy: return 1.0f + 9.0f * std::pow(0.5f * (1.0f + cos_theta), 8.0f);
    case PhaseType::MieMurky: return 1.0f + 50.0f * std::pow(0.5f * (1.0f + cos_theta), 32.0f);
    case PhaseType::Rayleigh: return 1.0f + cos_theta * cos_theta;
    case PhaseType::HenyeyGreenstein: {
        const float g2 = g * g;
        const float base = std::max(1.0f + g2 - 2.0f * g * cos_theta, 1e-12f);
        return (1.0f - g2) / (base * std::sqrt(base));
    }
    case PhaseType::Isotropic: break;
    }
    return 1.0f;
}

float shape_integral(PhaseType type) {
    switch (type) {
    case PhaseType::MieHazy: return 2.0f * kPi * (2.0f + 9.0f * 2.0f / 9.0f);
    case PhaseType::MieMurky: return 2.0f * kPi * (2.0f + 50.0f * 2.0f / 33.0f);
    case PhaseType::Rayleigh: return 2.0f * kPi * (2.0f + 2.0f / 3.0f);
    case PhaseType::HenyeyGreenstein:
    case PhaseType::Isotropic: break;
    }
    return 4.0f * kPi;
}

// cos(theta) drawn from the normalised phase of one type. Hazy, murky and
// Rayleigh are mixtures of a uniform cos and a power term, each drawn by
// inversion; Henyey-Greenstein by its closed-form inverse.
float sample_cos(PhaseType type, float g, float u_mix, float u) {
    const auto power_term = [&](float uniform_share, float exponent) {
        if (u_mix < uniform_share) return 1.0f - 2.0f * u;
        return 2.0f * std::pow(u, 1.0f / (exponent + 1.0f)) - 1.0f;  // u = ((1 + cos) / 2)^(n+1)
    };
    switch (type) {
    case PhaseType::MieHazy: return power_term(2.0f / 4.0f, 8.0f);
    case PhaseType::MieMurky: return power_term(2.0f / (2.0f + 100.0f / 33.0f), 32.0f);
    case PhaseType::Rayleigh: {
        if (u_mix < 0.75f) return 1.0f - 2.0f * u;  // uniform: 2 of the integral's 8/3
        // density proportional to cos^2: |cos| = u'^(1/3), either sign
        const float second = (u_mix - 0.75f) / 0.25f;
        const float magnitude = std::cbrt(u);
        return second < 0.5f ? magnitude : -magnitude;
    }
    case PhaseType::HenyeyGreenstein: {
        if (std::fabs(g) < 1e-3f) return 1.0f - 2.0f * u;
        const float s = (1.0f - g * g) / (1.0f - g + 2.0f * g * u);
        return std::clamp((1.0f + g * g - s * s) / (2.0f * g), -1.0f, 1.0f);
    }
    case PhaseType::Isotropic: break;
    }
    return 1.0f - 2.0f * u;
}

}  // namespace

float pov_phase_weight(PhaseType type, float eccentricity, float cos_theta) {
    const float shape = phase_shape(type, eccentricity, cos_theta);
    switch (type) {
    case PhaseType::MieHazy: return kPovHazy * shape;
    case PhaseType::MieMurky: return kPovMurky * shape;
    case PhaseType::Rayleigh: return kPovRayleigh * shape;
    case PhaseType::HenyeyGreenstein:
    case PhaseType::Isotropic: break;
    }
    return shape;
}

float phase_density(PhaseType type, float eccentricity, float cos_theta) {
    return phase_shape(type, eccentricity, cos_theta) / shape_integral(type);
}

Medium::Medium(std::vector<MediumComponent> components, const MediumSampling& sampling)
    : m_components(std::move(components)), m_sampling(sampling) {
    for (const MediumComponent& c : m_components) {
        m_homogeneous = m_homogeneous && c.densities.empty();
        m_constant.emission += c.emission;
        m_constant.extinction += c.extinction;
        m_constant.scattering += c.scattering;
        m_extinction_bound += glm::max(c.extinction * c.density_bound, Color(0.0f));
        m_emits = m_emits || !is_black(c.emission);
        m_scatters = m_scatters || !is_black(c.scattering);
        m_attenuates = m_attenuates || !is_black(c.extinction);
    }
}

MediumPoint Medium::at(const Vec3& p, std::uint32_t space) const {
    if (m_homogeneous) return m_constant;
    MediumPoint sum;
    Hit probe;
    probe.position = p;
    probe.object_id = space;
    for (const MediumComponent& c : m_components) {
        Color density(1.0f);
        for (const Texture* factor : c.densities) density *= factor->evaluate(probe).rgb;
        sum.emission += density * c.emission;
        sum.extinction += density * c.extinction;
        sum.scattering += density * c.scattering;
    }
    return sum;
}

float Medium::pov_phase(float cos_theta) const {
    if (m_components.empty()) return 0.0f;
    float sum = 0.0f;
    for (const MediumComponent& c : m_components) sum += pov_phase_weight(c.phase, c.eccentricity, cos_theta);
    return sum / float(m_components.size());
}

float Medium::phase_pdf(float cos_theta) const {
    if (m_components.empty()) return 0.0f;
    float sum = 0.0f;
    for (const MediumComponent& c : m_components) sum += phase_density(c.phase, c.eccentricity, cos_theta);
    return sum / float(m_components.size());
}

Vec3 Medium::sample_phase(const Vec3& direction, float u_choice, const Vec2& u) const {
    // One medium, chosen uniformly (POV averages them); the rest of u_choice
    // picks the branch of that medium's mixture.
    const float scaled = u_choice * float(m_components.size());
    const std::size_t index = std::min(std::size_t(scaled), m_components.size() - 1);
    const float u_mix = std::clamp(scaled - float(index), 0.0f, 1.0f);
    const MediumComponent& c = m_components[index];
    const float cos_theta = sample_cos(c.phase, c.eccentricity, u_mix, u.x);
    const float sin_theta = std::sqrt(std::max(0.0f, 1.0f - cos_theta * cos_theta));
    const float phi = 2.0f * kPi * u.y;
    // An orthonormal frame around the travel direction (Duff et al.).
    const Vec3 w = glm::normalize(direction);
    const float sign = std::copysign(1.0f, w.z);
    const float a = -1.0f / (sign + w.z);
    const float b = w.x * w.y * a;
    const Vec3 s(1.0f + sign * w.x * w.x * a, sign * b, -sign * w.x);
    const Vec3 t(b, sign + w.y * w.y * a, -w.y);
    return glm::normalize(sin_theta * std::cos(phi) * s + sin_theta * std::sin(phi) * t + cos_theta * w);
}

}  // namespace lancer
