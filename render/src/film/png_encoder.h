// Writing PNG files with libpng itself: every render that writes a PNG
// would otherwise load the image module (image_codecs.h) for it alone
// (internal to liblancer).
#pragma once

#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace lancer {

// Interleaved samples already encoded as the file stores them (sRGB or
// raw values in [0, 1]), quantised here to 8 or 16 bits by rounding to
// nearest. 3 channels (RGB) or 4 (RGBA, straight alpha).
struct PngPixels {
    int width = 0;
    int height = 0;
    int channels = 3;
    int bits = 8;
    const float* samples = nullptr;                     // every row, row-major; or
    std::function<void(int row, float* samples)> rows;  // fills one row when asked; or
    // (8 bits only) fills one row of codes when asked
    std::function<void(int row, unsigned char* codes)> code_rows;
    // tEXt chunks (keywords of 1 to 79 Latin-1 characters).
    std::vector<std::pair<std::string, std::string>> text;
};

// Throws std::runtime_error with libpng's reason. Not atomic: callers write
// a temporary file and rename it.
void write_png_file(const std::string& path, const PngPixels& pixels);
std::vector<unsigned char> encode_png_bytes(const PngPixels& pixels);

}  // namespace lancer
