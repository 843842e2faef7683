// Numerical stability at the extremes. Each test names the failure it guards
// against and states the expected result. Scenes are written in the scene
// language (parse_scene_string) so they read like user scenes; images are
// tiny. Self-intersection across 1e-6..1e6 lives in
// render/src/geometry/self_intersection_test.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "lancer/host/film.h"
#include "lancer/host/plugin_host.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/integrator.h"
#include "lancer/parser.h"
#include "lancer/render_scene.h"
#include "lancer/scene_error.h"
#include "lancer/scene_graph.h"
#include "run_command.h"

namespace lancer {
namespace {

using Parameters = std::map<std::string, std::string>;

sg::SceneGraph parse(const std::string& text, int width, int height) {
    ParseOptions options;
    options.image_width = width;
    options.image_height = height;
    options.image_size_from_command_line = true;
    const ParseResult parsed = parse_scene_string(text, "<extremes>", options);
    if (!parsed.ok()) {
        std::string message;
        for (const Diagnostic& d : parsed.diagnostics) message += format_diagnostic(d) + "\n";
        throw std::runtime_error("scene does not parse:\n" + message + text);
    }
    return *parsed.scene;
}

// Renders a scene graph with the named integrator on every core.
Film render_graph(const sg::SceneGraph& graph, const std::string& integrator_name, const Parameters& parameters,
                  int width, int height, int spp = 1, std::uint64_t seed = 3) {
    const auto scene = compile_scene(graph);
    const Plugin plugin = load_plugin(integrator_name);
    std::vector<std::string> assignments;
    for (const auto& [key, value] : parameters) assignments.push_back(key + "=" + value);
    const auto integrator = plugin.descriptor->create(resolve_parameters(*plugin.descriptor, {}, assignments));
    integrator->prepare(*scene);
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.samples_per_pixel = spp;
    options.seed = seed;
    options.threads = 0;
    options.tile_size = 8;
    options.progress = ProgressMode::Quiet;
    Film film(width, height);
    render_image(*scene, *integrator, options, film);
    return film;
}

// Renders scene text (parsed for width x height).
Film render(const std::string& text, const std::string& integrator_name, const Parameters& parameters, int width = 32,
            int height = 24, int spp = 1, std::uint64_t seed = 3) {
    return render_graph(parse(text, width, height), integrator_name, parameters, width, height, spp, seed);
}

// No NaN or Inf anywhere: neither dropped by the film nor in a pixel.
::testing::AssertionResult all_finite(const Film& film) {
    if (film.nonfinite_samples() != 0)
        return ::testing::AssertionFailure() << film.nonfinite_samples() << " non-finite samples";
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Color c = film.mean(x, y);
            if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b))
                return ::testing::AssertionFailure() << "pixel (" << x << ", " << y << ") is non-finite";
            if (c.r < 0.0f || c.g < 0.0f || c.b < 0.0f)
                return ::testing::AssertionFailure() << "pixel (" << x << ", " << y << ") is negative";
        }
    return ::testing::AssertionSuccess();
}

float max_value(const Film& film) {
    float m = 0.0f;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x)
            m = std::max({m, film.mean(x, y).r, film.mean(x, y).g, film.mean(x, y).b});
    return m;
}

// Mean relative difference of two images: sum |a - b| / sum |b| over
// pixels and channels, on v / (1 + v) so a lamp's few bright pixels do not
// hide a change everywhere else.
double relative_difference(const Film& a, const Film& b) {
    double difference = 0.0, total = 0.0;
    for (int y = 0; y < a.height(); ++y)
        for (int x = 0; x < a.width(); ++x)
            for (int c = 0; c < 3; ++c) {
                const double u = a.mean(x, y)[c], v = b.mean(x, y)[c];
                difference += std::abs(u / (1.0 + u) - v / (1.0 + v));
                total += v / (1.0 + v);
            }
    return total > 0.0 ? difference / total : difference;
}

// ---------------------------------------------------------------------------
// Scale invariance and distance from the origin.

// A small room-less scene lit only by things whose effect does not depend
// on scale: a directional light (its position scales too: as in POV-Ray,
// only what lies between a surface and the light's plane casts a shadow), an emissive sphere (radiance = emission x
// pigment), an area rectangle whose colour grows with the square of the
// scale (its radiance is pi C / area, so this keeps its radiance fixed) and
// the ambient term; spheres (matte, mirror, glass, emissive), a box, a
// triangle and a plane cover every intersector. Every length is multiplied
// by `scale` and shifted by `offset`, camera included; the picture should
// not change.
// The declarations both scaled scenes start with: S the scale, O the offset.
std::string scale_and_offset(double scale, double offset) {
    char head[512];
    std::snprintf(head, sizeof head, "#declare S = %.17g;\n#declare O = <%.17g, %.17g, %.17g>;\n", scale, offset,
                  offset * 0.5, -offset);
    return head;
}

