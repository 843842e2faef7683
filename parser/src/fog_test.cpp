// Parsing POV-Ray's fog: keywords and POV's defaults, declared fogs,
// several fogs, transforms turning only `up`, and located errors or
// warnings where POV complains.
#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

TEST(ParserFog, DefaultsAndItemsAreThoseOfPovRay) {
    const auto scene = parse_ok("fog { distance 10 color rgbf <0.5, 0.6, 0.7, 0.2> }");
    ASSERT_EQ(scene.fogs.size(), 1u);
    const sg::Fog& fog = scene.fogs[0];
    EXPECT_EQ(fog.type, sg::Fog::Type::Constant);
    EXPECT_DOUBLE_EQ(fog.distance, 10.0);
    EXPECT_DOUBLE_EQ(fog.color.rgb.y, 0.6);
    EXPECT_DOUBLE_EQ(fog.color.filter, 0.2);
    EXPECT_FALSE(fog.turbulent);
    EXPECT_DOUBLE_EQ(fog.turb_depth, 0.5);
    EXPECT_EQ(fog.octaves, 6);
    EXPECT_DOUBLE_EQ(fog.omega, 0.5);
    EXPECT_DOUBLE_EQ(fog.lambda, 2.0);
    EXPECT_DOUBLE_EQ(fog.up.y, 1.0);

    const auto ground = parse_ok(R"(
        fog { fog_type 2 distance 5 rgb 1 fog_offset 0.5 fog_alt 2 up <0, 0, 2>
              turbulence <1, 2, 3> turb_depth 0.3 octaves 3 omega 0.4 lambda 3 })");
    const sg::Fog& g = ground.fogs.at(0);
    EXPECT_EQ(g.type, sg::Fog::Type::Ground);
    EXPECT_DOUBLE_EQ(g.offset, 0.5);
    EXPECT_DOUBLE_EQ(g.alt, 2.0);
    EXPECT_DOUBLE_EQ(g.up.z, 1.0);  // normalised, as POV does
    EXPECT_TRUE(g.turbulent);
    EXPECT_DOUBLE_EQ(g.turbulence.z, 3.0);
    EXPECT_DOUBLE_EQ(g.turb_depth, 0.3);
    EXPECT_EQ(g.octaves, 3);
    EXPECT_DOUBLE_EQ(g.omega, 0.4);
    EXPECT_DOUBLE_EQ(g.lambda, 3.0);
}

TEST(ParserFog, DeclaredFogsAreEditedAndEveryFogApplies) {
    const auto scene = parse_ok(R"(
        #declare F = fog { distance 10 color rgb <1, 0, 0> }
        fog { F }
        fog { F distance 20 rotate z*90 })");
    ASSERT_EQ(scene.fogs.size(), 2u);
    EXPECT_DOUBLE_EQ(scene.fogs[0].distance, 10.0);
    EXPECT_DOUBLE_EQ(scene.fogs[1].distance, 20.0);
    EXPECT_DOUBLE_EQ(scene.fogs[1].color.rgb.x, 1.0);
    // rotate z*90 turns up (0, 1, 0) to (-1, 0, 0).
    EXPECT_NEAR(scene.fogs[1].up.x, -1.0, 1e-12);
    EXPECT_NEAR(scene.fogs[1].up.y, 0.0, 1e-12);
}

TEST(ParserFog, UnnamedDistanceAndTranslationWarnAsInPov) {
    ParseResult result = test::parse_snippet("fog { 15 color rgb 1 translate <1, 2, 3> }", "f.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_DOUBLE_EQ(result.scene->fogs.at(0).distance, 15.0);
    EXPECT_EQ(test::count_warnings(result), 2) << test::all_diagnostics(result);
}

TEST(ParserFog, ValuesPovCannotUseAreLocatedErrors) {
    const Diagnostic type = first_error("fog {\n fog_type 3 distance 1 }");
    EXPECT_NE(type.message.find("fog_type"), std::string::npos) << type.message;
    EXPECT_EQ(type.location.line, 2);
    EXPECT_NE(first_error("fog { fog_type 2 distance 1 }").message.find("fog_alt"), std::string::npos);
    EXPECT_NE(first_error("fog { distance 1 up 0 }").message.find("up"), std::string::npos);
}

}  // namespace
}  // namespace lancer
