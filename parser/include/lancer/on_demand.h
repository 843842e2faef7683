// OnDemand<T>: a T that takes a pointer's room until something is written to
// it. Most scene-graph pigments are plain colours, yet each carried a whole
// pattern (728 bytes) and image map; a loop of 100,000 spheres paid for them
// all. Reading an empty one sees a default-constructed T; the first
// non-const access makes it. Copies are deep, as the value they replace.
#pragma once

#include <memory>
#include <utility>

namespace lancer::sg {

template <class T>
class OnDemand {
  public:
    OnDemand() = default;
    OnDemand(const T& value) : m_value(std::make_unique<T>(value)) {}
    OnDemand(T&& value) : m_value(std::make_unique<T>(std::move(value))) {}
    OnDemand(const OnDemand& other) : m_value(other.m_value ? std::make_unique<T>(*other.m_value) : nullptr) {}
    OnDemand(OnDemand&&) noexcept = default;
    OnDemand& operator=(const OnDemand& other) {
        if (this != &other) m_value = other.m_value ? std::make_unique<T>(*other.m_value) : nullptr;
        return *this;
    }
    OnDemand& operator=(OnDemand&&) noexcept = default;
    OnDemand& operator=(const T& value) {
        if (m_value)
            *m_value = value;
        else
            m_value = std::make_unique<T>(value);
        return *this;
    }
    OnDemand& operator=(T&& value) {
        if (m_value)
            *m_value = std::move(value);
        else
            m_value = std::make_unique<T>(std::move(value));
        return *this;
    }

    // Whether anything was written (for a value that is optional in the
    // scene, whether it was given).
    bool has_value() const { return m_value != nullptr; }
    explicit operator bool() const { return has_value(); }
    void reset() { m_value.reset(); }
    T& emplace() {
        m_value = std::make_unique<T>();
        return *m_value;
    }

    const T& operator*() const { return m_value ? *m_value : default_value(); }
    const T* operator->() const { return &**this; }
    T& operator*() {
        if (!m_value) m_value = std::make_unique<T>();
        return *m_value;
    }
    T* operator->() { return &**this; }

  private:
    static const T& default_value() {
        static const T value{};
        return value;
    }
    std::unique_ptr<T> m_value;
};

}  // namespace lancer::sg
