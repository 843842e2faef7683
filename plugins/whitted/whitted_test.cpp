// The whitted integrator on scenes with known answers: invisible glass,
// mirrors, total internal reflection, POV-Ray's depth and bailout limits.
#include <cmath>
#include "lancer/host/scene_compiler.h"

#include "../seed_integrators_test.h"

namespace lancer {
namespace {

using namespace seed_test;

// A lit floor and back wall seen by a small camera, optionally with a
// sphere in front (the object under test).
sg::SceneGraph room(std::optional<sg::Object> extra) {
    sg::SceneGraph graph;
    graph.camera = camera({0.0, 1.5, -5.0}, {0.0, -0.2, 1.0});
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, material([](sg::Material& m) {
                                      m.pigment = sg::checker_pigment({1, 1, 1}, {0, 1, 0});
                                      m.finish->specular = 0.3;
                                  })));
    graph.objects.push_back(plane({0.0, 0.0, -1.0}, -4.0, material([](sg::Material& m) {
                                      m.pigment.color.rgb = {0.8, 0.4, 0.2};
                                      m.finish->phong = 0.4;
                                  })));
    // POV's point light does not fall off: colour 1.5 lights the room about as
    // the physical lamp beside it does.
    graph.lights.push_back(point_light({-2.0, 6.0, -4.0}, sg::Vec3(1.5)));
    graph.lights.push_back(square_light({2.0, 5.0, 0.0}, 1.0, sg::Vec3(20.0)));
    if (extra) graph.objects.push_back(*extra);
    return graph;
}

TEST(WhittedIntegrator, FullyTransmittingSphereWithIorOneIsInvisible) {
    // Default finish (diffuse 0.6, ambient 0.1): a transparent object has no
    // diffuse, no ambient and casts no shadow.
    sg::Object glass = sphere({0.0, 1.0, 0.0}, 1.0, material([](sg::Material& m) {
                                  m.pigment.color.transmit = 1.0;
                                  m.interior->ior = 1.0;
                              }));
    const auto with_sphere = compile_scene(room(glass));
    const auto without_sphere = compile_scene(room(std::nullopt));
    const auto whitted = load_integrator("whitted", *with_sphere);
    const Film seen = render_small(*with_sphere, *whitted, 32, 24);
    const Film reference = render_small(*without_sphere, *whitted, 32, 24);
    float largest_difference = 0.0f;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x)
            largest_difference =
                glm::max(largest_difference, max_component(glm::abs(seen.mean(x, y) - reference.mean(x, y))));
    EXPECT_LT(largest_difference, 1e-4f);
}

// A floor mirror of reflectance rho under a camera looking down at 45
// degrees; the reflected ray meets a uniformly coloured wall.
constexpr sg::Vec3 kWallColour{0.2, 0.5, 0.9};

sg::SceneGraph mirror_facing_wall(sg::MaterialRef mirror) {
    sg::SceneGraph graph;
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, std::move(mirror)));
    graph.objects.push_back(plane({0.0, 0.0, -1.0}, -10.0, flat_colour(kWallColour)));
    graph.lights.push_back(point_light({0.0, 5.0, 1.0}, sg::Vec3(30.0)));
    return graph;
}
const Ray kDownAt45 = ray_towards(Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, 0.0f, 1.0f));

// A layered texture, lit as POV-Ray lights one: the top layer (pigment
// <1, 0.5, 0> filter 0.5, ambient 0.2) shows 0.5 * 0.2 * pigment of its
// own and passes filter * pigment = <0.5, 0.25, 0> of the layer below
// (pigment <0.4, 1, 1>, ambient 1: <0.2, 0.25, 0>), so <0.3, 0.3, 0>;
// the bottom layer's mirror (0.5) is added undimmed by the layer above.
// raycast shows the layers' own light, whitted the mirror too. One
// material with a blended finish would give neither.
TEST(WhittedIntegrator, LayeredTextureLightsEachLayerWithItsOwnFinish) {
    auto layered = std::make_shared<sg::Material>(*material([](sg::Material& m) {
        m.pigment.color.rgb = {0.4, 1.0, 1.0};
        m.finish->ambient = sg::Vec3(1.0);
        m.finish->diffuse = 0.0;
        m.finish->reflection.min = m.finish->reflection.max = sg::Vec3(0.5);
    }));
    layered->layers_above.push_back(material([](sg::Material& m) {
        m.pigment.color.rgb = {1.0, 0.5, 0.0};
        m.pigment.color.filter = 0.5;
        m.finish->ambient = sg::Vec3(0.2);
        m.finish->diffuse = 0.0;
    }));
    const auto scene = compile_scene(mirror_facing_wall(layered));
    const Color own(0.3f, 0.3f, 0.0f);
    const auto raycast = load_integrator("raycast", *scene);
    const Color raycast_seen = mean_radiance(*raycast, *scene, kDownAt45);
    const auto whitted = load_integrator("whitted", *scene);
    const Color whitted_seen = mean_radiance(*whitted, *scene, kDownAt45);
    for (int c = 0; c < 3; ++c) {
        EXPECT_NEAR(raycast_seen[c], own[c], 1e-5f) << "channel " << c;
        EXPECT_NEAR(whitted_seen[c], own[c] + 0.5f * float(kWallColour[c]), 1e-5f) << "channel " << c;
    }
}

