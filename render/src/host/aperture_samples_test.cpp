// The lens points of focal blur: POV's grids for the classic integrators,
// uniform over the disc for the Monte Carlo ones.
#include "host/aperture_samples.h"

#include <gtest/gtest.h>

#include <cmath>
#include <set>

namespace lancer {
namespace {

TEST(ApertureSamples, ConcentricMapIsUniformOverTheDiscOfRadiusOneHalf) {
    // E[r^2] = R^2 / 2 and the mean is the centre for a uniform disc.
    double r2 = 0.0, mean_x = 0.0, mean_y = 0.0;
    constexpr int kSide = 200;
    for (int i = 0; i < kSide; ++i)
        for (int j = 0; j < kSide; ++j) {
            const Vec2 p = concentric_disc_point(Vec2((i + 0.5f) / kSide, (j + 0.5f) / kSide));
            ASSERT_LE(glm::length(p), 0.5f + 1e-6f);
            r2 += glm::dot(p, p);
            mean_x += p.x;
            mean_y += p.y;
        }
    const double n = double(kSide) * kSide;
    EXPECT_NEAR(r2 / n, 0.125, 1e-3);
    EXPECT_NEAR(mean_x / n, 0.0, 1e-6);
    EXPECT_NEAR(mean_y / n, 0.0, 1e-6);
}

TEST(ApertureSamples, PovGridsAreHexagonalAndStayOnTheLens) {
    for (int samples : {4, 7, 19, 37, 60}) {
        const ApertureSamples lens(samples, true);
        std::set<std::pair<int, int>> distinct;
        for (int s = 0; s < samples; ++s) {
            // The centre of each jitter cell (u = 0.5) is the grid point.
            const Vec2 centre = lens.point(std::uint32_t(s), Vec2(0.5f));
            distinct.insert({int(std::lround(centre.x * 1e4)), int(std::lround(centre.y * 1e4))});
            for (const Vec2 u : {Vec2(0.0f), Vec2(0.999f), Vec2(0.0f, 0.999f)})
                EXPECT_LE(glm::length(lens.point(std::uint32_t(s), u)), 0.5f * std::sqrt(2.0f) + 1e-6f);
        }
        EXPECT_EQ(int(distinct.size()), samples) << samples << " samples";
    }
    // 7 samples: the centre and a hexagon at 1/(2 sqrt 3), POV's grid.
    const ApertureSamples seven(7, true);
    int on_ring = 0;
    for (int s = 0; s < 7; ++s) {
        const float r = glm::length(seven.point(std::uint32_t(s), Vec2(0.5f)));
        if (std::fabs(r - 0.288675f) < 1e-5f) ++on_ring;
    }
    EXPECT_EQ(on_ring, 6);
}

TEST(ApertureSamples, MonteCarloLensIgnoresTheSampleIndex) {
    const ApertureSamples lens(37, false);
    EXPECT_EQ(lens.point(0, Vec2(0.3f, 0.8f)), lens.point(5, Vec2(0.3f, 0.8f)));
    EXPECT_EQ(lens.point(0, Vec2(0.3f, 0.8f)), concentric_disc_point(Vec2(0.3f, 0.8f)));
}

}  // namespace
}  // namespace lancer
