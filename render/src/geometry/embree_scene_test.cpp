// Intersections, normals, (u,v), transforms, instancing and materials of
// the compiled scene, from scene graphs built in C++.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "geometry/embree_scene.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/render_scene.h"
#include "lancer/scene_error.h"
#include "pov_text_scene.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;

std::unique_ptr<RenderScene> compile_objects(std::vector<sg::Object> objects) {
    sg::SceneGraph graph;
    graph.objects = std::move(objects);
    return compile_scene(graph);
}

TEST(EmbreeScene, SphereHitNormalAndUv) {
    auto scene = compile_pov_text("sphere { <0, 0, 5>, 1 pigment { uv_mapping checker } }");
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0), Vec3(0, 0, 1)), hit));
    EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
    EXPECT_NEAR(hit.position.z, 4.0f, 1e-5f);
    EXPECT_NEAR(hit.geometric_normal.z, -1.0f, 1e-6f);
    EXPECT_EQ(hit.geometric_normal, hit.shading_normal);
    // POV spherical map: equator at v = 0.5; -z is 3/4 of the way round from +x.
    EXPECT_NEAR(hit.uv.y, 0.5f, 1e-6f);
    EXPECT_NEAR(hit.uv.x, 0.75f, 1e-6f);
    ASSERT_NE(hit.material, nullptr);
    EXPECT_EQ(hit.emitter, nullptr);
    // North pole.
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0, 5, 5), Vec3(0, -1, 0)), hit));
    EXPECT_NEAR(hit.uv.y, 1.0f, 1e-6f);
    EXPECT_FALSE(scene->intersect(make_ray(Vec3(0, 2, 0), Vec3(0, 0, 1)), hit));
}

TEST(EmbreeScene, RayFromInsideSphereHitsFarSide) {
    auto scene = compile_objects({sphere_object({0, 0, 0}, 2.0)});
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0), Vec3(1, 0, 0)), hit));
    EXPECT_NEAR(hit.t, 2.0f, 1e-6f);
    EXPECT_FALSE(hit.is_front_face(Vec3(-1, 0, 0)));
    EXPECT_NEAR(hit.facing_normal(Vec3(-1, 0, 0)).x, -1.0f, 1e-6f);
}

TEST(EmbreeScene, BoxFacesNormalsAndUv) {
    auto scene = compile_pov_text("box { <-1, -2, -3>, <1, 2, 3> normal { uv_mapping bumps } }");
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(-10, 1, 1.5f), Vec3(1, 0, 0)), hit));
    EXPECT_NEAR(hit.t, 9.0f, 1e-5f);
    EXPECT_EQ(hit.geometric_normal, Vec3(-1, 0, 0));
    // POV's unfolded cube: the -x face is u in [0, 1/4] by z, v in [1/3, 2/3] by y.
    EXPECT_NEAR(hit.uv.x, (1.5f + 3.0f) / 6.0f / 4.0f, 1e-6f);
    EXPECT_NEAR(hit.uv.y, (1.0f + (1.0f + 2.0f) / 4.0f) / 3.0f, 1e-6f);
    // The top: u in [1/4, 1/2] by x, v in [2/3, 1] falling with z.
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0.5f, 10, -1.5f), Vec3(0, -1, 0)), hit));
    EXPECT_EQ(hit.geometric_normal, Vec3(0, 1, 0));
    EXPECT_NEAR(hit.uv.x, 0.25f + 0.75f / 4.0f, 1e-6f);
    EXPECT_NEAR(hit.uv.y, 1.0f - 0.25f / 3.0f, 1e-6f);
}

