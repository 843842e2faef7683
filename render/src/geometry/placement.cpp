// Placements: an object's affine map to the world, with the error bounds
// and normal transform hits need.
#include "geometry/shapes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

namespace lancer {
namespace {

DMat3 linear_part(const DMat4& m) {
    return DMat3(m);
}

}  // namespace

Placement Placement::from(const DMat4& world_from_object) {
    Placement p;
    p.world_from_object = world_from_object;
    p.object_from_world = glm::inverse(world_from_object);
    p.normal_to_world = glm::transpose(glm::inverse(linear_part(world_from_object)));
    p.identity = world_from_object == DMat4(1.0);
    return p;
}

Vec3 Placement::world_point_error(const DVec3& p_object, const DVec3& p_world) const {
    // Rounding the double result to float (half an ULP, taken as two for
    // safety) plus the double arithmetic of the intersection and the
    // transform. That arithmetic mixes the axes (a point found along a ray,
    // or snapped onto a disc), so its bound on every axis is the largest:
    // a point exactly on the plane z = 0 still gets an error across it, and
    // a ray leaving it starts off the surface, not on it where its own
    // rounding finds the surface again at t = 1e-17 (a cone's base in the
    // plane z = 0 stopped every shadow ray leaving through it).
    DVec3 magnitude = glm::abs(p_object);
    if (!identity) {
        const DMat3 a = linear_part(world_from_object);
        magnitude = DVec3(0.0);
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) magnitude[row] += std::fabs(a[col][row]) * std::fabs(p_object[col]);
        magnitude += glm::abs(DVec3(world_from_object[3]));
    }
    const double largest = std::max({magnitude.x, magnitude.y, magnitude.z});
    return Vec3(2.0 * double(FLT_EPSILON) * glm::abs(p_world) + DVec3(16.0 * DBL_EPSILON * largest));
}

bool Placement::is_similarity() const {
    const DMat3 a = linear_part(world_from_object);
    const double s0 = glm::length(a[0]), s1 = glm::length(a[1]), s2 = glm::length(a[2]);
    const double s = std::max({s0, s1, s2});
    if (!(s > 0.0)) return false;
    const double tolerance = 1e-9 * s * s;
    return std::fabs(s0 - s1) < 1e-9 * s && std::fabs(s0 - s2) < 1e-9 * s &&
           std::fabs(glm::dot(a[0], a[1])) < tolerance && std::fabs(glm::dot(a[0], a[2])) < tolerance &&
           std::fabs(glm::dot(a[1], a[2])) < tolerance;
}

double Placement::uniform_scale() const {
    return glm::length(linear_part(world_from_object)[0]);
}

}  // namespace lancer
