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
    return ext == ".png" || ext == ".exr" || ext == ".hdr" || ext == ".tif" || ext == ".tiff";
}

void write_image(const Film& film, const std::string& path, const ImageWriteOptions& options) {
    const std::string ext = lower_extension(path);
    if (!is_supported_image_extension(path))
        throw std::runtime_error("cannot write '" + path + "': unknown image extension '" + ext +
                                 "' (use .png, .exr, .hdr, .tif or .tiff)");
    const Encoding encoding = ext == ".png"                       ? Encoding::Srgb8
                              : (ext == ".tif" || ext == ".tiff") ? Encoding::Srgb16
                                                                  : Encoding::LinearFloat;
    const bool sample_channel = options.sample_count_channel && ext == ".exr";
    const int width = film.width(), height = film.height();
    const int channels = sample_channel ? 4 : 3;

    // Pixels in float, encoded as the format wants; OIIO quantises
    // (rounding to nearest) when the file is 8 or 16 bit.
    std::vector<float> pixels(std::size_t(width) * height * channels);
    for (int y = 0; y < height; ++y)
        for (int x = 0; x < width; ++x) {
            Color c = film.mean(x, y);
            if (options.gamma_correction && options.working_gamma != 1.0)
                for (int k = 0; k < 3; ++k) c[k] = float(std::pow(std::max(double(c[k]), 0.0), options.working_gamma));
            float* out = &pixels[(std::size_t(y) * width + x) * channels];
            const bool raw = encoding == Encoding::LinearFloat || !options.gamma_correction;
            for (int k = 0; k < 3; ++k) out[k] = raw ? c[k] : linear_to_srgb(c[k]);
            if (sample_channel) out[3] = float(film.sample_count(x, y));
        }

    OIIO::TypeDesc format = encoding == Encoding::Srgb8    ? OIIO::TypeDesc::UINT8
                            : encoding == Encoding::Srgb16 ? OIIO::TypeDesc::UINT16
                                                           : OIIO::TypeDesc::FLOAT;
    OIIO::ImageSpec spec(width, height, channels, format);
    spec.channelnames = {"R", "G", "B"};
    if (sample_channel) spec.channelnames.push_back("samples");
    spec.alpha_channel = -1;
    spec.attribute("oiio:ColorSpace", encoding == Encoding::LinearFloat ? "Linear" : "sRGB");
    spec.attribute("Software", "lancer");
    for (const auto& [key, value] : options.metadata) spec.attribute("lancer:" + key, value);

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

}  // namespace lancer
