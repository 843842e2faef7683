// Physical-consistency tests of the reference path tracer: scenes with
// answers known in closed form, agreement between estimators that must
// converge to the same image, and the convergence rate.
//
// Units (light.h): a point light of colour C has intensity pi*C; a sphere
// light of colour C and radius r has radiance C/r^2, so both emit 4 pi^2 C.
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lancer/host/camera_ray.h"
#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"
#include "lancer/scene_graph.h"
#include "stat_compare.h"

namespace lancer::test {
namespace {

sg::MaterialRef make_material(double diffuse, double emission, sg::Vec3 pigment = sg::Vec3(1.0)) {
    auto m = std::make_shared<sg::Material>();
    m->pigment.color.rgb = pigment;
    m->finish->diffuse = diffuse;
    m->finish->emission = sg::Vec3(emission);
    m->finish->ambient = sg::Vec3(0.0);
    return m;
}

sg::Object sphere(sg::Vec3 center, double radius, sg::MaterialRef material) {
    sg::Object o;
    o.kind = sg::Object::Kind::Sphere;
    o.shape = sg::Sphere{center, radius};
    o.material = std::move(material);
    return o;
}

sg::Object plane(sg::Vec3 normal, double distance, sg::MaterialRef material) {
    sg::Object o;
    o.kind = sg::Object::Kind::Plane;
    o.shape = sg::Plane{normal, distance};
    o.material = std::move(material);
    return o;
}

sg::Camera camera_at(sg::Vec3 location, sg::Vec3 look_at, double zoom = 1.0) {
    sg::Camera c;
    c.location = location;
    const sg::Vec3 forward = glm::normalize(look_at - location);
    const sg::Vec3 right = glm::normalize(glm::cross(sg::Vec3(0.0, 1.0, 0.0), forward));
    c.direction = forward * zoom;
    c.right = right;
    c.up = glm::cross(forward, right);
    return c;
}

std::unique_ptr<Integrator> make_integrator(const Plugin& plugin, std::vector<std::string> parameters = {}) {
    return plugin.descriptor->create(resolve_parameters(*plugin.descriptor, {}, parameters));
}

Film render(const sg::SceneGraph& graph, Integrator& integrator, int width, int height, int spp,
            std::uint64_t seed = 0) {
    const auto scene = compile_scene(graph);
    integrator.prepare(*scene);
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.samples_per_pixel = spp;
    options.seed = seed;
    options.threads = 2;
    options.progress = ProgressMode::Quiet;
    Film film(width, height);
    render_image(*scene, integrator, options, film);
    return film;
}

// Largest |pixel - expected| over the image, every channel.
double max_deviation(const Film& film, double expected) {
    double worst = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            for (int c = 0; c < 3; ++c) worst = std::max(worst, std::abs(film.mean(x, y)[c] - expected));
    return worst;
}

double image_mean(const Film& film) {
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) sum += luminance(film.mean(x, y));
    return sum / (film.width() * film.height());
}

struct PathFixture : ::testing::Test {
    Plugin path = load_plugin("path");
};

// Inside a closed sphere whose surface emits 0.5 and reflects half the light
// diffusely, radiance is L = 0.5 + 0.5 L everywhere: L = 1.
TEST_F(PathFixture, FurnaceEmittingEnclosure) {
    sg::SceneGraph graph;
    graph.camera = camera_at(sg::Vec3(0.0, 0.0, -0.3), sg::Vec3(0.2, 0.1, 1.0));
    graph.objects.push_back(sphere(sg::Vec3(0.0), 1.0, make_material(0.5, 0.5)));
    graph.global.ambient_light = sg::Vec3(0.0);
    auto integrator = make_integrator(path, {"max_depth=-1"});
    const Film film = render(graph, *integrator, 4, 4, 16384);
    const double mean = image_mean(film);
    RecordProperty("furnace_mean", std::to_string(mean));
    EXPECT_NEAR(mean, 1.0, 0.005);
    EXPECT_LT(max_deviation(film, 1.0), 0.02) << "image mean " << mean;
}

// pbrt's variant: a point light of intensity pi (colour 1) at the centre of
// a unit sphere of albedo 0.5: direct 0.5 and as much again from the
// furnace of interreflections, L = 1.
TEST_F(PathFixture, FurnacePointLightAtCentre) {
    sg::SceneGraph graph;
    graph.camera = camera_at(sg::Vec3(0.0, 0.0, -0.3), sg::Vec3(-0.1, 0.2, 1.0));
    graph.objects.push_back(sphere(sg::Vec3(0.0), 1.0, make_material(0.5, 0.0)));
    sg::Light light;
    light.kind = sg::Light::Kind::Point;
    light.position = sg::Vec3(0.0);
    light.color = sg::Vec3(1.0);
    graph.lights.push_back(light);
    graph.global.ambient_light = sg::Vec3(0.0);
    auto integrator = make_integrator(path, {"max_depth=-1"});
    const Film film = render(graph, *integrator, 4, 4, 16384);
    const double mean = image_mean(film);
    RecordProperty("point_furnace_mean", std::to_string(mean));
    EXPECT_NEAR(mean, 1.0, 0.005);
    EXPECT_LT(max_deviation(film, 1.0), 0.02) << "image mean " << mean;
}

// A white (albedo 1) diffuse ball inside a black enclosure emitting 1
// reflects exactly what surrounds it: the image is 1 everywhere, the ball
// disappears.
TEST_F(PathFixture, WhiteFurnaceHidesAnAlbedoOneObject) {
    sg::SceneGraph graph;
    graph.camera = camera_at(sg::Vec3(0.0, 0.0, -3.0), sg::Vec3(0.0));
    graph.objects.push_back(sphere(sg::Vec3(0.0), 10.0, make_material(0.0, 1.0)));
    graph.objects.push_back(sphere(sg::Vec3(0.0), 1.0, make_material(1.0, 0.0)));
    graph.global.ambient_light = sg::Vec3(0.0);
    auto integrator = make_integrator(path);
    const Film film = render(graph, *integrator, 6, 6, 4096);
    EXPECT_LT(max_deviation(film, 1.0), 0.02) << "image mean " << image_mean(film);
}

// Under a sky_sphere of constant radiance 0.7, an albedo-one diffuse ball
// reflects exactly the sky it sees: the whole image is 0.7. A ball that
// absorbs half is a disc of 0.35 in it (a convex object sees only sky).
TEST_F(PathFixture, ConstantSkyIsAnEnvironmentLight) {
    for (const double albedo : {1.0, 0.5}) {
        sg::SceneGraph graph;
        graph.camera = camera_at(sg::Vec3(0.0, 0.0, -3.0), sg::Vec3(0.0), 4.0);
        graph.objects.push_back(sphere(sg::Vec3(0.0), 1.0, make_material(1.0, 0.0, sg::Vec3(albedo))));
        graph.global.ambient_light = sg::Vec3(0.0);
        sg::SkySphere sky;
        sky.pigments.emplace_back();
        sky.pigments.back().color.rgb = sg::Vec3(0.7);
        graph.sky_sphere = sky;
        auto integrator = make_integrator(path);
        const Film film = render(graph, *integrator, 4, 4, 4096);
        // Zoom 4 frames the ball's middle only.
        EXPECT_LT(max_deviation(film, 0.7 * albedo), 0.02)
            << "albedo " << albedo << ", image mean " << image_mean(film);
    }
}

// A ball between two texture_map entries of albedo 1 and 0.2, blended
// half and half, under the same constant sky: path follows one entry per
// path with its weight's probability, so the ball converges to the mean of
// what each reflects, 0.7 * 0.6 (one material with either finish would
// give 0.7 or 0.14).
TEST_F(PathFixture, TextureMapEntriesAreLitEachWithItsOwnFinish) {
    ParseOptions options;
    options.language_version = 3.7;
    // Entries far apart: the value over the ball is 0.5 to within 0.001.
    ParseResult parsed = parse_scene_string(R"(
        camera { location <0, 0, -3> direction <0, 0, 4> right x up y look_at 0 }
        sphere { 0, 1 texture { gradient x texture_map {
            [-1000 pigment { rgb 1 } finish { ambient 0 diffuse 1 }]
            [1000 pigment { rgb 1 } finish { ambient 0 diffuse 0.2 }] } } }
        sky_sphere { pigment { rgb 0.7 } }
    )",
                                            "blend.pov", options);
    ASSERT_TRUE(parsed.ok());
    auto integrator = make_integrator(path);
    const Film film = render(*parsed.scene, *integrator, 4, 4, 4096);
    EXPECT_LT(max_deviation(film, 0.7 * 0.6), 0.02) << "image mean " << image_mean(film);
}

