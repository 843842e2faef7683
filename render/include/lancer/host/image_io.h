// Writing the film, format chosen by file extension:
// .png (sRGB, 8 or 16-bit, clamped), .jpg/.jpeg (sRGB, 8-bit, a quality),
// .exr (linear float RGB, optional alpha and extra layers), .hdr (linear),
// .tif/.tiff (sRGB 16-bit). Alpha is straight in PNG and TIFF and
// premultiplied in EXR, as POV-Ray writes them (the film's colour is
// premultiplied: a transparent background adds none). Written atomically:
// a temporary file beside the target, then rename, so a failure never
// leaves a partial image.
#pragma once

#include <map>
#include <string>
#include <vector>

#include "lancer/host/film.h"

namespace lancer {

// One layer as it goes into a file: channel names and interleaved float
// values, row-major, width x height x channels.size().
struct ImageLayer {
    std::vector<std::string> channels;
    std::vector<float> values;
};

struct ImageWriteOptions {
    // Metadata stored in the file (integrator, samples, seconds ...).
    std::map<std::string, std::string> metadata;
    bool sample_count_channel = false;  // EXR only: per-pixel sample count
    // POV-Ray's assumed_gamma: the film holds values of a working space of
    // this gamma, which the file receives decoded to linear (v^gamma) and
    // then encoded as its format wants. 1: the film is linear.
    double working_gamma = 1.0;
    // False: POV-Ray's legacy mode (lancer/scene_graph.h, GlobalSettings):
    // every format receives the film's values unchanged, with no transfer
    // curve (8 and 16 bit files then hold round(v * 255), as POV-Ray 3.6).
    bool gamma_correction = true;
    // Per pixel, row-major, the film's size: the alpha channel (empty:
    // none). PNG, TIFF and EXR only.
    std::vector<float> alpha;
    // Channels after the beauty (lancer/host/aov.h). EXR only.
    std::vector<ImageLayer> layers;
    int png_bits = 8;       // 8 or 16
    int jpeg_quality = 90;  // 1 (smallest) to 100 (best)
};

// Throws std::runtime_error naming the path on failure (unknown extension,
// unwritable directory).
void write_image(const Film& film, const std::string& path, const ImageWriteOptions& options = {});

// The PNG write_image would write, in memory (for a preview page).
std::vector<unsigned char> encode_png(const Film& film, const ImageWriteOptions& options = {});

// Loads what writing `path`'s format needs ahead of time: formats other
// than PNG are written by the image module, which takes a fraction of a
// second to load. Throws std::runtime_error when it cannot be loaded.
void prepare_image_writer(const std::string& path);

// True if the extension names a format write_image supports.
bool is_supported_image_extension(const std::string& path);
// Whether the format can hold an alpha channel; extra layers.
bool image_format_has_alpha(const std::string& path);
bool image_format_has_layers(const std::string& path);

// sRGB transfer function on one linear value in [0, 1].
float linear_to_srgb(float linear);
float srgb_to_linear(float encoded);

}  // namespace lancer
