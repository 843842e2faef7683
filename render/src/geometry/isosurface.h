// POV-Ray's isosurface (internal to liblancer): the surface where a user
// function equals a threshold inside a box or sphere, found by POV's
// interval subdivision (see isosurface.cpp).
#pragma once

#include <atomic>
#include <memory>
#include <optional>
#include <string>

#include "geometry/contained_by.h"
#include "geometry/shape.h"
#include "lancer/function.h"

namespace lancer {

struct IsosurfaceParameters {
    std::shared_ptr<const sg::Function> function;
    // What the function asks of the renderer (noise, patterns); null when
    // it asks for nothing.
    std::shared_ptr<const sg::FunctionNatives> natives;
    ContainedBy container;
    double threshold = 0.0;
    double accuracy = 0.001;
    double max_gradient = 1.1;
    bool evaluate = false;
    DVec3 evaluate_parameters{0.0};  // POV's evaluate P0, P1, P2
    bool open = false;
    int max_trace = 1;
};

// The steepest slope of the function any ray met while looking for roots,
// along the ray in the isosurface's own space: what POV-Ray compares with
// max_gradient when it warns after a render. Shared by every thread.
class IsosurfaceGradientRecord {
  public:
    void record(double slope) {
        double seen = m_steepest.load(std::memory_order_relaxed);
        while (slope > seen && !m_steepest.compare_exchange_weak(seen, slope, std::memory_order_relaxed)) {
        }
    }
    double steepest() const { return m_steepest.load(std::memory_order_relaxed); }

  private:
    std::atomic<double> m_steepest{0.0};
};

// Null for a function that is missing or parameters that are not finite.
std::shared_ptr<const Shape> make_isosurface_shape(const IsosurfaceParameters& parameters,
                                                   std::shared_ptr<IsosurfaceGradientRecord> gradients = nullptr);

// POV-Ray's advice after a render, from the slope found and the
// max_gradient given: holes when max_gradient was too low, slowness when
// far too high; nothing when it fits or `evaluate` chose it.
std::optional<std::string> isosurface_gradient_advice(const IsosurfaceParameters& parameters,
                                                      const IsosurfaceGradientRecord& gradients);

}  // namespace lancer