// A matte floor and ball under a sky_sphere whose sun (a disc of 0.1 rad
// radius, 250 times the rest of the sky) gives most of the light. NEE draws
// the sun from the sky's table, so the image converges to what BSDF
// sampling alone gives (the same mean: unbiased) with far less noise at
// the same sample count.
sg::SceneGraph sunny_sky_scene() {
    ParseOptions options;
    options.language_version = 3.7;
    ParseResult parsed = parse_scene_string(R"(
        camera { location <0, 2, -4> look_at <0, 0.4, 0> }
        plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 } }
        sphere { <0, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.5, 0.3> } finish { ambient 0 diffuse 1 } }
        #declare Sun = vnormalize(<-0.5, 0.8, -0.4>);
        sky_sphere { pigment { spherical scale 1.0 translate Sun
            color_map { [0 rgb <0.1, 0.15, 0.3>] [0.9 rgb <0.1, 0.15, 0.3>] [0.9 rgb 25] [1 rgb 25] } } }
    )",
                                            "sky.pov", options);
    EXPECT_TRUE(parsed.ok());
    for (const auto& d : parsed.diagnostics) ADD_FAILURE() << format_diagnostic(d);
    return parsed.ok() ? *parsed.scene : sg::SceneGraph{};
}

double mean_variance_of_mean(const PixelStatistics& image) {
    double sum = 0.0;
    for (const glm::dvec3& v : image.variance_of_mean) sum += v.x + v.y + v.z;
    return sum / (3.0 * double(image.variance_of_mean.size()));
}

