// The heights POV-Ray 3.7 reads from a height_field's image
// (image_height_at in its backend/support/imageutil.cpp, over its own file
// readers), with OpenImageIO decoding the files:
//   - palette images (GIF, palette PNG, colour-mapped TGA, BMP of 8 bits
//     or fewer): the palette index * 256 (never 65535: POV keeps 3.6's
//     factor);
//   - POT files (GIF whose right half holds low bytes): 256 * left + right;
//   - grey images (PNG, PGM, JPEG): the grey value * 65535, truncated;
//     8-bit grey PNGs pass through POV's palette path first, which rounds
//     the value down through a float luminance sum;
//   - 8-bit colour images (PNG, PPM, JPEG, TGA, BMP, TIFF, and grey TGA,
//     BMP, TIFF, which POV reads as colour) and float images (EXR, HDR):
//     red as the high byte and green as the low: (r * 256 + g) * 255;
//   - deeper colour images: the luminance 0.297 r + 0.589 g + 0.114 b.
// The float arithmetic is POV's, step for step, so the 16-bit values come
// out identical. `gamma` decodes the file's values first (POV decodes none
// unless the scene says gamma). Palette files' indices come from
// materials/palette_image.h: OpenImageIO gives their colours.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "film/png_reader.h"
#include "geometry/height_field.h"
#include "materials/palette_image.h"

namespace lancer {
namespace {

// Same limit as image maps: a tiny file can claim a huge size.
constexpr double kMaxImagePixels = 16384.0 * 16384.0;

[[noreturn]] void fail(const std::string& path, const std::string& why) {
    std::string text = "cannot read height field image '" + path + "': " + why;
    while (!text.empty() && text.back() == '\n') text.pop_back();
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at)) text.replace(at, 1, "; ");
    throw std::runtime_error(text);
}

void check_size(const std::string& path, long long width, long long height) {
    if (width < 1 || height < 1) fail(path, "it has no pixels");
    if (double(width) * double(height) > kMaxImagePixels)
        fail(path, "it claims " + std::to_string(width) + " x " + std::to_string(height) +
                       " pixels: more than lancer's limit of 16384 x 16384");
    if (width < 2 || height < 2)
        fail(path, "a height field needs at least 2 x 2 pixels, it has " + std::to_string(width) + " x " +
                       std::to_string(height));
}

std::vector<unsigned char> read_bytes(const std::string& path) {
    try {
        return read_file_bytes(path);
    } catch (const std::runtime_error& error) {
        fail(path, error.what());
    }
}

// A 16-bit height as POV converts a float, which it truncates.
std::uint16_t to_height_value(double value) {
    if (!(value > 0.0)) return 0;
    if (value >= 65535.0) return 65535;
    return std::uint16_t(value);
}

bool file_starts_with_gif_signature(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    char signature[6] = {};
    if (!file.read(signature, 6)) return false;
    return std::string_view(signature, 6) == "GIF87a" || std::string_view(signature, 6) == "GIF89a";
}

}  // namespace

// Grid row r is image row height - 1 - r: POV puts the image's top at z = 1.
HeightFieldGrid grid_from_values(int width, int height, const std::vector<std::uint16_t>& values) {
    HeightFieldGrid grid;
    grid.columns = width;
    grid.rows = height;
    grid.heights.resize(std::size_t(width) * height);
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < width; ++column)
            grid.heights[std::size_t(row) * width + column] =
                float(values[std::size_t(height - 1 - row) * width + column]) / 65536.0f;
    return grid;
}

