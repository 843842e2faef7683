// The Distribution of a job mpirun started (apps/distribution.h,
// docs/distributed.md): rank 0 coordinates on its main thread (the only
// thread that calls MPI) and renders on a second one; every other rank asks
// rank 0 for work, renders it and sends it back.
//
// Messages are raw bytes: a fixed header and, for tiles, the tile's film
// totals (Film::Accumulator, 56 bytes a pixel). The processes run the same
// lancer binary on machines of one architecture, as mpirun requires.
#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <condition_variable>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <exception>
#include <limits>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <thread>
#include <utility>

#include "distribution.h"
#include "lancer/host/counting_scene.h"
#include "lancer/host/estimate.h"
#include "tile_schedule.h"

namespace lancer::app {
namespace {

using Clock = std::chrono::steady_clock;
using Accumulator = Film::Accumulator;

constexpr int kTagWork = 1;    // rank 0 -> worker: a tile, a frame or stop
constexpr int kTagResult = 2;  // worker -> rank 0: ready, a tile's totals, a frame's status
// Tiles a process should expect in a round: enough that one slow tile does
// not keep the others waiting at the round's end.
constexpr int kTilesPerProcess = 6;
// How long rank 0's coordinator sleeps when no message and no local result
// is waiting; small against a tile's render time.
constexpr auto kPollInterval = std::chrono::microseconds(200);

enum class WorkKind : std::int32_t { Stop = 0, Tile = 1, Frame = 2 };
enum class ResultKind : std::int32_t { Ready = 0, Tile = 1, Frame = 2 };

struct WorkHeader {
    WorkKind kind = WorkKind::Stop;
    std::int32_t item = 0;  // tile or frame number
    std::int32_t x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    std::uint32_t target = 0;    // samples per pixel to reach
    std::int32_t has_state = 0;  // the tile's totals follow (else it starts empty)
    double seconds_left = 0.0;   // of a --time budget, when handed out
};

struct ResultHeader {
    ResultKind kind = ResultKind::Ready;
    std::int32_t item = 0;
    std::int32_t status = 0;            // a frame's exit status
    std::uint32_t least = 0, most = 0;  // least and most samples of the tile's pixels
    std::uint64_t samples = 0, nonfinite = 0, rays = 0;
};

// A header and the pixels after it (if any), as one buffer.
template <typename Header>
std::vector<char> pack(const Header& header, const Accumulator* pixels, std::size_t count) {
    std::vector<char> bytes(sizeof(Header) + count * sizeof(Accumulator));
    std::memcpy(bytes.data(), &header, sizeof(Header));
    if (count > 0) std::memcpy(bytes.data() + sizeof(Header), pixels, count * sizeof(Accumulator));
    return bytes;
}
template <typename Header>
std::vector<char> pack(const Header& header) {
    return pack(header, nullptr, 0);
}
// Not inlined: GCC 12 otherwise warns of a copy past the header when it
// cannot see that `pixels` may be empty (a false -Warray-bounds).
template <typename Header>
[[gnu::noinline]] std::vector<char> pack(const Header& header, const std::vector<Accumulator>& pixels) {
    return pack(header, pixels.data(), pixels.size());
}

template <typename Header>
Header unpack(const std::vector<char>& bytes, std::vector<Accumulator>& pixels) {
    if (bytes.size() < sizeof(Header) || (bytes.size() - sizeof(Header)) % sizeof(Accumulator) != 0)
        throw std::runtime_error("distributed render: a message of " + std::to_string(bytes.size()) +
                                 " bytes is not one lancer sent (mixed lancer versions in one job?)");
    Header header;
    std::memcpy(&header, bytes.data(), sizeof(Header));
    pixels.resize((bytes.size() - sizeof(Header)) / sizeof(Accumulator));
    if (!pixels.empty()) std::memcpy(pixels.data(), bytes.data() + sizeof(Header), pixels.size() * sizeof(Accumulator));
    return header;
}

// Receives the message `probed` announced (blocking until it is whole).
std::vector<char> receive(const MPI_Status& probed, int tag) {
    int count = 0;
    MPI_Get_count(&probed, MPI_BYTE, &count);
    std::vector<char> bytes(std::size_t(std::max(count, 0)));
    MPI_Recv(bytes.data(), count, MPI_BYTE, probed.MPI_SOURCE, tag, MPI_COMM_WORLD, MPI_STATUS_IGNORE);
    return bytes;
}

std::vector<char> receive_blocking(int source, int tag) {
    MPI_Status status;
    MPI_Probe(source, tag, MPI_COMM_WORLD, &status);
    return receive(status, tag);
}

void send(const std::vector<char>& bytes, int destination, int tag) {
    MPI_Send(bytes.data(), int(bytes.size()), MPI_BYTE, destination, tag, MPI_COMM_WORLD);
}

enum class StillMode { Fixed, Budget, Adaptive };

// As the host's pass planner decides it: a deterministic integrator is
// exact at its fixed count whatever --time or --noise say.
StillMode still_mode(const RenderOptions& options, const Integrator& integrator) {
    if (integrator.is_deterministic()) return StillMode::Fixed;
    if (options.noise_target > 0.0) return StillMode::Adaptive;
    if (options.time_budget_seconds > 0.0) return StillMode::Budget;
    return StillMode::Fixed;
}

CropWindow render_window(const RenderOptions& options, const Film& film) {
    return options.crop.value_or(CropWindow{0, 0, film.width(), film.height()});
}

std::vector<Accumulator> tile_pixels(const Film& film, const CropWindow& tile) {
    std::vector<Accumulator> pixels;
    pixels.reserve(std::size_t(tile.x1 - tile.x0) * std::size_t(tile.y1 - tile.y0));
    for (int y = tile.y0; y < tile.y1; ++y)
        for (int x = tile.x0; x < tile.x1; ++x) pixels.push_back(film.accumulator(std::size_t(y) * film.width() + x));
    return pixels;
}

std::uint32_t least_taken(const std::vector<Accumulator>& pixels) {
    std::uint32_t least = std::numeric_limits<std::uint32_t>::max();
    for (const Accumulator& p : pixels) least = std::min(least, p.count + p.nonfinite);
    return pixels.empty() ? 0 : least;
}

std::uint32_t most_taken(const std::vector<Accumulator>& pixels) {
    std::uint32_t most = 0;
    for (const Accumulator& p : pixels) most = std::max(most, p.count + p.nonfinite);
    return most;
}

// Renders tiles for one process into a scratch film of the image's size
// (only the tile being rendered is meaningful), with the user's options
// narrowed to the tile.
class TileRenderer {
  public:
    TileRenderer(const RenderScene& prepared, Integrator& integrator, const RenderOptions& options, StillMode mode,
                 Film& scratch, const std::atomic<bool>* cancel)
        : m_scene(prepared),
          m_integrator(integrator),
          m_options(options),
          m_mode(mode),
          m_film(scratch),
          m_cancel(cancel) {}

