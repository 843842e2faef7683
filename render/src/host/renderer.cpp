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
#include <optional>
#include <stdexcept>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/parallel_reduce.h>
#include <tbb/task_arena.h>

#include "lancer/host/counting_scene.h"
#include "lancer/host/estimate.h"

#include "host/aperture_samples.h"
#include "host/pass_planner.h"
#include "host/progress.h"

namespace lancer {
namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

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
    std::uint32_t index = 0;  // among the pixel's camera rays: selects its stream
};

// Camera samples waiting to be traced together, added in 4x4 blocks of
// pixels: a 16x16 tile at one sample each fills it. Long batches let
// RenderScene::intersect_batch overlap one packet's memory accesses with
// the next packet's tracing, and the rays are generated all at once
// (Camera::generate_rays) from the film and lens points. It positions each
// sample's random stream when the integrator asks for it: a sample's stream
// starts at (pixel, index) and continues past the host's own draws (the
// film point's jitter, the lens point). A mesh camera averages several rays
// per film sample (Camera::rays_per_pixel): they sit side by side, in
// groups that a batch never splits.
struct CameraBatch final : CameraSampleStreams {
    static constexpr int kBlock = 4;
    static constexpr int kCapacity = 16 * kBlock * kBlock;
    CameraSample samples[kCapacity];
    float film_x[kCapacity], film_y[kCapacity];
    Vec2 lens[kCapacity];
    int ray_number[kCapacity];
    Ray rays[kCapacity];
    bool sees[kCapacity];
    // Where each ray added went after the untraced ones were dropped (-1:
    // untraced), and the film pixel of each, in the order added.
    int slot[kCapacity];
    int pixel_x[kCapacity], pixel_y[kCapacity];
    Hit hits[kCapacity];
    bool found[kCapacity];
    Color radiance[kCapacity];
    int size = 0;
    Sampler* sampler = nullptr;
    bool jittered = false;
    bool lens_sampled = false;

    void add(int x, int y, std::uint32_t index, const Vec2& film_point, const Vec2& lens_point, int ray = 0) {
        samples[size] = CameraSample{x, y, index};
        film_x[size] = film_point.x;
        film_y[size] = film_point.y;
        lens[size] = lens_point;
        ray_number[size] = ray;
        pixel_x[size] = x;
        pixel_y[size] = y;
        ++size;
    }
    // Whether another group of `rays` fits.
    bool full(int rays = 1) const { return size + rays > kCapacity; }
    // Sample `from` moves to place `to` (to <= from), ray included.
    void move(int from, int to) {
        samples[to] = samples[from];
        film_x[to] = film_x[from];
        film_y[to] = film_y[from];
        lens[to] = lens[from];
        rays[to] = rays[from];
    }

    Sampler& stream(int i) const override {
        sampler->start_sample(samples[i].x, samples[i].y, samples[i].index);
        if (jittered) sampler->next_2d();
        if (lens_sampled) sampler->next_2d();
        return *sampler;
    }
};

// A camera with focal blur takes at least its blur_samples per pixel, as
// POV-Ray traces them, when the count is fixed.
RenderOptions with_focal_blur_samples(RenderOptions options, const Camera& camera) {
    if (camera.has_focal_blur() && options.time_budget_seconds <= 0.0 && options.noise_target <= 0.0)
        options.samples_per_pixel = std::max(options.samples_per_pixel, camera.focal_blur().samples);
    return options;
}
// POV-Ray's confidence test for a focal-blurred render of a deterministic
// integrator whose sample count is the scene's blur_samples (a larger
// --spp, a time budget or a noise target asks for something else). `path`
// and the other Monte Carlo integrators always take every sample: a stop
// decided by the samples themselves would bias them.
std::optional<FocalBlurConfidence> focal_blur_confidence(const RenderOptions& options, const Camera& camera,
                                                         bool deterministic) {
    if (!deterministic || !camera.has_focal_blur() || options.time_budget_seconds > 0.0 || options.noise_target > 0.0 ||
        options.samples_per_pixel > camera.focal_blur().samples)
        return std::nullopt;
    return FocalBlurConfidence(camera.focal_blur(), std::uint32_t(camera.focal_blur().samples),
                               camera.bokeh() != nullptr);
}

// Samples per pixel over a window: their sum, least and most.
struct SampleCounts {
    std::uint64_t sum = 0;
    std::uint32_t least = std::numeric_limits<std::uint32_t>::max(), most = 0;
};

