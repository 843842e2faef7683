// Patterns, maps, normals, patterned and layered textures and #default as
// the parser reads them: the scene graph POV-Ray's rules give.
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include <glm/gtc/matrix_transform.hpp>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

sg::Vec3 apply(const sg::Mat4& m, const sg::Vec3& p) {
    return sg::Vec3(m * glm::dvec4(p, 1.0));
}

// A file with an image's name and no image in it, in a folder of its own
// removed afterwards: the parser checks that a named image exists, not
// what it holds.
struct PlaceholderImage {
    std::filesystem::path dir;
    std::string path;
    PlaceholderImage(const std::string& tag, const std::string& name)
        : dir(std::filesystem::temp_directory_path() / ("lancer_" + tag + "_" + std::to_string(::getpid()))),
          path((dir / name).string()) {
        std::filesystem::create_directories(dir);
        std::ofstream(path) << "x";
    }
    ~PlaceholderImage() { std::filesystem::remove_all(dir); }
};

const sg::Material& material_of(const sg::SceneGraph& scene, std::size_t i = 0) {
    static const sg::Material none;
    if (i >= scene.objects.size() || !scene.objects[i].material) {
        ADD_FAILURE() << "object " << i << " has no material";
        return none;
    }
    return *scene.objects[i].material;
}

TEST(ParserPatterns, ColorMapBothFormsAndDefaults) {
    auto scene = parse_ok(
        "plane { y, 0 pigment { gradient x color_map { [0 rgb 0] [0.5, 0.8 rgb 1 rgbt <1, 0, 0, 0.5>] } } }\n"
        "plane { y, 0 pigment { wood } }\n"
        "plane { y, 0 pigment { granite } }");
    const sg::Pigment& p = material_of(scene, 0).pigment;
    ASSERT_EQ(p.kind, sg::Pigment::Kind::Patterned);
    EXPECT_EQ(p.pattern->kind, sg::Pattern::Kind::Gradient);
    ASSERT_TRUE(p.color_map);
    ASSERT_EQ(p.color_map->size(), 3u);  // the old [v1 v2 c1 c2] form is two entries
    EXPECT_DOUBLE_EQ((*p.color_map)[1].value, 0.5);
    EXPECT_DOUBLE_EQ((*p.color_map)[2].value, 0.8);
    EXPECT_DOUBLE_EQ((*p.color_map)[2].color.transmit, 0.5);
    // POV's own map for wood, and its triangle wave; a plain ramp for the rest.
    const sg::Pigment& wood = material_of(scene, 1).pigment;
    ASSERT_TRUE(wood.color_map);
    EXPECT_EQ(wood.color_map->size(), 2u);
    EXPECT_NEAR((*wood.color_map)[0].color.rgb.x, 0.666, 1e-12);
    EXPECT_EQ(wood.pattern->wave, sg::WaveType::Triangle);
    const sg::Pigment& granite = material_of(scene, 2).pigment;
    ASSERT_TRUE(granite.color_map);
    EXPECT_EQ(granite.pattern->wave, sg::WaveType::Ramp);
    EXPECT_EQ(granite.color_map->back().color.rgb, sg::Vec3(1.0));
}

// POV reads a map entry's colour without the colour keyword too
// ([0 blue 0.4], whiltile.pov), and the old two-colour form with one.
TEST(ParserPatterns, ColorMapEntryTakesABareColour) {
    auto scene = parse_ok(
        "plane { y, 0 pigment { gradient x color_map { [0 blue 0.4] [0.2 green 0.3 red 0.1] [0.5 0.8 rgb 1, red 0.5] } "
        "} }");
    const sg::Pigment& p = material_of(scene, 0).pigment;
    ASSERT_TRUE(p.color_map);
    ASSERT_EQ(p.color_map->size(), 4u);
    EXPECT_EQ((*p.color_map)[0].color.rgb, sg::Vec3(0.0, 0.0, 0.4));
    EXPECT_EQ((*p.color_map)[1].color.rgb, sg::Vec3(0.1, 0.3, 0.0));
    EXPECT_EQ((*p.color_map)[3].color.rgb, sg::Vec3(0.5, 0.0, 0.0));
}

TEST(ParserPatterns, DeclaredMapsAndNormalsReusable) {
    auto scene = parse_ok(
        "#declare M = color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] }\n"
        "#declare PM = pigment_map { [0 rgb 1] [1 checker rgb 0, rgb 1] }\n"
        "#declare N = normal { bumps 0.3 scale 0.2 }\n"
        "sphere { 0, 1 pigment { bozo color_map { M } } normal { N } }\n"
        "sphere { 0, 1 pigment { onion pigment_map { PM } } }");
    const sg::Material& a = material_of(scene, 0);
    ASSERT_TRUE(a.pigment.color_map);
    EXPECT_EQ(a.pigment.color_map->front().color.rgb, sg::Vec3(1, 0, 0));
    ASSERT_TRUE(a.normal);
    EXPECT_EQ(a.normal->pattern->kind, sg::Pattern::Kind::Bumps);
    EXPECT_NEAR(a.normal->bump_size, 0.3, 1e-12);
    const sg::Material& b = material_of(scene, 1);
    ASSERT_EQ(b.pigment.pigment_map.size(), 2u);
    EXPECT_EQ(b.pigment.pigment_map[1].pigment->pattern->kind, sg::Pattern::Kind::Checker);
}

