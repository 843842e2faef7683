// Checker and image_map lookups through the compiled scene.
#include <gtest/gtest.h>

#include <filesystem>

#include <OpenImageIO/imageio.h>

#include "lancer/host/scene_compiler.h"
#include "lancer/render_scene.h"
#include "lancer/scene_error.h"
#include "materials/palette_png_test_support.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;
namespace fs = std::filesystem;

Color pigment_at(const RenderScene& scene, const Ray& ray) {
    Hit hit;
    EXPECT_TRUE(scene.intersect(ray, hit));
    return hit.material->sample_surface(hit).pigment;
}

TEST(Textures, CheckerAlternatesUnitCellsInPatternSpace) {
    auto m = std::make_shared<sg::Material>();
    m->pigment = sg::checker_pigment({1, 1, 1}, {0, 1, 0});
    sg::SceneGraph graph;
    graph.objects.push_back(plane_object({0, 1, 0}, 0.0, m));
    auto scene = compile_scene(graph);
    const Vec3 down(0, -1, 0);
    EXPECT_EQ(pigment_at(*scene, make_ray(Vec3(0.5f, 1, 0.5f), down)), Color(1, 1, 1));
    EXPECT_EQ(pigment_at(*scene, make_ray(Vec3(1.5f, 1, 0.5f), down)), Color(0, 1, 0));
    EXPECT_EQ(pigment_at(*scene, make_ray(Vec3(1.5f, 1, 1.5f), down)), Color(1, 1, 1));
    EXPECT_EQ(pigment_at(*scene, make_ray(Vec3(-0.5f, 1, 0.5f), down)), Color(0, 1, 0));

    // Scaled by 2 in the pigment, and moved with the object by +1 x.
    auto scaled = std::make_shared<sg::Material>(*m);
    scaled->pigment.pattern->pattern_from_object = glm::scale(glm::dmat4(1.0), glm::dvec3(0.5));
    sg::Object plane = plane_object({0, 1, 0}, 0.0, scaled);
    plane.parent_from_object = glm::translate(glm::dmat4(1.0), glm::dvec3(1, 0, 0));
    sg::SceneGraph moved;
    moved.objects.push_back(plane);
    scene = compile_scene(moved);
    EXPECT_EQ(pigment_at(*scene, make_ray(Vec3(2.5f, 1, 0.5f), down)), Color(1, 1, 1));
    EXPECT_EQ(pigment_at(*scene, make_ray(Vec3(3.5f, 1, 0.5f), down)), Color(0, 1, 0));
}

// A 2x2 PNG: red, green / blue, sRGB grey 188 (linear ~0.5).
std::string write_test_png(const fs::path& dir) {
    const std::string path = (dir / "tex.png").string();
    const unsigned char pixels[] = {255, 0, 0, 0, 255, 0, 0, 0, 255, 188, 188, 188};
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(2, 2, 3, OIIO::TypeDesc::UINT8);
    EXPECT_TRUE(out->open(path, spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::UINT8, pixels));
    out->close();
    return path;
}

