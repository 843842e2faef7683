// The RenderScene on Embree 3 (internal to liblancer), in four files: the
// BVH build (embree_scene.cpp), the user geometry of analytic shapes
// (analytic_geometry.cpp), ray queries with the camera-packet pipeline
// (ray_queries.cpp) and hit completion (hit_completion.cpp). Only these
// files talk to Embree.
//
// Geometry IDs index our own tables: analytic shapes (spheres, boxes,
// rectangle lights) are one user geometry per kind whose primitive IDs index
// the instance table; a mesh used once is a world-space triangle geometry;
// a mesh used several times is built once in its own Embree scene and
// instanced. Unbounded shapes (planes, quadrics, CSG trees without a finite
// box) live outside the BVH and are tested analytically after it.
#pragma once

#include <embree3/rtcore.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "geometry/scene_data.h"
#include "geometry/shape_list.h"
#include "geometry/unbounded_shapes.h"
#include "lancer/render_scene.h"

namespace lancer::embree {

// Embree takes coordinates within ±1.844e18 (its FLT_LARGE): a ray past that
// aborts Debian's build on an assertion, and a primitive whose bounds reach
// past it is never hit.
constexpr float kLargestTraceable = 1.844e18f;

inline bool within_embree_range(const Vec3& v) {
    return std::fabs(v.x) <= kLargestTraceable && std::fabs(v.y) <= kLargestTraceable &&
           std::fabs(v.z) <= kLargestTraceable;  // false for NaN
}

constexpr unsigned kInvalidId = RTC_INVALID_GEOMETRY_ID;
// Lanes of a ray packet (rtcIntersect16).
constexpr int kMaxLanes = 16;

// One Embree user geometry's primitives: instance indices per primitive.
struct AnalyticGroup {
    const SceneData* data = nullptr;
    ShapeKind kind = ShapeKind::Sphere;
    std::vector<std::uint32_t> instances;
};

// What an Embree geometry id of the top-level scene stands for.
struct GeometryEntry {
    const AnalyticGroup* group = nullptr;  // analytic: primID indexes group->instances
    std::uint32_t instance = 0;            // mesh or mesh instance
};

// One ray's answer from Embree.
struct EmbreeHit {
    float tnear, tfar;
    unsigned geometry, primitive, instance;
    float u, v;
};

// The surfaces shadow_crossings() meets that may let light through, as
// Embree reports them (unsorted; a triangle may come twice).
struct SeeThroughRecords {
    static constexpr int kMost = 32;
    EmbreeHit found[kMost];
    int count = 0;
    bool overflowed = false;
    void add(const EmbreeHit& hit) {
        if (count < kMost)
            found[count++] = hit;
        else
            overflowed = true;
    }
};

// occluded()'s context: lets the filter skip no_shadow meshes, and
// shadow_blockers() pass the surfaces that may let light through, noting
// that it met one (and for shadow_crossings() recording each), so that
// only an opaque one ends the query.
struct ShadowContext {
    RTCIntersectContext base;
    const std::vector<GeometryEntry>* geometries;
    const SceneData* data;
    bool classify = false;
    bool see_through_met = false;
    SeeThroughRecords* records = nullptr;
};

// Everything a hit on a mesh placed in world space needs, when its
// triangles are its faces and it has no per-vertex normals, texture
// coordinates or per-face materials (the common OBJ and mesh2 case): a hit
// then reads this 48-byte record and the triangle's corners, nothing of
// the Instance or the source mesh.
struct PlainTriangles {
    const float* positions = nullptr;  // null: not a plain world mesh
    const std::uint32_t* indices = nullptr;
    const Material* material = nullptr;
    const Light* emitter = nullptr;
    std::uint32_t object_id = 0;
    std::uint32_t interior_id = 0;
    bool casts_shadow = true;
    bool lit_by_global_lights = true;
    std::int16_t light_group = -1;
    bool double_illuminate = false;
};

// A packet's answers, lane by lane, as Embree gives them.
struct PacketAnswers {
    float tnear[kMaxLanes], tfar[kMaxLanes];
    unsigned geometry[kMaxLanes], primitive[kMaxLanes], instance[kMaxLanes];
    float u[kMaxLanes], v[kMaxLanes];