    // Brings the tile to the unit's target from `state` (empty: no samples
    // yet); returns the header and the tile's totals to send back.
    ResultHeader render(const WorkHeader& unit, const std::vector<Accumulator>& state,
                        std::vector<Accumulator>& pixels) {
        const CropWindow tile{unit.x0, unit.y0, unit.x1, unit.y1};
        const std::size_t count = std::size_t(tile.x1 - tile.x0) * std::size_t(tile.y1 - tile.y0);
        if (unit.has_state && state.size() != count)
            throw std::runtime_error("distributed render: a tile's state has the wrong size");
        if (unit.has_state) {
            m_film.restore_region(tile.x0, tile.y0, tile.x1, tile.y1, state.data());
        } else {
            m_empty.resize(count);
            m_film.restore_region(tile.x0, tile.y0, tile.x1, tile.y1, m_empty.data());
        }
        RenderOptions options = m_options;
        options.crop = tile;
        options.progress = ProgressMode::Quiet;
        options.checkpoint_interval_seconds = 0.0;
        options.on_checkpoint = nullptr;
        options.cancel = m_cancel;
        options.ray_counter = dynamic_cast<const CountingScene*>(&m_scene);
        switch (m_mode) {
        case StillMode::Fixed:
            options.samples_per_pixel = int(unit.target);
            options.time_budget_seconds = 0.0;
            options.noise_target = 0.0;
            break;
        case StillMode::Budget:
            options.time_budget_seconds = std::max(unit.seconds_left, 1e-3);
            options.max_samples_per_pixel = int(unit.target);
            break;
        case StillMode::Adaptive:
            options.time_budget_seconds = m_options.time_budget_seconds > 0.0 ? std::max(unit.seconds_left, 1e-3) : 0.0;
            options.max_samples_per_pixel = int(unit.target);
            break;
        }
        const RenderStats stats = render_image(m_scene, m_integrator, options, m_film);
        pixels = tile_pixels(m_film, tile);
        ResultHeader result;
        result.kind = ResultKind::Tile;
        result.item = unit.item;
        result.least = least_taken(pixels);
        result.most = most_taken(pixels);
        result.samples = stats.samples;
        result.nonfinite = stats.nonfinite_samples;
        result.rays = stats.rays;
        return result;
    }

