// POV's `average` weights at the extremes fuzz_patterns reaches: a weight
// past float's range made an average pigment's mean inf / inf = NaN
// (tests/fuzz/regressions/average_weight_past_float_range.patterns); the
// same weights now reach normal and texture averages through one helper.
#include "materials/average_weights.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace lancer {
namespace {

TEST(AverageWeights, DividedByTheirSum) {
    const std::vector<double> w = average_weights({1.0, 3.0});
    EXPECT_DOUBLE_EQ(w[0], 0.25);
    EXPECT_DOUBLE_EQ(w[1], 0.75);
}

TEST(AverageWeights, HugeWeightsAndOverflowingSumsStayFinite) {
    const std::vector<double> past_float = average_weights({1.0, 8.9e38});
    EXPECT_NEAR(past_float[0], 1.0 / 8.9e38, 1e-50);
    EXPECT_NEAR(past_float[1], 1.0, 1e-12);
    // 1e308 + 1e308 overflows double: the scaled sum does not.
    const std::vector<double> past_double = average_weights({1e308, 1e308, -1e308});
    for (double w : past_double) EXPECT_TRUE(std::isfinite(w));
    EXPECT_NEAR(past_double[0], 1.0, 1e-12);
    EXPECT_NEAR(past_double[2], -1.0, 1e-12);
}

TEST(AverageWeights, ZeroSumKeepsTheWeightsAndNonFiniteCountsAsZero) {
    const std::vector<double> cancelling = average_weights({2.0, -2.0});
    EXPECT_DOUBLE_EQ(cancelling[0], 2.0);
    EXPECT_DOUBLE_EQ(cancelling[1], -2.0);
    const std::vector<double> clamped = average_weights({1e300, -1e300});
    EXPECT_DOUBLE_EQ(clamped[0], 1e30);
    EXPECT_DOUBLE_EQ(clamped[1], -1e30);
    const std::vector<double> odd = average_weights({std::numeric_limits<double>::infinity(), std::nan(""), 2.0});
    EXPECT_DOUBLE_EQ(odd[0], 0.0);
    EXPECT_DOUBLE_EQ(odd[1], 0.0);
    EXPECT_DOUBLE_EQ(odd[2], 1.0);
    EXPECT_TRUE(average_weights({}).empty());
    const std::vector<double> zeros = average_weights({0.0, 0.0});
    EXPECT_EQ(zeros[0], 0.0);
}

}  // namespace
}  // namespace lancer
