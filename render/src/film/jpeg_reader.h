// Reading JPEG files with libjpeg itself: Debian's OpenImageIO costs about
// 0.4 s of CPU to load (image_codecs.h), more than POV-Ray's whole run of a
// scene with a JPEG height field or image map. The values are the image
// module's, bit for bit (jpeg_reader_test.cpp holds them to it): OpenImageIO
// decodes with libjpeg's defaults too, to RGB or grey bytes. CMYK files,
// which OpenImageIO converts itself, are left to the module (internal to
// liblancer).
#pragma once

#include <memory>
#include <string>

#include "film/image_codecs.h"

namespace lancer {

// The file's reader when its signature is JPEG's and its colours RGB or
// grey; null otherwise (the module then reads it or names why not). Throws
// std::runtime_error with libjpeg's reason for a damaged JPEG. read_rows
// takes bytes (or 16 bits, scaled); other types go through the module.
std::unique_ptr<ImageFileReader> open_jpeg_file(const std::string& path);

}  // namespace lancer
