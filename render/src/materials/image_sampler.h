// An image file as POV-Ray's image_map, bump_map and image_pattern read
// it: map_type's projection of a pattern-space point onto the image, and
// the texel there, interpolated as the map asks (internal to liblancer).
#pragma once

#include <memory>
#include <optional>

#include <glm/glm.hpp>

#include "lancer/ray.h"
#include "lancer/scene_graph.h"
#include "materials/image_texels.h"
#include "materials/textures.h"

namespace lancer {

struct Texel {
    Color rgb{0.0f};
    float alpha = 1.0f;
    // A colour-mapped image given `filter N, v` or `transmit N, v`: its
    // palette entries' filter and transmit, which stand in for the alpha
    // and for the map's `filter all` and `transmit all`.
    bool from_palette = false;
    float filter = 0.0f;
    float transmit = 0.0f;
};

struct PaletteTransparency;

class ImageSampler {
  public:
    // Throws lancer::SceneError at the map's location when the file cannot
    // be read, claims too many pixels, or holds NaN texels, and at a
    // palette setting's when the file has no palette or no such entry.
    ImageSampler(const sg::ImageMap& map, ImageCache& images);

    // Where map_type puts a point of the image's space, as (u, v) with v
    // up and one image per unit square; empty where a `once` image does
    // not reach. MapType::UV takes the point's x and y (the point is then
    // the surface's (u, v, 0)).
    std::optional<glm::dvec2> project(const glm::dvec3& point) const;
    // The texel at (u, v), repeated beyond [0, 1)^2 unless `once` (then
    // transparent black), decoded to linear values unless the map says the
    // file holds linear data.
    Texel at(const glm::dvec2& uv) const;
    Texel average() const { return m_average; }

    // The map's last `filter all` and `transmit all` (0 without): what an
    // image without a palette adds to every texel.
    float filter_all() const { return m_filter_all; }
    float transmit_all() const { return m_transmit_all; }

    // Where (u, v) falls on an image columns x rows wide, in pixels from
    // its top left corner, as POV-Ray's map_pos puts it: nudged right and
    // up, so a point on a pixel's edge (the faces of a unit box, at u or
    // v = 0 and 1) takes the pixel POV-Ray takes. POV nudges by 1e-10 of a
    // pixel, working in double; lancer's hit points are floats, a few 1e-6
    // of a pixel off the face, so the nudge here is 1e-4 of a pixel.
    static glm::dvec2 pixel_position(const glm::dvec2& uv, int columns, int rows) {
        constexpr double kPovEpsilon = 1e-4;
        return {uv.x * columns + kPovEpsilon, (1.0 - uv.y) * rows - kPovEpsilon};
    }

    int width() const { return m_width; }
    int height() const { return m_height; }
    bool has_alpha() const { return m_channels == 2 || m_channels == 4; }

    // Texel (column, row) of an image columns x rows: clamped to the edges
    // of a `once` image, else repeated.
    glm::ivec2 wrap(long long column, long long row, int columns, int rows) const;

  private:
    // Shares of the texels at (0, 0), (1, 0), (0, 1) and (1, 1) from the
    // first, for a point (fx, fy) from it.
    struct CornerWeights {
        float a, b, c, d;
    };
    CornerWeights corner_weights(float fx, float fy) const;
    Texel decode(const float* texel) const;
    Texel texel(long long column, long long row) const;  // wrapped
    void add_palette_transparency(Texel& texel, const glm::dvec2& uv) const;

    std::shared_ptr<const ImageTexels> m_texels;
    sg::ImageMap m_map;
    int m_width = 1;
    int m_height = 1;
    int m_channels = 3;  // the first 4 of the file's at most
    bool m_decode_srgb = true;
    Texel m_average;
    float m_filter_all = 0.0f;
    float m_transmit_all = 0.0f;
    // Only for an image_map with palette settings on a colour-mapped file.
    std::shared_ptr<const PaletteTransparency> m_palette;
};

// A sampler sharing the build's image cache.
ImageSampler open_image(const sg::ImageMap& map, const MaterialBuild& build);

}  // namespace lancer
