// Every construct of the scene language parsed from a string, with the
// resulting scene graph asserted: values, composed transforms, defaults.
#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "lancer/finish_balance.h"
#include "lancer/scene_summary.h"
#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::parse_ok;

void expect_vec(const sg::Vec3& actual, const sg::Vec3& expected, double tolerance = 1e-9) {
    EXPECT_NEAR(actual.x, expected.x, tolerance);
    EXPECT_NEAR(actual.y, expected.y, tolerance);
    EXPECT_NEAR(actual.z, expected.z, tolerance);
}

sg::Vec3 apply(const sg::Mat4& m, const sg::Vec3& p) {
    return sg::Vec3(m * glm::dvec4(p, 1.0));
}

TEST(ParserObjects, SphereWithDefaults) {
    auto scene = parse_ok("sphere { <1, 2, 3>, 0.5 }");
    ASSERT_EQ(scene.objects.size(), 1u);
    const auto& object = scene.objects[0];
    EXPECT_EQ(object.kind, sg::Object::Kind::Sphere);
    const auto& sphere = std::get<sg::Sphere>(object.shape);
    expect_vec(sphere.center, {1, 2, 3});
    EXPECT_DOUBLE_EQ(sphere.radius, 0.5);
    EXPECT_EQ(object.material, nullptr);  // POV default texture applies
    EXPECT_FALSE(object.no_shadow);
    EXPECT_EQ(object.location.line, 1);
    EXPECT_EQ(object.location.column, 1);
    EXPECT_FALSE(scene.camera.has_value());
    expect_vec(scene.background, {0, 0, 0});
    EXPECT_EQ(scene.global.max_trace_level, 5);
}

TEST(ParserObjects, PlaneNormalisedAndBox) {
    auto scene = parse_ok("plane { <0, 2, 0>, 1 } box { <1, 1, 1>, <-1, 0, -2> }");
    const auto& plane = std::get<sg::Plane>(scene.objects[0].shape);
    expect_vec(plane.normal, {0, 1, 0});
    EXPECT_DOUBLE_EQ(plane.distance, 0.5);  // the set 2y = 1
    const auto& box = std::get<sg::Box>(scene.objects[1].shape);
    expect_vec(box.corner1, {-1, 0, -2});
    expect_vec(box.corner2, {1, 1, 1});
}

TEST(ParserObjects, TriangleAndSmoothTriangle) {
    auto scene = parse_ok(
        "triangle { <0,0,0>, <1,0,0>, <0,1,0> }\n"
        "smooth_triangle { <0,0,0>, <0,0,-1>, <1,0,0>, <0,0,-2>, <0,1,0>, <0,1,-1> }");
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].kind, sg::Object::Kind::Triangle);
    auto mesh = std::get<sg::MeshRef>(scene.objects[0].shape);
    ASSERT_EQ(mesh->faces.size(), 1u);
    expect_vec(mesh->positions[1], {1, 0, 0});
    EXPECT_EQ(mesh->faces[0].normal[0], -1);
    auto smooth = std::get<sg::MeshRef>(scene.objects[1].shape);
    EXPECT_EQ(scene.objects[1].kind, sg::Object::Kind::SmoothTriangle);
    ASSERT_EQ(smooth->normals.size(), 3u);
    expect_vec(smooth->normals[1], {0, 0, -1});  // normalised
}

TEST(ParserObjects, MeshWithPerTriangleTexture) {
    auto scene = parse_ok(
        "#declare T = texture { pigment { rgb <1,0,0> } }\n"
        "mesh { triangle { <0,0,0>, <1,0,0>, <0,1,0> texture { T } }\n"
        "       triangle { <0,0,1>, <1,0,1>, <0,1,1> } translate x }");
    auto mesh = std::get<sg::MeshRef>(scene.objects[0].shape);
    ASSERT_EQ(mesh->faces.size(), 2u);
    EXPECT_EQ(mesh->faces[0].material, 0);
    EXPECT_EQ(mesh->faces[1].material, -1);
    expect_vec(mesh->materials[0]->pigment.color.rgb, {1, 0, 0});
    expect_vec(apply(scene.objects[0].parent_from_object, {0, 0, 0}), {1, 0, 0});
}

TEST(ParserObjects, Mesh2WithNormalsAndUvs) {
    auto scene = parse_ok(R"(mesh2 {
        vertex_vectors { 4, <0,0,0>, <1,0,0>, <1,1,0>, <0,1,0> }
        normal_vectors { 1, <0,0,-1> }
        uv_vectors { 4, <0,0>, <1,0>, <1,1>, <0,1> }
        texture_list { 2, texture { pigment { rgb 1 } } texture { pigment { rgb 0.5 } } }
        face_indices { 2, <0,1,2>, 1, <0,2,3>, 0 }
        normal_indices { 2, <0,0,0>, <0,0,0> }
        uv_indices { 2, <0,1,2>, <0,2,3> }
    })");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].kind, sg::Object::Kind::Mesh2);
    auto mesh = std::get<sg::MeshRef>(scene.objects[0].shape);
    EXPECT_EQ(mesh->positions.size(), 4u);
    ASSERT_EQ(mesh->faces.size(), 2u);
    EXPECT_EQ(mesh->faces[1].position[2], 3);
    EXPECT_EQ(mesh->faces[0].normal[0], 0);
    EXPECT_EQ(mesh->faces[1].uv[2], 3);
    EXPECT_EQ(mesh->faces[0].material, 1);
    EXPECT_EQ(mesh->faces[1].material, 0);
    EXPECT_EQ(mesh->materials.size(), 2u);
}

// POV reads a section's count as a bare float and its commas as optional:
// `14 <-1, -1, -1>` is a count and a point, not a comparison (mesh2.pov);
// poly's order needs no comma either (primitiv.pov).
TEST(ParserObjects, Mesh2AndPolyCommasAreOptional) {
    auto scene = parse_ok(R"(mesh2 {
        vertex_vectors { 3
          <-1, -1, 0> <1, -1, 0>, <0,
          1, 0> }
        face_indices { 1 <0, 1, 2> }
    }
    poly { 2 <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> })");
    ASSERT_EQ(scene.objects.size(), 2u);
    auto mesh = std::get<sg::MeshRef>(scene.objects[0].shape);
    ASSERT_EQ(mesh->positions.size(), 3u);
    EXPECT_EQ(mesh->positions[0].x, -1.0);
    EXPECT_EQ(mesh->positions[2].y, 1.0);
    ASSERT_EQ(mesh->faces.size(), 1u);
    EXPECT_EQ(mesh->faces[0].position[2], 2);
}

TEST(ParserObjects, Mesh2NormalsPairWithVerticesWithoutIndices) {
    auto scene = parse_ok(
        "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }"
        " normal_vectors { 3, z, z, z } face_indices { 1, <0,1,2> } }");
    auto mesh = std::get<sg::MeshRef>(scene.objects[0].shape);
    EXPECT_EQ(mesh->faces[0].normal[2], 2);
}

TEST(ParserObjects, ObjectReuseComposesTransforms) {
    auto scene = parse_ok(
        "#declare S = sphere { 0, 1 translate <1, 0, 0> }\n"
        "object { S scale 2 }\n");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].name, "S");
    // translate then scale: the centre lands at x = 2
    expect_vec(apply(scene.objects[0].parent_from_object, {0, 0, 0}), {2, 0, 0});
}

TEST(ParserTransforms, RotationOrderXThenYThenZ) {
    auto scene =
        parse_ok("sphere { 0, 1 rotate <90, 0, 0> } sphere { 0, 1 rotate y*90 } sphere { 0, 1 rotate <90, 90, 0> }");
    // POV: rotate x*90 takes +y to +z; rotate y*90 takes +x to -z.
    expect_vec(apply(scene.objects[0].parent_from_object, {0, 1, 0}), {0, 0, 1}, 1e-12);
    expect_vec(apply(scene.objects[1].parent_from_object, {1, 0, 0}), {0, 0, -1}, 1e-12);
    // x first: +y -> +z, then y: +z -> +x
    expect_vec(apply(scene.objects[2].parent_from_object, {0, 1, 0}), {1, 0, 0}, 1e-12);
}

