// isosurface read as POV-Ray 3.7 reads it (Parse_Isosurface): the function
// first, then container and settings in any order, POV's defaults, its
// warnings and fallbacks, and the errors for what it refuses.
#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::contains;

using test::first_error;
using test::parse_ok;

const sg::Isosurface& isosurface_of(const sg::SceneGraph& scene, std::size_t i = 0) {
    return std::get<sg::Isosurface>(scene.objects.at(i).shape);
}

TEST(ParserIsosurface, DefaultsArePovRays) {
    auto scene = parse_ok("isosurface { function { x*x + y*y + z*z - 1 } }");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].kind, sg::Object::Kind::Isosurface);
    const auto& iso = isosurface_of(scene);
    ASSERT_TRUE(iso.function);
    const double at[3] = {2.0, 0.0, 0.0};
    EXPECT_DOUBLE_EQ(sg::evaluate_function(*iso.function, at, 3, nullptr), 3.0);
    EXPECT_EQ(iso.container, sg::Isosurface::Container::Box);
    EXPECT_EQ(iso.box_corner1, sg::Vec3(-1.0));
    EXPECT_EQ(iso.box_corner2, sg::Vec3(1.0));
    EXPECT_DOUBLE_EQ(iso.threshold, 0.0);
    EXPECT_DOUBLE_EQ(iso.accuracy, 0.001);
    EXPECT_DOUBLE_EQ(iso.max_gradient, 1.1);
    EXPECT_FALSE(iso.evaluate);
    EXPECT_FALSE(iso.open);
    EXPECT_EQ(iso.max_trace, 1);
}

TEST(ParserIsosurface, EverySettingInAnyOrder) {
    auto scene = parse_ok(R"(
        #declare F = function(x, y, z) { y - 0.5 * sin(4 * x) }
        isosurface {
          function { F(x, y, z) }
          threshold 0.25 open max_gradient 3.5
          contained_by { box { <2, 1, 3>, <-2, -1, -3> } }
          accuracy 1e-4 evaluate 5, 1.2, 0.95 all_intersections
          pigment { rgb 1 } translate y
        }
        isosurface { function { x } contained_by { sphere { <1, 2, 3>, 4 } } max_trace 3 })");
    const auto& iso = isosurface_of(scene);
    EXPECT_DOUBLE_EQ(iso.threshold, 0.25);
    EXPECT_TRUE(iso.open);
    EXPECT_DOUBLE_EQ(iso.max_gradient, 3.5);
    EXPECT_EQ(iso.box_corner1, sg::Vec3(-2, -1, -3));  // POV orders the corners
    EXPECT_EQ(iso.box_corner2, sg::Vec3(2, 1, 3));
    EXPECT_DOUBLE_EQ(iso.accuracy, 1e-4);
    EXPECT_TRUE(iso.evaluate);
    EXPECT_EQ(iso.evaluate_parameters, sg::Vec3(5, 1.2, 0.95));
    EXPECT_EQ(iso.max_trace, 10);
    EXPECT_DOUBLE_EQ(scene.objects[0].parent_from_object[3][1], 1.0);
    ASSERT_TRUE(scene.objects[0].material);
    const auto& sphere = isosurface_of(scene, 1);
    EXPECT_EQ(sphere.container, sg::Isosurface::Container::Sphere);
    EXPECT_EQ(sphere.sphere_center, sg::Vec3(1, 2, 3));
    EXPECT_DOUBLE_EQ(sphere.sphere_radius, 4.0);
    EXPECT_EQ(sphere.max_trace, 3);
}

TEST(ParserIsosurface, PovsFallbacksWarn) {
    const ParseResult result = test::parse_snippet(
        "isosurface { function { x } accuracy 0 max_gradient -2 }\n"
        "isosurface { function { x } max_trace 12 }\n"
        "isosurface { function { x } max_trace 0 }",
        "fallbacks.pov");
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(test::count_warnings(result), 4);
    EXPECT_DOUBLE_EQ(isosurface_of(*result.scene, 0).accuracy, 0.001);
    EXPECT_DOUBLE_EQ(isosurface_of(*result.scene, 0).max_gradient, 1.1);
    EXPECT_EQ(isosurface_of(*result.scene, 1).max_trace, 10);
    EXPECT_EQ(isosurface_of(*result.scene, 2).max_trace, 1);
}

TEST(ParserIsosurface, FunctionsFromFunctionsIncAndPatterns) {
    auto scene = parse_ok(R"(
        #include "functions.inc"
        isosurface { function { f_torus(x, y, z, 0.8, 0.2) } }
        isosurface { function { pattern { bozo scale 0.3 } } })");
    ASSERT_EQ(scene.objects.size(), 2u);
    const double at[3] = {0.8, 0.1, 0.0};
    EXPECT_NEAR(sg::evaluate_function(*isosurface_of(scene).function, at, 3, nullptr), -0.1, 1e-12);
    EXPECT_TRUE(isosurface_of(scene, 1).function->pattern);
}

TEST(ParserIsosurface, LocatedErrors) {
    const Diagnostic missing = first_error("isosurface { contained_by { box { -1, 1 } } }");
    EXPECT_EQ(missing.location.line, 1);
    EXPECT_FALSE(missing.message.empty());
    const Diagnostic radius = first_error("isosurface { function { x } contained_by { sphere { 0, -1 } } }");
    EXPECT_TRUE(contains(radius.message, "radius must be positive")) << radius.message;
    EXPECT_EQ(radius.location.column, 56);
    const Diagnostic colour = first_error("isosurface { function { pigment { rgb 1 } } }");
    EXPECT_FALSE(colour.message.empty());
    const Diagnostic internal = first_error("isosurface { function { internal(77) } }");
    EXPECT_TRUE(contains(internal.message, "no internal function 77")) << internal.message;
    const Diagnostic huge = first_error("isosurface { function { x } threshold 1e300 }");
    EXPECT_EQ(huge.location.column, 39);
}

}  // namespace
}  // namespace lancer
