// Colour-mapped files' indices: GIF decoded here, the palettes of PNG, TGA
// and BMP files read from their bytes (OpenImageIO gives their colours).
#include "materials/palette_image.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include <png.h>

#include "film/png_reader.h"

namespace lancer {
namespace {

// A tiny file can claim a huge size; the limit of every image lancer reads.
constexpr double kMaxImagePixels = 16384.0 * 16384.0;

[[noreturn]] void fail(const std::string& why) {
    throw std::runtime_error(why);
}

void check_size(long long width, long long height) {
    if (width < 1 || height < 1) fail("it has no pixels");
    if (double(width) * double(height) > kMaxImagePixels)
        fail("it claims " + std::to_string(width) + " x " + std::to_string(height) +
             " pixels: more than lancer's limit of 16384 x 16384");
}

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

// A palette PNG's indices and its entries' alpha, through libpng's
// simplified API (which reports errors instead of jumping); empty when the
// PNG has no palette.
std::optional<PaletteImage> read_png_indices(const std::string& path) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    if (!png_image_begin_read_from_file(&png, path.c_str())) fail(png.message);
    if (!(png.format & PNG_FORMAT_FLAG_COLORMAP)) {
        png_image_free(&png);
        return std::nullopt;
    }
    check_size(png.width, png.height);
    // For a palette file libpng keeps the file's entries and indices.
    png.format = PNG_FORMAT_RGBA_COLORMAP;
    PaletteImage image;
    image.width = int(png.width);
    image.height = int(png.height);
    image.indices.resize(PNG_IMAGE_SIZE(png));
    std::vector<unsigned char> colormap(PNG_IMAGE_COLORMAP_SIZE(png));
    if (!png_image_finish_read(&png, nullptr, image.indices.data(), 0, colormap.data())) {
        const std::string why = png.message;
        png_image_free(&png);
        fail(why);
    }
    const std::size_t entries = std::clamp<std::size_t>(png.colormap_entries, 1, 256);
    for (std::size_t i = 0; i < entries; ++i) image.alpha_by_index.push_back(float(colormap[i * 4 + 3]) / 255.0f);
    png_image_free(&png);
    return image;
}

}  // namespace

std::vector<unsigned char> read_file_bytes(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) fail("the file cannot be opened");
    return std::vector<unsigned char>(std::istreambuf_iterator<char>(file), std::istreambuf_iterator<char>());
}

GifIndices decode_gif_indices(const std::string& path) {
    const std::vector<unsigned char> bytes = read_file_bytes(path);
    GifIndices gif;
    int& width = gif.width;
    int& height = gif.height;
    std::size_t at = 0;
    auto need = [&](std::size_t count) {
        if (at + count > bytes.size()) fail("the GIF file is truncated");
    };
    need(13);
    if (std::memcmp(bytes.data(), "GIF", 3) != 0) fail("it is not a GIF file");
    const unsigned char screen_flags = bytes[10];
    at = 13;
    if (screen_flags & 0x80) {
        gif.palette_size = 1 << ((screen_flags & 7) + 1);
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
        if (block != 0x2C) fail("the GIF file holds no image");
        need(9);
        width = bytes[at + 4] | (bytes[at + 5] << 8);
        height = bytes[at + 6] | (bytes[at + 7] << 8);
        const unsigned char image_flags = bytes[at + 8];
        at += 9;
        check_size(width, height);
        // POV-Ray's reader refuses interlaced GIFs too.
        if (image_flags & 0x40) fail("interlaced GIF images are not supported (nor are they by POV-Ray)");
        if (image_flags & 0x80) {
            gif.palette_size = 1 << ((image_flags & 7) + 1);
            need(3u << ((image_flags & 7) + 1));
            at += 3u << ((image_flags & 7) + 1);
        }
        break;
    }
    need(1);
    const int minimum_size = bytes[at++];
    if (minimum_size < 1 || minimum_size > 11) fail("the GIF data is corrupt");
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
    std::vector<unsigned char>& indices = gif.indices;
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
            if (code >= clear) fail("the GIF data is corrupt");
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
            fail("the GIF data is corrupt");
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
    if (indices.size() < pixel_count) fail("the GIF file is truncated");
    return gif;
}