TEST(ParserTransforms, MatrixAndTransformBlocks) {
    auto scene = parse_ok(
        "#declare T = transform { scale 2 translate y }\n"
        "sphere { 0, 1 transform T }\n"
        "sphere { 0, 1 transform { T inverse } }\n"
        "sphere { 0, 1 matrix <1,0,0, 0,1,0, 0,0,1, 3,4,5> }");
    expect_vec(apply(scene.objects[0].parent_from_object, {1, 0, 0}), {2, 1, 0});
    expect_vec(apply(scene.objects[1].parent_from_object, {2, 1, 0}), {1, 0, 0});
    expect_vec(apply(scene.objects[2].parent_from_object, {0, 0, 0}), {3, 4, 5});
}

TEST(ParserTransforms, NestedUnionsComposeAndTexturesInherit) {
    auto scene = parse_ok(R"(
        union {
            union { sphere { 0, 1 translate x } box { 0, 1 pigment { rgb <0,1,0> } } translate y }
            sphere { 0, 1 }
            pigment { rgb <1,0,0> }
            translate z
        })");
    ASSERT_EQ(scene.objects.size(), 1u);
    const auto& outer = scene.objects[0];
    EXPECT_EQ(outer.kind, sg::Object::Kind::Union);
    const auto& children = std::get<sg::Group>(outer.shape).children;
    ASSERT_EQ(children.size(), 2u);
    const auto& inner = std::get<sg::Group>(children[0].shape).children;
    sg::Mat4 world_from_sphere =
        outer.parent_from_object * children[0].parent_from_object * inner[0].parent_from_object;
    expect_vec(apply(world_from_sphere, {0, 0, 0}), {1, 1, 1});
    // The union's pigment reaches the children without their own texture ...
    ASSERT_TRUE(inner[0].material);
    expect_vec(inner[0].material->pigment.color.rgb, {1, 0, 0});
    ASSERT_TRUE(children[1].material);
    // ... and not the box, which has its own.
    expect_vec(inner[1].material->pigment.color.rgb, {0, 1, 0});
    auto summary = summarize_scene(scene);
    EXPECT_EQ(summary.objects_by_kind["union"], 2);
    EXPECT_EQ(summary.objects_by_kind["sphere"], 2);
}

// A pigment then a finish on a union both reach the children without a
// texture of their own (the finish once replaced nothing: the children
// kept the pigment-only material the first modifier gave them).
TEST(ParserMaterials, EveryModifierOnAGroupReachesChildrenWithoutTextures) {
    auto scene = parse_ok(R"(
        intersection {
          cylinder { 0, y, 1 }
          box { -1, 1 pigment { rgb <0, 0, 1> } }
          pigment { rgb <0, 1, 0> }
          finish { phong 0.7 }
        })");
    ASSERT_EQ(scene.objects.size(), 1u);
    const auto& children = std::get<sg::Group>(scene.objects[0].shape).children;
    ASSERT_EQ(children.size(), 2u);
    ASSERT_TRUE(children[0].material);
    EXPECT_DOUBLE_EQ(children[0].material->finish->phong, 0.7);
    EXPECT_DOUBLE_EQ(children[0].material->pigment.color.rgb.y, 1.0);
    // The box's own texture stays.
    EXPECT_DOUBLE_EQ(children[1].material->pigment.color.rgb.z, 1.0);
    EXPECT_DOUBLE_EQ(children[1].material->finish->phong, 0.0);
}

TEST(ParserObjects, QuadricFamilyArguments) {
    auto scene = parse_ok(R"(
        cylinder { <1, 2, 3>, <1, 5, 3>, 0.5 open }
        cone { 0, 1, y, 0.25 }
        torus { 2, -0.5 sturm }
        disc { 0, y, 2, 1 }
        quadric { <1, 1, 0>, <0, 0, 0>, <0, 0, 0>, -1 })");
    ASSERT_EQ(scene.objects.size(), 5u);
    const auto& cylinder = std::get<sg::Cone>(scene.objects[0].shape);
    EXPECT_TRUE(cylinder.open);
    EXPECT_EQ(cylinder.cap, sg::Vec3(1, 5, 3));
    EXPECT_DOUBLE_EQ(cylinder.cap_radius, 0.5);
    const auto& cone = std::get<sg::Cone>(scene.objects[1].shape);
    EXPECT_DOUBLE_EQ(cone.base_radius, 1.0);
    EXPECT_DOUBLE_EQ(cone.cap_radius, 0.25);
    EXPECT_FALSE(cone.open);
    // POV: a negative radius inverts the torus (with a warning).
    EXPECT_TRUE(scene.objects[2].inverse);
    EXPECT_DOUBLE_EQ(std::get<sg::Torus>(scene.objects[2].shape).minor_radius, 0.5);
    EXPECT_DOUBLE_EQ(std::get<sg::Disc>(scene.objects[3].shape).hole_radius, 1.0);
    EXPECT_EQ(std::get<sg::Quadric>(scene.objects[4].shape).square_terms, sg::Vec3(1, 1, 0));
}

// text reads POV-Ray's fonts (Debian's fonts-povray, which setup installs)
// and lays glyphs out from x = 0 in units of the em.
TEST(ParserObjects, TextLaysOutGlyphOutlines) {
    auto scene = parse_ok(R"(text { ttf "timrom.ttf" "Ho" 0.5, 0 })");
    ASSERT_EQ(scene.objects.size(), 1u);
    const auto& text = std::get<sg::Text>(scene.objects[0].shape);
    ASSERT_FALSE(text.segments.empty());
    EXPECT_DOUBLE_EQ(text.thickness, 0.5);
    double lowest_x = 1e9, highest_x = -1e9, highest_y = -1e9;
    for (const auto& segment : text.segments)
        for (const auto& p : segment.p) {
            lowest_x = std::min(lowest_x, p.x);
            highest_x = std::max(highest_x, p.x);
            highest_y = std::max(highest_y, p.y);
        }
    EXPECT_NEAR(lowest_x, 0.0, 1e-9);  // the first glyph starts at the origin
    EXPECT_GT(highest_x, 1.0);         // two letters, each most of an em wide
    EXPECT_GT(highest_y, 0.5);         // capital height in ems
    EXPECT_LT(highest_y, 1.0);
    EXPECT_EQ(scene.input_files.size(), 1u);  // the font, never to be overwritten
    // POV-Ray adds .ttf to a name without an extension.
    EXPECT_EQ(
        std::get<sg::Text>(parse_ok(R"(text { ttf "timrom" "H" 1, 0 })").objects[0].shape).segments.size(),
        text.segments.size() -
            std::get<sg::Text>(parse_ok(R"(text { ttf "timrom.ttf" "o" 1, 0 })").objects[0].shape).segments.size());
    const Diagnostic missing = test::first_error(R"(text { ttf "no-such-font.ttf" "x" 1, 0 })");
    EXPECT_NE(missing.message.find("cannot find font file"), std::string::npos) << missing.message;
    EXPECT_EQ(missing.location.column, 12);
}

// An object's own uv_mapping maps the texture written after it by (u, v)
// (tests/reference/pov/uv_mapping_object.pov renders it); after the texture
// it is an error, as in POV-Ray.
TEST(ParserObjects, ObjectUvMappingComesBeforeItsTexture) {
    auto scene = parse_ok("sphere { 0, 1 uv_mapping pigment { checker } normal { bumps 0.5 } translate x }");
    const sg::Material& material = *scene.objects.at(0).material;
    EXPECT_TRUE(material.uv_mapping);
    EXPECT_TRUE(material.pigment.pattern->uv_mapping);
    ASSERT_TRUE(material.normal);
    EXPECT_TRUE(material.normal->pattern->uv_mapping);
    // The pattern stays on the surface: the translate does not move it.
    EXPECT_EQ(material.pigment.pattern->pattern_from_object, sg::Mat4(1.0));
    EXPECT_NE(
        test::first_error("sphere { 0, 1 pigment { checker } uv_mapping }").message.find("before the object's texture"),
        std::string::npos);
}

