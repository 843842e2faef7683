// RenderScene on Embree 3: the only file that talks to Embree.
//
// Geometry IDs index our own tables: analytic shapes (spheres, boxes,
// rectangle lights) are one user geometry per kind whose primitive IDs index
// the instance table; a mesh used once is a world-space triangle geometry;
// a mesh used several times is built once in its own Embree scene and
// instanced. Infinite planes live outside the BVH and are tested
// analytically after it.
#include <embree3/rtcore.h>

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <iostream>
#include <limits>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>

#include "lancer/scene_error.h"
#include "lancer/scene_graph.h"
#include "host/scene_builder.h"
#include "lancer/host/scene_compiler.h"

namespace lancer {
namespace {

constexpr unsigned kInvalidId = RTC_INVALID_GEOMETRY_ID;

// MEDIUM, not HIGH: on the 1M-triangle bench mesh HIGH traced no faster
// (robust: 4.82 vs 4.73 Mrays per CPU second, within noise) and built
// slower (bench/README.md).
constexpr RTCBuildQuality kBuildQuality = RTC_BUILD_QUALITY_MEDIUM;
// RTC_SCENE_FLAG_ROBUST is what makes meshes watertight: Embree then uses
// conservative box tests and its Pluecker triangle test, whose edge tests
// agree exactly between the two triangles sharing an edge. Without it, rays
// aimed at shared edges of a closed mesh leak through it (3-7% of them,
// render/src/geometry/watertight_test.cpp and bench/README.md), which shows as
// speckles of background or of what lies behind in any image. It costs
// traversal speed, measured by lancer_bench (BM_BareEmbreeRobustPrimaryRays).
constexpr RTCSceneFlags kSceneFlags = RTC_SCENE_FLAG_ROBUST;

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

// occluded()'s context: lets the filter skip no_shadow meshes.
struct ShadowContext {
    RTCIntersectContext base;
    const std::vector<GeometryEntry>* geometries;
    const SceneData* data;
};

// Ray in an object's space, in double.
void ray_to_object(const Instance& instance, const float org[3], const float dir[3], DVec3& o, DVec3& d) {
    o = instance.placement.point_to_object(DVec3(org[0], org[1], org[2]));
    d = instance.placement.vector_to_object(DVec3(dir[0], dir[1], dir[2]));
}

// Lane i of a packet of n rays in an object's space (a single ray is n = 1).
void ray_lane_to_object(const Instance& instance, RTCRayN* rays, unsigned n, unsigned i, DVec3& o, DVec3& d) {
    const float org[3] = {RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)};
    const float dir[3] = {RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)};
    ray_to_object(instance, org, dir, o, d);
}

// The float vertices Embree traces for a mesh instance: world space for a
// mesh used once, object space for an instanced one.
const std::vector<float>& traced_positions(const Instance& instance) {
    return instance.mesh_in_world ? instance.world_positions : instance.mesh->object_positions;
}

// Triangle hits from the float vertices Embree intersected: each point an
// affine combination of the corners (on the triangle's plane up to
// rounding, which the error bounds: pbrt-v4's gamma(7) bound for this sum,
// made generous for Embree's own arithmetic) and the unit geometric normal.
// Lane by lane (structure of arrays), so the compiler computes several
// lanes per instruction: a packet's square roots and divisions then cost
// little more than one ray's.
constexpr int kMaxLanes = 16;
struct TriangleSurfaces {
    float px[kMaxLanes], py[kMaxLanes], pz[kMaxLanes];
    float nx[kMaxLanes], ny[kMaxLanes], nz[kMaxLanes];
    float largest[kMaxLanes];  // of the corners' coordinates, in magnitude
};

// The point's error bound per axis, in the space of the corners.
inline float triangle_point_error(float largest_coordinate) { return 16.0f * FLT_EPSILON * largest_coordinate; }

