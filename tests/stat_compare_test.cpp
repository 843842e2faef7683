// The statistical image comparison must accept two independent renders of
// the same image and reject one biased by 2%. "Renders" here are synthetic:
// each pixel averages exponentially distributed samples (standard deviation
// equal to the mean, as noisy as a diffuse path tracer's) around a smooth
// image.
#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "stat_compare.h"

namespace lancer::test {
namespace {

PixelStatistics synthetic_render(std::uint32_t seed, double bias, int samples) {
    PixelStatistics s;
    s.width = 32;
    s.height = 32;
    std::mt19937_64 rng(seed);
    std::exponential_distribution<double> unit(1.0);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            const glm::dvec3 truth(0.5 + 0.3 * std::sin(0.2 * x), 0.4 + 0.2 * std::cos(0.3 * y), 0.3);
            glm::dvec3 sum(0.0), sum2(0.0);
            for (int i = 0; i < samples; ++i) {
                const glm::dvec3 v = truth * (1.0 + bias) * unit(rng);
                sum += v;
                sum2 += v * v;
            }
            const glm::dvec3 mean = sum / double(samples);
            const glm::dvec3 variance = (sum2 / double(samples) - mean * mean) * (double(samples) / (samples - 1));
            s.mean.push_back(mean);
            s.variance_of_mean.push_back(variance / double(samples));
        }
    return s;
}

TEST(StatCompare, IndependentRendersAgree) {
    for (std::uint32_t seed : {1u, 2u, 3u, 4u}) {
        const ImageComparison c =
            compare_images(synthetic_render(seed, 0.0, 256), synthetic_render(seed + 100, 0.0, 256));
        EXPECT_TRUE(c.passed) << c.summary;
    }
}

TEST(StatCompare, TwoPercentBiasIsCaught) {
    const ImageComparison c = compare_images(synthetic_render(5, 0.02, 256), synthetic_render(6, 0.0, 256));
    EXPECT_FALSE(c.passed) << c.summary;
    EXPECT_LT(c.worst_x, 0) << "the whole-image test should be the one to catch it";
}

TEST(StatCompare, LocalErrorIsCaught) {
    PixelStatistics image = synthetic_render(7, 0.0, 256);
    image.mean[5 * 32 + 9].g *= 2.0;  // one pixel twice too bright
    const ImageComparison c = compare_images(image, synthetic_render(8, 0.0, 256));
    EXPECT_FALSE(c.passed) << c.summary;
    EXPECT_EQ(c.worst_x, 9);
    EXPECT_EQ(c.worst_y, 5);
}

TEST(StatCompare, BlockAveragingKeepsAgreement) {
    const ImageComparison c = compare_images(synthetic_render(9, 0.0, 64), synthetic_render(10, 0.0, 64), 0.01, 4);
    EXPECT_TRUE(c.passed) << c.summary;
    EXPECT_EQ(c.tests, 3 * 8 * 8 + 3);
}

}  // namespace
}  // namespace lancer::test
