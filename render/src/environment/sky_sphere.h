// POV-Ray's sky_sphere: what a ray that escapes the scene sees, read from
// pigments at its direction (internal to liblancer).
#pragma once

#include <memory>
#include <vector>

#include "lancer/scene_graph.h"
#include "lancer/texture.h"

namespace lancer {

class PointPigment;
struct PatternContext;
class TextureFactory;

class SkySphere {
  public:
    // Throws lancer::SceneError where a pigment cannot be evaluated.
    SkySphere(const sg::SkySphere& sky, const Color& background, double language_version, TextureFactory& factory);
    ~SkySphere();
    SkySphere(const SkySphere&) = delete;
    SkySphere& operator=(const SkySphere&) = delete;

    // Radiance towards `direction` (any length, not zero): POV-Ray's
    // ComputeSky, the background's own filter and transmit ignored. From
    // #version 3.7 on, the layers are composited over the background as a
    // layered texture is; before, as POV 3.6 did (each layer's opacity
    // scaled by the filter and transmit multiplied down so far).
    Color radiance(const Vec3& direction) const;

  private:
    Color layered(const glm::dvec3& point, const PatternContext& context) const;
    Color legacy_layered(const glm::dvec3& point, const PatternContext& context) const;

    std::vector<std::unique_ptr<PointPigment>> m_layers;  // bottom first, as written
    glm::dmat4 m_sky_from_world;
    Color m_emission;
    Color m_background;
    bool m_legacy = false;
};

}  // namespace lancer
