// Helpers for the shadow, whitted and gather tests: small scene graphs
// written in C++, the built plugins loaded through the plugin host, and a
// radiance query for one ray. Test-only; not installed.
#pragma once

#include <cstdlib>
#include <map>
#include <memory>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "lancer/host/camera_ray.h"
#include "lancer/host/film.h"
#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/integrator.h"
#include "lancer/render_scene.h"
#include "lancer/scene_graph.h"

namespace lancer::seed_test {

// A material built from the POV defaults (ambient 0.1, diffuse 0.6), white,
// with `configure` changing what the test needs.
template <class Configure>
sg::MaterialRef material(Configure configure) {
    auto m = std::make_shared<sg::Material>();
    m->pigment.color.rgb = sg::Vec3(1.0);
    configure(*m);
    return m;
}
inline sg::MaterialRef default_material() {
    return material([](sg::Material&) {});
}
// A surface whose radiance is exactly `rgb` under ambient_light 1: no
// diffuse, ambient 1. A "uniformly coloured" backdrop.
inline sg::MaterialRef flat_colour(const sg::Vec3& rgb) {
    return material([&](sg::Material& m) {
        m.pigment.color.rgb = rgb;
        m.finish->ambient = sg::Vec3(1.0);
        m.finish->diffuse = 0.0;
    });
}

inline sg::Object sphere(const sg::Vec3& center, double radius, sg::MaterialRef m) {
    sg::Object object;
    object.kind = sg::Object::Kind::Sphere;
    object.shape = sg::Sphere{center, radius};
    object.material = std::move(m);
    return object;
}
inline sg::Object plane(const sg::Vec3& normal, double distance, sg::MaterialRef m) {
    sg::Object object;
    object.kind = sg::Object::Kind::Plane;
    object.shape = sg::Plane{normal, distance};
    object.material = std::move(m);
    return object;
}
inline sg::Object box(const sg::Vec3& corner1, const sg::Vec3& corner2, sg::MaterialRef m) {
    sg::Object object;
    object.kind = sg::Object::Kind::Box;
    object.shape = sg::Box{corner1, corner2};
    object.material = std::move(m);
    return object;
}
inline sg::Light point_light(const sg::Vec3& position, const sg::Vec3& color) {
    sg::Light light;
    light.kind = sg::Light::Kind::Point;
    light.position = position;
    light.color = color;
    return light;
}
// A rectangle of side `size` centred at `center`, horizontal (faces ±y).
inline sg::Light square_light(const sg::Vec3& center, double size, const sg::Vec3& color) {
    sg::Light light;
    light.kind = sg::Light::Kind::AreaRectangle;
    light.position = center;
    light.axis1 = sg::Vec3(size, 0.0, 0.0);
    light.axis2 = sg::Vec3(0.0, 0.0, size);
    light.color = color;
    return light;
}

// A plugin with one integrator made from it, prepared for `scene`. The
// integrator is declared after the plugin so it is destroyed first, while
// its code is still loaded.
struct LoadedIntegrator {
    Plugin plugin;
    std::unique_ptr<Integrator> integrator;

    Integrator& operator*() const { return *integrator; }
    Integrator* operator->() const { return integrator.get(); }
};

inline LoadedIntegrator load_integrator(const std::string& name, const RenderScene& scene,
                                        const std::map<std::string, std::string>& parameters = {}) {
    LoadedIntegrator loaded;
    loaded.plugin = load_plugin(name);
    std::vector<std::string> assignments;
    for (const auto& [key, value] : parameters) assignments.push_back(key + "=" + value);
    const ParameterSet resolved = resolve_parameters(*loaded.plugin.descriptor, {}, assignments);
    loaded.integrator = loaded.plugin.descriptor->create(resolved);
    loaded.integrator->prepare(scene);
    return loaded;
}

// Mean radiance along `ray` over `samples` sampler streams (pixel (0,0)).
inline Color mean_radiance(const Integrator& integrator, const RenderScene& scene, const Ray& ray, int samples = 1,
                           std::uint64_t seed = 7) {
    const std::unique_ptr<Sampler> sampler = integrator.make_sampler(seed);
    Color sum(0.0f);
    for (int i = 0; i < samples; ++i) {
        sampler->start_sample(0, 0, std::uint32_t(i));
        sum += shade_camera_ray(integrator, ray, scene, *sampler);
    }
    return sum / float(samples);
}

inline Ray ray_towards(const Vec3& origin, const Vec3& target) {
    Ray ray;
    ray.origin = origin;
    ray.direction = glm::normalize(target - origin);
    return ray;
}

inline Film render_small(const RenderScene& scene, const Integrator& integrator, int width, int height, int samples = 1,
                         int threads = 1) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.samples_per_pixel = samples;
    options.threads = threads;
    options.tile_size = 4;  // several tiles even on tiny images, so threads interleave
    options.progress = ProgressMode::Quiet;
    Film film(width, height);
    render_image(scene, integrator, options, film);
    return film;
}

// A camera looking from `location` along `direction` with 4:3 framing.
inline sg::Camera camera(const sg::Vec3& location, const sg::Vec3& direction) {
    sg::Camera c;
    c.location = location;
    c.direction = direction;
    c.right = sg::Vec3(1.33, 0.0, 0.0);
    c.up = sg::Vec3(0.0, 1.0, 0.0);
    return c;
}

// Golden images over scenes/ live in tests/golden/ (tests/golden_image_test.cpp).

}  // namespace lancer::seed_test