  private:
    const RenderScene& m_scene;
    Integrator& m_integrator;
    const RenderOptions m_options;
    const StillMode m_mode;
    Film& m_film;
    const std::atomic<bool>* m_cancel;
    std::vector<Accumulator> m_empty;
};

// Rank 0's own renderer, on a thread of its own so that the coordinator
// keeps answering the other ranks while it works. One job at a time.
class LocalWorker {
  public:
    explicit LocalWorker(std::function<void(std::int32_t)> work) : m_work(std::move(work)) {
        m_thread = std::thread([this] { loop(); });
    }
    ~LocalWorker() {
        {
            std::lock_guard lock(m_mutex);
            m_quit = true;
        }
        m_wake.notify_all();
        m_thread.join();
    }
    LocalWorker(const LocalWorker&) = delete;
    LocalWorker& operator=(const LocalWorker&) = delete;

    bool idle() const { return !m_busy; }
    void give(std::int32_t item) {
        {
            std::lock_guard lock(m_mutex);
            m_item = item;
            m_busy = true;
            m_has_item = true;
        }
        m_wake.notify_all();
    }
    // True (once) when the job given has finished; rethrows its exception.
    bool take_finished() {
        std::lock_guard lock(m_mutex);
        if (!m_finished) return false;
        m_finished = false;
        m_busy = false;
        if (m_error) std::rethrow_exception(std::exchange(m_error, nullptr));
        return true;
    }

  private:
    void loop() {
        std::unique_lock lock(m_mutex);
        while (true) {
            m_wake.wait(lock, [this] { return m_quit || m_has_item; });
            if (m_quit) return;
            m_has_item = false;
            const std::int32_t item = m_item;
            lock.unlock();
            std::exception_ptr error;
            try {
                m_work(item);
            } catch (...) {
                error = std::current_exception();
            }
            lock.lock();
            m_error = error;
            m_finished = true;
        }
    }

    std::function<void(std::int32_t)> m_work;
    std::mutex m_mutex;
    std::condition_variable m_wake;
    std::int32_t m_item = 0;
    bool m_has_item = false, m_finished = false, m_quit = false;
    std::atomic<bool> m_busy{false};
    std::exception_ptr m_error;
    std::thread m_thread;
};

// Rank 0's progress line: one display for the whole job.
class JobProgress {
  public:
    explicit JobProgress(bool shown) : m_shown(shown), m_terminal(::isatty(2) != 0) {}
    void report(double fraction, const char* what) {
        if (!m_shown) return;
        const int percent = std::clamp(int(fraction * 100.0), 0, 100);
        if (m_terminal) {
            if (percent == m_last) return;
            std::fprintf(stderr, "\rlancer: %s %3d%%", what, percent);
        } else {
            if (percent / 10 == m_last / 10 && m_last >= 0) return;
            std::fprintf(stderr, "lancer: %s %d%%\n", what, percent);
        }
        m_last = percent;
        std::fflush(stderr);
    }
    void finish() {
        if (m_shown && m_terminal && m_last >= 0) std::fprintf(stderr, "\n");
    }

  private:
    bool m_shown, m_terminal;
    int m_last = -1;
};

class MpiDistribution final : public Distribution {
  public:
    MpiDistribution(int rank, int processes) : m_rank(rank), m_processes(processes) {}
    ~MpiDistribution() override { MPI_Finalize(); }

    int rank() const override { return m_rank; }
    int processes() const override { return m_processes; }

    [[noreturn]] void abort(int status) override {
        std::fflush(stdout);
        std::fflush(stderr);
        MPI_Abort(MPI_COMM_WORLD, status);
        std::_Exit(status);
    }

