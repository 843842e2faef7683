// The objects a camera ray starts in (RenderScene::camera_interiors,
// geometry/containing_objects.h): POV-Ray's containing interiors, found by
// each object's inside test, largest first.
#include <gtest/gtest.h>

#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"
#include "lancer/render_scene.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;

// A camera at the origin looking along +z, with fog (so the scene asks
// which objects contain it), and `objects`.
std::unique_ptr<RenderScene> camera_among(const std::string& objects) {
    const std::string text = "#version 3.7;\ncamera { location 0 look_at z }\nfog { distance 10 rgb 1 }\n" + objects;
    ParseResult parsed = parse_scene_string(text, "<containing>");
    if (!parsed.ok()) throw std::runtime_error(format_diagnostic(parsed.diagnostics.front()));
    return compile_scene(*parsed.scene);
}

bool hollow(const InteriorStack::Entry& entry) {
    return entry.material->parameters().hollow;
}

TEST(CameraInteriors, EveryObjectHoldingTheCameraLargestFirst) {
    const auto scene = camera_among(
        "sphere { 0, 2 hollow }\n"
        "box { -50, 50 }\n"
        "plane { y, 1 }\n"                   // the camera is below it: inside
        "sphere { <10, 0, 0>, 1 hollow }\n"  // elsewhere
        "plane { y, -1 }\n");                // above it: outside
    const InteriorStack& inside = scene->camera_interiors();
    ASSERT_EQ(inside.size, 3);
    EXPECT_FALSE(hollow(inside.entries[0]));  // the plane (unbounded)
    EXPECT_FALSE(hollow(inside.entries[1]));  // the box
    EXPECT_TRUE(hollow(inside.entries[2]));   // the small sphere, innermost
}

TEST(CameraInteriors, TransformedAndCsgObjects) {
    // A sphere moved and scaled around the camera; a difference whose hole
    // is elsewhere holds it; one whose hole is at the camera does not.
    const auto scene = camera_among(
        "sphere { 0, 1 scale <5, 1, 1> translate <3, 0, 0> hollow }\n"
        "difference { sphere { 0, 8 } sphere { <5, 0, 0>, 1 } hollow }\n"
        "difference { sphere { 0, 9 } sphere { 0, 1 } }\n");
    const InteriorStack& inside = scene->camera_interiors();
    ASSERT_EQ(inside.size, 2);
    // A ray leaving each object leaves through the object (for the
    // difference, the leaf) the camera was entered by, so a transmitted ray
    // takes it off the stack: the ellipsoid (innermost) at 0.8, then the
    // difference's outer sphere at 8.
    Hit hit;
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, 0}, {0, 0, 1}), hit));
    EXPECT_NEAR(hit.t, 0.8f, 1e-4f);
    EXPECT_EQ(hit.object_id, inside.entries[1].object_id);
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, 1}, {0, 0, 1}), hit));
    EXPECT_NEAR(hit.t, 7.0f, 1e-4f);
    EXPECT_EQ(hit.object_id, inside.entries[0].object_id);
    EXPECT_TRUE(hollow(inside.entries[0]));
    EXPECT_TRUE(hollow(inside.entries[1]));
}

TEST(CameraInteriors, AMeshWithInsideVectorHoldsTheCameraOneWithoutDoesNot) {
    // Two closed tetrahedra around the camera; only inside_vector gives a
    // mesh an inside (POV's Mesh::Inside).
    const std::string tetrahedron =
        "triangle { <-3, -3, -3>, <3, -3, -3>, <0, 3, -3> } triangle { <-3, -3, -3>, <3, -3, -3>, <0, 0, 4> }\n"
        "triangle { <3, -3, -3>, <0, 3, -3>, <0, 0, 4> } triangle { <0, 3, -3>, <-3, -3, -3>, <0, 0, 4> }\n";
    const auto scene = camera_among("mesh { " + tetrahedron + " inside_vector <0.3, 1, 0.1> hollow }\nmesh { " +
                                    tetrahedron + " scale 2 }\n");
    const InteriorStack& inside = scene->camera_interiors();
    ASSERT_EQ(inside.size, 1);
    EXPECT_TRUE(hollow(inside.entries[0]));
}

