// Image error metrics against a reference.
#include "image_metrics.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>
#include <vector>

#include "lancer/host/image_io.h"

namespace lancer {
namespace {

void require_same_size(const RgbImage& image, const RgbImage& reference) {
    if (!image.same_size(reference) || image.pixels.empty())
        throw std::invalid_argument("image metrics need two non-empty images of the same size, got " +
                                    std::to_string(image.width) + "x" + std::to_string(image.height) + " and " +
                                    std::to_string(reference.width) + "x" + std::to_string(reference.height));
}

// Luma of the displayed pixel: what SSIM, a perceptual metric, should see.
std::vector<double> display_luma(const RgbImage& image) {
    std::vector<double> luma(image.pixels.size());
    for (std::size_t i = 0; i < luma.size(); ++i) {
        const Color& c = image.pixels[i];
        luma[i] = 0.2126 * linear_to_srgb(c.r) + 0.7152 * linear_to_srgb(c.g) + 0.0722 * linear_to_srgb(c.b);
    }
    return luma;
}

constexpr int kSsimRadius = 5;  // 11×11 window
constexpr double kSsimSigma = 1.5;

// Gaussian-weighted local mean of `values`, separable, with the window cut
// at the border and its weights renormalised (so tiny images still work).
std::vector<double> gaussian_blur(const std::vector<double>& values, int width, int height) {
    std::array<double, 2 * kSsimRadius + 1> kernel{};
    for (int i = -kSsimRadius; i <= kSsimRadius; ++i)
        kernel[i + kSsimRadius] = std::exp(-0.5 * i * i / (kSsimSigma * kSsimSigma));
    std::vector<double> horizontal(values.size()), result(values.size());
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0.0, weight = 0.0;
            for (int i = std::max(-kSsimRadius, -x); i <= std::min(kSsimRadius, width - 1 - x); ++i) {
                sum += kernel[i + kSsimRadius] * values[std::size_t(y) * width + x + i];
                weight += kernel[i + kSsimRadius];
            }
            horizontal[std::size_t(y) * width + x] = sum / weight;
        }
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            double sum = 0.0, weight = 0.0;
            for (int i = std::max(-kSsimRadius, -y); i <= std::min(kSsimRadius, height - 1 - y); ++i) {
                sum += kernel[i + kSsimRadius] * horizontal[std::size_t(y + i) * width + x];
                weight += kernel[i + kSsimRadius];
            }
            result[std::size_t(y) * width + x] = sum / weight;
        }
    return result;
}

double squared_relative_error(const Color& value, const Color& reference) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double d = double(value[k]) - double(reference[k]);
        sum += d * d / (double(reference[k]) * reference[k] + kRelativeErrorEpsilon);
    }
    return sum / 3.0;
}

}  // namespace

double rmse(const RgbImage& image, const RgbImage& reference) {
    require_same_size(image, reference);
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) {
            const double d = double(image.pixels[i][k]) - double(reference.pixels[i][k]);
            sum += d * d;
        }
    return std::sqrt(sum / (3.0 * double(image.pixels.size())));
}

double relative_mse(const RgbImage& image, const RgbImage& reference) {
    require_same_size(image, reference);
    double sum = 0.0;
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        sum += squared_relative_error(image.pixels[i], reference.pixels[i]);
    return sum / double(image.pixels.size());
}

double ssim(const RgbImage& image, const RgbImage& reference) {
    require_same_size(image, reference);
    const int w = image.width, h = image.height;
    const std::vector<double> x = display_luma(image), y = display_luma(reference);
    std::vector<double> xx(x.size()), yy(x.size()), xy(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        xx[i] = x[i] * x[i];
        yy[i] = y[i] * y[i];
        xy[i] = x[i] * y[i];
    }
    const std::vector<double> mean_x = gaussian_blur(x, w, h), mean_y = gaussian_blur(y, w, h);
    const std::vector<double> mean_xx = gaussian_blur(xx, w, h), mean_yy = gaussian_blur(yy, w, h);
    const std::vector<double> mean_xy = gaussian_blur(xy, w, h);
    // Wang et al.'s constants for a dynamic range of 1.
    constexpr double c1 = 0.01 * 0.01, c2 = 0.03 * 0.03;
    double sum = 0.0;
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double var_x = mean_xx[i] - mean_x[i] * mean_x[i];
        const double var_y = mean_yy[i] - mean_y[i] * mean_y[i];
        const double cov = mean_xy[i] - mean_x[i] * mean_y[i];
        sum += (2.0 * mean_x[i] * mean_y[i] + c1) * (2.0 * cov + c2) /
               ((mean_x[i] * mean_x[i] + mean_y[i] * mean_y[i] + c1) * (var_x + var_y + c2));
    }
    return sum / double(x.size());
}

RgbImage relative_error_map(const RgbImage& image, const RgbImage& reference) {
    require_same_size(image, reference);
    RgbImage map(image.width, image.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        map.pixels[i] = Color(float(std::sqrt(squared_relative_error(image.pixels[i], reference.pixels[i]))));
    return map;
}

Color heat_map_colour(double relative_error) {
    // Stops of a perceptually ordered dark-to-bright ramp (after matplotlib's
    // "inferno"), spaced evenly in log10 of the error.
    static constexpr std::array<Color, 6> stops = {Color(0.00f, 0.00f, 0.02f), Color(0.26f, 0.04f, 0.41f),
                                                   Color(0.58f, 0.15f, 0.40f), Color(0.87f, 0.32f, 0.23f),
                                                   Color(0.99f, 0.65f, 0.04f), Color(0.99f, 1.00f, 0.64f)};
    if (!(relative_error > kHeatMapMinimum)) return stops.front();  // also NaN
    const double t = std::clamp(
        std::log10(relative_error / kHeatMapMinimum) / std::log10(kHeatMapMaximum / kHeatMapMinimum), 0.0, 1.0);
    const double position = t * double(stops.size() - 1);
    const std::size_t i = std::min(std::size_t(position), stops.size() - 2);
    const float f = float(position - double(i));
    return stops[i] * (1.0f - f) + stops[i + 1] * f;
}

RgbImage error_heat_map(const RgbImage& image, const RgbImage& reference) {
    RgbImage map = relative_error_map(image, reference);
    for (Color& pixel : map.pixels) {
        const Color display = heat_map_colour(pixel.r);
        pixel = Color(srgb_to_linear(display.r), srgb_to_linear(display.g), srgb_to_linear(display.b));
    }
    return map;
}

}  // namespace lancer
