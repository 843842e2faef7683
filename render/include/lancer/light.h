// Lights as integrators see them. Units (docs/scene-language.md#lights):
// a POV point light of `color C` reaches a surface as radiance pi*C, so a
// white matte surface facing it shows C, as in POV-Ray, at any distance
// (POV's fade_distance/fade_power when given); the point proxies of the
// physical lamps fall off with the inverse square of the distance.
#pragma once

#include <cmath>
#include <cstdint>

#include "lancer/hit.h"
#include "lancer/ray.h"

namespace lancer {

// Incident light at a shading point p, from one sample on one light.
// A direct-lighting estimate is f(wo, wi) * |cos(n, wi)| * radiance / pdf,
// counted only if the shadow ray from p to `point` is unoccluded.
struct LightSample {
    Color radiance{0.0f};   // incident radiance (delta lights: intensity * attenuation)
    Vec3 wi{0.0f};          // unit, from p towards the light
    float distance = 0.0f;  // from p to `point` (infinite for directional)
    Vec3 point{0.0f};       // the sampled point (directional: far along wi)
    float pdf = 0.0f;       // solid-angle density; 1 for delta lights; 0 = no sample
    bool is_delta = false;
};

class Light {
  public:
    enum class Kind { Point, Directional, PovArea, Rectangle, Sphere, EmissiveShape, Environment };

    virtual ~Light() = default;
    virtual Kind kind() const = 0;
    // Lights that no ray can hit: their light arrives from one direction at
    // a time (POV's area light too: it lights from its centre).
    bool is_delta() const {
        const Kind k = kind();
        return k == Kind::Point || k == Kind::Directional || k == Kind::PovArea;
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

    // False for POV's `shadowless` lights: they light every surface facing
    // them and no shadow ray is cast towards them.
    bool casts_shadows() const { return m_casts_shadows; }
    void set_casts_shadows(bool casts) { m_casts_shadows = casts; }
    // POV's media_interaction (on by default): whether participating media
    // scatter this light. POV's media_attenuation (off by default): whether
    // the classic integrators dim it by the atmosphere on its way to a
    // surface (`path` always does, physically).
    bool lights_media() const { return m_lights_media; }
    // POV's light_group it belongs to (-1: a global light); see light_reaches.
    int light_group() const { return m_light_group; }
    void set_light_group(int group) { m_light_group = group; }
    bool dimmed_by_atmosphere() const { return m_dimmed_by_atmosphere; }
    void set_media_interaction(bool lights_media, bool dimmed_by_atmosphere) {
        m_lights_media = lights_media;
        m_dimmed_by_atmosphere = dimmed_by_atmosphere;
    }

    // The point or directional light that stands in for this one in the
    // seed's simple local model (raycast, shadow, gather). Point and
    // directional lights are their own proxy.
    virtual const Light& proxy() const { return *this; }

    // This light's parameters as `Parameters` (PointLightParameters,
    // DirectionalLightParameters, PovAreaLightParameters,
    // RectangleLightParameters, SphereLightParameters, EmissiveShapeParameters,
    // below), or null when the light is of another
    // kind. For integrators that evaluate a kind of light themselves; new
    // kinds of light add a parameter struct, not a method.
    template <class Parameters>
    const Parameters* parameters() const {
        return static_cast<const Parameters*>(parameters_of(Parameters::kKind));
    }

  protected:
    // The parameter struct of `kind` when this light is of that kind.
    virtual const void* parameters_of(Kind kind) const { return nullptr; }
    // For overrides: `parameters` when `kind` is its struct's kind.
    template <class Parameters>
    static const void* parameters_if(Kind kind, const Parameters& parameters) {
        return kind == Parameters::kKind ? &parameters : nullptr;
    }

  private:
    bool m_casts_shadows = true;
    bool m_lights_media = true;
    bool m_dimmed_by_atmosphere = false;
    int m_light_group = -1;
};

// POV's light_group rule: a group's lights light only the group's objects;
// the scene's other lights light every object outside the groups, and
// those of groups with global_lights on.
inline bool light_reaches(const Light& light, const Hit& hit) {
    return light.light_group() < 0 ? hit.lit_by_global_lights : light.light_group() == hit.light_group;
}

// How a point light's radiance changes with distance when it has no fade.
enum class PointFalloff {
    None,           // POV-Ray's point light: the same at every distance
    InverseSquare,  // a physical point: the proxies of lancer's physical lamps and emitters
};

// POV's point light; also the proxy of every physical lamp and emitter.
struct PointLightParameters {
    static constexpr Light::Kind kKind = Light::Kind::Point;
    Vec3 position{0.0f};
    // Radiance arriving from it at distance 1 on the pattern's axis (a POV
    // light of colour C: pi*C, so a white matte surface facing it shows C).
    Color intensity{0.0f};
    PointFalloff falloff = PointFalloff::InverseSquare;
    // POV's fade when fade_power > 0: 2 / (1 + (d / fade_distance)^fade_power),
    // or d^-fade_power when fade_distance is 0; instead of `falloff`.
    float fade_distance = 0.0f;
    float fade_power = 0.0f;
    Vec3 pattern_axis{0.0f};  // non-zero: a cosine pattern about it (proxies of flat emitters)
    bool one_sided = false;   // pattern max(0, cos) rather than |cos|
    // POV's spotlight when spot_axis is non-zero (unit, light -> point_at):
    // at cos c of the angle from the axis, c^tightness, times a smooth step
    // from 0 at spot_cos_falloff to 1 at spot_cos_radius; nothing behind.
    Vec3 spot_axis{0.0f};
    float spot_cos_radius = 1.0f;
    float spot_cos_falloff = 1.0f;
    float tightness = 0.0f;

