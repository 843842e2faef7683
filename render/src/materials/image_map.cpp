// POV-Ray's image_map through OpenImageIO's TextureSystem, with POV's
// map_type projections.
#include <cmath>
#include <string>

#include <OpenImageIO/texture.h>

#include "lancer/scene_error.h"
#include "materials/pattern_space.h"

namespace lancer {
namespace {

constexpr double kTwoPi = 6.283185307179586476925;

float srgb_decode(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

}  // namespace

Vec2 planar_map(const glm::dvec3& p) {
    return {float(p.x), float(p.y)};
}

Vec2 spherical_map(const glm::dvec3& p) {
    // POV's spherical map: u is the angle from +x in the x-z plane, v the
    // latitude from the south pole (0) to the north pole (1).
    const double horizontal = std::sqrt(p.x * p.x + p.z * p.z);
    double u = 0.0;
    if (horizontal > 0.0) {
        u = std::atan2(p.z, p.x) / kTwoPi;
        if (u < 0.0) u += 1.0;
    }
    const double v = 0.5 + std::atan2(p.y, horizontal) / kPiD;
    return {float(u), float(v)};
}

Vec2 cylindrical_map(const glm::dvec3& p) {
    const Vec2 around = spherical_map(glm::dvec3(p.x, 0.0, p.z));
    return {around.x, float(p.y)};
}

// Holds the TextureSystem for the life of every image texture using it.
class ImageTextureSystem {
  public:
    ImageTextureSystem() : m_system(OIIO::TextureSystem::create(false)) {
        m_system->attribute("automip", 1);
        m_system->attribute("max_memory_MB", 512.0f);
    }
    ~ImageTextureSystem() { OIIO::TextureSystem::destroy(m_system); }
    OIIO::TextureSystem& get() const { return *m_system; }

  private:
    OIIO::TextureSystem* m_system;
};

namespace {

class ImageTexture final : public Texture {
  public:
    ImageTexture(const sg::Pigment& pigment, const TextureSpaces& spaces, std::shared_ptr<ImageTextureSystem> images)
        : m_images(std::move(images)),
          m_map(pigment.image),
          m_filename(pigment.image.path),
          m_pattern_from_object(pigment.pattern_from_object),
          m_spaces(spaces) {
        OIIO::TextureSystem& system = m_images->get();
        OIIO::ImageSpec spec;
        if (m_map.path.empty() || !system.get_imagespec(m_filename, 0, spec)) {
            std::string why = system.geterror();
            throw SceneError(m_map.location,
                             "cannot read image '" + m_map.path + "'" + (why.empty() ? std::string() : ": " + why));
        }
        m_channels = glm::clamp(spec.nchannels, 1, 4);
        // 8- and 16-bit files are display-encoded; float files are linear.
        m_decode_srgb = m_map.srgb && !spec.format.is_floating_point();
        m_options.swrap = m_map.once ? OIIO::TextureOpt::WrapBlack : OIIO::TextureOpt::WrapPeriodic;
        m_options.twrap = m_options.swrap;
        m_options.interpmode =
            m_map.interpolate == 0 ? OIIO::TextureOpt::InterpClosest : OIIO::TextureOpt::InterpBilinear;
        m_options.mipmode = OIIO::TextureOpt::MipModeNoMIP;
        float mean[4] = {0, 0, 0, 1};
        if (system.get_texture_info(m_filename, 0, OIIO::ustring("averagecolor"),
                                    OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, m_channels), mean))
            m_average = finish(mean);
        else
            m_average = finish(mean);
    }

    TextureSample evaluate(const Hit& hit) const override {
        Vec2 uv = hit.uv;
        const glm::dvec3 p = pattern_point(hit, m_spaces, m_pattern_from_object);
        switch (m_map.map_type) {
        case sg::MapType::Planar: uv = planar_map(p); break;
        case sg::MapType::Spherical: uv = spherical_map(p); break;
        case sg::MapType::Cylindrical: uv = cylindrical_map(p); break;
        default: {
            // (u,v) mapping; pigment transforms act on the (u, v, 0) point.
            const glm::dvec4 q = m_pattern_from_object * glm::dvec4(uv.x, uv.y, 0.0, 1.0);
            uv = Vec2(float(q.x), float(q.y));
        }
        }
        if (m_map.once && (uv.x < 0.0f || uv.x > 1.0f || uv.y < 0.0f || uv.y > 1.0f)) return {Color(0.0f), 0.0f, 1.0f};
        float texel[4] = {0, 0, 0, 1};
        OIIO::TextureOpt options = m_options;
        // OIIO's t runs down the image; lancer's v runs up.
        m_images->get().texture(m_filename, options, uv.x, 1.0f - uv.y, 0.0f, 0.0f, 0.0f, 0.0f, m_channels, texel);
        return finish(texel);
    }
    TextureSample average() const override { return m_average; }

  private:
    TextureSample finish(const float* texel) const {
        TextureSample out;
        if (m_channels < 3) {
            out.rgb = Color(texel[0]);
        } else {
            out.rgb = Color(texel[0], texel[1], texel[2]);
        }
        if (m_decode_srgb) out.rgb = Color(srgb_decode(out.rgb.r), srgb_decode(out.rgb.g), srgb_decode(out.rgb.b));
        const float alpha = (m_channels == 4 || m_channels == 2) ? texel[m_channels - 1] : 1.0f;
        out.filter = float(m_map.filter_all);
        out.transmit = glm::clamp(float(m_map.transmit_all) + (1.0f - alpha), 0.0f, 1.0f);
        return out;
    }

    std::shared_ptr<ImageTextureSystem> m_images;
    sg::ImageMap m_map;
    OIIO::ustring m_filename;
    glm::dmat4 m_pattern_from_object;
    const TextureSpaces& m_spaces;
    int m_channels = 3;
    bool m_decode_srgb = true;
    OIIO::TextureOpt m_options;
    TextureSample m_average;
};

}  // namespace

std::unique_ptr<Texture> make_image_texture(const sg::Pigment& pigment, const TextureSpaces& spaces,
                                            std::shared_ptr<ImageTextureSystem>& images) {
    if (!images) images = std::make_shared<ImageTextureSystem>();
    return std::make_unique<ImageTexture>(pigment, spaces, images);
}

}  // namespace lancer
