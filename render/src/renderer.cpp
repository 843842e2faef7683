// The host's pixel loop: tiles on oneTBB, deterministic per-sample sampler
// streams, progress on stderr.
#include "lancer/renderer.h"

#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <mutex>

#include <tbb/blocked_range.h>
#include <tbb/enumerable_thread_specific.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

namespace lancer {
namespace {

using Clock = std::chrono::steady_clock;

// Reports finished tiles: a redrawn bar with ETA on a terminal, a line per
// 10% otherwise, nothing when quiet.
class Progress {
public:
    Progress(ProgressMode mode, int total) : m_total(std::max(total, 1)), m_start(Clock::now()) {
        if (mode == ProgressMode::Auto) mode = ::isatty(STDERR_FILENO) ? ProgressMode::Bar : ProgressMode::Lines;
        m_mode = mode;
    }
    void tile_done() {
        const int done = ++m_done;
        if (m_mode == ProgressMode::Quiet) return;
        std::lock_guard<std::mutex> lock(m_mutex);
        const int percent = int(100LL * done / m_total);
        const double elapsed = std::chrono::duration<double>(Clock::now() - m_start).count();
        if (m_mode == ProgressMode::Lines) {
            const int step = percent / 10 * 10;
            if (step > m_last_percent) {
                m_last_percent = step;
                std::fprintf(stderr, "progress: %d%%\n", step);
            }
            return;
        }
        if (done < m_total && elapsed - m_last_draw < 0.1) return;
        m_last_draw = elapsed;
        const int width = 40;
        const int filled = width * done / m_total;
        const double eta = done > 0 ? elapsed * double(m_total - done) / done : 0.0;
        char bar[width + 1];
        for (int i = 0; i < width; ++i) bar[i] = i < filled ? '=' : ' ';
        bar[width] = '\0';
        std::fprintf(stderr, "\r[%s] %3d%%  elapsed %.1fs  ETA %.1fs ", bar, percent, elapsed, eta);
        if (done == m_total) std::fprintf(stderr, "\n");
        std::fflush(stderr);
    }

private:
    ProgressMode m_mode;
    int m_total;
    std::atomic<int> m_done{0};
    Clock::time_point m_start;
    std::mutex m_mutex;
    int m_last_percent = -1;
    double m_last_draw = -1.0;
};

}  // namespace

RenderStats render_image(const RenderScene& scene, const Integrator& integrator, const RenderOptions& options,
                         Film& film) {
    const auto start = Clock::now();
    const int width = film.width(), height = film.height();
    CropWindow window{0, 0, width, height};
    if (options.crop) window = *options.crop;
    window.x0 = std::clamp(window.x0, 0, width);
    window.x1 = std::clamp(window.x1, window.x0, width);
    window.y0 = std::clamp(window.y0, 0, height);
    window.y1 = std::clamp(window.y1, window.y0, height);
    const int tile = std::max(options.tile_size, 1);
    const int tiles_x = (window.x1 - window.x0 + tile - 1) / tile;
    const int tiles_y = (window.y1 - window.y0 + tile - 1) / tile;
    const int tiles = tiles_x * tiles_y;
    // One sample of a deterministic integrator goes through the pixel centre
    // (POV-Ray's picture without antialiasing); more samples, of any
    // integrator, spread over the pixel and antialias.
    const int samples = std::max(options.samples_per_pixel, 1);
    const bool pixel_centre = samples == 1 && integrator.is_deterministic();
    const Camera& camera = scene.camera();

    const std::unique_ptr<Sampler> prototype = integrator.make_sampler(options.seed);
    tbb::enumerable_thread_specific<std::unique_ptr<Sampler>> samplers([&] { return prototype->clone(); });
    const std::uint64_t nonfinite_before = film.nonfinite_samples();
    Progress progress(options.progress, tiles);

    auto render_tile = [&](int tile_index) {
        Sampler& sampler = *samplers.local();
        const int tx = tile_index % tiles_x, ty = tile_index / tiles_x;
        const int x_begin = window.x0 + tx * tile, y_begin = window.y0 + ty * tile;
        const int x_end = std::min(x_begin + tile, window.x1), y_end = std::min(y_begin + tile, window.y1);
        for (int y = y_begin; y < y_end; ++y)
            for (int x = x_begin; x < x_end; ++x)
                for (int s = 0; s < samples; ++s) {
                    sampler.start_sample(x, y, std::uint32_t(s));
                    const Vec2 jitter = pixel_centre ? Vec2(0.5f) : sampler.next_2d();
                    const Ray ray = camera.generate_ray(float(x) + jitter.x, float(y) + jitter.y, width, height);
                    film.add_sample(x, y, integrator.radiance(ray, scene, sampler));
                }
        progress.tile_done();
    };

    tbb::task_arena arena(options.threads > 0 ? options.threads : tbb::task_arena::automatic);
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, tiles, 1), [&](const tbb::blocked_range<int>& range) {
            for (int t = range.begin(); t != range.end(); ++t) render_tile(t);
        });
    });

    RenderStats stats;
    stats.seconds = std::chrono::duration<double>(Clock::now() - start).count();
    stats.samples = std::uint64_t(window.x1 - window.x0) * std::uint64_t(window.y1 - window.y0) * samples;
    stats.nonfinite_samples = film.nonfinite_samples() - nonfinite_before;
    return stats;
}

}  // namespace lancer
