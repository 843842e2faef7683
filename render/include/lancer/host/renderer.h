// The host's pixel loop: tiles over oneTBB, one sampler stream per
// (seed, pixel, sample), the integrator's radiance into the film, progress.
//
// Rendering runs in passes. Each pass adds samples to the pixels still
// active; a pixel's k-th sample always comes from
// sampler.start_sample(x, y, k), so the film depends only on how many
// samples each pixel took, never on the pass schedule, thread count or tile
// order. Three ways to decide how many (docs/rendering.md):
//   fixed:    every pixel gets samples_per_pixel;
//   budget:   time_budget_seconds > 0, passes until the budget is spent;
//   adaptive: noise_target > 0, a pixel stops when its estimated relative
//             error falls under the target (both may be combined).
#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>

#include "lancer/host/film.h"
#include "lancer/integrator.h"
#include "lancer/render_scene.h"

namespace lancer {

enum class ProgressMode { Auto, Bar, Lines, Quiet };  // Auto: bar on a terminal, lines otherwise

// One render as a part of a longer job (an animation's frames), so the
// progress shown counts the whole job and its ETA is the job's.
struct ProgressShare {
    int part = 0;                 // 0-based
    int parts = 1;                // 1: the render is the whole job
    double seconds_before = 0.0;  // spent on the earlier parts
    std::string label;            // e.g. "frame 3": shown beside the percentage
};

struct CropWindow {
    int x0, y0, x1, y1;  // pixel rectangle [x0, x1) x [y0, y1)
};

struct RenderStats;
class CountingScene;

struct RenderOptions {
    int width = 640;
    int height = 480;
    // Fixed mode: every pixel is brought to this many samples (a film that
    // already holds samples, e.g. resumed from a checkpoint, is continued).
    int samples_per_pixel = 1;
    // Budget and adaptive modes: per-pixel cap; 0 means none for a time
    // budget and kDefaultAdaptiveCap for a noise target alone.
    int max_samples_per_pixel = 0;
    // > 0: render passes until this many seconds after render_image starts;
    // the pass size comes from the measured cost of earlier passes.
    double time_budget_seconds = 0.0;
    // > 0: per-pixel relative error target (see estimate.h for the
    // estimator); a pixel takes at least min_samples before it may stop.
    double noise_target = 0.0;
    int min_samples = 16;
    std::uint64_t seed = 0;
    int threads = 0;  // 0: every core
    std::optional<CropWindow> crop;
    ProgressMode progress = ProgressMode::Auto;
    ProgressShare progress_share;
    int tile_size = 16;
    // Called between passes, from the calling thread, with a consistent
    // film, at most every checkpoint_interval_seconds (0: never).
    double checkpoint_interval_seconds = 0.0;
    std::function<void(const Film&)> on_checkpoint;
    // Called after every pass, from the calling thread, with the film as it
    // stands and the fraction of the render done (a live preview shows it).
    std::function<void(const Film&, double)> on_pass;
    // Called as tiles finish, from any worker thread, with the fraction of
    // the render done: must be cheap and thread-safe.
    std::function<void(double)> on_progress;
    // When it becomes true (e.g. from a signal handler) the render abandons
    // its remaining pixels quickly and returns with stats.interrupted set.
    const std::atomic<bool>* cancel = nullptr;
    // The counting wrapper the scene is rendered through, if any: its count
    // over the call becomes stats.rays. Pass the same object as the scene.
    const CountingScene* ray_counter = nullptr;
};

inline constexpr int kDefaultAdaptiveCap = 4096;

struct RenderStats {
    double seconds = 0.0;                 // wall time of render_image
    std::uint64_t samples = 0;            // samples taken by this call
    std::uint64_t nonfinite_samples = 0;  // of those, NaN or infinite (dropped)
    // Ray queries (intersect + occluded) counted by options.ray_counter
    // (counting_scene.h), else 0.
    std::uint64_t rays = 0;
    double rays_per_second = 0.0;
    // Samples per pixel over the render window, including any the film
    // held before the call.
    double mean_samples_per_pixel = 0.0;
    std::uint32_t min_samples_per_pixel = 0;
    std::uint32_t max_samples_per_pixel = 0;
    int passes = 0;
    // Estimated relative RMSE of the window (estimate.h); 0 for a
    // deterministic integrator, and for a film that keeps no variance
    // (Film::Storage::Sums or MeanOnly).
    double estimated_rel_rmse = 0.0;
    bool interrupted = false;  // options.cancel stopped the render
};

// The most samples a pixel sums in float (Film::Storage::Sums): samples all
// alike then drift by up to about 4e-5 of their value.
inline constexpr int kMostFloatSummedSamples = 4096;

// The film storage a render needs: MeanOnly when no pixel takes more than
// one sample (fixed at 1 sample, no focal blur), which then needs no
// variance; Totals when something reads the variance (a time budget or a
// noise target, a deterministic integrator's focal-blur confidence, or the
// caller's wish for a Monte Carlo integrator's error estimate,
// RenderStats::estimated_rel_rmse) or a pixel takes more than
// kMostFloatSummedSamples; Sums otherwise (a fixed sample count).
Film::Storage film_storage_for(const RenderScene& scene, const Integrator& integrator, const RenderOptions& options,
                               bool error_estimate_wanted = false);

// Renders into `film` (of size width x height). Deterministic: the same
// per-pixel sample counts give the same film bit for bit whatever the
// thread count, tile size or pass schedule. A film whose storage keeps less
// than the render reads (film_storage_for) changes to that storage first.
RenderStats render_image(const RenderScene& scene, const Integrator& integrator, const RenderOptions& options,
                         Film& film);

}  // namespace lancer
