// Scenes with participating media for the whitted and path tests: scene
// text compiled as the command line compiles it. Test-only.
#pragma once

#include <memory>
#include <string>

#include <gtest/gtest.h>

#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"

#include "seed_integrators_test.h"

namespace lancer::media_test {

inline std::unique_ptr<RenderScene> scene_from(const std::string& text) {
    // Snippets are POV-Ray 3.7 scenes (+MV3.7): without it one with no
    // #version is read as 3.62 and warns about gamma.
    ParseOptions options;
    options.language_version = 3.7;
    ParseResult parsed = parse_scene_string(text, "<string>", options);
    for (const auto& d : parsed.diagnostics) ADD_FAILURE() << format_diagnostic(d);
    if (!parsed.ok()) return nullptr;
    return compile_scene(std::move(*parsed.scene));
}

// A slab 1 thick (z in [0, 1]) of a hollow, fully transmitting box whose
// interior holds `media`, seen along +z from z = -5 against `background`;
// `extra` adds lights or settings.
inline std::string slab(const std::string& media, double background, const std::string& extra = "") {
    return "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
           "background { rgb " +
           std::to_string(background) +
           " }\n"
           "box { <-3, -3, 0>, <3, 3, 1> pigment { rgbt 1 } finish { ambient 0 diffuse 0 } hollow\n"
           "      interior { media { " +
           media + " } } }\n" + extra;
}

inline const Ray kAlongZ = seed_test::ray_towards({0.0f, 0.0f, -5.0f}, {0.0f, 0.0f, 0.0f});

// Isotropic scattering (POV's k = 1, coefficient 0.1) of a parallel light
// from above, in front of a black wall 4 along kAlongZ: the single
// scattering integral is 1 - exp(-0.4) in the open. `roofed` adds an opaque
// slab between the light and the ray.
inline std::string scattering_under_parallel_light(bool roofed) {
    return std::string(
               "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
               "light_source { <0, 100, 0> color rgb 1 parallel point_at <0, 0, 0> }\n"
               "plane { -z, 1 pigment { rgb 0 } finish { ambient 0 diffuse 0 } }\n"
               "media { scattering { 1, 0.1 } intervals 400 samples 2 }\n") +
           (roofed ? "box { <-50, 5, -50>, <50, 6, 50> pigment { rgb 1 } }\n" : "");
}

// What `integrator` sees along `ray` in the scene `text` (-1 if it does not parse).
inline Color radiance_in(const std::string& integrator, const std::string& text, const Ray& ray = kAlongZ) {
    const auto scene = scene_from(text);
    if (!scene) return Color(-1.0f);
    const auto loaded = seed_test::load_integrator(integrator, *scene);
    return seed_test::mean_radiance(*loaded, *scene, ray);
}

inline void expect_colour(const Color& seen, const Color& expected, float tolerance) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(seen[k], expected[k], tolerance) << "channel " << k;
}

}  // namespace lancer::media_test