// A scene pays for (u, v) only where a texture reads it: without one, a
// sphere's, a box's and a cylinder's hits leave it zero (no arc tangents,
// no divisions, and a cylinder's own (u, v), which POV-Ray replaces by the
// world's x and y, is never computed);
// one reader anywhere (a pigment, a normal, a texture_map) gives every hit
// its (u, v).
TEST(EmbreeScene, HitsCarryUvWhereATextureReadsIt) {
    const Ray to_sphere = make_ray(Vec3(0), Vec3(0, 0, 1));
    const Ray to_box = make_ray(Vec3(-10, 1, 11.5f), Vec3(1, 0, 0));
    const Ray to_cylinder = make_ray(Vec3(5, 0.5f, -10), Vec3(0, 0, 1));
    const std::string shapes =
        "sphere { <0, 0, 5>, 1 }\nbox { <-1, -2, 7>, <1, 2, 13> }\ncylinder { <5, -1, 0>, <5, 1, 0>, 1 }\n";
    Hit hit;
    auto plain = compile_pov_text(shapes);
    for (const Ray& ray : {to_sphere, to_box, to_cylinder}) {
        ASSERT_TRUE(plain->intersect(ray, hit));
        EXPECT_EQ(hit.uv, Vec2(0.0f));
    }
    for (const char* reader :
         {"plane { y, -5 pigment { uv_mapping checker } }", "plane { y, -5 normal { uv_mapping bumps } }",
          "plane { y, -5 texture { uv_mapping checker texture { pigment { rgb 1 } } "
          "texture { pigment { rgb 0 } } } }"}) {
        auto reading = compile_pov_text(shapes + reader);
        ASSERT_TRUE(reading->intersect(to_sphere, hit)) << reader;
        EXPECT_NEAR(hit.uv.x, 0.75f, 1e-6f) << reader;
        EXPECT_NEAR(hit.uv.y, 0.5f, 1e-6f) << reader;
        ASSERT_TRUE(reading->intersect(to_box, hit)) << reader;
        EXPECT_NEAR(hit.uv.x, (1.5f + 3.0f) / 6.0f / 4.0f, 1e-6f) << reader;
        ASSERT_TRUE(reading->intersect(to_cylinder, hit)) << reader;
        EXPECT_EQ(hit.uv, Vec2(5.0f, 0.5f)) << reader;  // POV-Ray's: a cylinder's (u, v) is the world's x, y
    }
}

// POV-Ray defines no (u, v) for a plane: uv_mapping reads the hit's world
// x and y (ObjectBase::UVCoord).
TEST(EmbreeScene, PlaneHitUvIsItsWorldXyAsInPovRay) {
    auto scene = compile_pov_text("plane { y, -1 pigment { uv_mapping checker } }");
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(3, 5, 7), Vec3(0, -1, 0)), hit));
    EXPECT_NEAR(hit.t, 6.0f, 1e-5f);
    EXPECT_EQ(hit.geometric_normal, Vec3(0, 1, 0));
    EXPECT_NEAR(hit.uv.x, 3.0f, 1e-6f);
    EXPECT_NEAR(hit.uv.y, -1.0f, 1e-6f);
    EXPECT_TRUE(scene->bounds().empty());  // planes are not finite geometry
}

