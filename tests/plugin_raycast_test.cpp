// The raycast integrator against answers known in closed form, and the
// host's determinism with it.
//
// Wall test: a white matte wall (diffuse 1, no ambient) in the plane z = d,
// a point light of colour 1 at the camera's position. A point light of
// colour C has intensity pi*C (light.h), so the wall point p at distance r,
// seen at angle theta from the wall's normal, has radiance
//     L = (1/pi) * cos(theta) * pi / r^2 = cos(theta)^3 / d^2,
// since r = d / cos(theta). The inverse-square law is checked to 3%.
#include <cmath>
#include <cstring>
#include <memory>

#include <gtest/gtest.h>

#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/scene_graph.h"

namespace lancer::test {
namespace {

sg::MaterialRef matte_white() {
    auto material = std::make_shared<sg::Material>();
    material->pigment.kind = sg::Pigment::Kind::Solid;
    material->pigment.color.rgb = sg::Vec3(1.0);
    material->finish->diffuse = 1.0;
    material->finish->ambient = sg::Vec3(0.0);
    return material;
}

// Camera at the origin looking down +z with a 90 degree horizontal field,
// square image; a point light at the camera; a wall at z = distance.
sg::SceneGraph wall_scene(double distance) {
    sg::SceneGraph graph;
    sg::Camera camera;
    camera.location = sg::Vec3(0.0);
    camera.direction = sg::Vec3(0.0, 0.0, 0.5);
    camera.right = sg::Vec3(1.0, 0.0, 0.0);
    camera.up = sg::Vec3(0.0, 1.0, 0.0);
    graph.camera = camera;

    sg::Light light;
    light.kind = sg::Light::Kind::Point;
    light.position = sg::Vec3(0.0);
    light.color = sg::Vec3(1.0);
    graph.lights.push_back(light);

    sg::Object wall;
    wall.kind = sg::Object::Kind::Plane;
    wall.shape = sg::Plane{sg::Vec3(0.0, 0.0, 1.0), distance};
    wall.material = matte_white();
    graph.objects.push_back(wall);
    graph.global.ambient_light = sg::Vec3(0.0);
    return graph;
}

struct RaycastFixture {
    Plugin plugin = load_plugin("raycast");
    std::unique_ptr<Integrator> integrator = plugin.descriptor->create(resolve_parameters(*plugin.descriptor, {}, {}));
};

Film render(const sg::SceneGraph& graph, const Integrator& integrator, int size, int threads, int spp = 1) {
    const auto scene = compile_scene(graph);
    RenderOptions options;
    options.width = size;
    options.height = size;
    options.samples_per_pixel = spp;
    options.threads = threads;
    options.progress = ProgressMode::Quiet;
    Film film(size, size);
    render_image(*scene, integrator, options, film);
    return film;
}

// The wall's pixel (x, y) seen under a light at the camera: cos of the
// angle between the wall's normal (the view axis) and the pixel centre's
// direction; direction (0,0,0.5), right and up of length 1.
double pixel_cosine(int x, int y, int size) {
    const double sx = (x + 0.5) / size - 0.5;
    const double sy = 0.5 - (y + 0.5) / size;
    return 0.5 / std::sqrt(0.25 + sx * sx + sy * sy);
}

// POV-Ray's law (reference/pov-3.7-semantics.md section 5): a point light
// does not fall off, so a white matte wall shows diffuse * cos, whatever
// its distance.
TEST(RaycastIntegrator, MatteWallUnderAPovPointLightFollowsPovsLaw) {
    RaycastFixture raycast;
    // Odd, so the centre pixel looks straight at the wall; fine enough that
    // the cosine varies by well under 3% across one pixel even at the corners.
    constexpr int kSize = 101;
    for (const double distance : {1.0, 2.0, 4.0, 8.0, 1000.0}) {
        const Film film = render(wall_scene(distance), *raycast.integrator, kSize, 2);
        for (const auto& [x, y] : {std::pair{50, 50}, {75, 50}, {50, 15}, {90, 90}, {10, 35}}) {
            const double expected = pixel_cosine(x, y, kSize);
            const Color measured = film.mean(x, y);
            EXPECT_NEAR(measured.g, expected, 0.03 * expected) << "d=" << distance << " pixel " << x << "," << y;
            EXPECT_FLOAT_EQ(measured.r, measured.g);
            EXPECT_FLOAT_EQ(measured.b, measured.g);
        }
    }
}

// A physical point lamp (a sphere lamp of radius 0) follows the inverse-
// square law instead: cos / d'^2 with d' = d / cos, so cos^3 / d^2.
TEST(RaycastIntegrator, MatteWallUnderAPhysicalPointLampFollowsTheInverseSquareLaw) {
    RaycastFixture raycast;
    constexpr int kSize = 101;
    for (const double distance : {1.0, 2.0, 4.0, 8.0}) {
        sg::SceneGraph graph = wall_scene(distance);
        graph.lights[0].kind = sg::Light::Kind::AreaSphere;
        graph.lights[0].radius = 0.0;
        const Film film = render(graph, *raycast.integrator, kSize, 2);
        for (const auto& [x, y] : {std::pair{50, 50}, {75, 50}, {50, 15}, {90, 90}, {10, 35}}) {
            const double expected = std::pow(pixel_cosine(x, y, kSize), 3) / (distance * distance);
            const Color measured = film.mean(x, y);
            EXPECT_NEAR(measured.g, expected, 0.03 * expected) << "d=" << distance << " pixel " << x << "," << y;
            EXPECT_FLOAT_EQ(measured.r, measured.g);
            EXPECT_FLOAT_EQ(measured.b, measured.g);
        }
    }
}

TEST(RaycastIntegrator, AmbientAndEmissionAreAdded) {
    RaycastFixture raycast;
    sg::SceneGraph graph = wall_scene(2.0);
    graph.lights.clear();
    auto material = std::make_shared<sg::Material>(*matte_white());
    material->pigment.color.rgb = sg::Vec3(0.5, 0.25, 1.0);
    material->finish->ambient = sg::Vec3(0.2);
    material->finish->emission = sg::Vec3(0.1);
    graph.objects[0].material = material;
    graph.global.ambient_light = sg::Vec3(1.0);
    const Film film = render(graph, *raycast.integrator, 5, 1);
    // ambient * pigment * ambient_light + emission * pigment = 0.3 * pigment.
    const Color centre = film.mean(2, 2);
    EXPECT_NEAR(centre.r, 0.15f, 1e-4f);
    EXPECT_NEAR(centre.g, 0.075f, 1e-4f);
    EXPECT_NEAR(centre.b, 0.3f, 1e-4f);
}

TEST(RaycastIntegrator, MissReturnsTheBackground) {
    RaycastFixture raycast;
    sg::SceneGraph graph = wall_scene(2.0);
    graph.objects.clear();
    graph.background = sg::Vec3(0.25, 0.5, 0.75);
    const Film film = render(graph, *raycast.integrator, 3, 1);
    EXPECT_NEAR(film.mean(1, 1).r, 0.25f, 1e-6f);
    EXPECT_NEAR(film.mean(1, 1).b, 0.75f, 1e-6f);
}

sg::SceneGraph busy_scene() {
    sg::SceneGraph graph = wall_scene(6.0);
    graph.camera->direction = sg::Vec3(0.0, 0.0, 1.0);
    for (int i = 0; i < 5; ++i) {
        sg::Object ball;
        ball.kind = sg::Object::Kind::Sphere;
        ball.shape = sg::Sphere{sg::Vec3(-2.0 + i, 0.3 * i - 0.6, 4.0), 0.45};
        auto material = std::make_shared<sg::Material>(*matte_white());
        material->pigment.color.rgb = sg::Vec3(0.2 * i, 0.5, 1.0 - 0.2 * i);
        material->finish->phong = 0.5;
        material->finish->ambient = sg::Vec3(0.05);
        ball.material = material;
        graph.objects.push_back(ball);
    }
    sg::Light second;
    second.position = sg::Vec3(3.0, 4.0, 1.0);
    second.color = sg::Vec3(0.8, 0.7, 0.5);
    graph.lights.push_back(second);
    return graph;
}

TEST(RaycastIntegrator, OneAndTwoThreadsGiveTheSameImageBitForBit) {
    RaycastFixture raycast;
    const sg::SceneGraph graph = busy_scene();
    const Film one = render(graph, *raycast.integrator, 64, 1);
    const Film two = render(graph, *raycast.integrator, 64, 2);
    int differing = 0;
    for (int y = 0; y < 64; ++y) {
        for (int x = 0; x < 64; ++x) {
            const Color a = one.mean(x, y);
            const Color b = two.mean(x, y);
            differing += std::memcmp(&a, &b, sizeof a) != 0;
        }
    }
    EXPECT_EQ(differing, 0);
}

// raycast itself draws no random numbers; this wrapper does, so jittered
// camera rays and the per-sample sampler streams are covered by the same
// bit-exact check.
class JitteredRaycast final : public Integrator {
  public:
    explicit JitteredRaycast(const Integrator& raycast) : m_raycast(raycast) {}
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene, Sampler& sampler) const override {
        return m_raycast.shade_camera_hit(ray, hit, scene, sampler) * (0.5f + sampler.next_1d());
    }

