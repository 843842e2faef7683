// whitted's media (POV-Ray's sampling, lancer/shading/pov_media.h) against
// closed forms: Beer-Lambert and emission in a homogeneous slab (POV's
// sampling is exact there), single scattering of a parallel light (POV's
// quadrature converges to the integral as intervals grow), POV's rules for
// `hollow`, and the light a medium takes from the surfaces behind it.
#include <cmath>

#include "../media_test_support.h"

namespace lancer {
namespace {

using namespace seed_test;
using namespace media_test;

TEST(WhittedMedia, BeerLambertThroughASlab) {
    expect_colour(radiance_in("whitted", slab("absorption <0.5, 1, 2>", 1.0)), glm::exp(-Color(0.5f, 1.0f, 2.0f)),
                  1e-5f);
    // Scattering dims as much as absorption (extinction 1), or as `extinction` says.
    expect_colour(radiance_in("whitted", slab("scattering { 1, 0.7 }", 1.0)), Color(std::exp(-0.7f)), 1e-5f);
    expect_colour(radiance_in("whitted", slab("scattering { 1, 0.7 extinction 0.5 }", 1.0)), Color(std::exp(-0.35f)),
                  1e-5f);
    // Two media in one interior add their coefficients.
    expect_colour(radiance_in("whitted", slab("absorption 0.25 } media { absorption 0.5", 1.0)),
                  Color(std::exp(-0.75f)), 1e-5f);
}

TEST(WhittedMedia, EmissionAddsPerUnitLength) {
    // Without extinction POV's sum is exact: emission times the thickness.
    expect_colour(radiance_in("whitted", slab("emission <0.3, 0.2, 0.1>", 0.25)), Color(0.55f, 0.45f, 0.35f), 1e-5f);
}

TEST(WhittedMedia, SingleScatteringOfAParallelLightConvergesToTheIntegral) {
    // As path's test: L = sigma_s k(-1) C int_0^1 exp(-2 sigma s) ds, with
    // POV's unnormalised k (isotropic: 1) and the light's colour C = 1.
    // 400 intervals of 2 samples: POV's quadrature within 0.5% of it.
    const std::string light = "light_source { <0, 0, -100> color rgb 1 parallel point_at <0, 0, 0> }\n";
    const float sigma = 0.5f;
    for (const auto& [type, g] : {std::pair{1, 0.0f}, {2, 0.0f}, {5, -0.3f}}) {
        const std::string media = "scattering { " + std::to_string(type) + ", 0.5" +
                                  (type == 5 ? " eccentricity " + std::to_string(g) : std::string()) +
                                  " } intervals 400 samples 2";
        const float expected =
            sigma * pov_phase_weight(PhaseType(type), g, -1.0f) * (1.0f - std::exp(-2.0f * sigma)) / (2.0f * sigma);
        const Color seen = radiance_in("whitted", slab(media, 0.0, light));
        expect_colour(seen, Color(expected), 0.005f * expected);
    }
}

TEST(WhittedMedia, ACylinderLightsBeamTakesTheSamples) {
    // A vertical beam of radius 0.2 (full light inside, none outside)
    // crosses the camera ray at z = 0, 5 from the camera, in a thin
    // isotropic medium in front of a black wall 10 away: the scattered
    // light is sigma int_4.8^5.2 exp(-sigma s) ds. As in POV-Ray, the lit
    // stretch takes `ratio` (0.9) of the intervals, so 10 of them find it
    // within 0.1%; spread evenly over the whole segment, one sample in 30
    // falls in the beam and the estimate was 24% short.
    const float sigma = 0.05f;
    const std::string beam =
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "light_source { <0, 10, 0> color rgb 1 cylinder point_at <0, 0, 0>"
        " radius 0.2 falloff 0.2 }\n"
        "plane { -z, -5 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\n"
        "media { scattering { 1, 0.05 } intervals 10 }\n";
    const float expected = std::exp(-4.8f * sigma) - std::exp(-5.2f * sigma);
    expect_colour(radiance_in("whitted", beam), Color(expected), 0.001f * expected);
}

TEST(WhittedMedia, InteriorMediaNeedHollowAsInPovRay) {
    // POV-Ray 3.7 shows an interior's media only inside a hollow object.
    const std::string solid =
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "box { <-3, -3, 0>, <3, 3, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }\n"
        "      interior { media { emission 0.5 } } }\n";
    expect_colour(radiance_in("whitted", solid), Color(0.0f), 1e-6f);
}

TEST(WhittedMedia, AtmosphereFillsTheOpenButNotSolidObjects) {
    // Scene-level media between the camera and a white wall 4 away (its
    // normal towards the camera: the camera is outside the plane's solid).
    const std::string open =
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "media { absorption 0.25 }\n"
        "plane { -z, 1 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n";
    expect_colour(radiance_in("whitted", open), Color(std::exp(-1.0f)), 1e-5f);
    // A solid transmitting box 1 thick on the way: no atmosphere inside it.
    const std::string with_box =
        open + "box { <-3, -3, -3>, <3, 3, -2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }\n";
    expect_colour(radiance_in("whitted", with_box), Color(std::exp(-0.75f)), 1e-5f);
    // Hollow: the atmosphere fills it.
    const std::string hollow =
        open + "box { <-3, -3, -3>, <3, 3, -2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow }\n";
    expect_colour(radiance_in("whitted", hollow), Color(std::exp(-1.0f)), 1e-5f);
}

TEST(WhittedMedia, ACameraInsideAnObjectStartsInItsInterior) {
    // A white wall 4 away inside a sphere of absorption 0.25 that holds
    // the camera: every camera ray starts in the medium (POV's containing
    // interiors), exp(-1). Not hollow, the sphere shows no media at all.
    const std::string wall =
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "plane { -z, 1 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n";
    const std::string medium = " interior { media { absorption 0.25 } } }\n";
    const std::string hollow = wall + "sphere { <0, 0, -5>, 10 pigment { rgbt 1 } hollow" + medium;
    const std::string solid = wall + "sphere { <0, 0, -5>, 10 pigment { rgbt 1 }" + medium;
    for (const char* integrator : {"whitted", "raycast", "shadow"}) {  // gather shows no ambient
        expect_colour(radiance_in(integrator, hollow), Color(std::exp(-1.0f)), 1e-5f);
        expect_colour(radiance_in(integrator, solid), Color(1.0f), 1e-5f);
    }
}

TEST(WhittedMedia, ShadowRaysThroughAMediumAreDimmed) {
    // A white floor lit from straight above through a hollow slab of
    // absorption 1, 1 thick: the light arriving is exp(-1) of it.
    const std::string lit =
        "camera { location <0, 1, -3> look_at <0, 0, 0> }\n"
        "light_source { <0, 10, 0> color rgb 1 }\n"
        "plane { y, 0 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n";
    const std::string shaded = lit +
                               "box { <-50, 2, -50>, <50, 3, 50> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }"
                               " hollow interior { media { absorption 1 } } }\n";
    const Ray down = ray_towards({0.0f, 1.0f, -3.0f}, {0.0f, 0.0f, 0.0f});
    const Color bright = radiance_in("whitted", lit, down);
    const Color dimmed = radiance_in("whitted", shaded, down);
    expect_colour(dimmed, bright * std::exp(-1.0f), 1e-4f);
}

}  // namespace
}  // namespace lancer
