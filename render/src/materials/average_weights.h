// The weights of POV's `average` (pigment, normal and texture maps): what
// each entry counts for in the mean. Internal to liblancer.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

namespace lancer {

// `values` divided by their sum, as POV-Ray divides the weighted sum by
// the total; kept as written when they sum to 0. Worked in double after
// scaling by the largest magnitude, so weights anywhere in double's range
// (past float's, or whose sum overflows: fuzzing found 8.9e38) give a
// finite mean; a non-finite weight counts as 0, and every result is
// clamped to +-1e30 so float arithmetic on it stays finite.
inline std::vector<double> average_weights(const std::vector<double>& values) {
    std::vector<double> weights(values.size(), 0.0);
    double largest = 0.0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        weights[i] = std::isfinite(values[i]) ? values[i] : 0.0;
        largest = std::max(largest, std::fabs(weights[i]));
    }
    double scaled_total = 0.0;
    if (largest > 0.0)
        for (double w : weights) scaled_total += w / largest;
    for (double& w : weights) {
        if (scaled_total != 0.0) w = w / largest / scaled_total;
        w = std::clamp(w, -1e30, 1e30);
    }
    return weights;
}

}  // namespace lancer
