// Which objects contain a point, as POV-Ray finds the interiors a camera
// ray starts in (its InitRayContainerState): every object whose inside
// test holds there. Internal to liblancer.
#pragma once

#include "geometry/scene_data.h"
#include "lancer/interior_stack.h"

namespace lancer {

// The objects of `data` that contain `p`, the largest first (the
// innermost last, as InteriorStack keeps them). A CSG object is entered
// through the leaf that holds `p` (a ray leaving it leaves through one of
// its leaves, whose material carries the object's interior). Meshes are
// left out, as is a surface with no inside (a polygon, a bicubic patch).
InteriorStack objects_containing(const SceneData& data, const Vec3& p);

}  // namespace lancer