// Planes are tested from their world normal and distance, computed once
// for a placed one (geometry/unbounded_shapes.h): written in the world,
// moved, turned, scaled or mirrored they are found where they are, the
// nearer wins, the first listed wins a tie, and only those that cast
// shadows occlude.
TEST(EmbreeScene, PlanesInTheWorldOrPlacedAreFoundAlike) {
    sg::Object floor = plane_object({0, 1, 0}, 0.0, solid_material({1, 0, 0}));
    sg::Object placed = plane_object({0, 1, 0}, 0.0, solid_material({0, 1, 0}));
    placed.parent_from_object = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 2, 0));
    placed.no_shadow = true;
    auto scene = compile_objects({floor, placed});
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(1, 5, 1), Vec3(0, -1, 0)), hit));
    EXPECT_NEAR(hit.t, 3.0f, 1e-5f);
    EXPECT_EQ(hit.material->sample_surface(hit).pigment, Color(0, 1, 0));
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(1, 1, 1), Vec3(0, -1, 0)), hit));
    EXPECT_NEAR(hit.t, 1.0f, 1e-6f);
    EXPECT_EQ(hit.material->sample_surface(hit).pigment, Color(1, 0, 0));
    EXPECT_FALSE(scene->intersect(make_ray(Vec3(1, 1, 1), Vec3(1, 0, 0)), hit));  // parallel to both

    Ray through_placed = make_ray(Vec3(0, 3, 0), Vec3(0, -1, 0));
    through_placed.t_max = 2.0f;
    EXPECT_FALSE(scene->occluded(through_placed));  // the placed plane casts no shadow
    through_placed.t_max = 4.0f;
    EXPECT_TRUE(scene->occluded(through_placed));  // the floor does

    // Turned, scaled and moved: the plane through (0, 1, 0) whose normal is
    // y turned 30 degrees about x, hit along -y from (0, 5, 0) at
    // t = 4 (the plane dips along z, not x, so x moves nothing).
    sg::Object tilted = plane_object({0, 1, 0}, 0.0, solid_material({1, 1, 0}));
    tilted.parent_from_object = glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1, 0)) *
                                glm::rotate(glm::dmat4(1.0), glm::radians(30.0), glm::dvec3(1, 0, 0)) *
                                glm::scale(glm::dmat4(1.0), glm::dvec3(3, 0.5, 2));
    auto tilted_scene = compile_objects({tilted});
    ASSERT_TRUE(tilted_scene->intersect(make_ray(Vec3(0, 5, 0), Vec3(0, -1, 0)), hit));
    EXPECT_NEAR(hit.t, 4.0f, 1e-5f);
    ASSERT_TRUE(tilted_scene->intersect(make_ray(Vec3(0, 5, 1), Vec3(0, -1, 0)), hit));
    EXPECT_NEAR(hit.t, 4.0f + std::tan(glm::radians(30.0f)), 1e-5f);
    EXPECT_NEAR(glm::dot(hit.geometric_normal, Vec3(0, std::cos(glm::radians(30.0f)), std::sin(glm::radians(30.0f)))),
                1.0f, 1e-6f);
    EXPECT_TRUE(tilted_scene->occluded(make_ray(Vec3(0, 5, 1), Vec3(0, -1, 0))));
    EXPECT_FALSE(tilted_scene->intersect(make_ray(Vec3(0, 5, 1), Vec3(0, 1, 0)), hit));

    // Mirrored (a negative scale along its normal) and moved: the plane y = -1.
    sg::Object mirrored = plane_object({0, 1, 0}, 0.5, solid_material({1, 0, 1}));
    mirrored.parent_from_object =
        glm::translate(glm::dmat4(1.0), glm::dvec3(0, 1, 0)) * glm::scale(glm::dmat4(1.0), glm::dvec3(1, -4, 1));
    auto mirrored_scene = compile_objects({mirrored});
    ASSERT_TRUE(mirrored_scene->intersect(make_ray(Vec3(2, 5, 3), Vec3(0, -1, 0)), hit));
    EXPECT_NEAR(hit.t, 6.0f, 1e-5f);
    EXPECT_TRUE(mirrored_scene->occluded(make_ray(Vec3(2, -3, 3), Vec3(0, 1, 0))));

    // The same plane twice, once placed by a turn that leaves it in place.
    sg::Object turned = plane_object({0, 1, 0}, 0.0, solid_material({0, 0, 1}));
    turned.parent_from_object = glm::rotate(glm::dmat4(1.0), 1.0, glm::dvec3(0, 1, 0));
    for (const bool floor_first : {true, false}) {
        auto both = floor_first ? compile_objects({floor, turned}) : compile_objects({turned, floor});
        ASSERT_TRUE(both->intersect(make_ray(Vec3(0.5f, 2, 0.25f), Vec3(0, -1, 0)), hit));
        EXPECT_EQ(hit.material->sample_surface(hit).pigment, floor_first ? Color(1, 0, 0) : Color(0, 0, 1));
    }
}
// An object that is one shape made inverse (a room) is tested outside the
// BVH on its own; the same shape clipped by a sphere holding it is a
// bounded tree, found through the general CSG crossings: both must answer
// alike, inside and outside, placed or not, over limited t ranges.
TEST(EmbreeScene, AnInvertedShapeAnswersAsTheGeneralTree) {
    const char* shapes[] = {
        "box { <-3, 0, -4>, <3, 3, 4> inverse",
        "box { <-1, -2, -0.5>, <2, 1, 0.5> inverse rotate <10, 35, -5> scale <1, 2, 1.5> translate <0.5, 1, 0>",
        "sphere { <0.2, 1, 0.3>, 2.5 inverse",
        "sphere { 0, 1 inverse scale <3, 1, 2> translate y",
    };
    std::mt19937 random(7);
    std::uniform_real_distribution<float> coordinate(-6.0f, 6.0f), reach(0.1f, 12.0f);
    for (const char* shape : shapes) {
        auto lone = compile_pov_text(std::string(shape) + " }");
        auto tree = compile_pov_text(std::string(shape) + " clipped_by { sphere { 0, 100 } } }");
        for (int k = 0; k < 400; ++k) {
            const Vec3 origin(coordinate(random), coordinate(random) * 0.5f + 1.5f, coordinate(random));
            Ray ray = make_ray(origin, Vec3(coordinate(random), coordinate(random), coordinate(random)));
            ray.t_max = k % 2 ? reach(random) : kInfinity;
            Hit from_lone, from_tree;
            const bool found = lone->intersect(ray, from_lone);
            ASSERT_EQ(found, tree->intersect(ray, from_tree)) << shape << " ray " << k;
            EXPECT_EQ(lone->occluded(ray), tree->occluded(ray)) << shape << " ray " << k;
            if (!found) continue;
            EXPECT_EQ(from_lone.t, from_tree.t) << shape << " ray " << k;
            EXPECT_EQ(from_lone.position, from_tree.position) << shape << " ray " << k;
            EXPECT_EQ(from_lone.geometric_normal, from_tree.geometric_normal) << shape << " ray " << k;
        }
    }
}

