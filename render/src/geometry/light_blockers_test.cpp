// RenderScene::shadow_blockers: what lies on a shadow ray, told apart into
// nothing, surfaces that may let light through, and an opaque caster (which
// makes the shadow black without a walk through the surfaces). An Opaque
// answer must be safe: the walk would find no light either.
#include <gtest/gtest.h>

#include <random>
#include <string>

#include "geometry/embree_scene.h"
#include "lancer/shading/shadow_rays.h"
#include "pov_text_scene.h"

namespace lancer {
namespace {

// Far opaque spheres that put a scene past the shape list, into the BVH.
std::string far_spheres() {
    std::string spheres;
    for (int i = 0; i < 10; ++i) spheres += "sphere { <" + std::to_string(100 + 3 * i) + ", 0, 0>, 1 }\n";
    return spheres;
}

// The shadow ray from the origin straight up to y = 10, on `objects` alone
// and among far spheres (traced through the BVH); both must agree, and
// agree with occluded().
ShadowBlockers blockers_on_the_way(const std::string& objects) {
    Ray ray;
    ray.origin = Vec3(0.0f);
    ray.direction = Vec3(0.0f, 1.0f, 0.0f);
    ray.t_max = 10.0f;
    const std::string camera = "camera { location -5*z look_at 0 }\n";
    const auto few = testing::compile_pov_text(camera + objects, "<few>");
    const auto many = testing::compile_pov_text(camera + objects + far_spheres(), "<many>");
    const ShadowBlockers answer = few->shadow_blockers(ray);
    EXPECT_EQ(many->shadow_blockers(ray), answer) << objects;
    EXPECT_EQ(few->occluded(ray), answer != ShadowBlockers::None) << objects;
    EXPECT_EQ(many->occluded(ray), answer != ShadowBlockers::None) << objects;
    return answer;
}

// A shadow ray between two random points of the box `x` by `y` by `z`,
// ending at `to` (t_max 1).
struct Segment {
    Vec3 from, to;
    Ray ray;
};
Segment random_segment(std::mt19937& random, const Vec2& x, const Vec2& y, const Vec2& z) {
    std::uniform_real_distribution<float> along_x(x[0], x[1]), along_y(y[0], y[1]), along_z(z[0], z[1]);
    // One draw a statement: the order of a constructor's arguments is the compiler's.
    Segment s;
    s.from.x = along_x(random);
    s.from.y = along_y(random);
    s.from.z = along_z(random);
    s.to.x = along_x(random);
    s.to.y = along_y(random);
    s.to.z = along_z(random);
    s.ray.origin = s.from;
    s.ray.direction = s.to - s.from;
    s.ray.t_max = 1.0f;
    return s;
}

std::string where(const Segment& s) {
    return "from " + std::to_string(s.from.x) + " " + std::to_string(s.from.y) + " " + std::to_string(s.from.z) +
           " to " + std::to_string(s.to.x) + " " + std::to_string(s.to.y) + " " + std::to_string(s.to.z);
}

constexpr ShadowBlockers kNone = ShadowBlockers::None;
constexpr ShadowBlockers kSeeThrough = ShadowBlockers::SeeThrough;
constexpr ShadowBlockers kOpaque = ShadowBlockers::Opaque;

TEST(ShadowBlockers, AnOpaqueObjectBlocksAndAGlassOneLetsThrough) {
    EXPECT_EQ(blockers_on_the_way(""), kNone);
    EXPECT_EQ(blockers_on_the_way("sphere { <3, 5, 0>, 1 pigment { rgb 1 } }\n"), kNone);  // aside
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { rgb 1 } }\n"), kOpaque);
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { rgbf <1, 1, 1, 0.5> } }\n"), kSeeThrough);
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { rgbt <1, 1, 1, 0.5> } }\n"), kSeeThrough);
    // A plane outside the BVH, either way.
    EXPECT_EQ(blockers_on_the_way("plane { y, 5 pigment { rgb 1 } }\n"), kOpaque);
    EXPECT_EQ(blockers_on_the_way("plane { y, 5 pigment { rgbt <1, 1, 1, 0.2> } }\n"), kSeeThrough);
}

