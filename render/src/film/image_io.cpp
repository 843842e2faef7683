// Writing films through OpenImageIO, atomically.
#include "lancer/host/image_io.h"
#include "lancer/host/temporary_file.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <filesystem>
#include <stdexcept>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "film/file_extension.h"

namespace lancer {
namespace {

namespace fs = std::filesystem;

enum class Encoding { Srgb8, Srgb16, LinearFloat };

// A unique temporary name beside the target, keeping its extension so
// OpenImageIO picks the same format.
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

bool image_format_has_alpha(const std::string& path) {
    const std::string ext = lower_extension(path);
    return ext == ".png" || ext == ".exr" || ext == ".tif" || ext == ".tiff";
}

bool image_format_has_layers(const std::string& path) {
    return lower_extension(path) == ".exr";
}

namespace {

// The pixels and header a file of `path`'s format receives. Throws as
// write_image does.
struct EncodedImage {
    OIIO::ImageSpec spec;
    std::vector<float> pixels;
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

    // Pixels in float, encoded as the format wants; OIIO quantises
    // (rounding to nearest) when the file is 8 or 16 bit. The film is
    // premultiplied: integer formats get the colour divided by alpha.
    const bool raw = encoding == Encoding::LinearFloat || !options.gamma_correction;
    const bool straight = has_alpha && encoding != Encoding::LinearFloat;
    std::vector<float> pixels(pixel_count * std::size_t(channels));
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            const std::size_t index = std::size_t(y) * width + x;
            const float alpha = has_alpha ? glm::clamp(options.alpha[index], 0.0f, 1.0f) : 1.0f;
            Color c = film.mean(x, y);
            if (has_alpha) c = alpha > 0.0f ? c / alpha : Color(0.0f);
            if (options.gamma_correction && options.working_gamma != 1.0)
                for (int k = 0; k < 3; ++k) c[k] = float(std::pow(std::max(double(c[k]), 0.0), options.working_gamma));
            if (has_alpha && !straight) c *= alpha;
            float* out = &pixels[index * channels];
            int channel = 0;
            for (int k = 0; k < 3; ++k) out[channel++] = raw ? c[k] : linear_to_srgb(c[k]);
            if (has_alpha) out[channel++] = alpha;
            for (const ImageLayer& layer : options.layers)
                for (std::size_t k = 0; k < layer.channels.size(); ++k)
                    out[channel++] = layer.values[index * layer.channels.size() + k];
            if (sample_channel) out[channel++] = float(film.sample_count(x, y));
        }

    OIIO::TypeDesc format = encoding == Encoding::Srgb8    ? OIIO::TypeDesc::UINT8
                            : encoding == Encoding::Srgb16 ? OIIO::TypeDesc::UINT16
                                                           : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(width, height, channels, format);
    spec.channelnames = names;
    spec.alpha_channel = has_alpha ? 3 : -1;
    // Straight alpha as computed here: OIIO must not divide it again.
    if (straight) spec.attribute("oiio:UnassociatedAlpha", 1);
    if (jpeg) {
        const int quality = std::clamp(options.jpeg_quality, 1, 100);
        spec.attribute("Compression", "jpeg:" + std::to_string(quality));
        spec.attribute("CompressionQuality", quality);
        // Halving the colour's resolution costs more than the quality
        // asked for at 90 and above (a red edge bleeds a pixel).
        if (quality >= 90) spec.attribute("jpeg:subsampling", "4:4:4");
    }
    spec.attribute("oiio:ColorSpace", encoding == Encoding::LinearFloat ? "Linear" : "sRGB");
    spec.attribute("Software", "lancer");
    for (const auto& [key, value] : options.metadata) spec.attribute("lancer:" + key, value);
    return {std::move(spec), std::move(pixels)};
}

}  // namespace

void write_image(const Film& film, const std::string& path, const ImageWriteOptions& options) {
    const auto [spec, pixels] = encode_for(film, path, options);
    const fs::path target(path);
    std::error_code ignored;
    if (!target.parent_path().empty() && !fs::is_directory(target.parent_path(), ignored))
        throw std::runtime_error("cannot write '" + path + "': directory '" + target.parent_path().string() +
                                 "' does not exist");
    const fs::path temporary = temporary_path_for(target);
    auto fail = [&](const std::string& why) {
        fs::remove(temporary, ignored);
        throw std::runtime_error("cannot write '" + path + "': " + why);
    };
    {
        auto output = OIIO::ImageOutput::create(temporary.string());
        if (!output) fail(OIIO::geterror());
        if (!output->open(temporary.string(), spec)) fail(output->geterror());
        if (!output->write_image(OIIO::TypeDesc::FLOAT, pixels.data())) {
            const std::string why = output->geterror();
            output->close();
            fail(why);
        }
        if (!output->close()) fail(output->geterror());
    }
    std::error_code renamed;
    fs::rename(temporary, target, renamed);
    if (renamed) fail(renamed.message());
}

std::vector<unsigned char> encode_png(const Film& film, const ImageWriteOptions& options) {
    const auto [spec, pixels] = encode_for(film, "memory.png", options);
    std::vector<unsigned char> bytes;
    OIIO::Filesystem::IOVecOutput memory(bytes);
    OIIO::ImageSpec with_proxy = spec;
    OIIO::Filesystem::IOProxy* proxy = &memory;
    with_proxy.attribute("oiio:ioproxy", OIIO::TypeDesc::PTR, &proxy);
    auto output = OIIO::ImageOutput::create("memory.png");
    if (!output || !output->open("memory.png", with_proxy) ||
        !output->write_image(OIIO::TypeDesc::FLOAT, pixels.data()) || !output->close())
        throw std::runtime_error("cannot encode a PNG in memory: " + (output ? output->geterror() : OIIO::geterror()));
    return bytes;
}

}  // namespace lancer