TEST_F(PathFixture, SkyIsImportanceSampled) {
    const sg::SceneGraph graph = sunny_sky_scene();
    auto mis = make_integrator(path, {"max_depth=3"});
    auto bsdf_only = make_integrator(path, {"max_depth=3", "strategy=bsdf"});
    const PixelStatistics sampled = PixelStatistics::from_film(render(graph, *mis, 16, 12, 256, 1));
    const PixelStatistics reference = PixelStatistics::from_film(render(graph, *bsdf_only, 16, 12, 2048, 2));
    const ImageComparison c = compare_images(sampled, reference, 0.01, 2);
    EXPECT_TRUE(c.passed) << c.summary;
    // Noise per sample: BSDF sampling's variance of the mean at 2048
    // samples, scaled to 256, against the table's at 256.
    const double ratio = mean_variance_of_mean(sampled) / (8.0 * mean_variance_of_mean(reference));
    EXPECT_LT(ratio, 0.1) << "variance with the sky sampled / without";
}

// A floor and a ball lit from above, by a point light or by a tiny sphere
// light of the same colour (hence the same power) at the same place.
sg::SceneGraph lit_floor_scene(bool sphere_light) {
    sg::SceneGraph graph;
    graph.camera = camera_at(sg::Vec3(0.0, 2.0, -4.0), sg::Vec3(0.0, 0.5, 0.0));
    graph.objects.push_back(plane(sg::Vec3(0.0, 1.0, 0.0), 0.0, make_material(0.8, 0.0)));
    graph.objects.push_back(sphere(sg::Vec3(0.5, 0.5, 0.0), 0.5, make_material(0.7, 0.0, sg::Vec3(0.9, 0.5, 0.3))));
    sg::Light light;
    light.kind = sphere_light ? sg::Light::Kind::AreaSphere : sg::Light::Kind::Point;
    light.position = sg::Vec3(-0.5, 2.5, -0.5);
    light.color = sg::Vec3(2.0);
    light.radius = 0.01;
    graph.lights.push_back(light);
    graph.global.ambient_light = sg::Vec3(0.0);
    return graph;
}

// A sphere lamp of radius 0.01 lights the scene as the physical point it
// shrinks to: a lamp of radius 0, an inverse-square point of intensity
// pi*C (POV's point_light does not fall off, so it is not the comparison).
TEST_F(PathFixture, TinySphereLightMatchesPointLight) {
    auto integrator = make_integrator(path, {"max_depth=3"});
    sg::SceneGraph point_lamp = lit_floor_scene(true);
    point_lamp.lights[0].radius = 0.0;
    const Film point = render(point_lamp, *integrator, 16, 12, 256, 1);
    const Film sphere_light = render(lit_floor_scene(true), *integrator, 16, 12, 256, 2);
    const ImageComparison c =
        compare_images(PixelStatistics::from_film(sphere_light), PixelStatistics::from_film(point), 0.01, 2);
    EXPECT_TRUE(c.passed) << c.summary;
}