TEST(ParserPatterns, TransformsAndWarpsKeepTheirOrder) {
    auto scene = parse_ok(
        "plane { y, 0 pigment { bozo scale 2 warp { turbulence 0.5 } translate x } }\n"
        "plane { y, 0 pigment { bozo warp { repeat x * 0.5 flip y } } }");
    const sg::Pattern& p = *material_of(scene, 0).pigment.pattern;
    ASSERT_EQ(p.warps.size(), 2u);  // the scale before the warp becomes a step of its own
    EXPECT_EQ(p.warps[0].kind, sg::Warp::Kind::Transform);
    EXPECT_EQ(p.warps[1].kind, sg::Warp::Kind::Turbulence);
    EXPECT_EQ(p.warps[1].turbulence, sg::Vec3(0.5));
    // The translate after the warp is what the point meets first.
    EXPECT_EQ(apply(p.pattern_from_object, {1, 0, 0}), sg::Vec3(0, 0, 0));
    EXPECT_EQ(apply(p.warps[0].inner_from_outer, {2, 0, 0}), sg::Vec3(1, 0, 0));
    const sg::Warp& repeat = material_of(scene, 1).pigment.pattern->warps.at(0);
    EXPECT_EQ(repeat.kind, sg::Warp::Kind::Repeat);
    EXPECT_EQ(repeat.repeat, sg::Vec3(0.5, 0, 0));
    EXPECT_EQ(repeat.flip, sg::Vec3(0, 1, 0));
}

// POV-Ray reads a new colour or pattern after a pigment or normal
// identifier: the pattern changes and the identifier's moves, warps and
// turbulence stay. Its map stays too, unless the pattern had it only by
// default; a block pattern's list becomes a map with entry i at value i;
// a block pattern brings its own list. (Each case checked against
// povray 3.7's pixels.)
TEST(ParserPatterns, ANewPatternAfterAnIdentifierKeepsItsMovesAndMap) {
    auto scene = parse_ok(
        "#declare Blocks = pigment { checker rgb <1, 0, 0>, rgb <0, 0, 1> scale 0.5 }\n"
        "#declare Mapped = pigment { bozo color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } turbulence 0.5 }\n"
        "#declare Bare = pigment { bozo scale 0.3 }\n"
        "#declare Bumpy = normal { bumps 0.8 scale 0.2 }\n"
        "#declare Tiled = normal { checker normal { bumps 0.5 } normal { dents 0.5 } }\n"
        "plane { z, 0 pigment { Blocks } }\n"
        "plane { z, 0 pigment { Blocks checker rgb 0, rgb 1 } }\n"
        "plane { z, 0 pigment { Blocks gradient x } }\n"
        "plane { z, 0 pigment { Mapped gradient x } }\n"
        "plane { z, 0 pigment { Bare gradient x } }\n"
        "plane { z, 0 pigment { Mapped hexagon } }\n"
        "plane { z, 0 normal { Bumpy dents 0.9 } }\n"
        "plane { z, 0 pigment { Mapped rgb 0.5 } }\n"
        "plane { z, 0 normal { Tiled wrinkles } }\n");
    const sg::Pigment& blocks = material_of(scene, 0).pigment;
    const sg::Pigment& checker = material_of(scene, 1).pigment;
    EXPECT_EQ(checker.pattern->kind, sg::Pattern::Kind::Checker);
    EXPECT_EQ(checker.pattern->pattern_from_object, blocks.pattern->pattern_from_object);
    ASSERT_EQ(checker.block_pigments.size(), 2u);
    EXPECT_EQ(checker.block_pigments[1]->color.rgb, sg::Vec3(1));

    const sg::Pigment& from_blocks = material_of(scene, 2).pigment;
    EXPECT_EQ(from_blocks.pattern->kind, sg::Pattern::Kind::Gradient);
    EXPECT_EQ(from_blocks.pattern->pattern_from_object, blocks.pattern->pattern_from_object);
    EXPECT_TRUE(from_blocks.block_pigments.empty());
    EXPECT_FALSE(from_blocks.color_map);
    ASSERT_EQ(from_blocks.pigment_map.size(), 2u);
    EXPECT_EQ(from_blocks.pigment_map[1].value, 1.0);
    EXPECT_EQ(from_blocks.pigment_map[1].pigment->color.rgb, sg::Vec3(0, 0, 1));

    const sg::Pigment& from_mapped = material_of(scene, 3).pigment;
    EXPECT_EQ(from_mapped.pattern->kind, sg::Pattern::Kind::Gradient);
    EXPECT_EQ(from_mapped.pattern->turbulence, sg::Vec3(0.5));
    ASSERT_TRUE(from_mapped.color_map);
    EXPECT_EQ(from_mapped.color_map->front().color.rgb, sg::Vec3(1, 0, 0));

    // bozo's own colours were its default: gradient gets its own, grey.
    const sg::Pigment& from_bare = material_of(scene, 4).pigment;
    ASSERT_TRUE(from_bare.color_map);
    EXPECT_EQ(from_bare.color_map->front().color.rgb, sg::Vec3(0));
    EXPECT_EQ(from_bare.color_map->back().color.rgb, sg::Vec3(1));

    const sg::Pigment& hexagon = material_of(scene, 5).pigment;
    EXPECT_FALSE(hexagon.color_map);
    ASSERT_EQ(hexagon.block_pigments.size(), 3u);  // POV's defaults
    EXPECT_EQ(hexagon.block_pigments[0]->color.rgb, sg::Vec3(0, 0, 1));

    ASSERT_TRUE(material_of(scene, 6).normal);
    const sg::Normal& dents = *material_of(scene, 6).normal;
    EXPECT_EQ(dents.pattern->kind, sg::Pattern::Kind::Dents);
    EXPECT_NEAR(dents.bump_size, 0.9, 1e-12);
    EXPECT_EQ(apply(dents.pattern->pattern_from_object, {0.2, 0, 0}), sg::Vec3(1, 0, 0));

    const sg::Pigment& plain = material_of(scene, 7).pigment;
    EXPECT_EQ(plain.kind, sg::Pigment::Kind::Solid);
    EXPECT_EQ(plain.color.rgb, sg::Vec3(0.5));

    // A normal's block list, followed by a pattern that is not a block
    // pattern, becomes its map as a pigment's does.
    ASSERT_TRUE(material_of(scene, 8).normal);
    const sg::Normal& wrinkles = *material_of(scene, 8).normal;
    EXPECT_EQ(wrinkles.pattern->kind, sg::Pattern::Kind::Wrinkles);
    EXPECT_TRUE(wrinkles.block_normals.empty());
    ASSERT_EQ(wrinkles.normal_map.size(), 2u);
    EXPECT_EQ(wrinkles.normal_map[1].value, 1.0);
    EXPECT_EQ(wrinkles.normal_map[1].normal->pattern->kind, sg::Pattern::Kind::Dents);
}