// Lane k: the triangle whose corner indices start at corners[k], into the
// xyz array positions[k], at barycentrics (b1[k], b2[k]); count at most
// kMaxLanes.
void triangle_surfaces(const float* const* positions, const std::uint32_t* const* corners, const float* b1,
                       const float* b2, int count, TriangleSurfaces& out) {
    float corner_x[3][kMaxLanes], corner_y[3][kMaxLanes], corner_z[3][kMaxLanes];
    for (int k = 0; k < count; ++k)
        for (int c = 0; c < 3; ++c) {
            const float* xyz = &positions[k][3 * std::size_t(corners[k][c])];
            corner_x[c][k] = xyz[0];
            corner_y[c][k] = xyz[1];
            corner_z[c][k] = xyz[2];
        }
    for (int k = 0; k < count; ++k) {
        const float b0 = 1.0f - b1[k] - b2[k];
        out.px[k] = b0 * corner_x[0][k] + b1[k] * corner_x[1][k] + b2[k] * corner_x[2][k];
        out.py[k] = b0 * corner_y[0][k] + b1[k] * corner_y[1][k] + b2[k] * corner_y[2][k];
        out.pz[k] = b0 * corner_z[0][k] + b1[k] * corner_z[1][k] + b2[k] * corner_z[2][k];
        const float e1x = corner_x[1][k] - corner_x[0][k], e1y = corner_y[1][k] - corner_y[0][k],
                    e1z = corner_z[1][k] - corner_z[0][k];
        const float e2x = corner_x[2][k] - corner_x[0][k], e2y = corner_y[2][k] - corner_y[0][k],
                    e2z = corner_z[2][k] - corner_z[0][k];
        const float cx = e1y * e2z - e2y * e1z, cy = e1z * e2x - e2z * e1x, cz = e1x * e2y - e2x * e1y;
        const float length = std::sqrt(cx * cx + cy * cy + cz * cz);
        // A degenerate (zero-area) or overflowing triangle gets +y.
        const bool usable = length > 0.0f && length <= FLT_MAX;
        const float inverse = 1.0f / length;
        out.nx[k] = usable ? cx * inverse : 0.0f;
        out.ny[k] = usable ? cy * inverse : 1.0f;
        out.nz[k] = usable ? cz * inverse : 0.0f;
        float m = 0.0f;
        for (int c = 0; c < 3; ++c)
            m = std::max(m, std::max(std::fabs(corner_x[c][k]),
                                     std::max(std::fabs(corner_y[c][k]), std::fabs(corner_z[c][k]))));
        out.largest[k] = m;
    }
}

// One triangle's hit point, unit normal and the point's error bound.
struct TriangleSurface {
    Vec3 point, normal, error;
    float largest_coordinate;
};

TriangleSurface triangle_surface(const float* positions, const std::uint32_t* corners, float b1, float b2) {
    TriangleSurfaces lane;
    triangle_surfaces(&positions, &corners, &b1, &b2, 1, lane);
    return TriangleSurface{Vec3(lane.px[0], lane.py[0], lane.pz[0]), Vec3(lane.nx[0], lane.ny[0], lane.nz[0]),
                           Vec3(triangle_point_error(lane.largest[0])), lane.largest[0]};
}

// Everything a hit on a mesh placed in world space needs, when its
// triangles are its faces and it has no per-vertex normals, texture
// coordinates or per-face materials (the common OBJ and mesh2 case): a hit
// then reads this 40-byte record and the triangle's corners, nothing of
// the Instance or the source mesh.
struct PlainTriangles {
    const float* positions = nullptr;  // null: not a plain world mesh
    const std::uint32_t* indices = nullptr;
    const Material* material = nullptr;
    const Light* emitter = nullptr;
    std::uint32_t object_id = 0;
    bool casts_shadow = true;
};

// One ray's answer from Embree.
struct EmbreeHit {
    float tnear, tfar;
    unsigned geometry, primitive, instance;
    float u, v;
};

// A packet's answers, lane by lane, as Embree gives them.
struct PacketAnswers {
    float tnear[kMaxLanes], tfar[kMaxLanes];
    unsigned geometry[kMaxLanes], primitive[kMaxLanes], instance[kMaxLanes];
    float u[kMaxLanes], v[kMaxLanes];

    EmbreeHit lane(int k) const { return EmbreeHit{tnear[k], tfar[k], geometry[k], primitive[k], instance[k], u[k], v[k]}; }
};

// Completes `count` (at most kMaxLanes) hits on plain world meshes: lane k
// found triangle primitive[k] of *meshes[k] at distance t[k] and
// barycentrics (u[k], v[k]); written to hits[k].
void complete_plain_triangle_hits(const PlainTriangles* const* meshes, const float* t, const unsigned* primitive,
                                  const float* u, const float* v, int count, Hit* hits) {
    const float* positions[kMaxLanes];
    const std::uint32_t* corners[kMaxLanes];
    for (int k = 0; k < count; ++k) {
        positions[k] = meshes[k]->positions;
        corners[k] = &meshes[k]->indices[3 * std::size_t(primitive[k])];
    }
    TriangleSurfaces surfaces;
    triangle_surfaces(positions, corners, u, v, count, surfaces);
    // World-space error: the corners' bound and the rounding of the point.
    float ex[kMaxLanes], ey[kMaxLanes], ez[kMaxLanes];
    for (int k = 0; k < count; ++k) {
        const float corner_error = triangle_point_error(surfaces.largest[k]);
        ex[k] = corner_error + 2.0f * FLT_EPSILON * std::fabs(surfaces.px[k]);
        ey[k] = corner_error + 2.0f * FLT_EPSILON * std::fabs(surfaces.py[k]);
        ez[k] = corner_error + 2.0f * FLT_EPSILON * std::fabs(surfaces.pz[k]);
    }
    for (int k = 0; k < count; ++k) {
        const PlainTriangles& mesh = *meshes[k];
        Hit& hit = hits[k];
        hit.t = t[k];
        hit.position = Vec3(surfaces.px[k], surfaces.py[k], surfaces.pz[k]);
        hit.position_error = Vec3(ex[k], ey[k], ez[k]);
        hit.geometric_normal = hit.shading_normal = Vec3(surfaces.nx[k], surfaces.ny[k], surfaces.nz[k]);
        hit.uv = Vec2(u[k], v[k]);
        hit.material = mesh.material;
        hit.emitter = mesh.emitter;
        hit.object_id = mesh.object_id;
        hit.primitive_id = primitive[k];
        hit.casts_shadow = mesh.casts_shadow;
    }
}

