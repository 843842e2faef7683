// Progress of a render on stderr: a redrawn bar with ETA on a terminal, a
// line per 10% otherwise, nothing when quiet (internal to liblancer).
#pragma once

#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <mutex>

#include "lancer/host/renderer.h"

namespace lancer {

// per 10% otherwise, nothing when quiet. Safe to call from any thread.
class Progress {
    using Clock = std::chrono::steady_clock;

  public:
    explicit Progress(ProgressMode mode) : m_start(Clock::now()) {
        if (mode == ProgressMode::Auto) mode = ::isatty(STDERR_FILENO) ? ProgressMode::Bar : ProgressMode::Lines;
        m_mode = mode;
    }
    void report(double fraction) {
        if (m_mode == ProgressMode::Quiet) return;
        fraction = std::clamp(fraction, 0.0, 1.0);
        std::lock_guard<std::mutex> lock(m_mutex);
        const int percent = int(100.0 * fraction);
        const double elapsed = std::chrono::duration<double>(Clock::now() - m_start).count();
        if (m_mode == ProgressMode::Lines) {
            const int step = percent / 10 * 10;
            if (step > m_last_percent) {
                m_last_percent = step;
                std::fprintf(stderr, "progress: %d%%\n", step);
            }
            return;
        }
        if (fraction < 1.0 && elapsed - m_last_draw < 0.1) return;
        m_last_draw = elapsed;
        constexpr int kWidth = 40;
        const int filled = int(kWidth * fraction);
        const double eta = fraction > 0.0 ? elapsed * (1.0 - fraction) / fraction : 0.0;
        char bar[kWidth + 1];
        for (int i = 0; i < kWidth; ++i) bar[i] = i < filled ? '=' : ' ';
        bar[kWidth] = '\0';
        std::fprintf(stderr, "\r[%s] %3d%%  elapsed %.1fs  ETA %.1fs ", bar, percent, elapsed, eta);
        std::fflush(stderr);
    }
    void finish() {
        if (m_mode == ProgressMode::Bar && m_last_draw >= 0.0) std::fprintf(stderr, "\n");
    }

  private:
    ProgressMode m_mode;
    Clock::time_point m_start;
    std::mutex m_mutex;
    int m_last_percent = -1;
    double m_last_draw = -1.0;
};

}  // namespace lancer
