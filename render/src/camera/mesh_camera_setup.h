// The mesh camera's faces from the scene graph: POV's face order (a mesh { }
// without the triangles POV drops), corners, vertex normals and uv
// coordinates, and the settings POV reads off the camera's vectors.
#pragma once

#include <memory>

#include "camera/mesh_camera.h"
#include "lancer/scene_graph.h"

namespace lancer {

// Null unless the camera is a mesh camera with meshes.
std::unique_ptr<MeshCameraRays> make_mesh_camera_rays(const sg::Camera& camera);

// How many rays of a pixel the host averages: POV's rays_per_pixel, except
// for distribution type 1, where POV never finds a face for any ray but the
// first (so one ray gives its picture exactly).
int mesh_camera_rays_per_pixel(const sg::MeshCamera& camera);

}  // namespace lancer
