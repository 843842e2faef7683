// POV-Ray 3.7's ovus { bottom_radius, top_radius }: an egg about the y axis.
//
// Object space (POV 3.7, Parse_Ovus and core ovus): a sphere of radius
// bottom_radius about the origin below, a sphere of radius top_radius about
// <0, bottom_radius, 0> above, joined by a band of a spindle torus's inner
// "lemon" whose meridian is a circle of radius 2 max(bottom, top) tangent to
// both spheres. The surface is the bottom sphere below the lower tangent
// circle, the band between the two tangent circles and the top sphere above
// the upper one; the whole is convex and smooth (tangent-continuous).
//
// Parameters POV-Ray 3.7 treats specially:
//  - either radius negative: a parse error ("Both Ovus radii must be
//    positive"); the factory returns null.
//  - top_radius >= 2 bottom_radius (which includes bottom_radius = 0): a
//    non-fatal "Possible Parse Error: Ovus second radius should be less than
//    twice first radius / Substituing a sphere to ovus as it would be
//    identical & simpler"; POV then makes sphere { <0, bottom_radius, 0>,
//    top_radius }, and so does the factory (a sphere shape, with the
//    sphere's (u, v)).
//  - top_radius = 0 < bottom_radius: the bottom sphere alone.
// POV 3.7 accepts `sturm` in an ovus (it picks POV's quartic solver; no
// effect here). POV 3.8's `distance`, `radius` and `precision` are parse
// errors in 3.7 and are not modelled.
#pragma once

#include <memory>

#include "geometry/shape.h"

namespace lancer {

// The part of an ovus a crossing lies on (ShapeCrossing::face).
enum OvusFace { kOvusBottomSphere = 0, kOvusTopSphere = 1, kOvusConnection = 2 };

// Null for parameters POV refuses (a negative or non-finite radius).
std::shared_ptr<const Shape> make_ovus_shape(double bottom_radius, double top_radius);

}  // namespace lancer
