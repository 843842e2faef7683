// Height fields shared while one is alive. A height field made from a
// function evaluates it width x height times, one from an image decodes the
// file; a scene that trace()s its terrain while it is parsed (POV-Ray's
// advanced/landscape.pov places its 256 trees so) has that object built
// alone for the question (parse_time_geometry.cpp) and again for the
// render, and a declared height field placed several times was made once
// per placement.
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
// file's path, size and modification time, the gamma, smoothing and water
// level. `make` throws as it would alone (nothing is kept then).
std::shared_ptr<const Shape> shared_image_height_field(const sg::HeightField& field, const MakeShape& make);

}  // namespace lancer