// The three estimators (light sampling, BSDF sampling, their MIS) converge
// to the same image of a glossy scene under a rectangle light.
sg::SceneGraph glossy_area_scene() {
    sg::SceneGraph graph;
    graph.camera = camera_at(sg::Vec3(0.0, 1.5, -3.0), sg::Vec3(0.0, 0.4, 0.0));
    auto floor = make_material(0.4, 0.0);
    std::const_pointer_cast<sg::Material>(floor)->finish->phong = 0.4;
    std::const_pointer_cast<sg::Material>(floor)->finish->phong_size = 20.0;
    graph.objects.push_back(plane(sg::Vec3(0.0, 1.0, 0.0), 0.0, floor));
    auto ball = make_material(0.5, 0.0, sg::Vec3(0.3, 0.6, 0.9));
    std::const_pointer_cast<sg::Material>(ball)->finish->specular = 0.3;
    std::const_pointer_cast<sg::Material>(ball)->finish->roughness = 0.1;
    graph.objects.push_back(sphere(sg::Vec3(0.0, 0.5, 0.0), 0.5, ball));
    sg::Light light;
    light.kind = sg::Light::Kind::AreaRectangle;
    light.position = sg::Vec3(0.0, 2.0, 0.0);
    light.axis1 = sg::Vec3(1.5, 0.0, 0.0);
    light.axis2 = sg::Vec3(0.0, 0.0, 1.5);
    light.color = sg::Vec3(1.0);
    graph.lights.push_back(light);
    graph.global.ambient_light = sg::Vec3(0.0);
    return graph;
}

TEST_F(PathFixture, MisNeeAndBsdfSamplingAgree) {
    const sg::SceneGraph graph = glossy_area_scene();
    auto mis = make_integrator(path, {"max_depth=2"});
    auto nee = make_integrator(path, {"max_depth=2", "strategy=nee"});
    auto bsdf = make_integrator(path, {"max_depth=2", "strategy=bsdf"});
    const PixelStatistics a = PixelStatistics::from_film(render(graph, *mis, 16, 12, 256, 3));
    const PixelStatistics b = PixelStatistics::from_film(render(graph, *nee, 16, 12, 256, 4));
    const PixelStatistics c = PixelStatistics::from_film(render(graph, *bsdf, 16, 12, 1024, 5));
    const ImageComparison ab = compare_images(a, b, 0.01, 2);
    // BSDF sampling finds the lamp from the far floor only rarely: there
    // its variance estimate is unreliable, hence the small tolerance.
    const ImageComparison ac = compare_images(a, c, 0.01, 2, 2e-3);
    EXPECT_TRUE(ab.passed) << "mis vs nee: " << ab.summary;
    EXPECT_TRUE(ac.passed) << "mis vs bsdf: " << ac.summary;
}

// Every kind of light at once: lamps (spheres, a panel), an emitting box,
// POV lights with fade (a point and a spotlight), which one tree holds, POV
// lights without (points and a spotlight), which another holds, and a
// parallel light and a sky, which stay with the power distribution.
sg::SceneGraph many_kinds_of_light_scene() {
    ParseOptions options;
    options.language_version = 3.7;
    ParseResult parsed = parse_scene_string(R"(
        camera { location <0, 3, -5> look_at <0, 0.4, 0> }
        plane { y, 0 pigment { rgb 0.8 } finish { ambient 0 diffuse 1 phong 0.3 } }
        sphere { <0, 0.6, 0>, 0.6 pigment { rgb <0.9, 0.5, 0.3> } finish { ambient 0 diffuse 1 } }
        #for (I, 0, 11)
          light_source { <3 * cos(I * pi / 6), 0.4 + 0.2 * mod(I, 3), 3 * sin(I * pi / 6)>
                         rgb <1 + mod(I, 2), 1, 2 - mod(I, 2)> * 0.4 area_sphere 0.05 + 0.02 * mod(I, 4) }
        #end
        light_source { <0, 2.5, 1> rgb 0.6 area_rectangle <1, 0, 0>, <0, 0, 1> }
        box { <-2.5, 0, 2>, <-2, 0.8, 2.5> pigment { rgb <0.5, 1, 0.5> } finish { ambient 0 diffuse 0 emission 1.5 } }
        light_source { <2, 2, -1> rgb 0.5 fade_distance 1 fade_power 2 }
        light_source { <-1, 3, -1> rgb 0.8 spotlight point_at <0, 0, 0> radius 10 falloff 20 fade_distance 2 fade_power 1 }
        light_source { <1, 5, -4> rgb 0.15 }
        light_source { <-3, 4, 2> rgb 0.1 }
        light_source { <3, 2, 3> rgb 0.3 spotlight point_at <2, 0, 1> radius 15 falloff 25 }
        light_source { <0, 10, 0> rgb 0.1 parallel point_at <0, 0, 0> }
        sky_sphere { pigment { rgb <0.05, 0.07, 0.1> } }
    )",
                                            "many.pov", options);
    EXPECT_TRUE(parsed.ok());
    for (const auto& d : parsed.diagnostics) ADD_FAILURE() << format_diagnostic(d);
    return parsed.ok() ? *parsed.scene : sg::SceneGraph{};
}

