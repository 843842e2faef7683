// Reading PNG files with libpng itself (linked already for PNG output):
// Debian's OpenImageIO costs about 0.4 s of CPU to load (image_codecs.h),
// more than POV-Ray's whole run of many a scene with a PNG image map or
// height field. The values are the image module's, bit for bit
// (png_reader_test.cpp holds every kind of PNG to it): libpng expands
// palettes, low bit depths and tRNS transparency as OpenImageIO has it do,
// and colours are multiplied by alpha with OpenImageIO 2.4's arithmetic
// unless stored colours are asked for. Conversions to other sample types
// are left to the module (internal to liblancer).
#pragma once

#include <memory>
#include <string>

#include "film/image_codecs.h"

namespace lancer {

// The file's reader when its signature is PNG's; null otherwise (the
// module then reads it or names why not). Throws std::runtime_error with
// libpng's reason for a damaged PNG. read_rows takes the file's own sample
// type (and 16 bits from an 8-bit file); other types go through the module.
std::unique_ptr<ImageFileReader> open_png_file(const std::string& path, bool stored_colours);

// An image file through the PNG or JPEG reader (jpeg_reader.h) where one
// serves, else the module.
std::unique_ptr<ImageFileReader> open_image_file(const std::string& path, bool stored_colours);

}  // namespace lancer
