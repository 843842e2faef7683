// Small value types every stage of rendering speaks: vectors, colours, rays.
#pragma once

#include <cstdint>

#include <limits>

#include <glm/glm.hpp>

namespace lancer {

using Vec2 = glm::vec2;
using Vec3 = glm::vec3;
using Color = glm::vec3;  // linear RGB radiance or reflectance

inline constexpr float kInfinity = std::numeric_limits<float>::infinity();
inline constexpr float kPi = 3.14159265358979323846f;
inline constexpr double kPiD = 3.141592653589793238463;

// A ray is the half-line origin + t * direction for t in [t_min, t_max].
// direction need not be unit length, but every ray the host and the shared
// helpers (Hit::spawn_ray...) create has a unit direction.
// What a ray is to POV-Ray's no_image and no_reflection objects, which it
// passes through: a camera ray, or one refracted from it (Image); a mirror
// ray, or one refracted from it (Reflection); any other ray sees them all.
enum class RaySight : std::uint8_t { Other, Image, Reflection };

struct Ray {
    Vec3 origin{0.0f};
    Vec3 direction{0.0f, 0.0f, 1.0f};
    float t_min = 0.0f;
    float t_max = kInfinity;
    RaySight seen_as = RaySight::Other;

    Vec3 at(float t) const { return origin + t * direction; }
};

inline float max_component(const Color& c) {
    return glm::max(c.r, glm::max(c.g, c.b));
}
inline float luminance(const Color& c) {
    return 0.2126f * c.r + 0.7152f * c.g + 0.0722f * c.b;
}
// POV-Ray's grey of a colour (its intensities 0.297, 0.589, 0.114), which
// it weighs filtered light by where one number must stand for three.
inline float pov_grey(const Color& c) {
    return 0.297f * c.r + 0.589f * c.g + 0.114f * c.b;
}
inline bool is_black(const Color& c) {
    return c.r == 0.0f && c.g == 0.0f && c.b == 0.0f;
}

}  // namespace lancer
