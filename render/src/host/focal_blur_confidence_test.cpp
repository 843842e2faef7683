#include "host/focal_blur_confidence.h"

#include <gtest/gtest.h>

namespace lancer {
namespace {

Camera::FocalBlur blur(int least, int most, double variance = 1.0 / 10000.0, double confidence = 0.9) {
    Camera::FocalBlur b;
    b.aperture = 1.0f;
    b.samples_min = least;
    b.samples = most;
    b.variance = float(variance);
    b.confidence = float(confidence);
    return b;
}

Film::Accumulator constant_pixel(std::uint32_t n, double value) {
    Film::Accumulator pixel;
    pixel.count = n;
    pixel.sum = glm::dvec3(value * n);
    pixel.sum_squares = glm::dvec3(value * value * n);
    return pixel;
}

// Half its samples 0, half 1: the variance of the mean is 1/(4n).
Film::Accumulator split_pixel(std::uint32_t n) {
    Film::Accumulator pixel;
    pixel.count = n;
    pixel.sum = glm::dvec3(0.5 * n);
    pixel.sum_squares = glm::dvec3(0.5 * n);
    return pixel;
}

// POV's batches: the rings of the grid blur_samples covers, then fours.
TEST(FocalBlurConfidence, BatchesFollowPovsGridRings) {
    const FocalBlurConfidence big(blur(0, 50), 50);
    std::vector<std::uint32_t> ends;
    for (std::uint32_t taken = 0; taken < 50;) ends.push_back(taken = big.batch_end(taken));
    EXPECT_EQ(ends, (std::vector<std::uint32_t>{7, 13, 19, 23, 27, 31, 35, 37, 41, 45, 49, 50}));
    const FocalBlurConfidence nineteen(blur(0, 19), 19);
    EXPECT_EQ(nineteen.batch_end(0), 7u);
    EXPECT_EQ(nineteen.batch_end(7), 13u);
    EXPECT_EQ(nineteen.batch_end(13), 19u);
    const FocalBlurConfidence ten(blur(0, 10), 10);
    EXPECT_EQ(ten.batch_end(7), 10u);
    const FocalBlurConfidence five(blur(0, 5), 5);
    EXPECT_EQ(five.batch_end(0), 4u);
    EXPECT_EQ(five.batch_end(4), 5u);
    // A bokeh lens has no grid: fours from the first sample.
    const FocalBlurConfidence shaped(blur(0, 50), 50, /*bokeh=*/true);
    EXPECT_EQ(shaped.batch_end(0), 4u);
    EXPECT_EQ(shaped.batch_end(4), 8u);
    EXPECT_EQ(shaped.batch_end(48), 50u);
}

TEST(FocalBlurConfidence, ThresholdScalesTheVarianceByChiSquareQuantiles) {
    const FocalBlurConfidence confidence(blur(0, 19), 19);
    // T(n) = variance * q(n) / q(18), q the 10th percentile: q(18) = 10.865, q(7) = 2.833.
    EXPECT_NEAR(confidence.threshold(7), 1e-4 * 2.8331 / 10.8649, 1e-8);
    EXPECT_NEAR(confidence.threshold(18), 1e-4, 1e-9);
    EXPECT_EQ(FocalBlurConfidence(blur(0, 1), 1).threshold(1), 0.0);
}

TEST(FocalBlurConfidence, StopsAtABatchEndOnceTheMeanIsSure) {
    const FocalBlurConfidence confidence(blur(0, 37), 37);
    EXPECT_EQ(confidence.wanted(0, Film::Accumulator{}), 7u);
    EXPECT_EQ(confidence.wanted(7, constant_pixel(7, 0.4)), 0u);
    EXPECT_EQ(confidence.wanted(7, split_pixel(7)), 6u);
    EXPECT_EQ(confidence.wanted(5, constant_pixel(5, 0.4)), 2u);  // mid-batch: finish it
    EXPECT_EQ(confidence.wanted(37, split_pixel(37)), 0u);        // the most
    // Variance 0: never sure.
    EXPECT_EQ(FocalBlurConfidence(blur(0, 37, 0.0), 37).wanted(7, constant_pixel(7, 0.4)), 6u);
    // Not before MIN.
    const FocalBlurConfidence least(blur(20, 37), 37);
    EXPECT_EQ(least.wanted(13, constant_pixel(13, 0.4)), 6u);
    EXPECT_EQ(least.wanted(19, constant_pixel(19, 0.4)), 4u);
    EXPECT_EQ(least.wanted(23, constant_pixel(23, 0.4)), 0u);
    // T(7) = 1e-4 q(7) / q(36) = 1.07e-5: values spread by 0.008 (the
    // variance of their mean 9.1e-6) pass, by 0.009 (1.16e-5) do not.
    Film::Accumulator close;
    close.count = 7;
    close.sum = glm::dvec3(3.5);
    close.sum_squares = glm::dvec3(7 * (0.25 + 0.008 * 0.008));
    EXPECT_EQ(confidence.wanted(7, close), 0u);
    close.sum_squares = glm::dvec3(7 * (0.25 + 0.009 * 0.009));
    EXPECT_EQ(confidence.wanted(7, close), 6u);
}

}  // namespace
}  // namespace lancer
