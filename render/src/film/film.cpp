// Per-pixel accumulation: in double (Totals), so sums stay exact enough for
// thousands of samples and variance estimates, or the colour sum and counts
// alone (Sums, MeanOnly) when nothing reads a variance.
#include "lancer/host/film.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace lancer {

Film::Film(int width, int height, Storage storage) : m_width(width), m_height(height), m_storage(storage) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("film size must be positive");
    const std::size_t pixels = std::size_t(width) * std::size_t(height);
    allocate(pixels);
    m_taken = ZeroedArray<std::uint32_t>(pixels);
}

void Film::allocate(std::size_t pixels) {
    const bool totals = m_storage == Storage::Totals;
    m_sums = ZeroedArray<glm::dvec3>(totals ? pixels : 0);
    m_squares = ZeroedArray<glm::dvec3>(totals ? pixels : 0);
    m_colour_sums = ZeroedArray<Color>(totals ? 0 : pixels);
    m_finite = ZeroedArray<std::uint32_t>(m_storage == Storage::MeanOnly ? 0 : pixels);
}

// With allocate(): no pixel holds a sample, so restore_region's changes
// are the whole film's.
void Film::start_empty() {
    std::fill(m_taken.begin(), m_taken.end(), 0u);
    m_nonfinite_total.value.store(0, std::memory_order_relaxed);
}

void Film::change_storage(Storage storage) {
    if (storage == m_storage) return;
    const std::vector<Accumulator> all = accumulators();
    m_storage = storage;
    allocate(all.size());
    start_empty();
    restore_region(0, 0, m_width, m_height, all.data());
}

Film::Accumulator Film::accumulator(std::size_t index) const {
    Accumulator pixel;
    if (m_storage == Storage::Totals) {
        pixel.sum = m_sums[index];
        pixel.sum_squares = m_squares[index];
        pixel.count = m_finite[index];
        pixel.nonfinite = m_taken[index] - pixel.count;
        return pixel;
    }
    const Color sum = m_colour_sums[index];
    if (m_storage == Storage::Sums) {
        pixel.count = m_finite[index];
        pixel.nonfinite = m_taken[index] - pixel.count;
        pixel.sum = glm::dvec3(sum);
        if (pixel.count > 0) pixel.sum_squares = pixel.sum * pixel.sum / double(pixel.count);
        return pixel;
    }
    if (std::isnan(sum.r)) {
        pixel.nonfinite = m_taken[index];
        return pixel;
    }
    pixel.count = m_taken[index];
    pixel.sum = glm::dvec3(sum);
    pixel.sum_squares = pixel.sum * pixel.sum;
    return pixel;
}

std::vector<Film::Accumulator> Film::accumulators() const {
    std::vector<Accumulator> all(m_taken.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = accumulator(i);
    return all;
}

Color Film::mean(int x, int y) const {
    const std::size_t index = std::size_t(y) * m_width + x;
    if (m_storage == Storage::Sums) {
        const std::uint32_t count = m_finite[index];
        if (count == 0) return Color(0.0f);
        return count == 1 ? m_colour_sums[index] : m_colour_sums[index] / float(count);
    }
    if (m_storage == Storage::MeanOnly) {
        const Color sum = m_colour_sums[index];
        const std::uint32_t count = m_taken[index];
        if (count == 0 || std::isnan(sum.r)) return Color(0.0f);
        return count == 1 ? sum : sum / float(count);
    }
    const std::uint32_t count = m_finite[index];
    if (count == 0) return Color(0.0f);
    return Color(m_sums[index] / double(count));
}

Color Film::variance_of_mean(int x, int y) const {
    if (m_storage != Storage::Totals) return Color(0.0f);
    const std::size_t index = std::size_t(y) * m_width + x;
    if (m_finite[index] < 2) return Color(0.0f);
    const double n = double(m_finite[index]);
    const glm::dvec3 mean = m_sums[index] / n;
    const glm::dvec3 variance = glm::max(m_squares[index] / n - mean * mean, glm::dvec3(0.0)) * (n / (n - 1.0));
    return Color(variance / n);
}

std::uint32_t Film::sample_count(int x, int y) const {
    const std::size_t index = std::size_t(y) * m_width + x;
    if (m_storage == Storage::MeanOnly) return std::isnan(m_colour_sums[index].r) ? 0 : m_taken[index];
    return m_finite[index];
}

void Film::restore(std::vector<Accumulator> accumulators) {
    if (accumulators.size() != m_taken.size())
        throw std::invalid_argument("film restore: " + std::to_string(accumulators.size()) + " pixels for a " +
                                    std::to_string(m_width) + "x" + std::to_string(m_height) + " film");
    if (m_storage == Storage::MeanOnly) m_storage = Storage::Totals;
    allocate(accumulators.size());
    start_empty();
    restore_region(0, 0, m_width, m_height, accumulators.data());
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
            nonfinite_change += std::int64_t(pixels->nonfinite) - std::int64_t(accumulator(i).nonfinite);
            if (m_storage == Storage::MeanOnly) {
                m_colour_sums[i] = pixels->nonfinite > 0 ? Color(std::nanf("")) : Color(pixels->sum);
            } else if (m_storage == Storage::Sums) {
                m_colour_sums[i] = Color(pixels->sum);
                m_finite[i] = pixels->count;
            } else {
                m_sums[i] = pixels->sum;
                m_squares[i] = pixels->sum_squares;
                m_finite[i] = pixels->count;
            }
            m_taken[i] = pixels->count + pixels->nonfinite;
            any = any || m_taken[i] > 0;
        }
    m_nonfinite_total.value.fetch_add(std::uint64_t(nonfinite_change), std::memory_order_relaxed);
    // Stays true once set: a film that held samples is swept when planned,
    // which is right (if slower) for one that holds none any more.
    if (any) m_has_samples.value.store(true, std::memory_order_relaxed);
}

}  // namespace lancer
