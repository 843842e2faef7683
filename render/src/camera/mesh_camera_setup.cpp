#include "camera/mesh_camera_setup.h"

namespace lancer {
namespace {

// POV's test for the triangles mesh { } drops: (P1 - P2) x (P3 - P2) is
// exactly zero.
bool povray_drops(const glm::dvec3& p1, const glm::dvec3& p2, const glm::dvec3& p3) {
    return glm::length(glm::cross(p1 - p2, p3 - p2)) == 0.0;
}

std::vector<MeshCameraFace> camera_faces(const sg::MeshCamera::Mesh& source) {
    const sg::TriangleMesh& mesh = *source.mesh;
    std::vector<MeshCameraFace> faces;
    faces.reserve(mesh.faces.size());
    for (const sg::TriangleMesh::Face& f : mesh.faces) {
        MeshCameraFace face;
        for (int i = 0; i < 3; ++i) face.corners[i] = mesh.positions[std::size_t(f.position[i])];
        if (source.drops_degenerate_faces && povray_drops(face.corners[0], face.corners[1], face.corners[2])) continue;
        face.smooth = f.normal[0] >= 0;
        for (int i = 0; i < 3 && face.smooth; ++i) face.vertex_normals[i] = mesh.normals[std::size_t(f.normal[i])];
        // A triangle without uv_vectors has POV's <0,0> at every corner: no
        // uv triangle, so type 3 never finds it.
        for (int i = 0; i < 3; ++i) face.uv[i] = f.uv[i] >= 0 ? mesh.uvs[std::size_t(f.uv[i])] : glm::dvec2(0.0);
        faces.push_back(face);
    }
    return faces;
}

}  // namespace

int mesh_camera_rays_per_pixel(const sg::MeshCamera& camera) {
    return camera.distribution == 1 ? 1 : camera.rays_per_pixel;
}

std::unique_ptr<MeshCameraRays> make_mesh_camera_rays(const sg::Camera& camera) {
    if (camera.projection != sg::Camera::Projection::Mesh || !camera.mesh || camera.mesh->meshes.empty())
        return nullptr;
    const sg::MeshCamera& settings = *camera.mesh;
    MeshCameraRays::Settings rays;
    rays.distribution = static_cast<MeshCameraRays::Distribution>(settings.distribution);
    // POV's reading of the camera's vectors (CreateCameraRay): location.z
    // moves the start along the normal; a direction.z below -EPSILON sends
    // the rays against it. Both after look_at and the camera's transforms.
    rays.start_offset = camera.location.z;
    rays.reversed = camera.direction.z < -1e-10;
    rays.smooth = settings.smooth;
    rays.max_distance = settings.max_ray_distance;
    auto result = std::make_unique<MeshCameraRays>(rays);
    for (const sg::MeshCamera::Mesh& mesh : settings.meshes) result->add_mesh(camera_faces(mesh), mesh.world_from_mesh);
    return result;
}

}  // namespace lancer