std::string scaled_scene(double scale, double offset) {
    return scale_and_offset(scale, offset) + R"(
global_settings { assumed_gamma 1.0 max_trace_level 6 }
background { color rgb <0.05, 0.06, 0.08> }
camera { location <0, 2.2, -6> * S + O look_at <0, 0.6, 0> * S + O right x * 4 / 3 angle 50 }
light_source { <-3, 5, -4> * S + O color rgb 0.6 parallel point_at O }
light_source { <0, 3.2, 0> * S + O color rgb 1.5 * S * S area_rectangle <1.2, 0, 0> * S, <0, 0, 1.2> * S }
#declare Matte = texture { pigment { color rgb <0.7, 0.65, 0.6> } finish { ambient 0.05 diffuse 0.8 } }
plane { y, 0 texture { Matte } translate O }
sphere { <-1.1, 0.8, 0> * S + O, 0.8 * S texture { pigment { color rgb <0.8, 0.3, 0.2> } finish { ambient 0.05 diffuse 0.7 phong 0.4 } } }
sphere { <1.2, 0.6, 0.6> * S + O, 0.6 * S texture { pigment { color rgb 0.9 } finish { ambient 0 diffuse 0.05 reflection 0.85 } } }
box { <-0.2, 0, -1.9> * S + O, <0.6, 0.7, -1.1> * S + O texture { pigment { color rgb <0.2, 0.5, 0.8> } finish { ambient 0.05 diffuse 0.8 } } }
sphere { <1.6, 0.25, -1.6> * S + O, 0.25 * S texture { pigment { color rgb <1, 0.85, 0.6> } finish { ambient 0 diffuse 0 emission 3 } } }
sphere { <-0.6, 0.35, -2.2> * S + O, 0.35 * S texture { pigment { color rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.05 reflection 0.05 } } interior { ior 1.5 } }
triangle { <-2.6, 0, 1> * S + O, <-1.4, 0, 1.6> * S + O, <-2.2, 1.6, 1.4> * S + O texture { pigment { color rgb <0.3, 0.8, 0.3> } finish { ambient 0.05 diffuse 0.8 } } }
)";
}

// What both shape scenes share: camera, light, texture M, the floor, and
// an open union that the scene closes with `scale S translate O }`.
std::string shapes_scene_start(double scale, double offset) {
    return scale_and_offset(scale, offset) + R"(
global_settings { assumed_gamma 1.0 max_trace_level 6 }
background { color rgb <0.05, 0.06, 0.08> }
camera { location <0, 3, -7> * S + O look_at <0, 0.5, 0> * S + O right x * 4 / 3 angle 55 }
light_source { <-3, 5, -4> * S + O color rgb 0.8 parallel point_at O }
#declare M = texture { pigment { color rgb <0.7, 0.65, 0.6> } finish { ambient 0.05 diffuse 0.8 phong 0.3 } }
union {
  plane { y, 0 texture { M } }
)";
}

// Every analytic shape of issue 16 and a glass CSG, each written at unit
// size and then scaled by `scale` and moved by `offset` (so the shapes'
// own parameters stay the same and only the placement changes).
std::string scaled_shapes_scene(double scale, double offset) {
    return shapes_scene_start(scale, offset) + R"(
  cylinder { <-3, 0, 1>, <-3, 1.2, 1>, 0.4 texture { M } }
  cone { <-2, 0, 1>, 0.5, <-2, 1.2, 1>, 0 texture { M } }
  torus { 0.5, 0.15 rotate x*80 translate <-0.8, 0.7, 1> texture { M } }
  disc { <0.4, 0.6, 1>, <0, 0.3, -1>, 0.5, 0.15 texture { M } }
  quadric { <4, 2, 4>, <0, 0, 0>, <0, 0, 0>, -1 translate <1.6, 0.75, 1> texture { M } }
  superellipsoid { <0.3, 0.6> scale 0.45 translate <2.8, 0.45, 1> texture { M } }
  blob { threshold 0.5 sphere { <-0.3, 0, 0>, 0.6, 1 } sphere { <0.3, 0.2, 0>, 0.6, 1 } translate <-2.4, 0.5, -1> texture { M } }
  prism { bezier_spline 0, 0.6, 8, <0, 0>, <0.8, 0>, <0.8, 0.6>, <0, 0.6>, <0, 0.6>, <-0.4, 0.6>, <-0.4, 0>, <0, 0> translate <-1, 0, -1.2> texture { M } }
  lathe { cubic_spline 6, <0, -0.3>, <0, 0>, <0.5, 0.1>, <0.3, 0.5>, <0.45, 0.8>, <0.5, 1.2> translate <0.4, 0, -1> texture { M } }
  difference {
    box { <-0.4, 0, -0.4>, <0.4, 0.8, 0.4> }
    cylinder { <0, 0.4, -1>, <0, 0.4, 1>, 0.25 }
    texture { pigment { color rgbf <1, 1, 1, 0.9> } finish { ambient 0 diffuse 0.05 reflection 0.05 } }
    interior { ior 1.5 }
    // Lifted off the floor: a glass face coincident with the plane would
    // show float ties, not the shapes' numerics.
    translate <1.7, 0.05, -1.4>
  }
  scale S translate O
}
)";
}

// The shapes that scene leaves out (ovus, sphere_sweep, bicubic_patch,
// julia_fractal, height_field, sor, polygon, poly, text), placed the same way.
std::string scaled_curved_shapes_scene(double scale, double offset) {
    const std::string height_map = test::source_path("tests/reference/pov/height_field_16.png");
    return shapes_scene_start(scale, offset) + R"(
  ovus { 0.5, 0.3 translate <-3, 0.5, 1> texture { M } }
  sphere_sweep { cubic_spline 5, <-0.6, 0.2, 0>, 0.1, <-0.3, 0.8, 0>, 0.15, <0, 0.3, 0>, 0.2, <0.3, 0.9, 0.2>, 0.12,
                 <0.6, 0.2, 0>, 0.1 translate <-1.6, 0, 1> texture { M } }
  bicubic_patch { type 1 u_steps 3 v_steps 3
    <-0.5, 0, -0.5>, <-0.2, 0, -0.5>, <0.2, 0, -0.5>, <0.5, 0, -0.5>,
    <-0.5, 0, -0.2>, <-0.2, 1.2, -0.2>, <0.2, 1.2, -0.2>, <0.5, 0, -0.2>,
    <-0.5, 0, 0.2>, <-0.2, 1.2, 0.2>, <0.2, 1.2, 0.2>, <0.5, 0, 0.2>,
    <-0.5, 0, 0.5>, <-0.2, 0, 0.5>, <0.2, 0, 0.5>, <0.5, 0, 0.5> translate <0, 0.01, 1> texture { M } }
  julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion sqr max_iteration 8 precision 15
                  scale 0.4 translate <1.4, 0.6, 1> texture { M } }
  height_field { png ")" +
           height_map + R"(" gamma 1 smooth translate <-0.5, 0, -0.5> scale <1.2, 0.5, 1.2>
                 translate <2.8, 0.01, 1> texture { M } }
  sor { 5, <0, 0>, <0.4, 0.01>, <0.2, 0.5>, <0.4, 0.9>, <0.3, 1.2> translate <-2.2, 0.01, -1.2> texture { M } }
  polygon { 5, <0, 0>, <0.8, 0>, <0.8, 0.7>, <0, 0.7>, <0, 0> rotate x*60 translate <-0.9, 0.3, -1.4> texture { M } }
  poly { 2, <1, 0, 0, 0, 4, 0, 0, 1, 0, -0.16> translate <0.6, 0.4, -1.2> texture { M } }
  text { ttf "timrom.ttf" "Ab" 0.2, 0 scale 0.8 translate <1.4, 0.01, -1.4> texture { M } }
  scale S translate O
}
)";
}