    RenderStats render_still(const RenderScene& scene, Integrator& integrator, const RenderOptions& options, Film& film,
                             const std::function<void(const Film&)>& on_progress) override {
        // Each process prepares the integrator once, through one counting
        // wrapper that every tile is then rendered through.
        CountingScene counted(scene);
        integrator.prepare(counted);
        const StillMode mode = still_mode(options, integrator);
        if (m_rank != 0) return serve_tiles(counted, integrator, options, mode, film);
        return coordinate_still(counted, integrator, options, mode, film, on_progress);
    }

    int render_frames(const std::vector<int>& frames, const std::function<int(int frame)>& render_frame,
                      const std::atomic<bool>* cancel) override {
        if (m_rank != 0) return serve_frames(render_frame);
        return coordinate_frames(frames, render_frame, cancel);
    }

  private:
    RenderStats serve_tiles(const RenderScene& counted, Integrator& integrator, const RenderOptions& options,
                            StillMode mode, Film& film) {
        const auto started = Clock::now();
        // The film render_still was given is this process's scratch.
        TileRenderer renderer(counted, integrator, options, mode, film, nullptr);
        send(pack(ResultHeader{}), 0, kTagResult);
        RenderStats stats;
        std::vector<Accumulator> state, pixels;
        while (true) {
            const WorkHeader unit = unpack<WorkHeader>(receive_blocking(0, kTagWork), state);
            if (unit.kind != WorkKind::Tile) break;
            const ResultHeader result = renderer.render(unit, state, pixels);
            stats.samples += result.samples;
            send(pack(result, pixels), 0, kTagResult);
        }
        stats.seconds = std::chrono::duration<double>(Clock::now() - started).count();
        return stats;
    }

