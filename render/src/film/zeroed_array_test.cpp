#include "lancer/host/zeroed_array.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <glm/glm.hpp>

namespace lancer {
namespace {

template <typename T>
bool all_zero(const ZeroedArray<T>& array) {
    for (const T& element : array)
        if (element != T(0)) return false;
    return true;
}

TEST(ZeroedArray, EverySizeStartsAtZero) {
    // Small arrays come from calloc, large ones from a mapping of their own.
    for (std::size_t size : {std::size_t(0), std::size_t(1), std::size_t(1000), std::size_t(3) << 20}) {
        ZeroedArray<std::uint32_t> counts(size);
        EXPECT_EQ(counts.size(), size);
        EXPECT_TRUE(all_zero(counts)) << size;
        ZeroedArray<glm::dvec3> sums(size);
        EXPECT_TRUE(all_zero(sums)) << size;
    }
}

TEST(ZeroedArray, CopiesAndMovesKeepTheValues) {
    ZeroedArray<float> values((std::size_t(1) << 20) + 7);  // past the 2 MiB of a mapping of its own
    for (std::size_t i = 0; i < values.size(); i += 4097) values[i] = float(i);
    ZeroedArray<float> copy = values;
    ASSERT_EQ(copy.size(), values.size());
    for (std::size_t i = 0; i < copy.size(); ++i) ASSERT_EQ(copy[i], values[i]) << i;
    ZeroedArray<float> moved = std::move(copy);
    EXPECT_EQ(copy.size(), 0u);
    EXPECT_EQ(moved[4097], 4097.0f);
    moved = ZeroedArray<float>(3);
    EXPECT_EQ(moved.size(), 3u);
    EXPECT_TRUE(all_zero(moved));
}

}  // namespace
}  // namespace lancer