TEST(EmbreeScene, TriangleBarycentricUvAndMeshUv) {
    auto mesh = triangle_mesh({0, 0, 5}, {4, 0, 5}, {0, 4, 5});
    auto scene = compile_objects({mesh_object(mesh)});
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(1, 2, 0), Vec3(0, 0, 1)), hit));
    EXPECT_NEAR(hit.t, 5.0f, 1e-5f);
    EXPECT_NEAR(std::fabs(hit.geometric_normal.z), 1.0f, 1e-6f);
    EXPECT_NEAR(hit.uv.x, 0.25f, 1e-5f);
    EXPECT_NEAR(hit.uv.y, 0.5f, 1e-5f);

    auto textured = std::make_shared<sg::TriangleMesh>(*mesh);
    textured->uvs = {{10, 10}, {14, 10}, {10, 14}};
    textured->faces[0].uv[0] = 0;
    textured->faces[0].uv[1] = 1;
    textured->faces[0].uv[2] = 2;
    scene = compile_objects({mesh_object(textured)});
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(1, 2, 0), Vec3(0, 0, 1)), hit));
    EXPECT_NEAR(hit.uv.x, 11.0f, 1e-4f);
    EXPECT_NEAR(hit.uv.y, 12.0f, 1e-4f);
}

TEST(EmbreeScene, SmoothTriangleInterpolatesNormals) {
    auto mesh = std::make_shared<sg::TriangleMesh>(*triangle_mesh({0, 0, 5}, {4, 0, 5}, {0, 4, 5}));
    mesh->normals = {glm::normalize(glm::dvec3(-1, 0, -1)), glm::normalize(glm::dvec3(1, 0, -1)), {0, 0, -1}};
    for (int k = 0; k < 3; ++k) mesh->faces[0].normal[k] = k;
    auto scene = compile_objects({mesh_object(mesh)});
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(2, 0.001f, 0), Vec3(0, 0, 1)), hit));
    EXPECT_NEAR(hit.shading_normal.x, 0.0f, 1e-3f);
    EXPECT_LT(hit.shading_normal.z, 0.0f);
    EXPECT_LT(hit.geometric_normal.z, 0.0f);  // turned to the authored side
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0.01f, 0.01f, 0), Vec3(0, 0, 1)), hit));
    EXPECT_LT(hit.shading_normal.x, -0.6f);
}

TEST(EmbreeScene, TransformsComposeThroughUnions) {
    // A unit sphere in a union translated by +10 x, itself scaled by 2.
    sg::Object child = sphere_object({0, 0, 0}, 1.0);
    child.parent_from_object = glm::scale(glm::dmat4(1.0), glm::dvec3(2.0));
    sg::Object group;
    group.kind = sg::Object::Kind::Union;
    group.shape = sg::Group{{child}};
    group.parent_from_object = glm::translate(glm::dmat4(1.0), glm::dvec3(10, 0, 0));
    group.material = solid_material({1, 0, 0});
    auto scene = compile_objects({group});
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(10, 0, -10), Vec3(0, 0, 1)), hit));
    EXPECT_NEAR(hit.t, 8.0f, 1e-5f);
    EXPECT_EQ(hit.material->sample_surface(hit).pigment, Color(1, 0, 0));  // inherited
    const Bounds b = scene->bounds();
    EXPECT_NEAR(b.lower.x, 8.0f, 1e-4f);
    EXPECT_NEAR(b.upper.x, 12.0f, 1e-4f);
}

