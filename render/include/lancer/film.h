// Accumulates linear RGB samples per pixel. Each pixel keeps its sum, sum of
// squares (for variance estimates) and sample count; non-finite samples are
// counted and dropped, never written.
#pragma once

#include <cstdint>
#include <vector>

#include "lancer/ray.h"

namespace lancer {

class Film {
public:
    Film(int width, int height);

    int width() const { return m_width; }
    int height() const { return m_height; }

    // Not thread-safe per pixel: the host gives each pixel to one thread.
    void add_sample(int x, int y, const Color& radiance);

    Color mean(int x, int y) const;              // black if no samples
    Color variance_of_mean(int x, int y) const;  // sample variance / n
    std::uint32_t sample_count(int x, int y) const;
    std::uint64_t nonfinite_samples() const;     // over the whole film

private:
    struct Pixel {
        glm::dvec3 sum{0.0};
        glm::dvec3 sum_squares{0.0};
        std::uint32_t count = 0;
        std::uint32_t nonfinite = 0;
    };
    const Pixel& at(int x, int y) const { return m_pixels[std::size_t(y) * m_width + x]; }
    int m_width;
    int m_height;
    std::vector<Pixel> m_pixels;
};

}  // namespace lancer
