// Writes small palette PNGs for tests (libpng's simplified API keeps the
// palette as given, repeated colours and all).
#pragma once

#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <png.h>

namespace lancer::testing {

// `colormap`: red, green, blue a entry; `indices`: one a pixel, top row first.
inline void write_palette_png(const std::string& path, int width, int height,
                              const std::vector<unsigned char>& colormap, const std::vector<unsigned char>& indices) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    image.width = png_uint_32(width);
    image.height = png_uint_32(height);
    image.format = PNG_FORMAT_RGB_COLORMAP;
    image.colormap_entries = png_uint_32(colormap.size() / 3);
    ASSERT_TRUE(png_image_write_to_file(&image, path.c_str(), 0, indices.data(), 0, colormap.data())) << image.message;
}

}  // namespace lancer::testing