SampleCounts count_samples(const Film& film, const CropWindow& window) {
    return tbb::parallel_reduce(
        tbb::blocked_range<int>(window.y0, window.y1), SampleCounts{},
        [&](const tbb::blocked_range<int>& rows, SampleCounts c) {
            for (int y = rows.begin(); y < rows.end(); ++y)
                for (int x = window.x0; x < window.x1; ++x) {
                    const std::uint32_t taken = film.samples_taken(x, y);
                    c.sum += taken;
                    c.least = std::min(c.least, taken);
                    c.most = std::max(c.most, taken);
                }
            return c;
        },
        [](SampleCounts a, const SampleCounts& b) {
            a.sum += b.sum;
            a.least = std::min(a.least, b.least);
            a.most = std::max(a.most, b.most);
            return a;
        });
}

// One call of render_image: the passes, each a parallel sweep of the
// window's tiles, and what the render did.
class ImageRender {
  public:
    ImageRender(const RenderScene& scene, const Integrator& integrator, const RenderOptions& options, Film& film)
        : m_scene(scene),
          m_integrator(integrator),
          m_options(with_focal_blur_samples(options, scene.camera())),
          m_film(film),
          m_start(Clock::now()),
          m_window(clamped_window(options, film.width(), film.height())),
          m_tile(std::max(options.tile_size, 1)),
          m_tiles_x((m_window.x1 - m_window.x0 + m_tile - 1) / m_tile),
          m_tiles((m_window.y1 - m_window.y0 + m_tile - 1) / m_tile * m_tiles_x),
          m_window_pixels(std::uint64_t(m_window.x1 - m_window.x0) * std::uint64_t(m_window.y1 - m_window.y0)),
          m_confidence(focal_blur_confidence(options, scene.camera(), integrator.is_deterministic())),
          m_planner(m_options, integrator.is_deterministic(), m_window, m_confidence ? &*m_confidence : nullptr),
          // One sample of a deterministic integrator goes through the pixel
          // centre (POV-Ray's picture without antialiasing); more samples,
          // of any integrator, spread over the pixel and antialias.
          m_pixel_centre(integrator.is_deterministic() && m_planner.cap() == 1),
          m_lens_sampled(scene.camera().has_focal_blur()),
          m_rays_per_pixel(std::clamp(scene.camera().rays_per_pixel(), 1, CameraBatch::kCapacity)),
          m_aperture(scene.camera().focal_blur().samples, integrator.is_deterministic(), scene.camera().bokeh()),
          m_prototype(integrator.make_sampler(options.seed)),
          m_samplers([this] { return m_prototype->clone(); }),
          // One batch per thread for the whole render: its 41 KB of rays
          // and hits are initialised once, not once per tile.
          m_batches([] { return std::make_unique<CameraBatch>(); }),
          m_progress(options.progress, options.progress_share),
          // Budget mode stops at the deadline even mid-pass; the planner
          // keeps passes short enough that this is only a backstop.
          m_has_deadline(m_planner.mode() == PassMode::Budget ||
                         (m_planner.mode() == PassMode::Adaptive && m_options.time_budget_seconds > 0.0)),
          m_deadline(m_start + std::chrono::duration_cast<Clock::duration>(
                                   std::chrono::duration<double>(std::max(m_options.time_budget_seconds, 0.0)))) {}

    RenderStats run() {
        const CountingScene* counting = m_options.ray_counter;
        const std::uint64_t rays_before = counting ? counting->rays() : 0;
        const std::uint64_t nonfinite_before = m_film.nonfinite_samples();
        tbb::task_arena arena(m_options.threads > 0 ? m_options.threads : tbb::task_arena::automatic);
        RenderStats stats;
        arena.execute([&] { stats.passes = run_passes(); });
        const bool interrupted = m_options.cancel && m_options.cancel->load();
        if (!interrupted) m_progress.report(1.0);
        m_progress.finish(interrupted);

        stats.seconds = seconds_since(m_start);
        stats.samples = m_samples_taken;
        stats.nonfinite_samples = m_film.nonfinite_samples() - nonfinite_before;
        stats.interrupted = interrupted;
        if (counting) stats.rays = counting->rays() - rays_before;
        stats.rays_per_second = stats.seconds > 0.0 ? double(stats.rays) / stats.seconds : 0.0;
        const SampleCounts counts = arena.execute([&] { return count_samples(m_film, m_window); });
        stats.mean_samples_per_pixel = m_window_pixels > 0 ? double(counts.sum) / double(m_window_pixels) : 0.0;
        stats.min_samples_per_pixel = m_window_pixels > 0 ? counts.least : 0;
        stats.max_samples_per_pixel = counts.most;
        if (!m_integrator.is_deterministic() && m_window_pixels > 0)
            stats.estimated_rel_rmse =
                estimated_relative_rmse(m_film, PixelWindow{m_window.x0, m_window.y0, m_window.x1, m_window.y1});
        return stats;
    }

