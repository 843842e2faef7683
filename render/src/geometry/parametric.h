// POV-Ray's parametric (internal to liblancer): the surface
// (x(u, v), y(u, v), z(u, v)) over a rectangle of (u, v), drawn inside a
// box or sphere, found by POV's subdivision of (u, v) (see parametric.cpp).
#pragma once

#include <array>
#include <memory>

#include "geometry/contained_by.h"
#include "geometry/shape.h"
#include "lancer/function.h"

namespace lancer {

struct ParametricParameters {
    std::array<std::shared_ptr<const sg::Function>, 3> functions;
    // What each function asks of the renderer (noise, patterns); null when
    // it asks for nothing.
    std::array<std::shared_ptr<const sg::FunctionNatives>, 3> natives;
    glm::dvec2 uv_min{0.0}, uv_max{1.0};
    ContainedBy container;
    double accuracy = 0.001;
    double max_gradient = 1.0;
    int precompute_depth = 0;  // 1..20 with precompute_axes, else 0
    int precompute_axes = 0;   // bit 0 x, bit 1 y, bit 2 z
};

// Null for a function that is missing or parameters that are not finite
// or out of range.
std::shared_ptr<const Shape> make_parametric_shape(const ParametricParameters& parameters);

}  // namespace lancer
