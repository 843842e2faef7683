// POV-Ray's area_light in the integrators: lit from its centre, shadows
// from POV's hierarchical grid (shadow, whitted) or from the visible
// fraction of its rectangle (path), never seen by a ray.
#include <cmath>

#include "lancer/area_light_grid.h"
#include "lancer/host/counting_scene.h"
#include "lancer/host/scene_compiler.h"

#include "../seed_integrators_test.h"

namespace lancer {
namespace {

using namespace seed_test;

// A line light of five grid points x = -2 .. 2 at height 4 above the
// floor y = 0 (white, ambient 0.1, diffuse 0.6); its centre is straight
// above the origin.
sg::Light line_light(double colour, int adaptive = 100) {
    sg::Light light = point_light({0.0, 4.0, 0.0}, sg::Vec3(colour));
    light.area_light = true;
    light.axis1 = {4.0, 0.0, 0.0};
    light.axis2 = {0.0, 0.0, 0.0};
    light.samples1 = 5;
    light.samples2 = 1;
    light.adaptive = adaptive;
    return light;
}

// The floor, and a small sphere halfway between the origin and the grid
// point x = -2: from the origin it hides that point only (the ray to
// x = -1 passes 0.49 from the sphere's centre, its radius is 0.2).
sg::SceneGraph one_grid_point_hidden(const sg::Light& light) {
    sg::SceneGraph graph;
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, default_material()));
    graph.objects.push_back(sphere({-1.0, 2.0, 0.0}, 0.2, default_material()));
    graph.lights.push_back(light);
    return graph;
}

const Ray kToOrigin = ray_towards(Vec3(0.0f, 1.0f, -5.0f), Vec3(0.0f));

// The light's visibility from the origin, read off the floor's radiance:
// ambient 0.1 plus diffuse 0.6 × colour × cos 0 × visibility.
double visibility_at_origin(const sg::SceneGraph& graph, double colour, const std::string& integrator = "shadow") {
    const auto scene = compile_scene(graph);
    const auto shader = load_integrator(integrator, *scene);
    const Color seen = mean_radiance(*shader, *scene, kToOrigin);
    return (double(seen.g) - 0.1) / (0.6 * colour);
}

TEST(PovAreaLight, UnshadowedItLightsAsAPointLightAtItsCentre) {
    sg::SceneGraph area;
    area.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, default_material()));
    sg::SceneGraph point = area;
    sg::Light light = line_light(1.0);
    light.position = {0.7, 4.0, 0.3};  // off the axis: the cosine is the centre's
    area.lights.push_back(light);
    point.lights.push_back(point_light(light.position, light.color));
    for (const char* integrator : {"raycast", "shadow", "whitted"}) {
        const auto area_scene = compile_scene(area), point_scene = compile_scene(point);
        const auto a = load_integrator(integrator, *area_scene), p = load_integrator(integrator, *point_scene);
        const Color from_area = mean_radiance(*a, *area_scene, kToOrigin);
        const Color from_point = mean_radiance(*p, *point_scene, kToOrigin);
        EXPECT_FLOAT_EQ(from_area.g, from_point.g) << integrator;
    }
}

// POV averages corners hierarchically: with x = -2 hidden, the five points
// give (0.75 + 1 + 0.75 + 1) / 4 = 0.875, not their mean 0.8.
TEST(PovAreaLight, ShadowIsPovsHierarchicalAverageNotTheMean) {
    EXPECT_NEAR(visibility_at_origin(one_grid_point_hidden(line_light(1.0)), 1.0), 0.875, 1e-5);
    EXPECT_NEAR(visibility_at_origin(one_grid_point_hidden(line_light(1.0)), 1.0, "whitted"), 0.875, 1e-5);
}

// A light dimmer than POV's threshold (corners differ by 3 × 0.03 < 0.1,
// summed over the channels)
// subdivides only `adaptive` levels: 0 keeps the end points (0 and 1:
// 0.5), 1 splits once ((0.5 + 1 + 0.5 + 1) / 4), 2 reaches every point.
TEST(PovAreaLight, AdaptiveLevelsAsPovRay) {
    constexpr double kDim = 0.03;
    EXPECT_NEAR(visibility_at_origin(one_grid_point_hidden(line_light(kDim, 0)), kDim), 0.5, 1e-4);
    EXPECT_NEAR(visibility_at_origin(one_grid_point_hidden(line_light(kDim, 1)), kDim), 0.75, 1e-4);
    EXPECT_NEAR(visibility_at_origin(one_grid_point_hidden(line_light(kDim, 2)), kDim), 0.875, 1e-4);
    // A bright light subdivides where corners differ, whatever `adaptive` says.
    EXPECT_NEAR(visibility_at_origin(one_grid_point_hidden(line_light(1.0, 0)), 1.0), 0.875, 1e-5);
}