TEST(WhittedIntegrator, MirrorShowsWallColourTimesReflectance) {
    const auto scene = compile_scene(mirror_facing_wall(material([](sg::Material& m) {
        m.finish->diffuse = 0.0;
        m.finish->ambient = sg::Vec3(0.0);
        m.finish->reflection.min = m.finish->reflection.max = sg::Vec3(0.7);
    })));
    const auto whitted = load_integrator("whitted", *scene);
    const Color seen = mean_radiance(*whitted, *scene, kDownAt45);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], 0.7f * float(kWallColour[c]), 1e-5f) << "channel " << c;
}

TEST(WhittedIntegrator, MirrorAddsToTheDiffuseUnlessAdditiveReflectionIsOff) {
    // reflection 1 with POV's default diffuse 0.6 and ambient 0.1, lit from
    // above. POV-Ray's sum (the default) keeps the diffuse and ambient terms
    // on top of the reflected wall.
    const auto scene = compile_scene(mirror_facing_wall(
        material([](sg::Material& m) { m.finish->reflection.min = m.finish->reflection.max = sg::Vec3(1.0); })));
    const auto whitted = load_integrator("whitted", *scene);
    EXPECT_GT(mean_radiance(*whitted, *scene, kDownAt45).r, float(kWallColour[0]) + 0.1f);

    // additive_reflection=false: the mirror takes its share from the
    // diffuse, so a full mirror shows only the wall.
    const auto subtractive = load_integrator("whitted", *scene, {{"additive_reflection", "false"}});
    const Color seen = mean_radiance(*subtractive, *scene, kDownAt45);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], float(kWallColour[c]), 1e-5f) << "channel " << c;
}

// POV's reflection { exponent e }: the reflected colour is raised to 1/e
// (its parser stores Reflect_Exp = 1 / e; tests/reference/pov/
// irid_reflection.pov shows it against POV-Ray's pixels);
// metallic m tints the mirror towards the pigment (at 45 degrees POV's
// curve F is 0.0007, so the reflectance is rho * (1 + m (1 - F)(pig - 1))).
TEST(WhittedIntegrator, ReflectionExponentAndMetallicAsPovRay) {
    const auto mirror = [](double exponent, double metallic) {
        return material([=](sg::Material& m) {
            m.pigment.color.rgb = {1.0, 0.5, 0.25};
            m.finish->diffuse = 0.0;
            m.finish->ambient = sg::Vec3(0.0);
            m.finish->reflection.min = m.finish->reflection.max = sg::Vec3(0.7);
            m.finish->reflection.exponent = exponent;
            m.finish->reflection.metallic = metallic;
        });
    };
    const auto rooted = compile_scene(mirror_facing_wall(mirror(2.0, 0.0)));
    const Color seen = mean_radiance(*load_integrator("whitted", *rooted), *rooted, kDownAt45);
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(seen[c], 0.7f * float(std::sqrt(kWallColour[c])), 1e-5f) << "channel " << c;

    const auto tinted = compile_scene(mirror_facing_wall(mirror(1.0, 1.0)));
    const Color tint = mean_radiance(*load_integrator("whitted", *tinted), *tinted, kDownAt45);
    const double x = 0.5;  // the angle from the normal over pi/2
    const double f = 0.014567225 / ((x - 1.12) * (x - 1.12)) - 0.011612903;
    const sg::Vec3 pigment{1.0, 0.5, 0.25};
    for (int c = 0; c < 3; ++c)
        EXPECT_NEAR(tint[c], 0.7 * (1.0 + (1.0 - f) * (pigment[c] - 1.0)) * kWallColour[c], 1e-4) << "channel " << c;
}

