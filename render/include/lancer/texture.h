// Pigments: the colour, filter and transmit of a surface at a hit.
//
// Pattern space: procedural patterns (checker) and POV map_type projections
// are evaluated at the hit point in the space of the object the texture was
// attached to, transformed by the pigment's own transforms. (u,v) mapping
// uses Hit::uv with v = 1 at the top row of an image, as POV-Ray's.
#pragma once

#include "lancer/hit.h"

namespace lancer {

struct TextureSample {
    Color rgb{0.0f};  // linear
    float filter = 0.0f;
    float transmit = 0.0f;
};

class Texture {
  public:
    virtual ~Texture() = default;
    // The pigment at a hit returned by RenderScene::intersect (or built by a
    // light sampler on the same object; object_id must be valid).
    virtual TextureSample evaluate(const Hit& hit) const = 0;
    // Mean over the texture's area, for light power and proxies.
    virtual TextureSample average() const = 0;
    // The value everywhere, for a texture that does not vary; else null.
    // Lets a material skip the per-hit lookup.
    virtual const TextureSample* constant() const { return nullptr; }
};

}  // namespace lancer