struct Variant {
    const char* label;
    std::string integrator;
    Parameters parameters;
    int spp;
};

std::vector<Variant> every_integrator() {
    return {{"raycast", "raycast", {}, 1},
            {"shadow", "shadow", {}, 1},
            {"shadow_area", "shadow", {{"area_samples", "4"}}, 8},
            {"whitted", "whitted", {}, 1},
            {"gather", "gather", {{"n", "16"}}, 8},
            {"path", "path", {{"max_depth", "5"}}, 16},
            {"normal", "normal", {}, 1},
            {"albedo", "albedo", {}, 1}};
}

// Guards against: scale-dependent epsilons (self-shadowing acne when the
// scene is small, light leaking or missed hits when it is large), and light
// units that secretly depend on scale. Expected: every integrator renders
// the same image at scales 1e-4 .. 1e4 as at 1, within 1% mean relative
// difference. Stochastic integrators use the same seed, so only numerics
// (not noise) can tell the scales apart.
TEST(Extremes, ScaleInvariance) {
    constexpr int kWidth = 48, kHeight = 36;
    for (const Variant& v : every_integrator()) {
        const Film reference = render(scaled_scene(1.0, 0.0), v.integrator, v.parameters, kWidth, kHeight, v.spp);
        EXPECT_TRUE(all_finite(reference)) << v.label;
        for (double scale : {1e-4, 1e-2, 1e2, 1e4}) {
            const Film scaled = render(scaled_scene(scale, 0.0), v.integrator, v.parameters, kWidth, kHeight, v.spp);
            EXPECT_TRUE(all_finite(scaled)) << v.label << " at scale " << scale;
            const double difference = relative_difference(scaled, reference);
            std::cout << "[ scale    ] " << v.label << " x" << scale << ": " << 100.0 * difference << " %\n";
            EXPECT_LT(difference, 0.01) << v.label << " at scale " << scale;
        }
    }
}

// Guards against: float precision lost far from the origin (hits snapping to
// a coarse grid, offsets too small for the coordinates' magnitude so rays
// re-hit their surface). Expected: the scene moved to ~1e5 from the origin
// renders as at the origin, within 1% (float ULP at 1e5 is ~0.008, 2% of
// the glass sphere's radius, which refraction magnifies: whitted 0.6%,
// gather 0.85%, path 0.9% today, near what float geometry allows).
// Unlike scaling, the offset changes float decisions along each path; path
// tracing then continues with other random numbers, so the same-seed renders
// differ by noise: 2.3%, 1.2%, 0.7% at 16, 64, 256 spp (falling as
// 1/sqrt(spp): noise, not bias). So path is compared at 256 spp.
TEST(Extremes, FarFromTheOrigin) {
    constexpr int kWidth = 48, kHeight = 36;
    for (const Variant& v : every_integrator()) {
        const int spp = v.integrator == "path" ? 256 : v.spp;
        const Film reference = render(scaled_scene(1.0, 0.0), v.integrator, v.parameters, kWidth, kHeight, spp);
        const Film moved = render(scaled_scene(1.0, 1e5), v.integrator, v.parameters, kWidth, kHeight, spp);
        EXPECT_TRUE(all_finite(moved)) << v.label;
        const double difference = relative_difference(moved, reference);
        std::cout << "[ offset   ] " << v.label << " +1e5: " << 100.0 * difference << " %\n";
        EXPECT_LT(difference, 0.01) << v.label << " offset by 1e5";
    }
}

// What the camera extremes look at: a checkered floor and a few balls
// around the location, moved by `offset` with the camera.
std::string camera_scene(const std::string& camera, double offset) {
    const std::string o = "<" + std::to_string(offset) + ", 0, " + std::to_string(offset) + ">";
    return "#declare O = " + o + ";\n" + camera +
           R"(
light_source { <-10, 20, -15> + O color rgb 1 }
plane { y, 0 pigment { checker color rgb 0.9 color rgb 0.3 } translate O }
sphere { <0, 1, 4> + O, 1 pigment { color rgb <0.9, 0.3, 0.2> } }
sphere { <3, 0.7, 0> + O, 0.7 pigment { color rgb <0.2, 0.5, 0.9> } }
sphere { <-2, 0.5, -3> + O, 0.5 pigment { color rgb <0.3, 0.8, 0.3> } }
background { color rgb <0.4, 0.5, 0.7> }
)";
}

