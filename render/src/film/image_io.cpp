// Writing films, atomically: PNG through libpng, the other formats through
// the image module (OpenImageIO).
#include "lancer/host/image_io.h"
#include "lancer/host/temporary_file.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <stdexcept>
#include <vector>

#include "film/file_extension.h"
#include "film/image_codecs.h"
#include "film/png_encoder.h"
#include "film/srgb8.h"

namespace lancer {
namespace {

namespace fs = std::filesystem;

enum class Encoding { Srgb8, Srgb16, LinearFloat };

}  // namespace

float linear_to_srgb(float linear) {
    linear = glm::clamp(linear, 0.0f, 1.0f);
    if (linear <= 0.0031308f) return 12.92f * linear;
    return 1.055f * std::pow(linear, 1.0f / 2.4f) - 0.055f;
}

float srgb_to_linear(float encoded) {
    encoded = glm::clamp(encoded, 0.0f, 1.0f);
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

bool is_supported_image_extension(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == ".png" || ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff" || ext == ".jpg" ||
           ext == ".jpeg";
}

void prepare_image_writer(const std::string& path) {
    if (lower_extension(path) != ".png") image_codecs();
}

bool image_format_has_alpha(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == ".png" || ext == ".exr" || ext == ".tif" || ext == ".tiff";
}

bool image_format_has_layers(const std::string& path) {
    return lower_extension(path) == ".exr";
}

namespace {

// The header a file of `path`'s format receives, and its rows of samples
// made one at a time from the film (a PNG never holds the whole image in
// float). Throws as write_image does.
struct EncodedImage {
    bool png = false;
    ImageFileWrite header;  // its `pixels` unset
    std::function<void(int row, float* samples)> row;
    std::function<void(int row, unsigned char* codes)> code_row;  // 8-bit PNG codes straight from the film, or unset

    PngPixels png_pixels() const {
        PngPixels out;
        out.width = header.width;
        out.height = header.height;
        out.channels = int(header.channel_names.size());
        out.bits = header.file_type == SampleType::UInt16 ? 16 : 8;
        out.rows = row;
        if (out.bits == 8) out.code_rows = code_row;
        out.text = header.text_attributes;
        return out;
    }
    // Every row, for the writers that take a whole image.
    std::vector<float> whole() const {
        const std::size_t row_samples = std::size_t(header.width) * header.channel_names.size();
        std::vector<float> samples(row_samples * std::size_t(header.height));
        for (int y = 0; y < header.height; ++y) row(y, samples.data() + row_samples * std::size_t(y));
        return samples;
    }
};

EncodedImage encode_for(const Film& film, const std::string& path, const ImageWriteOptions& options) {
    const std::string ext = lower_extension(path);
    if (!is_supported_image_extension(path))
        throw std::runtime_error("cannot write '" + path + "': unknown image extension '" + ext +
                                 "' (use .png, .jpg, .exr, .hdr, .tif or .tiff)");
    const bool png = ext == ".png", jpeg = ext == ".jpg" || ext == ".jpeg";
    const Encoding encoding = (png && options.png_bits == 16) || ext == ".tif" || ext == ".tiff" ? Encoding::Srgb16
                              : png || jpeg                                                      ? Encoding::Srgb8
                                            : Encoding::LinearFloat;
    const int width = film.width(), height = film.height();
    const std::size_t pixel_count = std::size_t(width) * std::size_t(height);
    const bool has_alpha = !options.alpha.empty();
    if (has_alpha && !image_format_has_alpha(path))
        throw std::runtime_error("cannot write '" + path + "': " + ext +
                                 " has no alpha channel (use .png, .exr or .tif)");
    if (has_alpha && options.alpha.size() != pixel_count)
        throw std::invalid_argument("write_image: the alpha channel is not the film's size");
    if (!options.layers.empty() && !image_format_has_layers(path))
        throw std::runtime_error("cannot write '" + path + "': only EXR holds extra layers (AOVs)");
    const bool sample_channel = options.sample_count_channel && ext == ".exr";

    std::vector<std::string> names{"R", "G", "B"};
    if (has_alpha) names.push_back("A");
    for (const ImageLayer& layer : options.layers) {
        if (layer.values.size() != pixel_count * layer.channels.size())
            throw std::invalid_argument("write_image: layer values are not the film's size");
        names.insert(names.end(), layer.channels.begin(), layer.channels.end());
    }
    if (sample_channel) names.push_back("samples");
    const int channels = int(names.size());

    // Pixels in float, encoded as the format wants; the writer quantises
    // (rounding to nearest) when the file is 8 or 16 bit. The film is
    // premultiplied: integer formats get the colour divided by alpha.
    const bool raw = encoding == Encoding::LinearFloat || !options.gamma_correction;
    const bool straight = has_alpha && encoding != Encoding::LinearFloat;
    // An 8-bit PNG's codes come from a table (film/srgb8.h), the same codes
    // its encoder would round linear_to_srgb() to.
    const bool srgb8_table = png && encoding == Encoding::Srgb8 && !raw;
    auto row = [&film, &options, has_alpha, straight, raw, srgb8_table, sample_channel, width, channels](
                   int y, float* samples) {
        for (int x = 0; x < width; ++x) {
            const std::size_t index = std::size_t(y) * width + x;
            const float alpha = has_alpha ? glm::clamp(options.alpha[index], 0.0f, 1.0f) : 1.0f;
            Color c = film.mean(x, y);
            if (has_alpha) c = alpha > 0.0f ? c / alpha : Color(0.0f);
            if (options.gamma_correction && options.working_gamma != 1.0)
                for (int k = 0; k < 3; ++k) c[k] = float(std::pow(std::max(double(c[k]), 0.0), options.working_gamma));
            if (has_alpha && !straight) c *= alpha;
            float* out = samples + std::size_t(x) * channels;
            int channel = 0;
            for (int k = 0; k < 3; ++k)
                out[channel++] = srgb8_table ? float(linear_to_srgb8(c[k])) / 255.0f
                                 : raw       ? c[k]
                                             : linear_to_srgb(c[k]);
            if (has_alpha) out[channel++] = alpha;
            for (const ImageLayer& layer : options.layers)
                for (std::size_t k = 0; k < layer.channels.size(); ++k)
                    out[channel++] = layer.values[index * layer.channels.size() + k];
            if (sample_channel) out[channel++] = float(film.sample_count(x, y));
        }
    };

    EncodedImage encoded;
    encoded.png = png;
    // The common PNG, colour alone in the working gamma, skips the floats:
    // its codes come straight from the film's means.
    if (srgb8_table && !has_alpha && options.layers.empty() && !sample_channel &&
        !(options.gamma_correction && options.working_gamma != 1.0))
        encoded.code_row = [&film, width](int y, unsigned char* codes) {
            std::vector<float> linear(std::size_t(width) * 3);
            for (int x = 0; x < width; ++x) {
                const Color c = film.mean(x, y);
                for (int k = 0; k < 3; ++k) linear[std::size_t(x) * 3 + std::size_t(k)] = c[k];
            }
            linear_to_srgb8(linear.data(), codes, linear.size());
        };
    ImageFileWrite& header = encoded.header;
    header.width = width;
    header.height = height;
    header.channel_names = names;
    header.alpha_channel = has_alpha ? 3 : -1;
    header.file_type = encoding == Encoding::Srgb8    ? SampleType::UInt8
                       : encoding == Encoding::Srgb16 ? SampleType::UInt16
                                                      : SampleType::Float;
    // Straight alpha as computed here: OpenImageIO must not divide it again.
    if (straight && !png) header.integer_attributes.emplace_back("oiio:UnassociatedAlpha", 1);
    if (jpeg) {
        const int quality = std::clamp(options.jpeg_quality, 1, 100);
        header.text_attributes.emplace_back("Compression", "jpeg:" + std::to_string(quality));
        header.integer_attributes.emplace_back("CompressionQuality", quality);
        // Halving the colour's resolution costs more than the quality
        // asked for at 90 and above (a red edge bleeds a pixel).
        if (quality >= 90) header.text_attributes.emplace_back("jpeg:subsampling", "4:4:4");
    }
    if (!png)
        header.text_attributes.emplace_back("oiio:ColorSpace", encoding == Encoding::LinearFloat ? "Linear" : "sRGB");
    header.text_attributes.emplace_back("Software", "lancer");
    for (const auto& [key, value] : options.metadata) header.text_attributes.emplace_back("lancer:" + key, value);
    encoded.row = std::move(row);
    return encoded;
}

}  // namespace

void write_image(const Film& film, const std::string& path, const ImageWriteOptions& options) {
    const EncodedImage encoded = encode_for(film, path, options);
    const fs::path target(path);
    std::error_code ignored;
    if (!target.parent_path().empty() && !fs::is_directory(target.parent_path(), ignored))
        throw std::runtime_error("cannot write '" + path + "': directory '" + target.parent_path().string() +
                                 "' does not exist");
    const fs::path temporary = temporary_path_for(target);
    try {
        if (encoded.png) {
            write_png_file(temporary.string(), encoded.png_pixels());
        } else {
            const std::vector<float> samples = encoded.whole();
            ImageFileWrite header = encoded.header;
            header.pixels = samples.data();
            image_codecs().write(temporary.string(), header);
        }
    } catch (const std::runtime_error& error) {
        fs::remove(temporary, ignored);
        throw std::runtime_error("cannot write '" + path + "': " + error.what());
    }
    std::error_code renamed;
    fs::rename(temporary, target, renamed);
    if (renamed) {
        fs::remove(temporary, ignored);
        throw std::runtime_error("cannot write '" + path + "': " + renamed.message());
    }
}

std::vector<unsigned char> encode_png(const Film& film, const ImageWriteOptions& options) {
    const EncodedImage encoded = encode_for(film, "memory.png", options);
    return encode_png_bytes(encoded.png_pixels());
}

}  // namespace lancer
