// parametric read as POV-Ray 3.7 reads it (Parse_Parametric): three
// functions of u and v (commas between them optional), the (u, v) corners
// (each coordinate ordered), then contained_by, accuracy, max_gradient and
// precompute in any order; POV's defaults, and located errors for what
// POV-Ray refuses or cannot search.
#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::contains;

using test::first_error;
using test::parse_ok;

const sg::Parametric& parametric_of(const sg::SceneGraph& scene, std::size_t i = 0) {
    return std::get<sg::Parametric>(scene.objects.at(i).shape);
}

double at_uv(const sg::Parametric& p, int axis, double u, double v) {
    const double arguments[3] = {u, v, 0.0};
    return sg::evaluate_function(*p.functions[std::size_t(axis)], arguments, 3, nullptr);
}

TEST(ParserParametric, DefaultsArePovRays) {
    auto scene = parse_ok("parametric { function { u } function { v } function { u * v } <0, 0>, <1, 2> }");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(scene.objects[0].kind, sg::Object::Kind::Parametric);
    const auto& p = parametric_of(scene);
    EXPECT_DOUBLE_EQ(at_uv(p, 0, 0.25, 0.5), 0.25);
    EXPECT_DOUBLE_EQ(at_uv(p, 1, 0.25, 0.5), 0.5);
    EXPECT_DOUBLE_EQ(at_uv(p, 2, 0.25, 0.5), 0.125);
    EXPECT_EQ(p.uv_min, sg::Vec2(0, 0));
    EXPECT_EQ(p.uv_max, sg::Vec2(1, 2));
    EXPECT_EQ(p.container, sg::FunctionContainer::Container::Box);
    EXPECT_EQ(p.box_corner1, sg::Vec3(-1.0));
    EXPECT_EQ(p.box_corner2, sg::Vec3(1.0));
    EXPECT_DOUBLE_EQ(p.accuracy, 0.001);
    EXPECT_DOUBLE_EQ(p.max_gradient, 1.0);
    EXPECT_EQ(p.precompute_depth, 0);
    EXPECT_EQ(p.precompute_axes, 0);
}

TEST(ParserParametric, EverySettingInAnyOrder) {
    auto scene = parse_ok(R"(
        #declare Fx = function(u, v) { cos(u) * sin(v) }
        parametric {
          function { Fx(u, v) }, function { cos(v) }, function { sin(u) * sin(v) }
          <2*pi, pi>, <0, 0>
          accuracy 0.004 precompute 12, x, z max_gradient 2.5
          contained_by { sphere { <0, 1, 0>, 1.1 } }
          pigment { rgb 1 } translate y
        }
        parametric { function { u } function { v } function { 0 } <0, 1>, <1, 0>
                     contained_by { box { <2, 1, 3>, <-2, -1, -3> } } precompute 20 y })");
    const auto& p = parametric_of(scene);
    EXPECT_NEAR(at_uv(p, 0, 0.0, 0.5 * M_PI), 1.0, 1e-15);
    EXPECT_EQ(p.uv_min, sg::Vec2(0, 0));  // POV orders each coordinate
    EXPECT_EQ(p.uv_max, sg::Vec2(2 * M_PI, M_PI));
    EXPECT_DOUBLE_EQ(p.accuracy, 0.004);
    EXPECT_DOUBLE_EQ(p.max_gradient, 2.5);
    EXPECT_EQ(p.precompute_depth, 12);
    EXPECT_EQ(p.precompute_axes, 1 | 4);
    EXPECT_EQ(p.container, sg::FunctionContainer::Container::Sphere);
    EXPECT_EQ(p.sphere_center, sg::Vec3(0, 1, 0));
    EXPECT_DOUBLE_EQ(p.sphere_radius, 1.1);
    EXPECT_DOUBLE_EQ(scene.objects[0].parent_from_object[3][1], 1.0);
    ASSERT_TRUE(scene.objects[0].material);
    const auto& q = parametric_of(scene, 1);
    EXPECT_EQ(q.uv_min, sg::Vec2(0, 0));
    EXPECT_EQ(q.uv_max, sg::Vec2(1, 1));
    EXPECT_EQ(q.box_corner1, sg::Vec3(-2, -1, -3));
    EXPECT_EQ(q.box_corner2, sg::Vec3(2, 1, 3));
    EXPECT_EQ(q.precompute_depth, 20);
    EXPECT_EQ(q.precompute_axes, 2);
}

// POV-Ray checks precompute's depth only when a coordinate is named.
TEST(ParserParametric, PrecomputeWithoutCoordinatesIsNothing) {
    auto scene = parse_ok("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> precompute 40 }");
    EXPECT_EQ(parametric_of(scene).precompute_depth, 0);
    EXPECT_EQ(parametric_of(scene).precompute_axes, 0);
}

TEST(ParserParametric, FallbacksWarn) {
    const ParseResult result = test::parse_snippet(
        "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> accuracy 0 max_gradient -1 }",
        "fallbacks.pov");
    ASSERT_TRUE(result.ok());
    EXPECT_EQ(test::count_warnings(result), 2);
    EXPECT_DOUBLE_EQ(parametric_of(*result.scene).accuracy, 0.001);
    EXPECT_DOUBLE_EQ(parametric_of(*result.scene).max_gradient, 1.0);
}

TEST(ParserParametric, LocatedErrors) {
    const Diagnostic depth =
        first_error("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> precompute 21 x }");
    EXPECT_TRUE(contains(depth.message, "depth must be 1 to 20")) << depth.message;
    EXPECT_EQ(depth.location.column, 85);
    const Diagnostic axis =
        first_error("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> precompute 5 x, t }");
    EXPECT_TRUE(contains(axis.message, "not 't'")) << axis.message;
    const Diagnostic colour =
        first_error("parametric { function { u } function { pigment { rgb 1 } } function { 0 } <0, 0>, <1, 1> }");
    EXPECT_EQ(colour.location.line, 1);
    EXPECT_FALSE(colour.message.empty());
    const Diagnostic corner = first_error("parametric { function { u } function { v } function { 0 } \"a\", <1, 1> }");
    EXPECT_TRUE(contains(corner.message, "(u, v) range")) << corner.message;
    const Diagnostic huge =
        first_error("parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> accuracy 1e400 }");
    EXPECT_FALSE(huge.message.empty());
    const Diagnostic missing = first_error("parametric { function { u } function { v } <0, 0>, <1, 1> }");
    EXPECT_EQ(missing.location.line, 1);
    const Diagnostic radius = first_error(
        "parametric { function { u } function { v } function { 0 } <0, 0>, <1, 1> contained_by { sphere { 0, 0 } } }");
    EXPECT_TRUE(contains(radius.message, "radius must be positive")) << radius.message;
}

}  // namespace
}  // namespace lancer
