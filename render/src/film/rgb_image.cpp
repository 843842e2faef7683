// RgbImage I/O through OpenImageIO.
#include "lancer/host/rgb_image.h"
#include "lancer/host/temporary_file.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <memory>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

#include "film/file_extension.h"

#include "lancer/host/image_io.h"

namespace lancer {
namespace {

namespace fs = std::filesystem;

// Formats that store display-encoded values rather than linear radiance.
bool is_srgb_encoded(const std::string& ext) {
    return ext == ".png" || ext == ".tif" || ext == ".tiff";
}

}  // namespace

RgbImage image_from_film(const Film& film) {
    RgbImage image(film.width(), film.height());
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) image.at(x, y) = film.mean(x, y);
    return image;
}

RgbImage read_rgb_image(const std::string& path) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) throw std::runtime_error("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    if (spec.nchannels < 3) throw std::runtime_error("cannot read image '" + path + "': fewer than 3 channels");
    std::vector<float> values(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, values.data()))
        throw std::runtime_error("cannot read image '" + path + "': " + input->geterror());
    const bool decode = is_srgb_encoded(lower_extension(path));
    RgbImage image(spec.width, spec.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const float* p = &values[i * spec.nchannels];
        image.pixels[i] =
            decode ? Color(srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2])) : Color(p[0], p[1], p[2]);
    }
    return image;
}

void write_rgb_image(const RgbImage& image, const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext != ".png" && ext != ".exr")
        throw std::runtime_error("cannot write '" + path + "': write_rgb_image supports .png and .exr");
    const bool encode = ext == ".png";
    std::vector<float> values(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k)
            values[i * 3 + k] = encode ? linear_to_srgb(image.pixels[i][k]) : image.pixels[i][k];

    // A temporary name beside the target keeps the extension (OIIO picks the
    // format from it) and a failure leaves no partial file under the name.
    const fs::path target(path);
    const fs::path temporary = temporary_path_for(target);
    OIIO::ImageSpec spec(image.width, image.height, 3, encode ? OIIO::TypeDesc::UINT8 : OIIO::TypeDesc::FLOAT);
    auto output = OIIO::ImageOutput::create(temporary.string());
    if (!output || !output->open(temporary.string(), spec))
        throw std::runtime_error("cannot write '" + path + "': " + OIIO::geterror());
    const bool ok = output->write_image(OIIO::TypeDesc::FLOAT, values.data()) && output->close();
    if (!ok) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw std::runtime_error("cannot write '" + path + "': " + output->geterror());
    }
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) throw std::runtime_error("cannot write '" + path + "': " + error.message());
}

}  // namespace lancer