  private:
    // Passes until the plan is done, the deadline passes or the render is
    // cancelled; returns how many ran.
    int run_passes() {
        int passes = 0;
        double seconds_per_sample = 0.0;  // measured on the last pass
        auto last_checkpoint = m_start;
        while (!should_stop()) {
            const std::uint64_t planned = plan_pass(passes, seconds_per_sample);
            if (planned == 0) break;

            const auto pass_start = Clock::now();
            const std::uint64_t before = m_samples_taken;
            tbb::parallel_for(tbb::blocked_range<int>(0, m_tiles, 1), [&](const tbb::blocked_range<int>& range) {
                for (int t = range.begin(); t != range.end(); ++t) render_tile(t);
            });
            ++passes;
            const std::uint64_t done = m_samples_taken - before;
            if (done > 0) seconds_per_sample = seconds_since(pass_start) / double(done);
            const bool finished = done == planned && m_planner.plan_completes();

            // Checkpoint between passes, when the film is consistent.
            if (m_options.on_checkpoint && m_options.checkpoint_interval_seconds > 0.0 && !m_stop &&
                seconds_since(last_checkpoint) >= m_options.checkpoint_interval_seconds) {
                m_options.on_checkpoint(m_film);
                last_checkpoint = Clock::now();
            }
            if (m_options.on_pass) m_options.on_pass(m_film, finished ? 1.0 : fraction_done());
            if (finished) break;
        }
        return passes;
    }

    // Plans the next pass and returns its samples (0: none is worth
    // running). Under a time budget, only what fits in 90% of the time left
    // at the last pass's cost per sample.
    std::uint64_t plan_pass(int passes_so_far, double seconds_per_sample) {
        std::uint64_t planned = m_planner.plan_unlimited(m_film);
        if (passes_so_far == 0) m_already_taken = m_planner.taken_at_plan();
        if (planned == 0) return 0;
        if (m_has_deadline && seconds_per_sample > 0.0) {
            const double remaining = std::chrono::duration<double>(m_deadline - Clock::now()).count();
            const double affordable = 0.9 * remaining / seconds_per_sample;
            // A pass for a sliver of the pixels costs more in overhead than
            // it refines.
            if (affordable < double(m_planner.pixels_wanting()) / 32.0) return 0;
            planned = m_planner.limit_to(std::uint64_t(affordable));
            if (planned == 0) return 0;
        }
        // A fixed render that checkpoints keeps passes within the interval,
        // so a kill loses at most about that much work.
        if ((m_planner.mode() == PassMode::Fixed || m_planner.mode() == PassMode::Confidence) &&
            m_options.checkpoint_interval_seconds > 0.0 && seconds_per_sample > 0.0) {
            const double affordable = m_options.checkpoint_interval_seconds / seconds_per_sample;
            planned = m_planner.limit_to(std::max(std::uint64_t(affordable), m_planner.pixels_wanting()));
        }
        return planned;
    }

    bool should_stop() {
        if (m_stop.load(std::memory_order_relaxed)) return true;
        if ((m_options.cancel && m_options.cancel->load(std::memory_order_relaxed)) ||
            (m_has_deadline && Clock::now() >= m_deadline)) {
            m_stop.store(true, std::memory_order_relaxed);
            return true;
        }
        return false;
    }

    // Progress: samples against the fixed total; under a noise target,
    // samples against the total the planner predicts from the error each
    // pixel shows (the share of pixels that stopped runs ahead: the last
    // ones take most of the samples); under a time budget, at least the
    // time spent against it.
    double fraction_done() const {
        const double taken = double(m_already_taken + m_samples_taken);
        if (m_planner.mode() == PassMode::Fixed) {
            const double fixed_total = double(m_window_pixels) * m_planner.cap();
            return fixed_total > 0 ? taken / fixed_total : 1.0;
        }
        double fraction = 0.0;
        if ((m_planner.mode() == PassMode::Adaptive || m_planner.mode() == PassMode::Confidence) &&
            m_planner.predicted_total() > 0)
            fraction = taken / double(m_planner.predicted_total());
        if (m_has_deadline) fraction = std::max(fraction, seconds_since(m_start) / m_options.time_budget_seconds);
        return fraction;
    }

