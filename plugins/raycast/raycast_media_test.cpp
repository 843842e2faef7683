// raycast's media along camera rays (lancer/shading/pov_media.h), against
// closed forms: Beer-Lambert through the scene's media, emission of a
// hollow object the camera is in, and single scattering lit without shadow
// rays, as raycast lights its surfaces.
#include <cmath>

#include "../media_test_support.h"

namespace lancer {
namespace {

using namespace seed_test;
using namespace media_test;

// A wall 4 in front of the camera, white and lit head-on by a light at the
// camera (radiance 1 without media), behind the scene's `media`.
std::string wall_behind(const std::string& media) {
    return "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
           "light_source { <0, 0, -5> color rgb 1 }\n"
           "plane { -z, 1 pigment { rgb 1 } finish { ambient 0 diffuse 1 } }\n"
           "media { " +
           media + " }\n";
}

TEST(RaycastMedia, TheScenesMediaDimCameraRaysByBeerLambert) {
    expect_colour(radiance_in("raycast", wall_behind("absorption <0.25, 0.5, 1>")), glm::exp(-Color(1.0f, 2.0f, 4.0f)),
                  1e-5f);
}

TEST(RaycastMedia, LanesShadeThroughTheMediaToo) {
    // The wall is the lane-parallel kind of hit (diffuse, one colour, a
    // point light): a rendered pixel goes through the batch path.
    const auto scene = scene_from(wall_behind("absorption 0.25"));
    ASSERT_TRUE(scene);
    const auto raycast = load_integrator("raycast", *scene);
    const Film film = render_small(*scene, *raycast, 1, 1);
    expect_colour(film.mean(0, 0), Color(std::exp(-1.0f)), 1e-5f);
}

TEST(RaycastMedia, ACameraInsideAHollowObjectSeesItsMedia) {
    // A hollow sphere of radius 10 about the camera, black and fully
    // transmitting, emitting 0.05 per unit inside: 0.5 to its far side.
    const std::string inside =
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "sphere { <0, 0, -5>, 10 pigment { rgbt <0, 0, 0, 1> } finish { ambient 0 diffuse 0 } hollow\n"
        "         interior { media { emission 0.05 } } }\n";
    expect_colour(radiance_in("raycast", inside), Color(0.5f), 1e-5f);
}

TEST(RaycastMedia, ScatteringIsLitWithoutShadowRays) {
    // sigma int_0^4 exp(-sigma s) ds = 1 - exp(-4 sigma), even with an
    // opaque roof between light and ray.
    const float expected = 1.0f - std::exp(-0.4f);
    expect_colour(radiance_in("raycast", scattering_under_parallel_light(true)), Color(expected), 0.005f * expected);
}

}  // namespace
}  // namespace lancer
