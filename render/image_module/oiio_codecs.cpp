// liblancer_images.so: lancer's image codecs (film/image_codecs.h) through
// OpenImageIO. liblancer loads this module at the first image it reads or
// writes in a format other than PNG output.
#include <algorithm>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

#include "film/image_codecs.h"

namespace lancer {
namespace {

OIIO::TypeDesc type_of(SampleType type) {
    switch (type) {
    case SampleType::UInt8: return OIIO::TypeDesc::UINT8;
    case SampleType::UInt16: return OIIO::TypeDesc::UINT16;
    case SampleType::Float: break;
    }
    return OIIO::TypeDesc::FLOAT;
}

std::size_t bytes_of(SampleType type) {
    return type == SampleType::UInt8 ? 1 : type == SampleType::UInt16 ? 2 : 4;
}

// OpenImageIO's messages span lines; one diagnostic is one line.
std::string one_line(std::string text) {
    while (!text.empty() && text.back() == '\n') text.pop_back();
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at)) text.replace(at, 1, "; ");
    return text.empty() ? std::string("unknown error") : text;
}

class OiioReader final : public ImageFileReader {
  public:
    explicit OiioReader(std::unique_ptr<OIIO::ImageInput> input) : m_input(std::move(input)) {
        const OIIO::ImageSpec& spec = m_input->spec();
        m_first_row = spec.y;
        m_info.format = m_input->format_name();
        m_info.width = spec.width;
        m_info.height = spec.height * std::max(spec.depth, 1);
        m_info.channels = spec.nchannels;
        m_info.floating = spec.format.is_floating_point();
        m_info.bits_per_sample = spec.get_int_attribute("oiio:BitsPerSample", int(spec.format.size()) * 8);
        m_tiled = spec.tile_width > 0 || spec.depth > 1;
    }
    const ImageFileInfo& info() const override { return m_info; }

    void read_rows(int first, int end, SampleType type, void* out) override {
        if (first < 0 || end > m_info.height || first > end)
            throw std::out_of_range("read_rows: rows outside the image");
        const std::size_t row_bytes = std::size_t(m_info.width) * std::size_t(m_info.channels) * bytes_of(type);
        if (m_tiled) {
            // Tiles are read whole once, in the type asked first.
            if (m_whole.empty() || m_whole_type != type) {
                m_whole.resize(row_bytes * std::size_t(m_info.height));
                m_whole_type = type;
                if (!m_input->read_image(0, 0, 0, m_info.channels, type_of(type), m_whole.data()))
                    throw std::runtime_error(one_line(m_input->geterror()));
            }
            std::copy(m_whole.begin() + std::ptrdiff_t(row_bytes * first),
                      m_whole.begin() + std::ptrdiff_t(row_bytes * end), static_cast<unsigned char*>(out));
            return;
        }
        if (first == end) return;
        if (!m_input->read_scanlines(0, 0, m_first_row + first, m_first_row + end, 0, 0, m_info.channels, type_of(type),
                                     out))
            throw std::runtime_error(one_line(m_input->geterror()));
    }

  private:
    std::unique_ptr<OIIO::ImageInput> m_input;
    ImageFileInfo m_info;
    int m_first_row = 0;
    bool m_tiled = false;  // read whole once, then copied from
    std::vector<unsigned char> m_whole;
    SampleType m_whole_type = SampleType::Float;
};

class OiioCodecs final : public ImageCodecs {
  public:
    std::unique_ptr<ImageFileReader> open(const std::string& path, bool stored_colours) override {
        OIIO::ImageSpec config;
        if (stored_colours) config.attribute("oiio:UnassociatedAlpha", 1);
        auto input = OIIO::ImageInput::open(path, &config);
        if (!input) throw std::runtime_error(one_line(OIIO::geterror()));
        return std::make_unique<OiioReader>(std::move(input));
    }

    void write(const std::string& path, const ImageFileWrite& image) override {
        OIIO::ImageSpec spec(image.width, image.height, int(image.channel_names.size()), type_of(image.file_type));
        spec.channelnames = image.channel_names;
        spec.alpha_channel = image.alpha_channel;
        for (const auto& [name, value] : image.text_attributes) spec.attribute(name, value);
        for (const auto& [name, value] : image.integer_attributes) spec.attribute(name, value);
        auto output = OIIO::ImageOutput::create(path);
        if (!output) throw std::runtime_error(one_line(OIIO::geterror()));
        if (!output->open(path, spec)) throw std::runtime_error(one_line(output->geterror()));
        if (!output->write_image(OIIO::TypeDesc::FLOAT, image.pixels)) {
            const std::string why = one_line(output->geterror());
            output->close();
            throw std::runtime_error(why);
        }
        if (!output->close()) throw std::runtime_error(one_line(output->geterror()));
    }
};

}  // namespace
}  // namespace lancer

extern "C" __attribute__((visibility("default"))) lancer::ImageCodecs* lancer_image_codecs_v1() {
    static lancer::OiioCodecs codecs;
    return &codecs;
}