TEST(ShadowBlockers, AnOpaqueObjectBehindGlassStillBlocks) {
    const std::string glass = "sphere { <0, 3, 0>, 1 pigment { rgbf <1, 1, 1, 0.9> } }\n";
    const std::string opaque = "box { <-1, 6, -1>, <1, 7, 1> pigment { rgb 1 } }\n";
    EXPECT_EQ(blockers_on_the_way(glass + opaque), kOpaque);
    EXPECT_EQ(blockers_on_the_way(opaque + glass), kOpaque);
    EXPECT_EQ(blockers_on_the_way(glass + "plane { y, 8 pigment { rgb 1 } }\n"), kOpaque);
    // Past the end of the ray it does not count.
    EXPECT_EQ(blockers_on_the_way(glass + "plane { y, 12 pigment { rgb 1 } }\n"), kSeeThrough);
}

TEST(ShadowBlockers, WhatCastsNoShadowIsNotOnTheWay) {
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { rgb 1 } no_shadow }\n"), kNone);
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { rgb 1 } no_shadow }\n"
                                  "sphere { <0, 8, 0>, 1 pigment { rgbt 0.5 } }\n"),
              kSeeThrough);
}

// The light through layers is their product: one opaque layer stops it.
TEST(ShadowBlockers, ALayeredTextureBlocksWhenAnyLayerIsOpaque) {
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 texture { pigment { rgb 1 } }"
                                  " texture { pigment { rgbt <1, 0, 0, 0.5> } } }\n"),
              kOpaque);
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 texture { pigment { rgbf <1, 1, 1, 0.5> } }"
                                  " texture { pigment { rgbt <1, 0, 0, 0.5> } } }\n"),
              kSeeThrough);
}

TEST(ShadowBlockers, PatternsBlockOnlyWhenEveryEntryDoes) {
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { checker rgb 1, rgb 0 } }\n"), kOpaque);
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { checker rgb 1, rgbt 1 } }\n"), kSeeThrough);
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { gradient y color_map {"
                                  " [0 rgb 1] [1 rgbf <1, 1, 1, 0.3>] } } }\n"),
              kSeeThrough);
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 texture { checker"
                                  " texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } }\n"),
              kOpaque);
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 texture { gradient y texture_map {"
                                  " [0 pigment { rgb 1 }] [1 pigment { rgbt 0.5 }] } } }\n"),
              kSeeThrough);
    // An entry that is itself a map.
    EXPECT_EQ(blockers_on_the_way("sphere { <0, 5, 0>, 1 texture { gradient y texture_map {"
                                  " [0 pigment { rgb 1 }] [1 checker texture { pigment { rgb 0 } }"
                                  " texture { pigment { rgbt 0.5 } }] } } }\n"),
              kSeeThrough);
}

// A CSG tree is one object to the BVH: it blocks all light only when every
// part does, whichever part the ray meets (a plain union's parts are
// objects of their own).
TEST(ShadowBlockers, ACsgTreeBlocksOnlyWhenEveryPartDoes) {
    EXPECT_EQ(blockers_on_the_way("merge { sphere { <0, 5, 0>, 1 pigment { rgb 1 } }"
                                  " box { <-1, 7, -1>, <1, 8, 1> pigment { rgb 0 } } }\n"),
              kOpaque);
    EXPECT_EQ(blockers_on_the_way("merge { sphere { <0, 5, 0>, 1 pigment { rgb 1 } }"
                                  " box { <4, 7, -1>, <5, 8, 1> pigment { rgbt 0.5 } } }\n"),
              kSeeThrough);
    EXPECT_EQ(blockers_on_the_way("union { sphere { <0, 5, 0>, 1 pigment { rgb 1 } }"
                                  " box { <4, 7, -1>, <5, 8, 1> pigment { rgbt 0.5 } } }\n"),
              kOpaque);
    EXPECT_EQ(blockers_on_the_way("difference { sphere { <0, 5, 0>, 1 pigment { rgbf 0.5 } }"
                                  " sphere { <0, 5, 0>, 0.5 pigment { rgb 1 } } }\n"),
              kSeeThrough);
}

