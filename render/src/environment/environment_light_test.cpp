// The sky as an importance-sampled light: its density is a density (it
// integrates to 1 over the sphere, and sample() reports what pdf() says),
// the estimate it gives of the sky's total is unbiased, and it spends its
// samples where the sky is bright.
#include "lancer/shading/environment_light.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

#include "lancer/render_scene.h"

namespace lancer {
namespace {

// A scene of nothing but a sky, given as a function of the direction.
class SkyOnlyScene final : public RenderScene {
  public:
    explicit SkyOnlyScene(std::function<Color(const Vec3&)> sky) : m_sky(std::move(sky)) {}
    Color background(const Ray& ray) const override { return m_sky(glm::normalize(ray.direction)); }
    bool background_varies() const override { return true; }

    bool intersect(const Ray&, Hit&) const override { return false; }
    bool occluded(const Ray&) const override { return false; }
    const std::vector<const Light*>& lights() const override { return m_no_lights; }
    const std::vector<const Light*>& local_lights() const override { return m_no_lights; }
    const Camera& camera() const override { return m_camera; }
    const SceneOptions& options() const override { return m_options; }
    Bounds bounds() const override { return {}; }

  private:
    std::function<Color(const Vec3&)> m_sky;
    std::vector<const Light*> m_no_lights;
    Camera m_camera;
    SceneOptions m_options;
};

// A dim gradient and a small, very bright sun.
struct SunnySky {
    static constexpr double kSunCosRadius = 0.99875;  // about 0.05 rad
    static constexpr float kSunRadiance = 2000.0f;
    static Vec3 sun() { return glm::normalize(Vec3(0.4f, 0.8f, -0.3f)); }
    static Color radiance(const Vec3& d) {
        if (glm::dot(d, sun()) >= float(kSunCosRadius)) return Color(kSunRadiance);
        return Color(0.2f + 0.1f * d.y);
    }
    // The sky's integral over the sphere, in closed form: the gradient's
    // 0.2 * 4 pi (its y term integrates to 0) with the sun cap's share
    // replaced (the cap's y term is (1 + c) / 2 times its area at cos c).
    static double total() {
        const double cap = 2.0 * M_PI * (1.0 - kSunCosRadius);
        const double cap_dim = 0.2 * cap + 0.1 * cap * double(sun().y) * (1.0 + kSunCosRadius) / 2.0;
        return 0.2 * 4.0 * M_PI - cap_dim + kSunRadiance * cap;
    }
};

TEST(EnvironmentLight, DensityIntegratesToOneAndMatchesItsSamples) {
    const SkyOnlyScene scene(SunnySky::radiance);
    // The density is constant over each cell of the table: its integral is
    // the sum over cells of the value at the centre times the solid angle.
    constexpr int kColumns = 64, kRows = 32;
    const EnvironmentLight coarse(scene, kColumns, kRows);
    double integral = 0.0;
    for (int row = 0; row < kRows; ++row) {
        const double top = M_PI * row / kRows, bottom = M_PI * (row + 1) / kRows, middle = (top + bottom) / 2.0;
        for (int column = 0; column < kColumns; ++column) {
            const double phi = 2.0 * M_PI * (column + 0.5) / kColumns;
            const Vec3 centre(float(std::sin(middle) * std::cos(phi)), float(std::cos(middle)),
                              float(std::sin(middle) * std::sin(phi)));
            integral += coarse.pdf(centre) * 2.0 * M_PI / kColumns * (std::cos(top) - std::cos(bottom));
        }
    }
    EXPECT_NEAR(integral, 1.0, 1e-5);
    // The cells under the sun are drawn far more often than the rest.
    EXPECT_GT(coarse.pdf(SunnySky::sun()), 100.0f * coarse.pdf(-SunnySky::sun()));

    const EnvironmentLight light(scene);
    std::mt19937 random(1);
    // Every sample is a unit direction whose reported density is pdf()'s
    // and whose radiance is the sky's there.
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    for (int k = 0; k < 20000; ++k) {
        const Vec3 p(1.0f, 2.0f, 3.0f);
        const LightSample s = light.sample(p, Vec2(u(random), u(random)));
        ASSERT_NEAR(glm::length(s.wi), 1.0f, 1e-5f);
        ASSERT_GT(s.pdf, 0.0f);
        ASSERT_NEAR(s.pdf, light.pdf(s.wi), 1e-3f * s.pdf) << k;
        Ray ray;
        ray.direction = s.wi;
        ASSERT_EQ(s.radiance, scene.background(ray));
        ASSERT_FALSE(s.is_delta);
        ASSERT_NEAR(glm::length(s.point - p), EnvironmentLight::kDistance, 1e-4f * EnvironmentLight::kDistance);
    }
}

// sum(L / pdf) / N estimates the sky's integral without bias, and with a
// fraction of uniform sampling's noise: the sun is 1/2500 of the sphere and
// nearly all of its light.
TEST(EnvironmentLight, EstimatesTheSkysTotalWithLittleNoise) {
    const SkyOnlyScene scene(SunnySky::radiance);
    const EnvironmentLight light(scene);
    std::mt19937 random(2);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    constexpr int kSamples = 200000;
    double sum = 0.0, sum_squares = 0.0;
    for (int k = 0; k < kSamples; ++k) {
        const LightSample s = light.sample(Vec3(0.0f), Vec2(u(random), u(random)));
        const double estimate = double(s.radiance.r) / double(s.pdf);
        sum += estimate;
        sum_squares += estimate * estimate;
    }
    const double mean = sum / kSamples;
    const double deviation = std::sqrt(std::max(0.0, sum_squares / kSamples - mean * mean));
    const double standard_error = deviation / std::sqrt(double(kSamples));
    const double expected = SunnySky::total();
    EXPECT_NEAR(mean, expected, 4.0 * standard_error + 1e-3 * expected);
    // Uniform sampling's relative deviation, in closed form: the sun's
    // share p of the sphere makes it about sqrt((1 - p) / p) times the
    // mean, here near 50; the table's is a few percent of that.
    const double sun_share = (1.0 - SunnySky::kSunCosRadius) / 2.0;
    const double uniform_relative = std::sqrt((1.0 - sun_share) / sun_share) * 0.9;
    EXPECT_LT(deviation / mean, 0.05 * uniform_relative) << "relative deviation " << deviation / mean;
}

// A sky that is black everywhere still gives a density (uniform), so an
// estimator never divides by zero.
TEST(EnvironmentLight, BlackSkyIsUniform) {
    const SkyOnlyScene scene([](const Vec3&) { return Color(0.0f); });
    const EnvironmentLight light(scene, 16, 8);
    for (const Vec3 d : {Vec3(0, 1, 0), Vec3(0, -1, 0), Vec3(1, 0, 0), glm::normalize(Vec3(-1, 2, 3))})
        EXPECT_NEAR(light.pdf(d), 1.0f / (4.0f * kPi), 1e-5f);
    EXPECT_EQ(light.pdf(Vec3(0.0f)), 0.0f);
    EXPECT_EQ(light.pdf(Vec3(std::nanf(""), 0.0f, 0.0f)), 0.0f);
}

}  // namespace
}  // namespace lancer
