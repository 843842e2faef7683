// Comparing rendered images with goldens: load through OpenImageIO, measure
// per-pixel and mean absolute differences and RMSE, and on failure write the
// render, the golden and their difference side by side for inspection.
#pragma once

#include <string>
#include <vector>

namespace lancer::testing {

// A float RGB image (values as stored: linear for EXR/HDR, encoded for PNG).
struct Image {
    int width = 0;
    int height = 0;
    std::vector<float> rgb;  // row-major, 3 floats per pixel
    float at(int x, int y, int c) const { return rgb[(std::size_t(y) * width + x) * 3 + c]; }
};

// Throws std::runtime_error naming the file when it cannot be read.
Image load_image(const std::string& path);
void save_image(const Image& image, const std::string& path);

struct ImageDifference {
    bool same_size = false;
    double mean_absolute = 0.0;  // over all channels
    double max_absolute = 0.0;   // largest per-channel difference
    double rmse = 0.0;
    // Pixels whose largest channel difference exceeds the threshold given.
    long pixels_over_threshold = 0;
};

ImageDifference compare_images(const Image& render, const Image& golden, double pixel_threshold);

// render | golden | |difference| scaled by `diff_gain`, in one image.
Image side_by_side(const Image& render, const Image& golden, float diff_gain = 4.0f);

// Convenience for golden tests: compares and, when the difference exceeds
// the tolerances, writes `<failure_stem>.png` with the side-by-side view and
// returns false with a message.
bool images_match(const Image& render, const Image& golden, double max_mean_absolute, double pixel_threshold,
                  long max_pixels_over, const std::string& failure_stem, std::string* message);

}  // namespace lancer::testing