// text { internal N }: POV-Ray's built-in fonts by number (1 is timrom),
// and a character a font lacks drawn as its glyph 0 (povlogo's logo), as
// POV-Ray draws it. An empty text is an empty union, not an error.
TEST(ParserObjects, TextInternalFontsAndMissingCharacters) {
    auto segments = [](const std::string& text) {
        return std::get<sg::Text>(parse_ok(text).objects[0].shape).segments.size();
    };
    EXPECT_EQ(segments(R"(text { internal 1 "Ho" 0.5, 0 })"), segments(R"(text { ttf "timrom.ttf" "Ho" 0.5, 0 })"));
    const std::size_t logo = segments(R"(text { internal 0 "P" 0.5, 0 })");
    EXPECT_GT(logo, 0u);
    EXPECT_EQ(segments(R"(text { internal 0 "A" 0.5, 0 })"), logo);  // povlogo has no "A": its glyph 0 is the logo
    ParseResult empty = test::parse_snippet(R"(text { internal 1 "   " 0.5, 0 })", "t.pov");
    ASSERT_TRUE(empty.ok()) << test::all_diagnostics(empty);
    EXPECT_EQ(empty.scene->objects.at(0).kind, sg::Object::Kind::Union);
    EXPECT_EQ(test::count_warnings(empty), 1);
}

// POV-Ray accepts negative colours; on a surface they take light away, so
// lancer keeps them and says so where they are written. A negative light
// (POV's documented trick for darkening) gets no warning.
TEST(ParserMaterials, NegativeSurfaceColoursWarn) {
    ParseResult result = test::parse_snippet(
        "light_source { <5, 5, -5> rgb -0.5 }\n"
        "sphere { 0, 1 pigment { rgb <-1, 0.5, 0.5> } finish { ambient -0.2 } }");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(test::count_warnings(result), 2) << test::all_diagnostics(result);
    EXPECT_EQ(std::get<sg::Sphere>(result.scene->objects[0].shape).radius, 1.0);
    for (const Diagnostic& d : result.diagnostics) EXPECT_EQ(d.location.line, 2);
    EXPECT_EQ(test::count_warnings(test::parse_snippet("sphere { 0, 1 pigment { rgb 0.5 } finish { ambient 0.1 } }")),
              0);
}

// POV-Ray's dispersion and dispersion_samples: read, checked as POV-Ray
// checks them (at least 2 samples), and ignored with a warning at each.
TEST(ParserMaterials, DispersionSamplesAreCheckedThenIgnored) {
    const ParseResult read =
        test::parse_snippet("sphere { 0, 1 interior { ior 1.3 dispersion 1.05 dispersion_samples 7 } }");
    ASSERT_TRUE(read.ok()) << test::all_diagnostics(read);
    EXPECT_EQ(test::count_warnings(read), 2) << test::all_diagnostics(read);
    EXPECT_TRUE(test::contains(test::all_diagnostics(read), "dispersion_samples is accepted but ignored"));
    const Diagnostic one = test::first_error("sphere { 0, 1 interior { dispersion_samples 1 } }");
    EXPECT_TRUE(test::contains(one.message, "dispersion_samples must be at least 2")) << one.message;
    EXPECT_EQ(one.location.column, 45);
}

// POV-Ray gives a union's interior to every part without an interior of
// its own, textured or not, through nested unions and whether the part
// came before or after it; a part's own interior (or its material's) stays.
TEST(ParserMaterials, AGroupsInteriorReachesPartsWithoutOne) {
    auto scene = parse_ok(R"(
        #declare M = material { texture { pigment { rgbf 1 } } interior { ior 1.2 } }
        union {
          sphere { 0, 1 pigment { rgbf 1 } }
          union { sphere { 0, 1 texture { pigment { rgb 1 } } } }
          sphere { 0, 1 pigment { rgbf 1 } interior { ior 1.1 } }
          sphere { 0, 1 material { M } }
          union { sphere { 0, 1 } pigment { rgbf 1 } }
          interior { ior 1.6 }
        }
        union { interior { ior 1.4 } sphere { 0, 1 pigment { rgbf 1 } } }
        sphere { 0, 1 pigment { rgbf 1 } })");
    const auto& parts = std::get<sg::Group>(scene.objects.at(0).shape).children;
    ASSERT_EQ(parts.size(), 5u);
    EXPECT_DOUBLE_EQ(parts[0].material->interior->ior, 1.6);
    EXPECT_DOUBLE_EQ(std::get<sg::Group>(parts[1].shape).children.at(0).material->interior->ior, 1.6);
    EXPECT_DOUBLE_EQ(parts[2].material->interior->ior, 1.1);
    EXPECT_DOUBLE_EQ(parts[3].material->interior->ior, 1.2);
    // A part that takes its texture from a nested group takes the interior too.
    EXPECT_DOUBLE_EQ(std::get<sg::Group>(parts[4].shape).children.at(0).material->interior->ior, 1.6);
    const auto& later = std::get<sg::Group>(scene.objects.at(1).shape).children;
    EXPECT_DOUBLE_EQ(later.at(0).material->interior->ior, 1.4);
    EXPECT_DOUBLE_EQ(scene.objects.at(2).material->interior->ior, 1.0);
}

TEST(ParserMaterials, TextureFinishDefaultsAndValues) {
    auto scene = parse_ok(R"(sphere { 0, 1 texture {
        pigment { color rgbft <0.1, 0.2, 0.3, 0.4, 0.5> }
        finish { ambient 0.2 diffuse 0.7 brilliance 2 specular 0.3 roughness 0.01 phong 0.4 phong_size 60
                 metallic reflection { 0.1, 0.9 falloff 2 exponent 1.5 } emission rgb <1, 2, 3> }
    } interior { ior 1.5 } })");
    auto m = scene.objects[0].material;
    ASSERT_TRUE(m);
    expect_vec(m->pigment.color.rgb, {0.1, 0.2, 0.3});
    EXPECT_DOUBLE_EQ(m->pigment.color.filter, 0.4);
    EXPECT_DOUBLE_EQ(m->pigment.color.transmit, 0.5);
    expect_vec(m->finish->ambient, {0.2, 0.2, 0.2});
    EXPECT_DOUBLE_EQ(m->finish->diffuse, 0.7);
    EXPECT_DOUBLE_EQ(m->finish->brilliance, 2);
    EXPECT_DOUBLE_EQ(m->finish->specular, 0.3);
    EXPECT_DOUBLE_EQ(m->finish->roughness, 0.01);
    EXPECT_DOUBLE_EQ(m->finish->phong, 0.4);
    EXPECT_DOUBLE_EQ(m->finish->phong_size, 60);
    EXPECT_DOUBLE_EQ(m->finish->metallic, 1.0);
    expect_vec(m->finish->reflection.min, {0.1, 0.1, 0.1});
    expect_vec(m->finish->reflection.max, {0.9, 0.9, 0.9});
    EXPECT_DOUBLE_EQ(m->finish->reflection.falloff, 2);
    EXPECT_DOUBLE_EQ(m->finish->reflection.exponent, 1.5);
    expect_vec(m->finish->emission, {1, 2, 3});
    EXPECT_DOUBLE_EQ(m->interior->ior, 1.5);
}

// The older `reflection_exponent` sets the same exponent, which a later
// reflection block keeps (POV's Reflect_Exp); it must be positive (POV
// divides by it).
TEST(ParserMaterials, ReflectionExponentOldAndNew) {
    auto scene = parse_ok("sphere { 0, 1 finish { reflection_exponent 0.5 reflection { 0.3 } } }");
    EXPECT_DOUBLE_EQ(scene.objects[0].material->finish->reflection.exponent, 0.5);
    const Diagnostic error = test::first_error("sphere { 0, 1 finish { reflection { 0.3 exponent 0 } } }");
    EXPECT_NE(error.message.find("reflection exponent must be positive"), std::string::npos) << error.message;
    EXPECT_EQ(error.location.line, 1);
}

// POV-Ray's Parse_Finish: `albedo` values become the peaks that reflect
// that share, with the finish's final exponents (phong_size written after).
TEST(ParserMaterials, AlbedoBecomesPovsPeak) {
    auto scene = parse_ok(R"(
        #declare F = finish { phong albedo 0.5 phong_size 9 diffuse albedo 0.6 brilliance 3 }
        sphere { 0, 1 finish { F } }
        sphere { 0, 1 finish { specular albedo 0.2 roughness 0.1 conserve_energy } }
        sphere { 0, 1 finish { F phong_size 99 } })");
    const auto& first = *scene.objects[0].material->finish;
    EXPECT_DOUBLE_EQ(first.phong, 0.5 * (9.0 + 1.0) / 2.0);
    EXPECT_DOUBLE_EQ(first.diffuse, 0.6 * (3.0 + 1.0) / 2.0);
    const auto& second = *scene.objects[1].material->finish;
    EXPECT_NEAR(second.specular, 0.2 * 12.0 / (4.0 * (2.0 - std::pow(2.0, -5.0))), 1e-12);
    EXPECT_TRUE(second.conserve_energy);
    // A declared finish was rescaled once, when it was read.
    EXPECT_DOUBLE_EQ(scene.objects[2].material->finish->phong, 2.5);
}

