// Image files in every format lancer reads or writes besides PNG output,
// through OpenImageIO, which lives in a module of its own
// (liblancer_images.so beside liblancer.so) loaded at the first image:
// Debian's OpenImageIO maps 260 shared libraries and costs a third of a
// second before main, which a scene that reads no image and writes a PNG
// need not pay. The interface holds only standard types, so neither side
// sees the other's headers (internal to liblancer).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace lancer {

// How samples are stored in memory when read or handed over to be written.
enum class SampleType { UInt8, UInt16, Float };

struct ImageFileInfo {
    std::string format;  // OpenImageIO's format name: "png", "targa", "gif", "openexr" ...
    int width = 0;
    int height = 0;
    int channels = 0;
    int bits_per_sample = 8;  // as stored in the file (1 to 32)
    bool floating = false;    // half or float samples
    // The sample type that holds the file's values exactly (8-bit files as
    // bytes, 16-bit ones as UInt16, anything else as float).
    SampleType native_type() const {
        if (floating || bits_per_sample > 16) return SampleType::Float;
        return bits_per_sample > 8 ? SampleType::UInt16 : SampleType::UInt8;
    }
};

// One open image file. Methods throw std::runtime_error with the reason.
class ImageFileReader {
  public:
    virtual ~ImageFileReader() = default;
    virtual const ImageFileInfo& info() const = 0;
    // Rows [first, end) (0 at the top) of every channel, interleaved,
    // converted to `type` (integers scaled to their full range).
    virtual void read_rows(int first, int end, SampleType type, void* out) = 0;
};

// What write_image_file writes: interleaved float samples, row-major,
// quantised (rounding to nearest) when the file type is an integer one.
struct ImageFileWrite {
    int width = 0;
    int height = 0;
    std::vector<std::string> channel_names;
    int alpha_channel = -1;
    SampleType file_type = SampleType::Float;
    std::vector<std::pair<std::string, std::string>> text_attributes;
    std::vector<std::pair<std::string, int>> integer_attributes;
    const float* pixels = nullptr;
};

class ImageCodecs {
  public:
    virtual ~ImageCodecs() = default;
    // `stored_colours`: colours as the file stores them, not multiplied by
    // its alpha (OpenImageIO's default multiplies them for some formats).
    virtual std::unique_ptr<ImageFileReader> open(const std::string& path, bool stored_colours) = 0;
    // The format comes from the path's extension. Not atomic: callers
    // write a temporary file and rename it.
    virtual void write(const std::string& path, const ImageFileWrite& image) = 0;
};

// 8-bit samples as 16-bit ones, as the module widens them (v * 257), for
// lancer's own readers (png_reader.h, jpeg_reader.h).
inline void widen_samples(const unsigned char* samples, std::size_t count, std::uint16_t* out) {
    for (std::size_t i = 0; i < count; ++i) out[i] = std::uint16_t(samples[i] * 257u);
}

// The module's codecs, loaded at the first call. Throws std::runtime_error
// naming the module when it cannot be loaded.
ImageCodecs& image_codecs();

// Whether the module has been loaded in this process (for tests and stats).
bool image_codecs_loaded();

}  // namespace lancer

// The module's one entry point (version 1 of the interface above).
extern "C" lancer::ImageCodecs* lancer_image_codecs_v1();