    EmbreeHit lane(int k) const {
        return EmbreeHit{tnear[k], tfar[k], geometry[k], primitive[k], instance[k], u[k], v[k]};
    }
};

// The float vertices Embree traces for a mesh instance: world space for a
// mesh used once, object space for an instanced one.
inline const std::vector<float>& traced_positions(const Instance& instance) {
    return instance.mesh_in_world ? instance.world_positions : instance.mesh->object_positions;
}

// Analytic shapes as Embree user geometry (analytic_geometry.cpp).
void ray_to_object(const Instance& instance, const float org[3], const float dir[3], DVec3& o, DVec3& d);
// The nearest crossing of an analytic shape or CSG tree; `leaf` receives
// the CSG leaf's instance index (the instance's own index for other kinds:
// `self`).
bool intersect_analytic(const SceneData& data, std::uint32_t self, const DVec3& o, const DVec3& d, double t_min,
                        double t_max, double& t, int& face, std::uint32_t& leaf);
// Records the crossing intersect_analytic found at t (of `face`, on CSG
// leaf `leaf`) and every later one before t_far, as analytic_intersect
// reports them (u: the face; v: the leaf's distance from its root).
void record_crossings(const SceneData& data, std::uint32_t self, const DVec3& o, const DVec3& d, float t_near,
                      float t_far, double t, int face, std::uint32_t leaf, const EmbreeHit& ids,
                      SeeThroughRecords& records);
void analytic_bounds(const RTCBoundsFunctionArguments* args);
void analytic_intersect(const RTCIntersectFunctionNArguments* args);
void analytic_occluded(const RTCOccludedFunctionNArguments* args);
void shadow_filter(const RTCFilterFunctionNArguments* args);

// Hit completion on plain world meshes, lane by lane (hit_completion.cpp).
void complete_plain_triangle_hits(const PlainTriangles* const* meshes, const float* t, const unsigned* primitive,
                                  const float* u, const float* v, int count, Hit* hits);

class EmbreeScene final : public RenderScene {
  public:
    // Throws std::runtime_error when Embree reports an error.
    explicit EmbreeScene(std::unique_ptr<SceneData> data);
    ~EmbreeScene() override;

    bool intersect(const Ray& ray, Hit& hit) const override;
    void intersect_batch(const Ray* rays, int count, Hit* hits, bool* found, RayCoherence coherence) const override;
    bool occluded(const Ray& ray) const override;
    ShadowBlockers shadow_blockers(const Ray& ray) const override;
    // Gathered from the BVH or the shape list when the planes and other
    // unbounded shapes let the ray through untouched.
    ShadowBlockers shadow_crossings(const Ray& ray, SeeThroughHits& crossed) const override;
    // Answered for a scene traced from its shape list, whose unbounded
    // shapes are planes; true (unknown) otherwise.
    bool may_block_towards(const Vec3& origin, const Vec3& corner, const Vec3& edge1, const Vec3& edge2) const override;
    const std::vector<const Light*>& lights() const override { return m_data->lights; }
    const std::vector<const Light*>& local_lights() const override { return m_data->local_lights; }
    const Camera& camera() const override { return m_data->camera; }
    float background_transparency() const override { return m_data->background_transparency; }
    Color background(const Ray& ray) const override {
        return m_data->sky ? m_data->sky->radiance(ray.direction) : m_data->background;
    }
    bool background_varies() const override { return m_data->sky != nullptr; }
    const SceneOptions& options() const override { return m_data->options; }
    Bounds bounds() const override { return m_data->bounds; }
    bool has_media() const override { return m_data->has_media; }
    bool opaque_surfaces() const override { return m_data->opaque_surfaces; }
    MediumRegion atmosphere() const override { return m_data->atmosphere; }
    const SceneFog* fog() const override { return m_data->fog.get(); }
    const SceneRainbows* rainbows() const override { return m_data->rainbows.get(); }
    const InteriorStack& camera_interiors() const override { return m_camera_interiors; }
    // Whether rays are traced from the list of a few shapes, not the BVH.
    bool traces_shape_list() const { return m_traces_list; }
    // The tables the scene was built from (for the host's own reports).
    const SceneData& data() const { return *m_data; }