TEST(ParserMaterials, FinishDefaultsArePovs) {
    auto scene = parse_ok("sphere { 0, 1 finish { } }");
    auto m = scene.objects[0].material;
    ASSERT_TRUE(m);
    expect_vec(m->finish->ambient, {0.1, 0.1, 0.1});
    EXPECT_DOUBLE_EQ(m->finish->diffuse, 0.6);
    EXPECT_DOUBLE_EQ(m->finish->phong_size, 40);
    EXPECT_DOUBLE_EQ(m->finish->roughness, 0.05);
    expect_vec(m->pigment.color.rgb, {0, 0, 0});  // POV's default pigment is black
}

TEST(ParserMaterials, ColourForms) {
    auto scene = parse_ok(R"(#include "colors.inc"
        #declare A = color red 1 green 0.5;
        #declare B = rgbt <1, 1, 1, 0.25>;
        #declare C = srgb <0.5, 1, 0>;
        #declare D = Red * 0.5 + Blue;
        sphere { 0, 1 pigment { A } }
        sphere { 0, 1 pigment { B } }
        sphere { 0, 1 pigment { C } }
        sphere { 0, 1 pigment { color D filter 0.3 } }
        sphere { 0, 1 pigment { Gray50 } }
        sphere { 0, 1 pigment { color rgb <0.2, 0.1, 0.5,> } })");  // POV allows the last comma (float4.pov)
    expect_vec(scene.objects[0].material->pigment.color.rgb, {1, 0.5, 0});
    expect_vec(scene.objects[5].material->pigment.color.rgb, {0.2, 0.1, 0.5});
    EXPECT_DOUBLE_EQ(scene.objects[1].material->pigment.color.transmit, 0.25);
    EXPECT_DOUBLE_EQ(scene.objects[1].material->pigment.color.filter, 0.0);
    EXPECT_NEAR(scene.objects[2].material->pigment.color.rgb.x, 0.21404, 1e-4);  // sRGB decoded
    expect_vec(scene.objects[3].material->pigment.color.rgb, {0.5, 0, 1});
    EXPECT_DOUBLE_EQ(scene.objects[3].material->pigment.color.filter, 0.3);
    expect_vec(scene.objects[4].material->pigment.color.rgb, {0.5, 0.5, 0.5});
}

// rgb takes the whole arithmetic after it, as POV-Ray's Parse_Colour does:
// `rgb 0.6 + 0.3` is a grey of 0.9 with no filter or transmit (not rgb 0.6
// plus 0.3 in all five channels), and a second colour keyword or a
// channel name ends it.
TEST(ParserMaterials, ColourKeywordTakesTheWholeSum) {
    auto scene = parse_ok(R"(#declare X = 0.5;
        sphere { 0, 1 pigment { color rgb 0.6 + 0.5 * X } }
        sphere { 0, 1 pigment { rgbt <1, 0, 0, 0.2> * 0.5 + 0.25 } }
        sphere { 0, 1 pigment { rgb 0.2 * 2 - 0.1 filter 0.3 } }
        sphere { 0, 1 pigment { checker rgb 1 - X, rgb X + 0.25 } })");
    const sg::Color& grey = scene.objects[0].material->pigment.color;
    expect_vec(grey.rgb, {0.85, 0.85, 0.85});
    EXPECT_DOUBLE_EQ(grey.filter, 0.0);
    EXPECT_DOUBLE_EQ(grey.transmit, 0.0);
    const sg::Color& sum = scene.objects[1].material->pigment.color;
    expect_vec(sum.rgb, {0.75, 0.25, 0.25});
    EXPECT_DOUBLE_EQ(sum.filter, 0.0);  // the sum has rgbt's four terms
    EXPECT_DOUBLE_EQ(sum.transmit, 0.35);
    const sg::Color& filtered = scene.objects[2].material->pigment.color;
    expect_vec(filtered.rgb, {0.3, 0.3, 0.3});
    EXPECT_DOUBLE_EQ(filtered.filter, 0.3);
    const auto& blocks = scene.objects[3].material->pigment.block_pigments;
    ASSERT_EQ(blocks.size(), 2u);
    expect_vec(blocks[0]->color.rgb, {0.5, 0.5, 0.5});
    expect_vec(blocks[1]->color.rgb, {0.75, 0.75, 0.75});
}

TEST(ParserMaterials, CheckerAndPatternTransformFollowsObject) {
    auto scene = parse_ok("plane { y, 0 pigment { checker rgb 1, rgb 0 scale 2 } translate x }");
    auto m = scene.objects[0].material;
    ASSERT_TRUE(m);
    EXPECT_EQ(m->pigment.kind, sg::Pigment::Kind::Patterned);
    EXPECT_EQ(m->pigment.pattern->kind, sg::Pattern::Kind::Checker);
    ASSERT_EQ(m->pigment.block_pigments.size(), 2u);
    expect_vec(m->pigment.block_pigments[0]->color.rgb, {1, 1, 1});
    expect_vec(m->pigment.block_pigments[1]->color.rgb, {0, 0, 0});
    // Object space point (2,0,0) is pattern point (1,0,0): the later translate moves the pattern too.
    expect_vec(apply(m->pigment.pattern->pattern_from_object, {2, 0, 0}), {1, 0, 0});
}

TEST(ParserMaterials, DeclaredTexturesPigmentsFinishesReusable) {
    auto scene = parse_ok(R"(
        #declare P = pigment { rgb <0, 0, 1> }
        #declare F = finish { phong 1 }
        #declare T = texture { pigment { P } finish { F } }
        sphere { 0, 1 texture { T } }
        sphere { 0, 1 pigment { P } finish { F } })");
    EXPECT_EQ(scene.objects[0].material->name, "T");
    EXPECT_DOUBLE_EQ(scene.objects[0].material->finish->phong, 1);
    expect_vec(scene.objects[1].material->pigment.color.rgb, {0, 0, 1});
    EXPECT_DOUBLE_EQ(scene.objects[1].material->finish->phong, 1);
}

TEST(ParserLights, ShadowlessIsKeptOnPointAndParallelLights) {
    auto scene = parse_ok(R"(
        light_source { <1, 2, 3> color rgb 1 shadowless }
        light_source { <0, 10, 0>, 1 parallel point_at <0, 0, 0> shadowless }
        light_source { <0, 1, 0> rgb 1 })");
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_TRUE(scene.lights[0].shadowless);
    EXPECT_TRUE(scene.lights[1].shadowless);
    EXPECT_FALSE(scene.lights[2].shadowless);
}

