// Per-pixel z-tests with Šidák correction; see stat_compare.h.
#include "stat_compare.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace lancer::test {

PixelStatistics PixelStatistics::from_film(const Film& film) {
    PixelStatistics s;
    s.width = film.width();
    s.height = film.height();
    s.mean.reserve(std::size_t(s.width) * s.height);
    s.variance_of_mean.reserve(std::size_t(s.width) * s.height);
    for (int y = 0; y < s.height; ++y)
        for (int x = 0; x < s.width; ++x) {
            s.mean.push_back(glm::dvec3(film.mean(x, y)));
            s.variance_of_mean.push_back(glm::dvec3(film.variance_of_mean(x, y)));
        }
    return s;
}

PixelStatistics PixelStatistics::block_average(int block) const {
    if (block <= 1) return *this;
    PixelStatistics out;
    out.width = (width + block - 1) / block;
    out.height = (height + block - 1) / block;
    out.mean.assign(std::size_t(out.width) * out.height, glm::dvec3(0.0));
    out.variance_of_mean.assign(out.mean.size(), glm::dvec3(0.0));
    std::vector<int> count(out.mean.size(), 0);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t o = std::size_t(y / block) * out.width + x / block;
            const std::size_t i = std::size_t(y) * width + x;
            out.mean[o] += mean[i];
            out.variance_of_mean[o] += variance_of_mean[i];
            ++count[o];
        }
    for (std::size_t o = 0; o < out.mean.size(); ++o) {
        out.mean[o] /= double(count[o]);
        out.variance_of_mean[o] /= double(count[o]) * double(count[o]);
    }
    return out;
}

namespace {

// Two-sided p-value of a standard normal deviate.
double two_sided_p(double z) {
    return std::erfc(std::abs(z) / std::sqrt(2.0));
}

// z of a difference of means with standard error sqrt(variance); identical
// noiseless values give 0, differing ones infinity.
double z_score(double difference, double variance) {
    if (variance > 0.0) return difference / std::sqrt(variance);
    return std::abs(difference) <= 1e-7 ? 0.0 : std::copysign(INFINITY, difference);
}

}  // namespace

ImageComparison compare_images(const PixelStatistics& image, const PixelStatistics& reference, double alpha, int block,
                               double absolute_tolerance) {
    if (image.width != reference.width || image.height != reference.height)
        throw std::invalid_argument("compare_images: images differ in size");
    const PixelStatistics a = image.block_average(block);
    const PixelStatistics b = reference.block_average(block);

    ImageComparison result;
    const std::size_t pixels = a.mean.size();
    result.tests = int(3 * pixels + 3);
    // Šidák: 1 - (1 - alpha)^(1/m), computed without cancellation.
    result.per_test_alpha = -std::expm1(std::log1p(-alpha) / result.tests);

    auto consider = [&](double z, int x, int y, int channel) {
        const double p = two_sided_p(z);
        if (p < result.min_p_value || result.worst_channel < 0) {
            result.min_p_value = p;
            result.worst_z = z;
            result.worst_x = x;
            result.worst_y = y;
            result.worst_channel = channel;
        }
    };

    auto shrink = [&](double d) { return std::copysign(std::max(0.0, std::abs(d) - absolute_tolerance), d); };
    glm::dvec3 sum_difference(0.0), sum_variance(0.0);
    for (std::size_t i = 0; i < pixels; ++i) {
        glm::dvec3 difference = a.mean[i] - b.mean[i];
        for (int c = 0; c < 3; ++c) difference[c] = shrink(difference[c]);
        const glm::dvec3 variance = a.variance_of_mean[i] + b.variance_of_mean[i];
        sum_difference += difference;
        sum_variance += variance;
        for (int c = 0; c < 3; ++c)
            consider(z_score(difference[c], variance[c]), int(i % a.width), int(i / a.width), c);
    }
    // The whole image: mean of differences, variance of that mean.
    for (int c = 0; c < 3; ++c) {
        const double z =
            z_score(sum_difference[c] / double(pixels), sum_variance[c] / (double(pixels) * double(pixels)));
        result.image_z[c] = z;
        consider(z, -1, -1, c);
    }

    result.passed = result.min_p_value >= result.per_test_alpha;
    std::ostringstream text;
    text << (result.passed ? "images agree" : "images differ") << ": min p " << result.min_p_value
         << " vs per-test level " << result.per_test_alpha << " (" << result.tests << " tests, block "
         << std::max(block, 1) << "); worst z " << result.worst_z << " at ";
    if (result.worst_x < 0)
        text << "the whole-image mean";
    else
        text << "(" << result.worst_x << ", " << result.worst_y << ")";
    text << " channel " << result.worst_channel << "; whole-image z (" << result.image_z[0] << ", " << result.image_z[1]
         << ", " << result.image_z[2] << ")";
    result.summary = text.str();
    return result;
}

}  // namespace lancer::test