    // No fade, no pattern, no cone: sample() is plain_point_incidence's
    // arithmetic wherever in_plain_point_range(d^2).
    bool is_plain() const {
        return fade_distance == 0.0f && fade_power == 0.0f && pattern_axis == Vec3(0.0f) && spot_axis == Vec3(0.0f);
    }
};

// POV's `parallel` light: the same irradiance from one direction everywhere,
// and POV's `cylinder` light, the same confined to a beam. Its shadow rays
// end at the plane through `position` across the light (POV's rule).
struct DirectionalLightParameters {
    static constexpr Light::Kind kKind = Light::Kind::Directional;
    Vec3 to_light{0.0f, 1.0f, 0.0f};  // unit
    Color irradiance{0.0f};           // on a surface facing the light
    Vec3 position{0.0f};
    // POV's fade when fade_power > 0, at the distance to the light's plane
    // (as PointLightParameters).
    float fade_distance = 0.0f;
    float fade_power = 0.0f;
    // POV's cylinder light when beam_falloff > 0: nothing behind the
    // light's plane or beam_falloff or more from the axis through
    // `position`; at distance r from it, (1 - r / beam_falloff)^tightness,
    // times a smooth step up to 1 inside beam_radius.
    float beam_radius = 0.0f;
    float beam_falloff = 0.0f;
    float tightness = 0.0f;
};

// POV-Ray's area_light: a point light at the centre of the rectangle
// center ± axis1/2 ± axis2/2 whose shadows are sampled over its
// size1 × size2 grid (corners included), invisible to every ray. It lights
// from its centre: sample() gives the centre's direction and radiance and,
// as `point`, the point of the rectangle u picks (u in [0,1]^2 spans it),
// so a shadow ray to it is an unbiased estimate of the visible fraction of
// the rectangle; shading/area_light_shadows.h computes POV's grid instead.
struct PovAreaLightParameters {
    static constexpr Light::Kind kKind = Light::Kind::PovArea;
    PointLightParameters center;  // colour, fade and spotlight cone, at the centre
    Vec3 axis1{0.0f};
    Vec3 axis2{0.0f};
    int size1 = 1;
    int size2 = 1;
    int adaptive = 100;     // levels subdivided whatever the corners show (POV's default: all)
    bool jitter = false;    // each grid point moves by up to half a cell
    bool circular = false;  // the grid squashed onto the ellipse the axes span
    bool orient = false;    // the axes turned perpendicular to the direction of the light
    // POV's area_illumination: each grid point lights with its own
    // direction and attenuation, rather than the centre's.
    bool area_illumination = false;
};

// lancer's physical rectangle lamp: centre +- axis1/2 +- axis2/2, emitting
// on the side of axis1 x axis2.
struct RectangleLightParameters {
    static constexpr Light::Kind kKind = Light::Kind::Rectangle;
    Vec3 center{0.0f};
    Vec3 axis1{0.0f};
    Vec3 axis2{0.0f};
    Color radiance{0.0f};
};

// lancer's physical sphere lamp.
struct SphereLightParameters {
    static constexpr Light::Kind kKind = Light::Kind::Sphere;
    Vec3 center{0.0f};
    float radius = 0.0f;
    Color radiance{0.0f};
};

// An object whose material emits (EmissiveShapeLight): where it lies and
// which way it emits, for light selection.
struct EmissiveShapeParameters {
    static constexpr Light::Kind kKind = Light::Kind::EmissiveShape;
    Vec3 lower{0.0f};  // a world box holding the surface
    Vec3 upper{0.0f};
    // Flat: every point's normal is `normal`, emitting on both sides;
    // otherwise it emits every way.
    bool flat = false;
    Vec3 normal{0.0f};
};

// A plain point light (no fade, no pattern) at squared distance d2 from the
// shading point, in float: the one copy of the arithmetic, which
// PointLight::sample and lane-parallel shading (plugins/raycast) both use,
// so they agree bit for bit. Float is exact enough, and cannot overflow,
// only inside in_plain_point_range(d2); elsewhere sample() works in double.
struct PointIncidence {
    float distance;
    float inverse_distance;  // wi = (position - p) * inverse_distance
    float falloff;           // radiance = intensity * falloff
};
inline bool in_plain_point_range(float distance_squared) {
    return distance_squared > 1e-30f && distance_squared < 1e30f;
}
inline PointIncidence plain_point_incidence(float distance_squared, PointFalloff falloff) {
    const float distance = std::sqrt(distance_squared);
    const float inverse_distance = 1.0f / distance;
    return {distance, inverse_distance,
            falloff == PointFalloff::InverseSquare ? inverse_distance * inverse_distance : 1.0f};
}

}  // namespace lancer
