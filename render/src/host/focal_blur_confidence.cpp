// The rules of POV-Ray 3.7's TraceRayWithFocalBlur (tracepixel.cpp, read
// for them): batches sized by the rings of the standard grid blur_samples
// covers, and after each the test |(S2/n - (S1/n)^2) / n| < T(n) in every
// channel, with T(n) = variance * chdtri(n) / chdtri(blur_samples - 1)
// (chdtri at the confidence). A MIN of 0 (blur_samples N alone) tests from
// the first batch on.
#include "host/focal_blur_confidence.h"

#include <algorithm>
#include <cmath>

#include "sampling/chi_square.h"

namespace lancer {
namespace {

constexpr std::uint32_t kBatchAfterRings = 4;

}  // namespace

FocalBlurConfidence::FocalBlurConfidence(const Camera::FocalBlur& blur, std::uint32_t most, bool bokeh)
    : m_most(std::max(most, 1u)),
      m_least(std::uint32_t(std::max(blur.samples_min, 0))),
      m_variance(blur.variance),
      m_confidence(blur.confidence) {
    const int samples = blur.samples;
    // POV's standard grids: hexagons of 37, 19 and 7 points taken ring by
    // ring (its lists of batch sizes), else batches of four throughout.
    std::vector<std::uint32_t> rings;
    if (bokeh)
        rings.clear();  // fours only
    else if (samples >= 37)
        rings = {7, 6, 6, 4, 4, 4, 4, 2};
    else if (samples >= 19)
        rings = {7, 6, 6};
    else if (samples >= 7)
        rings = {7};
    std::uint32_t end = 0;
    for (std::uint32_t ring : rings) m_ring_ends.push_back(end += ring);
    if (samples > 1) m_scale = m_variance / chi_square_upper_quantile(double(samples - 1), m_confidence);
    for (std::uint32_t taken = 0; taken < m_most;) {
        taken = batch_end(taken);
        m_end_thresholds.push_back(threshold(taken));
    }
}

double FocalBlurConfidence::threshold(std::uint32_t n) const {
    if (m_scale <= 0.0 || n == 0) return 0.0;
    const double value = m_scale * chi_square_upper_quantile(double(n), m_confidence);
    return std::isfinite(value) ? value : 0.0;
}

std::uint32_t FocalBlurConfidence::batch_end(std::uint32_t taken) const {
    for (std::uint32_t end : m_ring_ends)
        if (end > taken) return std::min(end, m_most);
    const std::uint32_t after = m_ring_ends.empty() ? 0 : m_ring_ends.back();
    const std::uint32_t batches = (taken - after) / kBatchAfterRings + 1;
    return std::uint32_t(std::min<std::uint64_t>(after + std::uint64_t(batches) * kBatchAfterRings, m_most));
}

std::size_t FocalBlurConfidence::batch_index(std::uint32_t end) const {
    const auto ring = std::lower_bound(m_ring_ends.begin(), m_ring_ends.end(), end);
    if (ring != m_ring_ends.end() && *ring == end) return std::size_t(ring - m_ring_ends.begin());
    const std::uint32_t after = m_ring_ends.empty() ? 0 : m_ring_ends.back();
    return m_ring_ends.size() + (end - after - 1) / kBatchAfterRings;
}

std::uint32_t FocalBlurConfidence::wanted(std::uint32_t taken, const Film::Accumulator& pixel) const {
    if (taken >= m_most) return 0;
    const std::uint32_t end = batch_end(taken);
    if (taken == 0 || batch_end(taken - 1) != taken || taken < m_least || pixel.count == 0)
        return end - taken;  // mid-batch, before MIN, or nothing to test
    // taken ends a batch: test it.
    const double n = double(pixel.count);
    const glm::dvec3 mean = pixel.sum / n;
    const glm::dvec3 variance_of_mean = (pixel.sum_squares / n - mean * mean) / n;
    const std::size_t index = batch_index(taken);
    const double limit = index < m_end_thresholds.size() ? m_end_thresholds[index] : threshold(taken);
    const bool settled = std::fabs(variance_of_mean.r) < limit && std::fabs(variance_of_mean.g) < limit &&
                         std::fabs(variance_of_mean.b) < limit;
    return settled ? 0 : end - taken;
}

}  // namespace lancer
