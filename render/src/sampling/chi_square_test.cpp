#include "sampling/chi_square.h"

#include <gtest/gtest.h>

#include <cmath>

namespace lancer {
namespace {

// Percentiles from the standard chi-square tables.
TEST(ChiSquare, UpperQuantilesMatchTheTables) {
    struct Row {
        double degrees, upper_tail, x;
    };
    for (const Row& row : {Row{1, 0.9, 0.01579}, Row{2, 0.9, 0.2107}, Row{3, 0.9, 0.5844}, Row{5, 0.9, 1.6103},
                           Row{10, 0.9, 4.8652}, Row{20, 0.9, 12.4426}, Row{30, 0.9, 20.5992}, Row{100, 0.9, 82.3581},
                           Row{1, 0.05, 3.8415}, Row{10, 0.05, 18.3070}, Row{100, 0.05, 124.3421}, Row{2, 0.5, 1.3863}})
        EXPECT_NEAR(chi_square_upper_quantile(row.degrees, row.upper_tail), row.x, 1e-4 * std::max(1.0, row.x))
            << row.degrees << " degrees, tail " << row.upper_tail;
}

// Two degrees of freedom have a closed form, x = -2 ln(tail); and the
// approximation past 1000 degrees joins the exact values smoothly.
TEST(ChiSquare, ClosedFormAndLargeDegrees) {
    for (double tail : {0.999, 0.9, 0.5, 0.1, 1e-6})
        EXPECT_NEAR(chi_square_upper_quantile(2.0, tail), -2.0 * std::log(tail), 1e-8 * (1.0 - 2.0 * std::log(tail)));
    const double exact = chi_square_upper_quantile(1000.0, 0.9), approximate = chi_square_upper_quantile(1000.001, 0.9);
    EXPECT_NEAR(approximate, exact, 1e-4 * exact);
    EXPECT_NEAR(chi_square_upper_quantile(65535.0, 0.9), 65072.0, 5.0);
    EXPECT_TRUE(std::isnan(chi_square_upper_quantile(0.0, 0.9)));
    EXPECT_TRUE(std::isnan(chi_square_upper_quantile(5.0, 1.0)));
}

}  // namespace
}  // namespace lancer
