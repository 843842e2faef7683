// raycast's batch shading (shade_camera_hits in raycast.cpp, lane by lane
// through DiffusePointLanes) changes nothing in the image: at one sample
// per pixel and with several, where the host jitters camera rays with the
// sampler's values, the film is bit for bit the one shade_camera_hit() hit
// by hit (the SDK's default batch) gives.
#include <memory>

#include <gtest/gtest.h>

#include "diffuse_point_lanes.h"
#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/scene_graph.h"

namespace lancer::test {
namespace {

// raycast's shading hit by hit, through the SDK's default batch.
class HitByHit final : public Integrator {
  public:
    explicit HitByHit(const Integrator& inner) : m_inner(inner) {}
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene, Sampler& sampler) const override {
        return m_inner.shade_camera_hit(ray, hit, scene, sampler);
    }
    bool is_deterministic() const override { return m_inner.is_deterministic(); }

  private:
    const Integrator& m_inner;
};

sg::SceneGraph sphere_scene() {
    sg::SceneGraph graph;
    sg::Camera camera;
    camera.location = sg::Vec3(0.0, 0.0, -3.0);
    camera.direction = sg::Vec3(0.0, 0.0, 1.0);
    camera.right = sg::Vec3(1.0, 0.0, 0.0);
    camera.up = sg::Vec3(0.0, 1.0, 0.0);
    graph.camera = camera;
    sg::Light light;
    light.position = sg::Vec3(2.0, 3.0, -4.0);
    graph.lights.push_back(light);
    sg::Object sphere;
    sphere.kind = sg::Object::Kind::Sphere;
    sphere.shape = sg::Sphere{sg::Vec3(0.0), 1.0};
    auto material = std::make_shared<sg::Material>();
    material->pigment.color.rgb = sg::Vec3(0.9, 0.5, 0.2);
    sphere.material = material;
    graph.objects.push_back(sphere);
    // Hits the lane-parallel path does not take, among those it does: a
    // highlight, a checker pigment; and a second, coloured light.
    sg::Light second;
    second.position = sg::Vec3(-3.0, 1.0, -2.0);
    second.color = sg::Vec3(0.3, 0.6, 1.0);
    graph.lights.push_back(second);
    sg::Object shiny = sphere;
    shiny.shape = sg::Sphere{sg::Vec3(1.2, 0.8, 0.5), 0.5};
    auto shiny_material = std::make_shared<sg::Material>(*material);
    shiny_material->finish->phong = 0.7;
    shiny.material = shiny_material;
    graph.objects.push_back(shiny);
    sg::Object checkered = sphere;
    checkered.shape = sg::Sphere{sg::Vec3(-1.2, -0.8, 0.5), 0.5};
    auto checker_material = std::make_shared<sg::Material>(*material);
    checker_material->pigment = sg::checker_pigment({1, 1, 1}, {0, 1, 0});
    checkered.material = checker_material;
    graph.objects.push_back(checkered);
    return graph;
}

TEST(RaycastBatch, ImageIsHitByHitShadingsBitForBit) {
    Plugin plugin = load_plugin("raycast");
    const auto raycast = plugin.descriptor->create(resolve_parameters(*plugin.descriptor, {}, {}));
    const HitByHit reference(*raycast);
    const auto scene = compile_scene(sphere_scene());
    for (const std::uint32_t samples : {1u, 4u}) {
        SCOPED_TRACE(samples);
        RenderOptions options;
        options.width = 24;
        options.height = 24;
        options.samples_per_pixel = samples;
        options.threads = 2;
        options.progress = ProgressMode::Quiet;
        Film batch(24, 24), plain(24, 24);
        render_image(*scene, *raycast, options, batch);
        render_image(*scene, reference, options, plain);
        int lit_pixels = 0, edge_pixels = 0;  // antialiased: the jitter did reach the image
        for (int y = 0; y < 24; ++y)
            for (int x = 0; x < 24; ++x) {
                const Color a = batch.mean(x, y), b = plain.mean(x, y);
                EXPECT_EQ(a.r, b.r) << x << "," << y;
                EXPECT_EQ(a.g, b.g) << x << "," << y;
                EXPECT_EQ(a.b, b.b) << x << "," << y;
                if (a.r > 0.0f) ++lit_pixels;
                if (a.r > 0.0f && batch.variance_of_mean(x, y).r > 0.0f) ++edge_pixels;
            }
        EXPECT_GT(lit_pixels, 50);
        if (samples > 1) {
            EXPECT_GT(edge_pixels, 0);
        }
    }
}

// The lanes take a scene whose lights are all plain point lights (read
// through Light::parameters), and no other: a fade or an area light sends
// every hit the general way.
TEST(RaycastBatch, LanesTakeOnlyPlainPointLights) {
    const sg::SceneGraph plain = sphere_scene();
    EXPECT_TRUE(DiffusePointLanes(compile_scene(plain)->lights(), Color(1.0f), true).usable());
    sg::SceneGraph faded = sphere_scene();
    faded.lights[1].fade_distance = 2.0;
    faded.lights[1].fade_power = 2.0;
    EXPECT_FALSE(DiffusePointLanes(compile_scene(faded)->lights(), Color(1.0f), true).usable());
    sg::SceneGraph area = sphere_scene();
    area.lights[1].kind = sg::Light::Kind::AreaSphere;
    area.lights[1].radius = 0.2;
    EXPECT_FALSE(DiffusePointLanes(compile_scene(area)->lights(), Color(1.0f), true).usable());
}

}  // namespace
}  // namespace lancer::test
