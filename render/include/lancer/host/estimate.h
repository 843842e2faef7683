// Error estimates from the film's own statistics, and the matching true
// error against a reference. One definition, used by --noise, --stats and
// the tests (docs/rendering.md, "The error estimate"):
//
//   per pixel p, channel c, with m = mean, v = variance of the mean
//   (sample variance / n):
//     rel_var(p)        = 1/3 sum_c  v_c(p) / (m_c(p)^2 + eps)
//     estimated_rel_rmse = sqrt( mean_p rel_var(p) )
//   and against a reference r:
//     relative_rmse      = sqrt( mean_p 1/3 sum_c (m_c(p) - r_c(p))^2 / (r_c(p)^2 + eps) )
//
// eps = kRelativeErrorEpsilon keeps dark pixels from dominating: below a
// radiance of about 0.1 the error counts as absolute rather than relative
// (the relMSE of the adaptive-sampling literature).
#pragma once

#include "lancer/host/film.h"

namespace lancer {

inline constexpr double kRelativeErrorEpsilon = 0.01;

struct PixelWindow {
    int x0, y0, x1, y1;  // [x0, x1) x [y0, y1)
};

// rel_var(p) above; 0 for a pixel with fewer than two samples.
double pixel_relative_variance(const Film& film, int x, int y);

// sqrt(mean over the window of rel_var); the whole film by default.
double estimated_relative_rmse(const Film& film);
double estimated_relative_rmse(const Film& film, const PixelWindow& window);

// The true relative RMSE of `image` against `reference` (same size; throws
// std::invalid_argument otherwise), over the window or the whole film.
double relative_rmse(const Film& image, const Film& reference);
double relative_rmse(const Film& image, const Film& reference, const PixelWindow& window);

}  // namespace lancer
