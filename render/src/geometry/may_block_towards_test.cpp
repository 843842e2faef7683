// RenderScene::may_block_towards: whether anything that casts shadows may
// stand between a point and a parallelogram (an area light's grid), so that
// POV area shadows can skip their rays. A "no" must be safe: every shadow
// ray from the point to the parallelogram is then unoccluded.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "pov_text_scene.h"

namespace lancer {
namespace {

std::unique_ptr<RenderScene> compile(const std::string& objects) {
    return testing::compile_pov_text("camera { location -5*z look_at 0 }\n" + objects, "<block>");
}

// A 2 x 2 light square 6 units up, centred over x = 2.
const Vec3 kCorner(1.0f, 6.0f, -1.0f), kEdge1(2.0f, 0.0f, 0.0f), kEdge2(0.0f, 0.0f, 2.0f);

TEST(MayBlockTowards, ASphereOnTheWayMayBlockOneAsideCannot) {
    const auto scene = compile("sphere { <2, 3, 0>, 0.5 }\nplane { y, 0 }\n");
    EXPECT_TRUE(scene->may_block_towards(Vec3(2.0f, 0.0f, 0.0f), kCorner, kEdge1, kEdge2));
    EXPECT_FALSE(scene->may_block_towards(Vec3(-4.0f, 0.0f, 0.0f), kCorner, kEdge1, kEdge2));
    // The pyramid's bounding box meets the sphere's, its side faces do not.
    EXPECT_FALSE(scene->may_block_towards(Vec3(2.0f, 0.0f, 3.0f), kCorner, kEdge1, kEdge2));
}

TEST(MayBlockTowards, APlaneBlocksUnlessEverythingIsOnOneSide) {
    const auto scene = compile("plane { y, 0 }\n");
    EXPECT_FALSE(scene->may_block_towards(Vec3(0.0f, 0.0f, 0.0f), kCorner, kEdge1, kEdge2));  // on it
    EXPECT_FALSE(scene->may_block_towards(Vec3(0.0f, 1.0f, 0.0f), kCorner, kEdge1, kEdge2));
    EXPECT_TRUE(scene->may_block_towards(Vec3(0.0f, -1.0f, 0.0f), kCorner, kEdge1, kEdge2));
    // A light square reaching below the plane.
    EXPECT_TRUE(scene->may_block_towards(Vec3(0.0f, 1.0f, 0.0f), Vec3(1.0f, -0.5f, 0.0f), kEdge1, Vec3(0, 1, 0)));
    // A turned plane: the same sides in its own space.
    const auto turned = compile("plane { y, 0 rotate z * 90 translate x * 3 }\n");  // x = 3
    EXPECT_FALSE(turned->may_block_towards(Vec3(0.0f, 1.0f, 0.0f), Vec3(1.0f, 6.0f, -1.0f), Vec3(1, 0, 0), kEdge2));
    EXPECT_TRUE(turned->may_block_towards(Vec3(0.0f, 1.0f, 0.0f), kCorner, kEdge1, kEdge2));  // reaches x = 3
}

TEST(MayBlockTowards, WhatCastsNoShadowIsLeftOut) {
    const auto scene = compile("sphere { <2, 3, 0>, 0.5 no_shadow }\n");
    EXPECT_FALSE(scene->may_block_towards(Vec3(2.0f, 0.0f, 0.0f), kCorner, kEdge1, kEdge2));
}

TEST(MayBlockTowards, ScenesItCannotTellAboutAnswerMaybe) {
    // An unbounded shape other than a plane.
    EXPECT_TRUE(compile("quadric { <1, 0, 1>, <0, 0, 0>, <0, 0, 0>, -1 translate x * 40 }\n")
                    ->may_block_towards(Vec3(-4.0f, 0.0f, 0.0f), kCorner, kEdge1, kEdge2));
    // More shapes than the list holds, far away: the BVH scene does not tell.
    std::string many;
    for (int i = 0; i < 12; ++i) many += "sphere { <" + std::to_string(100 + 3 * i) + ", 0, 0>, 1 }\n";
    EXPECT_TRUE(compile(many)->may_block_towards(Vec3(-4.0f, 0.0f, 0.0f), kCorner, kEdge1, kEdge2));
}

// Shapes of several kinds around random points: every "cannot block"
// answer is checked with shadow rays to the corners, the edges and inside.
TEST(MayBlockTowards, ANoIsAlwaysSafe) {
    const auto scene = compile(
        "plane { y, -2 }\n"
        "sphere { <-1, 0.5, 0>, 0.8 }\n"
        "box { <0.2, -0.5, -0.5>, <1.4, 0.9, 0.7> rotate <20, 35, 0> }\n"
        "torus { 0.9, 0.25 rotate x * 70 translate <0, 1.4, 1> }\n"
        "difference { sphere { <0, -0.6, -1>, 0.7 } box { <-1, -0.6, -2>, <1, 0.5, 0> } }\n");
    std::mt19937 random(11);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int clear = 0, blocked_rays = 0;
    for (int trial = 0; trial < 3000; ++trial) {
        const Vec3 origin(8.0f * unit(random) - 4.0f, 5.0f * unit(random) - 2.0f, 8.0f * unit(random) - 4.0f);
        const Vec3 corner(8.0f * unit(random) - 4.0f, 3.0f + 3.0f * unit(random), 8.0f * unit(random) - 4.0f);
        const Vec3 edge1(2.0f * unit(random), 0.5f * unit(random), 0.0f);
        const Vec3 edge2(0.0f, 0.5f * unit(random), 2.0f * unit(random));
        if (scene->may_block_towards(origin, corner, edge1, edge2)) continue;
        ++clear;
        for (int i = 0; i <= 8; ++i)
            for (int j = 0; j <= 8; ++j) {
                const Vec3 target = corner + (float(i) / 8.0f) * edge1 + (float(j) / 8.0f) * edge2;
                Ray ray;
                ray.origin = origin;
                ray.direction = glm::normalize(target - origin);
                ray.t_max = glm::length(target - origin);
                blocked_rays += scene->occluded(ray);
            }
    }
    EXPECT_EQ(blocked_rays, 0);
    EXPECT_GT(clear, 300);  // the test means something
}

}  // namespace
}  // namespace lancer
