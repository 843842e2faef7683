// Statistical tests of the sampling routines (bsdf_sampling.h) and of the
// Sobol sampler: every sampler's histogram against its claimed density by a
// chi-square test (10^6 samples, significance 0.01, as pbrt's and Mitsuba's
// sampling tests do), and energy conservation of every material component.
#include <algorithm>
#include <cmath>
#include <functional>
#include <optional>
#include <random>
#include <set>
#include <string_view>
#include <vector>

#include <gtest/gtest.h>

#include "lancer/sampler.h"
#include "lancer/shading/bsdf_sampling.h"

namespace lancer {
namespace {

constexpr int kSamples = 1'000'000;
constexpr double kSignificance = 0.01;

// Upper tail of the chi-square distribution with k degrees of freedom at x,
// by the Wilson–Hilferty cube-root normal approximation (accurate to a few
// percent of p for k >= 30, far better than the test needs).
double chi_square_p_value(double x, int k) {
    const double a = 2.0 / (9.0 * k);
    const double z = (std::cbrt(x / k) - (1.0 - a)) / std::sqrt(a);
    return 0.5 * std::erfc(z / std::sqrt(2.0));
}

// Histogram of directions on a (theta, phi) grid about +z and the expected
// counts from integrating `pdf` over each cell.
struct SphereChiSquare {
    static constexpr int kTheta = 40;
    static constexpr int kPhi = 80;
    static constexpr int kSub = 12;  // midpoint sub-grid per cell for the integral

    // Draws one direction from `u` (uniform in [0,1)^3); nullopt: a failed draw.
    std::function<std::optional<Vec3>(const Vec3& u)> sample;
    std::function<double(const Vec3&)> pdf;  // over the whole sphere

    static int cell(const Vec3& d) {
        const double theta = std::acos(std::clamp(double(d.z), -1.0, 1.0));
        double phi = std::atan2(double(d.y), double(d.x));
        if (phi < 0.0) phi += 2.0 * M_PI;
        const int i = std::min(kTheta - 1, int(theta / M_PI * kTheta));
        const int j = std::min(kPhi - 1, int(phi / (2.0 * M_PI) * kPhi));
        return i * kPhi + j;
    }

