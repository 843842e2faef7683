// Lights as integrators see them. Units (docs/scene-language.md#lights):
// a point light of `color C` has radiant intensity pi*C, so a white matte
// surface facing it at distance 1 shows radiance C, as in POV-Ray; falloff
// is inverse-square unless the scene gives POV's fade_distance/fade_power.
#pragma once

#include <cstdint>

#include "lancer/hit.h"
#include "lancer/ray.h"

namespace lancer {

// Incident light at a shading point p, from one sample on one light.
// A direct-lighting estimate is f(wo, wi) * |cos(n, wi)| * radiance / pdf,
// counted only if the shadow ray from p to `point` is unoccluded.
struct LightSample {
    Color radiance{0.0f};  // incident radiance (delta lights: intensity * attenuation)
    Vec3 wi{0.0f};         // unit, from p towards the light
    float distance = 0.0f; // from p to `point` (infinite for directional)
    Vec3 point{0.0f};      // the sampled point (directional: far along wi)
    float pdf = 0.0f;      // solid-angle density; 1 for delta lights; 0 = no sample
    bool is_delta = false;
};

class Light {
public:
    enum class Kind { Point, Directional, Rectangle, Sphere, EmissiveShape };

    virtual ~Light() = default;
    virtual Kind kind() const = 0;
    bool is_delta() const {
        const Kind k = kind();
        return k == Kind::Point || k == Kind::Directional;
    }

    // Sample incident light at p; u uniform in [0,1)^2.
    virtual LightSample sample(const Vec3& p, const Vec2& u) const = 0;
    // Solid-angle density with which sample() would pick direction wi from p
    // and reach `light_hit` (a hit on this light's surface). 0 for delta lights.
    virtual float pdf(const Vec3& p, const Vec3& wi, const Hit& light_hit) const { return 0.0f; }
    // Radiance leaving the light's surface at `light_hit` towards wo
    // (area lights and emitters; black for delta lights).
    virtual Color emitted(const Hit& light_hit, const Vec3& wo) const { return Color(0.0f); }
    // Total emitted power in scene units, for light selection and proxies.
    virtual Color power() const = 0;

    // The point or directional light that stands in for this one in the
    // seed's simple local model (raycast, shadow, gather). Point and
    // directional lights are their own proxy.
    virtual const Light& proxy() const { return *this; }

    // True for a point light without fade or pattern whose sample() at any
    // p with squared distance d2 in (kPlainRangeLow, kPlainRangeHigh) is, in
    // float: wi = (position - p) / sqrt(d2), radiance = intensity * (1 /
    // sqrt(d2))^2, pdf 1. Lets an integrator evaluate many such samples at
    // once, bit for bit as sample() would.
    virtual bool inverse_square_point(Vec3& position, Color& intensity) const { return false; }
    static constexpr float kPlainRangeLow = 1e-30f, kPlainRangeHigh = 1e30f;
};

}  // namespace lancer