TEST(EmbreeScene, NonUniformScaleGivesEllipsoidNormals) {
    sg::Object o = sphere_object({0, 0, 0}, 1.0);
    o.parent_from_object = glm::scale(glm::dmat4(1.0), glm::dvec3(4, 1, 1));
    auto scene = compile_objects({o});
    Hit hit;
    // Point (2, y, 0) on the ellipsoid x^2/16 + y^2 = 1: y = sqrt(3)/2.
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(2, 5, 0), Vec3(0, -1, 0)), hit));
    EXPECT_NEAR(hit.position.y, std::sqrt(3.0f) / 2.0f, 1e-5f);
    const Vec3 expected = glm::normalize(Vec3(2.0f / 16.0f, std::sqrt(3.0f) / 2.0f, 0.0f));
    EXPECT_NEAR(glm::dot(hit.geometric_normal, expected), 1.0f, 1e-5f);
}

TEST(EmbreeScene, MeshUsedTwiceIsInstancedWithEachTransform) {
    auto mesh = triangle_mesh({-1, -1, 0}, {1, -1, 0}, {0, 1, 0});
    auto scene = compile_objects(
        {mesh_object(mesh, solid_material({1, 0, 0}), glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 5))),
         mesh_object(mesh, solid_material({0, 1, 0}), glm::translate(glm::dmat4(1.0), glm::dvec3(10, 0, 7)))});
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0, 0, 0), Vec3(0, 0, 1)), hit));
    EXPECT_NEAR(hit.t, 5.0f, 1e-5f);
    EXPECT_EQ(hit.material->sample_surface(hit).pigment, Color(1, 0, 0));
    const std::uint32_t first = hit.object_id;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(10, 0, 0), Vec3(0, 0, 1)), hit));
    EXPECT_NEAR(hit.t, 7.0f, 1e-5f);
    EXPECT_NEAR(hit.position.x, 10.0f, 1e-5f);
    EXPECT_EQ(hit.material->sample_surface(hit).pigment, Color(0, 1, 0));
    EXPECT_NE(hit.object_id, first);
}

// Rays traced together (as the host traces camera rays) must find exactly
// what they find one by one, on every kind of shape, including instanced
// meshes, planes outside the BVH and rays that hit nothing; batch sizes
// that are not multiples of the packet width leave idle lanes.
void expect_batches_find_what_single_rays_find(const RenderScene& scene, int batch_size,
                                               RayCoherence coherence = RayCoherence::Coherent) {
    std::mt19937 random(7);
    std::uniform_real_distribution<float> spread(-0.6f, 0.6f);
    std::vector<Ray> rays;
    for (int i = 0; i < 1000; ++i) rays.push_back(make_ray(Vec3(0, 0.5f, 0), Vec3(spread(random), spread(random), 1)));
    int hits_found = 0;
    for (std::size_t first = 0; first < rays.size(); first += batch_size) {
        const int count = int(std::min<std::size_t>(batch_size, rays.size() - first));
        std::vector<Hit> batch(count);
        std::unique_ptr<bool[]> found(new bool[count]);
        scene.intersect_batch(&rays[first], count, batch.data(), found.get(), coherence);
        for (int i = 0; i < count; ++i) {
            Hit single;
            const bool single_found = scene.intersect(rays[first + i], single);
            ASSERT_EQ(found[i], single_found) << "ray " << first + i;
            if (!single_found) continue;
            ++hits_found;
            const Hit& h = batch[i];
            EXPECT_EQ(h.t, single.t);
            EXPECT_EQ(h.position, single.position);
            EXPECT_EQ(h.position_error, single.position_error);
            EXPECT_EQ(h.geometric_normal, single.geometric_normal);
            EXPECT_EQ(h.shading_normal, single.shading_normal);
            EXPECT_EQ(h.uv, single.uv);
            EXPECT_EQ(h.material, single.material);
            EXPECT_EQ(h.emitter, single.emitter);
            EXPECT_EQ(h.object_id, single.object_id);
            EXPECT_EQ(h.primitive_id, single.primitive_id);
            EXPECT_EQ(h.casts_shadow, single.casts_shadow);
        }
    }
    EXPECT_GT(hits_found, 500);  // the rays do meet the shapes
}

