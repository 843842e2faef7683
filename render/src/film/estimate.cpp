// The relative error estimate and the true relative error (definitions in
// estimate.h). Sums run in double over pixels in a fixed order, so the
// estimate is as deterministic as the film.
#include "lancer/host/estimate.h"

#include <cmath>
#include <stdexcept>

namespace lancer {
namespace {

PixelWindow whole(const Film& film) {
    return {0, 0, film.width(), film.height()};
}

bool empty(const PixelWindow& window) {
    return window.x1 <= window.x0 || window.y1 <= window.y0;
}

}  // namespace

double pixel_relative_variance(const Film& film, int x, int y) {
    if (film.sample_count(x, y) < 2) return 0.0;
    const Color mean = film.mean(x, y);
    const Color variance = film.variance_of_mean(x, y);
    double sum = 0.0;
    for (int c = 0; c < 3; ++c)
        sum += double(variance[c]) / (double(mean[c]) * double(mean[c]) + kRelativeErrorEpsilon);
    return sum / 3.0;
}

double estimated_relative_rmse(const Film& film) {
    return estimated_relative_rmse(film, whole(film));
}

double estimated_relative_rmse(const Film& film, const PixelWindow& window) {
    if (empty(window)) return 0.0;
    double sum = 0.0;
    for (int y = window.y0; y < window.y1; ++y)
        for (int x = window.x0; x < window.x1; ++x) sum += pixel_relative_variance(film, x, y);
    return std::sqrt(sum / (double(window.x1 - window.x0) * double(window.y1 - window.y0)));
}

double relative_rmse(const Film& image, const Film& reference) {
    return relative_rmse(image, reference, whole(image));
}

double relative_rmse(const Film& image, const Film& reference, const PixelWindow& window) {
    if (image.width() != reference.width() || image.height() != reference.height())
        throw std::invalid_argument("relative_rmse: image and reference differ in size");
    if (empty(window)) return 0.0;
    double sum = 0.0;
    for (int y = window.y0; y < window.y1; ++y)
        for (int x = window.x0; x < window.x1; ++x) {
            const Color value = image.mean(x, y), truth = reference.mean(x, y);
            for (int c = 0; c < 3; ++c) {
                const double difference = double(value[c]) - double(truth[c]);
                sum += difference * difference / (double(truth[c]) * double(truth[c]) + kRelativeErrorEpsilon);
            }
        }
    return std::sqrt(sum / (3.0 * double(window.x1 - window.x0) * double(window.y1 - window.y0)));
}

}  // namespace lancer
