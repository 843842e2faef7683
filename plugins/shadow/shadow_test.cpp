// The shadow integrator against scenes whose shadows geometry predicts.
#include <cmath>
#include "lancer/host/scene_compiler.h"

#include "../seed_integrators_test.h"

namespace lancer {
namespace {

using namespace seed_test;

// A unit sphere floating at height 4 above the ground plane y = 0, a point
// light straight above it at height 10.
constexpr double kLightHeight = 10.0;
constexpr double kSphereHeight = 4.0;
constexpr double kSphereRadius = 1.0;
constexpr float kLightColor = 100.0f;

sg::SceneGraph floating_sphere_scene() {
    sg::SceneGraph graph;
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, default_material()));
    graph.objects.push_back(sphere({0.0, kSphereHeight, 0.0}, kSphereRadius, default_material()));
    graph.lights.push_back(point_light({0.0, kLightHeight, 0.0}, sg::Vec3(kLightColor)));
    return graph;
}

// Radius of the shadow on the ground: the cone from the light tangent to
// the sphere has half-angle asin(r / (H - h)), so it meets y = 0 at
// H * tan(half-angle).
double analytic_shadow_radius() {
    const double d = kLightHeight - kSphereHeight;
    return kLightHeight * kSphereRadius / std::sqrt(d * d - kSphereRadius * kSphereRadius);
}

// The ground at (x, 0, 0) seen from the side (a ray in the plane x = const,
// which passes under the sphere), so the ray itself never meets the sphere.
Ray ray_to_ground(double x) {
    return ray_towards(Vec3(float(x), 1.0f, -5.0f), Vec3(float(x), 0.0f, 0.0f));
}

// Default material: white, ambient 0.1, diffuse 0.6. A POV point light of
// colour C gives radiance 0.6 * C * cos on it, at any distance (POV-Ray's
// point lights do not fall off; light.h's units).
float lit_ground_radiance(double x) {
    const double d2 = x * x + kLightHeight * kLightHeight;
    const double cos_theta = kLightHeight / std::sqrt(d2);
    return float(0.1 + 0.6 * kLightColor * cos_theta);
}

TEST(ShadowIntegrator, GroundBelowFloatingSphereIsInFullShadow) {
    const auto scene = compile_scene(floating_sphere_scene());
    const auto shadow = load_integrator("shadow", *scene);
    const Color below = mean_radiance(*shadow, *scene, ray_to_ground(0.0));
    // Only the ambient term remains: 0.1 * white * ambient_light 1.
    EXPECT_NEAR(below.r, 0.1f, 1e-5f);
    EXPECT_NEAR(below.g, 0.1f, 1e-5f);
    EXPECT_NEAR(below.b, 0.1f, 1e-5f);
}

TEST(ShadowIntegrator, ShadowEdgeLiesWhereGeometrySays) {
    const auto scene = compile_scene(floating_sphere_scene());
    const auto shadow = load_integrator("shadow", *scene);
    const double edge = analytic_shadow_radius();  // 1.690 for these sizes
    for (double side : {-1.0, 1.0}) {
        const double inside = side * edge * 0.99;
        const double outside = side * edge * 1.01;
        EXPECT_NEAR(mean_radiance(*shadow, *scene, ray_to_ground(inside)).g, 0.1f, 1e-5f)
            << "x = " << inside << " should be in shadow (edge at " << edge << ")";
        EXPECT_NEAR(mean_radiance(*shadow, *scene, ray_to_ground(outside)).g, lit_ground_radiance(outside), 1e-4f)
            << "x = " << outside << " should be lit (edge at " << edge << ")";
    }
}

TEST(ShadowIntegrator, EqualsRaycastWhereNothingOccludes) {
    const auto scene = compile_scene(floating_sphere_scene());
    const auto shadow = load_integrator("shadow", *scene);
    const auto raycast = load_integrator("raycast", *scene);
    for (double x : {2.0, 3.5, -6.0}) {
        const Color with_shadows = mean_radiance(*shadow, *scene, ray_to_ground(x));
        const Color without = mean_radiance(*raycast, *scene, ray_to_ground(x));
        EXPECT_NEAR(with_shadows.g, without.g, 1e-6f) << "x = " << x;
        EXPECT_NEAR(with_shadows.g, lit_ground_radiance(x), 1e-4f) << "x = " << x;
    }
}

// POV's shadowless light lights what faces it through anything: the ground
// below the sphere is lit as if the sphere were not there, by shadow,
// whitted and path's direct light alike.
TEST(ShadowIntegrator, ShadowlessLightCastsNoShadow) {
    sg::SceneGraph graph = floating_sphere_scene();
    graph.lights[0].shadowless = true;
    const auto scene = compile_scene(graph);
    EXPECT_NEAR(mean_radiance(*load_integrator("shadow", *scene), *scene, ray_to_ground(0.0)).g,
                lit_ground_radiance(0.0), 1e-4f);
    EXPECT_NEAR(mean_radiance(*load_integrator("whitted", *scene), *scene, ray_to_ground(0.0)).g,
                lit_ground_radiance(0.0), 1e-4f);
    // path has no ambient term: the diffuse light alone.
    const auto path = load_integrator("path", *scene, {{"max_depth", "1"}, {"light_sampling", "all"}});
    EXPECT_NEAR(mean_radiance(*path, *scene, ray_to_ground(0.0)).g, lit_ground_radiance(0.0) - 0.1f, 1e-4f);
    // The same light with shadows leaves only the ambient term there.
    const auto shadowed = compile_scene(floating_sphere_scene());
    EXPECT_NEAR(mean_radiance(*load_integrator("shadow", *shadowed), *shadowed, ray_to_ground(0.0)).g, 0.1f, 1e-5f);
}