    // The k-th sample of a pixel always uses stream k: its film point, then
    // with focal blur its lens point. A mesh camera's n rays of sample k
    // use streams n k to n k + n - 1, all at sample k's film point.
    void add_sample(CameraBatch& batch, Sampler& sampler, int x, int y, std::uint32_t s) const {
        if (m_rays_per_pixel > 1) {
            const std::uint32_t first = s * std::uint32_t(m_rays_per_pixel);
            Vec2 film(float(x) + 0.5f, float(y) + 0.5f);
            if (!m_pixel_centre) {
                sampler.start_sample(x, y, first);
                const Vec2 jitter = sampler.next_2d();
                film = Vec2(float(x) + jitter.x, float(y) + jitter.y);
            }
            for (int r = 0; r < m_rays_per_pixel; ++r) batch.add(x, y, first + std::uint32_t(r), film, Vec2(0.0f), r);
            return;
        }
        if (m_pixel_centre && !m_lens_sampled) {
            batch.add(x, y, s, Vec2(float(x) + 0.5f, float(y) + 0.5f), Vec2(0.0f));
            return;
        }
        sampler.start_sample(x, y, s);
        Vec2 film(float(x) + 0.5f, float(y) + 0.5f);
        if (!m_pixel_centre) {
            const Vec2 jitter = sampler.next_2d();
            film = Vec2(float(x) + jitter.x, float(y) + jitter.y);
        }
        const Vec2 lens = m_lens_sampled ? m_aperture.point(s, sampler.next_2d()) : Vec2(0.0f);
        batch.add(x, y, s, film, lens);
    }

    // Camera rays for the batch's film points, their hits traced together,
    // shaded by the integrator, added to the film. A ray the camera cannot
    // make (outside a fisheye's circle) is not traced; as in POV-Ray, a
    // film sample is the mean of its group's traced rays (a group is one
    // ray but for a mesh camera), black if none was.
    void shade_batch(CameraBatch& batch) {
        if (batch.size == 0) return;
        const int added = batch.size;
        m_scene.camera().generate_rays(batch.film_x, batch.film_y, batch.lens, added, m_film.width(), m_film.height(),
                                       batch.rays, batch.sees, batch.ray_number);
        for (int i = 0; i < added; ++i) batch.rays[i].seen_as = RaySight::Image;
        int kept = 0;
        for (int i = 0; i < added; ++i) {
            if (!batch.sees[i]) {
                batch.slot[i] = -1;
                continue;
            }
            if (kept != i) batch.move(i, kept);
            batch.slot[i] = kept++;
        }
        batch.size = kept;
        if (kept > 0) {
            m_scene.intersect_batch(batch.rays, kept, batch.hits, batch.found, RayCoherence::Coherent);
            const CameraHits traced(kept, batch.rays, batch.hits, batch.found, batch);
            m_integrator.shade_camera_hits(traced, m_scene, batch.radiance);
        }
        for (int first = 0; first < added; first += m_rays_per_pixel) {
            Color sum(0.0f);
            int traced_rays = 0;
            for (int i = first; i < first + m_rays_per_pixel; ++i) {
                if (batch.slot[i] < 0) continue;
                sum += batch.radiance[batch.slot[i]];
                ++traced_rays;
            }
            if (traced_rays > 1) sum /= float(traced_rays);
            m_film.add_sample(batch.pixel_x[first], batch.pixel_y[first], sum);
        }
        batch.size = 0;
    }

