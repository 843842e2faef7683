// The evaluator's memory budget (ParseOptions::max_memory_bytes): what the
// process holds beyond what it held when the parse began. A scene can grow
// memory without bound only by repeating work (a #while, a recursive
// macro), so the evaluator asks at each loop iteration and macro call, and
// before it makes an array; asking costs a clock read, and the resident size
// is read at most once a millisecond.
#pragma once

#include <chrono>
#include <cstddef>

namespace lancer::parse {

// Bytes resident in this process now (/proc/self/statm), 0 when unknown.
long long resident_bytes();

class MemoryBudget {
  public:
    explicit MemoryBudget(long long max_bytes);

    // Whether the process has grown past the budget since the parse began
    // (a cheap answer from the last reading within a millisecond of it).
    bool exceeded();
    // Whether `bytes` more would cross the budget (read now).
    bool would_exceed(long long bytes);

    long long max_bytes() const { return m_max; }
    long long used_bytes() const { return m_used; }

  private:
    void read();

    long long m_max;
    long long m_baseline;
    long long m_used = 0;
    std::chrono::steady_clock::time_point m_next_read;
};

}  // namespace lancer::parse
