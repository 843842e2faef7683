// The mesh camera's rays, against answers worked out by hand from POV-Ray
// 3.7's CreateCameraRay: which face a pixel takes per distribution type,
// where its ray starts and where it points.
#include "camera/mesh_camera.h"

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "camera/mesh_camera_setup.h"
#include "lancer/camera.h"

namespace lancer {
namespace {

using DVec3 = glm::dvec3;

// A small triangle at `centre` in the z = centre.z plane; POV's normal,
// (P3 - P1) x (P2 - P1), is -z.
MeshCameraFace face_at(const DVec3& centre) {
    MeshCameraFace face;
    face.corners[0] = centre + DVec3(-0.1, -0.1, 0.0);
    face.corners[1] = centre + DVec3(0.2, -0.1, 0.0);
    face.corners[2] = centre + DVec3(-0.1, 0.2, 0.0);
    return face;
}

// Faces whose centroids are at (i, 0, 0) for i = 0 .. count - 1.
std::vector<MeshCameraFace> numbered_faces(int count, double z = 0.0) {
    std::vector<MeshCameraFace> faces;
    for (int i = 0; i < count; ++i) faces.push_back(face_at(DVec3(i, 0.0, z)));
    return faces;
}

MeshCameraRays rays_of(MeshCameraRays::Distribution distribution, double offset = 0.0, bool reversed = false) {
    MeshCameraRays::Settings settings;
    settings.distribution = distribution;
    settings.start_offset = offset;
    settings.reversed = reversed;
    return MeshCameraRays(settings);
}

// The face index (the centroid's x) pixel (column, row) of a width x height
// image gets through its centre, or -1 without a ray.
int face_seen(const MeshCameraRays& rays, int column, int row, int width, int height, int ray_number = 0) {
    DVec3 origin, direction;
    if (!rays.generate(column + 0.5, row + 0.5, width, height, ray_number, origin, direction)) return -1;
    return int(std::lround(origin.x));
}

// Two meshes of numbered faces, the first at z = 0, the second at z = z1.
MeshCameraRays two_meshes(MeshCameraRays::Distribution distribution, int faces0, int faces1, double z1) {
    MeshCameraRays rays = rays_of(distribution);
    rays.add_mesh(numbered_faces(faces0, 0.0), glm::dmat4(1.0));
    rays.add_mesh(numbered_faces(faces1, z1), glm::dmat4(1.0));
    return rays;
}

// The ray through film point (x, y) must start at `expected`.
void expect_start(const MeshCameraRays& rays, double x, double y, int width, int height, int ray_number,
                  const DVec3& expected) {
    DVec3 origin, direction;
    ASSERT_TRUE(rays.generate(x, y, width, height, ray_number, origin, direction));
    EXPECT_NEAR(glm::length(origin - expected), 0.0, 1e-6) << origin.x << " " << origin.y << " " << origin.z;
}

TEST(MeshCamera, FacePerPixelStartsAtTheCentroidAlongTheNormal) {
    MeshCameraRays rays = rays_of(MeshCameraRays::Distribution::FacePerPixel, 0.5);
    rays.add_mesh(numbered_faces(12), glm::dmat4(1.0));
    DVec3 origin, direction;
    // Pixel (2, 1) of a 4 x 3 image: POV reads its point half a pixel above
    // the top edge, in row 0, so face 2.
    ASSERT_TRUE(rays.generate(2.5, 1.5, 4, 3, 0, origin, direction));
    EXPECT_NEAR(origin.x, 2.0, 1e-6);
    EXPECT_NEAR(origin.y, 0.0, 1e-6);
    EXPECT_NEAR(origin.z, -0.5, 1e-6);  // moved 0.5 along the normal, -z
    EXPECT_NEAR(direction.x, 0.0, 1e-6);
    EXPECT_NEAR(direction.y, 0.0, 1e-6);
    EXPECT_NEAR(direction.z, -1.0, 1e-6);
    // Rows 0 and 1 both read face row 0; row 2 reads face row 1.
    EXPECT_EQ(face_seen(rays, 3, 0, 4, 3), 3);
    EXPECT_EQ(face_seen(rays, 3, 1, 4, 3), 3);
    EXPECT_EQ(face_seen(rays, 1, 2, 4, 3), 5);
}

TEST(MeshCamera, PixelsPastTheFacesGetNoRay) {
    MeshCameraRays rays = rays_of(MeshCameraRays::Distribution::FacePerPixel);
    rays.add_mesh(numbered_faces(6), glm::dmat4(1.0));
    EXPECT_EQ(face_seen(rays, 1, 2, 4, 3), 5);
    EXPECT_EQ(face_seen(rays, 2, 2, 4, 3), -1);
    // Film points off the image are clamped into it.
    DVec3 origin, direction;
    ASSERT_TRUE(rays.generate(-3.0, -3.0, 4, 3, 0, origin, direction));
    EXPECT_NEAR(origin.x, 0.0, 1e-6);
}

TEST(MeshCamera, ReversedRaysAreTurnedAfterTheOffset) {
    MeshCameraRays rays = rays_of(MeshCameraRays::Distribution::FacePerPixel, 0.5, true);
    rays.add_mesh(numbered_faces(1), glm::dmat4(1.0));
    DVec3 origin, direction;
    ASSERT_TRUE(rays.generate(0.5, 0.5, 1, 1, 0, origin, direction));
    EXPECT_NEAR(origin.z, -0.5, 1e-6);
    EXPECT_NEAR(direction.z, 1.0, 1e-6);
}

TEST(MeshCamera, FacePerPixelTakesTheRthMeshForTheRthRay) {
    const MeshCameraRays rays = two_meshes(MeshCameraRays::Distribution::FacePerPixel, 4, 4, 7.0);
    expect_start(rays, 1.5, 0.5, 2, 2, 1, DVec3(1.0, 0.0, 7.0));
    DVec3 origin, direction;
    EXPECT_FALSE(rays.generate(1.5, 0.5, 2, 2, 2, origin, direction));
}

TEST(MeshCamera, MeshesInARowCountOnAcrossMeshesAndOnlyTheFirstRayFindsAFace) {
    const MeshCameraRays rays = two_meshes(MeshCameraRays::Distribution::MeshesInARow, 5, 7, 3.0);
    // Pixel (2, 2) of 4 x 3 reads pixel index 1 * 4 + 2 = 6: the second
    // mesh's face 1.
    expect_start(rays, 2.5, 2.5, 4, 3, 0, DVec3(1.0, 0.0, 3.0));
    DVec3 origin, direction;
    EXPECT_FALSE(rays.generate(0.5, 0.5, 4, 3, 1, origin, direction));
}

TEST(MeshCamera, SideBySideStripsNumberFacesByTheImageColumn) {
    const MeshCameraRays rays = two_meshes(MeshCameraRays::Distribution::SideBySide, 8, 8, 5.0);
    // 4 x 3: strips 2 wide. Pixel (3, 2): right strip, face 1 * 2 + 3 = 5.
    expect_start(rays, 3.5, 2.5, 4, 3, 0, DVec3(5.0, 0.0, 5.0));
    // Pixel (1, 2): left strip, face 1 * 2 + 1 = 3.
    expect_start(rays, 1.5, 2.5, 4, 3, 0, DVec3(3.0, 0.0, 0.0));
}

TEST(MeshCamera, TheMeshTransformsMoveTheStartAndTurnTheNormalAsANormal) {
    MeshCameraRays rays = rays_of(MeshCameraRays::Distribution::FacePerPixel, 1.0);
    // A face whose normal is (1, 1, 0) / sqrt 2: corners in a plane x + y = 1.
    MeshCameraFace face;
    face.corners[0] = DVec3(1, 0, 0);
    face.corners[1] = DVec3(0.5, 0.5, 1);
    face.corners[2] = DVec3(0, 1, 0);
    ASSERT_GT(
        glm::dot(glm::cross(face.corners[2] - face.corners[0], face.corners[1] - face.corners[0]), DVec3(1, 1, 0)),
        0.0);
    glm::dmat4 world_from_mesh(1.0);
    world_from_mesh[1][1] = 2.0;                   // scale y by 2
    world_from_mesh[3] = glm::dvec4(0, 0, 10, 1);  // then translate z by 10
    rays.add_mesh({face}, world_from_mesh);
    DVec3 origin, direction;
    ASSERT_TRUE(rays.generate(0.5, 0.5, 1, 1, 0, origin, direction));
    // Start: centroid (0.5, 0.5, 1/3) + 1 * (0.7071, 0.7071, 0), then
    // scaled and moved.
    const double s = std::sqrt(0.5);
    EXPECT_NEAR(origin.x, 0.5 + s, 1e-6);
    EXPECT_NEAR(origin.y, 2.0 * (0.5 + s), 1e-6);
    EXPECT_NEAR(origin.z, 10.0 + 1.0 / 3.0, 1e-6);
    // A normal scales by the inverse: (1, 1/2, 0), normalised.
    const DVec3 expected = glm::normalize(DVec3(1.0, 0.5, 0.0));
    EXPECT_NEAR(direction.x, expected.x, 1e-6);
    EXPECT_NEAR(direction.y, expected.y, 1e-6);
    EXPECT_NEAR(direction.z, 0.0, 1e-6);
}

TEST(MeshCamera, AFaceWithoutANormalGivesNoRay) {
    MeshCameraRays rays = rays_of(MeshCameraRays::Distribution::FacePerPixel);
    MeshCameraFace flat;
    flat.corners[0] = DVec3(0, 0, 0);
    flat.corners[1] = DVec3(1, 0, 0);
    flat.corners[2] = DVec3(2, 0, 0);
    rays.add_mesh({flat}, glm::dmat4(1.0));
    DVec3 origin, direction;
    EXPECT_FALSE(rays.generate(0.5, 0.5, 1, 1, 0, origin, direction));
}

// Two faces covering the uv square, split along its diagonal; the first
// on z = 0 (u, v) = (x, y), the second on z = 1; vertex normals leaning.
std::vector<MeshCameraFace> uv_square() {
    MeshCameraFace lower, upper;
    lower.corners[0] = DVec3(0, 0, 0);
    lower.corners[1] = DVec3(1, 0, 0);
    lower.corners[2] = DVec3(1, 1, 0);
    lower.uv[0] = glm::dvec2(0, 0);
    lower.uv[1] = glm::dvec2(1, 0);
    lower.uv[2] = glm::dvec2(1, 1);
    lower.smooth = true;
    lower.vertex_normals[0] = DVec3(0, 0, -1);
    lower.vertex_normals[1] = DVec3(1, 0, 0);
    lower.vertex_normals[2] = DVec3(0, 1, 0);
    upper = lower;
    for (auto& corner : upper.corners) corner.z = 1.0;
    upper.corners[1] = DVec3(0, 1, 1);
    upper.uv[1] = glm::dvec2(0, 1);
    upper.smooth = false;
    return {lower, upper};
}

TEST(MeshCamera, UvMappedRayLeavesTheFacePointItsUvNames) {
    MeshCameraRays::Settings settings;
    settings.distribution = MeshCameraRays::Distribution::UvMapped;
    settings.smooth = true;
    MeshCameraRays rays(settings);
    rays.add_mesh(uv_square(), glm::dmat4(1.0));
    DVec3 origin, direction;
    // Pixel (6, 4) of 10 x 10, through its centre (6.5, 4.5): POV's point
    // is (x - 0.5, y - 1 + 0.5), so u = 6 / 10 and v = 1 - 4 / 10.
    ASSERT_TRUE(rays.generate(6.5, 4.5, 10, 10, 0, origin, direction));
    // (0.6, 0.6) lies on the diagonal both faces share: the first holds it,
    // barycentric (0.4, 0, 0.6).
    EXPECT_NEAR(origin.x, 0.6, 1e-9);
    EXPECT_NEAR(origin.y, 0.6, 1e-9);
    EXPECT_NEAR(origin.z, 0.0, 1e-9);
    EXPECT_NEAR(direction.x, 0.0, 1e-9);
    EXPECT_NEAR(direction.y, 0.6, 1e-9);
    EXPECT_NEAR(direction.z, -0.4, 1e-9);
    // (0.2, 0.7): only the second face holds it; without vertex normals
    // its own normal, (P3 - P1) x (P2 - P1) = (1,1,0) x (0,1,0) = +z.
    ASSERT_TRUE(rays.generate(2.5, 3.5, 10, 10, 0, origin, direction));
    EXPECT_NEAR(origin.x, 0.2, 1e-9);
    EXPECT_NEAR(origin.y, 0.7, 1e-9);
    EXPECT_NEAR(origin.z, 1.0, 1e-9);
    EXPECT_NEAR(direction.z, 1.0, 1e-9);
}

TEST(MeshCamera, UvMappedWithoutSmoothUsesTheFaceNormalAndMissesOutsideTheFaces) {
    MeshCameraRays rays = rays_of(MeshCameraRays::Distribution::UvMapped);
    std::vector<MeshCameraFace> faces = uv_square();
    faces.pop_back();  // the upper-left half of the square has no face now
    rays.add_mesh(faces, glm::dmat4(1.0));
    DVec3 origin, direction;
    ASSERT_TRUE(rays.generate(6.5, 4.5, 10, 10, 0, origin, direction));
    EXPECT_NEAR(direction.z, -1.0, 1e-9);  // (P3 - P1) x (P2 - P1) = -z
    EXPECT_FALSE(rays.generate(2.5, 3.5, 10, 10, 0, origin, direction));
}

TEST(MeshCamera, CameraNormalisesAndLimitsTheRay) {
    MeshCameraRays::Settings settings;
    settings.max_distance = 3.0;
    MeshCameraRays rays(settings);
    MeshCameraFace face = face_at(DVec3(0.0));
    rays.add_mesh({face}, glm::scale(glm::dmat4(1.0), DVec3(2.0)));
    Camera camera(Camera::Projection::Mesh, Vec3(0.0f), Vec3(0, 0, 1), Vec3(1.33f, 0, 0), Vec3(0, 1, 0));
    camera.set_mesh(&rays, 1);
    Ray ray;
    ASSERT_TRUE(camera.generate_ray(0.5f, 0.5f, 2, 2, ray));
    EXPECT_NEAR(glm::length(ray.direction), 1.0f, 1e-6f);
    EXPECT_EQ(ray.t_max, 3.0f);
    EXPECT_FALSE(camera.generate_ray(1.5f, 0.5f, 2, 2, ray));  // face 1 does not exist
}

TEST(MeshCameraSetup, MeshDropsTheTrianglesPovDropsMesh2KeepsThem) {
    auto mesh = std::make_shared<sg::TriangleMesh>();
    mesh->positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {2, 0, 0}, {5, 5, 0}, {6, 5, 0}, {5, 6, 0}};
    sg::TriangleMesh::Face degenerate, first, second;
    degenerate.position[0] = 0, degenerate.position[1] = 1, degenerate.position[2] = 3;
    first.position[0] = 0, first.position[1] = 1, first.position[2] = 2;
    second.position[0] = 4, second.position[1] = 5, second.position[2] = 6;
    mesh->faces = {first, degenerate, second};
    sg::Camera camera;
    camera.projection = sg::Camera::Projection::Mesh;
    camera.location = sg::Vec3(0, 0, 0);
    auto settings = std::make_shared<sg::MeshCamera>();
    sg::MeshCamera::Mesh as_mesh;
    as_mesh.mesh = mesh;
    as_mesh.drops_degenerate_faces = true;
    settings->meshes = {as_mesh};
    camera.mesh = settings;
    auto rays = make_mesh_camera_rays(camera);
    ASSERT_TRUE(rays);
    // 2 x 1 image: pixel 1 reads face 1, the third written (the collinear
    // one dropped).
    DVec3 origin, direction;
    ASSERT_TRUE(rays->generate(1.5, 0.5, 2, 1, 0, origin, direction));
    EXPECT_NEAR(origin.x, 16.0 / 3.0, 1e-6);  // the face rays are kept in float

    settings->meshes[0].drops_degenerate_faces = false;  // mesh2: kept, no ray
    rays = make_mesh_camera_rays(camera);
    EXPECT_FALSE(rays->generate(1.5, 0.5, 2, 1, 0, origin, direction));
}

}  // namespace
}  // namespace lancer