    // p-value of the chi-square statistic; cells expecting < 5 are pooled,
    // and failed draws form a cell of their own expecting 1 - integral(pdf).
    double run(std::uint32_t seed) const {
        std::vector<double> observed(kTheta * kPhi, 0.0);
        double failed = 0.0;
        std::mt19937 rng(seed);
        std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
        for (int s = 0; s < kSamples; ++s) {
            const Vec3 u(uniform(rng), uniform(rng), uniform(rng));
            const std::optional<Vec3> d = sample(u);
            if (!d) {
                failed += 1.0;
                continue;
            }
            observed[cell(*d)] += 1.0;
        }
        std::vector<double> expected(kTheta * kPhi, 0.0);
        const double dt = M_PI / kTheta, dp = 2.0 * M_PI / kPhi;
        double total_expected = 0.0;
        for (int i = 0; i < kTheta; ++i)
            for (int j = 0; j < kPhi; ++j) {
                double integral = 0.0;
                for (int a = 0; a < kSub; ++a)
                    for (int b = 0; b < kSub; ++b) {
                        const double theta = (i + (a + 0.5) / kSub) * dt;
                        const double phi = (j + (b + 0.5) / kSub) * dp;
                        const Vec3 d(float(std::sin(theta) * std::cos(phi)), float(std::sin(theta) * std::sin(phi)),
                                     float(std::cos(theta)));
                        integral += pdf(d) * std::sin(theta);
                    }
                integral *= dt * dp / (kSub * kSub);
                expected[i * kPhi + j] = integral * kSamples;
                total_expected += integral * kSamples;
            }
        double chi2 = 0.0;
        int dof = -1;
        double pooled_observed = failed, pooled_expected = std::max(0.0, kSamples - total_expected);
        for (std::size_t c = 0; c < expected.size(); ++c) {
            if (expected[c] < 5.0) {
                pooled_observed += observed[c];
                pooled_expected += expected[c];
                continue;
            }
            chi2 += (observed[c] - expected[c]) * (observed[c] - expected[c]) / expected[c];
            ++dof;
        }
        if (pooled_expected >= 5.0) {
            chi2 += (pooled_observed - pooled_expected) * (pooled_observed - pooled_expected) / pooled_expected;
            ++dof;
        } else if (pooled_observed > 10.0 * std::max(pooled_expected, 1.0)) {
            return 0.0;  // mass where the density says there is none
        }
        return chi_square_p_value(chi2, std::max(dof, 1));
    }
};

Vec3 direction_at(float theta_degrees) {
    const float t = glm::radians(theta_degrees);
    return Vec3(std::sin(t), 0.0f, std::cos(t));
}

TEST(BsdfSamplingChiSquare, CosineHemisphere) {
    SphereChiSquare test;
    test.sample = [](const Vec3& u3) {
        const Vec2 u(u3);
        return std::optional<Vec3>(sample_cosine_hemisphere(u));
    };
    test.pdf = [](const Vec3& d) { return double(cosine_hemisphere_pdf(d.z)); };
    EXPECT_GT(test.run(1), kSignificance);
}

TEST(BsdfSamplingChiSquare, UniformSphere) {
    SphereChiSquare test;
    test.sample = [](const Vec3& u3) {
        const Vec2 u(u3);
        return std::optional<Vec3>(sample_uniform_sphere(u));
    };
    test.pdf = [](const Vec3&) { return double(uniform_sphere_pdf()); };
    EXPECT_GT(test.run(2), kSignificance);
}

TEST(BsdfSamplingChiSquare, UniformCone) {
    // The rim on a theta bin edge (36 degrees), so the histogram's cells do
    // not straddle the density's discontinuity.
    const float cos_max = std::cos(glm::radians(36.0f));
    SphereChiSquare test;
    test.sample = [&](const Vec3& u3) {
        const Vec2 u(u3);
        return std::optional<Vec3>(sample_uniform_cone(u, cos_max));
    };
    test.pdf = [&](const Vec3& d) { return d.z >= cos_max ? double(uniform_cone_pdf(cos_max)) : 0.0; };
    EXPECT_GT(test.run(3), kSignificance);
}

TEST(BsdfSamplingChiSquare, PowerCosine) {
    SphereChiSquare test;
    test.sample = [](const Vec3& u3) {
        const Vec2 u(u3);
        return std::optional<Vec3>(sample_power_cosine(u, 7.0f));
    };
    test.pdf = [](const Vec3& d) { return double(power_cosine_pdf(d.z, 7.0f)); };
    EXPECT_GT(test.run(4), kSignificance);
}

TEST(BsdfSamplingChiSquare, DiffuseLobeTiltedNormal) {
    const Vec3 n = glm::normalize(Vec3(0.3f, -0.2f, 0.9f));
    SphereChiSquare test;
    test.sample = [&](const Vec3& u3) {
        const Vec2 u(u3);
        return std::optional<Vec3>(sample_diffuse_lobe(n, u));
    };
    test.pdf = [&](const Vec3& d) { return double(diffuse_lobe_pdf(n, d)); };
    EXPECT_GT(test.run(5), kSignificance);
}

TEST(BsdfSamplingChiSquare, PhongLobe) {
    const Vec3 n(0.0f, 0.0f, 1.0f);
    const Vec3 wo = direction_at(35.0f);
    SphereChiSquare test;
    test.sample = [&](const Vec3& u3) {
        const Vec2 u(u3);
        return std::optional<Vec3>(sample_phong_lobe(n, wo, 12.0f, u));
    };
    test.pdf = [&](const Vec3& d) { return double(phong_lobe_pdf(n, wo, d, 12.0f)); };
    EXPECT_GT(test.run(6), kSignificance);
}

TEST(BsdfSamplingChiSquare, BlinnLobe) {
    const Vec3 n(0.0f, 0.0f, 1.0f);
    const Vec3 wo = direction_at(60.0f);
    SphereChiSquare test;
    test.sample = [&](const Vec3& u3) {
        const Vec2 u(u3);
        return sample_blinn_lobe(n, wo, 15.0f, u);
    };
    test.pdf = [&](const Vec3& d) { return double(blinn_lobe_pdf(n, wo, d, 15.0f)); };
    EXPECT_GT(test.run(7), kSignificance);
}

// A material at a hit on the plane z = 0 with normal +z.
struct MaterialAtHit {
    explicit MaterialAtHit(const MaterialParameters& p, Color pigment = Color(0.8f), float filter = 0.0f,
                           float transmit = 0.0f)
        : material(p) {
        hit.position = Vec3(0.0f);
        hit.geometric_normal = hit.shading_normal = Vec3(0.0f, 0.0f, 1.0f);
        hit.material = &material;
        surface.pigment = pigment;
        surface.filter = filter;
        surface.transmit = transmit;
    }
    Material material;
    Hit hit;
    SurfaceSample surface;
};

TEST(BsdfSamplingChiSquare, MaterialMixture) {
    MaterialParameters p;
    p.diffuse = 0.5f;
    p.phong = 0.3f;
    p.phong_size = 20.0f;
    p.specular = 0.2f;
    p.roughness = 0.05f;
    MaterialAtHit m(p);
    const Vec3 wo = direction_at(50.0f);
    const Bsdf bsdf(m.material, m.surface, m.hit, wo);
    SphereChiSquare test;
    test.sample = [&](const Vec3& u) -> std::optional<Vec3> {
        const BsdfSample s = bsdf.sample(u.z, Vec2(u));
        if (!s.valid()) return std::nullopt;
        return s.wi;
    };
    test.pdf = [&](const Vec3& d) { return double(bsdf.pdf(d)); };
    EXPECT_GT(test.run(8), kSignificance);
}

// Sampled weights must equal eval/pdf (the estimator's consistency).
TEST(BsdfSampling, WeightIsEvalOverPdf) {
    MaterialParameters p;
    p.diffuse = 0.7f;
    p.phong = 0.2f;
    p.specular = 0.1f;
    MaterialAtHit m(p, Color(0.9f, 0.5f, 0.2f));
    std::mt19937 rng(9);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    const Bsdf bsdf(m.material, m.surface, m.hit, direction_at(30.0f));
    for (int i = 0; i < 1000; ++i) {
        const BsdfSample s = bsdf.sample(uniform(rng), Vec2(uniform(rng), uniform(rng)));
        if (!s.valid()) continue;
        const Color expected = bsdf.eval(s.wi) / bsdf.pdf(s.wi);
        EXPECT_NEAR(s.weight.r, expected.r, 1e-4f * (1.0f + expected.r));
        EXPECT_NEAR(s.pdf, bsdf.pdf(s.wi), 1e-4f * s.pdf);
    }
}

// Hemispherical-directional reflectance of every component, estimated by
// importance sampling, never exceeds 1 (+ 3 standard errors + 1%). The
// highlights are given as POV's `albedo 1` (the peak that reflects all the
// light at normal incidence, phong_albedo / specular_albedo): POV's peak
// values themselves reflect more than they receive as soon as the lobe is
// wide (see PovPeakHighlightsCanReflectMoreThanTheyReceive).
struct NamedMaterial {
    const char* name;
    double tolerance;  // allowed excess over 1
    MaterialParameters params;
    Color pigment;
    float filter, transmit;
};

TEST(BsdfSampling, EnergyConservation) {
    std::vector<NamedMaterial> materials;
    auto add = [&](const char* name, auto&& edit, Color pigment = Color(1.0f), float filter = 0.0f,
                   float transmit = 0.0f) {
        MaterialParameters p;
        p.diffuse = 0.0f;
        edit(p);
        // Every lobe, Blinn included (POV's albedo rescaling is exact at
        // normal incidence, material.cpp), conserves energy to Monte Carlo noise.
        const double tolerance = 0.01;
        materials.push_back({name, tolerance, p, pigment, filter, transmit});
    };
    add("diffuse", [](MaterialParameters& p) { p.diffuse = 1.0f; });
    for (float e : {1.0f, 10.0f, 40.0f, 400.0f})
        add("phong", [e](MaterialParameters& p) {
            p.phong = 1.0f / phong_albedo(e);
            p.phong_size = e;
        });
    for (float r : {0.5f, 0.05f, 0.005f})
        add("blinn", [r](MaterialParameters& p) {
            p.specular = 1.0f / specular_albedo(1.0f / r);
            p.roughness = r;
        });
    add("mix", [](MaterialParameters& p) {
        p.diffuse = 0.5f;
        p.phong = 0.25f / phong_albedo(p.phong_size);
        p.specular = 0.25f / specular_albedo(1.0f / p.roughness);
    });
    add("mirror", [](MaterialParameters& p) { p.reflection_max = p.reflection_min = Color(1.0f); });
    add("half mirror", [](MaterialParameters& p) {
        p.diffuse = 1.0f;
        p.reflection_max = p.reflection_min = Color(0.5f);
    });
    add(
        "fresnel glass",
        [](MaterialParameters& p) {
            p.ior = 1.5f;
            p.reflection_max = Color(1.0f);
            p.reflection_fresnel = true;
        },
        Color(1.0f), 0.0f, 1.0f);
    add(
        "glass", [](MaterialParameters& p) { p.ior = 1.5f; }, Color(1.0f), 0.0f, 1.0f);
    add(
        "filter glass",
        [](MaterialParameters& p) {
            p.ior = 1.33f;
            p.diffuse = 0.1f;
        },
        Color(0.5f, 0.9f, 0.3f), 0.7f, 0.2f);
    add(
        "clear", [](MaterialParameters& p) {}, Color(1.0f), 0.0f, 1.0f);

    std::mt19937 rng(10);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    for (const NamedMaterial& nm : materials) {
        MaterialAtHit m(nm.params, nm.pigment, nm.filter, nm.transmit);
        for (int trial = 0; trial < 12; ++trial) {
            // Random wo on either side (inside glass: wo below the geometric normal).
            const Vec3 wo = sample_uniform_sphere(Vec2(uniform(rng), uniform(rng)));
            if (std::abs(wo.z) < 1e-3f) continue;
            const Bsdf bsdf(m.material, m.surface, m.hit, wo);
            constexpr int kN = 20000;
            glm::dvec3 sum(0.0), sum2(0.0);
            for (int i = 0; i < kN; ++i) {
                const BsdfSample s = bsdf.sample(uniform(rng), Vec2(uniform(rng), uniform(rng)));
                // Undo the (eta_wo/eta_wi)^2 radiance scaling: albedo is about energy.
                Color w = s.weight;
                if (s.is_transmission && nm.params.ior != 1.0f) {
                    const float eta = wo.z > 0.0f ? 1.0f / nm.params.ior : nm.params.ior;
                    w /= eta * eta;
                }
                sum += glm::dvec3(w);
                sum2 += glm::dvec3(w) * glm::dvec3(w);
            }
            const glm::dvec3 mean = sum / double(kN);
            const glm::dvec3 error = glm::sqrt(glm::max(sum2 / double(kN) - mean * mean, 0.0) / double(kN));
            for (int c = 0; c < 3; ++c)
                EXPECT_LE(mean[c], 1.0 + nm.tolerance + 3.0 * error[c])
                    << nm.name << " wo.z=" << wo.z << " channel " << c;
        }
    }
}

// POV's `phong 1 phong_size 1` over a white diffuse 0.6: at normal
// incidence the highlight alone reflects 2 / (1 + 1) = 1 of the light, so
// the finish returns 1.6 of what it receives, as it does in POV-Ray.
TEST(BsdfSampling, PovPeakHighlightsCanReflectMoreThanTheyReceive) {
    MaterialParameters p;
    p.diffuse = 0.6f;
    p.phong = 1.0f;
    p.phong_size = 1.0f;
    MaterialAtHit m(p, Color(1.0f), 0.0f, 0.0f);
    const Bsdf bsdf(m.material, m.surface, m.hit, Vec3(0.0f, 0.0f, 1.0f));
    std::mt19937 rng(3);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    constexpr int kN = 200000;
    double sum = 0.0;
    for (int i = 0; i < kN; ++i) sum += bsdf.sample(uniform(rng), Vec2(uniform(rng), uniform(rng))).weight.g;
    EXPECT_NEAR(sum / kN, 1.6, 0.01);
}

// ------------------------------------------------------------------ Sobol

// Points 0 .. n-1 of a pixel put one value in each of n strata of every
// tabulated dimension.
void expect_every_dimension_stratified(std::uint64_t seed, int n, int pixel_x, int pixel_y) {
    constexpr int kDims = 53;
    auto sampler = make_sobol_sampler(seed);
    std::vector<std::set<int>> strata(kDims);
    for (int i = 0; i < n; ++i) {
        sampler->start_sample(pixel_x, pixel_y, std::uint32_t(i));
        for (int d = 0; d < kDims; ++d) strata[d].insert(int(sampler->next_1d() * float(n)));
    }
    for (int d = 0; d < kDims; ++d) EXPECT_EQ(strata[d].size(), std::size_t(n)) << "dimension " << d;
}

TEST(SobolSampler, EveryDimensionIsStratified) {
    expect_every_dimension_stratified(42, 256, 3, 7);
}

// The first 256 points of each dimension come from a table, the rest are
// built from the direction numbers: 1024 points stratify only if both
// give the same sequence.
TEST(SobolSampler, StratifiedAcrossTheTabulatedPoints) {
    expect_every_dimension_stratified(5, 1024, 2, 9);
}

TEST(SobolSampler, FirstPairIsA02Net) {
    auto sampler = make_sobol_sampler(7);
    constexpr int kLog = 8, kN = 1 << kLog;
    std::vector<Vec2> points;
    for (int i = 0; i < kN; ++i) {
        sampler->start_sample(11, 5, i);
        points.push_back(sampler->next_2d());
    }
    // Every elementary interval of area 1/N holds exactly one point.
    for (int a = 0; a <= kLog; ++a) {
        const int nx = 1 << a, ny = 1 << (kLog - a);
        std::set<int> cells;
        for (const Vec2& p : points) cells.insert(int(p.x * nx) * ny + int(p.y * ny));
        EXPECT_EQ(cells.size(), std::size_t(kN)) << nx << "x" << ny;
    }
}

TEST(SobolSampler, DeterministicAndDecorrelatedAcrossPixels) {
    auto a = make_sobol_sampler(1);
    auto b = a->clone();
    a->start_sample(4, 4, 9);
    b->start_sample(4, 4, 9);
    for (int d = 0; d < 80; ++d) EXPECT_EQ(a->next_1d(), b->next_1d());
    // Across pixels the same sample index gives uniformly spread values.
    std::vector<int> bins(64, 0);
    for (int y = 0; y < 128; ++y)
        for (int x = 0; x < 128; ++x) {
            a->start_sample(x, y, 5);
            a->next_2d();
            bins[std::min(63, int(a->next_1d() * 64))]++;
        }
    double chi2 = 0.0;
    const double expected = 128.0 * 128.0 / 64.0;
    for (int c : bins) chi2 += (c - expected) * (c - expected) / expected;
    EXPECT_GT(chi_square_p_value(chi2, 63), kSignificance);
}

}  // namespace
}  // namespace lancer
