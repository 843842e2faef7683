// POV-Ray's fog, as the classic integrators see it: the radiance a ray
// brings from a surface (or the sky) fades into the fog's colour with the
// distance it ran, evenly (constant fog) or thicker near the ground
// (ground fog), broken up by turbulence. Not a physical medium: it neither
// scatters light from the lights nor shadows it, except where a light's
// media_attenuation asks for it (POV-Ray 3.7's ComputeFog).
#pragma once

#include <vector>

#include "lancer/ray.h"

namespace lancer {

struct FogLayer {
    bool ground = false;  // fog_type 2
    float distance = 0.0f;
    Color color{0.0f};
    float filter = 0.0f;
    float transmit = 0.0f;  // the least transmittance the fog keeps
    float offset = 0.0f;
    float alt = 1.0f;
    Vec3 up{0.0f, 1.0f, 0.0f};  // unit
    bool turbulent = false;
    Vec3 turbulence{0.0f};
    float turb_depth = 0.5f;
    int octaves = 6;
    float omega = 0.5f;
    float lambda = 2.0f;
};

class SceneFog {
  public:
    // noise_generator: global_settings' (1 to 3), for the turbulence.
    SceneFog(std::vector<FogLayer> layers, int noise_generator);

    // What is seen from `origin` along unit `direction` of radiance
    // `behind` at `distance` (kFogEscapeDistance for a ray that escaped).
    Color seen_through(const Vec3& origin, const Vec3& direction, float distance, const Color& behind) const;
    // What the fog lets through over a shadow ray's length.
    Color transmittance(const Vec3& origin, const Vec3& direction, float distance) const;

  private:
    struct Passage {
        Color attenuation{1.0f};
        Color added{0.0f};
    };
    Passage passage(const Vec3& origin, const Vec3& direction, float distance) const;
    double layer_transmittance(const FogLayer& fog, const Vec3& origin, const Vec3& direction, double width) const;

    std::vector<FogLayer> m_layers;
    int m_noise_generator;
};

// POV's distance for a ray that escapes (BOUND_HUGE).
inline constexpr float kFogEscapeDistance = 2.0e10f;

}  // namespace lancer