bool intersect_analytic(const Instance& instance, const DVec3& o, const DVec3& d, double t_min, double t_max,
                        double& t, int& face) {
    face = 0;
    switch (instance.kind) {
    case ShapeKind::Sphere: return intersect_sphere(instance.sphere, o, d, t_min, t_max, t);
    case ShapeKind::Box: return intersect_box(instance.box, o, d, t_min, t_max, t, face);
    case ShapeKind::Rectangle: return intersect_rectangle(instance.rectangle, o, d, t_min, t_max, t);
    case ShapeKind::Plane: return intersect_plane(instance.plane, o, d, t_min, t_max, t);
    default: return false;
    }
}

void analytic_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* group = static_cast<const AnalyticGroup*>(args->geometryUserPtr);
    const Instance& instance = group->data->instances[group->instances[args->primID]];
    *args->bounds_o = RTCBounds{instance.bounds_lower.x, instance.bounds_lower.y, instance.bounds_lower.z, 0.0f,
                                instance.bounds_upper.x, instance.bounds_upper.y, instance.bounds_upper.z, 0.0f};
}

// Embree calls these with one ray, or with a packet of N when rays are
// traced together (intersect_batch); valid[i] says which lanes are live.
void analytic_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* group = static_cast<const AnalyticGroup*>(args->geometryUserPtr);
    const Instance& instance = group->data->instances[group->instances[args->primID]];
    const unsigned n = args->N;
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
    for (unsigned i = 0; i < n; ++i) {
        if (!args->valid[i]) continue;
        float& tfar = RTCRayN_tfar(rays, n, i);
        DVec3 o, d;
        ray_lane_to_object(instance, rays, n, i, o, d);
        double t;
        int face;
        if (!intersect_analytic(instance, o, d, RTCRayN_tnear(rays, n, i), tfar, t, face)) continue;
        const float t_float = float(t);
        if (!(t_float < tfar)) continue;
        tfar = t_float;
        RTCHitN_u(hits, n, i) = float(face);
        RTCHitN_v(hits, n, i) = 0.0f;
        RTCHitN_Ng_x(hits, n, i) = 0.0f;
        RTCHitN_Ng_y(hits, n, i) = 1.0f;
        RTCHitN_Ng_z(hits, n, i) = 0.0f;
        RTCHitN_primID(hits, n, i) = args->primID;
        RTCHitN_geomID(hits, n, i) = args->geomID;
        RTCHitN_instID(hits, n, i, 0) = args->context->instID[0];
    }
}

void analytic_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* group = static_cast<const AnalyticGroup*>(args->geometryUserPtr);
    const Instance& instance = group->data->instances[group->instances[args->primID]];
    if (!instance.casts_shadow) return;
    const unsigned n = args->N;
    RTCRayN* rays = args->ray;
    for (unsigned i = 0; i < n; ++i) {
        if (!args->valid[i]) continue;
        DVec3 o, d;
        ray_lane_to_object(instance, rays, n, i, o, d);
        double t;
        int face;
        if (intersect_analytic(instance, o, d, RTCRayN_tnear(rays, n, i), RTCRayN_tfar(rays, n, i), t, face))
            RTCRayN_tfar(rays, n, i) = -INFINITY;
    }
}

// Rejects hits on meshes of no_shadow objects during occluded().
void skip_no_shadow(const RTCFilterFunctionNArguments* args) {
    const auto* context = reinterpret_cast<const ShadowContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        unsigned top = RTCHitN_instID(args->hit, args->N, i, 0);
        if (top == kInvalidId) top = RTCHitN_geomID(args->hit, args->N, i);
        if (top >= context->geometries->size()) continue;
        const GeometryEntry& entry = (*context->geometries)[top];
        if (entry.group) continue;
        if (!context->data->instances[entry.instance].casts_shadow) args->valid[i] = 0;
    }
}

