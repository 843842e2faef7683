// The box or sphere an isosurface or a parametric is drawn in (POV-Ray's
// contained_by), in the shape's own space (internal to liblancer). Each
// shape finds its own chord through it, as POV-Ray's two differ.
#pragma once

#include <cmath>

#include "geometry/shape.h"
#include "lancer/scene_graph.h"

namespace lancer {

struct ContainedBy {
    bool sphere = false;  // else the box
    DVec3 box_lower{-1.0}, box_upper{1.0};
    DVec3 sphere_center{0.0};
    double sphere_radius = 1.0;

    static ContainedBy from(const sg::FunctionContainer& written) {
        ContainedBy c;
        c.sphere = written.container == sg::FunctionContainer::Container::Sphere;
        c.box_lower = written.box_corner1;
        c.box_upper = written.box_corner2;
        c.sphere_center = written.sphere_center;
        c.sphere_radius = written.sphere_radius;
        return c;
    }

    // Finite, and a sphere of positive radius.
    bool usable() const {
        const auto finite = [](const DVec3& v) {
            return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
        };
        return finite(box_lower) && finite(box_upper) && finite(sphere_center) && std::isfinite(sphere_radius) &&
               (!sphere || sphere_radius > 0.0);
    }

    // The same container with its box's corners in order on every axis.
    ContainedBy ordered() const {
        ContainedBy c = *this;
        c.box_lower = glm::min(box_lower, box_upper);
        c.box_upper = glm::max(box_lower, box_upper);
        return c;
    }

    void bounds(DVec3& lower, DVec3& upper) const {
        if (sphere) {
            lower = sphere_center - DVec3(sphere_radius);
            upper = sphere_center + DVec3(sphere_radius);
        } else {
            lower = box_lower;
            upper = box_upper;
        }
    }
};

}  // namespace lancer
