// Colour-mapped image files as POV-Ray reads them: each pixel's index into
// the file's palette. POV keeps these files indexed (a height field's
// heights are the indices; an image_map's `filter N, v` and
// `transmit N, v` change one palette entry), while OpenImageIO expands
// them to colours, so the indices are recovered here (internal to
// liblancer).
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace lancer {

struct PaletteEntry {
    int red, green, blue;
};

// A GIF's first image, LZW-decoded here: one index a pixel, row 0 at the
// top. Throws std::runtime_error with the reason (truncated, corrupt,
// interlaced, larger than 16384 x 16384) when it cannot be read.
struct GifIndices {
    int width = 0;
    int height = 0;
    int palette_size = 0;  // the entries of the colour table in force
    std::vector<unsigned char> indices;
};
GifIndices decode_gif_indices(const std::string& path);

// The palette of a palette PNG, a colour-mapped TGA or a BMP of 8 bits a
// pixel or fewer, given the file's bytes and OpenImageIO's format name
// ("png", "targa", "bmp"); empty when the file has none. A TGA's palette
// starts with placeholder entries (-1) below its first index.
std::vector<PaletteEntry> file_palette(const std::string& format, const std::vector<unsigned char>& bytes);

// The first palette index with a pixel's colour: POV's index, unless the
// palette repeats a colour.
int palette_index(const std::vector<PaletteEntry>& palette, int red, int green, int blue);

std::vector<unsigned char> read_file_bytes(const std::string& path);

// A palette image: its size, how many palette entries it has, each
// pixel's index (row 0 at the top) and each entry's alpha (1 unless the
// file makes it transparent).
struct PaletteImage {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> indices;
    std::vector<float> alpha_by_index;
};
// Empty when the file is not colour-mapped (or is a kind POV does not
// read as one). Throws std::runtime_error when it cannot be read.
std::optional<PaletteImage> read_palette_image(const std::string& path);

}  // namespace lancer
