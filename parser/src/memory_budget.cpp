#include "memory_budget.h"

#include <unistd.h>
#include <cstdio>

namespace lancer::parse {

long long resident_bytes() {
    std::FILE* file = std::fopen("/proc/self/statm", "r");
    if (!file) return 0;
    long long size = 0, resident = 0;
    const bool ok = std::fscanf(file, "%lld %lld", &size, &resident) == 2;
    std::fclose(file);
    return ok ? resident * static_cast<long long>(sysconf(_SC_PAGESIZE)) : 0;
}

MemoryBudget::MemoryBudget(long long max_bytes)
    : m_max(max_bytes), m_baseline(resident_bytes()), m_next_read(std::chrono::steady_clock::now()) {}

void MemoryBudget::read() {
    const long long now = resident_bytes();
    m_used = now > m_baseline ? now - m_baseline : 0;
    m_next_read = std::chrono::steady_clock::now() + std::chrono::milliseconds(1);
}

bool MemoryBudget::exceeded() {
    if (std::chrono::steady_clock::now() >= m_next_read) read();
    return m_used > m_max;
}

bool MemoryBudget::would_exceed(long long bytes) {
    read();
    return bytes > m_max - m_used;
}

}  // namespace lancer::parse

#include <string>

#include "evaluator.h"

namespace lancer::parse {

namespace {

std::string mebibytes(long long bytes) {
    return std::to_string((bytes + (1 << 20) - 1) >> 20) + " MiB";
}

}  // namespace

bool Evaluator::memory_exhausted(const sg::SourceLocation& at, long long more) {
    if (more > 0 ? !m_memory.would_exceed(more) : !m_memory.exceeded()) return false;
    const std::string budget = mebibytes(m_memory.max_bytes());
    if (more > 0)
        error(at, "this needs about " + mebibytes(more) + " and the parse already holds " +
                      mebibytes(m_memory.used_bytes()) + ", past its memory budget of " + budget +
                      " (--max-memory, ParseOptions::max_memory_bytes)");
    else
        error(at, "the parse holds " + mebibytes(m_memory.used_bytes()) + ", past its memory budget of " + budget +
                      " (--max-memory, ParseOptions::max_memory_bytes): a loop or recursive macro that keeps "
                      "growing arrays, objects or strings?");
    abort_parse();
    return true;
}

}  // namespace lancer::parse
