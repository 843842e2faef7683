// POV-Ray's phase functions (lancer/medium.h): each normalised shape
// integrates to 1 over the sphere, keeps POV's formula (up to its
// constant), and the sampler draws directions with exactly that density.
#include <cmath>

#include <gtest/gtest.h>

#include "lancer/medium.h"

namespace lancer {
namespace {

const PhaseType kTypes[] = {PhaseType::Isotropic, PhaseType::MieHazy, PhaseType::MieMurky, PhaseType::Rayleigh,
                            PhaseType::HenyeyGreenstein};

// Integral over the sphere of a function of cos(theta): 2 pi times the
// integral over cos in [-1, 1], by the midpoint rule on a fine grid.
template <class F>
double sphere_integral(F f) {
    constexpr int kSteps = 200000;
    double sum = 0.0;
    for (int i = 0; i < kSteps; ++i) {
        const double c = -1.0 + (i + 0.5) * 2.0 / kSteps;
        sum += f(float(c));
    }
    return 2.0 * kPiD * sum * 2.0 / kSteps;
}

TEST(PhaseFunctions, EachIntegratesToOne) {
    for (PhaseType type : kTypes)
        for (float g : {0.0f, 0.5f, -0.7f, 0.9f}) {
            if (type != PhaseType::HenyeyGreenstein && g != 0.0f) continue;
            EXPECT_NEAR(sphere_integral([&](float c) { return phase_density(type, g, c); }), 1.0, 1e-4)
                << "type " << int(type) << " g " << g;
        }
}

TEST(PhaseFunctions, KeepPovRaysFormulas) {
    // POV's k (media.cpp): its constants times these shapes.
    const auto u = [](float c) { return 0.5 * (1.0 + c); };
    for (float c : {-1.0f, -0.3f, 0.0f, 0.6f, 1.0f}) {
        EXPECT_FLOAT_EQ(pov_phase_weight(PhaseType::Isotropic, 0.0f, c), 1.0f);
        EXPECT_NEAR(pov_phase_weight(PhaseType::Rayleigh, 0.0f, c), 0.799372013 * (1.0 + c * c), 1e-5);
        EXPECT_NEAR(pov_phase_weight(PhaseType::MieHazy, 0.0f, c), 0.576655375 * (1.0 + 9.0 * std::pow(u(c), 8)), 1e-5);
        EXPECT_NEAR(pov_phase_weight(PhaseType::MieMurky, 0.0f, c), 0.495714547 * (1.0 + 50.0 * std::pow(u(c), 32)),
                    1e-4);
        const double g = 0.6;
        EXPECT_NEAR(pov_phase_weight(PhaseType::HenyeyGreenstein, float(g), c),
                    (1.0 - g * g) / std::pow(1.0 + g * g - 2.0 * g * c, 1.5), 1e-4);
        // The normalised density has the same shape.
        for (PhaseType type : kTypes)
            EXPECT_NEAR(phase_density(type, 0.3f, c) / phase_density(type, 0.3f, 0.25f),
                        pov_phase_weight(type, 0.3f, c) / pov_phase_weight(type, 0.3f, 0.25f), 1e-4);
    }
    // Henyey-Greenstein with g > 0 scatters forwards (cos 1: towards the light).
    EXPECT_GT(phase_density(PhaseType::HenyeyGreenstein, 0.5f, 1.0f),
              phase_density(PhaseType::HenyeyGreenstein, 0.5f, -1.0f));
}

// Chi-square of sampled cos(theta) in 20 bins against the density's bin
// probabilities (by integration): a wrong sampler fails it by far.
TEST(PhaseFunctions, SamplingDrawsTheDensity) {
    constexpr int kBins = 20, kDraws = 200000;
    const Vec3 direction = glm::normalize(Vec3(0.3f, -0.5f, 0.8f));
    std::uint64_t state = 12345;
    const auto next = [&state] {
        state = state * 6364136223846793005ULL + 1442695040888963407ULL;
        return float((state >> 40) & 0xffffff) / float(1 << 24);
    };
    for (PhaseType type : kTypes) {
        MediumComponent component;
        component.phase = type;
        component.eccentricity = 0.6f;
        component.scattering = Color(1.0f);
        const Medium medium({component}, MediumSampling{});
        int counts[kBins] = {};
        for (int i = 0; i < kDraws; ++i) {
            const float u0 = next(), u1 = next(), u2 = next();
            const Vec3 wi = medium.sample_phase(direction, u0, Vec2(u1, u2));
            ASSERT_NEAR(glm::length(wi), 1.0f, 1e-4f);
            const float c = glm::clamp(glm::dot(direction, wi), -1.0f, 1.0f);
            counts[std::min(kBins - 1, int((c + 1.0f) * 0.5f * kBins))]++;
        }
        double chi2 = 0.0;
        for (int b = 0; b < kBins; ++b) {
            const double lo = -1.0 + 2.0 * b / kBins, hi = lo + 2.0 / kBins;
            double p = 0.0;
            constexpr int kSteps = 2000;
            for (int k = 0; k < kSteps; ++k)
                p += medium.phase_pdf(float(lo + (k + 0.5) * (hi - lo) / kSteps)) * (hi - lo) / kSteps;
            p *= 2.0 * kPiD;
            const double expected = p * kDraws;
            chi2 += (counts[b] - expected) * (counts[b] - expected) / std::max(expected, 1.0);
        }
        // 19 degrees of freedom: 50 is far beyond the 0.1% tail (43.8).
        EXPECT_LT(chi2, 50.0) << "type " << int(type);
    }
}

}  // namespace
}  // namespace lancer