TEST(Textures, ImageMapThroughUvDecodesSrgb) {
    const fs::path dir = fs::temp_directory_path() / ("lancer_texture_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto m = std::make_shared<sg::Material>();
    m->pigment.kind = sg::Pigment::Kind::Image;
    m->pigment.image->path = write_test_png(dir);
    m->pigment.image->map_type = sg::MapType::UV;
    m->pigment.image->interpolate = 0;  // nearest texel: exact values
    sg::SceneGraph graph;
    // A plane's (u, v) is the hit's world (x, y), as POV-Ray's; v = 1 is
    // the image's top.
    graph.objects.push_back(plane_object({0, 0, -1}, 0.0, m));
    auto scene = compile_scene(graph);
    const Vec3 ahead(0, 0, 1);
    const Color top_left = pigment_at(*scene, make_ray(Vec3(0.25f, 0.75f, -1), ahead));
    const Color top_right = pigment_at(*scene, make_ray(Vec3(0.75f, 0.75f, -1), ahead));
    const Color bottom_left = pigment_at(*scene, make_ray(Vec3(0.25f, 0.25f, -1), ahead));
    const Color bottom_right = pigment_at(*scene, make_ray(Vec3(0.75f, 0.25f, -1), ahead));
    EXPECT_NEAR(top_left.r, 1.0f, 1e-3f);
    EXPECT_NEAR(top_left.g, 0.0f, 1e-3f);
    EXPECT_NEAR(top_right.g, 1.0f, 1e-3f);
    EXPECT_NEAR(bottom_left.b, 1.0f, 1e-3f);
    EXPECT_NEAR(bottom_right.r, 0.5029f, 2e-3f);  // sRGB 188 decoded to linear
    fs::remove_all(dir);
}

// A 2x2 palette PNG whose entries 0 and 2 are the same red: indices 2, 1
// on the top row, 0, 3 on the bottom.
std::string write_palette_png(const fs::path& dir) {
    const std::string path = (dir / "palette.png").string();
    testing::write_palette_png(path, 2, 2, {255, 0, 0, 0, 255, 0, 255, 0, 0, 0, 0, 255}, {2, 1, 0, 3});
    return path;
}

struct PaletteSample {
    SurfaceSample top_left, top_right, bottom_left, bottom_right, centre;
};

PaletteSample sample_palette(const std::string& path, std::vector<sg::PaletteSetting> settings, int interpolate = 0) {
    auto m = std::make_shared<sg::Material>();
    m->pigment.kind = sg::Pigment::Kind::Image;
    m->pigment.image->path = path;
    m->pigment.image->map_type = sg::MapType::UV;
    m->pigment.image->interpolate = interpolate;
    m->pigment.image->palette_settings = std::move(settings);
    sg::SceneGraph graph;
    // A plane's (u, v) is the hit's world (x, y), as POV-Ray's.
    graph.objects.push_back(plane_object({0, 0, -1}, 0.0, m));
    auto scene = compile_scene(graph);
    auto at = [&](float x, float y) {
        Hit hit;
        EXPECT_TRUE(scene->intersect(make_ray(Vec3(x, y, -1), Vec3(0, 0, 1)), hit));
        return hit.material->sample_surface(hit);
    };
    return {at(0.25f, 0.75f), at(0.75f, 0.75f), at(0.25f, 0.25f), at(0.75f, 0.25f), at(0.5f, 0.5f)};
}

sg::PaletteSetting setting(bool transmit, int index, double value) {
    sg::PaletteSetting s;
    s.transmit = transmit;
    s.index = index;
    s.value = value;
    s.location.line = 9;
    s.location.column = 4;
    return s;
}

// The entry a pixel uses decides its filter and transmit, even where two
// entries share a colour; later settings override earlier ones.
TEST(Textures, PaletteSettingsFollowTheIndexNotTheColour) {
    const fs::path dir = fs::temp_directory_path() / ("lancer_palette_test_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    const std::string path = write_palette_png(dir);
    const std::vector<sg::PaletteSetting> settings = {setting(true, 2, 1.0), setting(false, -1, 0.25),
                                                      setting(true, 3, 0.5), setting(false, 3, 0.0)};
    const PaletteSample nearest = sample_palette(path, settings);
    EXPECT_NEAR(nearest.top_left.pigment.r, 1.0f, 1e-3f);  // entry 2: red, clear
    EXPECT_FLOAT_EQ(nearest.top_left.transmit, 1.0f);
    EXPECT_FLOAT_EQ(nearest.top_left.filter, 0.25f);
    EXPECT_FLOAT_EQ(nearest.top_right.transmit, 0.0f);  // entry 1
    EXPECT_FLOAT_EQ(nearest.top_right.filter, 0.25f);
    EXPECT_NEAR(nearest.bottom_left.pigment.r, 1.0f, 1e-3f);  // entry 0: the same red, opaque
    EXPECT_FLOAT_EQ(nearest.bottom_left.transmit, 0.0f);
    EXPECT_FLOAT_EQ(nearest.bottom_right.transmit, 0.5f);  // entry 3
    EXPECT_FLOAT_EQ(nearest.bottom_right.filter, 0.0f);
    // Interpolated, the four entries blend at the image's centre.
    const PaletteSample blended = sample_palette(path, settings, 2);
    EXPECT_NEAR(blended.centre.transmit, (1.0f + 0.0f + 0.0f + 0.5f) / 4.0f, 1e-5f);
    EXPECT_NEAR(blended.centre.filter, (0.25f * 3.0f) / 4.0f, 1e-5f);
    fs::remove_all(dir);
}

TEST(Textures, PaletteSettingsNeedAPaletteAndAnEntry) {
    const fs::path dir = fs::temp_directory_path() / ("lancer_palette_errors_" + std::to_string(::getpid()));
    fs::create_directories(dir);
    auto expect_error = [](const std::string& path, const sg::PaletteSetting& s, const std::string& words) {
        try {
            sample_palette(path, {s});
            ADD_FAILURE() << "expected a SceneError with '" << words << "'";
        } catch (const SceneError& e) {
            EXPECT_EQ(e.location().line, 9);
            EXPECT_EQ(e.location().column, 4);
            EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
        }
    };
    expect_error(write_palette_png(dir), setting(false, 4, 0.5), "has 4 palette entries (0 to 3)");
    expect_error(write_test_png(dir), setting(true, 1, 0.5), "has no palette");
    // `transmit all` needs no palette.
    EXPECT_FLOAT_EQ(sample_palette(write_test_png(dir), {setting(true, -1, 0.5)}).top_left.transmit, 0.5f);
    fs::remove_all(dir);
}

TEST(Textures, MissingImageIsASceneErrorAtTheImageMap) {
    auto m = std::make_shared<sg::Material>();
    m->pigment.kind = sg::Pigment::Kind::Image;
    m->pigment.image->path = "/nonexistent/lancer/image.png";
    m->pigment.image->location.line = 42;
    m->pigment.image->location.column = 7;
    sg::SceneGraph graph;
    graph.objects.push_back(sphere_object({0, 0, 0}, 1.0, m));
    try {
        compile_scene(graph);
        FAIL() << "expected a SceneError";
    } catch (const SceneError& e) {
        EXPECT_EQ(e.location().line, 42);
        EXPECT_EQ(e.location().column, 7);
        EXPECT_NE(std::string(e.what()).find("image.png"), std::string::npos);
    }
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// POV bends the normal turned towards the ray: a slope seen from either
// side of a surface tilts the same way in the viewer's frame.
TEST(Normals, BentTowardsTheRayOnEitherSide) {
    auto m = std::make_shared<sg::Material>();
    auto normal = std::make_shared<sg::Normal>();
    normal->pattern->kind = sg::Pattern::Kind::Gradient;
    normal->pattern->vector = {1, 0, 0};
    normal->bump_size = 1.0;
    m->normal = normal;
    sg::SceneGraph graph;
    graph.objects.push_back(plane_object({0, 0, -1}, 0.0, m));
    auto scene = compile_scene(graph);
    Hit front, back;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0.3f, 0.2f, -1), Vec3(0, 0, 1)), front));
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0.3f, 0.2f, 1), Vec3(0, 0, -1)), back));
    const Vec3 seen_front = front.facing_normal(Vec3(0, 0, -1));
    const Vec3 seen_back = back.facing_normal(Vec3(0, 0, 1));
    EXPECT_GT(std::fabs(seen_front.x), 0.05f);  // the gradient does bend it
    EXPECT_NEAR(seen_front.x, seen_back.x, 1e-5f);
    EXPECT_NEAR(seen_front.z, -seen_back.z, 1e-5f);
    EXPECT_NEAR(glm::length(front.shading_normal), 1.0f, 1e-5f);
}

}  // namespace
}  // namespace lancer