// Choosing through the tree changes the noise, not the image: it agrees
// with lighting by every light at once, with MIS and with light sampling
// alone.
TEST_F(PathFixture, TreeLightSelectionAgreesWithEveryLight) {
    const sg::SceneGraph graph = many_kinds_of_light_scene();
    auto all = make_integrator(path, {"max_depth=2", "light_sampling=all"});
    auto tree = make_integrator(path, {"max_depth=2", "light_sampling=tree"});
    auto tree_nee = make_integrator(path, {"max_depth=2", "light_sampling=tree", "strategy=nee"});
    const PixelStatistics a = PixelStatistics::from_film(render(graph, *all, 16, 12, 256, 11));
    const PixelStatistics b = PixelStatistics::from_film(render(graph, *tree, 16, 12, 512, 12));
    const PixelStatistics c = PixelStatistics::from_film(render(graph, *tree_nee, 16, 12, 512, 13));
    const ImageComparison ab = compare_images(a, b, 0.01, 2);
    const ImageComparison ac = compare_images(a, c, 0.01, 2);
    EXPECT_TRUE(ab.passed) << "all vs tree: " << ab.summary;
    EXPECT_TRUE(ac.passed) << "all vs tree, nee only: " << ac.summary;
}

// Refraction reads the indices of the objects the path is in, as in
// POV-Ray: a ball of the same glass inside a glass ball is index-matched
// (n 1.5 on both sides of its surface), so it neither bends nor reflects
// the light and the image is the outer ball's alone. Judged by the faces,
// its surface would bend light as air to glass.
sg::SceneGraph glass_ball_scene(bool with_inner_ball) {
    ParseOptions options;
    options.language_version = 3.7;
    std::string text = R"(
        camera { location <0, 0.5, -4> look_at <0, 0.5, 0> }
        plane { y, -0.6 pigment { checker rgb 0.9 rgb 0.1 scale 0.5 } finish { ambient 0 diffuse 1 } }
        sphere { <0, 0.5, 0>, 1 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }
        sky_sphere { pigment { gradient y color_map { [0 rgb <0.2, 0.3, 0.9>] [1 rgb 1] } } }
    )";
    if (with_inner_ball)
        text +=
            "sphere { <0.2, 0.6, 0>, 0.5 pigment { rgbt 1 } finish { ambient 0 diffuse 0 } interior { ior 1.5 } }\n";
    ParseResult parsed = parse_scene_string(text, "glass.pov", options);
    EXPECT_TRUE(parsed.ok());
    return parsed.ok() ? *parsed.scene : sg::SceneGraph{};
}

TEST_F(PathFixture, AnIndexMatchedBallInsideGlassIsInvisible) {
    auto integrator = make_integrator(path, {"max_depth=12"});
    const PixelStatistics alone =
        PixelStatistics::from_film(render(glass_ball_scene(false), *integrator, 16, 12, 256, 21));
    const PixelStatistics nested =
        PixelStatistics::from_film(render(glass_ball_scene(true), *integrator, 16, 12, 256, 22));
    const ImageComparison c = compare_images(alone, nested, 0.01, 2);
    EXPECT_TRUE(c.passed) << c.summary;
}