void record_device_error(void* user, RTCError code, const char* message) {
    auto* log = static_cast<std::string*>(user);
    if (log->empty()) *log = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

void fill_embree_ray(const Ray& ray, RTCRay& out) {
    out.org_x = ray.origin.x;
    out.org_y = ray.origin.y;
    out.org_z = ray.origin.z;
    out.dir_x = ray.direction.x;
    out.dir_y = ray.direction.y;
    out.dir_z = ray.direction.z;
    out.tnear = glm::max(ray.t_min, 0.0f);
    out.tfar = glm::max(ray.t_max, out.tnear);
    out.time = 0.0f;
    out.mask = 0xffffffffu;
    out.id = 0;
    out.flags = 0;
}

class EmbreeScene final : public RenderScene {
public:
    explicit EmbreeScene(std::unique_ptr<SceneData> data) : m_data(std::move(data)) {
        m_device = rtcNewDevice(nullptr);
        if (!m_device) throw std::runtime_error("cannot create the Embree device");
        rtcSetDeviceErrorFunction(m_device, record_device_error, &m_device_error);
        build();
        if (!m_device_error.empty()) throw std::runtime_error(m_device_error);
    }
    ~EmbreeScene() override {
        if (m_scene) rtcReleaseScene(m_scene);
        for (RTCScene s : m_mesh_scenes) rtcReleaseScene(s);
        if (m_device) rtcReleaseDevice(m_device);
    }

    bool intersect(const Ray& ray, Hit& hit) const override;
    void intersect_batch(const Ray* rays, int count, Hit* hits, bool* found,
                         RayCoherence coherence) const override;
    bool occluded(const Ray& ray) const override;
    const std::vector<const Light*>& lights() const override { return m_data->lights; }
    const std::vector<const Light*>& local_lights() const override { return m_data->local_lights; }
    const Camera& camera() const override { return m_data->camera; }
    Color background(const Ray&) const override { return m_data->background; }
    const SceneOptions& options() const override { return m_data->options; }
    Bounds bounds() const override { return m_data->bounds; }

private:
    void build();
    RTCGeometry make_triangles(const MeshData& mesh, const std::vector<float>& positions);
    // intersect_batch's stages for coherent rays (see there); packets of kPacketLanes rays.
    static constexpr int kPacketLanes = kMaxLanes;
    void trace_packet(const Ray* rays, int lanes, PacketAnswers& answers) const;
    void prefetch_corner_indices(const PacketAnswers& answers, int lanes) const;
    void prefetch_corners(const PacketAnswers& answers, int lanes) const;
    void complete_packet(const Ray* rays, const PacketAnswers& answers, int lanes, Hit* hits, bool* found) const;
    // The Hit from what Embree found for `ray` (and the planes outside it).
    bool complete_hit(const Ray& ray, const EmbreeHit& found, Hit& hit) const;
    // The mesh instance Embree's answer names, or null (analytic or no hit).
    const Instance* mesh_instance_of(const EmbreeHit& found) const;
    void complete_analytic_hit(const Instance& instance, const Ray& ray, float t, int face, Hit& hit) const;
    void complete_mesh_hit(const Instance& instance, bool faces_are_triangles, std::uint32_t primitive, float b1,
                           float b2, Hit& hit) const;

    std::unique_ptr<SceneData> m_data;
    RTCDevice m_device = nullptr;
    RTCScene m_scene = nullptr;
    std::vector<RTCScene> m_mesh_scenes;
    std::map<const MeshData*, RTCScene> m_scene_of_mesh;
    std::vector<std::unique_ptr<AnalyticGroup>> m_groups;
    std::vector<GeometryEntry> m_geometries;  // by top-level geomID
    std::vector<std::uint32_t> m_planes;      // instance indices
    std::string m_device_error;
    bool m_has_no_shadow_mesh = false;
    // By instance: a mesh whose triangle i is its face i (no polygons split).
    std::vector<std::uint8_t> m_faces_are_triangles;
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

RTCGeometry EmbreeScene::make_triangles(const MeshData& mesh, const std::vector<float>& positions) {
    RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_TRIANGLE);
    // Shared buffers: Embree reads our arrays (padded by one float, as its
    // SIMD loads require), no copies.
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, positions.data(), 0,
                               3 * sizeof(float), (positions.size() - 1) / 3);
    rtcSetSharedGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, mesh.indices.data(), 0,
                               3 * sizeof(std::uint32_t), mesh.indices.size() / 3);
    rtcCommitGeometry(geometry);
    return geometry;
}