// POV-Ray's list of interiors goes by object, not by face: a transmitted
// ray adds the object it crosses, or takes it off if it is on the list.
TEST(InteriorStackCrossing, PartsOfOneCsgAreOneInsideAndAPatchIsEnteredFromEitherSide) {
    const auto scene = camera_among(
        "intersection { sphere { <0, 0, 5.5>, 1 } sphere { <0, 0, 4.5>, 1 } pigment { rgbf 1 } }\n"
        "polygon { 4, <-1, -1>, <1, -1>, <1, 1>, <-1, 1> translate 9 * z pigment { rgbf 1 } }\n");
    InteriorStack inside = scene->camera_interiors();
    ASSERT_EQ(inside.size, 0);
    // Along +z the ray enters the lens through one sphere and leaves
    // through the other: a different part, the same object.
    Hit enter, leave, patch;
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, 0}, {0, 0, 1}), enter));
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, enter.t + 0.01f}, {0, 0, 1}), leave));
    EXPECT_NE(enter.object_id, leave.object_id);
    EXPECT_EQ(enter.interior_id, leave.interior_id);
    inside = inside.crossed(enter);
    EXPECT_EQ(inside.size, 1);
    inside = inside.crossed(leave);
    EXPECT_EQ(inside.size, 0);
    // The polygon has no inside, yet a ray through it is "in" it from
    // then on, whichever face it met (POV's ComputeRefraction).
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, 8}, {0, 0, 1}), patch));
    EXPECT_EQ(inside.crossed(patch).size, 1);
    ASSERT_TRUE(scene->intersect(make_ray({0, 0, 10}, {0, 0, -1}), patch));
    EXPECT_EQ(inside.crossed(patch).size, 1);
}

// Follows the ray from the origin along +z through each surface in turn,
// expecting one at each crossing's z, and hands each hit to `check`.
template <class Crossing, std::size_t N, class Check>
void along_z(const RenderScene& scene, const Crossing (&crossings)[N], Check check) {
    float z = 0.0f;
    for (const Crossing& crossing : crossings) {
        Hit hit;
        ASSERT_TRUE(scene.intersect(make_ray({0, 0, z}, {0, 0, 1}), hit));
        z += hit.t;
        SCOPED_TRACE("crossing at z = " + std::to_string(crossing.z));
        EXPECT_NEAR(z, crossing.z, 1e-3f);
        check(crossing, hit);
        z += 1e-3f;
    }
}

// POV-Ray's parts share their group's Interior unless one is written for
// the part: along +z, two overlapping balls of a union are one object, so
// entering the second "leaves" it (and leaving the first enters it again),
// with an interior written on the union or with the one POV makes for it.
// In the merge, whose inner surfaces are gone, the ray enters the first
// ball and leaves through the second, which has its own interior: on
// POV's list it is then in both.
TEST(InteriorStackCrossing, PartsShareTheirGroupsInteriorUnlessTheyHaveTheirOwn) {
    const auto scene = camera_among(
        "union { sphere { <0, 0, 4>, 1.5 } sphere { <0, 0, 6>, 1.5 } pigment { rgbf 1 } interior { ior 1.5 } }\n"
        "union { sphere { <0, 0, 14>, 1.5 pigment { rgbf 1 } } sphere { <0, 0, 16>, 1.5 pigment { rgbf 1 } } }\n"
        "merge { sphere { <0, 0, 24>, 1.5 } sphere { <0, 0, 26>, 1.5 interior { ior 1.2 } }\n"
        "        pigment { rgbf 1 } interior { ior 1.5 } }\n");
    struct Crossing {
        float z;
        int size_after;
    };
    const Crossing expected[] = {
        {2.5f, 1},  {4.5f, 0},  {5.5f, 1},  {7.5f, 0},   // union with an interior
        {12.5f, 1}, {14.5f, 0}, {15.5f, 1}, {17.5f, 0},  // union without
        {22.5f, 1}, {27.5f, 2},                          // merge
    };
    InteriorStack inside = scene->camera_interiors();
    along_z(*scene, expected, [&inside](const Crossing& crossing, const Hit& hit) {
        inside = inside.crossed(hit);
        EXPECT_EQ(inside.size, crossing.size_after);
    });
}

