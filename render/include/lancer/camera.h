// The camera, resolved from the scene graph as POV-Ray 3.7 frames it
// (reference/pov-3.7-semantics.md §1).
#pragma once

#include "lancer/ray.h"

namespace lancer {

class Camera {
public:
    enum class Projection { Perspective, Orthographic };

    Camera() = default;
    Camera(Projection projection, const Vec3& location, const Vec3& direction, const Vec3& right,
           const Vec3& up)
        : m_projection(projection), m_location(location), m_direction(direction),
          m_right(right), m_up(up) {}

    // Ray through the film point (x, y) in pixels, (0,0) the top-left corner
    // of the image and (width, height) the bottom-right. Pixel centres are at
    // half-integers, as POV-Ray's.
    Ray generate_ray(float x, float y, int width, int height) const;

    Projection projection() const { return m_projection; }
    const Vec3& location() const { return m_location; }
    const Vec3& direction() const { return m_direction; }
    const Vec3& right() const { return m_right; }
    const Vec3& up() const { return m_up; }

private:
    Projection m_projection = Projection::Perspective;
    Vec3 m_location{0.0f};
    Vec3 m_direction{0.0f, 0.0f, 1.0f};
    Vec3 m_right{1.33f, 0.0f, 0.0f};
    Vec3 m_up{0.0f, 1.0f, 0.0f};
};

}  // namespace lancer
