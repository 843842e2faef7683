// Images as pigments and patterns: POV-Ray's image_map (on a surface, or
// inside a pigment_map, a block pattern's list or average), and
// image_pattern (the image's grey, or its alpha, as a pattern value).
#include <algorithm>

#include "lancer/scene_error.h"
#include "materials/image_sampler.h"
#include "materials/point_pigment.h"

namespace lancer {
namespace {

class ImagePointPigment final : public PointPigment {
  public:
    ImagePointPigment(const sg::Pigment& pigment, const MaterialBuild& build)
        : m_image(open_image(*pigment.image, build)), m_warps(*pigment.pattern, build.generator) {}

    TextureSample at(const glm::dvec3& point, const PatternContext&) const override {
        // POV moves the point (transforms, turbulence, warp { }) before it
        // projects it.
        const std::optional<glm::dvec2> uv = m_image.project(m_warps.pattern_point(point));
        if (!uv) return {Color(1.0f), 0.0f, 1.0f};  // clear, beyond a `once` image
        return sample(m_image.at(*uv));
    }
    TextureSample average() const override { return sample(m_image.average()); }

  private:
    TextureSample sample(const Texel& texel) const {
        if (texel.from_palette) return {texel.rgb, texel.filter, texel.transmit};
        return {texel.rgb, m_image.filter_all(), std::clamp(m_image.transmit_all() + (1.0f - texel.alpha), 0.0f, 1.0f)};
    }

    ImageSampler m_image;
    CompiledPattern m_warps;  // the pigment's transforms and warps
};

}  // namespace

std::unique_ptr<PointPigment> make_image_point_pigment(const sg::Pigment& pigment, const MaterialBuild& build) {
    return std::make_unique<ImagePointPigment>(pigment, build);
}

CompiledPattern::ValueSource image_pattern_source(const sg::Pattern& pattern, const MaterialBuild& build) {
    if (!pattern.image) throw SceneError(pattern.location, "image_pattern needs an image");
    auto image = std::make_shared<const ImageSampler>(open_image(*pattern.image, build));
    const bool use_alpha = pattern.image->use_alpha;
    return [image, use_alpha](const glm::dvec3& point, const PatternContext&) {
        const std::optional<glm::dvec2> uv = image->project(point);
        if (!uv) return 0.0;
        const Texel texel = image->at(*uv);
        // use_alpha reads how transparent the image is (its red where it
        // has no alpha); otherwise its grey.
        double value = pov_greyscale(texel.rgb);
        if (use_alpha) value = image->has_alpha() ? 1.0 - texel.alpha : texel.rgb.r;
        return std::clamp(value, 0.0, 1.0);
    };
}

}  // namespace lancer
