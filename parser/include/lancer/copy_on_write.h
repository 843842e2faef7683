// CopyOnWrite<T>: a T shared between copies until one of them is written.
// Every texture starts from the default texture's finish and interior, and
// most objects of a loop never change them: each copy used to carry its own
// (360 bytes a material). Reading an empty one sees a default-constructed T;
// non-const access first makes the value this copy's own. Not for values
// written from several threads (the scene graph is built by one).
#pragma once

#include <memory>

namespace lancer::sg {

template <class T>
class CopyOnWrite {
  public:
    CopyOnWrite() = default;
    CopyOnWrite(const T& value) : m_value(std::make_shared<T>(value)) {}
    CopyOnWrite& operator=(const T& value) {
        m_value = std::make_shared<T>(value);
        return *this;
    }

    // Whether a value was ever written or assigned.
    bool has_value() const { return m_value != nullptr; }
    // Whether this copy and `other` read the very same value.
    bool shares_with(const CopyOnWrite& other) const { return m_value == other.m_value; }

    const T& operator*() const { return m_value ? *m_value : default_value(); }
    const T* operator->() const { return &**this; }
    T& operator*() {
        if (!m_value)
            m_value = std::make_shared<T>();
        else if (m_value.use_count() > 1)
            m_value = std::make_shared<T>(*m_value);
        return *m_value;
    }
    T* operator->() { return &**this; }

  private:
    static const T& default_value() {
        static const T value{};
        return value;
    }
    std::shared_ptr<T> m_value;
};

}  // namespace lancer::sg
