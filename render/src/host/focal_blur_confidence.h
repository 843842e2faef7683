// POV-Ray's focal blur confidence test: a pixel of a focal-blurred render
// takes its blur samples in batches and stops between blur_samples MIN and
// MAX once the variance of its mean is small enough at the scene's
// `confidence`. Internal to liblancer.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/camera.h"
#include "lancer/host/film.h"

namespace lancer {

class FocalBlurConfidence {
  public:
    // `most` samples per pixel at most (at least the camera's blur_samples).
    // With a bokeh POV draws its lens points one by one (no hexagonal
    // grid), so batches are fours from the first.
    FocalBlurConfidence(const Camera::FocalBlur& blur, std::uint32_t most, bool bokeh = false);

    std::uint32_t most() const { return m_most; }

    // Samples a pixel holding `taken` takes next: the rest of its current
    // batch (POV's batches: the 7-, 6- and 6-point rings of its hexagonal
    // grids, then fours), or 0 when it has all it needs. A pixel stops at
    // the end of a batch, once it holds at least blur_samples MIN, when the
    // variance of its mean is below the threshold in every channel.
    std::uint32_t wanted(std::uint32_t taken, const Film::Accumulator& pixel) const;

    // The variance of the mean below which a pixel holding n samples stops
    // (0: never stops there): `variance` scaled by the chi-square quantiles
    // of n and of blur_samples - 1 degrees of freedom at the confidence.
    double threshold(std::uint32_t n) const;

    // The end of the batch a pixel holding `taken` samples is in.
    std::uint32_t batch_end(std::uint32_t taken) const;

  private:
    // Which batch ends at `end` (a value batch_end returns).
    std::size_t batch_index(std::uint32_t end) const;

    std::uint32_t m_most, m_least;
    double m_variance, m_confidence;
    double m_scale = 0.0;                    // variance / quantile(blur_samples - 1)
    std::vector<std::uint32_t> m_ring_ends;  // POV's grid rings, cumulative
    std::vector<double> m_end_thresholds;    // threshold(end) of every batch end
};

}  // namespace lancer
