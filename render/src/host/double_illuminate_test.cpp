// Which surfaces carry POV's double_illuminate (Hit::double_illuminate):
// an object's own setting, and a group's for everything inside it, the
// outermost setting winning as in POV-Ray's Set_CSG_Tree_Flag. How such a
// surface is lit is checked against POV-Ray's pixels
// (tests/reference/pov/double_illuminate.pov).
#include <gtest/gtest.h>

#include <string>

#include "pov_text_scene.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

// Whether the surface that a ray along +z through (x, 0) meets is double
// illuminated.
bool illuminated_at(const std::string& objects, float x) {
    const auto scene = testing::compile_pov_text(objects, "<double>");
    Hit hit;
    if (!scene->intersect(testing::make_ray(Vec3(x, 0.0f, -10.0f), Vec3(0, 0, 1)), hit))
        throw std::runtime_error("no hit");
    return hit.double_illuminate;
}

TEST(DoubleIlluminate, AnObjectsOwnSetting) {
    EXPECT_TRUE(illuminated_at("disc { 0, z, 1 double_illuminate }", 0.0f));
    EXPECT_FALSE(illuminated_at("disc { 0, z, 1 double_illuminate off }", 0.0f));
    EXPECT_FALSE(illuminated_at("disc { 0, z, 1 }", 0.0f));
}

TEST(DoubleIlluminate, AGroupsSettingReachesEverythingInsideAndWins) {
    const std::string inside =
        "sphere { <-2, 0, 0>, 0.5 double_illuminate off }\n"
        "disc { <2, 0, 0>, z, 0.5 }\n";
    for (const char* group : {"union", "merge"}) {
        const std::string scene = std::string(group) + " { " + inside + " double_illuminate }";
        EXPECT_TRUE(illuminated_at(scene, -2.0f)) << group;
        EXPECT_TRUE(illuminated_at(scene, 2.0f)) << group;
    }
    // A difference's leaves too, the subtracted ones included.
    const std::string difference = "difference { box { -1, 1 } sphere { <0, 0, -1>, 0.5 } double_illuminate }";
    EXPECT_TRUE(illuminated_at(difference, 0.0f));  // inside the subtracted sphere's dent
    EXPECT_TRUE(illuminated_at(difference, 0.8f));  // the box's face
    // Without a setting of its own, a group leaves its objects theirs.
    EXPECT_FALSE(illuminated_at("union { " + inside + " }", -2.0f));
    EXPECT_FALSE(illuminated_at("union { " + inside + " }", 2.0f));
    EXPECT_TRUE(illuminated_at("union { disc { 0, z, 1 double_illuminate } sphere { 5*x, 1 } }", 0.0f));
    // object { } of a declared group applies it the same way.
    EXPECT_TRUE(illuminated_at("#declare G = union { " + inside + " }\nobject { G double_illuminate }", -2.0f));
}

}  // namespace
}  // namespace lancer