// Guards against (issue 19): camera rays built in float from a location
// ~1e5 away (directions of the wide projections losing their angles,
// lens offsets vanishing next to the location). Expected: every projection
// renders the scene moved to 1e5 as at the origin, within 1% (whitted; the
// float ULP at 1e5 is ~0.008 at the checker's edges).
TEST(Extremes, EveryCameraFarFromTheOrigin) {
    const char* cameras[] = {"perspective angle 70",
                             "orthographic angle 50",
                             "fisheye angle 200",
                             "ultra_wide_angle angle 200",
                             "omnimax",
                             "panoramic",
                             "cylinder 1 angle 200",
                             "cylinder 2 angle 120",
                             "cylinder 3 angle 300 up y * 3",
                             "cylinder 4 angle 200 right x * 6",
                             "spherical",
                             "perspective angle 60 aperture 0.3 blur_samples 7"};
    for (const char* type : cameras) {
        const std::string camera = std::string("camera { ") + type + " location <0, 2, -5> + O look_at <0, 1, 0> + O }";
        const Film reference = render(camera_scene(camera, 0.0), "whitted", {}, 48, 36);
        const Film moved = render(camera_scene(camera, 1e5), "whitted", {}, 48, 36);
        EXPECT_TRUE(all_finite(moved)) << type;
        const double difference = relative_difference(moved, reference);
        std::cout << "[ camera   ] " << type << " +1e5: " << 100.0 * difference << " %\n";
        EXPECT_LT(difference, 0.01) << type << " offset by 1e5";
    }
}

// Guards against: fields of view near 0 (a perspective direction 1e5 times
// |right|, whose sums lose the image in float) and near 360 (tan and asin
// at their poles). Expected: finite everywhere; a 0.001-degree perspective
// view of a ball 1000 away, 0.0175 wide, still shows the ball's edge (both
// ball and background pixels); the wide projections at 359.99 and 360
// degrees see both the floor and the sky, never NaN.
TEST(Extremes, FieldsOfViewNearZeroAndNear360) {
    const std::string narrow = R"(
camera { location <0, 1, -1000> look_at <0.005, 1, 0> right x * 4 / 3 angle 0.001 }
light_source { <0, 5, -1000> color rgb 1 }
sphere { <0, 1, 0>, 0.01 pigment { color rgb 1 } finish { ambient 1 diffuse 0 } }
)";
    const Film tiny = render(narrow, "whitted", {}, 32, 24);
    EXPECT_TRUE(all_finite(tiny));
    int lit = 0;
    for (int y = 0; y < 24; ++y)
        for (int x = 0; x < 32; ++x) lit += tiny.mean(x, y).r > 0.5f;
    EXPECT_GT(lit, 32 * 24 / 10) << "the ball is missing";
    EXPECT_LT(lit, 32 * 24 * 9 / 10) << "the ball's edge is missing";
    for (const char* type : {"fisheye angle 359.99", "fisheye angle 360", "ultra_wide_angle angle 360",
                             "cylinder 1 angle 360", "spherical angle 360, 180", "perspective angle 179.999"}) {
        const Film wide =
            render(camera_scene(std::string("camera { ") + type + " location <0, 2, 0> }", 0.0), "whitted", {}, 32, 24);
        EXPECT_TRUE(all_finite(wide)) << type;
        EXPECT_GT(max_value(wide), 0.1f) << type;
    }
}

// Guards against: look_at along the sky (sky x view is zero: NaN right and
// up, a black picture) and nearly along it (a right vector of length 1e-9
// normalised). Expected: exactly along, POV's rule (the right vector kept,
// with a warning) and a picture; nearly along, a picture of the same floor
// as a camera tilted a hair the other way.
TEST(Extremes, LookAtAlongAndNearlyAlongTheSky) {
    for (const char* target : {"<0, -10, 0>", "<1e-9, -10, 0>", "<0, -10, 1e-9>"}) {
        const std::string camera = std::string("camera { location <0, 10, 0> look_at ") + target + " angle 60 }";
        const Film film = render(camera_scene(camera, 0.0), "whitted", {}, 32, 24);
        EXPECT_TRUE(all_finite(film)) << target;
        EXPECT_GT(max_value(film), 0.1f) << target;
    }
}

// Guards against, for the quadric family, polynomials, blobs, splines and
// CSG (issue 16): roots lost or found twice as the scale or the distance
// from the origin changes (acne, leaks at seams, missing silhouettes).
// Expected: as for the first scene, within 1% of scale 1 and of the origin.
TEST(Extremes, EveryShapeScaledAndFarFromTheOrigin) {
    constexpr int kWidth = 48, kHeight = 36;
    const std::pair<const char*, std::string (*)(double, double)> scenes[] = {{"shapes", scaled_shapes_scene},
                                                                              {"curved", scaled_curved_shapes_scene}};
    for (const auto& [name, scene] : scenes)
        for (const Variant& v : every_integrator()) {
            if (v.integrator != "shadow" && v.integrator != "whitted" && v.integrator != "path") continue;
            const std::string label = std::string(name) + " " + v.label;
            const Film reference = render(scene(1.0, 0.0), v.integrator, v.parameters, kWidth, kHeight, v.spp);
            EXPECT_TRUE(all_finite(reference)) << label;
            for (double scale : {1e-4, 1e4}) {
                const Film scaled = render(scene(scale, 0.0), v.integrator, v.parameters, kWidth, kHeight, v.spp);
                EXPECT_TRUE(all_finite(scaled)) << label << " at scale " << scale;
                const double difference = relative_difference(scaled, reference);
                std::cout << "[ shapes   ] " << label << " x" << scale << ": " << 100.0 * difference << " %\n";
                EXPECT_LT(difference, 0.01) << label << " at scale " << scale;
            }
            if (v.integrator == "path") continue;  // its offset render differs by noise (see FarFromTheOrigin)
            const Film moved = render(scene(1.0, 1e5), v.integrator, v.parameters, kWidth, kHeight, v.spp);
            EXPECT_TRUE(all_finite(moved)) << label;
            const double difference = relative_difference(moved, reference);
            std::cout << "[ shapes   ] " << label << " +1e5: " << 100.0 * difference << " %\n";
            EXPECT_LT(difference, 0.01) << label << " offset by 1e5";
        }
}

