// JPEG files through libjpeg (jpeg_reader.h).
#include "film/jpeg_reader.h"

#include <csetjmp>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

#include <jpeglib.h>

namespace lancer {
namespace {

// libjpeg reports errors through error_exit, which must not return: it
// records the reason and jumps back to the setjmp of the one function that
// called libjpeg, which holds no object with a destructor and returns false.
struct JpegErrors {
    jpeg_error_mgr manager;
    std::jmp_buf jump;
    char message[JMSG_LENGTH_MAX] = "libjpeg error";
};

[[noreturn]] void on_jpeg_error(j_common_ptr info) {
    auto* errors = reinterpret_cast<JpegErrors*>(info->err);
    info->err->format_message(info, errors->message);
    std::longjmp(errors->jump, 1);
}

// Warnings (corrupt data libjpeg can go on past) are not printed.
void on_jpeg_message(j_common_ptr) {}

bool read_header(jpeg_decompress_struct* jpeg, JpegErrors* errors, std::FILE* file) {
    if (setjmp(errors->jump)) return false;
    jpeg_create_decompress(jpeg);
    jpeg_stdio_src(jpeg, file);
    jpeg_read_header(jpeg, TRUE);
    return true;
}

bool start(jpeg_decompress_struct* jpeg, JpegErrors* errors, J_COLOR_SPACE colours) {
    if (setjmp(errors->jump)) return false;
    jpeg->out_color_space = colours;
    jpeg_start_decompress(jpeg);
    return true;
}

bool read_next_row(jpeg_decompress_struct* jpeg, JpegErrors* errors, unsigned char* row) {
    if (setjmp(errors->jump)) return false;
    JSAMPROW rows[1] = {row};
    return jpeg_read_scanlines(jpeg, rows, 1) == 1;
}

class JpegFileReader final : public ImageFileReader {
  public:
    explicit JpegFileReader(std::string path) : m_path(std::move(path)) {
        std::memset(&m_jpeg, 0, sizeof m_jpeg);
        m_jpeg.err = jpeg_std_error(&m_errors.manager);
        m_errors.manager.error_exit = on_jpeg_error;
        m_errors.manager.output_message = on_jpeg_message;
    }
    ~JpegFileReader() override {
        if (m_created) jpeg_destroy_decompress(&m_jpeg);
        if (m_file != nullptr) std::fclose(m_file);
    }

    // False when the file is no JPEG, or one this reader leaves to the module.
    bool open() {
        m_file = std::fopen(m_path.c_str(), "rb");
        if (m_file == nullptr) return false;  // the module names the reason
        unsigned char signature[3];
        const bool jpeg = std::fread(signature, 1, 3, m_file) == 3 && signature[0] == 0xFF && signature[1] == 0xD8 &&
                          signature[2] == 0xFF;
        if (!jpeg || std::fseek(m_file, 0, SEEK_SET) != 0) return false;
        m_created = true;
        if (!read_header(&m_jpeg, &m_errors, m_file)) fail();
        J_COLOR_SPACE colours;
        if (m_jpeg.num_components == 1) {
            colours = JCS_GRAYSCALE;
        } else if (m_jpeg.num_components == 3 && m_jpeg.jpeg_color_space != JCS_CMYK &&
                   m_jpeg.jpeg_color_space != JCS_YCCK) {
            colours = JCS_RGB;
        } else {
            return false;
        }
        if (!start(&m_jpeg, &m_errors, colours)) fail();
        m_info.format = "jpeg";
        m_info.width = int(m_jpeg.output_width);
        m_info.height = int(m_jpeg.output_height);
        m_info.channels = m_jpeg.output_components;
        m_info.bits_per_sample = 8;
        m_info.floating = false;
        m_row.resize(std::size_t(m_info.width) * std::size_t(m_info.channels));
        return true;
    }

    const ImageFileInfo& info() const override { return m_info; }

    void read_rows(int first, int end, SampleType type, void* out) override {
        if (first < 0 || end > m_info.height || first > end) throw std::runtime_error("rows out of range");
        if (type != SampleType::UInt8 && type != SampleType::UInt16) {
            // Conversions of the module's own (its rounding): through it.
            image_codecs().open(m_path, true)->read_rows(first, end, type, out);
            return;
        }
        const std::size_t row_samples = m_row.size();
        for (int y = first; y < end; ++y) {
            const unsigned char* source = row(y);
            const std::size_t at = std::size_t(y - first) * row_samples;
            if (type == SampleType::UInt8) {
                std::memcpy(static_cast<unsigned char*>(out) + at, source, row_samples);
                continue;
            }
            widen_samples(source, row_samples, static_cast<std::uint16_t*>(out) + at);
        }
    }

  private:
    [[noreturn]] void fail() const { throw std::runtime_error(m_errors.message); }

    // Row y, decoded. Rows come one at a time as the callers read them
    // (bands from the top), so a big image is never whole in memory; the
    // last row may be read again, an earlier one not.
    const unsigned char* row(int y) {
        if (m_failed) fail();  // libjpeg may not go on after an error
        if (y == m_next_row - 1) return m_row.data();
        if (y < m_next_row) throw std::runtime_error("JPEG rows read out of order");
        while (m_next_row <= y) {  // rows skipped are read and dropped
            if (!read_next_row(&m_jpeg, &m_errors, m_row.data())) {
                m_failed = true;
                fail();
            }
            ++m_next_row;
        }
        return m_row.data();
    }

    std::string m_path;
    std::FILE* m_file = nullptr;
    jpeg_decompress_struct m_jpeg;
    JpegErrors m_errors;
    bool m_created = false;
    ImageFileInfo m_info;
    std::vector<unsigned char> m_row;
    int m_next_row = 0;  // the next row libjpeg gives
    bool m_failed = false;
};

}  // namespace

std::unique_ptr<ImageFileReader> open_jpeg_file(const std::string& path) {
    auto reader = std::make_unique<JpegFileReader>(path);
    if (!reader->open()) return nullptr;
    return reader;
}

}  // namespace lancer