  private:
    const Integrator& m_raycast;
};

TEST(RaycastIntegrator, JitteredSamplesAreBitExactAcrossThreadCounts) {
    RaycastFixture raycast;
    const JitteredRaycast jittered(*raycast.integrator);
    const sg::SceneGraph graph = busy_scene();
    const Film one = render(graph, jittered, 48, 1, 8);
    const Film two = render(graph, jittered, 48, 2, 8);
    int differing = 0;
    for (int y = 0; y < 48; ++y) {
        for (int x = 0; x < 48; ++x) {
            const Color a = one.mean(x, y);
            const Color b = two.mean(x, y);
            differing += std::memcmp(&a, &b, sizeof a) != 0;
            EXPECT_EQ(one.sample_count(x, y), 8u);
        }
    }
    EXPECT_EQ(differing, 0);
}

TEST(RaycastIntegrator, AovsSeeTheSameSurface) {
    sg::SceneGraph graph = wall_scene(3.0);
    const auto create = [](const char* name, std::vector<std::string> cli = {}) {
        Plugin plugin = load_plugin(name);
        auto integrator = plugin.descriptor->create(resolve_parameters(*plugin.descriptor, {}, cli));
        return std::pair{std::move(plugin), std::move(integrator)};
    };
    const auto [normal_plugin, normal] = create("normal");
    const auto [albedo_plugin, albedo] = create("albedo");
    const auto [depth_plugin, depth] = create("depth");
    const auto [scaled_plugin, scaled_depth] = create("depth", {"max_distance=6"});
    // Centre pixel: the wall faces the camera along -z, albedo = pigment x diffuse = 1,
    // distance 3 (half of max_distance 6).
    const Color n = render(graph, *normal, 5, 1).mean(2, 2);
    EXPECT_NEAR(n.b, 0.0f, 0.02f);
    EXPECT_NEAR(n.r, 0.5f, 0.02f);
    EXPECT_NEAR(render(graph, *albedo, 5, 1).mean(2, 2).g, 1.0f, 1e-5f);
    EXPECT_NEAR(render(graph, *depth, 5, 1).mean(2, 2).g, 3.0f, 0.15f);
    EXPECT_NEAR(render(graph, *scaled_depth, 5, 1).mean(2, 2).g, 0.5f, 0.025f);
}

// POV's light_group, on the lane-parallel path raycast takes for matte
// walls under plain point lights as on the general one: the wall in a
// group without lights and without global_lights is dark; with
// global_lights the scene's light reaches it; a light of its group lights
// it, and the same light in another group does not.
TEST(RaycastIntegrator, LightGroupsDecideWhichLightsReachAWall) {
    RaycastFixture raycast;
    const double lit = render(wall_scene(2.0), *raycast.integrator, 8, 1).mean(4, 4).r;
    ASSERT_GT(lit, 0.1);
    for (const bool global : {false, true}) {
        sg::SceneGraph graph = wall_scene(2.0);
        graph.light_groups.push_back(sg::LightGroup{global});
        graph.objects[0].light_group = 0;
        EXPECT_NEAR(render(graph, *raycast.integrator, 8, 1).mean(4, 4).r, global ? lit : 0.0, 1e-6) << global;
    }
    for (const int light_group : {0, 1}) {
        sg::SceneGraph graph = wall_scene(2.0);
        graph.light_groups = {sg::LightGroup{}, sg::LightGroup{}};
        graph.objects[0].light_group = 0;
        graph.lights[0].light_group = light_group;
        EXPECT_NEAR(render(graph, *raycast.integrator, 8, 1).mean(4, 4).r, light_group == 0 ? lit : 0.0, 1e-6)
            << light_group;
    }
}

}  // namespace
}  // namespace lancer::test
