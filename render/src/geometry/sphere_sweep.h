// POV-Ray's sphere_sweep (internal to liblancer): the solid a sphere of
// varying radius sweeps along a spline, in its own object space.
#pragma once

#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "geometry/shape.h"

namespace lancer {

// The spline keyword: linear_spline (at least 2 spheres, a segment between
// each pair), b_spline (uniform cubic B-spline, at least 4; it passes
// through none of them) or cubic_spline (Catmull-Rom, at least 4; it passes
// through every sphere but the first and last, which only steer tangents).
enum class SphereSweepSpline { Linear, BSpline, CubicSpline };

// `spheres`: the modeling spheres as written, xyz the centre, w the radius
// (a negative radius acts as its magnitude, as in POV). `tolerance` is POV's
// depth tolerance (default 1e-6): crossings at t <= tolerance are dropped,
// t along the caller's ray (POV's depth for unit world rays). Null where POV
// refuses the sweep ("Too few modeling spheres for interpolation type.")
// and for non-finite numbers.
std::shared_ptr<const Shape> make_sphere_sweep_shape(SphereSweepSpline spline, const std::vector<glm::dvec4>& spheres,
                                                     double tolerance);

}  // namespace lancer
