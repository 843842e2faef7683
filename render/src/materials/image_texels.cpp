#include "materials/image_texels.h"

#include <cmath>
#include <stdexcept>

#include "film/png_reader.h"

namespace lancer {
namespace {

constexpr double kMaxTexturePixels = 16384.0 * 16384.0;

}  // namespace

ImageTexels::ImageTexels(const std::string& path) {
    if (path.empty()) throw std::runtime_error("no file name");
    // Colours as OpenImageIO gives them by default: what image maps have
    // always read (multiplied by alpha where the format's reader does so).
    const std::unique_ptr<ImageFileReader> input = open_image_file(path, false);
    const ImageFileInfo& info = input->info();
    if (double(info.width) * double(info.height) > kMaxTexturePixels)
        throw std::length_error("it claims " + std::to_string(info.width) + " x " + std::to_string(info.height) +
                                " pixels: more than lancer's limit of 16384 x 16384");
    if (info.channels < 1 || info.width < 1 || info.height < 1) throw std::runtime_error("it has no pixels");
    m_width = info.width;
    m_height = info.height;
    m_channels = info.channels;
    m_type = info.native_type();
    const std::size_t count = std::size_t(m_width) * std::size_t(m_height) * std::size_t(m_channels);
    void* out = nullptr;
    switch (m_type) {
    case SampleType::UInt8: m_bytes.resize(count), out = m_bytes.data(); break;
    case SampleType::UInt16: m_words.resize(count), out = m_words.data(); break;
    case SampleType::Float: m_floats.resize(count), out = m_floats.data(); break;
    }
    input->read_rows(0, m_height, m_type, out);
    for (const float value : m_floats)
        if (!std::isfinite(value)) throw std::runtime_error("it holds texels that are NaN or infinite");
    std::vector<double> sums(std::size_t(m_channels), 0.0);
    for (int y = 0; y < m_height; ++y)
        for (int x = 0; x < m_width; ++x)
            for (int c = 0; c < m_channels; ++c) sums[std::size_t(c)] += double(sample(x, y, c));
    const double pixels = double(m_width) * double(m_height);
    for (const double sum : sums) m_average.push_back(float(sum / pixels));
}

std::shared_ptr<const ImageTexels> ImageCache::get(const std::string& path) {
    std::lock_guard<std::mutex> lock(m_mutex);
    std::shared_ptr<const ImageTexels>& image = m_images[path];
    if (!image) image = std::make_shared<const ImageTexels>(path);
    return image;
}

}  // namespace lancer
