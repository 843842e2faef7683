// POV-Ray's map_type projections (imageutil.cpp in POV-Ray 3.7, read for
// its rules) and texel lookups through OpenImageIO's TextureSystem.
#include "materials/image_sampler.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>

#include "lancer/scene_error.h"
#include "materials/palette_image.h"

namespace lancer {

ImageTextureSystem::ImageTextureSystem() : m_system(OIIO::TextureSystem::create(false)) {
    m_system->attribute("automip", 1);
    m_system->attribute("max_memory_MB", 512.0f);
}

ImageTextureSystem::~ImageTextureSystem() {
    OIIO::TextureSystem::destroy(m_system);
}

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

float srgb_decode(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
}

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

// The angle of (x, z) from +x towards +z, as a share of a turn in [0, 1).
double turn_in_xz(double x, double z) {
    const double turn = std::atan2(z, x) / kTwoPi;
    return turn < 0.0 ? turn + 1.0 : turn;
}

}  // namespace

// Each pixel's palette entry, and each entry's filter and transmit.
struct PaletteTransparency {
    int width = 1;
    int height = 1;
    std::vector<unsigned char> indices;  // row 0 at the top
    float filter[256] = {};
    float transmit[256] = {};
};

namespace {

// POV-Ray sets `filter N, v` and `transmit N, v` (and, on a palette file,
// `filter all`, `transmit all`) on the palette's entries in the order
// written, starting from transmit = 1 - the entry's alpha.
std::shared_ptr<const PaletteTransparency> read_palette_transparency(const sg::ImageMap& map) {
    std::optional<PaletteImage> image;
    try {
        image = read_palette_image(map.path);
    } catch (const std::runtime_error& error) {
        throw SceneError(map.location, "cannot read image '" + map.path + "': " + one_line(error.what()));
    }
    auto keyword = [](const sg::PaletteSetting& setting) { return setting.transmit ? "transmit " : "filter "; };
    if (!image) {
        for (const sg::PaletteSetting& setting : map.palette_settings)
            if (setting.index >= 0)
                throw SceneError(setting.location,
                                 keyword(setting) + std::to_string(setting.index) +
                                     ", v changes an entry of a colour-mapped image's palette, and '" + map.path +
                                     "' has no palette (filter all and transmit all apply to any image)");
        return nullptr;
    }
    auto palette = std::make_shared<PaletteTransparency>();
    palette->width = image->width;
    palette->height = image->height;
    const int entries = int(image->alpha_by_index.size());
    palette->indices = std::move(image->indices);
    for (unsigned char& index : palette->indices) index = (unsigned char)std::min(int(index), entries - 1);
    for (int i = 0; i < entries; ++i) palette->transmit[i] = 1.0f - image->alpha_by_index[std::size_t(i)];
    for (const sg::PaletteSetting& setting : map.palette_settings) {
        if (setting.index >= entries)
            throw SceneError(setting.location, keyword(setting) + std::to_string(setting.index) + ", v: '" + map.path +
                                                   "' has " + std::to_string(entries) + " palette entries (0 to " +
                                                   std::to_string(entries - 1) + ")");
        float* values = setting.transmit ? palette->transmit : palette->filter;
        const int first = setting.index < 0 ? 0 : setting.index;
        const int last = setting.index < 0 ? entries - 1 : setting.index;
        for (int i = first; i <= last; ++i) values[i] = float(setting.value);
    }
    return palette;
}

}  // namespace

ImageSampler::ImageSampler(const sg::ImageMap& map, std::shared_ptr<ImageTextureSystem>& images)
    : m_map(map), m_filename(map.path) {
    if (!images) images = std::make_shared<ImageTextureSystem>();
    m_images = images;
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
    m_width = std::max(spec.width, 1);
    m_height = std::max(spec.height, 1);
    m_channels = std::clamp(spec.nchannels, 1, 4);
    // 8- and 16-bit files are display-encoded; float files are linear.
    m_decode_srgb = m_map.srgb && !spec.format.is_floating_point();
    // A `once` image is not repeated: POV takes the edge pixels for the
    // samples an interpolation needs beyond it.
    m_options.swrap = m_map.once ? OIIO::TextureOpt::WrapClamp : OIIO::TextureOpt::WrapPeriodic;
    m_options.twrap = m_options.swrap;
    m_options.interpmode = m_map.interpolate == 0 ? OIIO::TextureOpt::InterpClosest : OIIO::TextureOpt::InterpBilinear;
    if (m_map.interpolate != 0 && m_decode_srgb) {
        m_blend_decoded = true;
        m_options.interpmode = OIIO::TextureOpt::InterpClosest;
    }
    m_options.mipmode = OIIO::TextureOpt::MipModeNoMIP;
    float mean[4] = {0, 0, 0, 1};
    system.get_texture_info(m_filename, 0, OIIO::ustring("averagecolor"),
                            OIIO::TypeDesc(OIIO::TypeDesc::FLOAT, m_channels), mean);
    m_average = decode(mean);
    for (const sg::PaletteSetting& setting : m_map.palette_settings)
        if (setting.index < 0) (setting.transmit ? m_transmit_all : m_filter_all) = float(setting.value);
    if (!m_map.palette_settings.empty()) m_palette = read_palette_transparency(m_map);
    if (m_palette) {
        double filter = 0.0, transmit = 0.0;
        for (const unsigned char index : m_palette->indices) {
            filter += m_palette->filter[index];
            transmit += m_palette->transmit[index];
        }
        const double count = double(std::max<std::size_t>(m_palette->indices.size(), 1));
        m_average.from_palette = true;
        m_average.filter = float(filter / count);
        m_average.transmit = float(transmit / count);
    }
}