void EmbreeScene::build() {
    SceneData& data = *m_data;
    const bool any_no_shadow_mesh = [&] {
        for (const Instance& i : data.instances)
            if (i.kind == ShapeKind::Mesh && !i.casts_shadow) return true;
        return false;
    }();
    m_has_no_shadow_mesh = any_no_shadow_mesh;
    m_scene = rtcNewScene(m_device);
    rtcSetSceneFlags(m_scene, RTCSceneFlags(kSceneFlags |
                                            (any_no_shadow_mesh ? RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION : 0)));
    rtcSetSceneBuildQuality(m_scene, kBuildQuality);

    // Analytic kinds present in the scene, one user geometry each.
    std::map<ShapeKind, AnalyticGroup*> groups;
    for (std::uint32_t index = 0; index < data.instances.size(); ++index) {
        const Instance& instance = data.instances[index];
        if (instance.kind == ShapeKind::Plane) {
            m_planes.push_back(index);
            continue;
        }
        if (instance.kind == ShapeKind::Mesh) continue;
        AnalyticGroup*& group = groups[instance.kind];
        if (!group) {
            m_groups.push_back(std::make_unique<AnalyticGroup>());
            group = m_groups.back().get();
            group->data = m_data.get();
            group->kind = instance.kind;
        }
        group->instances.push_back(index);
    }
    auto attach = [&](RTCGeometry geometry, GeometryEntry entry) {
        const unsigned id = rtcAttachGeometry(m_scene, geometry);
        rtcReleaseGeometry(geometry);
        if (m_geometries.size() <= id) m_geometries.resize(id + 1);
        m_geometries[id] = entry;
    };
    for (auto& [kind, group] : groups) {
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geometry, unsigned(group->instances.size()));
        rtcSetGeometryUserData(geometry, group);
        rtcSetGeometryBoundsFunction(geometry, analytic_bounds, nullptr);
        rtcSetGeometryIntersectFunction(geometry, analytic_intersect);
        rtcSetGeometryOccludedFunction(geometry, analytic_occluded);
        rtcCommitGeometry(geometry);
        attach(geometry, GeometryEntry{group, 0});
    }

    m_faces_are_triangles.assign(data.instances.size(), 0);
    std::map<const MeshData*, bool> identity_of_mesh;
    for (std::uint32_t index = 0; index < data.instances.size(); ++index) {
        const Instance& instance = data.instances[index];
        if (instance.kind != ShapeKind::Mesh || !instance.mesh) continue;
        const MeshData& mesh = *instance.mesh;
        auto [found, inserted] = identity_of_mesh.try_emplace(&mesh, true);
        if (inserted) {
            for (std::uint32_t t = 0; t < mesh.face_of_triangle.size(); ++t)
                if (mesh.face_of_triangle[t] != t) {
                    found->second = false;
                    break;
                }
        }
        m_faces_are_triangles[index] = found->second ? 1 : 0;
    }

    // Meshes: world-space geometry when used once, instanced otherwise.
    for (std::uint32_t index = 0; index < data.instances.size(); ++index) {
        const Instance& instance = data.instances[index];
        if (instance.kind != ShapeKind::Mesh) continue;
        const MeshData& mesh = *instance.mesh;
        if (mesh.indices.empty()) continue;
        if (instance.mesh_in_world) {
            attach(make_triangles(mesh, instance.world_positions), GeometryEntry{nullptr, index});
            if (m_faces_are_triangles[index] && mesh.normals.empty() && mesh.uvs.empty() &&
                instance.face_materials.empty()) {
                const unsigned id = unsigned(m_geometries.size() - 1);
                if (m_plain_triangles.size() <= id) m_plain_triangles.resize(id + 1);
                m_plain_triangles[id] =
                    PlainTriangles{instance.world_positions.data(), mesh.indices.data(), instance.material,
                                   emitter_of(instance, instance.material), index, instance.casts_shadow};
            }
            continue;
        }
        RTCScene& shared = m_scene_of_mesh[&mesh];
        if (!shared) {
            shared = rtcNewScene(m_device);
            rtcSetSceneFlags(shared, kSceneFlags);
            rtcSetSceneBuildQuality(shared, kBuildQuality);
            RTCGeometry triangles = make_triangles(mesh, mesh.object_positions);
            rtcAttachGeometry(shared, triangles);
            rtcReleaseGeometry(triangles);
            rtcCommitScene(shared);
            m_mesh_scenes.push_back(shared);
        }
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_INSTANCE);
        rtcSetGeometryInstancedScene(geometry, shared);
        float transform[16];
        for (int col = 0; col < 4; ++col)
            for (int row = 0; row < 4; ++row)
                transform[4 * col + row] = float(instance.placement.world_from_object[col][row]);
        rtcSetGeometryTransform(geometry, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, transform);
        rtcCommitGeometry(geometry);
        attach(geometry, GeometryEntry{nullptr, index});
    }
    rtcCommitScene(m_scene);
}

