// Advice that a big array be backed by the kernel's huge pages: a scene of
// a million triangles holds its text, tokens and mesh in arrays of tens of
// megabytes, and faulting them in 4 KB at a time cost as much as reading
// them (the film's arrays get the same advice, render/src/film/zeroed_pages).
#pragma once

#include <sys/mman.h>

#include <cstddef>
#include <cstdint>
#include <new>
#include <stdexcept>

namespace lancer::parse {

// Below this an array is not worth a system call.
constexpr std::size_t kHugePageAdviceBytes = std::size_t(8) << 20;

// For storage not yet written (after a reserve): pages already touched
// keep their size. Only advice: where the kernel declines, nothing changes.
inline void advise_huge_pages(const void* data, std::size_t bytes) {
#ifdef MADV_HUGEPAGE
    if (data == nullptr || bytes < kHugePageAdviceBytes) return;
    constexpr std::uintptr_t kPage = 4096;
    const auto start = (reinterpret_cast<std::uintptr_t>(data) + kPage - 1) & ~(kPage - 1);
    const auto end = (reinterpret_cast<std::uintptr_t>(data) + bytes) & ~(kPage - 1);
    if (end > start) madvise(reinterpret_cast<void*>(start), end - start, MADV_HUGEPAGE);
#else
    (void)data;
    (void)bytes;
#endif
}

// Room for `count` elements, reserved ahead to spare the copies and page
// faults of growing: an estimate, so where the system refuses that much
// address space, the vector is left to grow as it is filled.
template <typename Vector>
void reserve_on_huge_pages(Vector& v, std::size_t count) {
    try {
        v.reserve(count);
    } catch (const std::bad_alloc&) {
        return;
    } catch (const std::length_error&) {
        return;
    }
    advise_huge_pages(v.data() + v.size(), (v.capacity() - v.size()) * sizeof(*v.data()));
}

}  // namespace lancer::parse
