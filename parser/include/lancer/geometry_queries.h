// What a scene may ask of its objects while it is parsed: POV-Ray's
// trace(), inside(), min_extent() and max_extent(), used to place objects on
// others. The parser declares the questions; the render core answers them
// (lancer/host/scene_compiler.h), so the parser knows nothing of how
// objects are intersected.
#pragma once

#include <memory>

#include <glm/glm.hpp>

namespace lancer::sg {

struct Object;
struct GlobalSettings;

class GeometryQueries {
  public:
    virtual ~GeometryQueries() = default;

    struct Crossing {
        bool found = false;
        glm::dvec3 point{0.0};
        glm::dvec3 normal{0.0};  // the surface's own (outward) unit normal there
    };
    // Each question comes with the global_settings read so far, as POV-Ray
    // asks it: what the object's patterns and functions default to (the
    // noise_generator of an isosurface's noise; a function height field
    // keeps its own, sg::HeightField::function_noise_generator).
    //
    // The nearest crossing of the ray from `origin` along `direction` (not
    // necessarily unit) with the object. The object is shared so an
    // answerer may keep what it built for it while the object lives.
    // Throws std::runtime_error for an object that cannot be built.
    virtual Crossing trace(const std::shared_ptr<const Object>& object, const GlobalSettings& settings,
                           const glm::dvec3& origin, const glm::dvec3& direction) const = 0;
    // POV-Ray's inside test of the object's solid.
    virtual bool inside(const std::shared_ptr<const Object>& object, const GlobalSettings& settings,
                        const glm::dvec3& point) const = 0;
    // The object's world bounding box; false for an unbounded object.
    virtual bool bounds(const std::shared_ptr<const Object>& object, const GlobalSettings& settings, glm::dvec3& lower,
                        glm::dvec3& upper) const = 0;
};

}  // namespace lancer::sg
