// mesh_camera's syntax as POV-Ray 3.7 reads it (its errors are located in
// diagnostics_test.cpp), and a mesh triangle's uv_vectors, which
// distribution type 3 places its rays by.
#include <gtest/gtest.h>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::parse_ok;

const char* const kTriangle = "triangle { <0, 0, 0>, <1, 0, 0>, <0, 1, 0> }";

TEST(ParserMeshCamera, SettingsMeshesAndTheVectorsPovReads) {
    const sg::SceneGraph scene = parse_ok(std::string("camera { mesh_camera { 2 0 mesh { ") + kTriangle +
                                          " translate <1, 2, 3> }\n"
                                          "  mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } } }\n"
                                          "  location <0, 0, 0.25> direction <0, 0, -1> }");
    ASSERT_TRUE(scene.camera);
    const sg::Camera& camera = *scene.camera;
    EXPECT_EQ(camera.projection, sg::Camera::Projection::Mesh);
    ASSERT_TRUE(camera.mesh);
    EXPECT_EQ(camera.mesh->rays_per_pixel, 2);
    EXPECT_EQ(camera.mesh->distribution, 0);
    EXPECT_EQ(camera.mesh->max_ray_distance, 0.0);
    EXPECT_FALSE(camera.mesh->smooth);
    ASSERT_EQ(camera.mesh->meshes.size(), 2u);
    // The mesh's own transforms travel with it; mesh { } drops the
    // triangles POV drops, mesh2 keeps them.
    EXPECT_EQ(sg::Vec3(camera.mesh->meshes[0].world_from_mesh[3]), sg::Vec3(1, 2, 3));
    EXPECT_TRUE(camera.mesh->meshes[0].drops_degenerate_faces);
    EXPECT_FALSE(camera.mesh->meshes[1].drops_degenerate_faces);
    EXPECT_EQ(camera.mesh->meshes[1].mesh->faces.size(), 1u);
    // POV reads location.z (start offset) and direction.z (its sign).
    EXPECT_EQ(camera.location.z, 0.25);
    EXPECT_EQ(camera.direction.z, -1.0);
    // A mesh camera's meshes are not objects of the scene.
    EXPECT_TRUE(scene.objects.empty());
}

TEST(ParserMeshCamera, OptionalMaximumRayDistance) {
    const sg::SceneGraph scene = parse_ok(std::string("camera { mesh_camera { 1 2 25 mesh { ") + kTriangle + " } } }");
    ASSERT_TRUE(scene.camera && scene.camera->mesh);
    EXPECT_EQ(scene.camera->mesh->distribution, 2);
    EXPECT_EQ(scene.camera->mesh->max_ray_distance, 25.0);
}

TEST(ParserMeshCamera, DeclaredMeshesInEveryForm) {
    // POV's mesh { M ... } copies a declared mesh (the form POV's own
    // mesh camera samples use); object { M } and mesh2 { M2 } too.
    const sg::SceneGraph scene = parse_ok(
        std::string("#declare M = mesh { ") + kTriangle +
        " }\n"
        "#declare M2 = mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } }\n"
        "camera { mesh_camera { 1 1 mesh { M rotate y * 90 } object { M } mesh2 { M2 scale 2 } mesh { M2 } } }\n"
        "object { mesh { M translate x } }");
    ASSERT_TRUE(scene.camera && scene.camera->mesh);
    const auto& meshes = scene.camera->mesh->meshes;
    ASSERT_EQ(meshes.size(), 4u);
    EXPECT_NEAR(meshes[0].world_from_mesh[0][2], -1.0, 1e-12);  // x turned to -z
    EXPECT_TRUE(meshes[1].drops_degenerate_faces);
    EXPECT_EQ(meshes[2].world_from_mesh[0][0], 2.0);
    EXPECT_FALSE(meshes[3].drops_degenerate_faces);
    // The declared copy is the same mesh, shared.
    EXPECT_EQ(meshes[0].mesh, meshes[1].mesh);
    // mesh { M } is an object like any other outside a camera.
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].kind, sg::Object::Kind::Mesh);
}

TEST(ParserMeshCamera, MeshTriangleUvVectors) {
    const sg::SceneGraph scene = parse_ok(
        "camera { mesh_camera { 1 3 mesh {\n"
        "  smooth_triangle { 0, z, x, z, y, z uv_vectors <0, 0>, <1, 0>, <0, 1> }\n"
        "  triangle { 0, x, -y }\n"
        "} smooth } }");
    ASSERT_TRUE(scene.camera && scene.camera->mesh);
    EXPECT_TRUE(scene.camera->mesh->smooth);
    const sg::TriangleMesh& mesh = *scene.camera->mesh->meshes[0].mesh;
    ASSERT_EQ(mesh.faces.size(), 2u);
    ASSERT_EQ(mesh.uvs.size(), 3u);
    EXPECT_EQ(mesh.uvs[std::size_t(mesh.faces[0].uv[1])], sg::Vec2(1, 0));
    EXPECT_EQ(mesh.uvs[std::size_t(mesh.faces[0].uv[2])], sg::Vec2(0, 1));
    EXPECT_EQ(mesh.faces[1].uv[0], -1);  // none given
}

TEST(ParserMeshCamera, WarningsForWhatPovIgnores) {
    const ParseResult extra_mesh =
        test::parse_snippet(std::string("camera { mesh_camera { 1 3 mesh { triangle { 0, x, y "
                                        "uv_vectors 0, <1, 0>, <0, 1> } } mesh { ") +
                                kTriangle + " } } }",
                            "test.pov");
    ASSERT_TRUE(extra_mesh.ok()) << test::all_diagnostics(extra_mesh);
    EXPECT_NE(test::all_diagnostics(extra_mesh).find("first mesh only"), std::string::npos);

    const ParseResult blurred = test::parse_snippet(
        std::string("camera { mesh_camera { 1 0 mesh { ") + kTriangle + " } } aperture 0.5 blur_samples 8 }",
        "test.pov");
    ASSERT_TRUE(blurred.ok()) << test::all_diagnostics(blurred);
    EXPECT_NE(test::all_diagnostics(blurred).find("focal blur is ignored"), std::string::npos);
    EXPECT_FALSE(blurred.scene->camera->focal_blur());
}

}  // namespace
}  // namespace lancer
