// An image file as POV-Ray's image_map, bump_map and image_pattern read
// it: map_type's projection of a pattern-space point onto the image, and
// the texel there, interpolated as the map asks (internal to liblancer).
#pragma once

#include <memory>
#include <optional>

#include <OpenImageIO/texture.h>
#include <glm/glm.hpp>

#include "lancer/ray.h"
#include "lancer/scene_graph.h"
#include "materials/textures.h"

namespace lancer {

// Holds OpenImageIO's TextureSystem for the life of every image using it.
class ImageTextureSystem {
  public:
    ImageTextureSystem();
    ~ImageTextureSystem();
    ImageTextureSystem(const ImageTextureSystem&) = delete;
    ImageTextureSystem& operator=(const ImageTextureSystem&) = delete;
    OIIO::TextureSystem& get() const { return *m_system; }

  private:
    OIIO::TextureSystem* m_system;
};

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
    ImageSampler(const sg::ImageMap& map, std::shared_ptr<ImageTextureSystem>& images);

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

    int width() const { return m_width; }
    int height() const { return m_height; }
    bool has_alpha() const { return m_channels == 2 || m_channels == 4; }

  private:
    Texel decode(const float* texel) const;
    Texel lookup(double s, double t) const;   // OpenImageIO's (s, t), t down
    Texel blended(double s, double t) const;  // four texels decoded, then blended
    void add_palette_transparency(Texel& texel, double s, double t) const;

    std::shared_ptr<ImageTextureSystem> m_images;
    sg::ImageMap m_map;
    OIIO::ustring m_filename;
    OIIO::TextureOpt m_options;
    int m_width = 1;
    int m_height = 1;
    int m_channels = 3;
    bool m_decode_srgb = true;
    bool m_blend_decoded = false;  // interpolated here, after decoding
    Texel m_average;
    float m_filter_all = 0.0f;
    float m_transmit_all = 0.0f;
    // Only for an image_map with palette settings on a colour-mapped file.
    std::shared_ptr<const PaletteTransparency> m_palette;
};

// A sampler sharing the build's image cache.
ImageSampler open_image(const sg::ImageMap& map, const MaterialBuild& build);

}  // namespace lancer