std::vector<sg::Object> shapes_of_every_kind(bool with_plane) {
    const auto mesh = triangle_mesh({-1, 0, 0}, {1, 0, 0}, {0, 1.5, 0});
    std::vector<sg::Object> objects = {
        sphere_object({-1.5, 0.5, 6}, 0.8, solid_material({1, 0, 0})),
        box_object({0.5, -0.5, 5}, {1.5, 0.5, 6}, solid_material({0, 1, 0})),
        mesh_object(mesh, solid_material({1, 1, 0}), glm::translate(glm::dmat4(1.0), glm::dvec3(0, 0, 8))),
        mesh_object(mesh, solid_material({0, 1, 1}), glm::translate(glm::dmat4(1.0), glm::dvec3(2, 1, 9))),
        // Used once, no normals or texture coordinates: a plain world mesh,
        // whose hits in packets are completed lane-parallel.
        mesh_object(triangle_mesh({-3, 2, 7}, {-2, 2, 7}, {-2.5, 3, 7}), solid_material({1, 0, 1})),
        mesh_object(triangle_mesh({-20, -20, 12}, {20, -20, 12}, {0, 20, 12}), solid_material({0.5, 0.5, 0.5})),
    };
    if (with_plane) objects.push_back(plane_object({0, 1, 0}, -1.0, solid_material({0, 0, 1})));
    return objects;
}

TEST(EmbreeScene, CoherentBatchesFindWhatSingleRaysFind) {
    expect_batches_find_what_single_rays_find(*compile_objects(shapes_of_every_kind(true)), 37);
}

// Without planes, packet lanes on plain world meshes take the lane-parallel
// completion, and long batches go through intersect_batch's pipeline.
TEST(EmbreeScene, CoherentBatchesWithoutPlanesFindWhatSingleRaysFind) {
    const auto scene = compile_objects(shapes_of_every_kind(false));
    expect_batches_find_what_single_rays_find(*scene, 37);
    expect_batches_find_what_single_rays_find(*scene, 256);
    expect_batches_find_what_single_rays_find(*scene, 1);
}

// Incoherent batches (bounces) are traced ray by ray: the same hits.
TEST(EmbreeScene, IncoherentBatchesFindWhatSingleRaysFind) {
    expect_batches_find_what_single_rays_find(*compile_objects(shapes_of_every_kind(true)), 37,
                                              RayCoherence::Incoherent);
}

// Compiling moves what hits read out of a graph it consumes, and copies
// it from a mesh the caller still holds: the caller's graph stays whole,
// and both render scenes find the same interpolated normals.
TEST(EmbreeScene, CompilingCopiesAMeshTheCallerShares) {
    auto mesh = std::make_shared<sg::TriangleMesh>(*triangle_mesh({0, 0, 5}, {4, 0, 5}, {0, 4, 5}));
    mesh->normals = {glm::normalize(glm::dvec3(-1, 0, -1)), glm::normalize(glm::dvec3(1, 0, -1)), {0, 0, -1}};
    for (int k = 0; k < 3; ++k) mesh->faces[0].normal[k] = k;
    sg::SceneGraph graph;
    graph.objects.push_back(mesh_object(mesh));
    const auto copied = compile_scene(graph);  // `graph` and `mesh` still hold the mesh
    EXPECT_EQ(mesh->normals.size(), 3u);
    EXPECT_EQ(mesh->faces.size(), 1u);
    const auto moved = compile_scene(std::move(graph));  // `mesh` still holds it: copied again
    EXPECT_EQ(mesh->normals.size(), 3u);
    mesh.reset();
    sg::SceneGraph alone;
    auto only = std::make_shared<sg::TriangleMesh>(*triangle_mesh({0, 0, 5}, {4, 0, 5}, {0, 4, 5}));
    only->normals = {glm::normalize(glm::dvec3(-1, 0, -1)), glm::normalize(glm::dvec3(1, 0, -1)), {0, 0, -1}};
    for (int k = 0; k < 3; ++k) only->faces[0].normal[k] = k;
    alone.objects.push_back(mesh_object(std::move(only)));
    const auto consumed = compile_scene(std::move(alone));  // the graph alone held it: moved
    const Ray ray = make_ray(Vec3(0.01f, 0.01f, 0), Vec3(0, 0, 1));
    Hit a, b, c;
    ASSERT_TRUE(copied->intersect(ray, a));
    ASSERT_TRUE(moved->intersect(ray, b));
    ASSERT_TRUE(consumed->intersect(ray, c));
    EXPECT_LT(a.shading_normal.x, -0.6f);  // the per-vertex normals were read
    EXPECT_EQ(a.shading_normal, b.shading_normal);
    EXPECT_EQ(a.shading_normal, c.shading_normal);
}

