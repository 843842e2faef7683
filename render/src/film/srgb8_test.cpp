// The 8-bit sRGB table (film/srgb8.h) against the formula it replaces:
// every code's threshold and its neighbours, a sweep over the floats of
// (0, 1), and the values outside it.
#include "film/srgb8.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <iterator>
#include <limits>

#include "lancer/host/image_io.h"

namespace lancer {
namespace {

unsigned formula_code(float linear) {
    const float encoded = linear_to_srgb(linear);
    if (!(encoded > 0.0f)) return 0;
    if (encoded >= 1.0f) return 255;
    return unsigned(encoded * 255.0f + 0.5f);
}

TEST(Srgb8, EveryStepIsWhereTheFormulaPutsIt) {
    // Around each code's threshold (the floats where the formula's code
    // changes), 64 floats either side agree.
    for (unsigned k = 1; k <= 255; ++k) {
        std::uint32_t low = 0, high = 0x3F800000u;
        while (high - low > 1) {
            const std::uint32_t middle = low + (high - low) / 2;
            (formula_code(std::bit_cast<float>(middle)) >= k ? high : low) = middle;
        }
        for (std::uint32_t bits = high - 64; bits <= high + 64; ++bits) {
            const float x = std::bit_cast<float>(bits);
            ASSERT_EQ(linear_to_srgb8(x), formula_code(x)) << "x = " << x << " near the step to " << k;
        }
    }
}

TEST(Srgb8, ASweepOverTheUnitIntervalAgrees) {
    for (std::uint32_t bits = 0; bits <= 0x3F800000u; bits += 997) {
        const float x = std::bit_cast<float>(bits);
        ASSERT_EQ(linear_to_srgb8(x), formula_code(x)) << "x = " << x;
    }
}

TEST(Srgb8, ValuesOutsideTheUnitInterval) {
    EXPECT_EQ(linear_to_srgb8(-1.0f), 0);
    EXPECT_EQ(linear_to_srgb8(-0.0f), 0);
    EXPECT_EQ(linear_to_srgb8(std::numeric_limits<float>::quiet_NaN()), 0);
    EXPECT_EQ(linear_to_srgb8(1.0f), 255);
    EXPECT_EQ(linear_to_srgb8(7.5f), 255);
    EXPECT_EQ(linear_to_srgb8(std::numeric_limits<float>::infinity()), 255);
    EXPECT_EQ(linear_to_srgb8(0.5f), 188);  // 255 (1.055 * 0.5^(1/2.4) - 0.055) = 187.5...
}

TEST(Srgb8, ARowGetsEachValuesCode) {
    const float row[] = {
        -1.0f, 0.0f, 0.0031308f, 0.2f, 0.5f, 0.99999994f, 1.0f, std::numeric_limits<float>::quiet_NaN(), 3.0f};
    std::uint8_t codes[std::size(row)] = {};
    linear_to_srgb8(row, codes, std::size(row));
    for (std::size_t i = 0; i < std::size(row); ++i) EXPECT_EQ(codes[i], formula_code(row[i])) << "x = " << row[i];
}

}  // namespace
}  // namespace lancer
