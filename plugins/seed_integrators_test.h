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

#include "image_compare.h"
#include "lancer/film.h"
#include "lancer/image_io.h"
#include "lancer/parser.h"
#include "lancer/integrator.h"
#include "lancer/plugin_host.h"
#include "lancer/render_scene.h"
#include "lancer/renderer.h"
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
        m.finish.ambient = sg::Vec3(1.0);
        m.finish.diffuse = 0.0;
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
inline Color mean_radiance(const Integrator& integrator, const RenderScene& scene, const Ray& ray,
                           int samples = 1, std::uint64_t seed = 7) {
    const std::unique_ptr<Sampler> sampler = integrator.make_sampler(seed);
    Color sum(0.0f);
    for (int i = 0; i < samples; ++i) {
        sampler->start_sample(0, 0, std::uint32_t(i));
        sum += integrator.radiance(ray, scene, *sampler);
    }
    return sum / float(samples);
}

inline Ray ray_towards(const Vec3& origin, const Vec3& target) {
    Ray ray;
    ray.origin = origin;
    ray.direction = glm::normalize(target - origin);
    return ray;
}

inline Film render_small(const RenderScene& scene, const Integrator& integrator, int width, int height,
                         int samples = 1, int threads = 1) {
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

// A scene of the corpus (scenes/NAME.pov), parsed for a width x height image.
inline sg::SceneGraph corpus_scene(const std::string& name, int width, int height) {
    ParseOptions options;
    options.image_width = width;
    options.image_height = height;
    options.image_size_from_command_line = true;
    const ParseResult parsed = parse_scene_file(std::string(LANCER_SOURCE_DIR) + "/scenes/" + name + ".pov", options);
    if (!parsed.ok()) {
        std::string message;
        for (const Diagnostic& d : parsed.diagnostics) message += format_diagnostic(d) + "\n";
        throw std::runtime_error(message);
    }
    return *parsed.scene;
}

// The film as an image for tests/image_compare.h, each channel mapped by
// v / (1 + v): bright lamps stay comparable with the same thresholds as the
// rest, and the golden's half-float rounding stays under them.
inline testing::Image to_compressed_image(const Film& film) {
    testing::Image image;
    image.width = film.width();
    image.height = film.height();
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Color c = film.mean(x, y);
            image.rgb.insert(image.rgb.end(), {c.r / (1.0f + c.r), c.g / (1.0f + c.g), c.b / (1.0f + c.b)});
        }
    return image;
}

// Golden-image regression: renders scenes/SCENE.pov small with the
// integrator and compares it with plugins/INTEGRATOR/golden/SCENE.exr
// (linear). LANCER_UPDATE_GOLDEN=1 rewrites the golden instead; a golden is
// a claim about the right answer, so say in the commit how the new one was
// checked. On failure, render | golden | difference is written beside the
// build for inspection.
inline void expect_matches_golden(const std::string& integrator, const std::string& scene_name,
                                  const std::map<std::string, std::string>& parameters, int width, int height,
                                  int samples = 1) {
    const auto scene = RenderScene::compile(corpus_scene(scene_name, width, height));
    const auto loaded = load_integrator(integrator, *scene, parameters);
    const Film film = render_small(*scene, *loaded, width, height, samples);
    const std::string golden = std::string(LANCER_SOURCE_DIR) + "/plugins/" + integrator + "/golden/" + scene_name + ".exr";
    if (const char* update = std::getenv("LANCER_UPDATE_GOLDEN"); update != nullptr && std::string(update) == "1") {
        write_image(film, golden);
        return;
    }
    // EXR goldens may be half floats (3 significant digits): the thresholds
    // allow that rounding and a few pixels flipped along silhouettes by
    // floating-point changes in the core, nothing more.
    testing::Image expected = testing::load_image(golden);
    for (float& v : expected.rgb) v = v / (1.0f + v);
    std::string message;
    const bool same = testing::images_match(to_compressed_image(film), expected, 1e-3, 0.01,
                                            long(width) * height / 100,
                                            std::string(LANCER_BINARY_DIR) + "/golden_failure_" + integrator + "_" + scene_name,
                                            &message);
    EXPECT_TRUE(same) << integrator << " on " << scene_name << ": " << message;
}

}  // namespace lancer::seed_test
