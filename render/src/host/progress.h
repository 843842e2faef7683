// Progress of a render on stderr: a redrawn bar with ETA on a terminal, a
// line per 10% otherwise, nothing when quiet (internal to liblancer).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <string>

#include "lancer/host/renderer.h"

namespace lancer {

// The fraction reported is the render's own; with a ProgressShare it
// counts as one part of a longer job, whose fraction and ETA are shown.
// The ETA is "--" until there is something to extrapolate from, and the
// bar never moves back (an adaptive render's prediction of its remaining
// work can grow). Safe to call from any thread.
class Progress {
    using Clock = std::chrono::steady_clock;

  public:
    Progress(ProgressMode mode, ProgressShare share) : m_share(std::move(share)), m_start(Clock::now()) {
        if (mode == ProgressMode::Auto) mode = ::isatty(STDERR_FILENO) ? ProgressMode::Bar : ProgressMode::Lines;
        m_mode = mode;
        m_share.parts = std::max(m_share.parts, 1);
    }
    void report(double fraction) {
        if (m_mode == ProgressMode::Quiet) return;
        std::lock_guard<std::mutex> lock(m_mutex);
        m_fraction = std::max(m_fraction, std::clamp(fraction, 0.0, 1.0));
        const int percent = int(100.0 * m_fraction);
        const double elapsed = seconds();
        if (m_mode == ProgressMode::Lines) {
            const int step = percent / 10 * 10;
            if (step > m_last_percent) {
                m_last_percent = step;
                std::fprintf(stderr, "progress: %d%%%s\n", step, details(elapsed).c_str());
            }
            return;
        }
        if (m_fraction < 1.0 && elapsed - m_last_draw < 0.1) return;
        m_last_draw = elapsed;
        draw(percent, details(elapsed));
    }
    // The render ended. Interrupted, it says so at the fraction it reached
    // instead of claiming 100%.
    void finish(bool interrupted) {
        if (m_mode == ProgressMode::Quiet) return;
        std::lock_guard<std::mutex> lock(m_mutex);
        const int percent = int(100.0 * m_fraction);
        if (interrupted) {
            if (m_mode == ProgressMode::Lines)
                std::fprintf(stderr, "progress: interrupted at %d%%\n", percent);
            else
                draw(percent, "  interrupted");
        }
        if (m_mode == ProgressMode::Bar && m_last_draw >= 0.0) std::fprintf(stderr, "\n");
    }

  private:
    double seconds() const { return std::chrono::duration<double>(Clock::now() - m_start).count(); }

    // "  [frame 3, 25% of all]  elapsed 1.2s  ETA 3.6s": the job's elapsed
    // time and ETA when the render is part of one.
    std::string details(double elapsed) const {
        const double job_fraction = (m_share.part + m_fraction) / m_share.parts;
        const double job_elapsed = m_share.seconds_before + elapsed;
        std::string text;
        char buffer[128];
        if (m_share.parts > 1 || !m_share.label.empty()) {
            std::snprintf(buffer, sizeof buffer, "  [%s%s%d%% of all]", m_share.label.c_str(),
                          m_share.label.empty() ? "" : ", ", int(100.0 * job_fraction));
            text += buffer;
        }
        // Too little done, or too soon, to extrapolate from.
        if (job_fraction < 0.005 || job_elapsed < 0.2) {
            std::snprintf(buffer, sizeof buffer, "  elapsed %.1fs  ETA --", job_elapsed);
        } else {
            const double eta = job_elapsed * (1.0 - job_fraction) / job_fraction;
            std::snprintf(buffer, sizeof buffer, "  elapsed %.1fs  ETA %.1fs", job_elapsed, eta);
        }
        return text + buffer;
    }
    void draw(int percent, const std::string& details) {
        constexpr int kWidth = 40;
        const int filled = int(kWidth * m_fraction);
        char bar[kWidth + 1];
        for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '=' : ' ';
        bar[kWidth] = '\0';
        // Clears what a longer line drawn before left at its end.
        std::fprintf(stderr, "\r[%s] %3d%%%s\x1b[K", bar, percent, details.c_str());
        std::fflush(stderr);
    }

    ProgressMode m_mode;
    ProgressShare m_share;
    Clock::time_point m_start;
    std::mutex m_mutex;
    double m_fraction = 0.0;
    int m_last_percent = -1;
    double m_last_draw = -1.0;
};

}  // namespace lancer
