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
// unless the scene says gamma). GIFs are decoded here: OpenImageIO would
// give their colours, and the heights are their indices.
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "geometry/height_field.h"

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
    std::ifstream file(path, std::ios::binary);
    if (!file) fail(path, "the file cannot be opened");
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

// A 16-bit height as POV converts a float, which it truncates.
std::uint16_t to_height_value(double value) {
    if (!(value > 0.0)) return 0;
    if (value >= 65535.0) return 65535;
    return std::uint16_t(value);
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

// ---- GIF: the palette indices, LZW-decoded here ----

std::vector<unsigned char> decode_gif_indices(const std::string& path, int& width, int& height) {
    const std::vector<unsigned char> bytes = read_bytes(path);
    std::size_t at = 0;
    auto need = [&](std::size_t count) {
        if (at + count > bytes.size()) fail(path, "the GIF file is truncated");
    };
    need(13);
    if (std::memcmp(bytes.data(), "GIF", 3) != 0) fail(path, "it is not a GIF file");
    const unsigned char screen_flags = bytes[10];
    at = 13;
    if (screen_flags & 0x80) {
        need(3u << ((screen_flags & 7) + 1));
        at += 3u << ((screen_flags & 7) + 1);
    }
    for (;;) {
        need(1);
        const unsigned char block = bytes[at++];
        if (block == 0x21) {  // extension: label, then sub-blocks
            need(1);
            ++at;
            for (;;) {
                need(1);
                const unsigned char length = bytes[at++];
                if (length == 0) break;
                need(length);
                at += length;
            }
            continue;
        }
        if (block != 0x2C) fail(path, "the GIF file holds no image");
        need(9);
        width = bytes[at + 4] | (bytes[at + 5] << 8);
        height = bytes[at + 6] | (bytes[at + 7] << 8);
        const unsigned char image_flags = bytes[at + 8];
        at += 9;
        check_size(path, width, height);
        // POV-Ray's reader refuses interlaced GIFs too.
        if (image_flags & 0x40) fail(path, "interlaced GIF images are not supported for height fields");
        if (image_flags & 0x80) {
            need(3u << ((image_flags & 7) + 1));
            at += 3u << ((image_flags & 7) + 1);
        }
        break;
    }
    need(1);
    const int minimum_size = bytes[at++];
    if (minimum_size < 1 || minimum_size > 11) fail(path, "the GIF data is corrupt");
    // The sub-blocks joined into one code stream.
    std::vector<unsigned char> stream;
    for (;;) {
        need(1);
        const unsigned char length = bytes[at++];
        if (length == 0) break;
        need(length);
        stream.insert(stream.end(), bytes.begin() + std::ptrdiff_t(at), bytes.begin() + std::ptrdiff_t(at + length));
        at += length;
    }
    const std::size_t pixel_count = std::size_t(width) * height;
    std::vector<unsigned char> indices;
    indices.reserve(pixel_count);
    const int clear = 1 << minimum_size, end_code = clear + 1;
    std::vector<std::uint16_t> prefix(4096);
    std::vector<unsigned char> suffix(4096), first(4096), string_stack(4097);
    for (int code = 0; code < clear; ++code) suffix[code] = first[code] = (unsigned char)code;
    int code_size = minimum_size + 1, next = clear + 2, previous = -1;
    std::size_t bit = 0;
    while (indices.size() < pixel_count) {
        if (bit + code_size > stream.size() * 8) break;
        int code = 0;
        for (int i = 0; i < code_size; ++i, ++bit) code |= ((stream[bit >> 3] >> (bit & 7)) & 1) << i;
        if (code == clear) {
            code_size = minimum_size + 1;
            next = clear + 2;
            previous = -1;
            continue;
        }
        if (code == end_code) break;
        if (previous < 0) {
            if (code >= clear) fail(path, "the GIF data is corrupt");
            indices.push_back((unsigned char)code);
            previous = code;
            continue;
        }
        int walk;
        if (code < next) {
            walk = code;
            if (next < 4096) {
                prefix[next] = std::uint16_t(previous);
                suffix[next] = first[code];
                first[next] = first[previous];
                ++next;
            }
        } else if (code == next && next < 4096) {
            prefix[next] = std::uint16_t(previous);
            suffix[next] = first[previous];
            first[next] = first[previous];
            ++next;
            walk = code;
        } else {
            fail(path, "the GIF data is corrupt");
        }
        int depth = 0;
        while (walk >= clear + 2 && depth < 4096) {
            string_stack[std::size_t(depth++)] = suffix[std::size_t(walk)];
            walk = prefix[std::size_t(walk)];
        }
        string_stack[std::size_t(depth++)] = suffix[std::size_t(walk)];
        while (depth > 0 && indices.size() < pixel_count) indices.push_back(string_stack[std::size_t(--depth)]);
        if (next == (1 << code_size) && code_size < 12) ++code_size;
        previous = code;
    }
    if (indices.size() < pixel_count) fail(path, "the GIF file is truncated");
    return indices;
}

HeightFieldGrid read_gif(const std::string& path, bool pot) {
    int width = 0, height = 0;
    const std::vector<unsigned char> indices = decode_gif_indices(path, width, height);
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

// ---- Palettes of files OpenImageIO expands to colours ----

struct PaletteEntry {
    int red, green, blue;
};

// The palette of a palette PNG (empty if the PNG has none).
std::vector<PaletteEntry> png_palette(const std::vector<unsigned char>& bytes) {
    std::vector<PaletteEntry> palette;
    if (bytes.size() < 33 || bytes[25] != 3) return palette;  // IHDR colour type 3: palette
    std::size_t at = 8;
    while (at + 8 <= bytes.size()) {
        const std::size_t length =
            std::size_t(bytes[at]) << 24 | std::size_t(bytes[at + 1]) << 16 | bytes[at + 2] << 8 | bytes[at + 3];
        if (std::memcmp(&bytes[at + 4], "PLTE", 4) == 0) {
            for (std::size_t i = 0; i + 2 < length && at + 8 + i + 2 < bytes.size(); i += 3)
                palette.push_back({bytes[at + 8 + i], bytes[at + 9 + i], bytes[at + 10 + i]});
            break;
        }
        if (std::memcmp(&bytes[at + 4], "IDAT", 4) == 0) break;
        at += 12 + length;
    }
    return palette;
}

// The colour map of a colour-mapped TGA (empty otherwise).
std::vector<PaletteEntry> tga_palette(const std::vector<unsigned char>& bytes) {
    std::vector<PaletteEntry> palette;
    if (bytes.size() < 18 || bytes[1] != 1 || (bytes[2] != 1 && bytes[2] != 9)) return palette;
    const int first_index = bytes[3] | bytes[4] << 8, length = bytes[5] | bytes[6] << 8, bits = bytes[7];
    const int entry_bytes = (bits + 7) / 8;
    std::size_t at = 18 + std::size_t(bytes[0]);
    palette.resize(std::size_t(first_index), PaletteEntry{-1, -1, -1});
    for (int i = 0; i < length && at + std::size_t(entry_bytes) <= bytes.size(); ++i, at += std::size_t(entry_bytes)) {
        if (entry_bytes >= 3) {
            palette.push_back({bytes[at + 2], bytes[at + 1], bytes[at]});
        } else {
            // 15/16-bit entries: 5 bits a channel, as OpenImageIO widens them.
            const int v = bytes[at] | bytes[at + 1] << 8;
            auto widen = [](int five) { return (five << 3) | (five >> 2); };
            palette.push_back({widen((v >> 10) & 31), widen((v >> 5) & 31), widen(v & 31)});
        }
    }
    return palette;
}

// The colour table of a BMP of 8 bits a pixel or fewer (empty otherwise).
std::vector<PaletteEntry> bmp_palette(const std::vector<unsigned char>& bytes) {
    std::vector<PaletteEntry> palette;
    if (bytes.size() < 54 || bytes[0] != 'B' || bytes[1] != 'M') return palette;
    auto u32 = [&](std::size_t at) {
        return std::size_t(bytes[at]) | std::size_t(bytes[at + 1]) << 8 | std::size_t(bytes[at + 2]) << 16 |
               std::size_t(bytes[at + 3]) << 24;
    };
    const std::size_t header = u32(14);
    const int bits = bytes[28] | bytes[29] << 8;
    if (bits > 8 || header < 40) return palette;
    std::size_t count = u32(46);
    if (count == 0 || count > 256) count = std::size_t(1) << bits;
    for (std::size_t i = 0, at = 14 + header; i < count && at + 3 < bytes.size(); ++i, at += 4)
        palette.push_back({bytes[at + 2], bytes[at + 1], bytes[at]});
    return palette;
}

// The first palette index with a pixel's colour (what POV's index was,
// unless the palette repeats a colour).
int palette_index(const std::vector<PaletteEntry>& palette, int red, int green, int blue) {
    for (std::size_t i = 0; i < palette.size(); ++i)
        if (palette[i].red == red && palette[i].green == green && palette[i].blue == blue) return int(i);
    return 0;
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
    // Open with OpenImageIO first: it names what the file is.
    // POV-Ray keeps a file's colours as stored, not multiplied by alpha.
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(path, &config);
    if (!input) {
        if (extension == "pot") return read_gif(path, true);
        fail(path, OIIO::geterror());
    }
    const OIIO::ImageSpec spec = input->spec();
    const std::string format = input->format_name();
    if (format == "gif" || extension == "pot") {
        input->close();
        return read_gif(path, extension == "pot");
    }
    check_size(path, spec.width, spec.height);
    const int channels = spec.nchannels;
    if (channels < 1) fail(path, "it has no channels");
    int bits = spec.get_int_attribute("oiio:BitsPerSample", int(spec.format.size()) * 8);
    const bool floating = spec.format.is_floating_point();
    if (!floating) bits = std::clamp(bits, 1, 16);

    // Which of POV's conversions this file gets.
    std::vector<PaletteEntry> palette;
    if (format == "png" || format == "targa" || format == "bmp") {
        const std::vector<unsigned char> bytes = read_bytes(path);
        palette = format == "png" ? png_palette(bytes) : format == "targa" ? tga_palette(bytes) : bmp_palette(bytes);
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
    const bool tiled = spec.tile_width > 0;
    const int band_rows = tiled ? height : kBandRows;
    if (floating)
        band.resize(std::size_t(width) * band_rows * channels);
    else
        band16.resize(std::size_t(width) * band_rows * channels);
    void* buffer = floating ? static_cast<void*>(band.data()) : static_cast<void*>(band16.data());
    const OIIO::TypeDesc type = floating ? OIIO::TypeDesc::FLOAT : OIIO::TypeDesc::UINT16;
    if (tiled && !input->read_image(0, 0, 0, channels, type, buffer)) fail(path, input->geterror());
    for (int y0 = 0; y0 < height; y0 += kBandRows) {
        const int y1 = std::min(y0 + kBandRows, height);
        std::size_t band_start = 0;
        if (!tiled) {
            if (!input->read_scanlines(0, 0, spec.y + y0, spec.y + y1, 0, 0, channels, type, buffer))
                fail(path, input->geterror());
        } else {
            band_start = std::size_t(y0) * width * channels;
        }
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < width; ++x) {
                const std::size_t first = band_start + (std::size_t(y - y0) * width + x) * channels;
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
    input->close();
    return grid_from_values(width, height, values);
}

}  // namespace lancer
