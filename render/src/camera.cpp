// POV-Ray 3.7 framing (reference/pov-3.7-semantics.md §1).
#include "lancer/camera.h"

namespace lancer {

Ray Camera::generate_ray(float x, float y, int width, int height) const {
    // Normalised image coordinates: x0 in [-0.5, 0.5] left to right, y0 in
    // [-0.5, 0.5] bottom to top.
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

}  // namespace lancer