void EmbreeScene::complete_analytic_hit(const Instance& instance, const Ray& ray, float t, int face,
                                        Hit& hit) const {
    DVec3 o, d;
    const float org[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const float dir[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    ray_to_object(instance, org, dir, o, d);
    const DVec3 p = o + double(t) * d;
    SurfaceGeometry g;
    switch (instance.kind) {
    case ShapeKind::Sphere: g = sphere_surface(instance.sphere, p); break;
    case ShapeKind::Box: g = box_surface(instance.box, p, face); break;
    case ShapeKind::Plane: g = plane_surface(instance.plane, p); break;
    default: g = rectangle_surface(instance.rectangle, p); break;
    }
    const DVec3 world = instance.placement.point_to_world(g.point);
    hit.position = Vec3(world);
    hit.position_error = instance.placement.world_point_error(g.point, world);
    hit.geometric_normal = Vec3(instance.placement.normal_to_world_unit(g.normal));
    hit.shading_normal = hit.geometric_normal;
    hit.uv = g.uv;
    hit.material = instance.material;
    hit.primitive_id = std::uint32_t(face);
}

void EmbreeScene::complete_mesh_hit(const Instance& instance, bool faces_are_triangles, std::uint32_t primitive,
                                    float u, float v, Hit& hit) const {
    const MeshData& mesh = *instance.mesh;
    // Skipping the lookup when triangle i is face i saves one more cold load.
    const std::uint32_t face_index = faces_are_triangles ? primitive : mesh.face_of_triangle[primitive];
    const std::vector<float>& positions = traced_positions(instance);
    const float* vertices = positions.data();
    const std::uint32_t* corners = &mesh.indices[3 * primitive];
    const TriangleSurface surface = triangle_surface(vertices, corners, u, v);
    const float b1 = u, b2 = v, b0 = 1.0f - b1 - b2;
    const Vec3& p = surface.point;
    const Vec3& normal = surface.normal;
    const Vec3& object_error = surface.error;
    const float largest = surface.largest_coordinate;
    Vec3 world, world_normal, error;
    if (instance.mesh_in_world) {
        world = p;
        world_normal = normal;
        error = object_error + 2.0f * FLT_EPSILON * glm::abs(p);
    } else {
        const DVec3 world_point = instance.placement.point_to_world(DVec3(p));
        world = Vec3(world_point);
        world_normal = Vec3(instance.placement.normal_to_world_unit(DVec3(normal)));
        const DMat3 a(instance.placement.world_from_object);
        DVec3 spread(0.0);
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) spread[row] += std::fabs(a[col][row]) * double(object_error[col]);
        // Embree maps the ray to object space in float: an error of a few
        // ULPs of the world coordinates and the translation too.
        error = Vec3(spread) + 8.0f * instance.placement.world_point_error(DVec3(largest), world_point);
    }
    hit.position = world;
    hit.position_error = error;
    hit.geometric_normal = world_normal;
    hit.shading_normal = world_normal;  // not read back from hit: that stalls on the store just made
    // The source face (40 bytes a triangle, cold in cache: Embree traces its
    // own copies of the vertices) is read only when the mesh has per-vertex
    // normals or texture coordinates to interpolate.
    const bool has_normals = !mesh.normals.empty(), has_uvs = !mesh.uvs.empty();
    const sg::TriangleMesh::Face* face = has_normals || has_uvs ? &mesh.faces[face_index] : nullptr;
    if (has_normals && face->normal[0] >= 0) {
        DVec3 interpolated(0.0);
        const double weight[3] = {b0, b1, b2};
        for (int k = 0; k < 3; ++k) {
            const int n = face->normal[k];
            if (n >= 0 && std::size_t(n) < mesh.normals.size()) interpolated += weight[k] * mesh.normals[n];
        }
        if (glm::length(interpolated) > 0.0) {
            const Vec3 shading(instance.placement.normal_to_world_unit(interpolated));
            hit.shading_normal = shading;
            // Keep both normals on the side the mesh author's normals give.
            if (glm::dot(shading, hit.geometric_normal) < 0.0f) hit.geometric_normal = -hit.geometric_normal;
        }
    }
    if (has_uvs && face->uv[0] >= 0) {
        glm::dvec2 uv(0.0);
        const double weight[3] = {b0, b1, b2};
        for (int k = 0; k < 3; ++k) {
            const int index = face->uv[k];
            if (index >= 0 && std::size_t(index) < mesh.uvs.size()) uv += weight[k] * mesh.uvs[index];
        }
        hit.uv = Vec2(uv);
    } else {
        hit.uv = Vec2(u, v);
    }
    const Material* face_material =
        face_index < instance.face_materials.size() ? instance.face_materials[face_index] : nullptr;
    hit.material = face_material ? face_material : instance.material;
    hit.primitive_id = face_index;
}

bool EmbreeScene::intersect(const Ray& ray, Hit& hit) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    RTCRayHit rayhit;
    fill_embree_ray(ray, rayhit.ray);
    rayhit.hit.geomID = kInvalidId;
    rayhit.hit.primID = kInvalidId;
    rayhit.hit.instID[0] = kInvalidId;
    rayhit.hit.u = rayhit.hit.v = 0.0f;
    rtcIntersect1(m_scene, &context, &rayhit);
    const EmbreeHit found{rayhit.ray.tnear, rayhit.ray.tfar, rayhit.hit.geomID, rayhit.hit.primID,
                          rayhit.hit.instID[0], rayhit.hit.u,  rayhit.hit.v};
    return complete_hit(ray, found, hit);
}

