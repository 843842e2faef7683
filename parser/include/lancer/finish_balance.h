// Finishes that reflect more light than they receive. POV-Ray's finish
// values are peaks, not albedos (docs/scene-language.md#finishes), so
// `diffuse 0.8 reflection 0.5` returns 1.3 of the light that falls on it.
// The classic integrators render that as written; `path` follows such a
// surface bounce after bounce, gaining energy each time, and says so.
#pragma once

#include <vector>

#include "lancer/parser.h"
#include "lancer/scene_graph.h"

namespace lancer {

// The largest share of incident light the finish can return at normal
// incidence, over the colour channels: diffuse × pigment, the highlights'
// shares, the mirror and what passes through. `pigment_peak` bounds the
// pigment's channels (1 for patterns and images).
double finish_reflectance_bound(const sg::Finish& finish, double pigment_peak, double transparency);

// One warning, at the material's location, for each distinct material of
// the scene whose finish returns more than it receives.
std::vector<Diagnostic> energy_gaining_finishes(const sg::SceneGraph& scene);

}  // namespace lancer
