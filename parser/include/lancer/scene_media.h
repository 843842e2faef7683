// POV-Ray's participating media in the scene graph: `media { … }` inside an
// object's `interior` and at scene level (the atmosphere). Included by
// scene_graph.h; kept apart so the media concept reads in one place.
//
// Values as written, with POV-Ray 3.7's defaults (parstxtr.cpp Parse_Media:
// from version 3.5 on, method 3 with 1 interval and 10 samples). Their
// meaning (docs/scene-language.md, "Media"): along a ray inside the
// medium, radiance gains emission + scattered light per unit length and
// loses (absorption + extinction * scattering) of itself per unit length,
// every coefficient multiplied by the product of the densities there.
#pragma once

#include <memory>
#include <vector>

namespace lancer::sg {

struct Pigment;

struct Media {
    // POV's scattering types 1–5: isotropic, Mie hazy, Mie murky, Rayleigh,
    // Henyey–Greenstein (with `eccentricity`).
    enum class ScatteringType { Isotropic = 1, MieHazy = 2, MieMurky = 3, Rayleigh = 4, HenyeyGreenstein = 5 };

    Vec3 emission{0.0};
    Vec3 absorption{0.0};
    Vec3 scattering{0.0};
    ScatteringType scattering_type = ScatteringType::Isotropic;
    double eccentricity = 0.0;  // Henyey–Greenstein's g, in (-1, 1)
    double extinction = 1.0;    // share of `scattering` that also dims the ray (POV's sc_ext)
    // Densities multiply (POV: each `density` block is one more factor);
    // each is a pigment whose rgb scales the coefficients, evaluated in the
    // space of the object the interior belongs to (world for the atmosphere).
    std::vector<std::shared_ptr<const Pigment>> densities;
    // Sampling, POV's method 3 (adaptive) unless `method 1`/`method 2`.
    int method = 3;
    int intervals = 1;
    int samples_min = 10;
    int samples_max = 10;
    double confidence = 0.9;
    double variance = 1.0 / 128.0;
    double ratio = 0.9;
    int aa_level = 3;
    double aa_threshold = 0.1;
    double jitter = 0.0;
    SourceLocation location;
};

}  // namespace lancer::sg
