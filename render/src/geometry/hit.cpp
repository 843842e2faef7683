// Scale-aware ray origins (pbrt-v4's OffsetRayOrigin idea): a spawned ray
// starts outside the error box of the hit point, measured along the
// geometric normal, and one float further; no fixed epsilon anywhere.
#include <cfloat>
#include <cmath>

#include "geometry/float_steps.h"
#include "lancer/hit.h"

namespace lancer {
namespace {

// How many float ULPs of the target's magnitude a shadow ray stops short of
// its target: covers the rounding of the sampled point, of the distance and
// of the intersector's t.
constexpr float kShadowMarginUlps = 64.0f;

float max_abs(const Vec3& v) {
    return glm::max(std::fabs(v.x), glm::max(std::fabs(v.y), std::fabs(v.z)));
}

}  // namespace

Vec3 Hit::offset_origin(const Vec3& direction) const {
    // Distance along the normal that clears the error box of `position`.
    const float distance = glm::dot(glm::abs(geometric_normal), position_error);
    Vec3 offset = distance * geometric_normal;
    if (glm::dot(direction, geometric_normal) < 0.0f) offset = -offset;
    Vec3 origin = position + offset;
    // Round away from the surface: the sum above may have rounded back.
    for (int axis = 0; axis < 3; ++axis) {
        if (offset[axis] > 0.0f)
            origin[axis] = next_float_up(origin[axis]);
        else if (offset[axis] < 0.0f)
            origin[axis] = next_float_down(origin[axis]);
    }
    return origin;
}

Ray Hit::spawn_ray(const Vec3& direction) const {
    Ray ray;
    ray.origin = offset_origin(direction);
    const float length = glm::length(direction);
    ray.direction = length > 0.0f ? direction / length : geometric_normal;
    ray.t_min = 0.0f;
    ray.t_max = kInfinity;
    return ray;
}

Ray Hit::spawn_ray_to(const Vec3& target) const {
    Ray ray;
    ray.origin = offset_origin(target - position);
    const Vec3 to_target = target - ray.origin;
    const float distance = glm::length(to_target);
    ray.t_min = 0.0f;
    if (!(distance > 0.0f) || !std::isfinite(distance)) {
        // Target on (or numerically at) the origin: nothing can lie between.
        ray.direction = geometric_normal;
        ray.t_max = 0.0f;
        return ray;
    }
    ray.direction = to_target / distance;
    const float magnitude = glm::max(max_abs(target), max_abs(ray.origin));
    const float margin = kShadowMarginUlps * FLT_EPSILON * magnitude;
    ray.t_max = glm::max(0.0f, distance - margin);
    return ray;
}

}  // namespace lancer