TEST(ParserLights, ShadowlessOnAPhysicalLampWarns) {
    ParseResult result = test::parse_snippet(
        "light_source { <0, 5, 0> rgb 1 area_rectangle <1, 0, 0>, <0, 0, 1> shadowless }", "lamp.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_FALSE(result.scene->lights[0].shadowless);
    EXPECT_EQ(test::count_warnings(result), 1);
    EXPECT_NE(test::all_diagnostics(result).find("shadowless is ignored"), std::string::npos)
        << test::all_diagnostics(result);
}

// A spotlight's or cylinder light's radius, falloff and tightness.
void expect_cone(const sg::Light& light, double radius, double falloff, double tightness) {
    EXPECT_DOUBLE_EQ(light.spot_radius, radius);
    EXPECT_DOUBLE_EQ(light.spot_falloff, falloff);
    EXPECT_DOUBLE_EQ(light.tightness, tightness);
}

TEST(ParserLights, SpotlightKeepsPovsDefaultsAndValues) {
    auto scene = parse_ok(R"(
        light_source { <0, 10, 0> rgb 1 spotlight point_at <0, 0, 0> }
        light_source { <0, 10, 0> rgb 1 spotlight point_at <1, 0, 0> radius 11 falloff 25 tightness 50 })");
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_TRUE(scene.lights[0].spotlight);
    expect_cone(scene.lights[0], 30.0, 45.0, 0.0);
    expect_cone(scene.lights[1], 11.0, 25.0, 50.0);
    expect_vec(scene.lights[1].point_at, {1, 0, 0});
}

TEST(ParserLights, SpotParametersNeedASpotlight) {
    const Diagnostic d = test::first_error("light_source { <0, 10, 0> rgb 1 radius 11 }");
    EXPECT_NE(d.message.find("belong to a spotlight"), std::string::npos) << d.message;
    const Diagnostic parallel =
        test::first_error("light_source { <0, 10, 0> rgb 1 spotlight parallel point_at <0, 0, 0> }");
    EXPECT_NE(parallel.message.find("spotlight cannot be combined"), std::string::npos) << parallel.message;
}

TEST(ParserLights, CylinderLightIsAParallelBeamWithPovsDefaults) {
    auto scene = parse_ok(R"(
        light_source { <0, 10, 0> rgb 1 cylinder point_at <0, 0, 0> }
        light_source { <0, 10, 0> rgb 1 cylinder point_at <1, 0, 0> radius 2 falloff 3 tightness 4 })");
    ASSERT_EQ(scene.lights.size(), 2u);
    EXPECT_EQ(scene.lights[0].kind, sg::Light::Kind::Directional);
    EXPECT_TRUE(scene.lights[0].cylinder);
    expect_cone(scene.lights[0], 0.75, 1.0, 0.0);  // distances from the axis, for a cylinder
    expect_cone(scene.lights[1], 2.0, 3.0, 4.0);
    // Outside a light_source, cylinder is the shape.
    const auto shapes = parse_ok("cylinder { 0, y, 1 }");
    ASSERT_EQ(shapes.objects.size(), 1u);
    EXPECT_EQ(shapes.objects[0].kind, sg::Object::Kind::Cylinder);
}

TEST(ParserLights, LooksLikeJoinsTheSceneAndProjectedThroughStaysWithTheLight) {
    auto scene = parse_ok(R"(
        light_source { <1, 2, 3> rgb 1 looks_like { sphere { 0, 0.5 } } translate x
                       projected_through { box { -1, 1 } } })");
    ASSERT_EQ(scene.lights.size(), 1u);
    ASSERT_EQ(scene.objects.size(), 1u);  // the looks_like sphere, moved to the light, then by x
    const sg::Object& bulb = scene.objects[0];
    EXPECT_TRUE(bulb.no_shadow);
    expect_vec(sg::Vec3(bulb.parent_from_object * glm::dvec4(0, 0, 0, 1)), {2, 2, 3});
    ASSERT_TRUE(scene.lights[0].projected_through);
    // The projector was written after the translate: it is not moved.
    expect_vec(sg::Vec3(scene.lights[0].projected_through->parent_from_object * glm::dvec4(0, 0, 0, 1)), {0, 0, 0});
    EXPECT_FALSE(scene.lights[0].looks_like);
}

TEST(ParserLights, PointParallelAreaSphere) {
    auto scene = parse_ok(R"(
        light_source { <1, 2, 3> color rgb <1, 0.5, 0.25> fade_distance 2 fade_power 1 }
        light_source { <0, 10, 0>, 1 parallel point_at <0, 0, 0> }
        light_source { <0, 5, 0> rgb 1 area_light <2, 0, 0>, <0, 0, 1>, 5, 3 jitter adaptive 1 translate x }
        light_source { <0, 1, 0> rgb 1 area_sphere 0.25 }
        union { sphere { 0, 1 } light_source { <0, 1, 0> rgb 1 } translate y*2 }
        light_source { <0, 5, 0> rgb 1 area_rectangle <2, 0, 0>, <0, 0, 1> rotate y*90 })");
    ASSERT_EQ(scene.lights.size(), 6u);
    EXPECT_EQ(scene.lights[0].kind, sg::Light::Kind::Point);
    expect_vec(scene.lights[0].color, {1, 0.5, 0.25});
    EXPECT_DOUBLE_EQ(scene.lights[0].fade_distance, 2);
    EXPECT_FALSE(scene.lights[0].area_light);
    EXPECT_EQ(scene.lights[1].kind, sg::Light::Kind::Directional);
    expect_vec(scene.lights[1].point_at, {0, 0, 0});
    // POV's area_light is a point light with a grid of shadow samples.
    const auto& area = scene.lights[2];
    EXPECT_EQ(area.kind, sg::Light::Kind::Point);
    EXPECT_TRUE(area.area_light);
    expect_vec(area.position, {1, 5, 0});
    expect_vec(area.axis1, {2, 0, 0});
    EXPECT_EQ(area.samples1, 5);
    EXPECT_EQ(area.samples2, 3);
    EXPECT_TRUE(area.jitter);
    EXPECT_FALSE(area.circular || area.orient || area.area_illumination);
    EXPECT_EQ(area.adaptive, 1);
    EXPECT_EQ(scene.lights[3].kind, sg::Light::Kind::AreaSphere);
    EXPECT_DOUBLE_EQ(scene.lights[3].radius, 0.25);
    expect_vec(scene.lights[4].position, {0, 3, 0});  // follows the union
    const auto& panel = scene.lights[5];
    EXPECT_EQ(panel.kind, sg::Light::Kind::AreaRectangle);
    EXPECT_FALSE(panel.area_light);
    expect_vec(panel.axis1, {0, 0, -2});  // rotated with the light
}

TEST(ParserLights, AreaLightModifiersAsPovRay) {
    ParseResult result = test::parse_snippet(R"(
        light_source { 0, 1 area_light x, z, 4, 4 orient area_illumination on }
        light_source { 0, 1 area_light x, 2*z, 4, 4 circular orient }
        light_source { 0, 1 jitter })",
                                             "lights.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    const auto& lights = result.scene->lights;
    ASSERT_EQ(lights.size(), 3u);
    EXPECT_TRUE(lights[0].orient && lights[0].circular);  // orient makes it circular, as POV does
    EXPECT_TRUE(lights[0].area_illumination);
    EXPECT_EQ(lights[0].adaptive, 100);  // POV's default: the full grid
    EXPECT_FALSE(lights[2].jitter);      // dropped, with a warning: no area_light
    const std::string diagnostics = test::all_diagnostics(result);
    EXPECT_EQ(test::count_warnings(result), 3) << diagnostics;
    EXPECT_NE(diagnostics.find("is now circular"), std::string::npos) << diagnostics;
    EXPECT_NE(diagnostics.find("same length"), std::string::npos) << diagnostics;
    EXPECT_NE(diagnostics.find("only affect an area_light"), std::string::npos) << diagnostics;
}

TEST(ParserCamera, DefaultsAndAngleLookAt) {
    auto scene = parse_ok("camera { location <0, 0, -5> look_at <0, 0, 0> angle 90 }");
    ASSERT_TRUE(scene.camera);
    const auto& c = *scene.camera;
    expect_vec(c.location, {0, 0, -5});
    expect_vec(c.right, {1.33, 0, 0});
    expect_vec(c.up, {0, 1, 0});
    // |direction| = |right| / 2 / tan(45 deg) = 0.665
    expect_vec(c.direction, {0, 0, 0.665}, 1e-12);
}

TEST(ParserCamera, FixedOrderSkyRightAndOrthographic) {
    // look_at written before location still uses it; right from image size.
    auto scene = parse_ok("camera { look_at <1, 0, 0> right x*image_width/image_height location <0, 0, 0> }");
    const auto& c = *scene.camera;
    expect_vec(c.direction, {1, 0, 0});
    // right = normalize(sky x d) * |right|: y x x = -z
    expect_vec(c.right, {0, 0, -4.0 / 3.0});
    expect_vec(c.up, {0, 1, 0});
    auto ortho = parse_ok("camera { orthographic location <0,0,-1> look_at 0 }");
    EXPECT_EQ(ortho.camera->projection, sg::Camera::Projection::Orthographic);
}

TEST(ParserCamera, UpAlongDirectionHasNoHandednessSoLookAtMirrorsRight) {
    // POV-Ray's sample objects/fractal3.pov: up <0,0,1> lies along the
    // default direction, so (up x direction) . right is 0, not positive,
    // and look_at turns right the other way (POV's Parse_Camera).
    auto scene = parse_ok("camera { location <0, 3.3, 0> up <0, 0, 1> right x sky <0, 0, 1> look_at 0 }");
    const auto& c = *scene.camera;
    expect_vec(c.direction, {0, -1, 0});
    expect_vec(c.right, {-1, 0, 0});  // sky x direction = z x -y = +x, turned
    expect_vec(c.up, {0, 0, 1});
}

TEST(ParserCamera, TypesAndTheirAngles) {
    auto fisheye = parse_ok("camera { fisheye angle 270 location <0, 1, 0> look_at <0, 1, 5> }");
    EXPECT_EQ(fisheye.camera->projection, sg::Camera::Projection::Fisheye);
    EXPECT_DOUBLE_EQ(fisheye.camera->angle, 270.0);
    // Only perspective and orthographic cameras turn angle into |direction|.
    EXPECT_DOUBLE_EQ(glm::length(fisheye.camera->direction), 1.0);
    EXPECT_DOUBLE_EQ(parse_ok("camera { omnimax }").camera->angle, 90.0);  // POV's default
    auto spherical = parse_ok("camera { spherical angle 200 }");
    EXPECT_DOUBLE_EQ(spherical.camera->horizontal_angle, 200.0);
    EXPECT_DOUBLE_EQ(spherical.camera->vertical_angle, 100.0);  // half the first, as POV
    auto both = parse_ok("camera { spherical angle 90, 30 }");
    EXPECT_DOUBLE_EQ(both.camera->vertical_angle, 30.0);
    // POV-Ray's comma there is optional.
    auto without_comma = parse_ok("camera { spherical angle 360 180 location 0 }");
    EXPECT_DOUBLE_EQ(without_comma.camera->horizontal_angle, 360.0);
    EXPECT_DOUBLE_EQ(without_comma.camera->vertical_angle, 180.0);
    EXPECT_DOUBLE_EQ(parse_ok("#declare V = 90;\ncamera { spherical angle 360 V }").camera->vertical_angle, 90.0);
    EXPECT_DOUBLE_EQ(parse_ok("#declare V = 90;\ncamera { spherical angle 360 (V + 10) }").camera->vertical_angle,
                     100.0);
    EXPECT_EQ(parse_ok("camera { cylinder 3 }").camera->projection, sg::Camera::Projection::Cylinder3);
    // A bare orthographic angle scales to the look_at distance, keeping direction.
    auto ortho = parse_ok("camera { orthographic location <0, 0, -4> look_at 0 right x up y angle }");
    expect_vec(ortho.camera->right, {4, 0, 0});
    expect_vec(ortho.camera->direction, {0, 0, 1});
}

TEST(ParserCamera, FocalBlurAsPovReadsIt) {
    auto scene = parse_ok(
        "camera { location <0, 0, -5> look_at 0 angle 90 aperture 0.5 blur_samples 5, 40 confidence 0.8 "
        "variance 0.001 focal_point <3, 4, -5> }");
    const auto& c = *scene.camera;
    EXPECT_TRUE(c.focal_blur());
    EXPECT_DOUBLE_EQ(c.aperture, 0.5);
    EXPECT_EQ(c.blur_samples_min, 5);
    EXPECT_EQ(c.blur_samples, 40);
    EXPECT_DOUBLE_EQ(c.confidence, 0.8);
    EXPECT_DOUBLE_EQ(c.variance, 0.001);
    EXPECT_DOUBLE_EQ(c.focal_distance, 5.0);  // |focal_point - location|
    // Without focal_point: POV's Direction_Length, what angle made it.
    auto unfocused = parse_ok("camera { angle 90 aperture 1 blur_samples 4 }");
    EXPECT_EQ(unfocused.camera->blur_samples, 4);
    EXPECT_EQ(unfocused.camera->blur_samples_min, 0);
    EXPECT_NEAR(unfocused.camera->focal_distance, 0.665, 1e-12);
    // A bare direction leaves it at 1, as in POV-Ray.
    EXPECT_DOUBLE_EQ(parse_ok("camera { direction z * 3 }").camera->focal_distance, 1.0);
}

TEST(ParserCamera, FocalBlurSettingsThatDoNothingWarn) {
    for (const char* text :
         {"camera { aperture 1 }", "camera { blur_samples 10 }", "camera { orthographic aperture 1 blur_samples 10 }",
          "camera { aperture 1 blur_samples 10 confidence 1.5 }", "camera { bokeh { pigment { rgb 1 } } }"}) {
        const ParseResult result = test::parse_snippet(text, "w.pov");
        EXPECT_TRUE(result.ok()) << text;
        EXPECT_GE(test::count_warnings(result), 1) << text;
    }
    EXPECT_EQ(test::count_warnings(test::parse_snippet("camera { aperture 1 blur_samples 10 }", "w.pov")), 0);
}

TEST(ParserCamera, BokehKeepsItsPigment) {
    auto scene = parse_ok(
        "camera { aperture 1 blur_samples 10 bokeh { pigment { gradient x color_map { [0.5 rgb 0] [0.5 rgb 1] } } } }");
    ASSERT_TRUE(scene.camera->bokeh);
    EXPECT_EQ(scene.camera->bokeh->kind, sg::Pigment::Kind::Patterned);
    EXPECT_FALSE(parse_ok("camera { aperture 1 blur_samples 10 }").camera->bokeh);
}

TEST(ParserCamera, NormalIsKept) {
    EXPECT_TRUE(parse_ok("camera { normal { bumps 0.5 } }").camera->normal);
}

TEST(ParserCamera, ImageSizeFromOptionsAndRenderSettings) {
    ParseOptions options;
    options.image_width = 800;
    options.image_height = 400;
    auto scene = parse_ok("#declare W = image_width; #declare H = image_height; sphere { 0, W / H }", options);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[0].shape).radius, 2.0);
    auto with_settings = parse_ok("render_settings { width 300 height 100 } sphere { 0, image_width / image_height }");
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(with_settings.objects[0].shape).radius, 3.0);
}