    RenderStats coordinate_still(const RenderScene& counted, Integrator& integrator, const RenderOptions& options,
                                 StillMode mode, Film& film, const std::function<void(const Film&)>& on_progress) {
        const auto started = Clock::now();
        const auto deadline = started + std::chrono::duration_cast<Clock::duration>(
                                            std::chrono::duration<double>(options.time_budget_seconds));
        const bool has_deadline = mode != StillMode::Fixed && options.time_budget_seconds > 0.0;
        const auto seconds_left = [&] {
            return has_deadline ? std::chrono::duration<double>(deadline - Clock::now()).count() : 0.0;
        };
        const CropWindow window = render_window(options, film);
        const std::uint64_t window_pixels = std::uint64_t(window.x1 - window.x0) * std::uint64_t(window.y1 - window.y0);
        TileSchedule schedule(window, TileSchedule::tile_size_for(window, m_processes, kTilesPerProcess));
        JobProgress progress(options.progress != ProgressMode::Quiet);

        // Rank 0's own share, rendered on the local worker's thread.
        // In the film's storage, as every other process renders: a sum
        // of floats rounds otherwise than a sum of doubles.
        Film scratch(film.width(), film.height(), film.storage());
        TileRenderer renderer(counted, integrator, options, mode, scratch, options.cancel);
        WorkHeader local_unit;
        std::vector<Accumulator> local_state, local_pixels;
        ResultHeader local_result;
        LocalWorker local([&](std::int32_t) { local_result = renderer.render(local_unit, local_state, local_pixels); });

        RenderStats stats;
        std::uint64_t bytes_exchanged = 0;
        // Rank 0 is ready from the start; the others once they ask.
        std::vector<bool> ready(std::size_t(m_processes), false), idle(std::size_t(m_processes), false);
        ready[0] = idle[0] = true;
        std::vector<int> tiles_by_rank(std::size_t(m_processes), 0);
        const auto merge = [&](const ResultHeader& result, const std::vector<Accumulator>& pixels, int from) {
            ++tiles_by_rank[std::size_t(from)];
            const CropWindow tile = schedule.tile_window(result.item);
            film.restore_region(tile.x0, tile.y0, tile.x1, tile.y1, pixels.data());
            schedule.completed(result.item, result.samples, result.least, result.most);
            stats.samples += result.samples;
            stats.rays += result.rays;
            stats.nonfinite_samples += result.nonfinite;
            if (on_progress) on_progress(film);
        };
        // The unit for a tile: its totals go along unless it has none.
        const auto unit_for = [&](const TileUnit& next, std::vector<Accumulator>& state) {
            WorkHeader unit;
            unit.kind = WorkKind::Tile;
            unit.item = next.tile;
            const CropWindow tile = schedule.tile_window(next.tile);
            unit.x0 = tile.x0, unit.y0 = tile.y0, unit.x1 = tile.x1, unit.y1 = tile.y1;
            unit.target = next.target;
            unit.seconds_left = seconds_left();
            state.clear();
            if (film.has_samples()) {
                state = tile_pixels(film, tile);
                const bool empty = std::all_of(state.begin(), state.end(),
                                               [](const Accumulator& p) { return p.count + p.nonfinite == 0; });
                if (empty) state.clear();
            }
            unit.has_state = !state.empty();
            return unit;
        };
        const std::uint32_t cap = std::uint32_t(
            mode == StillMode::Fixed ? std::max(options.samples_per_pixel, 1)
            : options.max_samples_per_pixel > 0
                ? options.max_samples_per_pixel
                : (mode == StillMode::Adaptive && options.time_budget_seconds <= 0.0 ? kDefaultAdaptiveCap : 1 << 30));
        // The first round continues whatever the film holds (a checkpoint).
        std::uint32_t least_held = std::numeric_limits<std::uint32_t>::max();
        for (int tile = 0; tile < schedule.tiles(); ++tile)
            least_held = std::min(least_held, least_taken(tile_pixels(film, schedule.tile_window(tile))));
        std::uint32_t target =
            mode == StillMode::Fixed ? cap : std::min(cap, std::max<std::uint32_t>(1, 2 * least_held));
        bool interrupted = options.cancel && options.cancel->load();
        int rounds = 0;
        bool more_rounds = !interrupted && window_pixels > 0;
        while (more_rounds) {
            schedule.begin_round(target);
            const auto round_start = Clock::now();
            const std::uint64_t samples_before = stats.samples;
            ++rounds;
            while (!schedule.round_complete()) {
                if (options.cancel && options.cancel->load()) {
                    interrupted = true;
                    break;
                }
                const bool out_of_time = has_deadline && seconds_left() <= 0.0;
                bool acted = false;
                // Hand out work to whoever waits for it.
                for (int r = 0; r < m_processes && !out_of_time; ++r) {
                    if (!idle[std::size_t(r)]) continue;
                    if (r == 0 && !local.idle()) continue;
                    const std::optional<TileUnit> next = schedule.next();
                    if (!next) break;
                    idle[std::size_t(r)] = false;
                    acted = true;
                    if (r == 0) {
                        local_unit = unit_for(*next, local_state);
                        local.give(next->tile);
                    } else {
                        std::vector<Accumulator> state;
                        const WorkHeader unit = unit_for(*next, state);
                        const std::vector<char> bytes = pack(unit, state);
                        bytes_exchanged += bytes.size();
                        send(bytes, r, kTagWork);
                    }
                }
                if (out_of_time && schedule.outstanding() == 0) break;
                if (!idle[0] && local.take_finished()) {
                    merge(local_result, local_pixels, 0);
                    idle[0] = true;
                    acted = true;
                }
                int waiting = 0;
                MPI_Status probed;
                MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &waiting, &probed);
                if (waiting) {
                    const std::vector<char> bytes = receive(probed, kTagResult);
                    bytes_exchanged += bytes.size();
                    std::vector<Accumulator> pixels;
                    const ResultHeader result = unpack<ResultHeader>(bytes, pixels);
                    if (result.kind == ResultKind::Tile) merge(result, pixels, probed.MPI_SOURCE);
                    ready[std::size_t(probed.MPI_SOURCE)] = idle[std::size_t(probed.MPI_SOURCE)] = true;
                    acted = true;
                }
                progress.report(progress_fraction(mode, schedule, options, started), "rendering");
                if (!acted) std::this_thread::sleep_for(kPollInterval);
            }
            if (interrupted) break;
            // The next round: done at the cap, at the deadline, or (noise)
            // when every tile has stopped; under a time budget, only as many
            // samples as the last round's pace says fit in 90% of what is left.
            more_rounds = target < cap && schedule.unfinished() > 0 && !(has_deadline && seconds_left() <= 0.0);
            if (more_rounds) {
                std::uint32_t next_target = target > cap / 2 ? cap : 2 * target;
                if (mode == StillMode::Budget) {
                    const double round_seconds = std::chrono::duration<double>(Clock::now() - round_start).count();
                    const double pace = double(stats.samples - samples_before) / std::max(round_seconds, 1e-6);
                    const double affordable = 0.9 * seconds_left() * pace / double(window_pixels);
                    next_target = std::min<std::uint32_t>(
                        next_target, target + std::uint32_t(std::min(affordable, double(cap - target))));
                    more_rounds = next_target > target;
                }
                target = next_target;
            }
        }
        if (!interrupted) progress.report(1.0, "rendering");
        progress.finish();
        if (!interrupted) interrupted = !release_workers(ready, options.cancel);
        if (interrupted) {
            // Rank 0 does not wait for tiles in flight: a rank that died
            // would keep it waiting for ever. Its own tile stops at once.
            while (!idle[0] && !local.take_finished()) std::this_thread::sleep_for(kPollInterval);
        }
        stats.seconds = std::chrono::duration<double>(Clock::now() - started).count();
        stats.passes = rounds;
        stats.interrupted = interrupted;
        stats.rays_per_second = stats.seconds > 0.0 ? double(stats.rays) / stats.seconds : 0.0;
        summarise_samples(film, window, integrator, stats);
        if (options.progress != ProgressMode::Quiet && !interrupted) {
            std::string shares;
            for (int count : tiles_by_rank) shares += (shares.empty() ? "" : " ") + std::to_string(count);
            std::fprintf(stderr,
                         "lancer: %d processes rendered %d tiles in %d rounds (tiles by process: %s); %.2f MB "
                         "exchanged\n",
                         m_processes, schedule.tiles(), rounds, shares.c_str(), double(bytes_exchanged) / 1e6);
        }
        return stats;
    }

