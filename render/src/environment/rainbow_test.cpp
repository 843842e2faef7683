// POV-Ray's rainbow against what ComputeRainbow gives by hand: the map
// read where a direction lies across the band, nothing outside the band
// or behind the viewer, the fade with distance and the transmit floor,
// and the falloff towards the ends of the arc.
#include <cmath>

#include <gtest/gtest.h>

#include "lancer/rainbow.h"
#include "lancer/scene_graph.h"
#include "materials/point_pigment.h"

namespace lancer {
namespace {

std::unique_ptr<PointPigment> two_colour_map(const sg::Color& low, const sg::Color& high) {
    sg::Pigment map;
    map.kind = sg::Pigment::Kind::Patterned;
    auto entries = std::make_shared<std::vector<sg::ColorMapEntry>>();
    entries->push_back(sg::ColorMapEntry{0.0, low});
    entries->push_back(sg::ColorMapEntry{1.0, high});
    map.color_map = entries;
    return make_point_pigment(map, MaterialBuild());
}

// A ring 40 degrees +-5 around +z, up +y.
SceneRainbows ring(double distance, const sg::Color& low, const sg::Color& high, double arc = 180.0,
                   double falloff = 180.0) {
    RainbowArc arc_of;
    arc_of.start_angle = glm::radians(35.0);
    arc_of.width = glm::radians(10.0);
    arc_of.distance = distance;
    arc_of.arc_angle = arc;
    arc_of.falloff_angle = falloff;
    std::vector<std::unique_ptr<PointPigment>> maps;
    maps.push_back(two_colour_map(low, high));
    return SceneRainbows({arc_of}, std::move(maps));
}

Vec3 off_axis(double degrees, double around_degrees = 0.0) {
    const double a = glm::radians(degrees), b = glm::radians(around_degrees);
    return Vec3(float(std::sin(a) * std::sin(b)), float(std::sin(a) * std::cos(b)), float(std::cos(a)));
}

TEST(Rainbow, ReadsTheMapAcrossTheBand) {
    const sg::Color red{{1.0, 0.0, 0.0}}, blue{{0.0, 0.0, 1.0}};
    const SceneRainbows rainbows = ring(1e7, red, blue);
    const Color behind(0.0f, 1.0f, 0.0f);
    // 37.5 degrees: a quarter across; seen against the sky (escaping ray).
    const Color seen = rainbows.seen_through(off_axis(37.5), 2e10f, behind);
    EXPECT_NEAR(seen.r, 0.75f, 1e-4f);
    EXPECT_NEAR(seen.g, 0.0f, 1e-4f);
    EXPECT_NEAR(seen.b, 0.25f, 1e-4f);
    // Outside the band, or looking away from the antisolar point: unchanged.
    EXPECT_EQ(rainbows.seen_through(off_axis(30.0), 2e10f, behind), behind);
    EXPECT_EQ(rainbows.seen_through(off_axis(46.0), 2e10f, behind), behind);
    EXPECT_EQ(rainbows.seen_through(Vec3(0.0f, 0.0f, -1.0f), 2e10f, behind), behind);
}

TEST(Rainbow, FadesWithDistanceDownToItsTransmit) {
    const sg::Color grey{{0.5, 0.5, 0.5}, 0.0, 0.3};
    const SceneRainbows rainbows = ring(10.0, grey, grey);
    const Color behind(1.0f);
    const double kept = std::exp(-4.0 / 10.0);
    EXPECT_NEAR(rainbows.seen_through(off_axis(40.0), 4.0f, behind).r, kept + (1.0 - kept) * 0.5, 1e-5);
    // Far away the rainbow is at its fullest, its transmit still passing.
    EXPECT_NEAR(rainbows.seen_through(off_axis(40.0), 2e10f, behind).r, 0.3 + 0.7 * 0.5, 1e-5);
}

TEST(Rainbow, FallsOffTowardsTheEndsOfItsArc) {
    const sg::Color white{{1.0, 1.0, 1.0}};
    // arc_angle 120 and falloff_angle 60 (POV keeps half-angles in radians).
    const SceneRainbows rainbows = ring(1e7, white, white, glm::radians(60.0), glm::radians(30.0));
    const Color behind(0.0f);
    EXPECT_NEAR(rainbows.seen_through(off_axis(40.0, 10.0), 2e10f, behind).r, 1.0f, 1e-5f);  // inside the falloff
    // Half-way through the falloff: smoothstep 0.5.
    const Color half = rainbows.seen_through(off_axis(40.0, 45.0), 2e10f, behind);
    EXPECT_NEAR(half.r, 0.5f, 1e-4f);
    EXPECT_EQ(rainbows.seen_through(off_axis(40.0, 70.0), 2e10f, behind), behind);  // beyond the arc
}

}  // namespace
}  // namespace lancer