void EmbreeScene::trace_packet(const Ray* rays, int lanes, PacketAnswers& answers) const {
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) int valid[kPacketLanes];
    alignas(64) RTCRayHit16 packet;
    for (int k = 0; k < kPacketLanes; ++k) {
        valid[k] = k < lanes ? -1 : 0;
        // Idle lanes repeat a live ray so every lane holds finite data.
        const Ray& ray = rays[std::min(k, lanes - 1)];
        packet.ray.org_x[k] = ray.origin.x;
        packet.ray.org_y[k] = ray.origin.y;
        packet.ray.org_z[k] = ray.origin.z;
        packet.ray.dir_x[k] = ray.direction.x;
        packet.ray.dir_y[k] = ray.direction.y;
        packet.ray.dir_z[k] = ray.direction.z;
        packet.ray.tnear[k] = glm::max(ray.t_min, 0.0f);  // as fill_embree_ray
        packet.ray.tfar[k] = glm::max(ray.t_max, packet.ray.tnear[k]);
        packet.ray.time[k] = 0.0f;
        packet.ray.mask[k] = 0xffffffffu;
        packet.ray.id[k] = 0;
        packet.ray.flags[k] = 0;
        packet.hit.geomID[k] = kInvalidId;
        packet.hit.primID[k] = kInvalidId;
        packet.hit.instID[0][k] = kInvalidId;
        packet.hit.u[k] = packet.hit.v[k] = 0.0f;
    }
    rtcIntersect16(valid, m_scene, &context, &packet);
    for (int k = 0; k < kPacketLanes; ++k) {
        answers.tnear[k] = packet.ray.tnear[k];
        answers.tfar[k] = packet.ray.tfar[k];
        answers.geometry[k] = packet.hit.geomID[k];
        answers.primitive[k] = packet.hit.primID[k];
        answers.instance[k] = packet.hit.instID[0][k];
        answers.u[k] = packet.hit.u[k];
        answers.v[k] = packet.hit.v[k];
    }
}

void EmbreeScene::prefetch_corner_indices(const PacketAnswers& answers, int lanes) const {
    for (int k = 0; k < lanes; ++k) {
        if (const PlainTriangles* mesh = plain_triangles_of(answers.geometry[k], answers.instance[k]))
            __builtin_prefetch(&mesh->indices[3 * std::size_t(answers.primitive[k])]);
        else if (const Instance* instance = mesh_instance_of(answers.lane(k)))
            __builtin_prefetch(&instance->mesh->indices[3 * std::size_t(answers.primitive[k])]);
    }
}

void EmbreeScene::prefetch_corners(const PacketAnswers& answers, int lanes) const {
    for (int k = 0; k < lanes; ++k) {
        const float* positions;
        const std::uint32_t* corner;
        if (const PlainTriangles* mesh = plain_triangles_of(answers.geometry[k], answers.instance[k])) {
            positions = mesh->positions;
            corner = &mesh->indices[3 * std::size_t(answers.primitive[k])];
        } else if (const Instance* instance = mesh_instance_of(answers.lane(k))) {
            positions = traced_positions(*instance).data();
            corner = &instance->mesh->indices[3 * std::size_t(answers.primitive[k])];
        } else {
            continue;
        }
        for (int c = 0; c < 3; ++c) __builtin_prefetch(&positions[3 * std::size_t(corner[c])]);
    }
}

void EmbreeScene::intersect_batch(const Ray* rays, int count, Hit* hits, bool* found,
                                  RayCoherence coherence) const {
    // Incoherent rays share too few BVH nodes for packets to pay.
    if (coherence == RayCoherence::Incoherent) {
        for (int i = 0; i < count; ++i) found[i] = intersect(rays[i], hits[i]);
        return;
    }
    // A mesh hit needs its triangle's corner indices, then the corners: two
    // dependent loads, cold in cache (Embree traverses its own copy of the
    // vertices), which would stall completion for most of a memory latency
    // each. So the packets go through a pipeline: after packet i is traced,
    // its indices are requested, packet i-1's corners (indices now cached)
    // are requested, and packet i-2 is completed; each packet's tracing
    // hides the next stage's misses.
    constexpr int kDepth = 3;
    PacketAnswers answers[kDepth];
    const int packets = (count + kPacketLanes - 1) / kPacketLanes;
    auto lanes_of = [&](int packet) { return std::min(kPacketLanes, count - packet * kPacketLanes); };
    for (int step = 0; step < packets + 2; ++step) {
        if (step < packets) {
            PacketAnswers& traced = answers[step % kDepth];
            trace_packet(rays + step * kPacketLanes, lanes_of(step), traced);
            prefetch_corner_indices(traced, lanes_of(step));
        }
        if (const int previous = step - 1; previous >= 0 && previous < packets)
            prefetch_corners(answers[previous % kDepth], lanes_of(previous));
        if (const int ready = step - 2; ready >= 0)
            complete_packet(rays + ready * kPacketLanes, answers[ready % kDepth], lanes_of(ready),
                            hits + ready * kPacketLanes, found + ready * kPacketLanes);
    }
}

