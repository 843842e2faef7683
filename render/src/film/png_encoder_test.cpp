// The PNG writer against OpenImageIO's reading of what it wrote.
#include "film/png_encoder.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "temp_folder.h"

namespace lancer {
namespace {

struct ReadBack {
    OIIO::ImageSpec spec;
    std::vector<unsigned short> values;
};

ReadBack read_back(const std::string& path) {
    ReadBack image;
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(path, &config);
    EXPECT_TRUE(input) << OIIO::geterror();
    if (!input) return image;
    image.spec = input->spec();
    image.values.resize(std::size_t(image.spec.width) * image.spec.height * image.spec.nchannels);
    EXPECT_TRUE(input->read_image(0, 0, 0, image.spec.nchannels, OIIO::TypeDesc::UINT16, image.values.data()));
    return image;
}

// Samples that hit the rounding boundaries and the clamps.
const std::vector<float> kSamples = {0.0f,  1.0f,        -0.5f,  2.0f, 0.6f / 255.0f, 0.4f / 255.0f,
                                     0.25f, 1.0f / 3.0f, 0.999f, 0.5f, 0.75f,         1e-9f};

// The samples above as an image of the given shape.
PngPixels sample_pixels(int width, int height, int channels = 3, int bits = 8) {
    PngPixels pixels;
    pixels.width = width;
    pixels.height = height;
    pixels.channels = channels;
    pixels.bits = bits;
    pixels.samples = kSamples.data();
    return pixels;
}

TEST(PngEncoder, EightBitSamplesRoundToNearestAndClamp) {
    test::TempFolder folder;
    const std::string path = (folder.path() / "rgb.png").string();
    PngPixels pixels = sample_pixels(2, 2);
    pixels.text = {{"Software", "lancer"}, {"lancer:integrator", "whitted"}};
    write_png_file(path, pixels);
    const ReadBack image = read_back(path);
    ASSERT_EQ(image.spec.width, 2);
    ASSERT_EQ(image.spec.height, 2);
    ASSERT_EQ(image.spec.nchannels, 3);
    EXPECT_EQ(image.spec.format, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(image.spec.get_string_attribute("lancer:integrator"), "whitted");
    EXPECT_EQ(image.spec.get_string_attribute("oiio:ColorSpace"), "sRGB");
    const int expected[] = {0, 255, 0, 255, 1, 0, 64, 85, 255, 128, 191, 0};
    for (std::size_t i = 0; i < kSamples.size(); ++i) EXPECT_EQ(image.values[i] / 257, expected[i]) << "sample " << i;
}

TEST(PngEncoder, CodeRowsAreWrittenAsGiven) {
    test::TempFolder folder;
    const std::string path = (folder.path() / "codes.png").string();
    PngPixels pixels;
    pixels.width = 2;
    pixels.height = 3;
    pixels.code_rows = [](int y, unsigned char* codes) {
        for (int i = 0; i < 6; ++i) codes[i] = (unsigned char)(40 * y + 7 * i);
    };
    write_png_file(path, pixels);
    const ReadBack image = read_back(path);
    ASSERT_EQ(image.spec.height, 3);
    for (int y = 0; y < 3; ++y)
        for (int i = 0; i < 6; ++i) EXPECT_EQ(image.values[std::size_t(6 * y + i)] / 257, 40 * y + 7 * i);
}

TEST(PngEncoder, SixteenBitsWithStraightAlpha) {
    test::TempFolder folder;
    const std::string path = (folder.path() / "rgba.png").string();
    write_png_file(path, sample_pixels(3, 1, 4, 16));
    const ReadBack image = read_back(path);
    ASSERT_EQ(image.spec.nchannels, 4);
    EXPECT_EQ(image.spec.format, OIIO::TypeDesc::UINT16);
    for (std::size_t i = 0; i < kSamples.size(); ++i) {
        const float clamped = std::clamp(kSamples[i], 0.0f, 1.0f);
        EXPECT_EQ(image.values[i], (unsigned short)(clamped * 65535.0f + 0.5f)) << "sample " << i;
    }
}

TEST(PngEncoder, MemoryAndFileHoldTheSameBytes) {
    test::TempFolder folder;
    const std::string path = (folder.path() / "same.png").string();
    const PngPixels pixels = sample_pixels(4, 1);
    write_png_file(path, pixels);
    const std::vector<unsigned char> bytes = encode_png_bytes(pixels);
    std::ifstream in(path, std::ios::binary);
    const std::vector<unsigned char> stored((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_EQ(bytes, stored);
}

TEST(PngEncoder, AnUnwritableFolderIsAnErrorWithTheReason) {
    try {
        write_png_file("/nonexistent-folder/x.png", sample_pixels(1, 1));
        FAIL() << "no error";
    } catch (const std::runtime_error& error) {
        EXPECT_NE(std::string(error.what()).find("No such file"), std::string::npos) << error.what();
    }
}

}  // namespace
}  // namespace lancer