TEST(EmbreeScene, NoShadowObjectsDoNotOcclude) {
    sg::Object blocker = sphere_object({0, 0, 5}, 1.0);
    sg::Object mesh_blocker = mesh_object(triangle_mesh({-1, -1, 0}, {1, -1, 0}, {0, 1, 0}), nullptr,
                                          glm::translate(glm::dmat4(1.0), glm::dvec3(5, 0, 5)));
    auto shadowing = compile_objects({blocker, mesh_blocker});
    EXPECT_TRUE(shadowing->occluded(make_ray(Vec3(0), Vec3(0, 0, 1))));
    EXPECT_TRUE(shadowing->occluded(make_ray(Vec3(5, 0, 0), Vec3(0, 0, 1))));
    Ray short_ray = make_ray(Vec3(0), Vec3(0, 0, 1));
    short_ray.t_max = 3.0f;
    EXPECT_FALSE(shadowing->occluded(short_ray));
    blocker.no_shadow = true;
    mesh_blocker.no_shadow = true;
    auto scene = compile_objects({blocker, mesh_blocker});
    EXPECT_FALSE(scene->occluded(make_ray(Vec3(0), Vec3(0, 0, 1))));
    EXPECT_FALSE(scene->occluded(make_ray(Vec3(5, 0, 0), Vec3(0, 0, 1))));
    Hit hit;
    EXPECT_TRUE(scene->intersect(make_ray(Vec3(0), Vec3(0, 0, 1)), hit));  // still visible
    EXPECT_FALSE(hit.casts_shadow);
}

TEST(EmbreeScene, AreaLightsAreVisibleEmitters) {
    sg::SceneGraph graph;
    sg::Light rectangle;
    rectangle.kind = sg::Light::Kind::AreaRectangle;
    rectangle.position = {0, 5, 0};
    rectangle.axis1 = {2, 0, 0};
    rectangle.axis2 = {0, 0, 2};
    rectangle.color = {1, 1, 1};
    graph.lights.push_back(rectangle);
    auto scene = compile_scene(graph);
    ASSERT_EQ(scene->lights().size(), 1u);
    ASSERT_EQ(scene->local_lights().size(), 1u);
    EXPECT_EQ(scene->lights()[0]->kind(), Light::Kind::Rectangle);
    EXPECT_EQ(scene->local_lights()[0]->kind(), Light::Kind::Point);
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0.5f, 0, 0.5f), Vec3(0, 1, 0)), hit));
    EXPECT_EQ(hit.emitter, scene->lights()[0]);
    const SurfaceSample surface = hit.material->sample_surface(hit);
    // Le = pi * C / area, shown by both the material and the light.
    EXPECT_NEAR(hit.material->emitted(surface).r, kPi / 4.0f, 1e-5f);
    EXPECT_NEAR(hit.emitter->emitted(hit, Vec3(0, -1, 0)).r, kPi / 4.0f, 1e-5f);
    EXPECT_EQ(hit.material->brdf(surface, Vec3(0, -1, 0), Vec3(0, -1, 0), Vec3(0, -1, 0)), Color(0.0f));
}

