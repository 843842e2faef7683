// POV-Ray's image_map through OpenImageIO's TextureSystem, with POV's
// map_type projections.
#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <OpenImageIO/texture.h>

#include "lancer/scene_error.h"
#include "materials/pattern.h"
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

// OpenImageIO's messages span lines; one diagnostic is one line.
std::string one_line(std::string text) {
    while (!text.empty() && text.back() == '\n') text.pop_back();
    for (std::size_t at = text.find('\n'); at != std::string::npos; at = text.find('\n', at)) text.replace(at, 1, "; ");
    return text;
}

// Textures larger than this many pixels are refused before any decoding:
// a file of a few hundred bytes can claim 100000 x 100000 in its header.
constexpr double kMaxTexturePixels = 16384.0 * 16384.0;

// Decodes the whole file once, a band of rows at a time (memory bounded by
// the band), so a truncated or corrupt image is an error naming it rather
// than a texture that reads black, and a float image holding NaN or
// infinite texels is refused before it reaches the film.
void verify_image_decodes(const std::string& path, const sg::ImageMap& map) {
    auto fail = [&](const std::string& why) {
        throw SceneError(map.location, "cannot read image '" + map.path + "': " + one_line(why));
    };
    auto input = OIIO::ImageInput::open(path);
    if (!input) fail(OIIO::geterror());
    const OIIO::ImageSpec spec = input->spec();
    const int channels = spec.nchannels;
    if (channels < 1 || spec.width < 1 || spec.height < 1) fail("it has no pixels");
    const bool floating = spec.format.is_floating_point();
    std::vector<float> values;
    auto check = [&](std::size_t count) {
        if (!floating) return;
        for (std::size_t i = 0; i < count; ++i)
            if (!std::isfinite(values[i])) fail("it holds texels that are NaN or infinite");
    };
    if (spec.tile_width > 0) {
        values.resize(std::size_t(spec.width) * spec.height * std::max(spec.depth, 1) * channels);
        if (!input->read_image(0, 0, 0, channels, OIIO::TypeDesc::FLOAT, values.data())) fail(input->geterror());
        check(values.size());
        return;
    }
    constexpr int kBandRows = 64;
    values.resize(std::size_t(spec.width) * kBandRows * channels);
    for (int y = spec.y; y < spec.y + spec.height; y += kBandRows) {
        const int end = std::min(y + kBandRows, spec.y + spec.height);
        if (!input->read_scanlines(0, 0, y, end, 0, 0, channels, OIIO::TypeDesc::FLOAT, values.data()))
            fail(input->geterror());
        check(std::size_t(spec.width) * (end - y) * channels);
    }
}

class ImageTexture final : public Texture {
  public:
    ImageTexture(const sg::Pigment& pigment, const TextureSpaces& spaces, std::shared_ptr<ImageTextureSystem> images)
        : m_images(std::move(images)),
          m_map(pigment.image),
          m_filename(pigment.image.path),
          m_pattern_from_object(pigment.pattern_from_object),
          m_warps(pigment.pattern.warps.empty() && pigment.pattern.turbulence == sg::Vec3(0.0)
                      ? std::nullopt
                      : std::optional<CompiledPattern>(std::in_place, pigment.pattern, NoiseGenerator::RangeCorrected)),
          m_spaces(spaces) {
        OIIO::TextureSystem& system = m_images->get();
        OIIO::ImageSpec spec;
        if (m_map.path.empty() || !system.get_imagespec(m_filename, 0, spec)) {
            std::string why = system.geterror();
            throw SceneError(m_map.location, "cannot read image '" + m_map.path + "'" +
                                                 (why.empty() ? std::string() : ": " + one_line(why)));
        }
        if (double(spec.width) * double(spec.height) * double(std::max(spec.depth, 1)) > kMaxTexturePixels)
            throw SceneError(m_map.location, "image '" + m_map.path + "' claims " + std::to_string(spec.width) + " x " +
                                                 std::to_string(spec.height) +
                                                 " pixels: more than lancer's limit of 16384 x 16384");
        verify_image_decodes(m_filename.string(), m_map);
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
        // POV warps the point (turbulence, warp { }) before projecting it.
        const glm::dvec3 p = m_warps ? m_warps->pattern_point(pattern_point(hit, m_spaces, glm::dmat4(1.0)))
                                     : pattern_point(hit, m_spaces, m_pattern_from_object);
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
    // The pigment's transforms, warps and turbulence, when it has warps or
    // turbulence (the projections only: POV does not warp (u,v)).
    std::optional<CompiledPattern> m_warps;
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
