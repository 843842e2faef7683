// Large arrays come from their own anonymous mapping, aligned to a huge
// page and advised to use them; small ones from calloc, which hands out
// zeroed memory without writing it when it takes fresh pages.
#include <sys/mman.h>

#include <cstdint>
#include <cstdlib>
#include <new>

#include "lancer/host/zeroed_array.h"

namespace lancer::zeroed_pages {

namespace {
constexpr std::size_t kHugePage = std::size_t(2) << 20;
// Below this, a mapping of its own costs more than the faults it saves.
constexpr std::size_t kOwnMapping = kHugePage;

std::size_t mapped_size(std::size_t bytes) {
    return (bytes + kHugePage - 1) / kHugePage * kHugePage;
}
}  // namespace

void* acquire(std::size_t bytes) {
    if (bytes == 0) return nullptr;
    if (bytes < kOwnMapping) {
        void* storage = std::calloc(1, bytes);
        if (storage == nullptr) throw std::bad_alloc();
        return storage;
    }
    const std::size_t size = mapped_size(bytes);
    if (size < bytes) throw std::bad_alloc();
    // Over-map by one huge page, then give back what lies outside the
    // aligned range, so the kernel can back all of it with huge pages.
    void* mapping = mmap(nullptr, size + kHugePage, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapping == MAP_FAILED) throw std::bad_alloc();
    const auto start = reinterpret_cast<std::uintptr_t>(mapping);
    const std::uintptr_t aligned = (start + kHugePage - 1) & ~(std::uintptr_t(kHugePage) - 1);
    if (aligned > start) munmap(mapping, aligned - start);
    if (const std::size_t tail = start + kHugePage - aligned; tail > 0)
        munmap(reinterpret_cast<void*>(aligned + size), tail);
#ifdef MADV_HUGEPAGE
    madvise(reinterpret_cast<void*>(aligned), size, MADV_HUGEPAGE);  // advice: failure only costs faults
#endif
    return reinterpret_cast<void*>(aligned);
}

void release(void* storage, std::size_t bytes) {
    if (storage == nullptr) return;
    if (bytes < kOwnMapping)
        std::free(storage);
    else
        munmap(storage, mapped_size(bytes));
}

}  // namespace lancer::zeroed_pages