// The ratio of indices a refracted ray bends by, as POV-Ray's
// ComputeRefraction reads it from the list: water (1.33) in glass (1.5),
// then two overlapping balls (1.3, entered first, and 1.7), along +z.
TEST(InteriorStackCrossing, RefractionReadsTheIndicesOfTheObjectsTheRayIsIn) {
    const auto scene = camera_among(
        "sphere { <0, 0, 5>, 2 pigment { rgbf 1 } interior { ior 1.5 } }\n"
        "sphere { <0, 0, 5>, 1 pigment { rgbf 1 } interior { ior 1.33 } }\n"
        "sphere { <0, 0, 12>, 1.5 pigment { rgbf 1 } interior { ior 1.3 } }\n"
        "sphere { <0, 0, 13.5>, 1.5 pigment { rgbf 1 } interior { ior 1.7 } }\n");
    InteriorStack inside = scene->camera_interiors();
    ASSERT_EQ(inside.size, 0);
    struct Crossing {
        float z, eta, fresnel_ior;
        int size_after;
    };
    const Crossing expected[] = {
        {3.0f, 1.0f / 1.5f, 1.5f, 1},           // into the glass from the air
        {4.0f, 1.5f / 1.33f, 1.33f / 1.5f, 2},  // into the water from the glass
        // out of the water, back into the glass; POV's Fresnel reads this
        // as the innermost's (the water's) index over the water's
        {6.0f, 1.33f / 1.5f, 1.0f, 1},
        {7.0f, 1.5f, 1.0f / 1.5f, 0},          // out into the air
        {10.5f, 1.0f / 1.3f, 1.3f, 1},         // into the first ball
        {12.0f, 1.3f / 1.7f, 1.7f / 1.3f, 2},  // into the second, which now wins
        {13.5f, 1.0f, 1.7f / 1.3f, 1},         // out of the first while in the second: no bend
        {15.0f, 1.7f, 1.0f / 1.7f, 0},         // out of the second
    };
    along_z(*scene, expected, [&inside](const Crossing& crossing, const Hit& hit) {
        const float ior = hit.material->parameters().ior;
        EXPECT_NEAR(inside.refraction_eta(hit, ior), crossing.eta, 1e-5f);
        EXPECT_NEAR(inside.fresnel_ior(hit, ior), crossing.fresnel_ior, 1e-5f);
        inside = inside.crossed(hit);
        EXPECT_EQ(inside.size, crossing.size_after);
    });
}

TEST(CameraInteriors, ACameraInGlassStartsInItWithoutMedia) {
    // Refraction reads the list too, so a scene with an ior asks which
    // objects hold the camera even without fog or media.
    ParseResult parsed = parse_scene_string(
        "#version 3.7;\ncamera { location 0 look_at z }\nsphere { 0, 2 pigment { rgbf 1 } interior { ior 1.5 } }\n",
        "<none>");
    ASSERT_TRUE(parsed.ok());
    EXPECT_EQ(compile_scene(*parsed.scene)->camera_interiors().size, 1);
}

TEST(CameraInteriors, NoneWithoutMediaFogOrRainbow) {
    ParseResult parsed =
        parse_scene_string("#version 3.7;\ncamera { location 0 look_at z }\nsphere { 0, 2 }\n", "<none>");
    ASSERT_TRUE(parsed.ok());
    EXPECT_EQ(compile_scene(*parsed.scene)->camera_interiors().size, 0);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// An inverted box is traced as its one box (csg.cpp), but its solid is all
// space outside it: a camera outside holds it, one inside (a room) does
// not, and rays from inside meet its walls with the normal facing the room.
TEST(CameraInteriors, AnInvertedBoxHoldsWhatLiesOutsideIt) {
    const auto outside = camera_among("box { <5, -1, -1>, <7, 1, 1> inverse }\n");
    EXPECT_EQ(outside->camera_interiors().size, 1);
    Hit hit;
    ASSERT_TRUE(outside->intersect(make_ray({0, 0, 0}, {1, 0, 0}), hit));
    EXPECT_NEAR(hit.t, 5.0f, 1e-5f);
    EXPECT_EQ(hit.geometric_normal, Vec3(1, 0, 0));  // into the box: out of the inverted solid
    EXPECT_FALSE(outside->intersect(make_ray({0, 3, 0}, {1, 0, 0}), hit));

    const auto room = camera_among("box { <-4, -3, -2>, <4, 3, 6> inverse }\n");
    EXPECT_EQ(room->camera_interiors().size, 0);
    ASSERT_TRUE(room->intersect(make_ray({0, 0, 0}, {0, 0, 1}), hit));
    EXPECT_NEAR(hit.t, 6.0f, 1e-5f);
    EXPECT_EQ(hit.geometric_normal, Vec3(0, 0, -1));
    EXPECT_TRUE(room->occluded(make_ray({0, 0, 0}, {0, -1, 0})));
}

}  // namespace
}  // namespace lancer
