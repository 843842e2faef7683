// Building the Embree scene from the compiled scene data: the device, user
// geometry for analytic shapes, world meshes and instanced meshes.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

#include "geometry/embree_scene.h"

#include "geometry/containing_objects.h"
#include "geometry/light_blockers.h"

namespace lancer {
namespace embree {
namespace {

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

void record_device_error(void* user, RTCError code, const char* message) {
    auto* log = static_cast<std::string*>(user);
    if (log->empty()) *log = "Embree error " + std::to_string(int(code)) + ": " + (message ? message : "");
}

}  // namespace

EmbreeScene::EmbreeScene(std::unique_ptr<SceneData> data) : m_data(std::move(data)) {
    m_device = rtcNewDevice(nullptr);
    if (!m_device) throw std::runtime_error("cannot create the Embree device");
    rtcSetDeviceErrorFunction(m_device, record_device_error, &m_device_error);
    build();
    if (!m_device_error.empty()) throw std::runtime_error(m_device_error);
    // Only media, fog, rainbows and refraction read it (a scene without
    // them tests no object).
    if (m_data->has_media || m_data->fog || m_data->rainbows || m_data->has_refraction)
        m_camera_interiors = objects_containing(*m_data, m_data->camera.location());
}

EmbreeScene::~EmbreeScene() {
    if (m_scene) rtcReleaseScene(m_scene);
    for (RTCScene s : m_mesh_scenes) rtcReleaseScene(s);
    if (m_device) rtcReleaseDevice(m_device);
}

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
    for (Instance& instance : data.instances) {
        if (instance.csg_leaf) continue;  // traced through its tree's root
        instance.blocks_all_light = blocks_all_light(data, instance);
        instance.gathers_crossings = gathers_crossings(data, instance);
        if (!instance.casts_shadow || instance.blocks_all_light) continue;
        m_has_see_through_caster = true;
        if (instance.kind == ShapeKind::Mesh) m_has_see_through_mesh = true;
    }
    m_has_no_shadow_mesh = std::any_of(data.instances.begin(), data.instances.end(),
                                       [](const Instance& i) { return i.kind == ShapeKind::Mesh && !i.casts_shadow; });
    // The filter of shadow queries (shadow_filter), in every scene a mesh
    // may be traced in: an instanced mesh's own scene needs the flag too.
    const RTCSceneFlags scene_flags = RTCSceneFlags(
        kSceneFlags | (m_has_no_shadow_mesh || m_has_see_through_mesh ? RTC_SCENE_FLAG_CONTEXT_FILTER_FUNCTION : 0));
    m_scene = rtcNewScene(m_device);
    rtcSetSceneFlags(m_scene, scene_flags);
    rtcSetSceneBuildQuality(m_scene, kBuildQuality);

    // Analytic kinds present in the scene, one user geometry each.
    std::map<ShapeKind, AnalyticGroup*> groups;
    for (std::uint32_t index = 0; index < data.instances.size(); ++index) {
        const Instance& instance = data.instances[index];
        if (instance.csg_leaf || instance.kind == ShapeKind::Mesh) continue;
        // An object reaching past Embree's range would never be hit in the
        // BVH: it is tested on every ray, as the unbounded ones are.
        if (!instance.bounded || !within_embree_range(instance.bounds_lower) ||
            !within_embree_range(instance.bounds_upper)) {
            m_unbounded.add(instance, index);
            continue;
        }
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
        return id;
    };
    const bool has_meshes = std::any_of(data.instances.begin(), data.instances.end(), [](const Instance& i) {
        return i.kind == ShapeKind::Mesh && i.mesh && !i.mesh->indices.empty();
    });
    std::size_t bounded_shapes = 0;
    for (const auto& [kind, group] : groups) bounded_shapes += group->instances.size();
    m_has_meshes = has_meshes;
    m_traces_list = !has_meshes && bounded_shapes <= ShapeList::kMostShapes;
    for (auto& [kind, group] : groups) {
        RTCGeometry geometry = rtcNewGeometry(m_device, RTC_GEOMETRY_TYPE_USER);
        rtcSetGeometryUserPrimitiveCount(geometry, unsigned(group->instances.size()));
        rtcSetGeometryUserData(geometry, group);
        rtcSetGeometryBoundsFunction(geometry, analytic_bounds, nullptr);
        rtcSetGeometryIntersectFunction(geometry, analytic_intersect);
        rtcSetGeometryOccludedFunction(geometry, analytic_occluded);
        rtcCommitGeometry(geometry);
        const unsigned id = attach(geometry, GeometryEntry{group, 0});
        if (m_traces_list)
            for (unsigned primitive = 0; primitive < group->instances.size(); ++primitive)
                m_few_shapes.add(data.instances[group->instances[primitive]], group->instances[primitive], id,
                                 primitive);
    }

    // Meshes: world-space geometry when used once, instanced otherwise.
    for (std::uint32_t index = 0; index < data.instances.size(); ++index) {
        const Instance& instance = data.instances[index];
        if (instance.kind != ShapeKind::Mesh) continue;
        const MeshData& mesh = *instance.mesh;
        if (mesh.indices.empty()) continue;
        if (instance.mesh_in_world) {
            attach(make_triangles(mesh, instance.world_positions), GeometryEntry{nullptr, index});
            if (mesh.normals.empty() && mesh.uvs.empty() && instance.face_materials.empty() &&
                instance.interior_material == nullptr) {
                const unsigned id = unsigned(m_geometries.size() - 1);
                if (m_plain_triangles.size() <= id) m_plain_triangles.resize(id + 1);
                m_plain_triangles[id] = PlainTriangles{instance.world_positions.data(),
                                                       mesh.indices.data(),
                                                       instance.material,
                                                       emitter_of(instance, instance.material),
                                                       index,
                                                       instance.interior_id,
                                                       instance.casts_shadow,
                                                       instance.lit_by_global_lights,
                                                       instance.light_group,
                                                       instance.double_illuminate};
            }
            continue;
        }
        RTCScene& shared = m_scene_of_mesh[&mesh];
        if (!shared) {
            shared = rtcNewScene(m_device);
            rtcSetSceneFlags(shared, scene_flags);
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

}  // namespace embree

std::unique_ptr<RenderScene> make_embree_scene(std::unique_ptr<SceneData> data) {
    return std::make_unique<embree::EmbreeScene>(std::move(data));
}

}  // namespace lancer
