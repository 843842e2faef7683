// SIGINT and SIGTERM during a render: the first asks the render to stop
// and write what it has, a second kills at once. Shared by the commands
// that render (render, live).
#pragma once

#include <atomic>

namespace lancer::app {

// A signal handler can only reach globals; these two are its whole state.
// Lock-free atomics are async-signal-safe.
extern std::atomic<bool> g_interrupt_requested;
extern std::atomic<int> g_interrupt_signal;

// Installs the handlers for its lifetime (clearing the two flags) and
// restores the previous ones after.
class InterruptHandlers {
  public:
    InterruptHandlers();
    ~InterruptHandlers();
    InterruptHandlers(const InterruptHandlers&) = delete;
    InterruptHandlers& operator=(const InterruptHandlers&) = delete;

  private:
    void (*m_previous_int)(int);
    void (*m_previous_term)(int);
};

}  // namespace lancer::app
