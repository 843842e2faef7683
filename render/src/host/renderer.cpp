// The host's pixel loop: passes over tiles on oneTBB, deterministic
// per-sample sampler streams, a per-pass plan of how many samples each pixel
// still takes (fixed count, time budget or noise target), progress on
// stderr.
#include "lancer/host/renderer.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <mutex>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include "lancer/host/counting_scene.h"
#include "lancer/host/estimate.h"

#include "host/pass_planner.h"
#include "host/progress.h"

namespace lancer {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

CropWindow clamped_window(const RenderOptions& options, int width, int height) {
    CropWindow window{0, 0, width, height};
    if (options.crop) window = *options.crop;
    window.x0 = std::clamp(window.x0, 0, width);
    window.x1 = std::clamp(window.x1, window.x0, width);
    window.y0 = std::clamp(window.y0, 0, height);
    window.y1 = std::clamp(window.y1, window.y0, height);
    return window;
}

struct CameraSample {
    int x = 0, y = 0;
    std::uint32_t index = 0;  // among the pixel's samples: selects its stream
};

// Camera samples waiting to be traced together, added in 4x4 blocks of
// pixels: a 16x16 tile at one sample each fills it. Long batches let
// RenderScene::intersect_batch overlap one packet's memory accesses with
// the next packet's tracing, and the rays are generated all at once
// (Camera::generate_rays) from the film points. It positions each sample's
// random stream when the integrator asks for it: a sample's stream starts
// at (pixel, index) and, when the host jittered the film point, continues
// past that draw.
struct CameraBatch final : CameraSampleStreams {
    static constexpr int kBlock = 4;
    static constexpr int kCapacity = 16 * kBlock * kBlock;
    CameraSample samples[kCapacity];
    float film_x[kCapacity], film_y[kCapacity];
    Ray rays[kCapacity];
    Hit hits[kCapacity];
    bool found[kCapacity];
    Color radiance[kCapacity];
    int size = 0;
    Sampler* sampler = nullptr;
    bool jittered = false;

    void add(int x, int y, std::uint32_t index, const Vec2& film_point) {
        samples[size] = CameraSample{x, y, index};
        film_x[size] = film_point.x;
        film_y[size] = film_point.y;
        ++size;
    }
    bool full() const { return size == kCapacity; }

    Sampler& stream(int i) const override {
        sampler->start_sample(samples[i].x, samples[i].y, samples[i].index);
        if (jittered) sampler->next_2d();
        return *sampler;
    }
};
}  // namespace