TEST_F(PathFixture, SobolAndIndependentAgree) {
    const sg::SceneGraph graph = glossy_area_scene();
    auto independent = make_integrator(path, {"sampler=independent"});
    auto sobol = make_integrator(path, {"sampler=sobol"});
    const ImageComparison c =
        compare_images(PixelStatistics::from_film(render(graph, *sobol, 16, 12, 256, 6)),
                       PixelStatistics::from_film(render(graph, *independent, 16, 12, 256, 7)), 0.01, 2);
    EXPECT_TRUE(c.passed) << c.summary;
}

// The comparison helper on real renders: two seeds agree, a render scaled
// by 1.02 does not.
TEST_F(PathFixture, StatCompareSeparatesNoiseFromTwoPercentBias) {
    const sg::SceneGraph graph = glossy_area_scene();
    auto integrator = make_integrator(path, {"max_depth=2"});
    const PixelStatistics a = PixelStatistics::from_film(render(graph, *integrator, 16, 12, 512, 8));
    const PixelStatistics b = PixelStatistics::from_film(render(graph, *integrator, 16, 12, 512, 9));
    EXPECT_TRUE(compare_images(a, b).passed) << compare_images(a, b).summary;
    PixelStatistics biased = a;
    for (auto& m : biased.mean) m *= 1.02;
    for (auto& v : biased.variance_of_mean) v *= 1.02 * 1.02;
    EXPECT_FALSE(compare_images(biased, b).passed) << compare_images(biased, b).summary;
}

// max_depth = 1 is direct lighting: on a scene lit only by point and
// directional lights (no ambient), it is what `shadow` computes. The host
// samples a deterministic integrator at pixel centres only, so both are
// evaluated here on the same centre rays. With every light sampled at each
// hit (light_sampling=all) path is exact there too; with one light picked
// by power it is an unbiased estimate of the same value.
TEST_F(PathFixture, DirectLightingEqualsShadow) {
    sg::SceneGraph graph = lit_floor_scene(false);
    std::const_pointer_cast<sg::Material>(graph.objects[1].material)->finish->phong = 0.3;
    std::const_pointer_cast<sg::Material>(graph.objects[0].material)->finish->specular = 0.2;
    sg::Light sun;
    sun.kind = sg::Light::Kind::Directional;
    sun.parallel = true;
    sun.position = sg::Vec3(3.0, 4.0, -2.0);
    sun.point_at = sg::Vec3(0.0);
    sun.color = sg::Vec3(0.4, 0.4, 0.3);
    graph.lights.push_back(sun);
    const auto scene = compile_scene(graph);
    const Plugin shadow_plugin = load_plugin("shadow");
    auto shadow = make_integrator(shadow_plugin);
    auto exact = make_integrator(path, {"max_depth=1", "light_sampling=all"});
    auto stochastic = make_integrator(path, {"max_depth=1"});
    for (Integrator* i : {shadow.get(), exact.get(), stochastic.get()}) i->prepare(*scene);

    constexpr int kWidth = 16, kHeight = 12, kSamples = 256;
    PixelStatistics reference, estimate;
    reference.width = estimate.width = kWidth;
    reference.height = estimate.height = kHeight;
    auto sampler = stochastic->make_sampler(12);
    auto unused = shadow->make_sampler(0);
    for (int y = 0; y < kHeight; ++y)
        for (int x = 0; x < kWidth; ++x) {
            Ray ray;
            ASSERT_TRUE(scene->camera().generate_ray(x + 0.5f, y + 0.5f, kWidth, kHeight, ray));
            unused->start_sample(x, y, 0);
            const Color expected = shade_camera_ray(*shadow, ray, *scene, *unused);
            sampler->start_sample(x, y, 0);
            const Color direct = shade_camera_ray(*exact, ray, *scene, *sampler);
            for (int c = 0; c < 3; ++c)
                ASSERT_NEAR(direct[c], expected[c], 1e-4 * (1.0 + expected[c])) << x << "," << y;
            glm::dvec3 sum(0.0), sum2(0.0);
            for (int s = 0; s < kSamples; ++s) {
                sampler->start_sample(x, y, s);
                const glm::dvec3 v(shade_camera_ray(*stochastic, ray, *scene, *sampler));
                sum += v;
                sum2 += v * v;
            }
            const glm::dvec3 mean = sum / double(kSamples);
            estimate.mean.push_back(mean);
            estimate.variance_of_mean.push_back(glm::max(sum2 / double(kSamples) - mean * mean, 0.0) /
                                                double(kSamples - 1));
            reference.mean.push_back(glm::dvec3(expected));
            reference.variance_of_mean.push_back(glm::dvec3(0.0));
        }
    const ImageComparison c = compare_images(estimate, reference);
    EXPECT_TRUE(c.passed) << c.summary;
}

