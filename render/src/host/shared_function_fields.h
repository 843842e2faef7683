// Height fields made from a function, shared while one is alive: a scene
// that trace()s its terrain while it is parsed (POV-Ray's
// advanced/landscape.pov places its 256 trees so) has that object built
// alone for the question (parse_time_geometry.cpp) and again for the
// render, and each build would evaluate the function width x height times.
#pragma once

#include <functional>
#include <memory>

#include "geometry/shape.h"
#include "lancer/scene_graph.h"

namespace lancer {

// The shape `make` gives for `field` (a `height_field { function W, H {…} }`)
// with patterns of `noise_generator` by default: one made earlier for the
// same function, size, smoothing and water level while it is still in use,
// else `make()`'s, kept for the next caller only as long as someone holds
// it. Thread-safe.
std::shared_ptr<const Shape> shared_function_height_field(const sg::HeightField& field, int noise_generator,
                                                          const std::function<std::shared_ptr<const Shape>()>& make);

}  // namespace lancer