TEST(ShadowBlockers, AnInteriorTextureThatLetsLightThroughIsSeeThrough) {
    EXPECT_EQ(
        blockers_on_the_way("sphere { <0, 5, 0>, 1 pigment { rgb 1 } interior_texture { pigment { rgbt 0.5 } } }\n"),
        kSeeThrough);
}

// Meshes are filtered in Embree, placed in the world or instanced (a mesh
// used twice is traced in a scene of its own).
TEST(ShadowBlockers, MeshesPlacedOnceOrInstanced) {
    const std::string triangle = "triangle { <-1, 5, -1>, <1, 5, -1>, <0, 5, 1> }";
    EXPECT_EQ(blockers_on_the_way("mesh { " + triangle + " pigment { rgb 1 } }\n"), kOpaque);
    EXPECT_EQ(blockers_on_the_way("mesh { " + triangle + " pigment { rgbt 0.5 } }\n"), kSeeThrough);
    for (const char* texture : {"pigment { rgbt 0.5 }", "pigment { rgb 1 }", "pigment { rgb 1 } no_shadow"}) {
        const std::string twice = "#declare M = mesh { " + triangle + " " + texture +
                                  " }\n"
                                  "object { M } object { M translate x * 50 }\n";
        const ShadowBlockers expected = std::string(texture).find("no_shadow") != std::string::npos ? kNone
                                        : std::string(texture).find("rgbt") != std::string::npos    ? kSeeThrough
                                                                                                    : kOpaque;
        EXPECT_EQ(blockers_on_the_way(twice), expected) << texture;
    }
}

// The claim itself, on random segments through a scene of every kind of
// blocker: where the scene answers Opaque the walk through the surfaces
// finds no light either, and where it answers None the walk finds all of
// it (surfaces_transmittance skips the walk on both answers).
TEST(ShadowBlockers, TheAnswersAgreeWithTheWalk) {
    const std::string objects =
        "sphere { <-2, 1, 0>, 0.8 pigment { rgb 1 } }\n"
        "sphere { <0, 1, 0>, 0.8 pigment { rgbf <1, 0.8, 0.8, 0.9> } interior { ior 1.5 } }\n"
        "box { <1.2, 0.2, -0.6>, <2.4, 1.6, 0.6> texture { pigment { rgbf 0.5 } }"
        " texture { pigment { checker rgb 1, rgbt 1 scale 0.3 } } }\n"
        "difference { box { <-2.6, 2, -0.6>, <-1.4, 3, 0.6> } sphere { <-2, 2.5, -0.6>, 0.4 }"
        " pigment { rgbt <1, 1, 1, 0.6> } }\n"
        "merge { sphere { <0, 2.6, 0>, 0.5 pigment { rgb 1 } } sphere { <0.5, 2.6, 0>, 0.5 pigment { rgb 0.5 } } }\n"
        "mesh { triangle { <1, 2, -1>, <3, 2, -1>, <2, 3, 1> } pigment { rgbt 0.7 } }\n"
        "mesh { triangle { <1, 2.2, 1>, <3, 2.2, 1>, <2, 3.2, -1> } pigment { rgb <0.2, 0.5, 0.9> } }\n"
        "cylinder { <-3, 0, 2>, <3, 0, 2>, 0.3 texture { gradient x texture_map { [0 pigment { rgb 1 }]"
        " [1 pigment { rgbt 0.5 }] } } }\n"
        "torus { 0.6, 0.2 rotate x * 90 translate <-1, 3.5, 0> pigment { granite color_map { [0 rgb 1] [1 rgb 0] } } "
        "}\n"
        "plane { y, -0.5 pigment { checker rgb 1, rgb 0.5 } }\n";
    const std::string camera = "camera { location -5*z look_at 0 }\n";
    std::mt19937 random(7);
    for (const std::string& text : {objects, objects + far_spheres()}) {
        const auto scene = testing::compile_pov_text(camera + text, "<mixed>");
        int opaque = 0, none = 0;
        for (int i = 0; i < 4000; ++i) {
            const Segment segment = random_segment(random, Vec2(-3.5f, 3.5f), Vec2(-1.0f, 4.0f), Vec2(-2.5f, 2.5f));
            const ShadowBlockers answer = scene->shadow_blockers(segment.ray);
            if (answer == ShadowBlockers::SeeThrough) continue;
            const Color walked = walked_transmittance(*scene, segment.ray, segment.to, nullptr);
            if (answer == ShadowBlockers::Opaque) {
                ++opaque;
                EXPECT_EQ(max_component(glm::abs(walked)), 0.0f) << where(segment);
            } else {
                ++none;
                EXPECT_EQ(walked, Color(1.0f));
            }
        }
        // Both answers were put to the test.
        EXPECT_GT(opaque, 500);
        EXPECT_GT(none, 500);
    }
}