    static double progress_fraction(StillMode mode, const TileSchedule& schedule, const RenderOptions& options,
                                    Clock::time_point started) {
        if (mode == StillMode::Budget || (mode == StillMode::Adaptive && options.time_budget_seconds > 0.0))
            return std::chrono::duration<double>(Clock::now() - started).count() / options.time_budget_seconds;
        if (mode == StillMode::Fixed) return schedule.round_fraction_done();
        return 1.0 - double(schedule.unfinished()) / double(std::max(schedule.tiles(), 1));
    }

    static void summarise_samples(const Film& film, const CropWindow& window, const Integrator& integrator,
                                  RenderStats& stats) {
        std::uint64_t sum = 0;
        std::uint32_t least = std::numeric_limits<std::uint32_t>::max(), most = 0;
        for (int y = window.y0; y < window.y1; ++y)
            for (int x = window.x0; x < window.x1; ++x) {
                const std::uint32_t taken = film.samples_taken(x, y);
                sum += taken;
                least = std::min(least, taken);
                most = std::max(most, taken);
            }
        const std::uint64_t pixels = std::uint64_t(window.x1 - window.x0) * std::uint64_t(window.y1 - window.y0);
        stats.mean_samples_per_pixel = pixels > 0 ? double(sum) / double(pixels) : 0.0;
        stats.min_samples_per_pixel = pixels > 0 ? least : 0;
        stats.max_samples_per_pixel = most;
        if (!integrator.is_deterministic() && pixels > 0)
            stats.estimated_rel_rmse =
                estimated_relative_rmse(film, PixelWindow{window.x0, window.y0, window.x1, window.y1});
    }

    int serve_frames(const std::function<int(int frame)>& render_frame) {
        send(pack(ResultHeader{}), 0, kTagResult);
        std::vector<Accumulator> none;
        while (true) {
            const WorkHeader unit = unpack<WorkHeader>(receive_blocking(0, kTagWork), none);
            if (unit.kind != WorkKind::Frame) return 0;
            ResultHeader result;
            result.kind = ResultKind::Frame;
            result.item = unit.item;
            result.status = render_frame(unit.item);
            send(pack(result), 0, kTagResult);
        }
    }

