// Per-pixel accumulation in double: sums stay exact enough for thousands of
// samples and variance estimates.
#include "lancer/film.h"

#include <cmath>
#include <stdexcept>
#include <string>

namespace lancer {

Film::Film(int width, int height) : m_width(width), m_height(height) {
    if (width <= 0 || height <= 0) throw std::invalid_argument("film size must be positive");
    m_pixels.resize(std::size_t(width) * std::size_t(height));
}

void Film::add_sample(int x, int y, const Color& radiance) {
    Accumulator& pixel = m_pixels[std::size_t(y) * m_width + x];
    if (!std::isfinite(radiance.r) || !std::isfinite(radiance.g) || !std::isfinite(radiance.b)) {
        ++pixel.nonfinite;
        return;
    }
    const glm::dvec3 value(radiance);
    pixel.sum += value;
    pixel.sum_squares += value * value;
    ++pixel.count;
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

std::uint32_t Film::sample_count(int x, int y) const { return at(x, y).count; }

std::uint32_t Film::samples_taken(int x, int y) const {
    const Accumulator& pixel = at(x, y);
    return pixel.count + pixel.nonfinite;
}

void Film::restore(std::vector<Accumulator> accumulators) {
    if (accumulators.size() != m_pixels.size())
        throw std::invalid_argument("film restore: " + std::to_string(accumulators.size()) + " pixels for a " +
                                    std::to_string(m_width) + "x" + std::to_string(m_height) + " film");
    m_pixels = std::move(accumulators);
}

std::uint64_t Film::nonfinite_samples() const {
    std::uint64_t total = 0;
    for (const Accumulator& pixel : m_pixels) total += pixel.nonfinite;
    return total;
}

}  // namespace lancer