// ---------------------------------------------------------------------------
// Degenerate configurations: no NaN/Inf, no crash, the stated result.

const char* kAllIntegrators[] = {"raycast", "shadow", "whitted", "gather", "path"};

Parameters quick(const std::string& integrator) {
    if (integrator == "gather") return {{"n", "8"}};
    if (integrator == "path") return {{"max_depth", "4"}};
    return {};
}

// Guards against: NaN from normalising near-zero vectors and negative
// cosines at grazing incidence (camera skimming a plane, light along it).
// Expected: finite and non-negative everywhere; the plane, lit by a
// directional light 0.01 degrees above its horizon, receives almost
// nothing: radiance sin(0.01 deg) = 1.7e-4 (ambient 0, diffuse 1); the
// sphere, lit head-on, is no brighter than 1 plus what the plane reflects
// onto it (path; under 1%).
TEST(Extremes, GrazingAngles) {
    const std::string scene = R"(
camera { location <0, 1e-3, -10> look_at <0, 0, 10> angle 60 }
light_source { <0, 0.00017453, -1> color rgb 1 parallel point_at <0, 0, 0> }
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
sphere { <0, 0.5, 4>, 0.5 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
)";
    for (const char* name : kAllIntegrators) {
        const Film film = render(scene, name, quick(name), 32, 24, 4);
        EXPECT_TRUE(all_finite(film)) << name;
        EXPECT_LE(max_value(film), 1.01f) << name;
        // A plane pixel at the bottom edge, below the sphere.
        EXPECT_NEAR(film.mean(2, 23).r, 1.7453e-4f, 2e-5f) << name;
    }
}

// Guards against: a point light lying on a surface (distance 0 to the
// points under it, cos = 0 for the rest) dividing by zero or shadowing
// itself. Expected: finite; the plane it lies on receives nothing (every
// direction to the light is tangent) so shows black with ambient 0, while
// a sphere above the plane is lit.
TEST(Extremes, LightExactlyOnASurface) {
    const std::string scene = R"(
camera { location <0, 3, -5> look_at <0, 0, 0> angle 60 }
light_source { <0, 0, 0> color rgb 1 }
plane { y, 0 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
sphere { <0, 1.5, 0>, 0.5 pigment { color rgb 1 } finish { ambient 0 diffuse 1 } }
)";
    for (const char* name : {"raycast", "shadow", "whitted", "path"}) {
        Parameters p = quick(name);
        if (std::string(name) == "path") p["max_depth"] = "1";  // direct light only
        const Film film = render(scene, name, p, 32, 24, std::string(name) == "path" ? 4 : 1);
        EXPECT_TRUE(all_finite(film)) << name;
        // A plane pixel in the lower corner (far from the light point).
        EXPECT_NEAR(film.mean(1, 22).r, 0.0f, 1e-4f) << name << ": the plane is lit by a light in its own plane";
        // The sphere's underside faces the light: lit.
        EXPECT_GT(max_value(film), 0.01f) << name << ": the sphere above the light is dark";
    }
}

// Guards against: light leaking into a closed object through offsets or
// missed hits when the camera is inside it. Expected: inside a closed matte
// sphere lit only from outside, shadow and whitted see ambient only (a
// uniform 0.1 x 0.5 = 0.05), path sees black.
TEST(Extremes, CameraInsideAnObject) {
    const std::string scene = R"(
camera { location <0, 0, 0> look_at <0, 0, 1> angle 90 }
light_source { <0, 10, -10> color rgb 100 }
light_source { <1, 1, 1> color rgb 1 parallel point_at <0, 0, 0> }
sphere { <0, 0, 0>, 1 pigment { color rgb 0.5 } finish { ambient 0.1 diffuse 0.8 } }
)";
    for (const char* name : {"shadow", "whitted", "path"}) {
        const Film film = render(scene, name, quick(name), 24, 18, std::string(name) == "path" ? 4 : 1);
        EXPECT_TRUE(all_finite(film)) << name;
        const float expected = std::string(name) == "path" ? 0.0f : 0.05f;
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x)
                ASSERT_NEAR(film.mean(x, y).g, expected, 1e-5f) << name << " at (" << x << ", " << y << ")";
    }
}

// Guards against: an abort inside Embree (Debian's build asserts on rays
// whose origin lies past ±1.8e18) when a ray starts from a hit that far
// out. Expected: the camera sees a mirror plane 1e20 away (planes are
// intersected in double precision, outside Embree), and every ray from
// there misses: reflections show the black background and shadow rays
// reach the light, so `shadow` and `whitted` see what `raycast` (no
// shadows, no mirrors) sees.
TEST(Extremes, RaysFromHitsBeyondTheTraceableRange) {
    const std::string scene = R"(
camera { location <0, 0, 0> look_at <0, 0, 1> angle 60 }
light_source { <0, 10, -10> color rgb 1 }
plane { -z, -1e20 pigment { color rgb 0.5 } finish { ambient 0.2 diffuse 0.5 reflection 0.5 } }
sphere { <0, 0, -100>, 1 }  // out of view: the BVH is not empty
)";
    const Film lit = render(scene, "raycast", quick("raycast"), 16, 12);
    ASSERT_TRUE(all_finite(lit));
    ASSERT_GT(lit.mean(8, 6).g, 0.1f);  // ambient and some diffuse
    for (const char* name : {"shadow", "whitted", "path"}) {
        const Film film = render(scene, name, quick(name), 16, 12, std::string(name) == "path" ? 2 : 1);
        EXPECT_TRUE(all_finite(film)) << name;
        if (std::string(name) == "path") continue;  // its own light transport
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x)
                ASSERT_NEAR(film.mean(x, y).g, lit.mean(x, y).g, 1e-4f) << name << " at (" << x << ", " << y << ")";
    }
}

