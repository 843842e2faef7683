#include "environment/sky_sphere.h"

#include "materials/pattern.h"
#include "materials/point_pigment.h"
#include "materials/textures.h"

namespace lancer {

SkySphere::SkySphere(const sg::SkySphere& sky, const Color& background, double language_version,
                     TextureFactory& factory)
    : m_sky_from_world(glm::inverse(glm::dmat4(sky.transform))),
      m_emission(Color(sky.emission)),
      m_background(background),
      m_legacy(language_version < 3.7 - 1e-9) {
    for (const sg::Pigment& pigment : sky.pigments) m_layers.push_back(factory.make_point_pigment(pigment));
}

SkySphere::~SkySphere() = default;

Color SkySphere::radiance(const Vec3& direction) const {
    const glm::dvec3 unit = glm::normalize(glm::dvec3(direction));
    // POV transforms the direction as a point (MInvTransPoint): a
    // translated sky reads its pigments at a shifted point.
    const glm::dvec3 point = glm::dvec3(m_sky_from_world * glm::dvec4(unit, 1.0));
    PatternContext context;
    context.ray_direction = unit;
    context.normal = -unit;
    context.hit_point = point;
    return m_legacy ? legacy_layered(point, context) : layered(point, context);
}

Color SkySphere::layered(const glm::dvec3& point, const PatternContext& context) const {
    Color seen(0.0f);
    Color through(1.0f);  // what the layers above let pass
    for (auto layer = m_layers.rbegin(); layer != m_layers.rend(); ++layer) {
        const TextureSample sample = (*layer)->at(point, context);
        const float opacity = 1.0f - sample.filter - sample.transmit;
        seen += sample.rgb * opacity * through * m_emission;
        through *= sample.rgb * sample.filter + Color(sample.transmit);
    }
    return seen + m_background * through;
}

Color SkySphere::legacy_layered(const glm::dvec3& point, const PatternContext& context) const {
    Color seen(0.0f);
    // The product of the layers' five channels so far, and how much of the
    // next layer shows through them.
    Color filter_rgb(1.0f);
    float filter = 1.0f, transmit = 1.0f, shown = 1.0f;
    for (auto layer = m_layers.rbegin(); layer != m_layers.rend(); ++layer) {
        const TextureSample sample = (*layer)->at(point, context);
        seen += sample.rgb * (shown * (1.0f - sample.filter - sample.transmit));
        filter_rgb *= sample.rgb;
        filter *= sample.filter;
        transmit *= sample.transmit;
        shown = std::abs(filter) + std::abs(transmit);
    }
    return seen * m_emission + m_background * (filter_rgb * filter + Color(transmit));
}

}  // namespace lancer
