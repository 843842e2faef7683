// The interrupt handlers of interrupts.h.
#include "interrupts.h"

#include <csignal>

namespace lancer::app {

std::atomic<bool> g_interrupt_requested{false};
std::atomic<int> g_interrupt_signal{0};

namespace {

extern "C" void request_interrupt(int signal_number) {
    g_interrupt_signal.store(signal_number);
    g_interrupt_requested.store(true);
    // A second signal kills at once, for a user who will not wait.
    std::signal(signal_number, SIG_DFL);
}

}  // namespace

InterruptHandlers::InterruptHandlers() {
    g_interrupt_requested = false;
    g_interrupt_signal = 0;
    m_previous_int = std::signal(SIGINT, request_interrupt);
    m_previous_term = std::signal(SIGTERM, request_interrupt);
}

InterruptHandlers::~InterruptHandlers() {
    std::signal(SIGINT, m_previous_int);
    std::signal(SIGTERM, m_previous_term);
}

}  // namespace lancer::app
