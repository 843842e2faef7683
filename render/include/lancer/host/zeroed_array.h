// A fixed-size array of zeros taken from fresh pages, for the film's
// per-pixel totals. std::vector::assign writes every element before a render
// writes them again: at 1280x960 that pass and its page faults were a tenth
// of a one-sample render's CPU time. Fresh anonymous pages already read as
// zero; their faults come at the first write, in the render's own threads,
// and a large array asks for huge pages, so the faults are few.
#pragma once

#include <cstddef>
#include <cstring>
#include <type_traits>
#include <utility>

namespace lancer {

namespace zeroed_pages {
// Zero-filled storage of at least `bytes` (nullptr for 0); throws
// std::bad_alloc when the system has none.
void* acquire(std::size_t bytes);
void release(void* storage, std::size_t bytes);
}  // namespace zeroed_pages

// T must read all-zero bytes as its zero value (integers, floats, glm
// vectors of them).
template <typename T>
class ZeroedArray {
    static_assert(std::is_trivially_copyable_v<T> && std::is_trivially_destructible_v<T>);

  public:
    ZeroedArray() = default;
    explicit ZeroedArray(std::size_t size)
        : m_data(static_cast<T*>(zeroed_pages::acquire(size * sizeof(T)))), m_size(size) {}
    ZeroedArray(const ZeroedArray& other) : ZeroedArray(other.m_size) {
        if (m_size > 0) std::memcpy(m_data, other.m_data, m_size * sizeof(T));
    }
    ZeroedArray(ZeroedArray&& other) noexcept : m_data(other.m_data), m_size(other.m_size) {
        other.m_data = nullptr;
        other.m_size = 0;
    }
    ZeroedArray& operator=(ZeroedArray other) noexcept {
        std::swap(m_data, other.m_data);
        std::swap(m_size, other.m_size);
        return *this;
    }
    ~ZeroedArray() { zeroed_pages::release(m_data, m_size * sizeof(T)); }

    std::size_t size() const { return m_size; }
    T& operator[](std::size_t i) { return m_data[i]; }
    const T& operator[](std::size_t i) const { return m_data[i]; }
    T* begin() { return m_data; }
    T* end() { return m_data + m_size; }
    const T* begin() const { return m_data; }
    const T* end() const { return m_data + m_size; }

  private:
    T* m_data = nullptr;
    std::size_t m_size = 0;
};

}  // namespace lancer
