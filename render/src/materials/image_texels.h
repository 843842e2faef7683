// An image file's texels in memory, each sample as the file stores it
// (bytes for 8-bit files, 16-bit words, floats), read whole once per file
// and shared by every map of a scene that names it (internal to liblancer).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "film/image_codecs.h"

namespace lancer {

class ImageTexels {
  public:
    // Throws std::runtime_error with the reason: the file cannot be read
    // or decoded in full, claims more than 16384 x 16384 pixels (refused
    // before decoding: a header of a few bytes can claim any size), or
    // holds NaN or infinite samples.
    explicit ImageTexels(const std::string& path);

    int width() const { return m_width; }
    int height() const { return m_height; }
    int channels() const { return m_channels; }
    bool floating() const { return m_type == SampleType::Float; }

    // Channel `c` of texel (x, y), row 0 at the top, in [0, 1] for integer
    // files (the file's value over its largest).
    float sample(int x, int y, int c) const {
        const std::size_t at =
            (std::size_t(y) * std::size_t(m_width) + std::size_t(x)) * std::size_t(m_channels) + std::size_t(c);
        switch (m_type) {
        case SampleType::UInt8: return float(m_bytes[at]) * (1.0f / 255.0f);
        case SampleType::UInt16: return float(m_words[at]) * (1.0f / 65535.0f);
        case SampleType::Float: break;
        }
        return m_floats[at];
    }
    // Each channel's mean over the image.
    const std::vector<float>& average() const { return m_average; }

  private:
    int m_width = 0;
    int m_height = 0;
    int m_channels = 0;
    SampleType m_type = SampleType::UInt8;
    std::vector<unsigned char> m_bytes;
    std::vector<unsigned short> m_words;
    std::vector<float> m_floats;
    std::vector<float> m_average;
};

// The scene's images by path, each read once.
class ImageCache {
  public:
    std::shared_ptr<const ImageTexels> get(const std::string& path);

  private:
    std::mutex m_mutex;
    std::map<std::string, std::shared_ptr<const ImageTexels>> m_images;
};

}  // namespace lancer