  private:
    bool bvh_occluded(RTCRay& shadow_ray, bool classify, bool* see_through, SeeThroughRecords* records = nullptr) const;
    // The nearest hit whatever POV's no_image and no_reflection say.
    bool nearest_hit(const Ray& ray, Hit& hit) const;
    // Whether `ray` passes through the object `hit` is on (POV's no_image,
    // no_reflection; Ray::seen_as).
    bool hidden_from(const Ray& ray, const Hit& hit) const;
    // The nearest hit past `hit` (hidden from `ray`) that `ray` sees.
    bool nearest_visible_hit(const Ray& ray, Hit& hit) const;
    void build();
    RTCGeometry make_triangles(const MeshData& mesh, const std::vector<float>& positions);
    // intersect_batch's stages for coherent rays (see there); packets of kPacketLanes rays.
    static constexpr int kPacketLanes = kMaxLanes;
    void trace_packet(const Ray* rays, int lanes, PacketAnswers& answers) const;
    void prefetch_corner_indices(const PacketAnswers& answers, int lanes) const;
    void prefetch_corners(const PacketAnswers& answers, int lanes) const;
    void complete_packet(const Ray* rays, const PacketAnswers& answers, int lanes, Hit* hits, bool* found) const;
    // The Hit from what Embree found for `ray` (and, unless told not to
    // look, the planes outside it, nearer).
    bool complete_hit(const Ray& ray, const EmbreeHit& found, Hit& hit, bool with_unbounded = true) const;
    // The Hit on what Embree found (a hit, not a miss).
    bool complete_bvh_hit(const Ray& ray, const EmbreeHit& found, Hit& hit) const;
    // The mesh instance Embree's answer names, or null (analytic or no hit).
    const Instance* mesh_instance_of(const EmbreeHit& found) const;
    void complete_analytic_hit(const Instance& instance, const Ray& ray, float t, int face, Hit& hit) const;
    // The Hit on analytic instance `index` (or its CSG leaf `leaf`) at t.
    void complete_instance_hit(std::uint32_t index, std::uint32_t leaf, const Ray& ray, float t, int face,
                               Hit& hit) const;
    // `ray_direction` decides POV's interior_texture.
    void complete_mesh_hit(const Instance& instance, std::uint32_t primitive, float b1, float b2,
                           const Vec3& ray_direction, Hit& hit) const;

    std::unique_ptr<SceneData> m_data;
    RTCDevice m_device = nullptr;
    RTCScene m_scene = nullptr;
    std::vector<RTCScene> m_mesh_scenes;
    std::map<const MeshData*, RTCScene> m_scene_of_mesh;
    std::vector<std::unique_ptr<AnalyticGroup>> m_groups;
    std::vector<GeometryEntry> m_geometries;  // by top-level geomID
    UnboundedShapes m_unbounded;              // outside the BVH
    // A scene of a few analytic shapes: traced from this list, not the BVH.
    ShapeList m_few_shapes;
    bool m_traces_list = false;
    bool m_has_meshes = false;  // without, camera packets prefetch no triangles
    std::string m_device_error;
    InteriorStack m_camera_interiors;
    bool m_has_no_shadow_mesh = false;
    // Shadow casters that may let light through somewhere (not
    // Instance::blocks_all_light): any, and any mesh.
    bool m_has_see_through_caster = false;
    bool m_has_see_through_mesh = false;
    // By top-level geometry id: plain world meshes (see PlainTriangles).
    std::vector<PlainTriangles> m_plain_triangles;
    // The emitter a hit on `instance` with `material` reports.
    static const Light* emitter_of(const Instance& instance, const Material* material) {
        if (instance.light) return instance.light;
        return material && material->is_emissive() ? instance.emitter : nullptr;
    }
    // The plain world mesh Embree's answer names, or null.
    const PlainTriangles* plain_triangles_of(unsigned geometry, unsigned instance) const {
        if (instance != kInvalidId || geometry >= m_plain_triangles.size()) return nullptr;
        const PlainTriangles& mesh = m_plain_triangles[geometry];
        return mesh.positions ? &mesh : nullptr;
    }
};

}  // namespace lancer::embree

namespace lancer {

// The render scene over `data`, which it owns. Throws std::runtime_error
// when Embree reports an error.
std::unique_ptr<RenderScene> make_embree_scene(std::unique_ptr<SceneData> data);

}  // namespace lancer
