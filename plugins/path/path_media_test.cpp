// path's participating media against closed forms: Beer-Lambert through a
// slab (chromatic, so null collisions are exercised), single scattering of
// a parallel light, a heterogeneous (delta tracked) slab of known optical
// depth, and a white furnace (albedo 1 medium inside an emitting sphere).
#include <cmath>

#include "../media_test_support.h"

namespace lancer {
namespace {

using namespace seed_test;
using namespace media_test;

// Mean and a 4-sigma bound of one ray's radiance over n samples.
struct Estimate {
    Color mean{0.0f};
    Color bound{0.0f};
};
Estimate estimate(const Integrator& integrator, const RenderScene& scene, const Ray& ray, int n) {
    const std::unique_ptr<Sampler> sampler = integrator.make_sampler(11);
    Color sum(0.0f), squares(0.0f);
    for (int i = 0; i < n; ++i) {
        sampler->start_sample(0, 0, std::uint32_t(i));
        const Color c = shade_camera_ray(integrator, ray, scene, *sampler);
        sum += c;
        squares += c * c;
    }
    Estimate e;
    e.mean = sum / float(n);
    const Color variance = glm::max(squares / float(n) - e.mean * e.mean, Color(0.0f));
    e.bound = 4.0f * glm::sqrt(variance / float(n)) + Color(1e-4f);
    return e;
}

void expect_within(const Estimate& e, const Color& expected) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(e.mean[k], expected[k], e.bound[k]) << "channel " << k;
}

TEST(PathMedia, BeerLambertThroughAChromaticSlab) {
    const auto scene = scene_from(slab("absorption <0.5, 1, 2>", 1.0));
    ASSERT_TRUE(scene);
    const auto path = load_integrator("path", *scene);
    expect_within(estimate(*path, *scene, kAlongZ, 4000), glm::exp(-Color(0.5f, 1.0f, 2.0f)));
}

TEST(PathMedia, EmissionAddsItsAttenuatedIntegral) {
    // dL/ds = e - sigma L: L = e (1 - exp(-sigma)) / sigma, plus the background dimmed.
    const auto scene = scene_from(slab("emission 0.3 absorption 0.5", 0.0));
    ASSERT_TRUE(scene);
    const auto path = load_integrator("path", *scene);
    expect_within(estimate(*path, *scene, kAlongZ, 200), Color(0.3f * (1.0f - std::exp(-0.5f)) / 0.5f));
}

TEST(PathMedia, SingleScatteringOfAParallelLight) {
    // Light travels along +z into the slab; the camera looks along +z, so
    // it sees light scattered straight back (cos = -1). With sigma_s = 0.5
    // (extinction 0.5), light reaching depth s is dimmed by exp(-0.5 s)
    // and its scattered share again on the way out:
    //   L = sigma_s p(-1) E int_0^1 exp(-2 sigma s) ds.
    // max_depth 2: the box face, then one scattering (single scattering only).
    const std::string light = "light_source { <0, 0, -100> color rgb 1 parallel point_at <0, 0, 0> }\n";
    for (const auto& [type, g] : {std::pair{1, 0.0f}, {4, 0.0f}, {5, 0.4f}}) {
        const std::string media = "scattering { " + std::to_string(type) + ", 0.5" +
                                  (type == 5 ? " eccentricity " + std::to_string(g) : std::string()) + " }";
        const auto scene = scene_from(slab(media, 0.0, light));
        ASSERT_TRUE(scene);
        const Color irradiance = scene->lights()[0]->sample(Vec3(0.0f, 0.0f, 0.5f), Vec2(0.5f)).radiance;
        const float sigma = 0.5f;
        const float expected_scale =
            sigma * phase_density(PhaseType(type), g, -1.0f) * (1.0f - std::exp(-2.0f * sigma)) / (2.0f * sigma);
        const auto path = load_integrator("path", *scene, {{"max_depth", "2"}});
        expect_within(estimate(*path, *scene, kAlongZ, 3000), expected_scale * irradiance);
    }
}

TEST(PathMedia, DeltaTrackingMatchesTheOpticalDepthOfADensityGradient) {
    // density = gradient z through the slab: extinction 2 z for z in [0, 1),
    // optical depth 1, transmittance exp(-1).
    const auto scene = scene_from(slab("absorption 2 density { gradient z }", 1.0));
    ASSERT_TRUE(scene);
    const auto path = load_integrator("path", *scene);
    expect_within(estimate(*path, *scene, kAlongZ, 4000), Color(std::exp(-1.0f)));
}

TEST(PathMedia, ACameraInsideAHollowMediumStartsInIt) {
    // An emitting wall 4 away inside a sphere of absorption 0.25 that holds
    // the camera: exp(-1) of its emission arrives.
    const auto scene = scene_from(
        "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
        "box { <-3, -3, -1>, <3, 3, -0.9> pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 1 } }\n"
        "sphere { <0, 0, -5>, 10 pigment { rgbt 1 } hollow interior { media { absorption 0.25 } } }\n");
    ASSERT_TRUE(scene);
    const auto path = load_integrator("path", *scene);
    expect_within(estimate(*path, *scene, kAlongZ, 4000), Color(std::exp(-1.0f)));
}

TEST(PathMedia, WhiteFurnaceConvergesToTheWallsEmission) {
    // Albedo 1: whatever the medium scatters, every direction ends on the
    // wall, which emits 0.7; the medium neither adds nor takes light.
    const auto scene = scene_from(
        "camera { location <0, 0, 0> look_at <0, 0, 1> }\n"
        "sphere { 0, 2 pigment { rgb 1 } finish { ambient 0 diffuse 0 emission 0.7 } hollow\n"
        "         interior { media { scattering { 5, 0.8 eccentricity 0.3 } } } }\n");
    ASSERT_TRUE(scene);
    const auto path = load_integrator("path", *scene, {{"max_depth", "-1"}});
    const Ray ray = ray_towards({0.0f, 0.0f, 0.0f}, {0.2f, 0.1f, 1.0f});
    expect_within(estimate(*path, *scene, ray, 3000), Color(0.7f));
}

}  // namespace
}  // namespace lancer
