// shadow's media along camera rays (lancer/shading/pov_media.h): the same
// closed forms as raycast's, but a medium's samples are lit behind shadow
// rays, as shadow lights its surfaces.
#include <cmath>

#include "../media_test_support.h"

namespace lancer {
namespace {

using namespace seed_test;
using namespace media_test;

TEST(ShadowMedia, TheScenesMediaDimCameraRaysByBeerLambert) {
    const std::string wall =
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "light_source { <0, 0, -5> color rgb 1 }\n"
        "plane { -z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
        "media { absorption 0.25 }\n";
    expect_colour(radiance_in("shadow", wall), Color(std::exp(-1.0f)), 1e-5f);
}

TEST(ShadowMedia, ScatteringIsLitBehindShadowRays) {
    // As RaycastMedia.ScatteringIsLitWithoutShadowRays: 1 - exp(-4 sigma)
    // in the open, nothing under an opaque roof.
    const float expected = 1.0f - std::exp(-0.4f);
    expect_colour(radiance_in("shadow", scattering_under_parallel_light(false)), Color(expected), 0.005f * expected);
    expect_colour(radiance_in("shadow", scattering_under_parallel_light(true)), Color(0.0f), 1e-6f);
}

}  // namespace
}  // namespace lancer
