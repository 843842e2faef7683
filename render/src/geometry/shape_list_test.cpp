// A scene of a few shapes is traced from a list of their boxes instead of
// Embree's BVH (geometry/shape_list.h): both must give the same answers.
// The same shapes are compiled twice, the second time with tiny spheres
// far above everything that push the scene over the list's limit, and the
// same random rays (none can reach the far spheres) must find the same
// hits and the same shadows in both.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <string>

#include "geometry/embree_scene.h"
#include "pov_text_scene.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

std::unique_ptr<RenderScene> compile(const std::string& objects) {
    return testing::compile_pov_text("camera { location -5*z look_at 0 }\n" + objects, "<list>");
}

bool traces_list(const RenderScene& scene) {
    return dynamic_cast<const embree::EmbreeScene&>(scene).traces_shape_list();
}

// Shapes of each analytic kind the list holds: a sphere, a turned box,
// a torus (a Shape), a CSG difference, a no_shadow sphere and box, and a
// plane (outside both the list and the BVH).
const std::string kFewShapes =
    "sphere { <-1, 0.5, 0>, 0.8 }\n"
    "box { <0.2, -0.5, -0.5>, <1.4, 0.9, 0.7> rotate <20, 35, 0> }\n"
    "torus { 0.9, 0.25 rotate x * 70 translate <0, 1.4, 1> }\n"
    "difference { sphere { <0, -0.6, -1>, 0.7 } box { <-1, -0.6, -2>, <1, 0.5, 0> } }\n"
    "sphere { <1.5, 1.5, -0.5>, 0.4 no_shadow }\n"
    "box { <-0.4, -0.3, -0.2>, <0.4, 0.3, 0.2> scale <1, 2, 1> rotate <10, -30, 50> translate <-1.6, -0.5, -1.5>"
    " no_shadow }\n"
    "plane { y, -1.2 }\n";

std::string far_spheres(int count) {
    std::string text;
    for (int i = 0; i < count; ++i) text += "sphere { <" + std::to_string(i) + ", 1e4, 0>, 0.001 }\n";
    return text;
}

TEST(ShapeList, AFewShapesFindWhatTheBvhFinds) {
    const auto few = compile(kFewShapes);
    const auto many = compile(kFewShapes + far_spheres(embree::ShapeList::kMostShapes));
    ASSERT_TRUE(traces_list(*few));
    ASSERT_FALSE(traces_list(*many));

    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
    int hits = 0, shadows = 0;
    for (int i = 0; i < 20000; ++i) {
        Ray ray;
        ray.origin = Vec3(3.0f * unit(random), 3.0f * unit(random), 3.0f * unit(random));
        // Away from +y, where the far spheres are.
        ray.direction = glm::normalize(Vec3(unit(random), 0.5f * unit(random) - 0.5f, unit(random)));
        if (i % 4 == 0) ray.t_max = 2.0f;  // short rays too, as shadow rays are
        Hit a, b;
        const bool found_a = few->intersect(ray, a);
        const bool found_b = many->intersect(ray, b);
        ASSERT_EQ(found_a, found_b) << "ray " << i;
        if (found_a) {
            ++hits;
            EXPECT_EQ(a.t, b.t) << "ray " << i;
            EXPECT_EQ(a.object_id, b.object_id) << "ray " << i;
            EXPECT_EQ(a.geometric_normal, b.geometric_normal) << "ray " << i;
            EXPECT_EQ(a.uv, b.uv) << "ray " << i;
        }
        const bool shadowed = few->occluded(ray);
        ASSERT_EQ(shadowed, many->occluded(ray)) << "ray " << i;
        shadows += shadowed;
    }
    // Both answers occur often enough for the comparison to mean something.
    EXPECT_GT(hits, 5000);
    EXPECT_GT(shadows, 2000);
    EXPECT_LT(shadows, hits);  // the no_shadow sphere is hit but casts none
}

TEST(ShapeList, CoherentBatchesFindWhatSingleRaysFind) {
    const auto scene = compile(kFewShapes);
    ASSERT_TRUE(traces_list(*scene));
    constexpr int kRays = 37;  // not a whole number of packets
    Ray rays[kRays];
    for (int i = 0; i < kRays; ++i)
        rays[i] = testing::make_ray(Vec3(-2.0f + 0.1f * float(i), 0.3f, -5.0f), Vec3(0.0f, 0.0f, 1.0f));
    rays[5].origin.x = std::numeric_limits<float>::infinity();  // untraceable: a miss, as single rays give
    Hit hits[kRays];
    bool found[kRays];
    scene->intersect_batch(rays, kRays, hits, found, RayCoherence::Coherent);
    for (int i = 0; i < kRays; ++i) {
        Hit single;
        ASSERT_EQ(found[i], scene->intersect(rays[i], single)) << "ray " << i;
        if (found[i]) {
            EXPECT_EQ(hits[i].t, single.t) << "ray " << i;
            EXPECT_EQ(hits[i].object_id, single.object_id) << "ray " << i;
        }
    }
}

TEST(ShapeList, RaysAlongABoxsFacesFindWhatTheBvhFinds) {
    // Direction components of zero with the origin on or near a slab's
    // plane: the box test must leave the decision to the shape.
    const std::string box = "box { <-1, -1, -1>, <1, 1, 1> }\n";
    const auto few = compile(box);
    const auto many = compile(box + far_spheres(embree::ShapeList::kMostShapes));
    ASSERT_TRUE(traces_list(*few));
    const float edges[] = {-1.0f, std::nextafter(-1.0f, 0.0f), std::nextafter(-1.0f, -2.0f), 0.0f, 1.0f};
    int found = 0;
    for (float x : edges)
        for (float y : edges) {
            const Ray ray = testing::make_ray(Vec3(x, y, -5.0f), Vec3(0, 0, 1));
            Hit a, b;
            const bool hit = few->intersect(ray, a);
            ASSERT_EQ(hit, many->intersect(ray, b)) << x << ", " << y;
            if (hit) {
                EXPECT_EQ(a.t, b.t) << x << ", " << y;
            }
            found += hit;
        }
    EXPECT_GT(found, 8);  // the inside ones at least
}

}  // namespace
}  // namespace lancer