// Guards against: the same abort for camera rays, whose origins an
// orthographic camera spreads over its right and up vectors (1e30 wide
// here, the location at the origin). Expected: every pixel's ray starts
// past the range (the nearest pixel centre lies 3e28 off the axis), so it
// misses the BVH but still meets the plane (tested in double precision):
// no abort, nothing non-finite, every pixel the plane's ambient green.
TEST(Extremes, CameraRaysFromBeyondTheTraceableRange) {
    const std::string scene = R"(
camera { orthographic location <0, 0, -5> right 1e30 * x up 1e30 * y look_at 0 }
light_source { <0, 10, -10> color rgb 1 }
sphere { 0, 1 pigment { color rgb <1, 0, 0> } }
plane { -z, -3 pigment { color rgb <0, 1, 0> } finish { ambient 1 diffuse 0 } }
)";
    for (const char* name : {"raycast", "whitted", "path"}) {
        const Film film = render(scene, name, quick(name), 16, 12, std::string(name) == "path" ? 2 : 1);
        EXPECT_TRUE(all_finite(film)) << name;
        if (std::string(name) == "path") continue;  // no ambient term
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x)
                ASSERT_NEAR(film.mean(x, y).g, 1.0f, 1e-4f) << name << " at (" << x << ", " << y << ")";
    }
}

// Guards against: an object whose bounds reach past Embree's range
// (±1.844e18) left out of the BVH's reach and never drawn (the image was
// black, in silence). Expected: a box 2e19 wide across the view and a sphere
// of radius 1e19 around everything show as they would at any size: the
// box's face (lit, diffuse) green, the sphere's inside (ambient 1) red; a shadow
// ray from the box towards the light is blocked by neither.
TEST(Extremes, ObjectsReachingPastTheTraceableRange) {
    const std::string scene = R"(
camera { location <0, 0, -5> look_at 0 }
light_source { <0, 0, -4> color rgb 1 }
sphere { 0, 1e19 pigment { color rgb <1, 0, 0> } finish { ambient 1 diffuse 0 } }
box { <-1e19, -1, 0>, <1e19, 1, 1> pigment { color rgb <0, 1, 0> } finish { ambient 0 diffuse 1 } }
)";
    for (const char* name : {"raycast", "shadow", "whitted"}) {
        const Film film = render(scene, name, quick(name), 16, 12);
        ASSERT_TRUE(all_finite(film)) << name;
        const Color middle = film.mean(8, 6);  // the box's face, lit head-on
        EXPECT_GT(middle.g, 0.5f) << name;
        EXPECT_NEAR(middle.r, 0.0f, 1e-4f) << name;
        const Color top = film.mean(8, 0);  // above the box: the sphere's inside
        EXPECT_NEAR(top.r, 1.0f, 1e-4f) << name;
        EXPECT_NEAR(top.g, 0.0f, 1e-4f) << name;
    }
}

// Guards against: coincident surfaces (z-fighting) shadowing each other, a
// shadow ray leaving one and hitting its twin at t ~ 0. Expected: two
// coincident planes, one red and one green, lit head-on by a directional
// light: each pixel shows one of them fully lit (red or green radiance 1),
// never a shadowed mix.
TEST(Extremes, CoincidentSurfaces) {
    const std::string scene = R"(
camera { location <0, 5, -0.01> look_at <0, 0, 0> angle 60 }
light_source { <0, 1, 0> color rgb 1 parallel point_at <0, 0, 0> }
plane { y, 0 pigment { color rgb <1, 0, 0> } finish { ambient 0 diffuse 1 } }
plane { y, 0 pigment { color rgb <0, 1, 0> } finish { ambient 0 diffuse 1 } }
box { <-1, -1, -1>, <1, 0, 1> pigment { color rgb <0, 0, 1> } finish { ambient 0 diffuse 1 } }
)";
    for (const char* name : {"raycast", "shadow", "whitted", "path"}) {
        Parameters p = quick(name);
        if (std::string(name) == "path") p["max_depth"] = "1";
        const Film film = render(scene, name, p, 24, 18, 1);
        EXPECT_TRUE(all_finite(film)) << name;
        long shadowed = 0;
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x) {
                const Color c = film.mean(x, y);
                if (std::max({c.r, c.g, c.b}) < 0.99f) ++shadowed;
            }
        EXPECT_EQ(shadowed, 0) << name << ": coincident surfaces shadow each other";
    }
}