// What casts no shadow is not on a shadow ray's way: a see-through plane in
// front of the glass (a hit completed on it let everything through), and
// a faded ball inside a faded one (the walk faded inside it, and began the
// outer one's fade again at its surface). And a checkered floor.
const std::string kNotOnTheWay =
    "plane { y, 1.7 pigment { rgbt 1 } no_shadow }\n"
    "sphere { <-2, 1, 0>, 0.3 pigment { rgbt 1 } interior { fade_distance 0.2 fade_power 2 } no_shadow }\n"
    "plane { y, -0.5 pigment { checker rgb 1, rgb 0.5 } }\n";

// shadow_crossings gathers the surfaces a SeeThrough shadow ray crosses in
// one query: what they let through must be what the walk through them, one
// intersect() each, finds. Random segments through glass, layers, a
// texture_map, CSG (a sphere's bubble cut into a box, a merge), meshes,
// patterns and a faded interior, among far spheres (the BVH); and where two
// surfaces are too close to tell apart by one query, or on an isosurface
// (whose search finds its later crossings only from a ray started past
// the first), nothing gathered.
TEST(ShadowBlockers, GatheredSurfacesLetThroughWhatTheWalkFinds) {
    const std::string objects =
        "sphere { <0, 1, 0>, 0.8 pigment { rgbf <1, 0.8, 0.8, 0.9> } interior { ior 1.5 } }\n"
        "sphere { <-2, 1, 0>, 0.7 pigment { rgbt <0.5, 0.9, 1, 0.7> } interior { fade_distance 0.5 fade_power 2 } }\n"
        "box { <1.2, 0.2, -0.6>, <2.4, 1.6, 0.6> texture { pigment { rgbf 0.5 } }"
        " texture { pigment { checker rgb 1, rgbt 1 scale 0.3 } } }\n"
        "difference { box { <-2.6, 2, -0.6>, <-1.4, 3, 0.6> } sphere { <-2, 2.5, 0>, 0.4 }"
        " pigment { rgbt <1, 1, 1, 0.6> } }\n"
        "merge { sphere { <0, 2.6, 0>, 0.5 } sphere { <0.5, 2.6, 0>, 0.5 } pigment { rgbf <0.6, 1, 0.6, 0.8> } }\n"
        "mesh { triangle { <1, 2, -1>, <3, 2, -1>, <2, 3, 1> } pigment { rgbt 0.7 } }\n"
        "mesh { triangle { <1, 2.2, 1>, <3, 2.2, 1>, <2, 3.2, -1> } pigment { rgb <0.2, 0.5, 0.9> } }\n"
        "cylinder { <-3, 0, 2>, <3, 0, 2>, 0.3 texture { gradient x texture_map { [0 pigment { rgb 1 }]"
        " [1 pigment { rgbt 0.5 }] } } }\n"
        "torus { 0.6, 0.2 rotate x * 90 translate <-1, 3.5, 0> pigment { granite color_map { [0 rgbt 1] [1 rgb 0] } } "
        "}\n"
        "isosurface { function { x*x + y*y + z*z - 0.16 } contained_by { box { -0.5, 0.5 } }"
        " pigment { rgbf <1, 1, 0.6, 0.8> } translate <2.5, 3.5, 1.5> }\n" +
        kNotOnTheWay;
    // Five analytic shapes and a plane: traced from the shape list.
    const std::string few =
        "sphere { <0, 1, 0>, 0.8 pigment { rgbf <1, 0.8, 0.8, 0.9> } interior { ior 1.5 } }\n"
        "sphere { <-2, 1, 0>, 0.7 pigment { rgbt <0.5, 0.9, 1, 0.7> } interior { fade_distance 0.5 fade_power 2 } }\n"
        "difference { box { <-2.6, 2, -0.6>, <-1.4, 3, 0.6> } sphere { <-2, 2.5, 0>, 0.4 }"
        " pigment { rgbt <1, 1, 1, 0.6> } }\n"
        "merge { sphere { <0, 2.6, 0>, 0.5 } sphere { <0.5, 2.6, 0>, 0.5 } pigment { rgbf <0.6, 1, 0.6, 0.8> } }\n"
        "isosurface { function { x*x + y*y + z*z - 0.16 } contained_by { box { -0.5, 0.5 } }"
        " pigment { rgbf <1, 1, 0.6, 0.8> } translate <1.5, 1, 0> }\n" +
        kNotOnTheWay;
    const std::string camera = "camera { location -5*z look_at 0 }\n";
    for (const std::string& text : {objects + far_spheres(), few}) {
        const auto scene = testing::compile_pov_text(camera + text, "<mixed>");
        const auto* traced = dynamic_cast<const embree::EmbreeScene*>(scene.get());
        ASSERT_TRUE(traced);
        EXPECT_EQ(traced->traces_shape_list(), text == few);
        std::mt19937 random(11);
        int gathered = 0, several = 0;
        for (int i = 0; i < 6000; ++i) {
            const Segment segment = random_segment(random, Vec2(-3.5f, 3.5f), Vec2(-0.4f, 4.0f), Vec2(-2.5f, 2.5f));
            const Ray& ray = segment.ray;
            SeeThroughHits crossed;
            const ShadowBlockers answer = scene->shadow_crossings(ray, crossed);
            EXPECT_EQ(answer, scene->shadow_blockers(ray));
            if (answer != ShadowBlockers::SeeThrough) {
                EXPECT_EQ(crossed.count, -1);
                continue;
            }
            if (crossed.count < 0) continue;
            ++gathered;
            several += crossed.count > 1;
            for (int k = 1; k < crossed.count; ++k) EXPECT_LT(crossed[k - 1].t, crossed[k].t);
            const Color walked = walked_transmittance(*scene, ray, segment.to, nullptr);
            const Color gathered_light = crossed_transmittance(ray, crossed, nullptr);
            // The walk meets each surface from a ray spawned at the one before,
            // so its hit points (where patterns and fades are read) differ by
            // rounding: the two answers differed by at most 2.4e-5 here.
            for (int c = 0; c < 3; ++c) EXPECT_NEAR(gathered_light[c], walked[c], 1e-4f) << where(segment);
        }
        // The gathered path was put to the test, with several surfaces at once.
        EXPECT_GT(gathered, 500);
        EXPECT_GT(several, 200);
    }
}

}  // namespace
}  // namespace lancer