std::optional<glm::dvec2> ImageSampler::project(const glm::dvec3& p) const {
    glm::dvec2 uv(p.x, p.y);
    switch (m_map.map_type) {
    case sg::MapType::Planar:
    case sg::MapType::UV:
        if (m_map.once && (p.x < 0.0 || p.x > 1.0 || p.y < 0.0 || p.y > 1.0)) return std::nullopt;
        break;
    case sg::MapType::Spherical: {
        const double length = glm::length(p);
        if (length == 0.0) return std::nullopt;
        uv = {turn_in_xz(p.x, p.z), 0.5 + std::asin(std::clamp(p.y / length, -1.0, 1.0)) / kPiD};
        break;
    }
    case sg::MapType::Cylindrical:
        if (m_map.once && (p.y < 0.0 || p.y > 1.0)) return std::nullopt;
        if (p.x == 0.0 && p.z == 0.0) return std::nullopt;
        uv = {turn_in_xz(p.x, p.z), p.y};
        break;
    case sg::MapType::Torus: {
        // A torus of major radius 1 about y: u around the y axis, v around
        // the tube, starting on its inside and turning over its bottom.
        const double around = std::sqrt(p.x * p.x + p.z * p.z);
        if (around == 0.0) return std::nullopt;
        const double out = around - 1.0;
        const double tube = std::sqrt(out * out + p.y * p.y);
        double phi = tube > 0.0 ? std::acos(std::clamp(-out / tube, -1.0, 1.0)) : 0.0;
        if (p.y > 0.0) phi = kTwoPi - phi;
        uv = {turn_in_xz(p.x, p.z), phi / kTwoPi};
        break;
    }
    }
    return uv;
}

Texel ImageSampler::lookup(double s, double t) const {
    float texel[4] = {0, 0, 0, 1};
    OIIO::TextureOpt options = m_options;
    m_images->get().texture(m_filename, options, float(s), float(t), 0.0f, 0.0f, 0.0f, 0.0f, m_channels, texel);
    return decode(texel);
}

Texel ImageSampler::at(const glm::dvec2& uv) const {
    // OpenImageIO's t runs down the image; v runs up.
    const double s = uv.x, t = 1.0 - uv.y;
    Texel texel = m_blend_decoded ? blended(s, t) : lookup(s, t);
    if (m_palette) add_palette_transparency(texel, s, t);
    return texel;
}

// The entries' filter and transmit, at the texels the colour came from
// and blended with the same weights.
void ImageSampler::add_palette_transparency(Texel& texel, double s, double t) const {
    const PaletteTransparency& palette = *m_palette;
    auto entry = [&](double x, double y) {
        // A `once` image takes its edge texels beyond it; others repeat.
        const int columns = palette.width, rows = palette.height;
        long long column = (long long)std::floor(x), row = (long long)std::floor(y);
        if (m_map.once) {
            column = std::clamp<long long>(column, 0, columns - 1);
            row = std::clamp<long long>(row, 0, rows - 1);
        } else {
            column = ((column % columns) + columns) % columns;
            row = ((row % rows) + rows) % rows;
        }
        return palette.indices[std::size_t(row) * std::size_t(columns) + std::size_t(column)];
    };
    texel.from_palette = true;
    const double x = s * palette.width, y = t * palette.height;
    if (m_map.interpolate == 0) {
        const unsigned char index = entry(x, y);
        texel.filter = palette.filter[index];
        texel.transmit = palette.transmit[index];
        return;
    }
    const double left = std::floor(x - 0.5), top = std::floor(y - 0.5);
    const float fx = float(x - 0.5 - left), fy = float(y - 0.5 - top);
    const unsigned char a = entry(left, top), b = entry(left + 1.0, top), c = entry(left, top + 1.0),
                        d = entry(left + 1.0, top + 1.0);
    auto blend = [&](const float* values) {
        return (1.0f - fy) * ((1.0f - fx) * values[a] + fx * values[b]) +
               fy * ((1.0f - fx) * values[c] + fx * values[d]);
    };
    texel.filter = blend(palette.filter);
    texel.transmit = blend(palette.transmit);
}

Texel ImageSampler::blended(double s, double t) const {
    // POV decodes the texels before it blends them: blend the four nearest
    // texels' decoded values (texel centres at (i + 0.5) / width).
    const double x = s * m_width - 0.5, y = t * m_height - 0.5;
    const double left = std::floor(x), top = std::floor(y);
    const float fx = float(x - left), fy = float(y - top);
    const double s0 = (left + 0.5) / m_width, s1 = (left + 1.5) / m_width;
    const double t0 = (top + 0.5) / m_height, t1 = (top + 1.5) / m_height;
    const Texel a = lookup(s0, t0), b = lookup(s1, t0), c = lookup(s0, t1), d = lookup(s1, t1);
    auto blend = [&](auto member) {
        return (1.0f - fy) * ((1.0f - fx) * a.*member + fx * b.*member) +
               fy * ((1.0f - fx) * c.*member + fx * d.*member);
    };
    return {blend(&Texel::rgb), blend(&Texel::alpha)};
}

Texel ImageSampler::decode(const float* texel) const {
    Texel out;
    out.rgb = m_channels < 3 ? Color(texel[0]) : Color(texel[0], texel[1], texel[2]);
    if (m_decode_srgb) out.rgb = Color(srgb_decode(out.rgb.r), srgb_decode(out.rgb.g), srgb_decode(out.rgb.b));
    out.alpha = has_alpha() ? texel[m_channels - 1] : 1.0f;
    return out;
}

ImageSampler open_image(const sg::ImageMap& map, const MaterialBuild& build) {
    std::shared_ptr<ImageTextureSystem> own;
    return ImageSampler(map, build.images ? *build.images : own);
}

}  // namespace lancer
