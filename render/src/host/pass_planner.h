// How many samples each pixel takes in each pass of a render: a fixed
// count, a time budget or a noise target (internal to liblancer; see
// lancer/host/renderer.h and docs/rendering.md).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include <tbb/parallel_for.h>

#include "host/focal_blur_confidence.h"
#include "lancer/host/estimate.h"
#include "lancer/host/film.h"
#include "lancer/host/renderer.h"

namespace lancer {

// Confidence: a fixed count that a focal-blurred pixel of a deterministic
// integrator may cut short by POV-Ray's confidence test.
enum class PassMode { Fixed, Budget, Adaptive, Confidence };

// Decides, before each pass, how many samples every pixel of the window
// takes in it. Everything except the time-budget limit is a function of the
// film alone, so a resumed render plans the same passes as an uninterrupted
// one. A pixel at most doubles its samples per pass, so the image refines
// evenly and the estimates that steer adaptive sampling are refreshed often.
class PassPlanner {
  public:
    // `confidence`, when given, turns a fixed count into PassMode::Confidence
    // (its most() is the count); it must outlive the planner.
    PassPlanner(const RenderOptions& options, bool deterministic, const CropWindow& window,
                const FocalBlurConfidence* confidence = nullptr)
        : m_window(window), m_width(window.x1 - window.x0), m_height(window.y1 - window.y0), m_confidence(confidence) {
        const bool budget = !deterministic && options.time_budget_seconds > 0.0;
        const bool adaptive = !deterministic && options.noise_target > 0.0;
        m_mode = adaptive ? PassMode::Adaptive : budget ? PassMode::Budget : PassMode::Fixed;
        if (m_mode == PassMode::Fixed && confidence) {
            m_mode = PassMode::Confidence;
            m_cap = confidence->most();
        } else if (m_mode == PassMode::Fixed) {
            m_cap = std::uint32_t(std::max(options.samples_per_pixel, 1));
        } else if (options.max_samples_per_pixel > 0) {
            m_cap = std::uint32_t(options.max_samples_per_pixel);
        } else {
            m_cap = adaptive && !budget ? std::uint32_t(kDefaultAdaptiveCap) : std::uint32_t(1) << 30;
        }
        m_noise_target = options.noise_target;
        m_min_samples = std::uint32_t(std::max(options.min_samples, 2));
        // A fixed count without checkpoints is never limited (limit_to), and
        // a pixel's share of it depends on its own count alone: planned()
        // works it out when asked, and no per-pixel plan is stored.
        m_plans_per_pixel = m_mode != PassMode::Fixed || options.checkpoint_interval_seconds > 0.0;
        if (m_plans_per_pixel) m_plan.assign(std::size_t(m_width) * m_height, 0);
        if (m_mode == PassMode::Adaptive) m_relative_variance.assign(std::size_t(m_width) * m_height, 0.0f);
    }

    PassMode mode() const { return m_mode; }
    std::uint32_t cap() const { return m_cap; }

