// Image metrics on images with known answers.
#include "image_metrics.h"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace lancer {
namespace {

// A smooth gradient with some structure: a checker of two greys over a ramp.
RgbImage test_pattern(int width = 48, int height = 32) {
    RgbImage image(width, height);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const float ramp = 0.1f + 0.6f * float(x) / float(width);
            const float checker = ((x / 8 + y / 8) % 2) ? 0.2f : 0.0f;
            image.at(x, y) = Color(ramp + checker, ramp, 0.5f * ramp + checker);
        }
    return image;
}

RgbImage with_noise(const RgbImage& image, float sigma, unsigned seed) {
    std::mt19937 random(seed);
    std::normal_distribution<float> noise(0.0f, sigma);
    RgbImage noisy = image;
    for (Color& pixel : noisy.pixels)
        pixel = glm::max(pixel + Color(noise(random), noise(random), noise(random)), 0.0f);
    return noisy;
}

TEST(ImageMetrics, IdenticalImagesHaveNoError) {
    const RgbImage image = test_pattern();
    EXPECT_DOUBLE_EQ(rmse(image, image), 0.0);
    EXPECT_DOUBLE_EQ(relative_mse(image, image), 0.0);
    EXPECT_NEAR(ssim(image, image), 1.0, 1e-12);
}

TEST(ImageMetrics, RmseOfAConstantOffsetIsTheOffset) {
    RgbImage reference(10, 10), image(10, 10);
    for (Color& pixel : image.pixels) pixel = Color(0.25f);
    EXPECT_NEAR(rmse(image, reference), 0.25, 1e-7);
    // One channel off by 0.3 in one pixel of four: sqrt(0.09 / 12).
    RgbImage small_reference(2, 2), small_image(2, 2);
    small_image.at(1, 0).g = 0.3f;
    EXPECT_NEAR(rmse(small_image, small_reference), std::sqrt(0.09 / 12.0), 1e-7);
}

TEST(ImageMetrics, RelativeMseDividesByTheReference) {
    RgbImage reference(4, 4), image(4, 4);
    for (Color& pixel : reference.pixels) pixel = Color(2.0f);
    for (Color& pixel : image.pixels) pixel = Color(3.0f);
    EXPECT_NEAR(relative_mse(image, reference), 1.0 / (4.0 + kRelativeErrorEpsilon), 1e-7);
    // Against black, ε alone is the denominator.
    RgbImage black(4, 4);
    for (Color& pixel : image.pixels) pixel = Color(0.1f);
    EXPECT_NEAR(relative_mse(image, black), 0.01 / kRelativeErrorEpsilon, 1e-6);
}

TEST(ImageMetrics, SsimFallsAsNoiseGrows) {
    const RgbImage reference = test_pattern();
    const double light = ssim(with_noise(reference, 0.02f, 1), reference);
    const double heavy = ssim(with_noise(reference, 0.2f, 2), reference);
    EXPECT_LT(light, 1.0);
    EXPECT_GT(light, 0.5);
    EXPECT_LT(heavy, light);
    EXPECT_GT(heavy, -1.0);
    // Symmetric in its arguments.
    const RgbImage noisy = with_noise(reference, 0.1f, 3);
    EXPECT_NEAR(ssim(noisy, reference), ssim(reference, noisy), 1e-12);
}

TEST(ImageMetrics, SsimSeesABiasedButSmoothImage) {
    const RgbImage reference = test_pattern();
    RgbImage darker = reference;
    for (Color& pixel : darker.pixels) pixel *= 0.5f;
    EXPECT_LT(ssim(darker, reference), 0.99);
}

TEST(ImageMetrics, SizesMustMatch) {
    EXPECT_THROW(rmse(RgbImage(2, 2), RgbImage(3, 2)), std::invalid_argument);
    EXPECT_THROW(ssim(RgbImage(2, 2), RgbImage(2, 3)), std::invalid_argument);
}

TEST(ImageMetrics, HeatMapRampIsOrderedAndClamped) {
    EXPECT_EQ(heat_map_colour(0.0), heat_map_colour(kHeatMapMinimum / 10));
    EXPECT_EQ(heat_map_colour(kHeatMapMaximum), heat_map_colour(kHeatMapMaximum * 10));
    // Brightness (sum of channels) grows along the ramp.
    double previous = -1.0;
    for (double e = kHeatMapMinimum; e <= kHeatMapMaximum * 1.0001; e *= 1.5) {
        const Color c = heat_map_colour(e);
        const double brightness = c.r + c.g + c.b;
        EXPECT_GE(brightness, previous - 1e-6) << "at " << e;
        previous = brightness;
    }
    const RgbImage reference = test_pattern();
    EXPECT_EQ(error_heat_map(reference, reference).width, reference.width);
}

TEST(ImageMetrics, RelativeErrorMapIsPerPixel) {
    RgbImage reference(3, 1), image(3, 1);
    for (Color& pixel : reference.pixels) pixel = Color(1.0f);
    image.at(0, 0) = Color(1.0f);
    image.at(1, 0) = Color(1.5f);
    image.at(2, 0) = Color(0.0f);
    const RgbImage map = relative_error_map(image, reference);
    EXPECT_NEAR(map.at(0, 0).r, 0.0, 1e-7);
    EXPECT_NEAR(map.at(1, 0).r, 0.5 / std::sqrt(1.0 + kRelativeErrorEpsilon), 1e-6);
    EXPECT_NEAR(map.at(2, 0).r, 1.0 / std::sqrt(1.0 + kRelativeErrorEpsilon), 1e-6);
}

}  // namespace
}  // namespace lancer
