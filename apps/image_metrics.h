// How far a render is from a reference: the numbers `lancer trade` plots.
// All take two images of the same size (std::invalid_argument otherwise).
#pragma once

#include "lancer/host/estimate.h"  // kRelativeErrorEpsilon, shared with --noise
#include "lancer/host/rgb_image.h"

namespace lancer {

// Root mean square of (x − r) over every pixel and channel, linear RGB.
double rmse(const RgbImage& image, const RgbImage& reference);

// Mean over pixels and channels of (x − r)² / (r² + ε), ε =
// kRelativeErrorEpsilon (0.01, as in the adaptive-sampling literature):
// errors in dark regions count as much as bright ones. The square of
// estimate.h's relative_rmse, so trade's numbers and --noise's agree.
double relative_mse(const RgbImage& image, const RgbImage& reference);

// Mean structural similarity (Wang et al. 2004) of the two images' luma:
// each channel clamped and sRGB-encoded as displayed, then Y' = Rec. 709
// weights; 11×11 Gaussian window, σ = 1.5, C1 = 0.01², C2 = 0.03²; windows
// are cut at the image border and renormalised. 1 for identical images,
// lower for noise, blur or bias.
double ssim(const RgbImage& image, const RgbImage& reference);

// Per pixel, sqrt of the channel-mean of (x − r)² / (r² + ε): the relative
// error a heat map shows. Stored in every channel of the result.
RgbImage relative_error_map(const RgbImage& image, const RgbImage& reference);

// A display colour (sRGB-encoded, each channel in [0, 1]) for a relative
// error on a logarithmic ramp: kHeatMapMinimum and below black, through
// purple, red and orange to pale yellow at kHeatMapMaximum and above.
inline constexpr double kHeatMapMinimum = 0.001;
inline constexpr double kHeatMapMaximum = 1.0;
Color heat_map_colour(double relative_error);

// The error map coloured by heat_map_colour, as a linear image ready for
// write_rgb_image (which encodes it back to the ramp's sRGB colours).
RgbImage error_heat_map(const RgbImage& image, const RgbImage& reference);

}  // namespace lancer
