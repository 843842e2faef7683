// Whether one of lancer's own image readers reads a file as the image
// module (OpenImageIO) does: the png_reader and jpeg_reader tests' yardstick.
#pragma once

#include <algorithm>
#include <cstddef>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "film/image_codecs.h"

namespace lancer::test {

// Both readers' header and samples, as `type`, must agree; ours is read in
// two bands, as the height field and palette readers ask.
inline void expect_same_reading(std::unique_ptr<ImageFileReader> ours, std::unique_ptr<ImageFileReader> module,
                                SampleType type, const std::string& what) {
    ASSERT_TRUE(module) << what;
    ASSERT_TRUE(ours) << what;
    const ImageFileInfo& a = ours->info();
    const ImageFileInfo& b = module->info();
    ASSERT_EQ(a.format, b.format) << what;
    ASSERT_EQ(a.width, b.width) << what;
    ASSERT_EQ(a.height, b.height) << what;
    ASSERT_EQ(a.channels, b.channels) << what;
    EXPECT_EQ(a.bits_per_sample, b.bits_per_sample) << what;
    EXPECT_EQ(a.floating, b.floating) << what;
    const std::size_t count = std::size_t(a.width) * std::size_t(a.height) * std::size_t(a.channels);
    const std::size_t bytes = count * (type == SampleType::UInt8 ? 1 : type == SampleType::UInt16 ? 2 : 4);
    std::vector<unsigned char> from_ours(bytes), from_module(bytes);
    const int middle = a.height / 2;
    const std::size_t split = bytes / std::size_t(a.height) * std::size_t(middle);
    ours->read_rows(0, middle, type, from_ours.data());
    ours->read_rows(middle, a.height, type, from_ours.data() + split);
    module->read_rows(0, a.height, type, from_module.data());
    EXPECT_EQ(from_ours, from_module) << what;
}

// Rows are decoded as they are read: a later band read first skips the
// rows before it and gives the module's samples (8-bit RGB files).
inline void expect_later_band_read_first(ImageFileReader& ours, ImageFileReader& module) {
    const int width = ours.info().width, height = ours.info().height;
    std::vector<unsigned char> from_ours(std::size_t(width) * 3 * std::size_t(height - 2));
    std::vector<unsigned char> all(std::size_t(width) * 3 * std::size_t(height));
    ours.read_rows(2, height, SampleType::UInt8, from_ours.data());
    module.read_rows(0, height, SampleType::UInt8, all.data());
    EXPECT_TRUE(std::equal(from_ours.begin(), from_ours.end(), all.begin() + std::ptrdiff_t(width) * 3 * 2));
}

}  // namespace lancer::test
