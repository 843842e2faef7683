// Where the points of POV-Ray's area_light lie (POV-Ray 3.7's
// TraceAreaLightShadowRay; ../shared/reference/pov-3.7-semantics.md §6).
// One copy for the light's own sampling (PovAreaLight, `path`) and POV's
// grid of shadow rays (shading/area_light_shadows.h), so both span the
// same rectangle, ellipse or oriented disc.
#pragma once

#include <cmath>

#include "lancer/light.h"

namespace lancer {

// The axes the grid spans as seen from one shading point. `to_light` is
// the unit direction from the point to the light's centre; `orient` turns
// the axes perpendicular to it, both as long as the first one.
struct AreaGridAxes {
    glm::dvec3 axis1;
    glm::dvec3 axis2;
};

inline AreaGridAxes area_grid_axes(const PovAreaLightParameters& light, const glm::dvec3& to_light) {
    if (!light.orient) return {glm::dvec3(light.axis1), glm::dvec3(light.axis2)};
    const double length = glm::length(glm::dvec3(light.axis1));
    // Too close to the z axis for a cross product with it: use y (POV's rule).
    const glm::dvec3 helper =
        std::fabs(std::fabs(to_light.z) - 1.0) < 0.01 ? glm::dvec3(0.0, 1.0, 0.0) : glm::dvec3(0.0, 0.0, 1.0);
    const glm::dvec3 axis1 = glm::normalize(glm::cross(to_light, helper));
    const glm::dvec3 axis2 = glm::normalize(glm::cross(to_light, axis1));
    return {axis1 * length, axis2 * length};
}

// The offset from the centre of the point at grid coordinates (u, v):
// u = 0 .. size1 - 1 spans axis1 from -1/2 to +1/2 (jitter moves u by up
// to half a cell, past the edges too); along an axis of size 1 the offset
// is 0. `circular` maps the square's concentric shells onto circles,
// which keeps a uniform density uniform.
inline glm::dvec3 area_grid_offset(const PovAreaLightParameters& light, const AreaGridAxes& axes, double u, double v) {
    if (light.circular) {
        // POV nudges both coordinates so the centre has a direction.
        double ju = u / double(light.size1 - 1) - 0.5 + 0.001;
        double jv = v / double(light.size2 - 1) - 0.5 + 0.001;
        const double shell = std::fmax(std::fabs(ju), std::fabs(jv)) / std::sqrt(ju * ju + jv * jv);
        return axes.axis1 * (ju * shell) + axes.axis2 * (jv * shell);
    }
    glm::dvec3 offset(0.0);
    if (light.size1 > 1) offset += axes.axis1 * (u / double(light.size1 - 1) - 0.5);
    if (light.size2 > 1) offset += axes.axis2 * (v / double(light.size2 - 1) - 0.5);
    return offset;
}

}  // namespace lancer