TEST(EmbreeScene, EmissiveObjectsBecomeLightsExceptPlanes) {
    auto glowing = solid_material({1, 1, 1}, 0.0, {2, 2, 2});
    auto scene = compile_objects({sphere_object({0, 0, 5}, 1.0, glowing), box_object({3, 0, 0}, {4, 1, 1}, glowing),
                                  mesh_object(triangle_mesh({0, 0, 9}, {1, 0, 9}, {0, 1, 9}), glowing),
                                  plane_object({0, 1, 0}, -10.0, glowing)});
    EXPECT_EQ(scene->lights().size(), 3u);
    EXPECT_EQ(scene->local_lights().size(), 3u);
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0), Vec3(0, 0, 1)), hit));
    ASSERT_NE(hit.emitter, nullptr);
    EXPECT_EQ(hit.emitter->kind(), Light::Kind::EmissiveShape);
    EXPECT_NEAR(hit.emitter->emitted(hit, Vec3(0, 0, -1)).g, 2.0f, 1e-6f);
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0, 0, 0), Vec3(0, -1, 0)), hit));  // the plane still shows
    EXPECT_EQ(hit.emitter, nullptr);
    EXPECT_NEAR(hit.material->emitted(hit.material->sample_surface(hit)).r, 2.0f, 1e-6f);
}

TEST(EmbreeScene, BadMeshIndexIsASceneError) {
    auto mesh = std::make_shared<sg::TriangleMesh>(*triangle_mesh({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
    mesh->faces[0].position[2] = 7;
    sg::Object o = mesh_object(mesh);
    o.location.line = 12;
    try {
        compile_objects({o});
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().line, 12);
    }
}

TEST(EmbreeScene, OptionsBackgroundAndDefaultCamera) {
    sg::SceneGraph graph;
    graph.background = {0.1, 0.2, 0.3};
    graph.global.max_trace_level = 9;
    auto scene = compile_scene(graph);
    EXPECT_EQ(scene->options().max_trace_level, 9);
    EXPECT_NEAR(scene->background(Ray{}).b, 0.3f, 1e-7f);
    EXPECT_NEAR(scene->camera().right().x, 1.33f, 1e-7f);
    Hit hit;
    EXPECT_FALSE(scene->intersect(make_ray(Vec3(0), Vec3(0, 0, 1)), hit));
    EXPECT_FALSE(scene->occluded(make_ray(Vec3(0), Vec3(0, 0, 1))));
}

// A ray inside a box standing on a plane meets its bottom and the floor at
// one distance, and must see the floor, as POV-Ray does
// (tests/reference/pov/glass_on_floor.pov, a scene of a few shapes, traced
// from the shape list): here among enough shapes to be traced through the
// BVH, with turned and scaled boxes.
TEST(EmbreeScene, FromInsideABoxStandingOnAPlaneTheFloorIsSeen) {
    std::string text =
        "plane { y, 0 }\n"
        "box { <-0.6, 0, -0.6>, <0.6, 1.2, 0.6> rotate y*-20 translate <-1.6, 0, 0.1> }\n"
        "box { <-0.55, 0, -0.5>, <0.55, 1.5, 0.5> rotate y*30 scale 1.3 translate <0, 0, -0.1> }\n"
        "box { <1.0, 0, -0.4>, <2.2, 1.6, 0.8> }\n";
    for (int i = 0; i < 8; ++i) text += "sphere { <" + std::to_string(50 + 3 * i) + ", 10, 0>, 1 }\n";
    const auto scene = compile_pov_text(text);
    ASSERT_FALSE(dynamic_cast<const embree::EmbreeScene&>(*scene).traces_shape_list());
    const Vec3 centres[] = {Vec3(1.6f, 0.7f, 0.2f), Vec3(0.0f, 0.7f, -0.1f), Vec3(-1.6f, 0.7f, 0.1f)};
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    for (int i = 0; i < 3000; ++i) {
        const Vec3 origin = centres[i % 3] + Vec3(0.2f * unit(random), 0.3f * unit(random), 0.2f * unit(random));
        // Steeply down, so that the bottom is met before any side.
        const Vec3 direction = glm::normalize(Vec3(0.15f * unit(random), -1.0f, 0.15f * unit(random)));
        Hit hit;
        ASSERT_TRUE(scene->intersect(make_ray(origin, direction), hit)) << i;
        EXPECT_EQ(hit.position.y, 0.0f) << i;
        EXPECT_GT(hit.geometric_normal.y, 0.5f) << "the box's bottom face, not the floor: ray " << i;
    }
}

}  // namespace
}  // namespace lancer