// A texture's pigment edit keeps the map of the pigment it edits (POV-Ray).
TEST(ParserPatterns, APatternWrittenIntoATexturesPigmentKeepsItsMap) {
    auto scene = parse_ok(
        "#declare T = texture { pigment { gradient x color_map { [0 rgb <1, 0, 0>] [1 rgb <0, 0, 1>] } } }\n"
        "plane { z, 0 texture { T pigment { bozo } } }\n");
    const sg::Pigment& p = material_of(scene).pigment;
    EXPECT_EQ(p.pattern->kind, sg::Pattern::Kind::Bozo);
    ASSERT_TRUE(p.color_map);
    EXPECT_EQ(p.color_map->back().color.rgb, sg::Vec3(0, 0, 1));
}

// A plain colour keeps no pattern (sg::OnDemand): a loop of coloured
// objects would otherwise carry one each. The moves it meets still reach
// a pattern made later (uv_mapping here).
TEST(ParserPatterns, APlainColourKeepsNoPatternYetALaterPatternMeetsItsMoves) {
    auto scene = parse_ok(
        "#declare Moved = pigment { rgb 1 scale 2 }\n"
        "sphere { 0, 1 pigment { rgb <1, 0, 0> scale 3 } translate x }\n"
        "sphere { 0, 1 pigment { Moved uv_mapping } }\n"
        "sphere { 0, 1 pigment { Moved warp { turbulence 0.5 } } }\n"
        "sphere { 0, 1 uv_mapping pigment { rgb 1 scale 4 } translate y }\n");
    // Moved: the move is kept, no pattern made.
    const sg::Pigment& plain = material_of(scene, 0).pigment;
    EXPECT_FALSE(plain.pattern.has_value());
    EXPECT_FALSE(plain.image.has_value());
    EXPECT_EQ(apply(plain.pattern_from_object, {3, 0, 0}), sg::Vec3(1, 0, 0));
    EXPECT_EQ(apply(plain.pattern->pattern_from_object, {3, 0, 0}), sg::Vec3(3, 0, 0));  // the default's
    EXPECT_FALSE(plain.pattern.has_value());                                             // reading made none

    const sg::Pigment& uv = material_of(scene, 1).pigment;
    ASSERT_TRUE(uv.pattern.has_value());
    EXPECT_TRUE(uv.pattern->uv_mapping);
    EXPECT_EQ(apply(uv.pattern->pattern_from_object, {2, 0, 0}), sg::Vec3(1, 0, 0));

    // A pattern modifier on a plain colour changes nothing (POV).
    EXPECT_FALSE(material_of(scene, 2).pigment.pattern.has_value());

    // The scale reaches the pattern the object's uv_mapping makes.
    const sg::Pigment& on_surface = material_of(scene, 3).pigment;
    ASSERT_TRUE(on_surface.pattern.has_value());
    EXPECT_TRUE(on_surface.pattern->uv_mapping);
    EXPECT_EQ(apply(on_surface.pattern->pattern_from_object, {4, 0, 0}), sg::Vec3(1, 0, 0));
}

TEST(ParserPatterns, MapEntriesLiveInTheirParentsPatternSpace) {
    // A transform on the outer pigment moves its own pattern only: POV
    // evaluates the map's pigments at the parent's pattern point.
    auto scene =
        parse_ok("plane { y, 0 pigment { gradient x pigment_map { [0 checker scale 0.5] [1 rgb 1] } scale 4 } }");
    const sg::Pigment& p = material_of(scene).pigment;
    EXPECT_EQ(apply(p.pattern->pattern_from_object, {4, 0, 0}), sg::Vec3(1, 0, 0));
    EXPECT_EQ(apply(p.pigment_map[0].pigment->pattern->pattern_from_object, {1, 0, 0}), sg::Vec3(2, 0, 0));
}

TEST(ParserPatterns, BlockPatternsTakeListsAndFillDefaults) {
    auto scene = parse_ok(
        "plane { y, 0 pigment { hexagon rgb 1 } }\n"
        "plane { y, 0 pigment { brick pigment { rgb 1 } pigment { bozo } } }");
    const sg::Pigment& hexagon = material_of(scene, 0).pigment;
    ASSERT_EQ(hexagon.block_pigments.size(), 3u);
    EXPECT_EQ(hexagon.block_pigments[0]->color.rgb, sg::Vec3(1));
    EXPECT_EQ(hexagon.block_pigments[1]->color.rgb, sg::Vec3(0, 1, 0));  // POV's default green, red
    EXPECT_EQ(hexagon.block_pigments[2]->color.rgb, sg::Vec3(1, 0, 0));
    const sg::Pigment& brick = material_of(scene, 1).pigment;
    ASSERT_EQ(brick.block_pigments.size(), 2u);
    EXPECT_EQ(brick.block_pigments[1]->pattern->kind, sg::Pattern::Kind::Bozo);
    const Diagnostic too_many = first_error("plane { y, 0 pigment { checker rgb 1, rgb 0, rgb 0.5 } }");
    EXPECT_NE(too_many.message.find("checker takes at most 2"), std::string::npos) << too_many.message;
    const Diagnostic map = first_error("plane { y, 0 pigment { hexagon color_map { [0 rgb 0] } } }");
    EXPECT_NE(map.message.find("list of colours, not a color_map"), std::string::npos) << map.message;
}

