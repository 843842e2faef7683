// The concrete lights (internal to liblancer). Units, lancer/light.h:
// a light of `color C` has radiant intensity pi*C (point), irradiance pi*C
// on a perpendicular surface (directional); area lights are physical
// Lambertian emitters with the same on-axis intensity.
#pragma once

#include <memory>

#include "geometry/shapes.h"
#include "lancer/light.h"
#include "lancer/render_scene.h"

namespace lancer {

// Isotropic, or with a cosine pattern about `pattern_axis` when it is not
// zero: |cos| for the proxy of a flat two-sided emitter, max(0, cos) for a
// one-sided one (a rectangle light).
class PointLight final : public Light {
  public:
    // `scene_radius`: of the sphere bounding the scene's finite geometry,
    // which power() needs for a light without falloff.
    explicit PointLight(const PointLightParameters& parameters, float scene_radius = 1.0f);
    Kind kind() const override { return Kind::Point; }
    LightSample sample(const Vec3& p, const Vec2& u) const override;
    Color power() const override;
    const Vec3& position() const { return m_parameters.position; }
    const Color& intensity() const { return m_parameters.intensity; }

  protected:
    const void* parameters_of(Kind kind) const override { return parameters_if(kind, m_parameters); }

  private:
    PointLightParameters m_parameters;
    // No fade and no pattern: sample()'s float path applies.
    bool m_plain;
    float m_scene_radius;
};

// POV's projected_through: `light`, reaching a point only along the
// segments from it to the light that meet `projector` (a scene of its own,
// holding only that object). It answers no parameters, so integrators that
// evaluate a kind of light themselves treat it through sample().
class ProjectedLight final : public Light {
  public:
    ProjectedLight(std::unique_ptr<Light> light, std::unique_ptr<RenderScene> projector);
    ~ProjectedLight() override;
    Kind kind() const override { return m_light->kind(); }
    LightSample sample(const Vec3& p, const Vec2& u) const override;
    Color power() const override { return m_light->power(); }

  private:
    std::unique_ptr<Light> m_light;
    std::unique_ptr<RenderScene> m_projector;
};

// A point light's sample at p, in double precision: fade, falloff, pattern
// and spotlight cone (PointLight::sample's general path).
LightSample sample_point_light(const PointLightParameters& light, const Vec3& p);

// POV-Ray's area_light (lancer/light.h, PovAreaLightParameters).
class PovAreaLight final : public Light {
  public:
    PovAreaLight(const PovAreaLightParameters& parameters, float scene_radius);
    Kind kind() const override { return Kind::PovArea; }
    LightSample sample(const Vec3& p, const Vec2& u) const override;
    Color power() const override { return m_center.power(); }

  protected:
    const void* parameters_of(Kind kind) const override { return parameters_if(kind, m_parameters); }

  private:
    PovAreaLightParameters m_parameters;
    PointLight m_center;
};

// POV-Ray's fade (Attenuate_Light), for fade_power > 0:
// 2 / (1 + (d / fade_distance)^fade_power), or d^-fade_power without a distance.
double pov_fade(double distance, float fade_distance, float fade_power);

// 0 below `low`, 1 from `high` on, a cubic smooth step between (POV-Ray's
// cubic_spline).
double smooth_step(double low, double high, double x);

// POV's spotlight cone at cos c of the angle between the light's axis and
// the direction from the light to the shading point (section 5 of the POV
// reference; POV-Ray's Attenuate_Light).
double spot_cone(const PointLightParameters& light, double cos_from_axis);

class DirectionalLight final : public Light {
  public:
    // `parameters.to_light` need not be unit (it is normalised; zero means
    // +y). As in POV-Ray, only what lies between a surface and the plane
    // through `position` across the light casts a shadow (the shadow ray
    // ends at that plane); the scene sphere gives the light's power.
    DirectionalLight(const DirectionalLightParameters& parameters, float scene_radius);
    Kind kind() const override { return Kind::Directional; }
    LightSample sample(const Vec3& p, const Vec2& u) const override;
    Color power() const override;

  protected:
    const void* parameters_of(Kind kind) const override { return parameters_if(kind, m_parameters); }

