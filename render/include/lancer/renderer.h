// The host's pixel loop: tiles over oneTBB, one sampler stream per
// (seed, pixel, sample), the integrator's radiance into the film, progress.
#pragma once

#include <cstdint>
#include <optional>

#include "lancer/film.h"
#include "lancer/integrator.h"
#include "lancer/render_scene.h"

namespace lancer {

enum class ProgressMode { Auto, Bar, Lines, Quiet };  // Auto: bar on a terminal, lines otherwise

struct CropWindow {
    int x0, y0, x1, y1;  // pixel rectangle [x0, x1) x [y0, y1)
};

struct RenderOptions {
    int width = 640;
    int height = 480;
    int samples_per_pixel = 1;
    std::uint64_t seed = 0;
    int threads = 0;  // 0: every core
    std::optional<CropWindow> crop;
    ProgressMode progress = ProgressMode::Auto;
    int tile_size = 16;
};

struct RenderStats {
    double seconds = 0.0;
    std::uint64_t samples = 0;
    std::uint64_t nonfinite_samples = 0;
};

// Renders into `film` (of size width x height). Deterministic: the same
// options give the same film bit for bit whatever the thread count.
RenderStats render_image(const RenderScene& scene, const Integrator& integrator,
                         const RenderOptions& options, Film& film);

}  // namespace lancer