void EmbreeScene::complete_packet(const Ray* rays, const PacketAnswers& answers, int lanes, Hit* hits,
                                  bool* found) const {
    // The common case, every lane on a plain world mesh (and no planes,
    // outside the BVH, that may lie nearer), is completed lane-parallel;
    // any other packet lane by lane.
    const PlainTriangles* plain_mesh[kPacketLanes];
    bool all_plain = m_planes.empty();
    for (int k = 0; k < lanes; ++k) {
        plain_mesh[k] = plain_triangles_of(answers.geometry[k], answers.instance[k]);
        all_plain = all_plain && plain_mesh[k] != nullptr;
    }
    if (all_plain) {
        complete_plain_triangle_hits(plain_mesh, answers.tfar, answers.primitive, answers.u, answers.v, lanes, hits);
        for (int k = 0; k < lanes; ++k) found[k] = true;
        return;
    }
    for (int k = 0; k < lanes; ++k) found[k] = complete_hit(rays[k], answers.lane(k), hits[k]);
}

const Instance* EmbreeScene::mesh_instance_of(const EmbreeHit& found) const {
    if (found.geometry == kInvalidId) return nullptr;
    const GeometryEntry& entry = m_geometries[found.instance != kInvalidId ? found.instance : found.geometry];
    return entry.group ? nullptr : &m_data->instances[entry.instance];
}

bool EmbreeScene::complete_hit(const Ray& ray, const EmbreeHit& found, Hit& hit) const {
    // Planes are outside the BVH: test them against the nearest so far.
    std::uint32_t plane_hit = kInvalidId;
    double plane_t = double(found.tfar);
    for (std::uint32_t index : m_planes) {
        const Instance& instance = m_data->instances[index];
        DVec3 o, d;
        const float org[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
        const float dir[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
        ray_to_object(instance, org, dir, o, d);
        double t;
        if (intersect_plane(instance.plane, o, d, found.tnear, plane_t, t)) {
            plane_t = t;
            plane_hit = index;
        }
    }
    if (plane_hit != kInvalidId) {
        const Instance& instance = m_data->instances[plane_hit];
        hit = Hit{};
        hit.t = float(plane_t);
        complete_analytic_hit(instance, ray, float(plane_t), 0, hit);
        hit.object_id = plane_hit;
        hit.casts_shadow = instance.casts_shadow;
        hit.emitter = instance.emitter;
        return true;
    }
    if (found.geometry == kInvalidId) return false;
    if (const PlainTriangles* mesh = plain_triangles_of(found.geometry, found.instance)) {
        complete_plain_triangle_hits(&mesh, &found.tfar, &found.primitive, &found.u, &found.v, 1, &hit);
        return true;
    }

    hit = Hit{};
    hit.t = found.tfar;
    const unsigned top = found.instance != kInvalidId ? found.instance : found.geometry;
    const GeometryEntry& entry = m_geometries[top];
    std::uint32_t index;
    if (entry.group) {
        index = entry.group->instances[found.primitive];
        complete_analytic_hit(m_data->instances[index], ray, found.tfar, int(found.u), hit);
    } else {
        index = entry.instance;
        complete_mesh_hit(m_data->instances[index], m_faces_are_triangles[index] != 0, found.primitive, found.u,
                          found.v, hit);
    }
    const Instance& instance = m_data->instances[index];
    hit.object_id = index;
    hit.casts_shadow = instance.casts_shadow;
    hit.emitter = emitter_of(instance, hit.material);
    return true;
}

bool EmbreeScene::occluded(const Ray& ray) const {
    ShadowContext context;
    rtcInitIntersectContext(&context.base);
    context.geometries = &m_geometries;
    context.data = m_data.get();
    if (m_has_no_shadow_mesh) context.base.filter = skip_no_shadow;
    RTCRay shadow_ray;
    fill_embree_ray(ray, shadow_ray);
    rtcOccluded1(m_scene, &context.base, &shadow_ray);
    if (shadow_ray.tfar == -INFINITY) return true;
    for (std::uint32_t index : m_planes) {
        const Instance& instance = m_data->instances[index];
        if (!instance.casts_shadow) continue;
        DVec3 o, d;
        const float org[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
        const float dir[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
        ray_to_object(instance, org, dir, o, d);
        double t;
        if (intersect_plane(instance.plane, o, d, glm::max(ray.t_min, 0.0f), ray.t_max, t)) return true;
    }
    return false;
}

}  // namespace

std::unique_ptr<RenderScene> compile_scene(sg::SceneGraph graph) {
    return std::make_unique<EmbreeScene>(build_scene_data(graph));
}

}  // namespace lancer
