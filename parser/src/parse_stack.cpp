#include "parse_stack.h"

#include <pthread.h>

#include <exception>

namespace lancer::parse {

namespace {

// The first address of the parse thread's stack in use (its top, as stacks
// grow down), and how much of it the parse may use.
thread_local const char* t_stack_top = nullptr;
thread_local std::size_t t_stack_bytes = 0;

struct Job {
    const std::function<void()>* work;
    std::exception_ptr failure;
};

void* run_job(void* argument) {
    Job& job = *static_cast<Job*>(argument);
    char top = 0;
    t_stack_top = &top;
    t_stack_bytes = kParseStackBytes;
    try {
        (*job.work)();
    } catch (...) {
        job.failure = std::current_exception();
    }
    t_stack_top = nullptr;
    return nullptr;
}

}  // namespace

void run_on_parse_stack(const std::function<void()>& work) {
    Job job{&work, nullptr};
    pthread_attr_t attributes;
    pthread_t thread;
    bool started = pthread_attr_init(&attributes) == 0;
    if (started) {
        started = pthread_attr_setstacksize(&attributes, kParseStackBytes) == 0 &&
                  pthread_create(&thread, &attributes, run_job, &job) == 0;
        pthread_attr_destroy(&attributes);
    }
    if (!started) {
        work();
        return;
    }
    pthread_join(thread, nullptr);
    if (job.failure) std::rethrow_exception(job.failure);
}

bool parse_stack_nearly_full() {
    if (!t_stack_top) return false;
    char here = 0;
    const std::size_t used = static_cast<std::size_t>(t_stack_top - &here);
    return used > t_stack_bytes / 4 * 3;
}

}  // namespace lancer::parse
