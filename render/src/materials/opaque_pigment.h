// Whether a pigment can let light through anywhere: a shadow ray that meets
// a surface none of whose colours has filter or transmit is black there,
// whatever point of the pattern it meets (render/include/lancer/shading/
// shadow_rays.h takes that shortcut when every surface is so).
#pragma once

#include "lancer/scene_graph.h"

namespace lancer {

// True when every colour the pigment can take has filter and transmit 0.
// An image is taken to let light through (its alpha, a palette's `filter
// all`): only colours written in the scene are read.
bool pigment_is_opaque(const sg::Pigment& pigment);

}  // namespace lancer
