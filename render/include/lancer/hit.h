// What a ray finds: the nearest surface point and everything shading needs.
#pragma once

#include <cstdint>

#include "lancer/ray.h"

namespace lancer {

class Material;
class MaterialMix;
class Light;

struct Hit {
    float t = kInfinity;          // ray parameter of the hit
    Vec3 position{0.0f};          // world space
    Vec3 geometric_normal{0.0f};  // unit, the surface's own orientation (not flipped)
    Vec3 shading_normal{0.0f};    // unit, interpolated (smooth meshes), same side as geometric
    // Surface coordinates (docs/scene-language.md per shape). A scene whose
    // textures read none (no uv_mapping, no image mapped by (u, v)) does not
    // pay for them: spheres, boxes, planes and the other analytic shapes
    // leave them zero (a mesh may keep its own, which costs nothing).
    Vec2 uv{0.0f};
    Vec3 ray_direction{0.0f};  // of the ray that found it (POV's aoi pattern); 0 when unknown
    // Conservative bound on the absolute floating-point error of `position`
    // per axis; spawn_ray offsets by it so new rays never re-hit this surface.
    Vec3 position_error{0.0f};
    const Material* material = nullptr;  // never null for a hit the scene returns
    // POV-Ray's patterned textures where more than one entry holds (between
    // two entries of a texture_map, an `average`): the entries and their
    // shares, each lit with its own finish and normal and the lit colours
    // blended (lancer/shading/material_blend.h); `material` is the heaviest.
    // Null where one material holds, as everywhere outside a texture_map.
    const MaterialMix* mix = nullptr;
    // The shading normal before any normal { } bent it, for the layers of a
    // layered texture, each bent by its own normal (zero: as shading_normal).
    Vec3 unbumped_normal{0.0f};
    const Light* emitter = nullptr;  // area light or emissive object, else null
    std::uint32_t object_id = 0;     // index of the world-space instance
    // The interior the surface bounds, as POV-Ray's Interior: the parts of
    // a union or CSG share their group's unless an interior is written for
    // the part, so a ray that enters through one part and leaves through
    // another left the one object. What lancer/interior_stack.h goes by.
    std::uint32_t interior_id = 0;
    std::uint32_t primitive_id = 0;
    bool casts_shadow = true;  // false for no_shadow objects
    // POV's light_group the surface is in (-1: none), and whether the
    // scene's global lights reach it (light.h: light_reaches).
    std::int16_t light_group = -1;
    bool lit_by_global_lights = true;
    // POV's double_illuminate: a light behind the surface lights it as if
    // it were in front (local_shading.h: reflect_light_sample).
    bool double_illuminate = false;

    // Unit normals turned to face the side `toward` (e.g. -ray.direction):
    // POV-Ray surfaces are two-sided.
    Vec3 facing_normal(const Vec3& toward) const {
        return glm::dot(geometric_normal, toward) < 0.0f ? -shading_normal : shading_normal;
    }
    bool is_front_face(const Vec3& toward) const { return glm::dot(geometric_normal, toward) >= 0.0f; }

    // Origin offset off the surface along the geometric normal, on the side
    // `direction` leaves towards, by position_error (pbrt's OffsetRayOrigin).
    Vec3 offset_origin(const Vec3& direction) const;
    // A ray leaving the surface in `direction` (normalised here).
    Ray spawn_ray(const Vec3& direction) const;
    // A shadow ray from the surface towards `target`: unit direction, t_max
    // the distance less a margin scaled to the magnitude of `target`, so a
    // light lying on another surface does not shadow itself.
    Ray spawn_ray_to(const Vec3& target) const;
};

}  // namespace lancer
