// Height fields shared while one is alive. A height field made from a
// function evaluates it width x height times, one from an image decodes the
// file: a height field declared once and placed several times was made once
// per placement. (trace() while parsing builds its object alone and frees
// it before the render is built, so the render makes its own.)
#pragma once

#include <functional>
#include <memory>

#include "geometry/shape.h"
#include "lancer/scene_graph.h"

namespace lancer {

using MakeShape = std::function<std::shared_ptr<const Shape>()>;

// The shape `make` gives for `field`, a `height_field { function W, H {…} }`:
// one made earlier for the same function, size, noise generator, smoothing
// and water level while it is still in use, else `make()`'s, kept for the
// next caller only as long as someone holds it. Thread-safe.
std::shared_ptr<const Shape> shared_function_height_field(const sg::HeightField& field, const MakeShape& make);

// The same for a height field read from an image file: shared by the
// file's path, the length and hash of its bytes, the gamma, smoothing and
// water level. `make` throws as it would alone (nothing is kept then).
std::shared_ptr<const Shape> shared_image_height_field(const sg::HeightField& field, const MakeShape& make);

}  // namespace lancer