  private:
    DirectionalLightParameters m_parameters;
    float m_scene_radius;
};

// One-sided Lambertian parallelogram, radiance pi*C/area, emitting on the
// side of normalize(axis1 x axis2) (docs/scene-language.md: a ceiling light
// `area_light <a,0,0>, <0,0,b>` faces down). One-sided because a physical
// panel lights the room, not the ceiling it hangs from.
class RectangleLight final : public Light {
  public:
    RectangleLight(const AnalyticRectangle& rectangle, const Color& color);
    Kind kind() const override { return Kind::Rectangle; }
    LightSample sample(const Vec3& p, const Vec2& u) const override;
    float pdf(const Vec3& p, const Vec3& wi, const Hit& light_hit) const override;
    Color emitted(const Hit& light_hit, const Vec3& wo) const override;
    Color power() const override;
    const Light& proxy() const override { return *m_proxy; }
    const Color& radiance() const { return m_radiance; }
    const AnalyticRectangle& rectangle() const { return m_rectangle; }
    bool emits_towards(const glm::dvec3& from_surface) const { return glm::dot(m_normal, from_surface) > 0.0; }

  protected:
    const void* parameters_of(Kind kind) const override { return parameters_if(kind, m_parameters); }

  private:
    RectangleLightParameters m_parameters;
    AnalyticRectangle m_rectangle;
    glm::dvec3 m_normal;
    double m_area;
    Color m_radiance;
    std::unique_ptr<PointLight> m_proxy;
};

// The sample of a point on an emitting surface (lifted off it towards p),
// seen from p; pdf 0 (no sample) when degenerate.
LightSample area_light_sample(const DVec3& p, const DVec3& surface_point, const DVec3& normal, const Color& radiance,
                              float pdf);

// Solid-angle density of a point sampled on a surface with area density
// pdf_area, seen from p: pdf_area * d^2 / |cos at the light|; 0 when
// degenerate (p on the surface's plane or at the point).
float area_to_solid_angle(double pdf_area, const DVec3& p, const DVec3& point, const DVec3& light_normal);

// Solid-angle sampling of the cone a sphere subtends from p (outside), in
// double precision. Returns false when p is inside or on the sphere.
struct ConeSample {
    DVec3 point, normal;
    double pdf = 0.0;  // solid angle
};
// `point` moved off its surface towards the side of p by more than its
// float rounding, so a shadow ray from p to it cannot clip the surface the
// point lies on (the segment stays in p's half-space of the tangent plane).
DVec3 lift_towards(const DVec3& point, const DVec3& normal, const DVec3& p);

bool sample_sphere_cone(const DVec3& center, double radius, const DVec3& p, const Vec2& u, ConeSample& out);
double sphere_cone_pdf(const DVec3& center, double radius, const DVec3& p);

// Sphere of radius R with radiance C/R^2: intensity pi*C in every direction.
class SphereLight final : public Light {
  public:
    SphereLight(const DVec3& center, double radius, const Color& color);
    Kind kind() const override { return Kind::Sphere; }
    LightSample sample(const Vec3& p, const Vec2& u) const override;
    float pdf(const Vec3& p, const Vec3& wi, const Hit& light_hit) const override;
    Color emitted(const Hit& light_hit, const Vec3& wo) const override { return m_radiance; }
    Color power() const override;
    const Light& proxy() const override { return *m_proxy; }
    const Color& radiance() const { return m_radiance; }

  protected:
    const void* parameters_of(Kind kind) const override { return parameters_if(kind, m_parameters); }

  private:
    SphereLightParameters m_parameters;
    DVec3 m_center;
    double m_radius;
    Color m_radiance;
    std::unique_ptr<PointLight> m_proxy;
};

// An object whose material emits: radiance emission * pigment, two-sided.
class EmissiveShapeLight final : public Light {
  public:
    // `sphere`: when set (a sphere under a similarity transform, world
    // centre and radius), sampled by the cone it subtends.
    struct SphereShape {
        AnalyticSphere world;   // centre and radius in world space
        AnalyticSphere object;  // as the scene gave it, for (u,v)
        Placement placement;
    };
    EmissiveShapeLight(std::unique_ptr<SurfaceSampler> surface, std::uint32_t object_id, const Material* material,
                       const SphereShape* sphere);
    Kind kind() const override { return Kind::EmissiveShape; }
    LightSample sample(const Vec3& p, const Vec2& u) const override;
    float pdf(const Vec3& p, const Vec3& wi, const Hit& light_hit) const override;
    Color emitted(const Hit& light_hit, const Vec3& wo) const override;
    Color power() const override { return m_power; }
    const Light& proxy() const override { return *m_proxy; }

  protected:
    const void* parameters_of(Kind kind) const override { return parameters_if(kind, m_parameters); }

  private:
    Color radiance_at(const Hit& hit) const;
    EmissiveShapeParameters m_parameters;
    std::unique_ptr<SurfaceSampler> m_surface;
    std::uint32_t m_object_id;
    const Material* m_material;
    bool m_has_sphere = false;
    SphereShape m_sphere;
    Color m_power{0.0f};
    std::unique_ptr<PointLight> m_proxy;
};

}  // namespace lancer