// POV's conserve_energy: a clear pane (transmit 1, ior 1) with reflection
// 0.4 passes 1 - 0.4 of the wall behind it, not all of it.
TEST(WhittedIntegrator, ConserveEnergyTakesTheReflectionFromTheTransmission) {
    const auto pane = [](bool conserve) {
        sg::SceneGraph graph;
        graph.objects.push_back(plane({0.0, 0.0, 1.0}, 0.0, material([=](sg::Material& m) {
                                          m.pigment.color.transmit = 1.0;
                                          m.finish->reflection.min = m.finish->reflection.max = sg::Vec3(0.4);
                                          m.finish->conserve_energy = conserve;
                                      })));
        graph.objects.push_back(plane({0.0, 0.0, 1.0}, 10.0, flat_colour(kWallColour)));
        return compile_scene(std::move(graph));
    };
    const Ray ahead = ray_towards(Vec3(0.0f, 0.0f, -5.0f), Vec3(0.0f, 0.0f, 1.0f));
    for (bool conserve : {false, true}) {
        const auto scene = pane(conserve);
        const Color seen = mean_radiance(*load_integrator("whitted", *scene), *scene, ahead);
        for (int c = 0; c < 3; ++c)
            EXPECT_NEAR(seen[c], (conserve ? 0.6f : 1.0f) * float(kWallColour[c]), 1e-5f) << "channel " << c;
    }
}

// A slab of dense glass (y in [-1, 0], ior 1.5) under a red sky, over a
// black floor; inside it, a green ball. A ray inside the slab meets the top
// face at a grazing angle, reflects totally and finds the ball; a steeper
// ray leaves into the sky.
sg::SceneGraph glass_slab() {
    sg::SceneGraph graph;
    graph.background = {1.0, 0.0, 0.0};
    graph.objects.push_back(box({-100.0, -1.0, -100.0}, {100.0, 0.0, 100.0}, material([](sg::Material& m) {
                                    m.pigment.color.transmit = 1.0;
                                    m.finish->ambient = sg::Vec3(0.0);
                                    m.finish->diffuse = 0.0;
                                    m.interior->ior = 1.5;
                                })));
    graph.objects.push_back(sphere({10.0, -0.5, 0.0}, 0.3, flat_colour({0.0, 1.0, 0.0})));
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, -2.0, flat_colour({0.0, 0.0, 0.0})));
    return graph;
}

TEST(WhittedIntegrator, TotalInternalReflectionAtGrazingAngle) {
    const auto scene = compile_scene(glass_slab());
    for (const char* fresnel : {"false", "true"}) {
        const auto whitted = load_integrator("whitted", *scene, {{"fresnel", fresnel}});
        // sin(incidence) = 0.995 > 1/1.5: no light crosses the top face.
        const Ray grazing{Vec3(0.0f, -0.5f, 0.0f), glm::normalize(Vec3(1.0f, 0.1f, 0.0f))};
        const Color seen = mean_radiance(*whitted, *scene, grazing);
        EXPECT_NEAR(seen.r, 0.0f, 1e-6f) << "fresnel " << fresnel;
        EXPECT_NEAR(seen.g, 1.0f, 1e-5f) << "fresnel " << fresnel;
    }
}

// POV-Ray's total internal reflection reflects all of the light, whatever
// the transparency and the finish's own reflection: a half-transparent
// slab with reflection 0.3 shows the ball at full strength, not 0.5 + 0.3.
TEST(WhittedIntegrator, TotalInternalReflectionReflectsEverythingAsPovRay) {
    sg::SceneGraph graph = glass_slab();
    graph.objects[0].material = material([](sg::Material& m) {
        m.pigment.color.transmit = 0.5;
        m.finish->ambient = sg::Vec3(0.0);
        m.finish->diffuse = 0.0;
        m.finish->reflection.min = m.finish->reflection.max = sg::Vec3(0.3);
        m.interior->ior = 1.5;
    });
    const auto scene = compile_scene(std::move(graph));
    const Ray grazing{Vec3(0.0f, -0.5f, 0.0f), glm::normalize(Vec3(1.0f, 0.1f, 0.0f))};
    EXPECT_NEAR(mean_radiance(*load_integrator("whitted", *scene), *scene, grazing).g, 1.0f, 1e-5f);
}

TEST(WhittedIntegrator, SteepRayLeavesTheDenseMedium) {
    const auto scene = compile_scene(glass_slab());
    const Ray steep{Vec3(0.0f, -0.5f, 0.0f), glm::normalize(Vec3(0.5f, 1.0f, 0.0f))};
    // Fixed coefficients: all of the transparency passes into the sky.
    const auto fixed = load_integrator("whitted", *scene);
    EXPECT_NEAR(mean_radiance(*fixed, *scene, steep).r, 1.0f, 1e-5f);
    // Fresnel: the sky is seen through 1 - F of the glass-to-air interface.
    const auto fresnel = load_integrator("whitted", *scene, {{"fresnel", "true"}});
    const float cos_i = glm::dot(steep.direction, Vec3(0.0f, 1.0f, 0.0f));
    EXPECT_NEAR(mean_radiance(*fresnel, *scene, steep).r, 1.0f - fresnel_dielectric(cos_i, 1.5f), 1e-5f);
}

