// Statistical comparison of a stochastic render with a reference, for the
// golden tests of Monte Carlo integrators (after Mitsuba's render tests).
//
// Each pixel (or block of pixels) of both images carries a mean and the
// variance of that mean. For every pixel and channel the test asks whether
// the two means could differ by noise alone (z = difference / combined
// standard error, two-sided); one more test does the same for the mean of
// the whole image, which catches a small global bias that no single pixel
// shows. The family's significance is Šidák-corrected: each of the m tests
// runs at 1 - (1 - alpha)^(1/m), so two unbiased renders fail with
// probability alpha whatever the image size, while a bias shows as soon as
// it is a few standard errors of the mean.
//
// Use enough samples that per-pixel variance estimates are sound (>= 64 per
// pixel, or average blocks), since the z-test trusts them.
#pragma once

#include <string>
#include <vector>

#include <glm/glm.hpp>

#include "lancer/host/film.h"

namespace lancer::test {

// Per-pixel mean and variance of the mean, linear RGB, row-major.
struct PixelStatistics {
    int width = 0;
    int height = 0;
    std::vector<glm::dvec3> mean;
    std::vector<glm::dvec3> variance_of_mean;

    static PixelStatistics from_film(const Film& film);
    // Means of block x block tiles (edge tiles cropped); their variance is
    // the sum of the pixels' over block^2 squared (pixels are independent).
    PixelStatistics block_average(int block) const;
};

struct ImageComparison {
    bool passed = false;
    int tests = 0;                // pixel-channel tests + the whole-image test
    double per_test_alpha = 0.0;  // Šidák-corrected level of each test
    double min_p_value = 1.0;
    int worst_x = -1, worst_y = -1, worst_channel = -1;  // -1 x: the whole image
    double worst_z = 0.0;
    double image_z[3] = {0.0, 0.0, 0.0};  // whole-image mean difference, in std errors
    std::string summary;                  // one line for test failure messages
};

// Compares `image` with `reference` (same size) at family-wise significance
// `alpha`. `block` > 1 compares block averages instead of pixels.
// `absolute_tolerance` is subtracted from every |difference| before its z is
// taken: for estimators that reach some pixels only through rare events
// (BSDF sampling of a small light), whose variance estimate is then 0 at
// any affordable sample count.
ImageComparison compare_images(const PixelStatistics& image, const PixelStatistics& reference, double alpha = 0.01,
                               int block = 1, double absolute_tolerance = 0.0);

}  // namespace lancer::test
