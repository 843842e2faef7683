// The reference path tracer on the Cornell box (scenes/cornell_box.pov,
// built here in C++ so the bench needs no parser) at 256x256 on 2 threads:
// throughput in camera samples (paths) per second, for the independent and
// the Sobol sampler. The time to reach a given RMSE is measured, by
// rendering, in cycles_compare.cpp (against Blender Cycles).
//
//     build/bin/lancer_bench --benchmark_filter=PathCornellThroughput
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>

#include <glm/gtc/matrix_transform.hpp>

#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/scene_graph.h"

namespace {

using namespace lancer;

constexpr int kSize = 256;
constexpr int kThreads = 2;

sg::MaterialRef matte(sg::Vec3 rgb) {
    auto m = std::make_shared<sg::Material>();
    m->pigment.color.rgb = rgb;
    m->finish->ambient = sg::Vec3(0.0);
    m->finish->diffuse = 1.0;
    return m;
}

sg::Object plane(sg::Vec3 normal, double distance, sg::MaterialRef m) {
    sg::Object o;
    o.kind = sg::Object::Kind::Plane;
    o.shape = sg::Plane{normal, distance};
    o.material = std::move(m);
    return o;
}

sg::Object box(sg::Vec3 lower, sg::Vec3 upper, double rotate_y_degrees, sg::Vec3 offset, sg::MaterialRef m) {
    sg::Object o;
    o.kind = sg::Object::Kind::Box;
    o.shape = sg::Box{lower, upper};
    // Rotate about +y, then translate (the box's orientation approximates
    // the .pov scene's; the bench only needs a fixed scene).
    const sg::Mat4 rotation = glm::rotate(sg::Mat4(1.0), glm::radians(-rotate_y_degrees), sg::Vec3(0, 1, 0));
    o.parent_from_object = glm::translate(sg::Mat4(1.0), offset) * rotation;
    o.material = std::move(m);
    return o;
}

// scenes/cornell_box.pov.
sg::SceneGraph cornell_box() {
    sg::SceneGraph g;
    sg::Camera camera;
    camera.location = sg::Vec3(0.0, 1.0, -3.4);
    camera.right = sg::Vec3(1.0, 0.0, 0.0);
    camera.up = sg::Vec3(0.0, 1.0, 0.0);
    camera.direction = sg::Vec3(0.0, 0.0, 0.5 / std::tan(glm::radians(20.0)));  // angle 40
    g.camera = camera;
    const auto white = matte(sg::Vec3(0.73));
    g.objects.push_back(plane(sg::Vec3(0, 1, 0), 0.0, white));
    g.objects.push_back(plane(sg::Vec3(0, 1, 0), 2.0, white));
    g.objects.push_back(plane(sg::Vec3(0, 0, 1), 1.0, white));
    g.objects.push_back(plane(sg::Vec3(1, 0, 0), -1.0, matte(sg::Vec3(0.63, 0.065, 0.05))));
    g.objects.push_back(plane(sg::Vec3(1, 0, 0), 1.0, matte(sg::Vec3(0.14, 0.45, 0.091))));
    g.objects.push_back(box(sg::Vec3(-0.3, 0, -0.3), sg::Vec3(0.3, 1.2, 0.3), 20.0, sg::Vec3(-0.35, 0, 0.35), white));
    g.objects.push_back(box(sg::Vec3(-0.3, 0, -0.3), sg::Vec3(0.3, 0.6, 0.3), -18.0, sg::Vec3(0.35, 0, -0.3), white));
    sg::Light light;
    light.kind = sg::Light::Kind::AreaRectangle;
    light.position = sg::Vec3(0.0, 1.98, 0.0);
    light.color = sg::Vec3(1.0, 0.85, 0.6) * 4.0;
    light.axis1 = sg::Vec3(0.5, 0, 0);
    light.axis2 = sg::Vec3(0, 0, 0.5);
    g.lights.push_back(light);
    g.global.ambient_light = sg::Vec3(0.0);
    return g;
}

struct Setup {
    Plugin plugin = load_plugin("path");
    std::unique_ptr<RenderScene> scene = compile_scene(cornell_box());

    std::unique_ptr<Integrator> integrator(const std::string& sampler) const {
        auto i = plugin.descriptor->create(
            resolve_parameters(*plugin.descriptor, {}, {"max_depth=8", "sampler=" + sampler}));
        i->prepare(*scene);
        return i;
    }
    Film render(const Integrator& integrator, int spp, std::uint64_t seed, RenderStats* stats = nullptr) const {
        RenderOptions options;
        options.width = options.height = kSize;
        options.samples_per_pixel = spp;
        options.seed = seed;
        options.threads = kThreads;
        options.progress = ProgressMode::Quiet;
        Film film(kSize, kSize);
        const RenderStats s = render_image(*scene, integrator, options, film);
        if (stats) *stats = s;
        return film;
    }
};

Setup& setup() {
    static Setup s;
    return s;
}

// Paths per second at 4 samples per pixel.
void BM_PathCornellThroughput(benchmark::State& state, const char* sampler) {
    const auto integrator = setup().integrator(sampler);
    std::uint64_t samples = 0;
    std::uint64_t seed = 0;
    for (auto _ : state) {
        RenderStats stats;
        setup().render(*integrator, 4, seed++, &stats);
        samples += stats.samples;
    }
    state.counters["samples_per_second"] = benchmark::Counter(double(samples), benchmark::Counter::kIsRate);
}
BENCHMARK_CAPTURE(BM_PathCornellThroughput, independent, "independent")->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK_CAPTURE(BM_PathCornellThroughput, sobol, "sobol")->Unit(benchmark::kMillisecond)->UseRealTime();

}  // namespace