// Glass that already writes POV's `reflection {0, 1 fresnel on}`, under a
// white sky over a black floor: with the fresnel parameter on, the surface
// reflects F once (max(rho_r, T F)), not rho_r + T F.
TEST(WhittedIntegrator, FresnelGlassWithFresnelReflectionReflectsOnce) {
    sg::SceneGraph graph;
    graph.background = {1.0, 1.0, 1.0};
    graph.objects.push_back(box({-10.0, -1.0, -10.0}, {10.0, 0.0, 10.0}, material([](sg::Material& m) {
                                    m.pigment.color.filter = 1.0;
                                    m.finish->ambient = sg::Vec3(0.0);
                                    m.finish->diffuse = 0.0;
                                    m.finish->reflection.max = sg::Vec3(1.0);
                                    m.finish->reflection.fresnel = true;
                                    m.interior->ior = 1.5;
                                })));
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, -2.0, flat_colour({0.0, 0.0, 0.0})));
    const auto scene = compile_scene(graph);
    const auto whitted = load_integrator("whitted", *scene, {{"fresnel", "true"}});
    const Ray straight_down{Vec3(0.0f, 1.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f)};
    const float f = fresnel_dielectric(1.0f, 1.0f / 1.5f);  // 0.04
    // The top face reflects F of the sky; the 1 - F that enters is reflected
    // by F at the bottom face and leaves through the top by 1 - F (levels 2
    // to 4); the next round trip would need level 6 (max_trace_level 5).
    EXPECT_NEAR(mean_radiance(*whitted, *scene, straight_down).g, f + (1.0f - f) * f * (1.0f - f), 1e-5f);
}

// Two facing mirrors of reflectance 1/2 and ambient 1 (no diffuse): each
// level adds (1 - 1/2) * 1 and passes half on, so a ray traced to level D
// sees 1 - 2^-D.
sg::SceneGraph facing_half_mirrors(double adc_bailout) {
    sg::SceneGraph graph;
    const auto half_mirror = material([](sg::Material& m) {
        m.finish->ambient = sg::Vec3(1.0);
        m.finish->diffuse = 0.0;
        m.finish->reflection.min = m.finish->reflection.max = sg::Vec3(0.5);
    });
    graph.objects.push_back(plane({0.0, 0.0, 1.0}, 1.0, half_mirror));
    graph.objects.push_back(plane({0.0, 0.0, 1.0}, -1.0, half_mirror));
    graph.global.adc_bailout = adc_bailout;
    return graph;
}
const Ray kAlongZ{Vec3(0.0f), Vec3(0.0f, 0.0f, 1.0f)};

// Each level adds its ambient 1 (POV's sum: the reflection does not take it
// away) and passes half on: levels 1..n give 2 - 2^(1-n).
TEST(WhittedIntegrator, DepthFollowsPovRayLevels) {
    const auto scene = compile_scene(facing_half_mirrors(1e-6));
    // Default: the scene's max_trace_level 5 (camera ray = level 1).
    EXPECT_NEAR(mean_radiance(*load_integrator("whitted", *scene), *scene, kAlongZ).g, 2.0f - 1.0f / 16.0f, 1e-5f);
    EXPECT_NEAR(mean_radiance(*load_integrator("whitted", *scene, {{"max_depth", "1"}}), *scene, kAlongZ).g, 1.0f,
                1e-5f);
    EXPECT_NEAR(mean_radiance(*load_integrator("whitted", *scene, {{"max_depth", "3"}}), *scene, kAlongZ).g, 1.75f,
                1e-5f);
}

TEST(WhittedIntegrator, StopsWhenPathWeightFallsUnderAdcBailout) {
    // Weights 1, 1/2, 1/4, 1/8: with adc_bailout 0.2 the fourth level is not traced.
    const auto scene = compile_scene(facing_half_mirrors(0.2));
    EXPECT_NEAR(mean_radiance(*load_integrator("whitted", *scene), *scene, kAlongZ).g, 1.75f, 1e-5f);
}

TEST(WhittedIntegrator, RejectsNegativeDepth) {
    const Plugin plugin = load_plugin("whitted");
    EXPECT_THROW(plugin.descriptor->create(resolve_parameters(*plugin.descriptor, {}, {"max_depth=-1"})),
                 std::invalid_argument);
}

}  // namespace
}  // namespace lancer