namespace {

HeightFieldGrid read_gif(const std::string& path, bool pot) {
    GifIndices gif;
    try {
        gif = decode_gif_indices(path);
    } catch (const std::runtime_error& error) {
        fail(path, error.what());
    }
    const int width = gif.width, height = gif.height;
    check_size(path, width, height);
    const std::vector<unsigned char>& indices = gif.indices;
    std::vector<std::uint16_t> values(indices.size());
    if (!pot) {
        for (std::size_t i = 0; i < indices.size(); ++i) values[i] = std::uint16_t(indices[i] * 256);
        return grid_from_values(width, height, values);
    }
    if (width % 2 != 0) fail(path, "a POT file must have an even width");
    const int half = width / 2;
    check_size(path, half, height);
    values.resize(std::size_t(half) * height);
    for (int row = 0; row < height; ++row)
        for (int column = 0; column < half; ++column) {
            const std::size_t left = std::size_t(row) * width + column;
            values[std::size_t(row) * half + column] = std::uint16_t(indices[left] << 8 | indices[left + half]);
        }
    return grid_from_values(half, height, values);
}

// ---- POV-Ray's conversions ----

// A file value 0..max as POV's images give it: decoded by the gamma, if
// one was given, in float.
float decode_value(unsigned value, unsigned max, double gamma) {
    const float linear = float(value) / float(max);
    if (std::isnan(gamma) || gamma == 1.0) return linear;
    return float(std::pow(double(linear), gamma));
}

enum class Conversion {
    Index,            // palette index * 256
    GreyPalettePath,  // 8-bit grey PNG: through a float luminance, stored as 8 bits
    Grey,             // grey value * 65535
    HighLowBytes,     // (r * 256 + g) * 255
    Luminance,        // 0.297 r + 0.589 g + 0.114 b, * 65535
};

}  // namespace