TEST(ParserPatterns, BadSettingsAreLocatedErrors) {
    EXPECT_NE(first_error("plane { y, 0 pigment { bozo noise_generator 7 } }").message.find("noise_generator"),
              std::string::npos);
    EXPECT_NE(first_error("plane { y, 0 pigment { tiling 40 } }").message.find("tiling type"), std::string::npos);
    EXPECT_NE(first_error("plane { y, 0 pigment { bozo warp { offset 1 } } }").message.find("needs a kind"),
              std::string::npos);
    const Diagnostic e = first_error("plane { y, 0\n  pigment { mandel 0 } }");
    EXPECT_EQ(e.location.line, 2);
    EXPECT_NE(e.message.find("at least 1 iteration"), std::string::npos);
}

TEST(ParserNormals, SlopeMapNormalMapAndAccuracy) {
    auto scene = parse_ok(
        "sphere { 0, 1 normal { gradient x 0.8 slope_map { [0 <0, 1>] [1 <1, 0>] } accuracy 0.01 } }\n"
        "sphere { 0, 1 normal { onion normal_map { [0.2 bumps 0.5] [0.8 dents 0.2 scale 0.1] } } }");
    const sg::Normal& a = *material_of(scene, 0).normal;
    EXPECT_NEAR(a.bump_size, 0.8, 1e-12);
    EXPECT_NEAR(a.accuracy, 0.01, 1e-12);
    ASSERT_EQ(a.slope_map.size(), 2u);
    EXPECT_DOUBLE_EQ(a.slope_map[1].height, 1.0);
    EXPECT_DOUBLE_EQ(a.slope_map[0].slope, 1.0);
    const sg::Normal& b = *material_of(scene, 1).normal;
    ASSERT_EQ(b.normal_map.size(), 2u);
    EXPECT_EQ(b.normal_map[1].normal->pattern->kind, sg::Pattern::Kind::Dents);
    EXPECT_NEAR(b.normal_map[1].normal->bump_size, 0.2, 1e-12);
}

TEST(ParserTextures, LayeredTexturesStackOnObjectsAndInDeclarations) {
    auto scene = parse_ok(
        "#declare T = texture { pigment { rgb 1 } } texture { pigment { bozo } finish { phong 1 } }\n"
        "#declare After = 1;\n"
        "sphere { 0, 1 texture { T } }\n"
        "sphere { 0, 1 texture { pigment { rgb <1, 0, 0> } } texture { pigment { rgbt <0, 0, 1, 0.5> } } }");
    const sg::Material& declared = material_of(scene, 0);
    ASSERT_EQ(declared.layers_above.size(), 1u);
    EXPECT_EQ(declared.layers_above[0]->pigment.pattern->kind, sg::Pattern::Kind::Bozo);
    EXPECT_DOUBLE_EQ(declared.layers_above[0]->finish->phong, 1.0);
    const sg::Material& object = material_of(scene, 1);
    EXPECT_EQ(object.pigment.color.rgb, sg::Vec3(1, 0, 0));
    ASSERT_EQ(object.layers_above.size(), 1u);
    EXPECT_DOUBLE_EQ(object.layers_above[0]->pigment.color.transmit, 0.5);
}

// A pigment (normal, finish) written on an object without a texture makes
// its texture, as POV-Ray copies its default texture for it: a texture
// written after it lies on top (advanced/glasschess.pov's knight). An
// interior alone makes none, so a texture after it is the only layer.
TEST(ParserTextures, ATextureAfterAPigmentLiesOnTopOfIt) {
    auto scene = parse_ok(
        "sphere { 0, 1 pigment { rgbf 0.9 } texture { pigment { rgbf <0.98, 1, 0.98, 1> } } }\n"
        "sphere { 0, 1 finish { phong 1 } texture { pigment { rgb 1 } } }\n"
        "sphere { 0, 1 interior { ior 1.5 } texture { pigment { rgb 1 } } }");
    const sg::Material& pigmented = material_of(scene, 0);
    EXPECT_DOUBLE_EQ(pigmented.pigment.color.filter, 0.9);
    ASSERT_EQ(pigmented.layers_above.size(), 1u);
    EXPECT_DOUBLE_EQ(pigmented.layers_above[0]->pigment.color.filter, 1.0);
    const sg::Material& finished = material_of(scene, 1);
    EXPECT_DOUBLE_EQ(finished.finish->phong, 1.0);
    EXPECT_EQ(finished.layers_above.size(), 1u);
    const sg::Material& interior_only = material_of(scene, 2);
    EXPECT_TRUE(interior_only.layers_above.empty());
    EXPECT_DOUBLE_EQ(interior_only.interior->ior, 1.5);
}

TEST(ParserTextures, TextureMapAndBlockTextures) {
    auto scene = parse_ok(
        "#declare A = texture { pigment { rgb 1 } finish { phong 1 } }\n"
        "plane { y, 0 texture { gradient x texture_map { [0 A] [1 pigment { rgb 0 }] } scale 2 } }\n"
        "plane { y, 0 texture { checker texture { A } texture { pigment { rgb 0.5 } } } }");
    const sg::Material& map = material_of(scene, 0);
    ASSERT_TRUE(map.pattern);
    EXPECT_EQ(map.pattern->kind, sg::Pattern::Kind::Gradient);
    ASSERT_EQ(map.texture_map.size(), 2u);
    EXPECT_DOUBLE_EQ(map.texture_map[0].texture->finish->phong, 1.0);
    EXPECT_EQ(apply(map.pattern->pattern_from_object, {2, 0, 0}), sg::Vec3(1, 0, 0));
    const sg::Material& blocks = material_of(scene, 1);
    ASSERT_EQ(blocks.block_textures.size(), 2u);
    EXPECT_EQ(blocks.block_textures[1]->pigment.color.rgb, sg::Vec3(0.5));
    EXPECT_NE(
        first_error("plane { y, 0 texture { texture_map { [0 pigment { rgb 1 }] } } }").message.find("needs a pattern"),
        std::string::npos);
}