// Guards against: zero-size lights dividing by their area or radius
// (radiance = C / area) into Inf and then NaN. Expected: the parser refuses
// them with a located diagnostic; a scene graph built in code (no parser)
// with such lights either fails to compile with a SceneError or renders
// finite; never NaN or a crash.
TEST(Extremes, ZeroAreaAndZeroRadiusLights) {
    const std::string base = R"(
camera { location <0, 2, -5> look_at <0, 0.5, 0> }
plane { y, 0 pigment { color rgb 1 } }
sphere { <0, 1, 0>, 0.5 pigment { color rgb 1 } }
)";
    const std::pair<std::string, std::string> refused[] = {
        {"light_source { <0, 3, 0> color rgb 1 area_rectangle <0, 0, 0>, <0, 0, 1> }", "area_rectangle axes"},
        {"light_source { <0, 3, 0> color rgb 1 area_rectangle <1, 0, 0>, <2, 0, 0> }", "area_rectangle axes"},
        {"light_source { <0, 3, 0> color rgb 1 area_sphere 0 }", "area_sphere radius"},
    };
    for (const auto& [light, message] : refused) {
        ParseOptions options;
        const ParseResult parsed = parse_scene_string(base + light, "<extremes>", options);
        ASSERT_FALSE(parsed.ok()) << light;
        ASSERT_FALSE(parsed.diagnostics.empty());
        EXPECT_NE(parsed.diagnostics.front().message.find(message), std::string::npos)
            << format_diagnostic(parsed.diagnostics.front());
        EXPECT_EQ(parsed.diagnostics.front().location.line, 5) << light;
    }
    // The same lights built in code, past the parser's checks.
    sg::SceneGraph graph = parse(base +
                                     "light_source { <0, 3, 0> color rgb 1 area_rectangle <1, 0, 0>, <0, 0, 1> }\n"
                                     "light_source { <1, 3, 0> color rgb 1 area_sphere 0.5 }\n",
                                 16, 12);
    ASSERT_EQ(graph.lights.size(), 2u);
    for (int variant = 0; variant < 3; ++variant) {
        sg::SceneGraph degenerate = graph;
        if (variant == 0) degenerate.lights[0].axis1 = sg::Vec3(0.0);
        if (variant == 1) degenerate.lights[0].axis2 = degenerate.lights[0].axis1;
        if (variant == 2) degenerate.lights[1].radius = 0.0;
        for (const char* name : kAllIntegrators) {
            try {
                const Film film = render_graph(degenerate, name, quick(name), 16, 12, 2);
                EXPECT_TRUE(all_finite(film)) << name << " with degenerate light " << variant;
                std::cout << "[ zero     ] " << name << " renders degenerate light " << variant << ": max "
                          << max_value(film) << "\n";
            } catch (const SceneError& e) {
                std::cout << "[ zero     ] " << name << " refuses degenerate light " << variant << ": " << e.what()
                          << "\n";
            }
        }
    }
}

// Guards against: overflow and 0 x Inf with extreme light intensities.
// Expected: colour 0 gives the ambient term only (ambient 0.1 x pigment 1)
// for the simple-model integrators and black for path; colour 1e30 gives
// exactly 1e30 times the image of colour 1 (ambient 0), all finite.
TEST(Extremes, ZeroAndHugeIntensities) {
    auto scene = [](const char* intensity, const char* ambient) {
        return std::string("camera { location <0, 2, -5> look_at <0, 0.5, 0> }\n") +
               "light_source { <2, 4, -3> color rgb " + intensity + " }\n" + "light_source { <-2, 3, 0> color rgb " +
               intensity + " area_rectangle <1, 0, 0>, <0, 0, 1> }\n" +
               "plane { y, 0 pigment { color rgb 1 } finish { ambient " + ambient + " diffuse 0.8 } }\n" +
               "sphere { <0, 1, 0>, 0.6 pigment { color rgb 1 } finish { ambient " + ambient +
               " diffuse 0.8 phong 0.5 reflection 0.3 } }\n";
    };
    for (const char* name : kAllIntegrators) {
        const bool path = std::string(name) == "path";
        const int spp = path || std::string(name) == "gather" ? 4 : 1;
        const Film dark = render(scene("0", "0.1"), name, quick(name), 16, 12, spp);
        EXPECT_TRUE(all_finite(dark)) << name;
        // Every geometry pixel (the lower half is plane or sphere).
        for (int x = 0; x < dark.width(); ++x) {
            const float v = dark.mean(x, dark.height() - 1).g;
            if (path)
                EXPECT_EQ(v, 0.0f) << name;
            else if (std::string(name) != "gather")
                EXPECT_NEAR(v, 0.1f, 1e-5f) << name;  // gather has no ambient
            else
                EXPECT_EQ(v, 0.0f) << name;
        }
        const Film one = render(scene("1", "0"), name, quick(name), 16, 12, spp);
        const Film huge = render(scene("1e30", "0"), name, quick(name), 16, 12, spp);
        EXPECT_TRUE(all_finite(huge)) << name;
        for (int y = 0; y < one.height(); ++y)
            for (int x = 0; x < one.width(); ++x) {
                const float a = one.mean(x, y).g, b = huge.mean(x, y).g;
                if (a > 1e-6f)
                    ASSERT_NEAR(b / a, 1e30f, 1e25f) << name << " at (" << x << ", " << y << ")";
                else
                    ASSERT_LE(b, 1e30f * 1e-5f) << name << " at (" << x << ", " << y << ")";
            }
    }
}

// Guards against: zero-area triangles in an OBJ (repeated vertex, collinear
// vertices) producing NaN normals, crashing the loader or Embree.
// Expected: they are invisible; the one good triangle renders as without
// them.
TEST(Extremes, ZeroAreaTrianglesInAnObj) {
    const auto folder = std::filesystem::temp_directory_path() / ("lancer_extremes_" + std::to_string(::getpid()));
    std::filesystem::create_directories(folder);
    const auto write_obj = [&](const std::string& file, bool degenerate) {
        std::ofstream obj(folder / file);
        obj << "v -1 0 0\nv 1 0 0\nv 0 1.5 0\nv 0.5 0.5 0\nv 2 2 0\nv 3 3 0\n";
        obj << "f 1 2 3\n";
        if (degenerate) obj << "f 1 1 2\nf 4 5 6\nf 2 2 2\nf 3 3 1\n";  // repeated and collinear
    };
    write_obj("good.obj", false);
    write_obj("degenerate.obj", true);
    auto scene = [&](const std::string& file) {
        return "camera { location <0, 0.7, -4> look_at <0, 0.7, 0> }\n"
               "light_source { <0, 2, -5> color rgb 20 }\n"
               "obj_mesh { \"" +
               (folder / file).string() + "\" pigment { color rgb 1 } }\n";
    };
    for (const char* name : kAllIntegrators) {
        const int spp = std::string(name) == "path" || std::string(name) == "gather" ? 4 : 1;
        const Film good = render(scene("good.obj"), name, quick(name), 24, 18, spp);
        const Film degenerate = render(scene("degenerate.obj"), name, quick(name), 24, 18, spp);
        EXPECT_TRUE(all_finite(degenerate)) << name;
        EXPECT_LT(relative_difference(degenerate, good), 1e-4) << name;
    }
    std::filesystem::remove_all(folder);
}