TEST_F(PathFixture, DepthZeroIsEmissionOnly) {
    sg::SceneGraph graph = lit_floor_scene(false);
    graph.objects.push_back(sphere(sg::Vec3(-0.8, 0.3, -0.5), 0.3, make_material(0.0, 0.7)));
    auto integrator = make_integrator(path, {"max_depth=0"});
    const Film film = render(graph, *integrator, 16, 12, 4);
    double brightest = 0.0;
    for (int y = 0; y < 12; ++y)
        for (int x = 0; x < 16; ++x) brightest = std::max(brightest, double(max_component(film.mean(x, y))));
    EXPECT_LE(brightest, 0.7 + 1e-5);  // no reflected light anywhere
    EXPECT_GT(brightest, 0.0);         // the emitter is visible
}

TEST_F(PathFixture, RejectsUnknownSampler) {
    EXPECT_ANY_THROW(make_integrator(path, {"sampler=halton"}));
}

// RMSE against a high-sample reference falls as N^-1/2 with independent
// samples and faster with Sobol on a smooth integrand (direct light from a
// large rectangle on a matte floor).
double rmse(const Film& film, const Film& reference) {
    double sum = 0.0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Color d = film.mean(x, y) - reference.mean(x, y);
            sum += glm::dot(d, d) / 3.0;
        }
    return std::sqrt(sum / (film.width() * film.height()));
}

double log_log_slope(const std::vector<double>& n, const std::vector<double>& e) {
    double mx = 0, my = 0;
    for (std::size_t i = 0; i < n.size(); ++i) mx += std::log(n[i]) / n.size(), my += std::log(e[i]) / n.size();
    double sxy = 0, sxx = 0;
    for (std::size_t i = 0; i < n.size(); ++i) {
        sxy += (std::log(n[i]) - mx) * (std::log(e[i]) - my);
        sxx += (std::log(n[i]) - mx) * (std::log(n[i]) - mx);
    }
    return sxy / sxx;
}

TEST_F(PathFixture, ConvergenceRate) {
    sg::SceneGraph graph;
    graph.camera = camera_at(sg::Vec3(0.0, 3.0, -2.0), sg::Vec3(0.0, 0.0, 0.5));
    graph.objects.push_back(plane(sg::Vec3(0.0, 1.0, 0.0), 0.0, make_material(0.8, 0.0)));
    sg::Light light;
    light.kind = sg::Light::Kind::AreaRectangle;
    light.position = sg::Vec3(0.0, 1.0, 0.5);
    light.axis1 = sg::Vec3(2.0, 0.0, 0.0);
    light.axis2 = sg::Vec3(0.0, 0.0, 2.0);
    light.color = sg::Vec3(1.0);
    graph.lights.push_back(light);
    graph.global.ambient_light = sg::Vec3(0.0);

    auto independent = make_integrator(path, {"max_depth=1", "sampler=independent"});
    auto sobol = make_integrator(path, {"max_depth=1", "sampler=sobol"});
    const Film reference = render(graph, *sobol, 8, 8, 1 << 14, 99);
    const std::vector<double> counts = {4, 16, 64, 256};
    std::vector<double> e_independent, e_sobol;
    for (double n : counts) {
        double ei = 0.0, es = 0.0;
        for (std::uint64_t seed = 0; seed < 4; ++seed) {  // average out the RMSE's own noise
            ei += rmse(render(graph, *independent, 8, 8, int(n), seed), reference) / 4.0;
            es += rmse(render(graph, *sobol, 8, 8, int(n), seed), reference) / 4.0;
        }
        e_independent.push_back(ei);
        e_sobol.push_back(es);
    }
    const double slope_independent = log_log_slope(counts, e_independent);
    const double slope_sobol = log_log_slope(counts, e_sobol);
    RecordProperty("slope_independent", std::to_string(slope_independent));
    RecordProperty("slope_sobol", std::to_string(slope_sobol));
    EXPECT_GE(slope_independent, -0.6);
    EXPECT_LE(slope_independent, -0.4);
    EXPECT_LT(slope_sobol, slope_independent - 0.1) << "independent " << slope_independent;
}

}  // namespace
}  // namespace lancer::test
