// The libjpeg reader against the image module's (OpenImageIO's) reading of
// the same files: grey and colour, every chroma subsampling, progressive
// and restart-marked files, colours stored as RGB, odd sizes, and the
// JPEGs POV-Ray ships. Same header values, same samples, bit for bit.
#include "film/jpeg_reader.h"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <vector>

#include <jpeglib.h>

#include <gtest/gtest.h>

#include "film/png_reader.h"
#include "film/same_reading_test_support.h"
#include "temp_folder.h"

namespace lancer {
namespace {

struct JpegShape {
    int width, height;
    int components;  // 1 or 3
    int h_sampling;  // of the first component: 1 (4:4:4), 2 (4:2:x)
    int v_sampling;  // 1 (4:4:4, 4:2:2), 2 (4:2:0)
    bool progressive;
    bool restarts;    // a restart marker every row of blocks
    bool stored_rgb;  // colours stored as RGB, not YCbCr
};

std::string describe(const JpegShape& s) {
    return std::to_string(s.width) + "x" + std::to_string(s.height) + ", " + std::to_string(s.components) +
           " components, sampling " + std::to_string(s.h_sampling) + "x" + std::to_string(s.v_sampling) +
           (s.progressive ? ", progressive" : "") + (s.restarts ? ", restarts" : "") +
           (s.stored_rgb ? ", stored RGB" : "");
}

// Smooth gradients with noise: what a photograph's blocks hold.
void write_jpeg(const std::string& path, const JpegShape& shape, std::uint32_t seed) {
    std::mt19937 random(seed);
    std::uniform_int_distribution<int> noise(-20, 20);
    std::FILE* file = std::fopen(path.c_str(), "wb");
    ASSERT_NE(file, nullptr);
    jpeg_compress_struct jpeg;
    jpeg_error_mgr errors;
    jpeg.err = jpeg_std_error(&errors);
    jpeg_create_compress(&jpeg);
    jpeg_stdio_dest(&jpeg, file);
    jpeg.image_width = JDIMENSION(shape.width);
    jpeg.image_height = JDIMENSION(shape.height);
    jpeg.input_components = shape.components;
    jpeg.in_color_space = shape.components == 1 ? JCS_GRAYSCALE : JCS_RGB;
    jpeg_set_defaults(&jpeg);
    jpeg_set_quality(&jpeg, 85, TRUE);
    if (shape.stored_rgb) jpeg_set_colorspace(&jpeg, JCS_RGB);
    jpeg.comp_info[0].h_samp_factor = shape.h_sampling;
    jpeg.comp_info[0].v_samp_factor = shape.v_sampling;
    if (shape.progressive) jpeg_simple_progression(&jpeg);
    if (shape.restarts) jpeg.restart_in_rows = 1;
    jpeg_start_compress(&jpeg, TRUE);
    std::vector<JSAMPLE> row(std::size_t(shape.width) * std::size_t(shape.components));
    for (int y = 0; y < shape.height; ++y) {
        for (int x = 0; x < shape.width; ++x)
            for (int c = 0; c < shape.components; ++c)
                row[std::size_t(x * shape.components + c)] =
                    JSAMPLE(std::clamp((x * 255) / shape.width + (c * 80 + y * 3) % 120 + noise(random), 0, 255));
        JSAMPROW rows[1] = {row.data()};
        jpeg_write_scanlines(&jpeg, rows, 1);
    }
    jpeg_finish_compress(&jpeg);
    jpeg_destroy_compress(&jpeg);
    std::fclose(file);
}

// Both readers' header and samples, as `type`, must agree.
void expect_same_reading(const std::string& path, SampleType type, const std::string& what) {
    test::expect_same_reading(open_jpeg_file(path), image_codecs().open(path, false), type, what);
}

TEST(JpegReader, ReadsEveryKindOfJpegAsTheImageModuleDoes) {
    const test::TempFolder folder;
    std::vector<JpegShape> shapes = {
        {16, 16, 1, 1, 1, false, false, false}, {37, 23, 1, 1, 1, true, false, false},
        {37, 23, 3, 2, 2, false, false, false}, {37, 23, 3, 2, 1, false, false, false},
        {37, 23, 3, 1, 1, false, false, false}, {64, 48, 3, 2, 2, true, false, false},
        {41, 29, 3, 2, 2, false, true, false},  {33, 17, 3, 1, 1, false, false, true},
        {1, 1, 3, 2, 2, false, false, false},   {300, 7, 3, 2, 2, true, true, false},
    };
    std::uint32_t seed = 1;
    for (const JpegShape& shape : shapes) {
        const std::string path = (folder.path() / ("kind_" + std::to_string(seed) + ".jpg")).string();
        write_jpeg(path, shape, seed++);
        expect_same_reading(path, SampleType::UInt8, describe(shape));
        expect_same_reading(path, SampleType::UInt16, describe(shape) + ", as 16 bits");
        expect_same_reading(path, SampleType::Float, describe(shape) + ", as float");
        // open_image_file takes this reader for it, stored colours or not.
        EXPECT_EQ(open_image_file(path, false)->info().format, "jpeg");
    }
}

TEST(JpegReader, ReadsPovRaysOwnJpegsAsTheImageModuleDoes) {
    int files = 0;
    for (const char* folder : {"/usr/share/povray-3.7/include", "/usr/share/doc/povray/examples"}) {
        if (!std::filesystem::is_directory(folder)) continue;
        for (const auto& entry : std::filesystem::recursive_directory_iterator(folder)) {
            const std::string extension = entry.path().extension().string();
            if (extension != ".jpg" && extension != ".jpeg") continue;
            if (!open_jpeg_file(entry.path().string())) continue;  // CMYK: the module's
            ++files;
            expect_same_reading(entry.path().string(), SampleType::UInt8, entry.path().string());
        }
    }
    if (files == 0) GTEST_SKIP() << "POV-Ray's JPEGs are not installed (povray-includes, povray-examples)";
}

TEST(JpegReader, LeavesOtherFilesToTheModuleAndNamesDamage) {
    const test::TempFolder folder;
    const std::string text = (folder.path() / "not_a_jpeg.jpg").string();
    std::ofstream(text) << "P3\n1 1\n255\n0 0 0\n";
    EXPECT_EQ(open_jpeg_file(text), nullptr);
    EXPECT_EQ(open_jpeg_file((folder.path() / "missing.jpg").string()), nullptr);

    const std::string whole = (folder.path() / "whole.jpg").string();
    write_jpeg(whole, JpegShape{40, 40, 3, 2, 2, false, false, false}, 5);
    std::vector<char> bytes;
    {
        std::ifstream in(whole, std::ios::binary);
        bytes.assign(std::istreambuf_iterator<char>(in), {});
    }
    // Rows are decoded as they are read: a later band first skips the rows
    // before it; the last row again is served, an earlier one refused.
    {
        std::unique_ptr<ImageFileReader> ours = open_jpeg_file(whole);
        test::expect_later_band_read_first(*ours, *image_codecs().open(whole, true));
        const int height = ours->info().height;
        std::vector<unsigned char> row(std::size_t(ours->info().width) * 3);
        EXPECT_NO_THROW(ours->read_rows(height - 1, height, SampleType::UInt8, row.data()));
        EXPECT_THROW(ours->read_rows(0, 1, SampleType::UInt8, row.data()), std::runtime_error);
    }
    // Its header alone cut: named at open.
    const std::string cut = (folder.path() / "cut.jpg").string();
    std::ofstream(cut, std::ios::binary).write(bytes.data(), 20);
    EXPECT_THROW(open_jpeg_file(cut), std::runtime_error);
}

}  // namespace
}  // namespace lancer