TEST(ParserSettings, GlobalBackgroundAndRenderSettings) {
    auto scene = parse_ok(R"(
        global_settings { assumed_gamma 1.0 max_trace_level 7 ambient_light rgb 0.5 adc_bailout 0.01 }
        background { color rgb <0.1, 0.2, 0.3> }
        render_settings { integrator "path" { max_depth 8 russian_roulette on tint <1, 0.5, 0> label "x" fresnel true }
                          width 640 height 480 samples 16 seed 7 })");
    EXPECT_EQ(scene.global.max_trace_level, 7);
    expect_vec(scene.global.ambient_light, {0.5, 0.5, 0.5});
    EXPECT_DOUBLE_EQ(scene.global.adc_bailout, 0.01);
    expect_vec(scene.background, {0.1, 0.2, 0.3});
    ASSERT_TRUE(scene.render.integrator);
    EXPECT_EQ(*scene.render.integrator, "path");
    EXPECT_EQ(std::get<double>(scene.render.parameters.at("max_depth").value), 8.0);
    EXPECT_EQ(std::get<bool>(scene.render.parameters.at("russian_roulette").value), true);
    expect_vec(std::get<sg::Vec3>(scene.render.parameters.at("tint").value), {1, 0.5, 0});
    EXPECT_EQ(std::get<std::string>(scene.render.parameters.at("label").value), "x");
    EXPECT_EQ(std::get<bool>(scene.render.parameters.at("fresnel").value), true);  // a keyword as a name
    EXPECT_EQ(*scene.render.width, 640);
    EXPECT_EQ(*scene.render.height, 480);
    EXPECT_EQ(*scene.render.samples, 16);
    EXPECT_EQ(*scene.render.seed, 7u);
}

TEST(ParserExpressions, OperatorsFunctionsAndComponents) {
    auto scene = parse_ok(R"(
        #declare V = <1, 2, 3>;
        #declare A = V.y + vdot(V, x) * 2 - pow(2, 3) / 4;   // 2 + 2 - 2 = 2
        #declare B = (A > 1 & A < 3) ? 10 : 20;
        #declare C = vlength(vcross(x, y)) + abs(-1) + max(1, 5, 3) + mod(7, 4) + int(2.7) + floor(-0.5);
        #declare D = vrotate(x, <0, 0, 90>);
        #declare E = degrees(atan2(1, 1)) + radians(180) / pi;
        #declare S = concat("a", str(1.5, 0, 1), chr(66));
        sphere { D, A }
        sphere { <B, C, E>, 1 }
        #if (strlen(S) = 5 & !false & yes) sphere { 0, 1 } #end
    )");
    ASSERT_EQ(scene.objects.size(), 3u);
    const auto& s0 = std::get<sg::Sphere>(scene.objects[0].shape);
    EXPECT_DOUBLE_EQ(s0.radius, 2.0);
    expect_vec(s0.center, {0, 1, 0}, 1e-12);
    const auto& s1 = std::get<sg::Sphere>(scene.objects[1].shape);
    expect_vec(s1.center, {10, 1 + 1 + 5 + 3 + 2 - 1, 46}, 1e-9);
}

