// POV-Ray 3.7's solid noise, recovered by measuring POV-Ray itself
// (scripts/measure-pov-noise.sh; docs/noise.md says how): the scalar
// noise behind bozo, granite, agate, wrinkles ..., the vector noise behind
// turbulence and bumps, and their fractal sums (internal to liblancer).
//
// All four agree with Debian's povray 3.7.0.10 to the digits it prints
// (generator 3 to ~1e-14); materials/noise_test.cpp checks them against
// POV's own output.
#pragma once

#include <glm/glm.hpp>

namespace lancer {

// POV's noise_generator values (global_settings' default, and so f_noise3d's,
// is 2). 1 and 2 share one lattice noise and differ only in how its sum is
// mapped to [0, 1]; 3 is a different, gradient-only lattice noise (POV calls
// it Perlin noise; it is not Perlin's 2002 "improved noise").
enum class NoiseGenerator { Original = 1, RangeCorrected = 2, Perlin = 3 };

// POV's Noise(): a value in [0, 1] at p, the very value f_noise_generator(x,
// y, z, generator) returns (bozo, spotted and bumps are this value).
//   1: the lattice sum + 0.5, clamped (the sum rarely leaves [-0.5, 0.5]);
//   2: (sum + 1.05242) * 0.48985582, clamped (stretched to fill [0, 1]);
//   3: 0.4925 at the corners of its lattice, in about [0, 1], clamped.
double pov_noise(const glm::dvec3& p, NoiseGenerator generator);

// POV's DNoise(): a vector noise at p, each component centred on 0 (about
// [-1, 1]); its x component is generator 1's lattice sum (noise - 0.5,
// unclamped). POV's DNoise has no generator: the argument is ignored, and
// turbulence warps, bumps and wood displace points the same way whatever
// noise_generator says.
glm::dvec3 pov_dnoise(const glm::dvec3& p, NoiseGenerator generator);

// POV's Turbulence(), the scalar fractal sum that classic turbulence feeds
// marble (x + turbulence.x * this), agate, iridescence and fog:
//   sum over octaves i = 0 .. octaves-1 of omega^i * n(lambda^i p),
// where n is pov_noise for generator 1 and 2 * pov_noise - 0.5 for 2 and 3
// (only the first octave's n is clamped to [0, 1] then). octaves: how many
// terms; omega: each term's amplitude relative to the one before; lambda:
// each term's frequency relative to the one before. POV's defaults: octaves
// 6, omega 0.5, lambda 2.0. Like POV, omega and lambda are rounded to single
// precision first.
double pov_turbulence(const glm::dvec3& p, double omega, double lambda, int octaves, NoiseGenerator generator);

// POV's DTurbulence(): sum over octaves i of omega^i * pov_dnoise(lambda^i p)
// (same parameters and defaults as above; SDL's vturbulence(lambda, omega,
// octaves, p)). A turbulence warp moves the point by this times the
// turbulence vector, component by component. generator is ignored, as in
// pov_dnoise.
glm::dvec3 pov_dturbulence(const glm::dvec3& p, double omega, double lambda, int octaves, NoiseGenerator generator);

}  // namespace lancer
