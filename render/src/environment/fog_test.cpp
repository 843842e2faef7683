// POV-Ray's fog against its closed forms: constant fog's exp(-d/distance),
// ground fog's atan integral of 1/(1+h^2), filter and transmit, several
// fogs at once, and a shadow ray's attenuation without the fog's colour.
#include <cmath>

#include <gtest/gtest.h>

#include "lancer/fog.h"

namespace lancer {
namespace {

FogLayer constant_fog(float distance, Color color) {
    FogLayer fog;
    fog.distance = distance;
    fog.color = color;
    return fog;
}

void expect_color_near(const Color& actual, const Color& expected, float tolerance) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(actual[c], expected[c], tolerance) << "channel " << c;
}

TEST(Fog, ConstantFogFadesByExpOfDistance) {
    const SceneFog fog({constant_fog(10.0f, Color(0.2f, 0.4f, 0.6f))}, 2);
    const Color behind(1.0f, 0.5f, 0.0f);
    const float t = std::exp(-25.0f / 10.0f);
    expect_color_near(fog.seen_through(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), 25.0f, behind),
                      t * behind + (1.0f - t) * Color(0.2f, 0.4f, 0.6f), 1e-6f);
    // An escaping ray sees the fog's colour alone.
    expect_color_near(fog.seen_through(Vec3(0.0f), Vec3(1.0f, 0.0f, 0.0f), kFogEscapeDistance, behind),
                      Color(0.2f, 0.4f, 0.6f), 1e-6f);
    // The shadow ray is dimmed but gains no colour.
    expect_color_near(fog.transmittance(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), 25.0f), Color(t), 1e-6f);
}

TEST(Fog, FilterTintsAndTransmitKeepsAFloor) {
    FogLayer layer = constant_fog(1.0f, Color(0.5f, 1.0f, 0.25f));
    layer.filter = 0.4f;
    layer.transmit = 0.3f;
    const SceneFog fog({layer}, 2);
    const Color behind(1.0f);
    // exp(-50) is far under the floor 0.3.
    const Color tint = Color(0.6f) + 0.4f * layer.color;
    expect_color_near(fog.seen_through(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), 50.0f, behind),
                      0.3f * tint * behind + 0.7f * layer.color, 1e-6f);
}

TEST(Fog, GroundFogIntegratesItsDensityAlongTheRay) {
    FogLayer layer = constant_fog(4.0f, Color(1.0f));
    layer.ground = true;
    layer.offset = 1.0f;
    layer.alt = 2.0f;
    const SceneFog fog({layer}, 2);
    // Horizontal at height 3: h = (3 - 1) / 2 = 1, density 1 / (1 + 1).
    const Color level = fog.transmittance(Vec3(0.0f, 3.0f, 0.0f), Vec3(1.0f, 0.0f, 0.0f), 6.0f);
    EXPECT_NEAR(level.r, std::exp(-6.0f * 0.5f / 4.0f), 1e-6f);
    // Rising from the ground (h from -0.5 to 2) along y over 5: the mean
    // density is (atan(2) + 0.5) / 2.5, the part below the offset counting 1.
    const Color rising = fog.transmittance(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), 5.0f);
    const double mean_density = (std::atan(2.0) + 0.5) / 2.5;
    EXPECT_NEAR(rising.r, std::exp(-5.0 * mean_density / 4.0), 1e-6);
    // Numerical check of the same against a midpoint sum of the density.
    double optical_depth = 0.0;
    constexpr int kSteps = 100000;
    for (int i = 0; i < kSteps; ++i) {
        const double y = (i + 0.5) * 5.0 / kSteps;
        const double h = (y - 1.0) / 2.0;
        optical_depth += (h <= 0.0 ? 1.0 : 1.0 / (1.0 + h * h)) * 5.0 / kSteps;
    }
    EXPECT_NEAR(rising.r, std::exp(-optical_depth / 4.0), 1e-5);
}

TEST(Fog, SeveralFogsMultiplyTheirAttenuationsAndAddTheirColours) {
    const SceneFog fog({constant_fog(2.0f, Color(1.0f, 0.0f, 0.0f)), constant_fog(8.0f, Color(0.0f, 0.0f, 1.0f))}, 2);
    const float a = std::exp(-4.0f / 2.0f), b = std::exp(-4.0f / 8.0f);
    expect_color_near(fog.seen_through(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), 4.0f, Color(0.0f, 1.0f, 0.0f)),
                      Color(1.0f - a, a * b, 1.0f - b), 1e-6f);
}

TEST(Fog, ZeroDistanceIsNoFogAndExtremesStayFinite) {
    const SceneFog none({constant_fog(0.0f, Color(1.0f))}, 2);
    expect_color_near(none.seen_through(Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f), 5.0f, Color(0.25f)), Color(0.25f), 0.0f);
    FogLayer ground = constant_fog(1e-3f, Color(0.5f));
    ground.ground = true;
    ground.alt = 1e-4f;
    ground.turbulent = true;
    ground.turbulence = Vec3(1.0f);
    const SceneFog steep({ground}, 2);
    for (const float distance : {0.0f, 1e-6f, 1.0f, 1e6f, kFogEscapeDistance}) {
        const Color seen = steep.seen_through(Vec3(1e5f, -3.0f, 2.0f), Vec3(0.0f, 1.0f, 0.0f), distance, Color(1.0f));
        for (int c = 0; c < 3; ++c) EXPECT_TRUE(std::isfinite(seen[c])) << "distance " << distance;
    }
}

}  // namespace
}  // namespace lancer