    int coordinate_frames(const std::vector<int>& frames, const std::function<int(int frame)>& render_frame,
                          const std::atomic<bool>* cancel) {
        int local_status = 0;
        LocalWorker local([&](std::int32_t frame) { local_status = render_frame(frame); });
        std::vector<int> busy_with(std::size_t(m_processes), -1);  // frame, or -1 when idle
        std::vector<bool> ready(std::size_t(m_processes), false);
        ready[0] = true;
        std::size_t next = 0, done = 0;
        int failure = 0;
        const auto finished = [&](int rank, int frame, int status) {
            busy_with[std::size_t(rank)] = -1;
            ++done;
            if (status != 0) {
                if (failure == 0)
                    std::fprintf(stderr, "lancer: error: frame %d failed on process %d (exit status %d)\n", frame, rank,
                                 status);
                failure = failure ? failure : status;
                return;
            }
            std::printf("lancer: frame %d done by process %d (%zu of %zu)\n", frame, rank, done, frames.size());
            std::fflush(stdout);
        };
        while (done < next || (next < frames.size() && failure == 0 && !(cancel && cancel->load()))) {
            bool acted = false;
            for (int r = 0; r < m_processes; ++r) {
                if (next >= frames.size() || failure != 0 || (cancel && cancel->load())) break;
                if (!ready[std::size_t(r)] || busy_with[std::size_t(r)] >= 0) continue;
                const int frame = frames[next++];
                busy_with[std::size_t(r)] = frame;
                acted = true;
                if (r == 0) {
                    local.give(frame);
                } else {
                    WorkHeader unit;
                    unit.kind = WorkKind::Frame;
                    unit.item = frame;
                    send(pack(unit), r, kTagWork);
                }
            }
            if (busy_with[0] >= 0 && local.take_finished()) {
                finished(0, busy_with[0], local_status);
                acted = true;
            }
            // With a frame failed or the job interrupted, rank 0 waits only
            // for its own frame: another rank's may never come back.
            if ((failure != 0 || (cancel && cancel->load())) && busy_with[0] < 0) break;
            int waiting = 0;
            MPI_Status probed;
            MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &waiting, &probed);
            if (waiting) {
                std::vector<Accumulator> none;
                const ResultHeader result = unpack<ResultHeader>(receive(probed, kTagResult), none);
                const int source = probed.MPI_SOURCE;
                if (result.kind == ResultKind::Frame) finished(source, result.item, result.status);
                ready[std::size_t(source)] = true;
                acted = true;
            }
            if (!acted) std::this_thread::sleep_for(kPollInterval);
        }
        if (failure != 0) return failure;
        if (cancel && cancel->load()) return 128 + SIGTERM;
        return release_workers(ready, cancel) ? 0 : 128 + SIGTERM;
    }

    // Tells every other rank to stop once it has asked for work (a slow
    // parse may ask only now), so no message is left unread. False if
    // `cancel` came first: a rank that died never asks.
    bool release_workers(std::vector<bool>& ready, const std::atomic<bool>* cancel) {
        for (int r = 1; r < m_processes; ++r) {
            while (!ready[std::size_t(r)]) {
                if (cancel && cancel->load()) return false;
                int waiting = 0;
                MPI_Status probed;
                MPI_Iprobe(MPI_ANY_SOURCE, kTagResult, MPI_COMM_WORLD, &waiting, &probed);
                if (!waiting) {
                    std::this_thread::sleep_for(kPollInterval);
                    continue;
                }
                std::vector<Accumulator> none;
                unpack<ResultHeader>(receive(probed, kTagResult), none);
                ready[std::size_t(probed.MPI_SOURCE)] = true;
            }
            send(pack(WorkHeader{}), r, kTagWork);
        }
        return true;
    }

    int m_rank, m_processes;
};

}  // namespace

std::unique_ptr<Distribution> join_mpi_job(std::string& problem) {
    int provided = 0;
    if (MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided) != MPI_SUCCESS) {
        problem = "MPI_Init_thread failed: cannot join the job mpirun started";
        return nullptr;
    }
    if (provided < MPI_THREAD_FUNNELED) {
        problem = "this MPI library cannot run threads beside MPI calls (MPI_THREAD_FUNNELED)";
        MPI_Finalize();
        return nullptr;
    }
    int rank = 0, size = 1;
    MPI_Comm_rank(MPI_COMM_WORLD, &rank);
    MPI_Comm_size(MPI_COMM_WORLD, &size);
    if (size <= 1) {
        MPI_Finalize();
        return nullptr;
    }
    return std::make_unique<MpiDistribution>(rank, size);
}

}  // namespace lancer::app
