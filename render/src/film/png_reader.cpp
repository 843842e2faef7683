// PNG files through libpng (png_reader.h).
#include "film/png_reader.h"

#include <png.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <vector>

#include "film/jpeg_reader.h"
#include "film/libpng_errors.h"

namespace lancer {
namespace {

// The functions below that call libpng hold no object with a destructor
// and turn its longjmp (libpng_errors.h) into `false`.
struct Header {
    png_uint_32 width = 0, height = 0;
    int bit_depth = 0;
    int color_type = 0;
    bool transparency = false;  // a tRNS chunk
    bool interlaced = false;
    bool srgb = false;   // an sRGB chunk
    double gamma = 0.0;  // a gAMA chunk's value (0: none)
};

bool read_header(png_structp png, png_infop info, std::FILE* file, Header* header) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_init_io(png, file);
    png_set_sig_bytes(png, 8);
    png_read_info(png, info);
    header->width = png_get_image_width(png, info);
    header->height = png_get_image_height(png, info);
    header->bit_depth = png_get_bit_depth(png, info);
    header->color_type = png_get_color_type(png, info);
    header->transparency = png_get_valid(png, info, PNG_INFO_tRNS) != 0;
    header->interlaced = png_get_interlace_type(png, info) != PNG_INTERLACE_NONE;
    int intent = 0;
    header->srgb = png_get_sRGB(png, info, &intent) != 0;
    if (!png_get_gAMA(png, info, &header->gamma)) header->gamma = 0.0;
    return true;
}

// What the image module's reader asks libpng for: palettes to RGB, grey
// below 8 bits to 8, tRNS to an alpha channel, 16-bit samples in the
// machine's order.
struct Layout {
    int channels = 0;
    int bit_depth = 0;
    std::size_t row_bytes = 0;
};

bool expand(png_structp png, png_infop info, int file_bit_depth, Layout* layout) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_set_expand(png);
    if (file_bit_depth == 16) {
        const std::uint16_t probe = 1;
        unsigned char first;
        std::memcpy(&first, &probe, 1);
        if (first == 1) png_set_swap(png);  // little-endian machine
    }
    png_read_update_info(png, info);
    layout->channels = png_get_channels(png, info);
    layout->bit_depth = png_get_bit_depth(png, info);
    layout->row_bytes = png_get_rowbytes(png, info);
    return true;
}

bool read_pixels(png_structp png, png_bytepp rows) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_image(png, rows);
    return true;
}

bool read_next_row(png_structp png, png_bytep row) {
    if (setjmp(png_jmpbuf(png))) return false;
    png_read_row(png, row, nullptr);
    return true;
}

class PngFileReader final : public ImageFileReader {
  public:
    PngFileReader(std::string path, bool stored_colours) : m_path(std::move(path)), m_stored(stored_colours) {}
    ~PngFileReader() override {
        if (m_png != nullptr) png_destroy_read_struct(&m_png, m_info != nullptr ? &m_info : nullptr, nullptr);
        if (m_file != nullptr) std::fclose(m_file);
    }

    // False when the file is no PNG, or one this reader leaves to the module.
    bool open() {
        m_file = std::fopen(m_path.c_str(), "rb");
        if (m_file == nullptr) return false;  // the module names the reason
        png_byte signature[8];
        if (std::fread(signature, 1, 8, m_file) != 8 || png_sig_cmp(signature, 0, 8) != 0) return false;
        m_png = png_create_read_struct(PNG_LIBPNG_VER_STRING, &m_error, on_libpng_error, on_libpng_warning);
        if (m_png == nullptr) throw std::runtime_error("libpng cannot start");
        m_info = png_create_info_struct(m_png);
        if (m_info == nullptr) throw std::runtime_error("libpng cannot start");
        Header header;
        if (!read_header(m_png, m_info, m_file, &header)) fail();
        m_alpha = (header.color_type & PNG_COLOR_MASK_ALPHA) != 0 || header.transparency;
        m_interlaced = header.interlaced;
        // OpenImageIO's gamma: the gAMA chunk's inverse to the hundredth,
        // unless an sRGB chunk says sRGB.
        if (!header.srgb && header.gamma > 0.0) m_gamma = std::round(100.0f * float(1.0 / header.gamma)) / 100.0f;
        Layout layout;
        if (!expand(m_png, m_info, header.bit_depth, &layout)) fail();
        m_row_bytes = layout.row_bytes;
        m_info_out.format = "png";
        m_info_out.width = int(header.width);
        m_info_out.height = int(header.height);
        m_info_out.channels = layout.channels;
        // As the module reports it: the depth libpng expanded the samples to.
        m_info_out.bits_per_sample = layout.bit_depth;
        m_info_out.floating = false;
        m_sample_bytes = layout.bit_depth == 16 ? 2 : 1;
        if (layout.bit_depth != 8 && layout.bit_depth != 16) throw std::runtime_error("unexpected PNG sample size");
        return true;
    }

    const ImageFileInfo& info() const override { return m_info_out; }