    // Samples each pixel would take next pass without a time limit; returns
    // their total (0: the render is done). One parallel sweep of the film,
    // which also counts the samples it already holds (taken_at_plan()) and
    // whether this plan, carried out whole, completes every pixel.
    std::uint64_t plan_unlimited(const Film& film) {
        if (!m_plans_per_pixel && !film.has_samples()) {
            // A fixed count on an empty film: every pixel wants the same.
            const std::uint64_t pixels = std::uint64_t(m_width) * std::uint64_t(m_height);
            const std::uint32_t wanted = wanted_after(0, 0, 0);
            m_taken_at_plan = 0;
            m_plan_completes = wanted >= m_cap;
            m_pixels_wanting = wanted > 0 ? pixels : 0;
            return pixels * wanted;
        }
        if (m_mode == PassMode::Adaptive) update_relative_variance(film);
        struct Sweep {
            std::uint64_t wanted = 0, taken = 0, pixels_wanting = 0, predicted = 0;
            bool completes = true;
        };
        const Sweep sweep = tbb::parallel_reduce(
            tbb::blocked_range<int>(0, m_height), Sweep{},
            [&](const tbb::blocked_range<int>& rows, Sweep sum) {
                for (int y = rows.begin(); y < rows.end(); ++y)
                    for (int x = 0; x < m_width; ++x) {
                        const std::size_t i = index(x, y);
                        const std::uint32_t taken =
                            std::min(film.samples_taken(m_window.x0 + x, m_window.y0 + y), m_cap);
                        const std::uint32_t wanted =
                            m_mode == PassMode::Confidence
                                ? m_confidence->wanted(taken,
                                                       film.accumulator(std::size_t(m_window.y0 + y) * film.width() +
                                                                        std::size_t(m_window.x0 + x)))
                                : wanted_after(taken, x, y);
                        if (m_plans_per_pixel) m_plan[i] = wanted;
                        sum.wanted += wanted;
                        sum.taken += taken;
                        sum.pixels_wanting += wanted > 0;
                        if (m_mode == PassMode::Adaptive) sum.predicted += predicted_final(taken, x, y);
                        // A pixel the test stopped is done; the others may run to the cap.
                        if (m_mode == PassMode::Confidence) sum.predicted += wanted > 0 ? m_cap : taken;
                        sum.completes = sum.completes && taken + wanted >= m_cap;
                    }
                return sum;
            },
            [](Sweep a, const Sweep& b) {
                a.wanted += b.wanted;
                a.taken += b.taken;
                a.pixels_wanting += b.pixels_wanting;
                a.predicted += b.predicted;
                a.completes = a.completes && b.completes;
                return a;
            });
        m_taken_at_plan = sweep.taken;
        m_plan_completes = sweep.completes;
        m_pixels_wanting = sweep.pixels_wanting;
        m_predicted_total = sweep.predicted;
        return sweep.wanted;
    }

    // Samples the film held (each pixel counted up to the cap) when the
    // last plan was made.
    std::uint64_t taken_at_plan() const { return m_taken_at_plan; }
    // True when the current plan, carried out whole, leaves no pixel wanting
    // more: the render can end without sweeping the film once more.
    bool plan_completes() const { return m_plan_completes && m_mode != PassMode::Adaptive; }

    // Lowers the plan so that it costs at most `samples` samples by capping
    // every pixel at the largest common per-pixel count that fits. Returns
    // the new total (0 when not even one sample per pixel fits).
    std::uint64_t limit_to(std::uint64_t samples) {
        if (!m_plans_per_pixel) throw std::logic_error("PassPlanner::limit_to on a plan kept per count");
        auto total_at = [&](std::uint32_t limit) {
            std::uint64_t total = 0;
            for (std::uint32_t wanted : m_plan) total += std::min(wanted, limit);
            return total;
        };
        std::uint32_t low = 0, high = *std::max_element(m_plan.begin(), m_plan.end());
        if (total_at(high) <= samples) return total_at(high);
        m_plan_completes = false;
        while (low < high) {  // largest limit whose total fits
            const std::uint32_t middle = low + (high - low + 1) / 2;
            if (total_at(middle) <= samples)
                low = middle;
            else
                high = middle - 1;
        }
        if (low == 0 && samples > 0) return spread_one_sample(samples);
        for (std::uint32_t& planned : m_plan) planned = std::min(planned, low);
        return total_at(low);
    }

    // Pixels that want at least one more sample (in the plan before any limit).
    std::uint64_t pixels_wanting() const { return m_pixels_wanting; }
    // Adaptive mode: the samples the window will hold when every pixel
    // meets the target, as the last plan predicts from the error each
    // pixel shows (0 before the first plan over a film with samples).
    // Confidence mode: at most that many (pixels still sampling count
    // their cap).
    std::uint64_t predicted_total() const { return m_predicted_total; }

    // Samples pixel (x, y) of the window takes this pass, given the samples
    // `taken` it held when the pass began.
    std::uint32_t planned(int x, int y, std::uint32_t taken) const {
        return m_plans_per_pixel ? m_plan[index(x, y)] : wanted_after(std::min(taken, m_cap), x, y);
    }

  private:
    std::size_t index(int x, int y) const { return std::size_t(y) * m_width + x; }

