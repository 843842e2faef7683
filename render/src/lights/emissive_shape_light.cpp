// Objects whose material emits light, sampled by area (or by the cone of a
// sphere), with an automatically derived point proxy.
#include <cmath>

#include "lancer/texture.h"
#include "lights/lights.h"

namespace lancer {

EmissiveShapeLight::EmissiveShapeLight(std::unique_ptr<SurfaceSampler> surface, std::uint32_t object_id,
                                       const Material* material, const SphereShape* sphere)
    : m_surface(std::move(surface)), m_object_id(object_id), m_material(material) {
    if (sphere) {
        m_has_sphere = true;
        m_sphere = *sphere;
    }
    // Mean radiance from the pigment's average (textured emitters).
    Color mean_radiance(0.0f);
    if (material && material->parameters().pigment)
        mean_radiance = material->parameters().emission * material->parameters().pigment->average().rgb;
    const double area = m_surface->area();
    DVec3 flat_normal;
    const bool flat = m_surface->is_flat(flat_normal);
    // Closed shapes radiate pi*A*Le outwards; flat two-sided ones 2*pi*A*Le.
    const double sides = flat ? 2.0 : 1.0;
    m_power = float(sides * kPiD * area) * mean_radiance;
    const Vec3 centre(m_surface->centroid());
    DVec3 lower, upper;
    m_surface->bounds(lower, upper);
    m_parameters.lower = Vec3(lower);
    m_parameters.upper = Vec3(upper);
    m_parameters.flat = flat;
    if (flat) m_parameters.normal = Vec3(glm::normalize(flat_normal));
    if (flat)
        m_proxy = std::make_unique<PointLight>(PointLightParameters{
            .position = centre, .intensity = float(area) * mean_radiance, .pattern_axis = Vec3(flat_normal)});
    else
        m_proxy = std::make_unique<PointLight>(
            PointLightParameters{.position = centre, .intensity = float(area / 4.0) * mean_radiance});
}

Color EmissiveShapeLight::radiance_at(const Hit& hit) const {
    const Material* material = hit.material ? hit.material : m_material;
    if (!material) return Color(0.0f);
    return material->emitted(material->sample_surface(hit));
}

LightSample EmissiveShapeLight::sample(const Vec3& p, const Vec2& u) const {
    LightSample s;
    const DVec3 origin(p);
    DVec3 position, normal;
    const Material* material = m_material;
    float pdf = 0.0f;
    ConeSample cone;
    SurfacePoint point;
    const bool on_cone =
        m_has_sphere && sample_sphere_cone(m_sphere.world.center, m_sphere.world.radius, origin, u, cone);
    if (on_cone) {
        position = cone.point;
        normal = cone.normal;
        pdf = float(cone.pdf);
    } else {
        point = m_surface->sample(u);
        if (!(point.pdf_area > 0.0)) return s;
        position = point.position;
        normal = point.normal;
        if (point.material) material = point.material;
        pdf = area_to_solid_angle(point.pdf_area, origin, point.position, point.normal);
    }
    if (!(pdf > 0.0f)) return s;
    // Lifted from the point as a hit holds it (in float), as before.
    const DVec3 target = lift_towards(DVec3(Vec3(position)), DVec3(Vec3(normal)), origin);
    const DVec3 offset = target - origin;
    const double distance = glm::length(offset);
    if (!(distance > 0.0)) return s;
    // An emitter of one colour needs no hit to look its pigment up at (most
    // lamps): the hit, and a sphere's (u, v), are made only for a pattern.
    if (material && material->pigment_is_constant()) {
        s.radiance = material->emitted(material->constant_surface());
    } else {
        Hit hit;
        hit.position = Vec3(position);
        hit.geometric_normal = hit.shading_normal = Vec3(normal);
        hit.uv =
            on_cone ? sphere_surface(m_sphere.object, m_sphere.placement.point_to_object(cone.point)).uv : point.uv;
        hit.object_id = m_object_id;
        hit.material = material;
        s.radiance = radiance_at(hit);
    }
    s.wi = Vec3(offset / distance);
    s.distance = float(distance);
    s.point = Vec3(target);
    s.pdf = pdf;
    return s;
}

float EmissiveShapeLight::pdf(const Vec3& p, const Vec3&, const Hit& light_hit) const {
    const DVec3 origin(p);
    if (m_has_sphere) {
        const double cone = sphere_cone_pdf(m_sphere.world.center, m_sphere.world.radius, origin);
        if (cone > 0.0) return float(cone);
    }
    return area_to_solid_angle(m_surface->pdf_area(light_hit), origin, DVec3(light_hit.position),
                               DVec3(light_hit.geometric_normal));
}

Color EmissiveShapeLight::emitted(const Hit& light_hit, const Vec3&) const {
    return radiance_at(light_hit);
}

}  // namespace lancer