    // This pass's samples of one tile, in 4x4 blocks of pixels (neighbours
    // in one batch), checking for a stop between blocks.
    void render_tile(int tile_index) {
        Sampler& sampler = *m_samplers.local();
        const int tx = tile_index % m_tiles_x, ty = tile_index / m_tiles_x;
        const int x_begin = m_window.x0 + tx * m_tile, y_begin = m_window.y0 + ty * m_tile;
        const int x_end = std::min(x_begin + m_tile, m_window.x1), y_end = std::min(y_begin + m_tile, m_window.y1);
        std::uint64_t taken = 0;
        CameraBatch& batch = *m_batches.local();
        batch.size = 0;
        batch.sampler = &sampler;
        batch.jittered = !m_pixel_centre;
        batch.lens_sampled = m_lens_sampled;
        constexpr int kBlock = CameraBatch::kBlock;
        for (int block_y = y_begin; block_y < y_end; block_y += kBlock)
            for (int block_x = x_begin; block_x < x_end; block_x += kBlock) {
                if (should_stop()) {
                    shade_batch(batch);
                    m_samples_taken += taken;
                    return;
                }
                for (int y = block_y; y < std::min(block_y + kBlock, y_end); ++y)
                    for (int x = block_x; x < std::min(block_x + kBlock, x_end); ++x) {
                        const std::uint32_t first = m_film.samples_taken(x, y);
                        const std::uint32_t count = m_planner.planned(x - m_window.x0, y - m_window.y0, first);
                        for (std::uint32_t s = first; s < first + count; ++s) {
                            if (batch.full(m_rays_per_pixel)) shade_batch(batch);
                            add_sample(batch, sampler, x, y, s);
                            m_film.prefetch(x, y);
                        }
                        taken += count;
                    }
            }
        shade_batch(batch);
        m_samples_taken += taken;
        const double fraction = fraction_done();
        m_progress.report(fraction);
        if (m_options.on_progress) m_options.on_progress(fraction);
    }

    const RenderScene& m_scene;
    const Integrator& m_integrator;
    const RenderOptions m_options;
    Film& m_film;
    const Clock::time_point m_start;
    const CropWindow m_window;
    const int m_tile, m_tiles_x, m_tiles;
    const std::uint64_t m_window_pixels;
    const std::optional<FocalBlurConfidence> m_confidence;
    PassPlanner m_planner;
    const bool m_pixel_centre;
    const bool m_lens_sampled;
    const int m_rays_per_pixel;  // camera rays per film sample
    const ApertureSamples m_aperture;
    const std::unique_ptr<Sampler> m_prototype;
    tbb::enumerable_thread_specific<std::unique_ptr<Sampler>> m_samplers;
    tbb::enumerable_thread_specific<std::unique_ptr<CameraBatch>> m_batches;
    Progress m_progress;
    const bool m_has_deadline;
    const Clock::time_point m_deadline;
    std::atomic<bool> m_stop{false};
    std::atomic<std::uint64_t> m_samples_taken{0};
    std::uint64_t m_already_taken = 0;  // e.g. resumed from a checkpoint; set by the first plan
};

}  // namespace

// At most one sample a pixel: a fixed count of 1 (a time budget or a noise
// target adds samples, except to a deterministic integrator, which ignores
// them) and no focal blur.
bool takes_one_sample(const RenderScene& scene, const Integrator& integrator, const RenderOptions& options) {
    const bool fixed =
        integrator.is_deterministic() || (options.time_budget_seconds <= 0.0 && options.noise_target <= 0.0);
    return fixed && !scene.camera().has_focal_blur() && options.samples_per_pixel <= 1;
}

Film::Storage film_storage_for(const RenderScene& scene, const Integrator& integrator, const RenderOptions& options,
                               bool error_estimate_wanted) {
    if (takes_one_sample(scene, integrator, options)) return Film::Storage::MeanOnly;
    // Adaptive modes and the confidence of a deterministic focal blur read
    // every pixel's variance; a deterministic integrator has no estimate.
    const bool deterministic = integrator.is_deterministic();
    const bool adaptive = !deterministic && (options.time_budget_seconds > 0.0 || options.noise_target > 0.0);
    const bool confidence = deterministic && scene.camera().has_focal_blur();
    const bool estimate = error_estimate_wanted && !deterministic;
    // Float sums of samples all alike drift by about n 1e-8 of their value:
    // past kMostFloatSummedSamples a pixel sums in double.
    int most = options.samples_per_pixel;
    if (scene.camera().has_focal_blur()) most = std::max(most, scene.camera().focal_blur().samples);
    const bool many = most > kMostFloatSummedSamples;
    return adaptive || confidence || estimate || many ? Film::Storage::Totals : Film::Storage::Sums;
}

RenderStats render_image(const RenderScene& scene, const Integrator& integrator, const RenderOptions& options,
                         Film& film) {
    // A film keeps at least what this render reads: MeanOnly < Sums < Totals.
    const auto rank = [](Film::Storage storage) {
        return storage == Film::Storage::MeanOnly ? 0 : storage == Film::Storage::Sums ? 1 : 2;
    };
    const Film::Storage needed = film_storage_for(scene, integrator, options);
    if (rank(film.storage()) < rank(needed)) film.change_storage(needed);
    return ImageRender(scene, integrator, options, film).run();
}

}  // namespace lancer