    // When not every pixel can have one more sample, `samples` pixels get
    // one, spread evenly over the image (an error-diffusion walk in scan
    // order), so the last seconds of a budget are not wasted and no region
    // is favoured.
    std::uint64_t spread_one_sample(std::uint64_t samples) {
        const double share = double(samples) / double(std::max<std::uint64_t>(pixels_wanting(), 1));
        double credit = 0.0;
        std::uint64_t total = 0;
        for (std::uint32_t& planned : m_plan) {
            if (planned == 0) continue;  // wants none
            planned = 0;
            credit += share;
            if (credit >= 1.0) {
                credit -= 1.0;
                planned = 1;
                ++total;
            }
        }
        return total;
    }

    std::uint32_t wanted_after(std::uint32_t taken, int x, int y) const {
        if (taken >= m_cap) return 0;
        const std::uint32_t room = m_cap - taken;
        const std::uint32_t doubling = std::max<std::uint32_t>(taken, 1);
        if (m_mode != PassMode::Adaptive) return std::min(room, doubling);
        if (taken < m_min_samples) return std::min({room, doubling, m_min_samples - taken});
        // Relative error falls as 1/sqrt(n): aim for the n that meets the
        // target, with 10% to spare, at most doubling per pass.
        const double error_squared = pooled_relative_variance(x, y);
        const double target_squared = m_noise_target * m_noise_target;
        if (error_squared < target_squared) return 0;
        const double needed = std::ceil(double(taken) * error_squared / target_squared * 1.1);
        const double extra = std::clamp(needed - double(taken), 1.0, double(doubling));
        return std::min(room, std::uint32_t(extra));
    }

    // The samples a pixel holding `taken` will end with, by the same 1/n
    // rule as wanted_after but with no limit on the step.
    std::uint32_t predicted_final(std::uint32_t taken, int x, int y) const {
        const double least = double(std::min(std::max(m_min_samples, taken), m_cap));
        if (taken >= m_cap || taken < 2) return std::uint32_t(least);  // one sample shows no error
        const double error_squared = pooled_relative_variance(x, y);
        const double target_squared = m_noise_target * m_noise_target;
        const double needed = std::ceil(double(taken) * error_squared / target_squared * 1.1);
        return std::uint32_t(std::clamp(needed, least, double(m_cap)));
    }

    void update_relative_variance(const Film& film) {
        tbb::parallel_for(0, m_height, [&](int y) {
            for (int x = 0; x < m_width; ++x)
                m_relative_variance[index(x, y)] =
                    float(pixel_relative_variance(film, m_window.x0 + x, m_window.y0 + y));
        });
    }

    // The pixel's own estimate, or its 3x3 neighbourhood's mean if larger:
    // a pixel whose few samples happened to agree (a caustic not yet found)
    // does not stop while its neighbours are still noisy.
    double pooled_relative_variance(int x, int y) const {
        double sum = 0.0;
        int count = 0;
        for (int ny = std::max(y - 1, 0); ny <= std::min(y + 1, m_height - 1); ++ny)
            for (int nx = std::max(x - 1, 0); nx <= std::min(x + 1, m_width - 1); ++nx) {
                sum += m_relative_variance[index(nx, ny)];
                ++count;
            }
        return std::max(double(m_relative_variance[index(x, y)]), sum / count);
    }

    CropWindow m_window;
    int m_width, m_height;
    PassMode m_mode = PassMode::Fixed;
    std::uint32_t m_cap = 1;
    std::uint32_t m_min_samples = 16;
    double m_noise_target = 0.0;
    // Per pixel, this pass: what it wants, then lowered by limit_to.
    std::vector<std::uint32_t> m_plan;
    std::vector<float> m_relative_variance;  // per pixel, adaptive mode only
    std::uint64_t m_taken_at_plan = 0;
    std::uint64_t m_pixels_wanting = 0;
    std::uint64_t m_predicted_total = 0;
    bool m_plan_completes = false;
    bool m_plans_per_pixel = true;  // else m_plan stays empty
    const FocalBlurConfidence* m_confidence = nullptr;
};

}  // namespace lancer
