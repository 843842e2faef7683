// mesh_camera { rays_per_pixel, distribution_type [, max_ray_distance]
// mesh { } ... [smooth] }, checked as POV-Ray 3.7's Parse_Mesh_Camera
// checks it (parse.cpp, read for its rules and messages). The rays
// themselves are made by the renderer (render/src/camera/mesh_camera.cpp).
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {

std::function<void(CameraSpec&)> Evaluator::mesh_camera(
    const Value& rays, const SourceRange& wr, const Value& distribution, const SourceRange& wd,
    const std::optional<std::pair<Value, SourceRange>>& reach,
    const std::vector<std::pair<ShapePtr, sg::SourceLocation>>& meshes,
    const std::optional<sg::SourceLocation>& smooth_at, const sg::SourceLocation& at,
    const sg::SourceLocation& close_at) {
    auto camera = std::make_shared<sg::MeshCamera>();
    // POV truncates both numbers, as it does every integer it reads.
    const double rays_value = to_float(rays, wr, "a number of rays per pixel");
    const double type_value = to_float(distribution, wd, "a distribution type (0 to 3)");
    camera->rays_per_pixel = std::isfinite(rays_value) && std::fabs(rays_value) < 1e9 ? int(rays_value) : 0;
    camera->distribution = std::isfinite(type_value) && std::fabs(type_value) < 1e9 ? int(type_value) : -1;
    if (reach) camera->max_ray_distance = to_float(reach->first, reach->second, "a maximum ray distance");
    camera->smooth = smooth_at.has_value();

    bool ok = true;
    auto fail = [&](const sg::SourceLocation& where, const std::string& message) {
        error(where, message);
        ok = false;
    };
    if (camera->rays_per_pixel < 1)
        fail(wr.begin, "mesh_camera needs at least 1 ray per pixel, got " + std::to_string(camera->rays_per_pixel));
    if (camera->distribution < 0 || camera->distribution > 3) {
        fail(wd.begin, "unknown mesh_camera distribution type " + std::to_string(camera->distribution) +
                           ": the types are 0 to 3");
    } else if (camera->distribution >= 2 && camera->rays_per_pixel != 1) {
        fail(wr.begin, "rays per pixel must be 1 for distribution type " + std::to_string(camera->distribution) +
                           ", got " + std::to_string(camera->rays_per_pixel));
    }
    if (smooth_at && camera->distribution != 3)
        fail(*smooth_at, "smooth only works with distribution type 3 (rays placed by uv coordinates)");

    for (const auto& [shape, where] : meshes) {
        const sg::Object& object = shape->object;
        if (object.kind != sg::Object::Kind::Mesh && object.kind != sg::Object::Kind::Mesh2) {
            fail(where, "a mesh_camera takes mesh and mesh2 objects only");
            continue;
        }
        if (!shape->lights.empty()) warning(where, "light sources inside a mesh_camera's mesh are ignored");
        sg::MeshCamera::Mesh mesh;
        mesh.mesh = std::get<sg::MeshRef>(object.shape);
        mesh.world_from_mesh = object.parent_from_object;
        mesh.drops_degenerate_faces = object.kind == sg::Object::Kind::Mesh;
        mesh.location = where;
        camera->meshes.push_back(std::move(mesh));
    }
    if (meshes.empty()) fail(close_at, "mesh_camera needs at least one mesh or mesh2 before its closing brace");
    if (!ok) return [](CameraSpec&) {};

    const std::size_t count = camera->meshes.size();
    // The host averages a pixel's rays in one batch of 256 camera samples.
    constexpr int kMostRaysPerPixel = 256;
    if (camera->distribution == 0 && std::size_t(camera->rays_per_pixel) > count) {
        error(wr.begin, "distribution type 0 sends a pixel's r-th ray from the r-th mesh: " +
                            std::to_string(camera->rays_per_pixel) + " rays per pixel need as many meshes, found " +
                            std::to_string(count));
        return [](CameraSpec&) {};
    }
    if (camera->rays_per_pixel > kMostRaysPerPixel) {
        error(wr.begin, "mesh_camera takes at most " + std::to_string(kMostRaysPerPixel) + " rays per pixel");
        return [](CameraSpec&) {};
    }
    if (camera->distribution == 3) {
        if (count > 1)
            warning(camera->meshes[1].location,
                    "distribution type 3 reads the first mesh only; the others are ignored (as in POV-Ray)");
        const sg::TriangleMesh& first = *camera->meshes.front().mesh;
        bool has_uv = false;
        for (const auto& face : first.faces) has_uv = has_uv || face.uv[0] >= 0;
        if (!has_uv) {
            error(camera->meshes.front().location,
                  "distribution type 3 places rays by the mesh's uv coordinates, and this mesh has none: give its "
                  "triangles uv_vectors (a mesh2: uv_vectors and uv_indices)");
            return [](CameraSpec&) {};
        }
    }
    return [camera, at](CameraSpec& c) {
        c.set_projection(sg::Camera::Projection::Mesh, at);
        c.mesh = camera;
    };
}

}  // namespace lancer::parse
