// POV-Ray's material_map: an image whose pixels pick textures. A pixel of
// a colour-mapped file picks by its palette index, any other by its red
// (0-255, as stored); block_in_list says how a number past the list's end
// picks, and a point a `once` image does not reach takes the first texture. The scene graph
// holds it as an image pattern with a list of block textures.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lancer/scene_error.h"
#include "materials/image_sampler.h"
#include "materials/palette_image.h"
#include "materials/point_pigment.h"

namespace lancer {

CompiledPattern::BlockSource material_map_source(const sg::Pattern& pattern, const MaterialBuild& build) {
    if (!pattern.image) throw SceneError(pattern.location, "material_map needs an image");
    auto image = std::make_shared<const ImageSampler>(open_image(*pattern.image, build));
    std::shared_ptr<const PaletteImage> palette;
    try {
        if (std::optional<PaletteImage> indexed = read_palette_image(pattern.image->path))
            palette = std::make_shared<const PaletteImage>(std::move(*indexed));
    } catch (const std::exception& e) {
        throw SceneError(pattern.image->location, e.what());
    }
    return {[image, palette](const glm::dvec3& point, const PatternContext&) -> double {
        const std::optional<glm::dvec2> uv = image->project(point);
        if (!uv) return 0.0;
        if (palette) {
            const double u = uv->x - std::floor(uv->x);
            const double v = uv->y - std::floor(uv->y);
            const int x = std::clamp(int(u * palette->width), 0, palette->width - 1);
            const int y = std::clamp(int((1.0 - v) * palette->height), 0, palette->height - 1);
            return palette->indices[std::size_t(y) * std::size_t(palette->width) + std::size_t(x)];
        }
        return std::round(double(image->at(*uv).rgb.r) * 255.0);
    }};
}

CompiledPattern compile_block_pattern(const sg::Pattern& pattern, const MaterialBuild& build) {
    // Only material_map lists blocks after an image pattern.
    if (pattern.kind == sg::Pattern::Kind::ImagePattern)
        return CompiledPattern(pattern, build.generator, material_map_source(pattern, build));
    return compile_pattern(pattern, build);
}

// POV-Ray 3.7 reduces a number above the count modulo it, then walks its
// list that many steps but not past the end: with 5 textures, 5 picks the
// last and 6 the second (measured: Debian's povray agrees).
int block_in_list(int index, std::size_t count) {
    const int n = static_cast<int>(count);
    if (n <= 0 || index <= 0) return 0;
    if (index > n) index %= n;
    return std::min(index, n - 1);
}

}  // namespace lancer