RenderStats render_image(const RenderScene& scene, const Integrator& integrator, const RenderOptions& options,
                         Film& film) {
    const auto start = Clock::now();
    const int width = film.width(), height = film.height();
    const CropWindow window = clamped_window(options, width, height);
    const int tile = std::max(options.tile_size, 1);
    const int tiles_x = (window.x1 - window.x0 + tile - 1) / tile;
    const int tiles_y = (window.y1 - window.y0 + tile - 1) / tile;
    const int tiles = tiles_x * tiles_y;
    const std::uint64_t window_pixels = std::uint64_t(window.x1 - window.x0) * std::uint64_t(window.y1 - window.y0);
    const bool deterministic = integrator.is_deterministic();
    PassPlanner planner(options, deterministic, window);
    // One sample of a deterministic integrator goes through the pixel centre
    // (POV-Ray's picture without antialiasing); more samples, of any
    // integrator, spread over the pixel and antialias.
    const bool pixel_centre = deterministic && planner.cap() == 1;
    const Camera& camera = scene.camera();
    const CountingScene* counting = options.ray_counter;
    const std::uint64_t rays_before = counting ? counting->rays() : 0;

    const std::unique_ptr<Sampler> prototype = integrator.make_sampler(options.seed);
    tbb::enumerable_thread_specific<std::unique_ptr<Sampler>> samplers([&] { return prototype->clone(); });
    const std::uint64_t nonfinite_before = film.nonfinite_samples();
    Progress progress(options.progress);

    // Budget mode stops at the deadline even mid-pass; the planner keeps
    // passes short enough that this is only a backstop.
    const bool has_deadline = planner.mode() == PassMode::Budget ||
                              (planner.mode() == PassMode::Adaptive && options.time_budget_seconds > 0.0);
    const auto deadline = start + std::chrono::duration_cast<Clock::duration>(
                                      std::chrono::duration<double>(std::max(options.time_budget_seconds, 0.0)));
    std::atomic<bool> stop{false};
    auto should_stop = [&] {
        if (stop.load(std::memory_order_relaxed)) return true;
        if ((options.cancel && options.cancel->load(std::memory_order_relaxed)) ||
            (has_deadline && Clock::now() >= deadline)) {
            stop.store(true, std::memory_order_relaxed);
            return true;
        }
        return false;
    };

    // Progress: samples against the fixed total, else time against the
    // budget, else (adaptive alone) the share of pixels that stopped.
    std::atomic<std::uint64_t> samples_taken{0};
    std::uint64_t already_taken = 0;  // e.g. resumed from a checkpoint; set by the first plan
    const double fixed_total = double(window_pixels) * planner.cap();
    auto fraction_done = [&](double stopped_pixels_fraction) {
        if (planner.mode() == PassMode::Fixed)
            return fixed_total > 0 ? double(already_taken + samples_taken) / fixed_total : 1.0;
        if (has_deadline) return seconds_since(start) / options.time_budget_seconds;
        return stopped_pixels_fraction;
    };
    double stopped_fraction = 0.0;

    // Camera rays are traced in batches of neighbouring pixels (4x4 blocks
    // of the tile), which Embree traverses together.
    // One batch per thread for the whole render: its 41 KB of rays and hits
    // are initialised once, not once per tile.
    tbb::enumerable_thread_specific<std::unique_ptr<CameraBatch>> batches(
        [] { return std::make_unique<CameraBatch>(); });
    auto render_tile = [&](int tile_index) {
        Sampler& sampler = *samplers.local();
        const int tx = tile_index % tiles_x, ty = tile_index / tiles_x;
        const int x_begin = window.x0 + tx * tile, y_begin = window.y0 + ty * tile;
        const int x_end = std::min(x_begin + tile, window.x1), y_end = std::min(y_begin + tile, window.y1);
        std::uint64_t taken = 0;
        // The k-th sample of a pixel always uses stream k.
        auto film_point = [&](int x, int y, std::uint32_t s) {
            if (pixel_centre) return Vec2(float(x) + 0.5f, float(y) + 0.5f);
            sampler.start_sample(x, y, s);
            const Vec2 jitter = sampler.next_2d();
            return Vec2(float(x) + jitter.x, float(y) + jitter.y);
        };
        CameraBatch& batch = *batches.local();
        batch.size = 0;
        batch.sampler = &sampler;
        batch.jittered = !pixel_centre;
        auto shade_batch = [&] {
            if (batch.size == 0) return;
            camera.generate_rays(batch.film_x, batch.film_y, batch.size, width, height, batch.rays);
            scene.intersect_batch(batch.rays, batch.size, batch.hits, batch.found, RayCoherence::Coherent);
            const CameraHits traced(batch.size, batch.rays, batch.hits, batch.found, batch);
            integrator.shade_camera_hits(traced, scene, batch.radiance);
            for (int i = 0; i < batch.size; ++i)
                film.add_sample(batch.samples[i].x, batch.samples[i].y, batch.radiance[i]);
            batch.size = 0;
        };
        constexpr int kBlock = CameraBatch::kBlock;
        for (int block_y = y_begin; block_y < y_end; block_y += kBlock)
            for (int block_x = x_begin; block_x < x_end; block_x += kBlock) {
                if (should_stop()) {
                    shade_batch();
                    samples_taken += taken;
                    return;
                }
                for (int y = block_y; y < std::min(block_y + kBlock, y_end); ++y)
                    for (int x = block_x; x < std::min(block_x + kBlock, x_end); ++x) {
                        const std::uint32_t first = film.samples_taken(x, y);
                        const std::uint32_t count = planner.planned(x - window.x0, y - window.y0, first);
                        for (std::uint32_t s = first; s < first + count; ++s) {
                            const Vec2 point = film_point(x, y, s);
                            film.prefetch(x, y);
                            batch.add(x, y, s, point);
                            if (batch.full()) shade_batch();
                        }
                        taken += count;
                    }
            }
        shade_batch();
        samples_taken += taken;
        progress.report(fraction_done(stopped_fraction));
    };

    RenderStats stats;
    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    double seconds_per_sample = 0.0;  // measured on the last pass
    auto last_checkpoint = start;
    arena.execute([&] {
        while (!should_stop()) {
            // Plan the pass; under a time budget, only what fits in 90% of
            // the time left at the last pass's cost per sample.
            std::uint64_t planned = planner.plan_unlimited(film);
            if (stats.passes == 0) already_taken = planner.taken_at_plan();
            if (planned == 0) break;
            if (has_deadline && seconds_per_sample > 0.0) {
                const double remaining = std::chrono::duration<double>(deadline - Clock::now()).count();
                const double affordable = 0.9 * remaining / seconds_per_sample;
                // A pass for a sliver of the pixels costs more in overhead
                // than it refines.
                if (affordable < double(planner.pixels_wanting()) / 32.0) break;
                planned = planner.limit_to(std::uint64_t(affordable));
                if (planned == 0) break;
            }
            // A fixed render that checkpoints keeps passes within the
            // interval, so a kill loses at most about that much work.
            if (planner.mode() == PassMode::Fixed && options.checkpoint_interval_seconds > 0.0 &&
                seconds_per_sample > 0.0) {
                const double affordable = options.checkpoint_interval_seconds / seconds_per_sample;
                planned = planner.limit_to(std::max(std::uint64_t(affordable), planner.pixels_wanting()));
            }
            stopped_fraction = 1.0 - double(planner.pixels_wanting()) / double(std::max<std::uint64_t>(window_pixels, 1));

            // Render it.
            const auto pass_start = Clock::now();
            const std::uint64_t before = samples_taken;
            tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& range) {
                for (int t = range.begin(); t != range.end(); ++t) render_tile(t);
            });
            ++stats.passes;
            const std::uint64_t done = samples_taken - before;
            if (done > 0) seconds_per_sample = seconds_since(pass_start) / double(done);
            const bool finished = done == planned && planner.plan_completes();

            // Checkpoint between passes, when the film is consistent.
            if (options.on_checkpoint && options.checkpoint_interval_seconds > 0.0 && !stop &&
                seconds_since(last_checkpoint) >= options.checkpoint_interval_seconds) {
                options.on_checkpoint(film);
                last_checkpoint = Clock::now();
            }
            if (finished) break;
        }
    });
    progress.report(1.0);
    progress.finish();

    // What the render did.
    stats.seconds = seconds_since(start);
    stats.samples = samples_taken;
    stats.nonfinite_samples = film.nonfinite_samples() - nonfinite_before;
    stats.interrupted = options.cancel && options.cancel->load();
    if (counting) stats.rays = counting->rays() - rays_before;
    stats.rays_per_second = stats.seconds > 0.0 ? double(stats.rays) / stats.seconds : 0.0;
    struct Counts {
        std::uint64_t sum = 0;
        std::uint32_t least = std::numeric_limits<std::uint32_t>::max(), most = 0;
    };
    const Counts counts = arena.execute([&] { return tbb::parallel_reduce(
        tbb::blocked_range<int>(window.y0, window.y1), Counts{},
        [&](const tbb::blocked_range<int>& rows, Counts c) {
            for (int y = rows.begin(); y < rows.end(); ++y)
                for (int x = window.x0; x < window.x1; ++x) {
                    const std::uint32_t taken = film.samples_taken(x, y);
                    c.sum += taken;
                    c.least = std::min(c.least, taken);
                    c.most = std::max(c.most, taken);
                }
            return c;
        },
        [](Counts a, const Counts& b) {
            a.sum += b.sum;
            a.least = std::min(a.least, b.least);
            a.most = std::max(a.most, b.most);
            return a;
        }); });
    const std::uint64_t sum = counts.sum;
    const std::uint32_t least = counts.least, most = counts.most;
    stats.mean_samples_per_pixel = window_pixels > 0 ? double(sum) / double(window_pixels) : 0.0;
    stats.min_samples_per_pixel = window_pixels > 0 ? least : 0;
    stats.max_samples_per_pixel = most;
    if (!deterministic && window_pixels > 0)
        stats.estimated_rel_rmse =
            estimated_relative_rmse(film, PixelWindow{window.x0, window.y0, window.x1, window.y1});
    return stats;
}

}  // namespace lancer
