// POV-Ray's checker pattern between two colours, with no warp or
// turbulence: the commonest pattern, one floor per axis (the general
// checker is the pattern family's).
#include <cmath>

#include "materials/pattern_space.h"

namespace lancer {
namespace {

// POV-Ray's checker: unit cubes in pattern space alternate between the two
// colours; POV's small tolerance keeps a plane at an integer coordinate on
// one side.
class CheckerTexture final : public Texture {
  public:
    CheckerTexture(const TextureSample& first, const TextureSample& second, const glm::dmat4& pattern_from_object,
                   const TextureSpaces& spaces)
        : m_first(first), m_second(second), m_pattern_from_object(pattern_from_object), m_spaces(spaces) {}

    TextureSample evaluate(const Hit& hit) const override {
        constexpr double kTolerance = 1e-6;  // POV: Small_Tolerance, relative to a unit cell
        const glm::dvec3 p = pattern_point(hit, m_spaces, m_pattern_from_object);
        const double cells = std::floor(p.x + kTolerance) + std::floor(p.y + kTolerance) + std::floor(p.z + kTolerance);
        const bool odd = std::fmod(std::fabs(cells), 2.0) == 1.0;
        return odd ? m_second : m_first;
    }
    TextureSample average() const override {
        return {0.5f * (m_first.rgb + m_second.rgb), 0.5f * (m_first.filter + m_second.filter),
                0.5f * (m_first.transmit + m_second.transmit)};
    }

  private:
    TextureSample m_first, m_second;
    glm::dmat4 m_pattern_from_object;
    const TextureSpaces& m_spaces;
};

}  // namespace

std::unique_ptr<Texture> make_checker_texture(const TextureSample& first, const TextureSample& second,
                                              const glm::dmat4& pattern_from_object, const TextureSpaces& spaces) {
    return std::make_unique<CheckerTexture>(first, second, pattern_from_object, spaces);
}

}  // namespace lancer
