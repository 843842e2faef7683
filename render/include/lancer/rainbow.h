// POV-Ray's rainbow, as the classic integrators see it: a colour map laid
// in a ring around the antisolar direction over the radiance a ray brings
// back, fading with the distance to what it hit and towards the ends of
// its arc (POV-Ray 3.7's ComputeRainbow). Not lit: a rainbow shows
// whatever lights the scene.
#pragma once

#include <memory>
#include <vector>

#include "lancer/ray.h"

namespace lancer {

class PointPigment;

struct RainbowArc {
    double start_angle = 0.0;  // radians off the antisolar direction where the map starts
    double width = 0.0;        // radians the map spans
    double distance = 1e7;
    double jitter = 0.0;
    Vec3 antisolar{0.0f, 0.0f, 1.0f};  // unit
    Vec3 up{0.0f, 1.0f, 0.0f};         // unit, square to antisolar
    Vec3 right{1.0f, 0.0f, 0.0f};      // unit
    double arc_angle = 180.0;          // half-angles, radians (POV keeps 180 when neither is given)
    double falloff_angle = 180.0;
};

class SceneRainbows {
  public:
    // colour_maps[i]: arcs[i]'s map, read at (index, 0, 0).
    SceneRainbows(std::vector<RainbowArc> arcs, std::vector<std::unique_ptr<PointPigment>> colour_maps);
    ~SceneRainbows();
    SceneRainbows(const SceneRainbows&) = delete;
    SceneRainbows& operator=(const SceneRainbows&) = delete;

    // What is seen along unit `direction` of radiance `behind` at
    // `distance`. POV's jitter draws at random; lancer hashes the direction,
    // so a render repeats.
    Color seen_through(const Vec3& direction, float distance, const Color& behind) const;

  private:
    std::vector<RainbowArc> m_arcs;
    std::vector<std::unique_ptr<PointPigment>> m_maps;
};

}  // namespace lancer
