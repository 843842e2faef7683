// Random numbers for one pixel sample. A sampler's output depends only on
// (seed, pixel, sample index, dimension), never on threads or tile order, so
// renders are reproducible bit for bit.
#pragma once

#include <cstdint>
#include <memory>

#include "lancer/ray.h"

namespace lancer {

class Sampler {
  public:
    virtual ~Sampler() = default;
    // Position the sampler at one sample of one pixel; resets the dimension.
    virtual void start_sample(int pixel_x, int pixel_y, std::uint32_t sample_index) = 0;
    // Next value in [0, 1) and next pair in [0, 1)^2.
    virtual float next_1d() = 0;
    virtual Vec2 next_2d() = 0;
    virtual std::unique_ptr<Sampler> clone() const = 0;
};

// Independent uniform samples from a counter-based hash of
// (seed, pixel, sample, dimension).
std::unique_ptr<Sampler> make_independent_sampler(std::uint64_t seed);

// Owen-scrambled Sobol points (Joe–Kuo direction numbers), one independent
// scramble per (seed, pixel, dimension); the sample index runs through the
// sequence, so a pixel's first 2^k samples are stratified in every 2D
// projection of the table. Dimensions beyond the table fall back to hashed
// independent values. Best with power-of-two sample counts.
std::unique_ptr<Sampler> make_sobol_sampler(std::uint64_t seed);

}  // namespace lancer