HeightFieldGrid read_height_field_image(const std::string& path, double gamma) {
    std::string extension;
    if (const std::size_t dot = path.find_last_of('.'); dot != std::string::npos) {
        extension = path.substr(dot + 1);
        for (char& c : extension) c = char(std::tolower((unsigned char)c));
    }
    // A GIF (and POV's POT, a GIF of twice the width) is decoded here, so
    // its signature spares loading the image module to name it.
    if (file_starts_with_gif_signature(path)) return read_gif(path, extension == "pot");
    // Open with libpng or the image module: it names what the file is.
    // POV-Ray keeps a file's colours as stored, not multiplied by alpha.
    std::unique_ptr<ImageFileReader> input;
    try {
        input = open_image_file(path, true);
    } catch (const std::runtime_error& error) {
        if (extension == "pot") return read_gif(path, true);
        fail(path, error.what());
    }
    const ImageFileInfo& spec = input->info();
    const std::string format = spec.format;
    if (format == "gif" || extension == "pot") {
        input.reset();
        return read_gif(path, extension == "pot");
    }
    check_size(path, spec.width, spec.height);
    const int channels = spec.channels;
    if (channels < 1) fail(path, "it has no channels");
    int bits = spec.bits_per_sample;
    const bool floating = spec.floating;
    if (!floating) bits = std::clamp(bits, 1, 16);

    // Which of POV's conversions this file gets.
    std::vector<PaletteEntry> palette;
    if (format == "png" || format == "targa" || format == "bmp") {
        palette = file_palette(format, read_bytes(path));
    }
    if (format == "png" && !palette.empty()) {
        // libpng's indices: entries that share a colour stay apart.
        std::optional<PaletteImage> image;
        try {
            image = read_palette_image(path);
        } catch (const std::runtime_error& error) {
            fail(path, error.what());
        }
        if (image) {
            std::vector<std::uint16_t> values(image->indices.size());
            for (std::size_t i = 0; i < values.size(); ++i) values[i] = std::uint16_t(image->indices[i] * 256);
            return grid_from_values(image->width, image->height, values);
        }
    }
    const bool grey = channels <= 2;
    Conversion conversion;
    if (!palette.empty()) {
        conversion = Conversion::Index;
    } else if (floating) {
        conversion = Conversion::HighLowBytes;
    } else if (format == "targa" || format == "bmp" || format == "tiff") {
        // POV reads these as 8-bit colour, grey ones too.
        conversion = Conversion::HighLowBytes;
        if (format == "tiff") bits = std::min(bits, 8);
    } else if (grey) {
        conversion = format == "png" && bits <= 8 && channels == 1 ? Conversion::GreyPalettePath : Conversion::Grey;
    } else {
        conversion = bits <= 8 ? Conversion::HighLowBytes : Conversion::Luminance;
    }

    // Decode a band of rows at a time: integer files as 16 bits (exact
    // for every depth up to 16), from which the file's own values come back;
    // float files as float.
    const int width = spec.width, height = spec.height;
    const unsigned file_max = floating ? 1u : (1u << std::min(bits, 16)) - 1u;
    std::vector<std::uint16_t> values(std::size_t(width) * height);
    std::vector<float> band;
    std::vector<std::uint16_t> band16;
    constexpr int kBandRows = 64;
    if (floating)
        band.resize(std::size_t(width) * kBandRows * channels);
    else
        band16.resize(std::size_t(width) * kBandRows * channels);
    void* buffer = floating ? static_cast<void*>(band.data()) : static_cast<void*>(band16.data());
    const SampleType type = floating ? SampleType::Float : SampleType::UInt16;
    for (int y0 = 0; y0 < height; y0 += kBandRows) {
        const int y1 = std::min(y0 + kBandRows, height);
        try {
            input->read_rows(y0, y1, type, buffer);
        } catch (const std::runtime_error& error) {
            fail(path, error.what());
        }
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t first = (std::size_t(y - y0) * width + x) * channels;
                const float* pixel = floating ? band.data() + first : nullptr;
                const std::uint16_t* pixel16 = floating ? nullptr : band16.data() + first;
                if (floating) {
                    for (int c = 0; c < channels; ++c)
                        if (!std::isfinite(pixel[c])) fail(path, "it holds values that are NaN or infinite");
                }
                // The file's value 0..file_max of a channel.
                auto code = [&](int channel) {
                    const unsigned wide = pixel16[std::min(channel, channels - 1)];
                    return file_max == 65535u ? wide : (wide * file_max + 32767u) / 65535u;
                };
                const int green_channel = grey ? 0 : 1, blue_channel = grey ? 0 : 2;
                std::uint16_t value = 0;
                switch (conversion) {
                case Conversion::Index: {
                    auto byte = [&](int channel) {
                        return int((pixel16[std::min(channel, channels - 1)] * 255u + 32767u) / 65535u);
                    };
                    value =
                        std::uint16_t(palette_index(palette, byte(0), byte(green_channel), byte(blue_channel)) * 256);
                    break;
                }
                case Conversion::GreyPalettePath: {
                    const float g = decode_value(code(0), file_max, gamma);
                    const float luminance = g * 0.297f + g * 0.589f + g * 0.114f;
                    const unsigned char stored = (unsigned char)std::clamp(luminance * 255.0f, 0.0f, 255.0f);
                    value = to_height_value(double(float(stored) / 255.0f * 65535.0f));
                    break;
                }
                case Conversion::Grey:
                    // POV's 16-bit PGM reader keeps the value exactly.
                    if (format == "pnm" && file_max == 65535 && (std::isnan(gamma) || gamma == 1.0))
                        value = std::uint16_t(code(0));
                    else
                        value = to_height_value(double(decode_value(code(0), file_max, gamma) * 65535.0f));
                    break;
                case Conversion::HighLowBytes: {
                    float red, green;
                    if (floating) {
                        red = pixel[0];
                        green = pixel[green_channel];
                    } else {
                        red = decode_value(code(0), file_max, gamma);
                        green = decode_value(code(green_channel), file_max, gamma);
                    }
                    value = to_height_value((double(red) * 256.0 + double(green)) * 255.0);
                    break;
                }
                case Conversion::Luminance: {
                    const double red = decode_value(code(0), file_max, gamma);
                    const double green = decode_value(code(green_channel), file_max, gamma);
                    const double blue = decode_value(code(blue_channel), file_max, gamma);
                    value = to_height_value((0.297 * red + 0.589 * green + 0.114 * blue) * double(65535.0f));
                    break;
                }
                }
                values[std::size_t(y) * width + x] = value;
            }
    }
    return grid_from_values(width, height, values);
}

}  // namespace lancer
