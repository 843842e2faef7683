// Parsing POV-Ray's sky_sphere: pigments in order, transforms and emission
// of the whole sky, declared skies edited further, the last sky winning,
// and an empty sky as a located error (as POV's "Empty sky_sphere").
#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

TEST(ParserSkySphere, PigmentsTransformsAndEmission) {
    const auto scene = parse_ok(R"(
        sky_sphere {
          pigment { gradient y color_map { [0 rgb 1] [1 rgb <0, 0, 1>] } }
          pigment { rgbt <1, 1, 1, 0.5> }
          emission rgb <2, 1, 1>
          scale 2 translate <0, 1, 0>
        })");
    ASSERT_TRUE(scene.sky_sphere);
    const sg::SkySphere& sky = *scene.sky_sphere;
    ASSERT_EQ(sky.pigments.size(), 2u);
    EXPECT_EQ(sky.pigments[0].kind, sg::Pigment::Kind::Patterned);
    EXPECT_EQ(sky.pigments[1].kind, sg::Pigment::Kind::Solid);
    EXPECT_DOUBLE_EQ(sky.pigments[1].color.transmit, 0.5);
    EXPECT_DOUBLE_EQ(sky.emission.x, 2.0);
    const glm::dvec4 moved = sky.transform * glm::dvec4(1.0, 1.0, 1.0, 1.0);  // scale, then translate
    EXPECT_DOUBLE_EQ(moved.x, 2.0);
    EXPECT_DOUBLE_EQ(moved.y, 3.0);
    EXPECT_EQ(sky.location.line, 2);
}

TEST(ParserSkySphere, DeclaredSkyIsEditedAndTheLastSkyWins) {
    const auto scene = parse_ok(R"(
        #declare S = sky_sphere { pigment { rgb <1, 0, 0> } }
        sky_sphere { pigment { rgb 1 } }
        sky_sphere { S pigment { rgbf <0, 1, 0, 1> } rotate y*90 })");
    ASSERT_TRUE(scene.sky_sphere);
    const sg::SkySphere& sky = *scene.sky_sphere;
    ASSERT_EQ(sky.pigments.size(), 2u);
    EXPECT_DOUBLE_EQ(sky.pigments[0].color.rgb.x, 1.0);
    EXPECT_DOUBLE_EQ(sky.pigments[0].color.rgb.y, 0.0);
    EXPECT_DOUBLE_EQ(sky.pigments[1].color.filter, 1.0);
    const glm::dvec4 turned = sky.transform * glm::dvec4(1.0, 0.0, 0.0, 0.0);
    EXPECT_NEAR(turned.z, -1.0, 1e-12);  // POV's left-handed rotate y*90 takes +x to -z
}

TEST(ParserSkySphere, AnEmptySkyIsALocatedError) {
    const Diagnostic empty = first_error("camera { location -z }\n sky_sphere { rotate y*10 }");
    EXPECT_NE(empty.message.find("sky_sphere"), std::string::npos) << empty.message;
    EXPECT_EQ(empty.location.line, 2);
    EXPECT_NE(first_error("sky_sphere { pigment { rgb 1 } sphere { 0, 1 } }").message.find("sphere"),
              std::string::npos);
}

}  // namespace
}  // namespace lancer