// Shadow rays traced for one floor point under an unshadowed square grid:
// each grid point at most once; `adaptive` a stops uniform regions after a
// levels (the manual: 8×8 with adaptive 1 traces 16 rays, 9×9 shares
// midpoints and traces 9). With `decoy`, a tiny sphere halfway up, whose
// box holds the vertical ray, stands between the rays of the 1, 8 and 9
// point grids (0.0113 from the nearest, its radius 0.01): it shadows
// nothing, but nothing can prove that without the rays. Without it, the
// way is clear.
std::uint64_t shadow_rays(int size, int adaptive, bool decoy = true) {
    sg::SceneGraph graph;
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, default_material()));
    if (decoy) graph.objects.push_back(sphere({0.008, 2.0, 0.008}, 0.01, default_material()));
    sg::Light light = point_light({0.0, 4.0, 0.0}, sg::Vec3(1.0));
    light.area_light = true;
    light.axis1 = {2.0, 0.0, 0.0};
    light.axis2 = {0.0, 0.0, 2.0};
    light.samples1 = light.samples2 = size;
    light.adaptive = adaptive;
    graph.lights.push_back(light);
    const auto scene = compile_scene(std::move(graph));
    CountingScene counted(*scene);
    const auto shadow = load_integrator("shadow", counted);
    const std::unique_ptr<Sampler> sampler = shadow->make_sampler(1);
    sampler->start_sample(0, 0, 0);
    shade_camera_ray(*shadow, kToOrigin, counted, *sampler);
    return counted.rays() - 1;  // less the camera ray
}

TEST(PovAreaLight, GridPointsTracedAsPovTracesThem) {
    EXPECT_EQ(shadow_rays(9, 100), 81u);
    EXPECT_EQ(shadow_rays(9, 0), 4u);
    EXPECT_EQ(shadow_rays(9, 1), 9u);
    EXPECT_EQ(shadow_rays(8, 1), 16u);
    EXPECT_EQ(shadow_rays(1, 100), 1u);
}

// RenderScene::may_block_towards: with nothing near the way, no grid point
// needs a ray.
TEST(PovAreaLight, AClearWayTracesNoShadowRay) {
    EXPECT_EQ(shadow_rays(9, 100, false), 0u);
    EXPECT_EQ(shadow_rays(1, 100, false), 0u);
}

TEST(PovAreaLight, NoRayEverSeesIt) {
    sg::SceneGraph graph;
    sg::Light light = line_light(5.0);
    light.axis2 = {0.0, 0.0, 4.0};
    light.samples2 = 5;
    graph.lights.push_back(light);
    const auto scene = compile_scene(std::move(graph));
    const Ray up = ray_towards(Vec3(0.0f, 0.0f, 0.0f), Vec3(0.0f, 4.0f, 0.0f));
    for (const char* integrator : {"whitted", "path"}) {
        const auto shader = load_integrator(integrator, *scene);
        const Color seen = mean_radiance(*shader, *scene, up, 16);
        EXPECT_EQ(seen, Color(0.0f)) << integrator;
    }
}

// `path` estimates the visible fraction of the rectangle without bias: a
// shelf above the floor hides the light's points x < -0.4 from the origin
// (the ray to x meets the shelf's height 2 at x / 2), which is 40 % of it.
TEST(PovAreaLight, PathSeesTheVisibleFractionOfTheRectangle) {
    sg::SceneGraph open;
    open.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, default_material()));
    open.lights.push_back(line_light(1.0));
    sg::SceneGraph shelved = open;
    shelved.objects.push_back(box({-10.0, 1.95, -1.0}, {-0.2, 2.05, 1.0}, default_material()));
    const auto open_scene = compile_scene(open), shelved_scene = compile_scene(shelved);
    const std::map<std::string, std::string> direct_only{{"max_depth", "1"}};
    const auto open_path = load_integrator("path", *open_scene, direct_only);
    const auto shelved_path = load_integrator("path", *shelved_scene, direct_only);
    constexpr int kSamples = 4096;
    const double lit = mean_radiance(*open_path, *open_scene, kToOrigin, kSamples).g;
    const double shaded = mean_radiance(*shelved_path, *shelved_scene, kToOrigin, kSamples).g;
    ASSERT_GT(lit, 0.0);
    // A Bernoulli fraction of 0.6 over 4096 samples: standard error 0.0077.
    EXPECT_NEAR(shaded / lit, 0.6, 0.03);
}

TEST(PovAreaLightGrid, CircularGridLiesOnTheEllipseAndOrientFacesTheLight) {
    PovAreaLightParameters light;
    light.axis1 = Vec3(2.0f, 0.0f, 0.0f);
    light.axis2 = Vec3(0.0f, 0.0f, 2.0f);
    light.size1 = light.size2 = 5;
    light.circular = true;
    const AreaGridAxes axes = area_grid_axes(light, glm::dvec3(0.0, -1.0, 0.0));
    // The square's corners and edge midpoints land on the circle of radius 1.
    for (const auto& [u, v] : {std::pair{0, 0}, {4, 4}, {0, 4}, {2, 0}, {4, 2}})
        EXPECT_NEAR(glm::length(area_grid_offset(light, axes, u, v)), 1.0, 0.003) << u << "," << v;
    EXPECT_LT(glm::length(area_grid_offset(light, axes, 2, 2)), 0.003);
    light.orient = true;
    const glm::dvec3 to_light = glm::normalize(glm::dvec3(1.0, 2.0, -0.5));
    const AreaGridAxes turned = area_grid_axes(light, to_light);
    EXPECT_NEAR(glm::dot(turned.axis1, to_light), 0.0, 1e-12);
    EXPECT_NEAR(glm::dot(turned.axis2, to_light), 0.0, 1e-12);
    EXPECT_NEAR(glm::length(turned.axis1), 2.0, 1e-12);
    EXPECT_NEAR(glm::length(turned.axis2), 2.0, 1e-12);
}

}  // namespace
}  // namespace lancer
