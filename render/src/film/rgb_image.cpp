// RgbImage files: read through the image module, written as PNG by libpng
// or as EXR through the module.
#include "lancer/host/rgb_image.h"
#include "lancer/host/temporary_file.h"

#include <filesystem>
#include <stdexcept>

#include "film/file_extension.h"
#include "film/image_codecs.h"
#include "film/png_encoder.h"
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
    std::vector<float> values;
    ImageFileInfo info;
    try {
        std::unique_ptr<ImageFileReader> input = image_codecs().open(path, false);
        info = input->info();
        if (info.channels < 3) throw std::runtime_error("fewer than 3 channels");
        values.resize(std::size_t(info.width) * info.height * info.channels);
        input->read_rows(0, info.height, SampleType::Float, values.data());
    } catch (const std::runtime_error& error) {
        throw std::runtime_error("cannot read image '" + path + "': " + error.what());
    }
    const bool decode = is_srgb_encoded(lower_extension(path));
    RgbImage image(info.width, info.height);
    for (std::size_t i = 0; i < image.pixels.size(); ++i) {
        const float* p = &values[i * info.channels];
        image.pixels[i] =
            decode ? Color(srgb_to_linear(p[0]), srgb_to_linear(p[1]), srgb_to_linear(p[2])) : Color(p[0], p[1], p[2]);
    }
    return image;
}

void write_rgb_image(const RgbImage& image, const std::string& path) {
    const std::string ext = lower_extension(path);
    if (ext != ".png" && ext != ".exr")
        throw std::runtime_error("cannot write '" + path + "': write_rgb_image supports .png and .exr");
    const bool png = ext == ".png";
    std::vector<float> values(image.pixels.size() * 3);
    for (std::size_t i = 0; i < image.pixels.size(); ++i)
        for (int k = 0; k < 3; ++k) values[i * 3 + k] = png ? linear_to_srgb(image.pixels[i][k]) : image.pixels[i][k];

    // A temporary name beside the target: a failure leaves no partial file
    // under the name.
    const fs::path target(path);
    const fs::path temporary = temporary_path_for(target);
    try {
        if (png) {
            PngPixels pixels;
            pixels.width = image.width;
            pixels.height = image.height;
            pixels.samples = values.data();
            write_png_file(temporary.string(), pixels);
        } else {
            ImageFileWrite exr;
            exr.width = image.width;
            exr.height = image.height;
            exr.channel_names = {"R", "G", "B"};
            exr.pixels = values.data();
            image_codecs().write(temporary.string(), exr);
        }
    } catch (const std::runtime_error& error) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw std::runtime_error("cannot write '" + path + "': " + error.what());
    }
    std::error_code error;
    fs::rename(temporary, target, error);
    if (error) throw std::runtime_error("cannot write '" + path + "': " + error.message());
}

}  // namespace lancer
