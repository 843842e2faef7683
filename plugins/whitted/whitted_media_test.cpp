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

Color whitted_radiance(const std::string& text, const Ray& ray = kAlongZ) {
    const auto scene = scene_from(text);
    if (!scene) return Color(-1.0f);
    const auto whitted = load_integrator("whitted", *scene);
    return mean_radiance(*whitted, *scene, ray);
}

void expect_colour(const Color& seen, const Color& expected, float tolerance) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(seen[k], expected[k], tolerance) << "channel " << k;
}

TEST(WhittedMedia, BeerLambertThroughASlab) {
    expect_colour(whitted_radiance(slab("absorption <0.5, 1, 2>", 1.0)), glm::exp(-Color(0.5f, 1.0f, 2.0f)), 1e-5f);
    // Scattering dims as much as absorption (extinction 1), or as `extinction` says.
    expect_colour(whitted_radiance(slab("scattering { 1, 0.7 }", 1.0)), Color(std::exp(-0.7f)), 1e-5f);
    expect_colour(whitted_radiance(slab("scattering { 1, 0.7 extinction 0.5 }", 1.0)), Color(std::exp(-0.35f)), 1e-5f);
    // Two media in one interior add their coefficients.
    expect_colour(whitted_radiance(slab("absorption 0.25 } media { absorption 0.5", 1.0)), Color(std::exp(-0.75f)),
                  1e-5f);
}

TEST(WhittedMedia, EmissionAddsPerUnitLength) {
    // Without extinction POV's sum is exact: emission times the thickness.
    expect_colour(whitted_radiance(slab("emission <0.3, 0.2, 0.1>", 0.25)), Color(0.55f, 0.45f, 0.35f), 1e-5f);
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
        const Color seen = whitted_radiance(slab(media, 0.0, light));
        expect_colour(seen, Color(expected), 0.005f * expected);
    }
}

TEST(WhittedMedia, InteriorMediaNeedHollowAsInPovRay) {
    // POV-Ray 3.7 shows an interior's media only inside a hollow object.
    const std::string solid =
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "box { <-3, -3, 0>, <3, 3, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 }\n"
        "      interior { media { emission 0.5 } } }\n";
    expect_colour(whitted_radiance(solid), Color(0.0f), 1e-6f);
}

TEST(WhittedMedia, AtmosphereFillsTheOpenButNotSolidObjects) {
    // Scene-level media between the camera and a white wall 4 away (its
    // normal towards the camera: the camera is outside the plane's solid).
    const std::string open =
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "media { absorption 0.25 }\n"
        "plane { -z, 1 pigment { rgb 1 } finish { ambient 1 diffuse 0 } }\n";
    expect_colour(whitted_radiance(open), Color(std::exp(-1.0f)), 1e-5f);
    // A solid transmitting box 1 thick on the way: no atmosphere inside it.
    const std::string with_box =
        open + "box { <-3, -3, -3>, <3, 3, -2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } }\n";
    expect_colour(whitted_radiance(with_box), Color(std::exp(-0.75f)), 1e-5f);
    // Hollow: the atmosphere fills it.
    const std::string hollow =
        open + "box { <-3, -3, -3>, <3, 3, -2> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow }\n";
    expect_colour(whitted_radiance(hollow), Color(std::exp(-1.0f)), 1e-5f);
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
    const Color bright = whitted_radiance(lit, down);
    const Color dimmed = whitted_radiance(shaded, down);
    expect_colour(dimmed, bright * std::exp(-1.0f), 1e-4f);
}

}  // namespace
}  // namespace lancer
