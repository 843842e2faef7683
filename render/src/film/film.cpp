// Per-pixel accumulation in double: sums stay exact enough for thousands of
// samples and variance estimates.
#include "lancer/host/film.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lancer {

Film::Film(int width, int height) : m_width(width), m_height(height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("film size must be positive");
    m_pixels.resize(std::size_t(width) * std::size_t(height));
    m_taken.resize(m_pixels.size(), 0);
}

Color Film::mean(int x, int y) const {
    const Accumulator& pixel = at(x, y);
    if (pixel.count == 0) return Color(0.0f);
    return Color(pixel.sum / double(pixel.count));
}

Color Film::variance_of_mean(int x, int y) const {
    const Accumulator& pixel = at(x, y);
    if (pixel.count < 2) return Color(0.0f);
    const double n = double(pixel.count);
    const glm::dvec3 mean = pixel.sum / n;
    const glm::dvec3 variance = glm::max(pixel.sum_squares / n - mean * mean, glm::dvec3(0.0)) * (n / (n - 1.0));
    return Color(variance / n);
}

std::uint32_t Film::sample_count(int x, int y) const {
    return at(x, y).count;
}

void Film::restore(std::vector<Accumulator> accumulators) {
    if (accumulators.size() != m_pixels.size())
        throw std::invalid_argument("film restore: " + std::to_string(accumulators.size()) + " pixels for a " +
                                    std::to_string(m_width) + "x" + std::to_string(m_height) + " film");
    m_pixels = std::move(accumulators);
    std::uint64_t nonfinite = 0;
    for (std::size_t i = 0; i < m_pixels.size(); ++i) {
        nonfinite += m_pixels[i].nonfinite;
        m_taken[i] = m_pixels[i].count + m_pixels[i].nonfinite;
    }
    m_nonfinite_total.value.store(nonfinite, std::memory_order_relaxed);
    m_has_samples.value.store(std::any_of(m_taken.begin(), m_taken.end(), [](std::uint32_t n) { return n > 0; }),
                              std::memory_order_relaxed);
}

void Film::restore_region(int x0, int y0, int x1, int y1, const Accumulator* pixels) {
    if (x0 < 0 || y0 < 0 || x1 > m_width || y1 > m_height || x0 > x1 || y0 > y1)
        throw std::invalid_argument("film restore_region: rectangle outside the film");
    std::int64_t nonfinite_change = 0;
    bool any = false;
    for (int y = y0; y < y1; ++y)
        for (int x = x0; x < x1; ++x, ++pixels) {
            const std::size_t i = std::size_t(y) * m_width + x;
            nonfinite_change += std::int64_t(pixels->nonfinite) - std::int64_t(m_pixels[i].nonfinite);
            m_pixels[i] = *pixels;
            m_taken[i] = pixels->count + pixels->nonfinite;
            any = any || m_taken[i] > 0;
        }
    m_nonfinite_total.value.fetch_add(std::uint64_t(nonfinite_change), std::memory_order_relaxed);
    // Stays true once set: a film that held samples is swept when planned,
    // which is right (if slower) for one that holds none any more.
    if (any) m_has_samples.value.store(true, std::memory_order_relaxed);
}

}  // namespace lancer
