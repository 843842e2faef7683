// Accumulates linear RGB samples per pixel. Each pixel keeps its sum, sum of
// squares (for variance estimates) and sample count; non-finite samples are
// counted and dropped, never written. A render that reads no variance keeps
// less: the colour sum and the counts (Storage::Sums), or for one sample a
// pixel the colour and the count (Storage::MeanOnly).
#pragma once

#include <atomic>
#include <cmath>
#include <cstdint>
#include <vector>

#include "lancer/host/zeroed_array.h"
#include "lancer/ray.h"

namespace lancer {

class Film {
  public:
    // One pixel's running totals, in double so sums stay exact enough for
    // thousands of samples; also the checkpoint's on-disk record.
    struct Accumulator {
        glm::dvec3 sum{0.0};
        glm::dvec3 sum_squares{0.0};
        std::uint32_t count = 0;      // finite samples
        std::uint32_t nonfinite = 0;  // dropped samples
    };

    enum class Storage {
        // Double sums and sums of squares, and the counts: 56 bytes a pixel.
        Totals,
        // A float sum and the count, 16 bytes a pixel, for renders whose
        // pixels take at most one sample (a variance needs two): exact for
        // those. With more, a pixel keeps no variance, and one that meets a
        // non-finite sample keeps none of its samples.
        MeanOnly,
        // A float sum and the counts of samples taken and finite, 20 bytes
        // a pixel, for renders of a fixed sample count that read no
        // variance (no adaptive sampling, no error estimate asked for). No
        // variance: as if every sample of a pixel were alike. The sum
        // rounds to float at each sample: after n samples a relative error
        // near sqrt(n) 6e-8 for random ones, up to about n 1e-8 for
        // samples all alike (renderer.h: kMostFloatSummedSamples).
        Sums,
    };

    explicit Film(int width, int height, Storage storage = Storage::Totals);
    Storage storage() const { return m_storage; }
    // Moves every pixel's totals into another storage: what the new one
    // cannot hold is lost (a variance into Sums), what the old did not
    // keep is made up as in accumulator().
    void change_storage(Storage storage);

    int width() const { return m_width; }
    int height() const { return m_height; }

    // Not thread-safe per pixel: the host gives each pixel to one thread.
    // Inline: the host calls it once per sample.
    void add_sample(int x, int y, const Color& radiance) {
        const std::size_t index = std::size_t(y) * m_width + x;
        ++m_taken[index];
        // Written once: afterwards every thread only reads the flag.
        if (!m_has_samples.value.load(std::memory_order_relaxed))
            m_has_samples.value.store(true, std::memory_order_relaxed);
        const bool finite = std::isfinite(radiance.r) && std::isfinite(radiance.g) && std::isfinite(radiance.b);
        if (!finite) m_nonfinite_total.value.fetch_add(1, std::memory_order_relaxed);
        if (m_storage == Storage::MeanOnly) {
            // NaN marks a pixel whose samples were not all finite.
            m_colour_sums[index] = finite ? m_colour_sums[index] + radiance : Color(std::nanf(""));
            return;
        }
        if (!finite) return;
        ++m_finite[index];
        if (m_storage == Storage::Sums) {
            m_colour_sums[index] += radiance;
            return;
        }
        const glm::dvec3 value(radiance);
        m_sums[index] += value;
        m_squares[index] += value * value;
    }

    // Asks the cache for a pixel's totals ahead of a coming add_sample. The
    // film of a large image lies far out of cache, and the host adds a
    // batch's samples only after tracing it: prefetched when the sample
    // joins the batch, its totals have arrived by then.
    void prefetch(int x, int y) const {
        const std::size_t index = std::size_t(y) * m_width + x;
        if (m_storage == Storage::Totals) {
            // A dvec3 may straddle two cache lines.
            for (const glm::dvec3* totals : {&m_sums[index], &m_squares[index]}) {
                const char* first = reinterpret_cast<const char*>(totals);
                __builtin_prefetch(first, 1);
                __builtin_prefetch(first + sizeof(glm::dvec3) - 1, 1);
            }
        } else {
            __builtin_prefetch(&m_colour_sums[index], 1);
        }
        if (m_storage != Storage::MeanOnly) __builtin_prefetch(&m_finite[index], 1);
    }

    Color mean(int x, int y) const;                  // black if no samples
    Color variance_of_mean(int x, int y) const;      // sample variance / n
    std::uint32_t sample_count(int x, int y) const;  // finite samples
    // Samples taken, finite or not: the index of the pixel's next sample.
    std::uint32_t samples_taken(int x, int y) const { return m_taken[std::size_t(y) * m_width + x]; }
    std::uint64_t nonfinite_samples() const {  // over the whole film
        return m_nonfinite_total.value.load(std::memory_order_relaxed);
    }
    // False until a sample is added (or restored): every pixel has taken
    // none, and the host plans a first pass without sweeping the film.
    bool has_samples() const { return m_has_samples.value.load(std::memory_order_relaxed); }

    // One pixel's totals (index y * width + x), in any storage: for
    // checkpoints and the processes of a distributed render. A MeanOnly
    // pixel's sum of squares is its sum's square (exact for one sample), a
    // Sums pixel's that of samples all alike (no variance).
    Accumulator accumulator(std::size_t index) const;
    std::vector<Accumulator> accumulators() const;  // every pixel, row-major
    // Replaces every pixel's totals; throws std::invalid_argument unless
    // there are width x height of them. A MeanOnly film becomes Totals; a
    // Sums film keeps its storage.
    void restore(std::vector<Accumulator> accumulators);
    // Replaces the totals of the pixels x0 <= x < x1, y0 <= y < y1 with
    // `pixels` (row-major over that rectangle) and leaves the others: a
    // render spread over processes moves one tile's state at a time. The
    // film keeps its storage (a MeanOnly or Sums pixel the sums and counts).
    void restore_region(int x0, int y0, int x1, int y1, const Accumulator* pixels);

  private:
    void allocate(std::size_t pixels);  // zeroed totals of m_storage's kind
    void start_empty();

    int m_width;
    int m_height;
    Storage m_storage;
    // By pixel, each kept by the storages named: one array a quantity, so
    // a Totals pixel takes 56 bytes (an Accumulator's count of non-finite
    // samples is the difference of the two counts).
    ZeroedArray<glm::dvec3> m_sums;       // Totals
    ZeroedArray<glm::dvec3> m_squares;    // Totals
    ZeroedArray<Color> m_colour_sums;     // MeanOnly, Sums
    ZeroedArray<std::uint32_t> m_finite;  // Totals, Sums: finite samples
    // Samples taken per pixel (count + nonfinite), apart from the totals:
    // the host's sweeps over the film read 4 bytes a pixel, not 56. Every
    // storage keeps it.
    ZeroedArray<std::uint32_t> m_taken;
    // A value threads update concurrently, copied along with the film.
    template <typename T>
    struct Shared {
        std::atomic<T> value{};
        Shared() = default;
        Shared(const Shared& other) : value(other.value.load(std::memory_order_relaxed)) {}
        Shared& operator=(const Shared& other) {
            value.store(other.value.load(std::memory_order_relaxed), std::memory_order_relaxed);
            return *this;
        }
    };
    // Kept as samples arrive, so asking costs no sweep of the film.
    Shared<std::uint64_t> m_nonfinite_total;
    Shared<bool> m_has_samples;
};

}  // namespace lancer
