// POV-Ray's map_type projections (imageutil.cpp in POV-Ray 3.7, read for
// its rules) and texel lookups in the image's texels.
#include "materials/image_sampler.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "lancer/scene_error.h"
#include "materials/palette_image.h"

namespace lancer {

namespace {

constexpr double kTwoPi = 6.283185307179586476925;

float srgb_decode(float encoded) {
    if (encoded <= 0.04045f) return encoded / 12.92f;
    return std::pow((encoded + 0.055f) / 1.055f, 2.4f);
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
        throw SceneError(map.location, "cannot read image '" + map.path + "': " + error.what());
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

ImageSampler::ImageSampler(const sg::ImageMap& map, ImageCache& images) : m_map(map) {
    try {
        m_texels = images.get(m_map.path);
    } catch (const std::length_error& error) {
        throw SceneError(m_map.location, "image '" + m_map.path + "' " + error.what());
    } catch (const std::runtime_error& error) {
        throw SceneError(m_map.location, "cannot read image '" + m_map.path + "': " + error.what());
    }
    m_width = m_texels->width();
    m_height = m_texels->height();
    m_channels = std::min(m_texels->channels(), 4);
    // 8- and 16-bit files are display-encoded; float files are linear.
    m_decode_srgb = m_map.srgb && !m_texels->floating();
    float mean[4] = {0, 0, 0, 1};
    for (int c = 0; c < m_channels; ++c) mean[c] = m_texels->average()[std::size_t(c)];
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

glm::ivec2 ImageSampler::wrap(long long column, long long row, int columns, int rows) const {
    // A `once` image is not repeated: POV takes the edge pixels for the
    // samples an interpolation needs beyond it.
    if (m_map.once)
        return {int(std::clamp<long long>(column, 0, columns - 1)), int(std::clamp<long long>(row, 0, rows - 1))};
    return {int(((column % columns) + columns) % columns), int(((row % rows) + rows) % rows)};
}

Texel ImageSampler::texel(long long column, long long row) const {
    const glm::ivec2 at = wrap(column, row, m_width, m_height);
    float values[4] = {0, 0, 0, 1};
    for (int c = 0; c < m_channels; ++c) values[c] = m_texels->sample(at.x, at.y, c);
    return decode(values);
}

// The four nearest texels' shares at (fx, fy) from the first: POV's
// interpolate 4 weighs each by the inverse of its squared distance
// (imageutil.cpp's norm_dist), every other kind bilinearly.
ImageSampler::CornerWeights ImageSampler::corner_weights(float fx, float fy) const {
    if (m_map.interpolate != 4) return {(1.0f - fx) * (1.0f - fy), fx * (1.0f - fy), (1.0f - fx) * fy, fx * fy};
    const double x = fx, y = fy;
    const double distance2[4] = {x * x + y * y, (1.0 - x) * (1.0 - x) + y * y, x * x + (1.0 - y) * (1.0 - y),
                                 (1.0 - x) * (1.0 - x) + (1.0 - y) * (1.0 - y)};
    double weight[4], sum = 0.0;
    for (int k = 0; k < 4; ++k) {
        if (distance2[k] == 0.0)  // on a texel's centre: that texel alone
            return {k == 0 ? 1.0f : 0.0f, k == 1 ? 1.0f : 0.0f, k == 2 ? 1.0f : 0.0f, k == 3 ? 1.0f : 0.0f};
        weight[k] = 1.0 / distance2[k];
        sum += weight[k];
    }
    return {float(weight[0] / sum), float(weight[1] / sum), float(weight[2] / sum), float(weight[3] / sum)};
}

Texel ImageSampler::at(const glm::dvec2& uv) const {
    // Row 0 is the image's top; v runs up.
    const glm::dvec2 position = pixel_position(uv, m_width, m_height);
    Texel result;
    if (m_map.interpolate == 0) {
        result = texel((long long)std::floor(position.x), (long long)std::floor(position.y));
    } else {
        // POV decodes the texels before it blends them: the four nearest
        // texels' decoded values (texel centres at (i + 0.5) / width).
        const double x = position.x - 0.5, y = position.y - 0.5;
        const double left = std::floor(x), top = std::floor(y);
        const float fx = float(x - left), fy = float(y - top);
        const long long column = (long long)left, row = (long long)top;
        const Texel a = texel(column, row), b = texel(column + 1, row), c = texel(column, row + 1),
                    d = texel(column + 1, row + 1);
        const CornerWeights w = corner_weights(fx, fy);
        auto blend = [&](auto member) { return w.a * a.*member + w.b * b.*member + w.c * c.*member + w.d * d.*member; };
        result = {blend(&Texel::rgb), blend(&Texel::alpha)};
    }
    if (m_palette) add_palette_transparency(result, uv);
    return result;
}

// The entries' filter and transmit, at the texels the colour came from
// and blended with the same weights.
void ImageSampler::add_palette_transparency(Texel& texel, const glm::dvec2& uv) const {
    const PaletteTransparency& palette = *m_palette;
    auto entry = [&](double x, double y) {
        const glm::ivec2 at = wrap((long long)std::floor(x), (long long)std::floor(y), palette.width, palette.height);
        return palette.indices[std::size_t(at.y) * std::size_t(palette.width) + std::size_t(at.x)];
    };
    texel.from_palette = true;
    const glm::dvec2 position = pixel_position(uv, palette.width, palette.height);
    const double x = position.x, y = position.y;
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
    const CornerWeights w = corner_weights(fx, fy);
    auto blend = [&](const float* values) {
        return w.a * values[a] + w.b * values[b] + w.c * values[c] + w.d * values[d];
    };
    texel.filter = blend(palette.filter);
    texel.transmit = blend(palette.transmit);
}

Texel ImageSampler::decode(const float* texel) const {
    Texel out;
    out.rgb = m_channels < 3 ? Color(texel[0]) : Color(texel[0], texel[1], texel[2]);
    if (m_decode_srgb) out.rgb = Color(srgb_decode(out.rgb.r), srgb_decode(out.rgb.g), srgb_decode(out.rgb.b));
    if (m_decode_srgb && m_map.working_gamma != 1.0 && m_map.working_gamma > 0.0)
        out.rgb = glm::pow(glm::max(out.rgb, Color(0.0f)), Color(float(1.0 / m_map.working_gamma)));
    out.alpha = has_alpha() ? texel[m_channels - 1] : 1.0f;
    return out;
}

ImageSampler open_image(const sg::ImageMap& map, const MaterialBuild& build) {
    if (build.images == nullptr) {
        ImageCache own;
        return ImageSampler(map, own);
    }
    if (!*build.images) *build.images = std::make_shared<ImageCache>();
    return ImageSampler(map, **build.images);
}

}  // namespace lancer
