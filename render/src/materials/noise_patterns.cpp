// POV-Ray's patterns made of solid noise (dents, granite, agate, marble,
// wood, wrinkles; bozo, spotted and bumps are the noise itself), leopard,
// and the normals bumps, dents and wrinkles perturb by.
#include <algorithm>
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

double dents_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const double n = pov_noise(p, s.generator);
    return n * n * n;
}

double granite_pattern(const PatternSetup& s, const glm::dvec3& p) {
    // Six octaves of |noise| folded about its middle, at 4x the point's scale.
    const glm::dvec3 base = p * 4.0;
    double sum = 0.0;
    double frequency = 1.0;
    for (int octave = 0; octave < 6; ++octave, frequency *= 2.0) {
        const double n = pov_noise(base * frequency, s.generator);
        double fold;
        if (s.generator == NoiseGenerator::Original) {
            fold = std::fabs(0.5 - n);
        } else {
            // The newer generators span [0, 1] fully: fold twice as steeply
            // and cap, which keeps the original's look.
            fold = std::min(std::fabs(1.0 - 2.0 * n), 0.5);
        }
        sum += fold / frequency;
    }
    return sum;
}

double agate_pattern(const PatternSetup& s, const glm::dvec3& p) {
    const TurbulenceSettings& t = s.turbulence;
    const double turbulence = s.agate_turbulence * pov_turbulence(p, t.omega, t.lambda, t.octaves, s.generator);
    const double wave = 0.5 * (cycloidal(1.3 * turbulence + 1.1 * p.z) + 1.0);
    if (wave < 0.0) return 0.0;
    return std::pow(std::min(1.0, wave), 0.77);
}

double marble_pattern(const PatternSetup& s, const glm::dvec3& p) {
    // Marble takes turbulence on its value only (the pipeline leaves its
    // point alone): x shifted by turbulence's x times Turbulence().
    if (!s.turbulence.present()) return p.x;
    const TurbulenceSettings& t = s.turbulence;
    return p.x + t.amount.x * pov_turbulence(p, t.omega, t.lambda, t.octaves, s.generator);
}

double wood_pattern(const PatternSetup& s, const glm::dvec3& p) {
    // Rings around z; turbulence (on the value only, like marble) wobbles
    // them by a sine of the displaced x and y.
    double x = p.x, y = p.y;
    if (s.turbulence.present()) {
        const TurbulenceSettings& t = s.turbulence;
        const glm::dvec3 d = pov_dturbulence(p, t.omega, t.lambda, t.octaves, s.generator);
        x += cycloidal((p.x + d.x) * t.amount.x);
        y += cycloidal((p.y + d.y) * t.amount.y);
    }
    return std::sqrt(x * x + y * y);
}

double wrinkles_pattern(const PatternSetup& s, const glm::dvec3& p) {
    // Ten octaves of noise, each half the amplitude at twice the frequency;
    // the newer generators stretch and clip each octave as turbulence does.
    const bool stretch = s.generator != NoiseGenerator::Original;
    auto octave = [&](const glm::dvec3& q) {
        const double n = pov_noise(q, s.generator);
        return stretch ? std::min(std::max(n * 2.0 - 0.5, 0.0), 1.0) : n;
    };
    double value = octave(p);
    double lambda = 2.0, omega = 0.5;
    for (int i = 1; i < 10; ++i) {
        value += omega * octave(p * lambda);
        lambda *= 2.0;
        omega *= 0.5;
    }
    return value / 2.0;
}

double leopard_pattern(const glm::dvec3& p) {
    const double mean = (std::sin(p.x) + std::sin(p.y) + std::sin(p.z)) / 3.0;
    return mean * mean;
}

void bumps_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal) {
    normal += amount * pov_dnoise(p, s.generator);
}

void dents_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal) {
    const double n = pov_noise(p, s.generator);
    normal += (n * n * n * amount) * pov_dnoise(p, s.generator);
}

void wrinkles_normal(const PatternSetup& s, const glm::dvec3& p, double amount, glm::dvec3& normal) {
    glm::dvec3 sum(0.0);
    double scale = 1.0;
    for (int i = 0; i < 10; ++i, scale *= 2.0) sum += glm::abs(pov_dnoise(p * scale, s.generator) / scale);
    normal += amount * sum;
}

}  // namespace lancer::pattern_detail