TEST(ParserExpressions, RandIsReproducible) {
    auto a = parse_ok("#declare R = seed(42); sphere { <rand(R), rand(R), 0>, 1 }");
    auto b = parse_ok("#declare R = seed(42); sphere { <rand(R), rand(R), 0>, 1 }");
    auto ca = std::get<sg::Sphere>(a.objects[0].shape).center, cb = std::get<sg::Sphere>(b.objects[0].shape).center;
    EXPECT_EQ(ca, cb);
    EXPECT_NE(ca.x, ca.y);
    EXPECT_GE(ca.x, 0.0);
    EXPECT_LT(ca.x, 1.0);
}

// POV-Ray's own sequence, so objects placed at random land where POV-Ray
// puts them. Printed by Debian's povray 3.7 with str(rand(S), 0, 12).
TEST(ParserExpressions, RandIsPovRaysSequence) {
    auto scene = parse_ok(
        "#declare S1 = seed(1); #declare S2 = seed(12); #declare S3 = seed(-5.9);\n"
        "sphere { <rand(S1), rand(S1), rand(S2)>, 1 }\n"
        "sphere { <rand(S3), rand(S3), S2>, 1 }\n");
    const sg::Vec3 first = std::get<sg::Sphere>(scene.objects[0].shape).center;
    const sg::Vec3 second = std::get<sg::Sphere>(scene.objects[1].shape).center;
    EXPECT_NEAR(first.x, 0.421992875268, 1e-12);
    EXPECT_NEAR(first.y, 0.487121198207, 1e-12);
    EXPECT_NEAR(first.z, 0.063882884817, 1e-12);
    EXPECT_NEAR(second.x, 0.890052870123, 1e-12);  // seed -5.9 is -5, modulo 2^32
    EXPECT_NEAR(second.y, 0.363776116018, 1e-12);
    EXPECT_EQ(second.z, 1.0);  // streams are numbered from 0
}

