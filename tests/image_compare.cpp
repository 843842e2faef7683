#include "image_compare.h"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include <OpenImageIO/imageio.h>

namespace lancer::testing {

Image load_image(const std::string& path) {
    auto input = OIIO::ImageInput::open(path);
    if (!input) throw std::runtime_error("cannot read image '" + path + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = input->spec();
    Image image;
    image.width = spec.width;
    image.height = spec.height;
    std::vector<float> all(std::size_t(spec.width) * spec.height * spec.nchannels);
    if (!input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, all.data()))
        throw std::runtime_error("cannot read image '" + path + "': " + input->geterror());
    image.rgb.resize(std::size_t(spec.width) * spec.height * 3);
    for (std::size_t p = 0; p < std::size_t(spec.width) * spec.height; ++p)
        for (int c = 0; c < 3; ++c) image.rgb[p * 3 + c] = all[p * spec.nchannels + std::min(c, spec.nchannels - 1)];
    return image;
}

void save_image(const Image& image, const std::string& path) {
    auto output = OIIO::ImageOutput::create(path);
    if (!output) throw std::runtime_error("cannot write image '" + path + "': " + OIIO::geterror());
    OIIO::ImageSpec spec(image.width, image.height, 3, OIIO::TypeDesc::UINT8);
    if (!output->open(path, spec) || !output->write_image(OIIO::TypeDesc::FLOAT, image.rgb.data()))
        throw std::runtime_error("cannot write image '" + path + "': " + output->geterror());
    output->close();
}

ImageDifference compare_images(const Image& render, const Image& golden, double pixel_threshold) {
    ImageDifference d;
    d.same_size = render.width == golden.width && render.height == golden.height;
    if (!d.same_size || render.rgb.empty()) return d;
    double sum = 0.0, sum_squares = 0.0;
    for (std::size_t p = 0; p < render.rgb.size() / 3; ++p) {
        double pixel_max = 0.0;
        for (int c = 0; c < 3; ++c) {
            const double diff = std::fabs(double(render.rgb[p * 3 + c]) - double(golden.rgb[p * 3 + c]));
            sum += diff;
            sum_squares += diff * diff;
            pixel_max = std::max(pixel_max, diff);
        }
        d.max_absolute = std::max(d.max_absolute, pixel_max);
        if (pixel_max > pixel_threshold) ++d.pixels_over_threshold;
    }
    const double n = double(render.rgb.size());
    d.mean_absolute = sum / n;
    d.rmse = std::sqrt(sum_squares / n);
    return d;
}

Image side_by_side(const Image& render, const Image& golden, float diff_gain) {
    Image out;
    out.width = render.width + golden.width + std::max(render.width, golden.width);
    out.height = std::max(render.height, golden.height);
    out.rgb.assign(std::size_t(out.width) * out.height * 3, 0.0f);
    auto put = [&](int x, int y, int c, float v) { out.rgb[(std::size_t(y) * out.width + x) * 3 + c] = v; };
    for (int y = 0; y < out.height; ++y)
        for (int c = 0; c < 3; ++c) {
            for (int x = 0; x < render.width && y < render.height; ++x) put(x, y, c, render.at(x, y, c));
            for (int x = 0; x < golden.width && y < golden.height; ++x) put(render.width + x, y, c, golden.at(x, y, c));
            for (int x = 0; x < std::min(render.width, golden.width); ++x)
                if (y < render.height && y < golden.height)
                    put(render.width + golden.width + x, y, c,
                        std::min(1.0f, diff_gain * std::fabs(render.at(x, y, c) - golden.at(x, y, c))));
        }
    return out;
}

bool images_match(const Image& render, const Image& golden, double max_mean_absolute, double pixel_threshold,
                  long max_pixels_over, const std::string& failure_stem, std::string* message) {
    const ImageDifference d = compare_images(render, golden, pixel_threshold);
    std::ostringstream why;
    bool ok = d.same_size && d.mean_absolute <= max_mean_absolute && d.pixels_over_threshold <= max_pixels_over;
    if (!d.same_size)
        why << "size " << render.width << "x" << render.height << " differs from the golden's " << golden.width << "x"
            << golden.height;
    else
        why << "mean |diff| " << d.mean_absolute << " (limit " << max_mean_absolute << "), max " << d.max_absolute
            << ", RMSE " << d.rmse << ", " << d.pixels_over_threshold << " pixels over " << pixel_threshold
            << " (limit " << max_pixels_over << ")";
    if (!ok) {
        const std::string path = failure_stem + ".png";
        try {
            save_image(side_by_side(render, golden), path);
            why << "; render | golden | diff written to " << path;
        } catch (const std::exception& e) {
            why << "; " << e.what();
        }
    }
    if (message) *message = why.str();
    return ok;
}

}  // namespace lancer::testing