TEST(ShadowIntegrator, FullyTransmittingBlockerCastsNoShadow) {
    sg::SceneGraph graph = floating_sphere_scene();
    EXPECT_TRUE(compile_scene(graph)->opaque_surfaces());  // blocked shadow rays black at once
    graph.objects[1].material = material([](sg::Material& m) { m.pigment.color.transmit = 1.0; });
    const auto scene = compile_scene(graph);
    EXPECT_FALSE(scene->opaque_surfaces());  // each blocker is looked at
    const auto shadow = load_integrator("shadow", *scene);
    EXPECT_NEAR(mean_radiance(*shadow, *scene, ray_to_ground(0.0)).g, lit_ground_radiance(0.0), 1e-4f);
}

// With every surface opaque a blocked shadow ray is black at once; an
// object that casts no shadow is still no blocker.
TEST(ShadowIntegrator, NoShadowObjectLetsTheLightThroughInAnOpaqueScene) {
    sg::SceneGraph graph = floating_sphere_scene();
    graph.objects[1].no_shadow = true;
    const auto scene = compile_scene(graph);
    ASSERT_TRUE(scene->opaque_surfaces());
    for (const char* integrator : {"shadow", "whitted"})
        EXPECT_NEAR(mean_radiance(*load_integrator(integrator, *scene), *scene, ray_to_ground(0.0)).g,
                    lit_ground_radiance(0.0), 1e-4f)
            << integrator;
}

// A square lamp (side 2) at height 10 above the sphere: through its proxy
// the shadow stays hard; with area_samples the rim of the umbra becomes a
// penumbra, lit by a fraction of the lamp.
TEST(ShadowIntegrator, AreaSamplesSoftenTheShadowEdge) {
    sg::SceneGraph graph = floating_sphere_scene();
    graph.lights = {square_light({0.0, kLightHeight, 0.0}, 2.0, sg::Vec3(kLightColor))};
    sg::SceneGraph unoccluded_graph = graph;
    unoccluded_graph.objects.pop_back();  // the sphere
    const auto scene = compile_scene(graph);
    const auto unoccluded = compile_scene(unoccluded_graph);
    const auto hard = load_integrator("shadow", *scene);
    const auto soft = load_integrator("shadow", *scene, {{"area_samples", "16"}});
    EXPECT_TRUE(hard->is_deterministic());
    EXPECT_FALSE(soft->is_deterministic());

    const Ray at_edge = ray_to_ground(analytic_shadow_radius() * 0.99);  // inside the proxy's hard shadow
    EXPECT_NEAR(mean_radiance(*hard, *scene, at_edge).g, 0.1f, 1e-5f);
    const float lit_fraction = (mean_radiance(*soft, *scene, at_edge, 64).g - 0.1f) /
                               (mean_radiance(*soft, *unoccluded, at_edge, 64).g - 0.1f);
    EXPECT_GT(lit_fraction, 0.1f);
    EXPECT_LT(lit_fraction, 0.9f);
    // The umbra's core stays dark: no point of the lamp is visible from it.
    EXPECT_NEAR(mean_radiance(*soft, *scene, ray_to_ground(0.0), 16).g, 0.1f, 1e-5f);
    // Unoccluded, the sampled lamp and its proxy agree to a few percent at this distance.
    const float proxy_lit = mean_radiance(*hard, *unoccluded, at_edge).g;
    EXPECT_NEAR(mean_radiance(*soft, *unoccluded, at_edge, 64).g, proxy_lit, 0.03f * proxy_lit);
}

// With area_samples, the lamp's direct light is estimated without bias: on
// a floor that sees only the lamp it converges to rho * Le * F (F the view
// factor from the floor point to the square, Le = pi C / area).
TEST(ShadowIntegrator, AreaSamplesConvergeToTheLampsDirectLight) {
    sg::SceneGraph graph;
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, default_material()));
    graph.lights.push_back(square_light({0.0, 1.0, 0.0}, 1.0, sg::Vec3(10.0)));
    const auto scene = compile_scene(graph);
    const auto soft = load_integrator("shadow", *scene, {{"area_samples", "16"}});
    const double x = 0.5 / 1.0;  // half side over height
    const double corner = 2.0 * x / std::sqrt(1.0 + x * x) * std::atan(x / std::sqrt(1.0 + x * x)) / (2.0 * M_PI);
    const double expected = 0.1 + 0.6 * (M_PI * 10.0) * 4.0 * corner;
    const Ray to_floor_centre = ray_towards(Vec3(0.0f, 0.3f, -3.0f), Vec3(0.0f));
    EXPECT_NEAR(mean_radiance(*soft, *scene, to_floor_centre, 256).g, expected, 0.01 * expected);
}

TEST(ShadowIntegrator, RejectsNegativeAreaSamples) {
    const Plugin plugin = load_plugin("shadow");
    const ParameterSet parameters = resolve_parameters(*plugin.descriptor, {}, {"area_samples=-1"});
    EXPECT_THROW(plugin.descriptor->create(parameters), std::invalid_argument);
}

}  // namespace
}  // namespace lancer
