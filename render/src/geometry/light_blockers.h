// Which objects stop every shadow ray that meets them, known before the
// render (internal to liblancer): RenderScene::shadow_blockers then answers
// Opaque without the walk through the surfaces that finds what a shadow
// ray's blockers let through (lancer/shading/shadow_rays.h).
#pragma once

#include "geometry/scene_data.h"

namespace lancer {

// Whether no light passes `instance` anywhere: it casts shadows, and each
// material a hit on it may carry (a CSG tree: on any of its leaves) blocks
// light as the walk would find it (MaterialParameters::blocks_light; a
// light's own surface is seen as one material, without its layers).
bool blocks_all_light(const SceneData& data, const Instance& instance);

// Whether every crossing of `instance` past some t_min is found by one
// search from the ray's own origin (Instance::gathers_crossings).
bool gathers_crossings(const SceneData& data, const Instance& instance);

}  // namespace lancer
