// The camera, resolved from the scene graph as POV-Ray 3.7 frames it
// (pov-3.7-semantics.md §1, the POV-Ray reference kept outside this repository).
#pragma once

#include <cmath>

#include "lancer/ray.h"

namespace lancer {

class Camera {
  public:
    enum class Projection { Perspective, Orthographic };

    Camera() = default;
    Camera(Projection projection, const Vec3& location, const Vec3& direction, const Vec3& right, const Vec3& up)
        : m_projection(projection), m_location(location), m_direction(direction), m_right(right), m_up(up) {}

    // Ray through the film point (x, y) in pixels, (0,0) the top-left corner
    // of the image and (width, height) the bottom-right. Pixel centres are at
    // half-integers, as POV-Ray's. Inline: the host calls it once per
    // camera sample, and the ray is then built where it is stored.
    Ray generate_ray(float x, float y, int width, int height) const {
        // Normalised image coordinates: x0 in [-0.5, 0.5] left to right, y0
        // in [-0.5, 0.5] bottom to top.
        const float x0 = x / float(width) - 0.5f;
        const float y0 = 0.5f - y / float(height);
        Ray ray;
        if (m_projection == Projection::Orthographic) {
            ray.origin = m_location + x0 * m_right + y0 * m_up;
            ray.direction = glm::normalize(m_direction);
        } else {
            ray.origin = m_location;
            ray.direction = glm::normalize(m_direction + x0 * m_right + y0 * m_up);
        }
        ray.t_min = 0.0f;
        ray.t_max = kInfinity;
        return ray;
    }

    // generate_ray for `count` film points (x[i], y[i]), bit for bit, into
    // out[i]. Computed lane by lane, so the compiler takes several rays per
    // instruction: the host generates a tile's camera rays at once.
    void generate_rays(const float* x, const float* y, int count, int width, int height, Ray* out) const {
        if (m_projection == Projection::Orthographic) {
            for (int i = 0; i < count; ++i) out[i] = generate_ray(x[i], y[i], width, height);
            return;
        }
        constexpr int kLanes = 16;
        for (int first = 0; first < count; first += kLanes) {
            const int lanes = count - first < kLanes ? count - first : kLanes;
            float dx[kLanes], dy[kLanes], dz[kLanes];
            for (int i = 0; i < lanes; ++i) {
                // generate_ray's arithmetic, component by component.
                const float x0 = x[first + i] / float(width) - 0.5f;
                const float y0 = 0.5f - y[first + i] / float(height);
                const float vx = (m_direction.x + x0 * m_right.x) + y0 * m_up.x;
                const float vy = (m_direction.y + x0 * m_right.y) + y0 * m_up.y;
                const float vz = (m_direction.z + x0 * m_right.z) + y0 * m_up.z;
                const float inverse_length = 1.0f / std::sqrt((vx * vx + vy * vy) + vz * vz);
                dx[i] = vx * inverse_length;
                dy[i] = vy * inverse_length;
                dz[i] = vz * inverse_length;
            }
            for (int i = 0; i < lanes; ++i) {
                Ray& ray = out[first + i];
                ray.origin = m_location;
                ray.direction = Vec3(dx[i], dy[i], dz[i]);
                ray.t_min = 0.0f;
                ray.t_max = kInfinity;
            }
        }
    }

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