    void read_rows(int first, int end, SampleType type, void* out) override {
        if (first < 0 || end > m_info_out.height || first > end) throw std::runtime_error("rows out of range");
        const SampleType native = m_sample_bytes == 2 ? SampleType::UInt16 : SampleType::UInt8;
        const bool widened = native == SampleType::UInt8 && type == SampleType::UInt16;
        if (type != native && !widened) {
            // Conversions of the module's own (its rounding): through it.
            image_codecs().open(m_path, m_stored)->read_rows(first, end, type, out);
            return;
        }
        const std::size_t row_samples = m_row_bytes / std::size_t(m_sample_bytes);
        for (int y = first; y < end; ++y) {
            const unsigned char* source = row(y);
            const std::size_t at = std::size_t(y - first) * row_samples;
            if (!widened) {
                std::memcpy(static_cast<unsigned char*>(out) + at * std::size_t(m_sample_bytes), source, m_row_bytes);
                continue;
            }
            widen_samples(source, row_samples, static_cast<std::uint16_t*>(out) + at);
        }
    }

  private:
    [[noreturn]] void fail() const { throw std::runtime_error(m_error.message); }

    // Row y, decoded. Rows come one at a time as the callers read them
    // (bands from the top), so a big height field is never whole in
    // memory; an interlaced file, or a row read again, needs the whole
    // image, decoded at once.
    const unsigned char* row(int y) {
        if (m_failed) fail();  // libpng may not go on after an error
        if (!m_interlaced && !m_whole && y >= m_next_row) {
            m_pixels.resize(m_row_bytes);
            while (m_next_row <= y) {  // rows skipped are read and dropped
                if (!read_next_row(m_png, m_pixels.data())) {
                    m_failed = true;
                    fail();
                }
                ++m_next_row;
            }
            multiply_rows_by_alpha(m_pixels.data(), 1);
            return m_pixels.data();
        }
        if (!m_whole) {
            if (m_next_row != 0) throw std::runtime_error("PNG rows read out of order");
            const std::size_t height = std::size_t(m_info_out.height);
            m_pixels.resize(m_row_bytes * height);
            std::vector<png_bytep> rows(height);
            for (std::size_t r = 0; r < height; ++r) rows[r] = m_pixels.data() + r * m_row_bytes;
            if (!read_pixels(m_png, rows.data())) {
                m_failed = true;
                fail();
            }
            m_whole = true;
            multiply_rows_by_alpha(m_pixels.data(), m_info_out.height);
        }
        return m_pixels.data() + std::size_t(y) * m_row_bytes;
    }

    void multiply_rows_by_alpha(unsigned char* bytes, int rows) const {
        if (!m_alpha || m_stored) return;
        const std::size_t pixels = std::size_t(m_info_out.width) * std::size_t(rows);
        if (m_sample_bytes == 2)
            multiply_by_alpha(reinterpret_cast<std::uint16_t*>(bytes), pixels);
        else
            multiply_by_alpha(bytes, pixels);
    }

    // Colours multiplied by alpha as the image module has OpenImageIO 2.4
    // do it: in integers where the file declares no gamma, else by alpha
    // raised to the file's gamma, truncated.
    template <class Sample>
    void multiply_by_alpha(Sample* samples, std::size_t pixels) const {
        constexpr unsigned top = std::numeric_limits<Sample>::max();
        const int channels = m_info_out.channels, alpha = channels - 1;
        for (std::size_t i = 0; i < pixels; ++i, samples += channels) {
            if (m_gamma == 1.0f) {
                for (int c = 0; c < alpha; ++c) samples[c] = Sample(unsigned(samples[c]) * samples[alpha] / top);
                continue;
            }
            const float associate = std::pow(float(samples[alpha]) * (1.0f / float(top)), m_gamma);
            for (int c = 0; c < alpha; ++c) samples[c] = Sample(float(samples[c]) * associate);
        }
    }

    std::string m_path;
    bool m_stored;
    std::FILE* m_file = nullptr;
    png_structp m_png = nullptr;
    png_infop m_info = nullptr;
    LibpngError m_error;
    ImageFileInfo m_info_out;
    std::size_t m_row_bytes = 0;
    int m_sample_bytes = 1;
    bool m_interlaced = false;
    bool m_whole = false;  // every row decoded into m_pixels
    int m_next_row = 0;    // the next row libpng gives, read row by row
    bool m_failed = false;
    bool m_alpha = false;  // an alpha channel, or one from tRNS
    float m_gamma = 1.0f;  // OpenImageIO's oiio:Gamma for the file
    std::vector<unsigned char> m_pixels;
};

}  // namespace

std::unique_ptr<ImageFileReader> open_png_file(const std::string& path, bool stored_colours) {
    auto reader = std::make_unique<PngFileReader>(path, stored_colours);
    if (!reader->open()) return nullptr;
    return reader;
}

std::unique_ptr<ImageFileReader> open_image_file(const std::string& path, bool stored_colours) {
    if (std::unique_ptr<ImageFileReader> png = open_png_file(path, stored_colours)) return png;
    // A JPEG has no alpha: its colours are the same stored or multiplied.
    if (std::unique_ptr<ImageFileReader> jpeg = open_jpeg_file(path)) return jpeg;
    return image_codecs().open(path, stored_colours);
}

}  // namespace lancer