TEST(ParserObjects, NoShadowHollowAndIgnoredKeywordsWarn) {
    ParseResult result = test::parse_snippet(
        "sphere { 0, 1 no_shadow hollow double_illuminate no_radiosity normal { bumps 0.5 } }", "w.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_TRUE(result.scene->objects[0].no_shadow);
    EXPECT_TRUE(result.scene->objects[0].hollow);
    EXPECT_EQ(result.scene->objects[0].double_illuminate, std::optional<bool>(true));
    EXPECT_EQ(test::count_warnings(result), 1);  // no_radiosity (hollow has a meaning: media)
    ASSERT_TRUE(result.scene->objects[0].material && result.scene->objects[0].material->normal);
    EXPECT_EQ(result.scene->objects[0].material->normal->pattern->kind, sg::Pattern::Kind::Bumps);
    EXPECT_DOUBLE_EQ(result.scene->objects[0].material->normal->bump_size, 0.5);
    for (const auto& d : result.diagnostics) EXPECT_EQ(d.location.line, 1);
}

TEST(ParserObjects, DoubleIlluminateTakesAnOptionalSwitch) {
    ParseResult result = test::parse_snippet(
        "disc { 0, y, 1 double_illuminate off }\n"
        "disc { 0, y, 1 double_illuminate 1 }\n"
        "disc { 0, y, 1 }\n",
        "d.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(result.scene->objects[0].double_illuminate, std::optional<bool>(false));
    EXPECT_EQ(result.scene->objects[1].double_illuminate, std::optional<bool>(true));
    EXPECT_FALSE(result.scene->objects[2].double_illuminate.has_value());
    EXPECT_EQ(test::count_warnings(result), 0);
}

TEST(ParserObjects, NoImageAndNoReflectionTakeAnOptionalSwitch) {
    ParseResult result = test::parse_snippet(
        "sphere { 0, 1 no_image no_reflection off }\n"
        "sphere { 0, 1 no_image 0 no_reflection }\n"
        "sphere { 0, 1 }\n",
        "h.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_TRUE(result.scene->objects[0].no_image);
    EXPECT_FALSE(result.scene->objects[0].no_reflection);
    EXPECT_FALSE(result.scene->objects[1].no_image);
    EXPECT_TRUE(result.scene->objects[1].no_reflection);
    EXPECT_FALSE(result.scene->objects[2].no_image || result.scene->objects[2].no_reflection);
    EXPECT_EQ(test::count_warnings(result), 0);
}

// interior_texture: kept beside the texture whatever their order, in the
// space a texture written at the same place would have (moving with the
// object's later transforms, not its earlier ones).
TEST(ParserObjects, InteriorTextureSitsBesideTheTexture) {
    ParseResult result = test::parse_snippet(
        "sphere { 0, 1 scale 2 interior_texture { pigment { checker rgb 1 rgb 0 } } texture { pigment { rgb x } } "
        "translate 3*y }\n"
        "sphere { 0, 1 texture { pigment { rgb x } } interior_texture { pigment { rgb y } } }\n"
        "sphere { 0, 1 scale 2 texture { pigment { checker rgb 1 rgb 0 } } translate 3*y }\n",
        "i.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(test::count_warnings(result), 0);
    const sg::Object& first = result.scene->objects[0];
    ASSERT_TRUE(first.material && first.material->interior_texture);
    EXPECT_EQ(first.material->pigment.color.rgb, sg::Vec3(1.0, 0.0, 0.0));
    const sg::Mat4& inside = first.material->interior_texture->pigment.pattern->pattern_from_object;
    const sg::Mat4& as_texture = result.scene->objects[2].material->pigment.pattern->pattern_from_object;
    for (int column = 0; column < 4; ++column)
        for (int row = 0; row < 4; ++row) EXPECT_NEAR(inside[column][row], as_texture[column][row], 1e-12);
    EXPECT_NE(inside, sg::Mat4(1.0));  // the comparison means something
    const sg::Object& second = result.scene->objects[1];
    ASSERT_TRUE(second.material && second.material->interior_texture);
    EXPECT_EQ(second.material->interior_texture->pigment.color.rgb, sg::Vec3(0.0, 1.0, 0.0));
}

TEST(ParserObjects, ImageMapResolvesNextToTheScene) {
    ParseResult result = test::parse_snippet("sphere { 0, 1 pigment { image_map { png \"missing.png\" } } }", "i.pov");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(test::all_diagnostics(result).find("cannot find image file \"missing.png\""), std::string::npos);
}

TEST(SceneSummary, CountsAndBounds) {
    auto scene = parse_ok(R"(
        sphere { <0, 0, 0>, 1 }
        box { <2, 2, 2>, <3, 3, 3> translate x }
        plane { y, -1 }
        mesh { triangle { 0, x, y } triangle { 0, y, z } }
        light_source { <0, 5, 0> rgb 1 }
        light_source { <0, 5, 0> rgb 1 parallel point_at 0 })");
    auto summary = summarize_scene(scene);
    EXPECT_EQ(summary.object_count, 4);
    EXPECT_EQ(summary.triangles, 2);
    EXPECT_EQ(summary.unbounded_objects, 1);
    ASSERT_TRUE(summary.bounds);
    expect_vec(summary.bounds->first, {-1, -1, -1});
    expect_vec(summary.bounds->second, {4, 3, 3});
    EXPECT_EQ(summary.lights_by_kind["point"], 1);
    EXPECT_EQ(summary.lights_by_kind["directional"], 1);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// POV's finish values are peaks: `diffuse 0.8 reflection 0.5` returns 1.3
// of the light; path says so, at the finish.
TEST(FinishBalance, WarnsAtFinishesThatReturnMoreThanTheyReceive) {
    auto scene = parse_ok(R"(
        sphere { 0, 1 pigment { color rgb 1 } finish { diffuse 0.8 reflection 0.5 } }
        sphere { 0, 1 pigment { color rgb 1 } finish { diffuse 0.6 phong 1 } }
        sphere { 0, 1 pigment { color rgb 0.5 } finish { diffuse 0.8 reflection 0.5 } }
        sphere { 0, 1 pigment { color rgb 1 } finish { phong 1 phong_size 1 } })");
    const std::vector<Diagnostic> warnings = energy_gaining_finishes(scene);
    ASSERT_EQ(warnings.size(), 2u);
    EXPECT_EQ(warnings[0].location.line, 2);
    EXPECT_NE(warnings[0].message.find("1.3 times"), std::string::npos) << warnings[0].message;
    EXPECT_EQ(warnings[1].location.line, 5);  // 0.6 + 1 * 2 / (1 + 1)
    sg::Finish clear;
    clear.diffuse = 0.6;
    clear.reflection.min = clear.reflection.max = sg::Vec3(0.5);
    EXPECT_NEAR(finish_reflectance_bound(clear, 1.0, 1.0), 1.5, 1e-12);  // glass: all passes, and the mirror
    clear.conserve_energy = true;
    EXPECT_NEAR(finish_reflectance_bound(clear, 1.0, 1.0), 1.0, 1e-12);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// POV-Ray's #version: `version` reads the version in force; a scene that
// ends below 3.7 without assumed_gamma is in POV's legacy gamma mode.
TEST(ParserVersion, VersionIsReadBackAndSetsLegacyGamma) {
    auto legacy = parse_ok(R"(#version 3.5;
        #declare Seen = version;
        #version 3.7;
        #declare Now = version;
        #version Seen;
        sphere { <Seen, Now, 0>, 1 })");
    EXPECT_FALSE(legacy.global.gamma_correction);
    EXPECT_DOUBLE_EQ(legacy.global.language_version, 3.5);
    const auto& centre = std::get<sg::Sphere>(legacy.objects[0].shape).center;
    expect_vec(centre, {3.5, 3.7, 0});
    EXPECT_TRUE(parse_ok("#version 3.6; global_settings { assumed_gamma 2.2 }").global.gamma_correction);
    EXPECT_TRUE(parse_ok("#version 3.7;").global.gamma_correction);
    // No #version at all (and no +MV): POV-Ray 3.7 reads `version` as 3.7
    // but the scene as 3.62, so legacy gamma without assumed_gamma, and a
    // warning that says why (measured: a lit box's bytes are POV's linear
    // values, not sRGB-encoded ones).
    const ParseResult bare = parse_scene_string("#declare V = version; sphere { V * x, 1 }", "bare.pov");
    ASSERT_TRUE(bare.ok()) << test::all_diagnostics(bare);
    EXPECT_FALSE(bare.scene->global.gamma_correction);
    EXPECT_DOUBLE_EQ(bare.scene->global.language_version, 3.62);
    expect_vec(std::get<sg::Sphere>(bare.scene->objects[0].shape).center, {3.7, 0, 0});
    EXPECT_EQ(test::count_warnings(bare), 1);
    EXPECT_NE(test::all_diagnostics(bare).find("without #version"), std::string::npos) << test::all_diagnostics(bare);
    const ParseResult gamma_set = parse_scene_string("global_settings { assumed_gamma 1 } sphere { 0, 1 }");
    ASSERT_TRUE(gamma_set.ok());
    EXPECT_TRUE(gamma_set.scene->global.gamma_correction);
    // POV's Version= (+MV) stands in for a #version until the scene has one.
    ParseOptions as_3_5;
    as_3_5.language_version = 3.5;
    EXPECT_FALSE(parse_ok("#declare V = version; sphere { V * x, 1 }", as_3_5).global.gamma_correction);
    EXPECT_TRUE(parse_ok("sphere { 0, 1 }").global.gamma_correction);  // the helpers' +MV3.7
    EXPECT_TRUE(parse_ok("#version 3.7; sphere { 0, 1 }", as_3_5).global.gamma_correction);
    const Diagnostic bad = test::first_error("#version -1;");
    EXPECT_NE(bad.message.find("#version must be"), std::string::npos) << bad.message;
}

// inside_vector makes a mesh a solid for CSG (POV-Ray 3.7: mesh and mesh2);
// a triangle or a mesh without it is a patch object: a warning in an
// intersection or difference, an error as a clip.
TEST(ParserObjects, InsideVectorAndPatchObjectsInCsg) {
    auto scene = parse_ok(R"(
        mesh { triangle { 0, x, y } triangle { 0, y, z } inside_vector <0, 0, 2> }
        mesh2 { vertex_vectors { 3, 0, x, y } face_indices { 1, <0, 1, 2> } inside_vector y })");
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(*std::get<sg::MeshRef>(scene.objects[0].shape)->inside_vector, sg::Vec3(0, 0, 1));
    EXPECT_EQ(*std::get<sg::MeshRef>(scene.objects[1].shape)->inside_vector, sg::Vec3(0, 1, 0));  // normalised

    ParseResult patch = test::parse_snippet("difference { sphere { 0, 1 } triangle { 0, x, y } }");
    ASSERT_TRUE(patch.ok()) << test::all_diagnostics(patch);
    EXPECT_NE(test::all_diagnostics(patch).find("has no inside"), std::string::npos);
    EXPECT_EQ(test::count_warnings(
                  test::parse_snippet("difference { sphere { 0, 1 } mesh { triangle { 0, x, y } inside_vector z } }")),
              0);
    const Diagnostic clip = test::first_error("sphere { 0, 1 clipped_by { triangle { 0, x, y } } }");
    EXPECT_NE(clip.message.find("cannot clip"), std::string::npos) << clip.message;
    // POV-Ray takes a zero inside_vector as none.
    auto zero = parse_ok("mesh { triangle { 0, x, y } inside_vector 0 }");
    EXPECT_FALSE(std::get<sg::MeshRef>(zero.objects[0].shape)->inside_vector);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

TEST(ParserIgnoredForms, QuickColourNoRadiosityAndMmPerUnitWarn) {
    // Forms from POV-Ray's samples (sunsethf, chess2, subsurface) that change
    // nothing lancer draws: accepted with a warning each.
    const ParseResult result = test::parse_snippet(
        "global_settings { mm_per_unit 10 }\n"
        "sphere { 0, 1 pigment { rgb 1 quick_colour red 0.7 green 0.7 blue 1.0 } no_radiosity }\n"
        "sphere { 0, 1 pigment { quick_color red 0.95 green 0.62 } }\n",
        "ignored.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(test::count_warnings(result), 4);
}

// POV's light_group: a union whose lights (moved with it) belong to the
// group, as does the object; global_lights is off unless given; a group
// inside keeps its own lights and objects.
TEST(ParserObjects, LightGroupsTagTheirLightsAndObjects) {
    const auto scene = parse_ok(R"(
        light_source { <0, 10, 0> color rgb 1 }
        light_group {
          light_source { <1, 2, 3> color rgb 1 }
          sphere { 0, 1 }
          light_group { light_source { 0 color rgb 0.5 } box { -1, 1 } global_lights }
          translate x * 10
        }
        #declare G = light_group { sphere { 0, 1 } global_lights off }
        object { G })");
    ASSERT_EQ(scene.light_groups.size(), 3u);
    ASSERT_EQ(scene.lights.size(), 3u);
    EXPECT_EQ(scene.lights[0].light_group, -1);
    // The inner group is read first: it is group 0, the outer one group 1.
    EXPECT_FALSE(scene.light_groups[1].global_lights);
    EXPECT_TRUE(scene.light_groups[0].global_lights);
    EXPECT_FALSE(scene.light_groups[2].global_lights);
    int outer_lights = 0, inner_lights = 0;
    for (const sg::Light& light : scene.lights) {
        if (light.light_group == 1) {
            ++outer_lights;
            expect_vec(light.position, {11, 2, 3});
        }
        if (light.light_group == 0) {
            ++inner_lights;
            expect_vec(light.position, {10, 0, 0});
        }
    }
    EXPECT_EQ(outer_lights, 1);
    EXPECT_EQ(inner_lights, 1);
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].light_group, 1);
    const auto& children = std::get<sg::Group>(scene.objects[0].shape).children;
    ASSERT_EQ(children.size(), 2u);
    EXPECT_EQ(children[0].light_group, -1);  // in the group through its parent
    EXPECT_EQ(children[1].light_group, 0);
    EXPECT_EQ(scene.objects[1].light_group, 2);
}

TEST(ParserObjects, LightGroupLimitsAndSyntax) {
    const Diagnostic many = test::first_error("#for (I, 0, 40000) light_group { sphere { 0, 1 } } #end");
    EXPECT_NE(many.message.find("more than 32767 light_groups"), std::string::npos) << many.message;
    EXPECT_EQ(many.location.line, 1);
    // global_lights belongs in a light_group only.
    test::first_error("union { sphere { 0, 1 } global_lights on }");
    const auto empty = parse_ok("light_group { }");
    EXPECT_EQ(empty.light_groups.size(), 1u);
}

}  // namespace
}  // namespace lancer
