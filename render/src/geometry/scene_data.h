// The compiled scene's flat world-space tables (internal to liblancer):
// instances with their placement and material, the meshes, the material and
// texture tables, the lights with their proxies. host/scene_builder.cpp
// fills them from the scene graph; the Embree scene (embree_scene.h) builds
// its acceleration structure over them and owns them.
#pragma once

#include <memory>
#include <optional>
#include <vector>

#include "camera/aperture_shape.h"
#include "camera/mesh_camera.h"
#include "environment/sky_sphere.h"
#include "geometry/csg.h"
#include "geometry/isosurface.h"
#include "geometry/shape.h"
#include "geometry/shapes.h"
#include "lancer/camera.h"
#include "lancer/render_scene.h"
#include "lancer/scene_graph.h"
#include "lights/lights.h"
#include "materials/material_entries.h"
#include "materials/textures.h"

namespace lancer {

// Sphere, Box, Plane and Rectangle have direct code paths (shapes.h);
// Analytic is any other Shape (shape.h); Csg a CSG tree's root (csg.h).
enum class ShapeKind { Sphere, Box, Plane, Rectangle, Mesh, Analytic, Csg };

// One distinct sg::TriangleMesh, in its own object space. The render scene
// owns everything hits read: once compiled, nothing refers to the graph.
struct MeshData {
    sg::MeshRef source;  // while compiling only; null afterwards
    // What hit completion interpolates (per-vertex normals and texture
    // coordinates, and the faces that index them), moved out of the graph.
    std::vector<sg::Vec3> normals;
    std::vector<sg::Vec2> uvs;
    std::vector<sg::TriangleMesh::Face> faces;
    std::vector<float> object_positions;  // xyz per vertex, plus one padding float
    std::vector<std::uint32_t> indices;   // three per triangle; triangle i is faces[i]
    // POV's inside_vector, in world space (POV-Ray never transforms it):
    // only with one has the mesh an inside (the camera's interiors).
    std::optional<sg::Vec3> inside_vector;
    int uses = 0;
};

// One leaf object (or area light surface) placed in the world; its index is
// Hit::object_id.
struct Instance {
    ShapeKind kind = ShapeKind::Sphere;
    Placement placement;
    AnalyticSphere sphere;
    AnalyticBox box;
    AnalyticPlane plane;
    AnalyticRectangle rectangle;
    // Analytic: the shape; a CSG leaf of any analytic kind has it too.
    std::shared_ptr<const Shape> shape;
    const CsgTree* csg = nullptr;  // Csg
    // A CSG leaf is traced only through its tree's root: no BVH entry, no
    // light of its own.
    bool csg_leaf = false;
    bool flip_normal = false;  // an inverted CSG leaf: its normal points into its solid
    // POV-Ray defines no (u, v) for this kind of shape (only spheres,
    // boxes, tori, lathes, sors, ovus, bicubic patches, parametrics and
    // meshes have one): uv_mapping then reads the hit's world x and y.
    bool uv_from_world = false;
    bool bounded = true;  // false for planes and unbounded shapes and trees
    // Bounded by lancer alone (csg.h: CsgNode::pov_bounded): its box culls
    // rays but is left out of the scene's bounds, which min_extent reports.
    bool pov_unbounded = false;
    const MeshData* mesh = nullptr;
    bool mesh_in_world = false;  // world_positions used instead of instancing
    std::vector<float> world_positions;
    const Material* material = nullptr;
    // POV's interior_texture: shown where a ray meets the surface against
    // its normal (null: none, `material` on both sides).
    const Material* interior_material = nullptr;
    // Which interior the surface bounds (Hit::interior_id): POV-Ray's
    // Interior, which the parts of a group share unless a part has an
    // interior written for it.
    std::uint32_t interior_id = 0;
    std::vector<const Material*> face_materials;  // by face; null: `material`
    const Light* emitter = nullptr;               // for emissive materials
    const Light* light = nullptr;                 // the area light this surface is
    bool casts_shadow = true;
    // No shadow ray passes it (light_blockers.h); set when the render
    // scene is built, on every instance but CSG leaves.
    bool blocks_all_light = false;
    // Its crossings along a ray can be listed in one query (Shape::
    // finds_crossings_past_t_min, for each CSG leaf): set with blocks_all_light.
    bool gathers_crossings = true;
    std::int16_t light_group = -1;                // POV's light_group (Hit::light_group)
    bool lit_by_global_lights = true;             // false in a light_group without global_lights
    bool double_illuminate = false;               // POV's (Hit::double_illuminate)
    bool no_image = false;                        // POV's: camera rays pass through (Ray::seen_as)
    bool no_reflection = false;                   // POV's: mirror rays pass through
    Vec3 bounds_lower{0.0f}, bounds_upper{0.0f};  // world, conservative
    sg::SourceLocation location;
};

struct SceneData {
    std::vector<Instance> instances;
    std::vector<std::unique_ptr<MeshData>> meshes;
    std::vector<std::unique_ptr<CsgTree>> csg_trees;
    TextureSpaces texture_spaces;  // by object id
    std::unique_ptr<TextureFactory> texture_factory;
    std::vector<std::unique_ptr<Texture>> textures;
    std::vector<std::unique_ptr<NormalPerturbation>> normals;  // a scene without normal { } pays nothing
    bool has_normal_perturbation = false;
    // Whether a texture reads the hits' (u, v) (TextureFactory::
    // reads_surface_uv): without, analytic shapes leave Hit::uv zero
    // rather than pay for it (two arc tangents a sphere hit).
    bool reads_surface_uv = true;
    bool has_hidden_objects = false;  // some instance has no_image or no_reflection
    // texture_maps lit entry by entry (materials/material_entries.h).
    std::vector<std::unique_ptr<MaterialEntries>> material_entries;
    bool has_material_entries = false;
    std::vector<std::unique_ptr<MaterialLayers>> material_layers;  // layered textures' (lancer/material.h)
    std::vector<std::unique_ptr<Material>> materials;
    // Participating media: interiors' (of hollow objects) and the atmosphere's.
    std::vector<std::unique_ptr<Medium>> media;
    MediumRegion atmosphere;
    bool has_media = false;
    bool has_refraction = false;  // some material's ior is not 1: what bends depends on the objects a ray is in
    // No material's pigment has filter or transmit anywhere (RenderScene::opaque_surfaces).
    bool opaque_surfaces = true;
    std::vector<std::unique_ptr<Light>> owned_lights;
    std::vector<const Light*> lights;
    std::vector<const Light*> local_lights;
    Camera camera;
    std::unique_ptr<MeshCameraRays> mesh_camera;  // a mesh_camera's faces, which `camera` reads
    std::unique_ptr<ApertureShape> bokeh;         // the lens shape `camera` reads, if the scene has one
    Color background{0.0f};
    // What an alpha channel sees through where rays escape: the background's
    // transmit (1 when the scene has none), 0 under a sky_sphere.
    float background_transparency = 1.0f;
    std::unique_ptr<SkySphere> sky;           // null: escaping rays see `background`
    std::unique_ptr<SceneFog> fog;            // null: no fog
    std::unique_ptr<SceneRainbows> rainbows;  // null: none
    SceneOptions options;
    Bounds bounds;
    // Each isosurface's steepest slope met while rendering, for POV's
    // max_gradient advice afterwards.
    struct IsosurfaceRecord {
        IsosurfaceParameters parameters;
        std::shared_ptr<IsosurfaceGradientRecord> gradients;
        sg::SourceLocation location;
    };
    std::vector<IsosurfaceRecord> isosurfaces;
};

}  // namespace lancer
