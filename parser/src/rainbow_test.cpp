// Parsing POV-Ray's rainbow: its items and defaults, arc and falloff
// angles as POV keeps them, declared rainbows, and POV's errors located.
#include <cmath>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

TEST(ParserRainbow, ItemsAndDefaults) {
    const auto scene = parse_ok(R"(
        rainbow { angle 42.5 width 5 distance 100 jitter 0.01 direction <0, 0, 1> up <0, 1, 0.1>
                  color_map { [0 rgbt <1, 0, 0, 0.5>] [1 rgbt <0, 0, 1, 0.5>] } })");
    ASSERT_EQ(scene.rainbows.size(), 1u);
    const sg::Rainbow& r = scene.rainbows[0];
    EXPECT_DOUBLE_EQ(r.angle, 42.5);
    EXPECT_DOUBLE_EQ(r.width, 5.0);
    EXPECT_DOUBLE_EQ(r.distance, 100.0);
    EXPECT_DOUBLE_EQ(r.jitter, 0.01);
    EXPECT_DOUBLE_EQ(r.up.z, 0.1);
    ASSERT_TRUE(r.color_map);
    EXPECT_EQ(r.color_map->size(), 2u);
    // Neither angle given: POV keeps 180 for both (every direction, no fade).
    EXPECT_DOUBLE_EQ(r.arc_angle, 180.0);
    EXPECT_DOUBLE_EQ(r.falloff_angle, 180.0);
}

TEST(ParserRainbow, ArcAngleAloneIsAlsoTheFalloffAngle) {
    const auto arc = parse_ok("rainbow { direction z width 1 arc_angle 90 color_map { [0 rgb 1] [1 rgb 0] } }");
    EXPECT_NEAR(arc.rainbows.at(0).arc_angle, M_PI / 4.0, 1e-12);  // half the arc, in radians
    EXPECT_NEAR(arc.rainbows.at(0).falloff_angle, M_PI / 4.0, 1e-12);
    const auto both = parse_ok(R"(
        #declare R = rainbow { direction z width 1 arc_angle 120 falloff_angle 60 color_map { [0 rgb 1] [1 rgb 0] } }
        rainbow { R }
        rainbow { R angle 40 })");
    ASSERT_EQ(both.rainbows.size(), 2u);
    EXPECT_NEAR(both.rainbows[1].falloff_angle, M_PI / 6.0, 1e-12);
    EXPECT_DOUBLE_EQ(both.rainbows[1].angle, 40.0);
}

TEST(ParserRainbow, WhatPovRefusesIsALocatedError) {
    const Diagnostic no_direction = first_error("rainbow {\n angle 40 width 2 color_map { [0 rgb 1] [1 rgb 0] } }");
    EXPECT_NE(no_direction.message.find("direction"), std::string::npos) << no_direction.message;
    EXPECT_EQ(no_direction.location.line, 1);
    EXPECT_NE(first_error("rainbow { direction y up y }").message.find("co-linear"), std::string::npos);
    EXPECT_NE(first_error("rainbow { direction z arc_angle 400 }").message.find("arc_angle"), std::string::npos);
    EXPECT_NE(first_error("rainbow { direction z arc_angle 30 falloff_angle 60 }").message.find("smaller"),
              std::string::npos);
}

TEST(ParserRainbow, WidthStaysARenderSettingName) {
    const auto scene = parse_ok("render_settings { width 64 height 48 }");
    EXPECT_EQ(*scene.render.width, 64);
}

}  // namespace
}  // namespace lancer