TEST(ParserTextures, DefaultFinishReachesPigmentOnlyObjectsAndTextures) {
    auto scene = parse_ok(
        "#default { finish { ambient 0 diffuse 0.9 } }\n"
        "sphere { 0, 1 pigment { rgb 1 } }\n"
        "sphere { 0, 1 texture { pigment { rgb 1 } } }\n"
        "sphere { 0, 1 finish { phong 1 } }\n"
        "sphere { 0, 1 }");
    for (std::size_t i = 0; i < 4; ++i) {
        const sg::Material& m = material_of(scene, i);
        EXPECT_DOUBLE_EQ(m.finish->diffuse, 0.9) << "object " << i;
        EXPECT_EQ(m.finish->ambient, sg::Vec3(0.0)) << "object " << i;
    }
    EXPECT_DOUBLE_EQ(material_of(scene, 2).finish->phong, 1.0);
}

TEST(ParserTextures, BlocksEditWhatTheTextureHas) {
    // POV edits a texture's pigment, normal and finish in place.
    auto scene = parse_ok(
        "#declare T = texture { pigment { rgb <1, 0, 0> } finish { ambient 0.5 diffuse 0.3 } }\n"
        "sphere { 0, 1 texture { T finish { phong 1 } } }\n"
        "sphere { 0, 1 texture { T } finish { phong 1 } }\n"
        "sphere { 0, 1 pigment { bozo } pigment { scale 0.2 } }\n"
        "#default { normal { onion 0.8 scale 0.4 } }\n"
        "sphere { 0, 1 normal { slope_map { [0 <0, 1>] [1 <1, 0>] } } }\n"
        "#declare L = texture { pigment { rgb 1 } } texture { pigment { rgbt <0, 0, 1, 0.5> } }\n"
        "sphere { 0, 1 texture { L finish { ambient 1 } } }");
    for (std::size_t i = 0; i < 2; ++i) {
        const sg::Material& m = material_of(scene, i);
        EXPECT_DOUBLE_EQ(m.finish->phong, 1.0) << i;
        EXPECT_EQ(m.finish->ambient, sg::Vec3(0.5)) << i;
        EXPECT_DOUBLE_EQ(m.finish->diffuse, 0.3) << i;
        EXPECT_EQ(m.pigment.color.rgb, sg::Vec3(1, 0, 0)) << i;
    }
    const sg::Pigment& bozo = material_of(scene, 2).pigment;
    EXPECT_EQ(bozo.pattern->kind, sg::Pattern::Kind::Bozo);
    EXPECT_EQ(apply(bozo.pattern->pattern_from_object, {0.2, 0, 0}), sg::Vec3(1, 0, 0));
    const sg::Normal& onion = *material_of(scene, 3).normal;
    EXPECT_EQ(onion.pattern->kind, sg::Pattern::Kind::Onion);
    EXPECT_NEAR(onion.bump_size, 0.8, 1e-12);
    EXPECT_EQ(onion.slope_map.size(), 2u);
    EXPECT_NEAR(apply(onion.pattern->pattern_from_object, {0.4, 0, 0}).x, 1.0, 1e-12);
    // A finish after a layered texture changes its top layer.
    const sg::Material& layered = material_of(scene, 4);
    ASSERT_EQ(layered.layers_above.size(), 1u);
    EXPECT_EQ(layered.layers_above[0]->finish->ambient, sg::Vec3(1.0));
    EXPECT_NE(layered.finish->ambient, sg::Vec3(1.0));
}

