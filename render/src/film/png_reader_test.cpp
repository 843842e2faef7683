// The libpng reader against the image module's (OpenImageIO's) reading of
// the same files: every colour type and bit depth PNG has, palettes with
// and without tRNS, grey tRNS, interlacing, gAMA and sRGB chunks; and the files
// POV-Ray ships. Same header values, same samples, bit for bit.
#include "film/png_reader.h"

#include <png.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "film/same_reading_test_support.h"
#include "temp_folder.h"

namespace lancer {
namespace {

struct PngShape {
    int color_type;
    int bit_depth;
    bool transparency;  // a tRNS chunk
    bool interlaced;
    bool gamma;  // a gAMA chunk of 1/1.8
    bool srgb;   // an sRGB chunk (with its gAMA of 1/2.2)
};

std::string describe(const PngShape& shape) {
    return "colour type " + std::to_string(shape.color_type) + ", " + std::to_string(shape.bit_depth) + " bits" +
           (shape.transparency ? ", tRNS" : "") + (shape.interlaced ? ", interlaced" : "") +
           (shape.gamma ? ", gAMA" : "") + (shape.srgb ? ", sRGB" : "");
}

// Writes a 13 x 7 PNG of random samples (indices below the palette's size).
void write_png(const std::string& path, const PngShape& shape, std::uint32_t seed) {
    const int width = 13, height = 7;
    std::mt19937 random(seed);
    std::FILE* file = std::fopen(path.c_str(), "wb");
    ASSERT_NE(file, nullptr);
    png_structp png = png_create_write_struct(PNG_LIBPNG_VER_STRING, nullptr, nullptr, nullptr);
    png_infop info = png_create_info_struct(png);
    if (setjmp(png_jmpbuf(png))) {
        ADD_FAILURE() << "libpng failed writing " << describe(shape);
        png_destroy_write_struct(&png, &info);
        std::fclose(file);
        return;
    }
    png_init_io(png, file);
    png_set_IHDR(png, info, width, height, shape.bit_depth, shape.color_type,
                 shape.interlaced ? PNG_INTERLACE_ADAM7 : PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    const int palette_size = shape.color_type == PNG_COLOR_TYPE_PALETTE ? 1 << std::min(shape.bit_depth, 4) : 0;
    std::vector<png_color> palette(std::size_t(std::max(palette_size, 1)));
    for (png_color& entry : palette)
        entry = png_color{png_byte(random() & 255u), png_byte(random() & 255u), png_byte(random() & 255u)};
    if (palette_size > 0) png_set_PLTE(png, info, palette.data(), palette_size);
    std::vector<png_byte> alphas(std::size_t(std::max(palette_size, 1)));
    for (png_byte& alpha : alphas) alpha = png_byte(random() & 255u);
    png_color_16 key{};
    key.gray = png_uint_16(1u % (1u << std::min(shape.bit_depth, 16)));
    key.red = 3, key.green = 5, key.blue = 7;
    if (shape.transparency) png_set_tRNS(png, info, alphas.data(), palette_size, &key);
    if (shape.gamma) png_set_gAMA(png, info, 1.0 / 1.8);
    if (shape.srgb) png_set_sRGB_gAMA_and_cHRM(png, info, PNG_sRGB_INTENT_PERCEPTUAL);
    png_write_info(png, info);
    if (shape.bit_depth == 16) png_set_swap(png);  // rows below are in the machine's order
    const int channels = shape.color_type == PNG_COLOR_TYPE_GRAY || shape.color_type == PNG_COLOR_TYPE_PALETTE ? 1
                         : shape.color_type == PNG_COLOR_TYPE_GRAY_ALPHA                                       ? 2
                         : shape.color_type == PNG_COLOR_TYPE_RGB                                              ? 3
                                                                                                               : 4;
    const std::uint32_t top = palette_size > 0 ? std::uint32_t(palette_size - 1) : (1u << shape.bit_depth) - 1u;
    std::vector<png_byte> rows(std::size_t(height) * png_get_rowbytes(png, info) + 16, 0);
    std::vector<png_bytep> pointers(height);
    for (int y = 0; y < height; ++y) {
        png_bytep row = rows.data() + std::size_t(y) * png_get_rowbytes(png, info);
        pointers[std::size_t(y)] = row;
        for (int i = 0; i < width * channels; ++i) {
            // Some samples equal the tRNS key, so it makes pixels transparent.
            const std::uint32_t value = random() % 4 == 0 ? 1u % (top + 1u) : random() % (top + 1u);
            if (shape.bit_depth == 16) {
                const std::uint16_t word = std::uint16_t(value);
                std::memcpy(row + 2 * i, &word, 2);
            } else if (shape.bit_depth == 8) {
                row[i] = png_byte(value);
            } else {
                const int per_byte = 8 / shape.bit_depth;
                const int shift = 8 - shape.bit_depth * (i % per_byte + 1);
                row[i / per_byte] = png_byte(row[i / per_byte] | (value << shift));
            }
        }
    }
    png_write_image(png, pointers.data());
    png_write_end(png, nullptr);
    png_destroy_write_struct(&png, &info);
    std::fclose(file);
}

// Both readers' header and samples, as `type`, must agree.
void expect_same_reading(const std::string& path, bool stored_colours, SampleType type, const std::string& what) {
    test::expect_same_reading(open_png_file(path, stored_colours), image_codecs().open(path, stored_colours), type,
                              what);
}

TEST(PngReader, ReadsEveryKindOfPngAsTheImageModuleDoes) {
    const test::TempFolder folder;
    const std::vector<std::pair<int, std::vector<int>>> kinds = {
        {PNG_COLOR_TYPE_GRAY, {1, 2, 4, 8, 16}}, {PNG_COLOR_TYPE_PALETTE, {1, 2, 4, 8}}, {PNG_COLOR_TYPE_RGB, {8, 16}},
        {PNG_COLOR_TYPE_GRAY_ALPHA, {8, 16}},    {PNG_COLOR_TYPE_RGB_ALPHA, {8, 16}},
    };
    std::uint32_t seed = 1;
    for (const auto& [color_type, depths] : kinds)
        for (const int depth : depths)
            for (const bool transparency : {false, true}) {
                if (transparency && (color_type & PNG_COLOR_MASK_ALPHA)) continue;  // tRNS only without alpha
                for (const bool interlaced : {false, true})
                    for (const int chunk : {0, 1, 2}) {
                        const PngShape shape{color_type, depth, transparency, interlaced, chunk == 1, chunk == 2};
                        const std::string path = (folder.path() / ("kind_" + std::to_string(seed) + ".png")).string();
                        write_png(path, shape, seed++);
                        for (const bool stored : {true, false}) {
                            const std::unique_ptr<ImageFileReader> ours = open_png_file(path, stored);
                            const SampleType native =
                                ours && ours->info().bits_per_sample == 16 ? SampleType::UInt16 : SampleType::UInt8;
                            const std::string what = describe(shape) + (stored ? ", stored colours" : "");
                            expect_same_reading(path, stored, native, what);
                            expect_same_reading(path, stored, SampleType::UInt16, what + ", as 16 bits");
                            expect_same_reading(path, stored, SampleType::Float, what + ", as float");
                        }
                    }
            }
}

TEST(PngReader, ReadsPovRaysOwnPngsAsTheImageModuleDoes) {
    int files = 0;
    for (const char* folder : {"/usr/share/povray-3.7/include", "/usr/share/doc/povray/examples"}) {
        if (!std::filesystem::is_directory(folder)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
            if (entry.path().extension() != ".png") continue;
            ++files;
            for (const bool stored : {true, false}) {
                const std::unique_ptr<ImageFileReader> ours = open_png_file(entry.path().string(), stored);
                const SampleType native =
                    ours && ours->info().bits_per_sample == 16 ? SampleType::UInt16 : SampleType::UInt8;
                expect_same_reading(entry.path().string(), stored, native, entry.path().string());
            }
        }
    }
    if (files == 0) GTEST_SKIP() << "POV-Ray's files are not installed (povray-includes)";
}

TEST(PngReader, LeavesOtherFilesToTheModuleAndNamesDamage) {
    const test::TempFolder folder;
    const std::string text = (folder.path() / "not_a_png.png").string();
    std::ofstream(text) << "P3\n1 1\n255\n0 0 0\n";
    EXPECT_EQ(open_png_file(text, true), nullptr);
    EXPECT_EQ(open_png_file((folder.path() / "missing.png").string(), true), nullptr);

    // A PNG cut short: the header reads, the pixels do not.
    const std::string whole = (folder.path() / "whole.png").string();
    write_png(whole, PngShape{PNG_COLOR_TYPE_RGB, 8, false, false, false, false}, 5);
    std::vector<char> bytes;
    {
        std::ifstream in(whole, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    const std::string cut = (folder.path() / "cut.png").string();
    std::ofstream(cut, std::ios::binary).write(bytes.data(), std::streamsize(bytes.size() / 2 + 20));
    std::unique_ptr<ImageFileReader> reader = open_png_file(cut, true);
    ASSERT_NE(reader, nullptr);
    std::vector<unsigned char> pixels(std::size_t(reader->info().width) * reader->info().height * 3);
    EXPECT_THROW(reader->read_rows(0, reader->info().height, SampleType::UInt8, pixels.data()), std::runtime_error);
    // Rows are decoded as they are read: a later band first skips the rows
    // before it; an earlier one after that is refused, not misread.
    {
        std::unique_ptr<ImageFileReader> ours = open_png_file(whole, true);
        test::expect_later_band_read_first(*ours, *image_codecs().open(whole, true));
        std::vector<unsigned char> row(std::size_t(ours->info().width) * 3);
        EXPECT_THROW(ours->read_rows(0, 1, SampleType::UInt8, row.data()), std::runtime_error);
    }
    // Its header alone cut: named at open.
    std::ofstream(cut, std::ios::binary).write(bytes.data(), 20);
    EXPECT_THROW(open_png_file(cut, true), std::runtime_error);
}

}  // namespace
}  // namespace lancer
