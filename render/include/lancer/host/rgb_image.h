// A plain linear RGB image: what a finished render is once its samples are
// averaged, and what image metrics, heat maps and caches work on (PNG is
// sRGB-encoded, EXR is linear).
#pragma once

#include <string>
#include <vector>

#include "lancer/host/film.h"
#include "lancer/ray.h"

namespace lancer {

struct RgbImage {
    int width = 0;
    int height = 0;
    std::vector<Color> pixels;  // row-major, linear RGB

    RgbImage() = default;
    RgbImage(int w, int h) : width(w), height(h), pixels(std::size_t(w) * std::size_t(h), Color(0.0f)) {}

    Color& at(int x, int y) { return pixels[std::size_t(y) * width + x]; }
    const Color& at(int x, int y) const { return pixels[std::size_t(y) * width + x]; }
    bool same_size(const RgbImage& other) const { return width == other.width && height == other.height; }
};

// The film's per-pixel means.
RgbImage image_from_film(const Film& film);

// Throws std::runtime_error naming the path when the file cannot be read.
// PNG/TIFF values are decoded from sRGB to linear; EXR/HDR are taken as is.
RgbImage read_rgb_image(const std::string& path);

// Format by extension as write_image: .png sRGB 8-bit (clamped), .exr linear
// float. Atomic (temporary file, then rename). Throws on failure.
void write_rgb_image(const RgbImage& image, const std::string& path);

}  // namespace lancer