TEST(ParserDirectives, DeclaringAnIgnoredBlockDeclaresNothingAndReadsNoFurther) {
    // An ignored block declared; the next statement must stay its own.
    ParseResult result =
        test::parse_snippet("#declare P = photons { spacing 0.1 }\n#declare A = 2;\nsphere { 0, A }", "s.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    ASSERT_EQ(result.scene->objects.size(), 1u);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(result.scene->objects[0].shape).radius, 2.0);
    EXPECT_EQ(test::count_warnings(result), 1);
}

TEST(ParserDirectives, OldDefaultWithoutHashIsRead) {
    auto scene = parse_ok("default { finish { ambient 0 diffuse 0.9 } }\nsphere { 0, 1 pigment { rgb 1 } }");
    EXPECT_DOUBLE_EQ(material_of(scene).finish->diffuse, 0.9);
}

TEST(ParserDirectives, DeprecatedDeclarationWarnsOnUse) {
    ParseResult result = test::parse_snippet(
        "#declare deprecated once \"use T2\" T1 = texture { pigment { rgb 1 } }\n"
        "sphere { 0, 1 texture { T1 } }\nsphere { 0, 1 texture { T1 } }",
        "d.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(test::count_warnings(result), 1);  // once
    EXPECT_NE(test::all_diagnostics(result).find("'T1' is deprecated: use T2"), std::string::npos);
}

TEST(ParserPatterns, AverageEntriesMayLeaveOutTheirWeight) {
    auto scene = parse_ok(
        "plane { z, 0 normal { average normal_map { [gradient x, -5 scallop_wave] [2 gradient y] } } }\n"
        "plane { z, 0 texture { average texture_map { [pigment { rgb 1 }] [3.0 pigment { rgb x } finish { phong 1 }] "
        "} } }");
    const sg::NormalRef& n = material_of(scene, 0).normal;
    ASSERT_TRUE(n);
    EXPECT_EQ(n->kind, sg::Normal::Kind::Average);
    ASSERT_EQ(n->normal_map.size(), 2u);
    EXPECT_DOUBLE_EQ(n->normal_map[0].value, 1.0);  // POV's default weight
    EXPECT_DOUBLE_EQ(n->normal_map[0].normal->bump_size, -5.0);
    EXPECT_DOUBLE_EQ(n->normal_map[1].value, 2.0);
    const sg::Material& t = material_of(scene, 1);
    EXPECT_TRUE(t.average);
    ASSERT_EQ(t.texture_map.size(), 2u);
    EXPECT_DOUBLE_EQ(t.texture_map[0].value, 1.0);
    EXPECT_DOUBLE_EQ(t.texture_map[1].value, 3.0);
    // Any other map needs each entry's value.
    EXPECT_NE(first_error("plane { z, 0 normal { gradient x normal_map { [bumps] [1 dents] } } }")
                  .message.find("needs its value"),
              std::string::npos);
    EXPECT_NE(first_error("plane { z, 0 texture { onion texture_map { [pigment { rgb 1 }] } } }")
                  .message.find("needs its value"),
              std::string::npos);
}

TEST(ParserPatterns, AveragePigmentEntriesMayLeaveOutTheirWeight) {
    auto scene = parse_ok(
        "#declare P = pigment { rgb 1 }\n"
        "plane { z, 0 pigment { average pigment_map { [function { x } color_map { [0 rgb 0] [1 rgb 1] }] [P] [2 "
        "bozo] } } }");
    const sg::Pigment& p = material_of(scene).pigment;
    ASSERT_EQ(p.pigment_map.size(), 3u);
    EXPECT_DOUBLE_EQ(p.pigment_map[0].value, 1.0);
    EXPECT_EQ(p.pigment_map[0].pigment->pattern->kind, sg::Pattern::Kind::Function);
    EXPECT_DOUBLE_EQ(p.pigment_map[1].value, 1.0);
    EXPECT_DOUBLE_EQ(p.pigment_map[2].value, 2.0);
    EXPECT_NE(
        first_error("plane { z, 0 pigment { gradient x pigment_map { [bozo] } } }").message.find("needs its value"),
        std::string::npos);
}

// POV's old tiles { … tile2 … } is a checker of two textures, each side
// layered (chess2.pov, wineglass.pov).
TEST(ParserPatterns, TilesIsACheckerOfLayeredTextures) {
    auto scene = parse_ok(
        "box { 0, 1 texture { tiles { texture { pigment { rgb x } } texture { pigment { rgbt 1 } }\n"
        "  tile2 texture { pigment { rgb y } } } scale 2 } }");
    const sg::Material& m = material_of(scene, 0);
    ASSERT_TRUE(m.pattern);
    EXPECT_EQ(m.pattern->kind, sg::Pattern::Kind::Checker);
    ASSERT_EQ(m.block_textures.size(), 2u);
    // povray shows tile2 where checker shows its first texture.
    EXPECT_EQ(m.block_textures[1]->layers_above.size(), 1u);
    EXPECT_EQ(m.block_textures[0]->pigment.color.rgb, sg::Vec3(0.0, 1.0, 0.0));
    // Each side is shown with all its layers (tests/reference/pov/texture_map_finishes.pov).
    EXPECT_EQ(test::all_diagnostics(
                  test::parse_snippet("box { 0, 1 texture { tiles { texture { pigment { rgb x } } texture { "
                                      "pigment { rgbt 1 } } tile2 texture { pigment { rgb y } } } } }",
                                      "t.pov")),
              "");
    EXPECT_NE(first_error("box { 0, 1 texture { tiles { texture { pigment { rgb x } } } } }").message.find("tile2"),
              std::string::npos);
}

// POV-Ray's Link_Textures: layers lie over a plain texture only, and a
// patterned texture is never a layer; a pigment, normal or finish on an
// object is a layer over its texture.
TEST(ParserPatterns, NoLayerOverOrOfAPatternedTexture) {
    const char* over =
        "plane { y, 0 texture { checker texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } }\n"
        "  texture { pigment { rgbt <1, 0, 0, 0.5> } } }";
    EXPECT_NE(first_error(over).message.find("cannot layer over a patterned texture"), std::string::npos);
    EXPECT_EQ(first_error(over).location.line, 2);
    const char* of =
        "#declare A = texture { pigment { rgb 1 } }\n#declare T = texture { A }\n"
        "  texture { gradient x texture_map { [0 A] [1 A] } }\nplane { y, 0 texture { T } }";
    EXPECT_NE(first_error(of).message.find("cannot layer a patterned texture over another"), std::string::npos);
    const char* pigment_over =
        "plane { y, 0 texture { hexagon texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } "
        "finish { phong 1 } }";
    EXPECT_NE(first_error(pigment_over).message.find("cannot layer over a patterned texture"), std::string::npos);
    // Layers inside the map's entries, and plain layers, are what POV takes.
    parse_ok(
        "#declare L = texture { pigment { rgb 1 } } texture { pigment { rgbt <0, 0, 1, 0.5> } }\n"
        "plane { y, 0 texture { checker texture { L } texture { pigment { rgb 0 } } } }\n"
        "sphere { 0, 1 texture { L } texture { pigment { rgbt 0.5 } } finish { phong 1 } }");
}

TEST(ParserPatterns, BlockPatternNormalsOnePerBlock) {
    auto scene = parse_ok(
        "box { 0, 1 normal { checker normal { marble turbulence 0.5 } normal { radial sine_wave } } }\n"
        "box { 0, 1 normal { hexagon 0.5 normal { bumps } } }");
    const sg::NormalRef& checker = material_of(scene, 0).normal;
    ASSERT_TRUE(checker);
    EXPECT_EQ(checker->pattern->kind, sg::Pattern::Kind::Checker);
    ASSERT_EQ(checker->block_normals.size(), 2u);
    EXPECT_EQ(checker->block_normals[0]->pattern->kind, sg::Pattern::Kind::Marble);
    EXPECT_EQ(checker->block_normals[1]->pattern->kind, sg::Pattern::Kind::Radial);
    const sg::NormalRef& hexagon = material_of(scene, 1).normal;
    ASSERT_TRUE(hexagon);
    ASSERT_EQ(hexagon->block_normals.size(), 3u);  // the missing blocks stay flat
    EXPECT_DOUBLE_EQ(hexagon->block_normals[2]->bump_size, 0.0);
    EXPECT_NE(first_error("box { 0, 1 normal { checker normal { bumps } normal { dents } normal { wrinkles } } }")
                  .message.find("at most 2 normals"),
              std::string::npos);
}

TEST(ParserPatterns, BumpMapTakesItsOwnItemsInsideTheBlock) {
    const PlaceholderImage placeholder("bump", "bumps.png");
    const std::string& image = placeholder.path;
    auto scene = parse_ok("sphere { 0, 1 normal { bump_map { png \"" + image +
                          "\" bump_size 10 use_color interpolate 2 once } } }\n"
                          "sphere { 0, 1 normal { bump_map { png \"" +
                          image + "\" bump_size 10 } 3 } }");
    const sg::NormalRef& inside = material_of(scene, 0).normal;
    ASSERT_TRUE(inside);
    EXPECT_EQ(inside->kind, sg::Normal::Kind::BumpMap);
    EXPECT_DOUBLE_EQ(inside->bump_size, 10.0);
    EXPECT_TRUE(inside->bump_map_use_color);
    EXPECT_TRUE(inside->bump_map.once);
    EXPECT_DOUBLE_EQ(material_of(scene, 1).normal->bump_size, 3.0);  // the amount after the block wins
    EXPECT_TRUE(material_of(scene, 1).normal->bump_map_use_color);   // POV-Ray's default: the colour's grey
    EXPECT_FALSE(material_of(parse_ok("sphere { 0, 1 normal { bump_map { png \"" + image + "\" use_index } } }"), 0)
                     .normal->bump_map_use_color);
    const std::string before = "sphere { 0, 1 pigment { image_map { png \"" + image + "\" ";
    const Diagnostic in_image_map = first_error(before + "bump_size 2 } } }");
    EXPECT_NE(in_image_map.message.find("belong in a bump_map"), std::string::npos);
    EXPECT_EQ(in_image_map.location.column, before.size() + 1);
}

TEST(ParserPatterns, ObjectPatternIsAListOfTwo) {
    auto scene = parse_ok(
        "#declare S = sphere { 0, 1 }\n"
        "plane { z, 0 pigment { object { S rgb x, rgb y } } }\n"
        "plane { z, 0 pigment { object { box { -1, 1 } } } }\n"
        "plane { z, 0 texture { object { S texture { pigment { rgb 1 } } texture { pigment { rgb 0 } } } } }\n"
        "plane { z, 0 normal { object { S normal { bumps } } } }\n"
        "plane { z, 0 texture { object { S texture { pigment { rgb 1 } }, texture { pigment { rgb 0 } } } } }");
    const sg::Pigment& colours = material_of(scene, 0).pigment;
    EXPECT_EQ(colours.pattern->kind, sg::Pattern::Kind::Object);
    ASSERT_TRUE(colours.pattern->object);
    ASSERT_EQ(colours.block_pigments.size(), 2u);
    EXPECT_EQ(colours.block_pigments[1]->color.rgb, sg::Vec3(0, 1, 0));  // inside
    const sg::Pigment& defaults = material_of(scene, 1).pigment;
    ASSERT_EQ(defaults.block_pigments.size(), 2u);  // POV's: checker's blue and green
    EXPECT_EQ(defaults.block_pigments[0]->color.rgb, sg::Vec3(0, 0, 1));
    EXPECT_EQ(material_of(scene, 2).block_textures.size(), 2u);
    ASSERT_TRUE(material_of(scene, 3).normal);
    EXPECT_EQ(material_of(scene, 3).normal->block_normals.size(), 2u);
    EXPECT_EQ(material_of(scene, 4).block_textures.size(), 2u);  // a comma between (object_pattern.pov)
    EXPECT_NE(first_error("plane { z, 0 pigment { object { sphere { 0, 1 } rgb 0, rgb 1, rgb 2 } } }")
                  .message.find("object takes at most 2"),
              std::string::npos);
}

// material_map: an image pattern whose values pick among the textures
// listed after it, read as stored; what belongs to other image blocks, or
// no texture at all, is a located error.
TEST(ParserPatterns, MaterialMapListsTexturesAfterItsImage) {
    const PlaceholderImage placeholder("material_map", "map.png");
    const std::string& image = placeholder.path;
    auto scene = parse_ok(
        "#declare T = texture { pigment { rgb 1 } }\n"
        "plane { y, 0 texture { material_map { png \"" +
        image + "\" once map_type 0 texture { pigment { rgb x } } texture { T } } scale 2 } }");
    const sg::Material& m = material_of(scene, 0);
    ASSERT_TRUE(m.pattern);
    EXPECT_EQ(m.pattern->kind, sg::Pattern::Kind::ImagePattern);
    ASSERT_TRUE(m.pattern->image);
    EXPECT_TRUE(m.pattern->image->once);
    EXPECT_FALSE(m.pattern->image->srgb);
    ASSERT_EQ(m.block_textures.size(), 2u);
    EXPECT_EQ(m.block_textures[0]->pigment.color.rgb, sg::Vec3(1, 0, 0));
    EXPECT_EQ(m.pattern->pattern_from_object, glm::inverse(glm::scale(sg::Mat4(1.0), sg::Vec3(2.0))));
    const Diagnostic empty = first_error("plane { y, 0 texture { material_map { png \"" + image + "\" } } }");
    EXPECT_NE(empty.message.find("material_map needs a list of textures"), std::string::npos) << empty.message;
    EXPECT_EQ(empty.location.column, 24);
    const Diagnostic alpha =
        first_error("plane { y, 0 texture { material_map { png \"" + image + "\" use_alpha texture { } } } }");
    EXPECT_NE(alpha.message.find("use_alpha belongs in an image_pattern, not in material_map"), std::string::npos)
        << alpha.message;
}

TEST(ParserPatterns, ImageMapColoursAreDecodedOnlyInA37Scene) {
    // POV-Ray 3.7 reads an image_map's colours as stored while the scene's
    // #version is below 3.7 (with or without assumed_gamma), and decodes
    // them from the #version 3.7 on; `gamma` decodes them in any scene.
    const PlaceholderImage placeholder("image_map_gamma", "colours.png");
    const std::string map = "plane { y, 0 pigment { image_map { png \"" + placeholder.path + "\" } } }\n";
    const std::string map_with_gamma =
        "plane { y, 0 pigment { image_map { png \"" + placeholder.path + "\" gamma 2.2 } } }\n";
    ParseOptions legacy;
    legacy.language_version = 3.6;
    const sg::SceneGraph scene =
        parse_ok("global_settings { assumed_gamma 1 }\n" + map + map_with_gamma + "#version 3.7;\n" + map, legacy);
    EXPECT_FALSE(material_of(scene, 0).pigment.image->srgb);
    EXPECT_TRUE(material_of(scene, 1).pigment.image->srgb);
    EXPECT_TRUE(material_of(scene, 2).pigment.image->srgb);
}

TEST(ParserPatterns, ImagePatternReadsItsImageAsStored) {
    const PlaceholderImage placeholder("image_pattern", "mask.png");
    const std::string& image = placeholder.path;
    auto scene =
        parse_ok("plane { y, 0 pigment { image_pattern { png \"" + image +
                 "\" use_alpha once } color_map { [0 rgb 0] [1 rgb 1] } } }\n"
                 "plane { y, 0 pigment { image_pattern { png \"" +
                 image + "\" gamma 2.2 } } }\n" + "plane { y, 0 pigment { image_map { png \"" + image + "\" } } }");
    const sg::Pattern& masked = *material_of(scene, 0).pigment.pattern;
    EXPECT_EQ(masked.kind, sg::Pattern::Kind::ImagePattern);
    ASSERT_TRUE(masked.image);
    EXPECT_TRUE(masked.image->use_alpha);
    EXPECT_TRUE(masked.image->once);
    EXPECT_FALSE(masked.image->srgb);  // data, not colour: no decoding unless gamma is given
    EXPECT_TRUE(material_of(scene, 1).pigment.pattern->image->srgb);
    // POV's image_map defaults: planar, no interpolation, decoded colours.
    const sg::ImageMap& colours = *material_of(scene, 2).pigment.image;
    EXPECT_EQ(colours.map_type, sg::MapType::Planar);
    EXPECT_EQ(colours.interpolate, 0);
    EXPECT_TRUE(colours.srgb);
    EXPECT_NE(first_error("plane { y, 0 pigment { image_map { png \"" + image + "\" use_alpha } } }")
                  .message.find("use_alpha belongs in an image_pattern"),
              std::string::npos);
}

// POV's `filter N, v` and `transmit N, v` set one palette entry, `... all v`
// every entry, in the order written (checked against the image when it is
// read: tests/reference/pov/image_palette.pov, Textures.Palette*).
TEST(ParserPatterns, ImageMapPaletteSettingsKeepTheirOrder) {
    const PlaceholderImage placeholder("image_palette", "palette.gif");
    const std::string& image = placeholder.path;
    auto scene = parse_ok("plane { y, 0 pigment { image_map { gif \"" + image +
                          "\" transmit 2, 1 filter all 0.25 transmit 3 0.5 filter 2.995, 0 } } }");
    const sg::ImageMap& map = *material_of(scene, 0).pigment.image;
    EXPECT_EQ(map.format, sg::ImageFormat::Gif);
    ASSERT_EQ(map.palette_settings.size(), 4u);
    const sg::PaletteSetting& first = map.palette_settings[0];
    EXPECT_TRUE(first.transmit);
    EXPECT_EQ(first.index, 2);
    EXPECT_DOUBLE_EQ(first.value, 1.0);
    EXPECT_EQ(first.location.line, 1);
    EXPECT_EQ(map.palette_settings[1].index, -1);  // all
    EXPECT_DOUBLE_EQ(map.palette_settings[1].value, 0.25);
    EXPECT_FALSE(map.palette_settings[1].transmit);
    EXPECT_EQ(map.palette_settings[2].index, 3);
    EXPECT_EQ(map.palette_settings[3].index, 3);  // POV adds 0.01 before truncating
    EXPECT_FALSE(map.palette_settings[3].transmit);

    EXPECT_NE(first_error("plane { y, 0 pigment { image_map { gif \"" + image + "\" filter 256, 0.5 } } }")
                  .message.find("must be 0 to 255"),
              std::string::npos);
    EXPECT_NE(first_error("plane { y, 0 normal { bump_map { gif \"" + image + "\" transmit 1, 0.5 } } }")
                  .message.find("filter and transmit belong in an image_map"),
              std::string::npos);
}

}  // namespace
}  // namespace lancer