std::vector<PaletteEntry> file_palette(const std::string& format, const std::vector<unsigned char>& bytes) {
    if (format == "png") return png_palette(bytes);
    if (format == "targa") return tga_palette(bytes);
    if (format == "bmp") return bmp_palette(bytes);
    return {};
}

// The first palette index with a pixel's colour (what POV's index was,
// unless the palette repeats a colour).
int palette_index(const std::vector<PaletteEntry>& palette, int red, int green, int blue) {
    for (std::size_t i = 0; i < palette.size(); ++i)
        if (palette[i].red == red && palette[i].green == green && palette[i].blue == blue) return int(i);
    return 0;
}

std::optional<PaletteImage> read_palette_image(const std::string& path) {
    // POV-Ray keeps a file's colours as stored, not multiplied by alpha.
    const std::unique_ptr<ImageFileReader> input = open_image_file(path, true);
    const ImageFileInfo& spec = input->info();
    const std::string& format = spec.format;
    check_size(spec.width, spec.height);
    PaletteImage image;
    image.width = spec.width;
    image.height = spec.height;
    std::size_t palette_size = 0;
    std::vector<PaletteEntry> palette;
    if (format == "png") {
        const int bits = spec.bits_per_sample;
        if (spec.channels != 1 || bits > 8) return read_png_indices(path);
        // POV reads a grey PNG of 8 bits or fewer as a palette of greys:
        // the index is the grey value.
        image.indices.resize(std::size_t(spec.width) * spec.height);
        input->read_rows(0, spec.height, SampleType::UInt8, image.indices.data());
        const int levels = 1 << bits;
        for (unsigned char& value : image.indices) value = (unsigned char)((value * (levels - 1) + 127) / 255);
        image.alpha_by_index.assign(std::size_t(levels), 1.0f);
        return image;
    }
    if (format == "gif") {
        GifIndices gif = decode_gif_indices(path);
        if (gif.width != spec.width || gif.height != spec.height) fail("the GIF's image and screen sizes disagree");
        palette_size = std::size_t(std::max(gif.palette_size, 1));
        image.indices = std::move(gif.indices);
    } else {
        palette = file_palette(format, read_file_bytes(path));
        if (palette.empty()) return std::nullopt;
        palette_size = palette.size();
        image.indices.resize(std::size_t(spec.width) * spec.height);
    }
    const int channels = spec.channels;
    const bool has_alpha = channels == 2 || channels == 4;
    const bool grey = channels <= 2;
    image.alpha_by_index.assign(palette_size, has_alpha ? -1.0f : 1.0f);
    if (palette.empty() && !has_alpha) return image;  // a GIF without transparency
    // Each pixel's colour (for its index) and alpha, a band of rows at a time.
    constexpr int kBandRows = 64;
    std::vector<unsigned char> band(std::size_t(spec.width) * kBandRows * channels);
    for (int y0 = 0; y0 < spec.height; y0 += kBandRows) {
        const int y1 = std::min(y0 + kBandRows, spec.height);
        input->read_rows(y0, y1, SampleType::UInt8, band.data());
        for (int y = y0; y < y1; ++y)
            for (int x = 0; x < spec.width; ++x) {
                const unsigned char* pixel = band.data() + (std::size_t(y - y0) * spec.width + x) * channels;
                const std::size_t at = std::size_t(y) * spec.width + x;
                if (!palette.empty())
                    image.indices[at] =
                        (unsigned char)palette_index(palette, pixel[0], pixel[grey ? 0 : 1], pixel[grey ? 0 : 2]);
                float& alpha = image.alpha_by_index[std::min<std::size_t>(image.indices[at], palette_size - 1)];
                if (alpha < 0.0f) alpha = has_alpha ? float(pixel[channels - 1]) / 255.0f : 1.0f;
            }
    }
    for (float& alpha : image.alpha_by_index)
        if (alpha < 0.0f) alpha = 1.0f;  // an entry no pixel uses
    return image;
}

}  // namespace lancer