// A closed mirror box with a light and a matte sphere: every ray bounces.
const char* kMirrorRoom = R"(
global_settings { max_trace_level 256 adc_bailout 0 }
camera { location <0, 1, -1.5> look_at <0, 1, 0> angle 70 }
light_source { <0, 1.8, 0> color rgb 1 }
sphere { <0, 1.9, 0>, 0.05 pigment { color rgb 1 } finish { emission 2 diffuse 0 ambient 0 } }
sphere { <0, 0.5, 0.5>, 0.4 pigment { color rgb <0.8, 0.5, 0.3> } finish { ambient 0.1 diffuse 0.7 } }
box { <-2, 0, -2>, <2, 2, 2> pigment { color rgb 1 } finish { ambient 0 diffuse 0 reflection 0.999 } }
)";

// Guards against: gather's lattice degenerate at n = 1 (one direction:
// the normal itself) and slow or overflowing at n = 10000. Expected: both
// finite; n = 10000 is the converged one-bounce estimate, n = 1 an unbiased
// but poorer estimate of the same image (means within 25%).
TEST(Extremes, GatherWithOneAndTenThousandDirections) {
    const std::string scene = R"(
camera { location <0, 1, -3> look_at <0, 0.6, 0> }
light_source { <0, 2.5, 0> color rgb 2 area_rectangle <1, 0, 0>, <0, 0, 1> }
plane { y, 0 pigment { color rgb 0.8 } finish { diffuse 1 } }
sphere { <0, 0.6, 0>, 0.6 pigment { color rgb <0.8, 0.4, 0.2> } finish { diffuse 1 } }
)";
    const Film one = render(scene, "gather", {{"n", "1"}}, 8, 6, 64);
    const Film many = render(scene, "gather", {{"n", "10000"}}, 8, 6, 1);
    EXPECT_TRUE(all_finite(one));
    EXPECT_TRUE(all_finite(many));
    double sum_one = 0.0, sum_many = 0.0;
    for (int y = 0; y < 6; ++y)
        for (int x = 0; x < 8; ++x) {
            sum_one += one.mean(x, y).g;
            sum_many += many.mean(x, y).g;
        }
    EXPECT_GT(sum_many, 0.0);
    EXPECT_NEAR(sum_one / sum_many, 1.0, 0.25);
}

// Guards against: unbounded recursion (stack overflow) and runaway weights
// with max depth 1000, and off-by-one at max depth 0. Expected:
//   whitted max_depth 1000 is refused (its limit is 256, POV-Ray's);
//   whitted max_depth 256 in a mirror room terminates, finite, and
//   max_depth 0 (the scene's max_trace_level, 256) gives the same image;
//   path max_depth 0 shows emission only (the lamp sphere; all else black);
//   path max_depth 1000 in a mirror room terminates, finite.
TEST(Extremes, WhittedAndPathDepthZeroAndThousand) {
    EXPECT_THROW(render(kMirrorRoom, "whitted", {{"max_depth", "1000"}}, 4, 3), std::exception);
    const Film deep = render(kMirrorRoom, "whitted", {{"max_depth", "256"}}, 16, 12);
    EXPECT_TRUE(all_finite(deep));
    EXPECT_GT(max_value(deep), 0.0f);
    // max_depth 0 means the scene's max_trace_level (256 here): the same image.
    const Film scene_depth = render(kMirrorRoom, "whitted", {{"max_depth", "0"}}, 16, 12);
    EXPECT_EQ(relative_difference(scene_depth, deep), 0.0);

    const Film emission_only = render(kMirrorRoom, "path", {{"max_depth", "0"}}, 16, 12, 4);
    EXPECT_TRUE(all_finite(emission_only));
    EXPECT_EQ(max_value(emission_only), 0.0f) << "the lamp sphere is out of view: everything is black";

    const Film very_deep = render(kMirrorRoom, "path", {{"max_depth", "1000"}}, 16, 12, 4);
    EXPECT_TRUE(all_finite(very_deep));
    EXPECT_GT(max_value(very_deep), 0.0f);
}

// Guards against: whitted taking the scene's max_trace_level without a cap
// (100000 levels of recursion overflow the stack). Expected: the parser
// refuses max_trace_level outside 1..256 (POV-Ray's limit), and a scene
// graph built in code with 100000 renders, whitted clamping it to 256.
TEST(Extremes, SceneMaxTraceLevelHuge) {
    std::string text = kMirrorRoom;
    text.replace(text.find("max_trace_level 256"), 19, "max_trace_level 100000");
    const ParseResult parsed = parse_scene_string(text, "<extremes>", ParseOptions{});
    ASSERT_FALSE(parsed.ok());
    EXPECT_NE(parsed.diagnostics.front().message.find("max_trace_level"), std::string::npos);

    sg::SceneGraph graph = parse(kMirrorRoom, 8, 6);
    graph.global.max_trace_level = 100000;
    const Film film = render_graph(graph, "whitted", {}, 8, 6);
    EXPECT_TRUE(all_finite(film));
    EXPECT_GT(max_value(film), 0.0f);
}

}  // namespace
}  // namespace lancer
