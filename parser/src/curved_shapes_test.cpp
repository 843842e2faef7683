// ovus, sphere_sweep, bicubic_patch, julia_fractal, height_field and
// POV 3.7's polynomial { xyz(i, j, k): c } read as POV-Ray 3.7 reads them:
// arguments, defaults, and the inputs POV refuses.
#include <cmath>
#include <filesystem>

#include "parse_test_helpers.h"
#include "run_command.h"

namespace lancer {
namespace {

using test::contains;

using test::first_error;
using test::parse_ok;

TEST(ParserCurvedShapes, OvusRadiiAndRefusals) {
    auto scene = parse_ok("ovus { 1, 0.6 translate y }");
    const auto& ovus = std::get<sg::Ovus>(scene.objects[0].shape);
    EXPECT_DOUBLE_EQ(ovus.bottom_radius, 1.0);
    EXPECT_DOUBLE_EQ(ovus.top_radius, 0.6);
    EXPECT_TRUE(contains(first_error("ovus { 0, 1 }").message, "bottom radius must be positive"));
    EXPECT_TRUE(contains(first_error("ovus { 1, -1 }").message, "top radius"));
}

TEST(ParserCurvedShapes, SphereSweepSplinesCountsAndTolerance) {
    auto scene = parse_ok(R"(
        sphere_sweep { linear_spline 2, <0, 0, 0>, 0.5, <1, 0, 0>, 0.25 }
        sphere_sweep { b_spline 4, <0,0,0>, 1, <1,0,0>, 1, <2,0,0>, 1, <3,0,0>, 1 tolerance 1e-4 }
        sphere_sweep { cubic_spline, 4, <0,0,0>, 1, <1,0,0>, 1, <2,0,0>, 1, <3,0,0>, 1, })");
    ASSERT_EQ(scene.objects.size(), 3u);
    const auto& linear = std::get<sg::SphereSweep>(scene.objects[0].shape);
    EXPECT_EQ(linear.spline, sg::SphereSweep::Spline::Linear);
    ASSERT_EQ(linear.spheres.size(), 2u);
    EXPECT_EQ(linear.spheres[1].center, sg::Vec3(1, 0, 0));
    EXPECT_DOUBLE_EQ(linear.spheres[1].radius, 0.25);
    EXPECT_DOUBLE_EQ(linear.tolerance, 1e-6);  // POV's default
    const auto& b = std::get<sg::SphereSweep>(scene.objects[1].shape);
    EXPECT_EQ(b.spline, sg::SphereSweep::Spline::BSpline);
    EXPECT_DOUBLE_EQ(b.tolerance, 1e-4);
    EXPECT_EQ(std::get<sg::SphereSweep>(scene.objects[2].shape).spline, sg::SphereSweep::Spline::CubicSpline);
    // POV: "Too few modeling spheres for interpolation type."
    const Diagnostic few = first_error("sphere_sweep { b_spline 3, <0,0,0>, 1, <1,0,0>, 1, <2,0,0>, 1 }");
    EXPECT_TRUE(contains(few.message, "at least 4 spheres")) << few.message;
    EXPECT_EQ(few.location.column, 25);
    EXPECT_TRUE(contains(first_error("sphere_sweep { linear_spline 3, <0,0,0>, 1, <1,0,0>, 1 }").message,
                         "3 spheres need 6 values"));
}

TEST(ParserCurvedShapes, BicubicPatchKeywordsAndPointsWithoutCommas) {
    // As POV's bezier.pov writes it: a count, then a point with no comma
    // between (POV reads no relational operator at an argument's top level).
    auto scene = parse_ok(R"(bicubic_patch { type 1 flatness 0.1  u_steps 8  v_steps 4
        <0, 0, 2>, <1, 0, 0>, <2, 0, 0>, <3, 0, -2>
        <0, 1, 0> <1, 1, 0> <2, 1, 0> <3, 1, 0>
        <0, 2, 0>, <1, 2, 0>, <2, 2, 0>, <3, 2, 0>,
        <0, 3, 2>, <1, 3, 0>, <2, 3, 0>, <3, 3, -2> - <0, 0, 1> })");
    const auto& patch = std::get<sg::BicubicPatch>(scene.objects[0].shape);
    EXPECT_EQ(patch.type, 1);
    EXPECT_DOUBLE_EQ(patch.flatness, 0.1);
    EXPECT_EQ(patch.u_steps, 8);
    EXPECT_EQ(patch.v_steps, 4);
    EXPECT_EQ(patch.points[0], sg::Vec3(0, 0, 2));
    EXPECT_EQ(patch.points[5], sg::Vec3(1, 1, 0));
    EXPECT_EQ(patch.points[15], sg::Vec3(3, 3, -3));  // "-" continues the last point, as in POV
    EXPECT_EQ(patch.uv_corners[2], sg::Vec2(1, 1));

    auto uv = parse_ok(R"(bicubic_patch { type 0 uv_vectors <0, 0>, <2, 0>, <2, 2>, <0, 2>
        <0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>,<0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>,
        <0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>,<0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> })");
    const auto& uv_patch = std::get<sg::BicubicPatch>(uv.objects[0].shape);
    EXPECT_EQ(uv_patch.uv_corners[1], sg::Vec2(2, 0));
    EXPECT_EQ(uv_patch.points[3], sg::Vec3(3, 0, 0));

    // POV: "Undefined bicubic patch type."; 16 points exactly.
    EXPECT_TRUE(contains(first_error("bicubic_patch { u_steps 2 <0,0,0>,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15 }").message,
                         "type"));
    EXPECT_TRUE(contains(first_error("bicubic_patch { type 1 <0,0,0>, <1,0,0> }").message, "16 control points"));
    EXPECT_TRUE(
        contains(first_error("bicubic_patch { type 1 u_steps 11 <0,0,0>,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15 }").message,
                 "u_steps must be 0 to 10"));
}

TEST(ParserCurvedShapes, BicubicPatchPovRayOneNumbers) {
    ParseResult result = test::parse_snippet(R"(bicubic_patch { 1, 3, 2,
        <0,0,0>,<1,0,0>,<2,0,0>,<3,0,0>,<0,1,0>,<1,1,0>,<2,1,0>,<3,1,0>,
        <0,2,0>,<1,2,0>,<2,2,0>,<3,2,0>,<0,3,0>,<1,3,0>,<2,3,0>,<3,3,0> })");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(test::count_warnings(result), 1);
    const auto& patch = std::get<sg::BicubicPatch>(result.scene->objects[0].shape);
    EXPECT_EQ(patch.type, 1);
    EXPECT_EQ(patch.u_steps, 3);
    EXPECT_EQ(patch.v_steps, 2);
}

TEST(ParserCurvedShapes, JuliaFractalOptions) {
    auto scene = parse_ok(R"(
        julia_fractal { <-0.083, 0.0, -0.83, -0.025> quaternion cube max_iteration 8.7 precision 0.5
                        slice <0, 0, 1, 1>, 0.2 }
        julia_fractal { <0.4, 0, 0, 0> hypercomplex exp }
        julia_fractal { 0.3 hypercomplex pwr(2, 0.5) })");
    ASSERT_EQ(scene.objects.size(), 3u);
    const auto& q = std::get<sg::JuliaFractal>(scene.objects[0].shape);
    EXPECT_EQ(q.julia, glm::dvec4(-0.083, 0.0, -0.83, -0.025));
    EXPECT_EQ(q.function, sg::JuliaFractal::Function::Cube);
    EXPECT_EQ(q.max_iteration, 8);                  // POV floors it
    EXPECT_DOUBLE_EQ(q.precision, 1.0);             // and takes at least 1
    EXPECT_NEAR(q.slice.z, std::sqrt(0.5), 1e-15);  // normalised
    EXPECT_DOUBLE_EQ(q.slice_distance, 0.2);
    const auto& e = std::get<sg::JuliaFractal>(scene.objects[1].shape);
    EXPECT_EQ(e.algebra, sg::JuliaFractal::Algebra::Hypercomplex);
    EXPECT_EQ(e.function, sg::JuliaFractal::Function::Exp);
    EXPECT_EQ(e.max_iteration, 20);  // defaults
    EXPECT_EQ(e.slice, glm::dvec4(0, 0, 0, 1));
    const auto& p = std::get<sg::JuliaFractal>(scene.objects[2].shape);
    EXPECT_EQ(p.function, sg::JuliaFractal::Function::Pwr);
    EXPECT_EQ(p.power, sg::Vec2(2, 0.5));
    EXPECT_EQ(p.julia, glm::dvec4(0.3));

    EXPECT_TRUE(contains(first_error("julia_fractal { <0,0,0,0> exp }").message, "quaternion supports only sqr"));
    EXPECT_TRUE(contains(first_error("julia_fractal { <0,0,0,0> slice <1, 0, 0, 0>, 0 }").message, "t (4th)"));
    EXPECT_TRUE(contains(first_error("julia_fractal { <0,0,0,0> slice <0, 0, 0, 0>, 0 }").message, "zero"));
    EXPECT_TRUE(contains(first_error("julia_fractal { <0,0,0,0> hypercomplex abs }").message, "no function 'abs'"));
}

TEST(ParserCurvedShapes, HeightFieldOptionsAndFile) {
    const std::string image = test::source_path("tests/reference/pov/height_field_16.png");
    ASSERT_TRUE(std::filesystem::exists(image));
    auto scene = parse_ok("height_field { png \"" + image + "\" gamma 1 smooth water_level 0.25 scale 2 }");
    const auto& field = std::get<sg::HeightField>(scene.objects[0].shape);
    EXPECT_EQ(field.path, image);
    EXPECT_TRUE(field.smooth);
    EXPECT_DOUBLE_EQ(field.water_level, 0.25);
    EXPECT_DOUBLE_EQ(field.gamma, 1.0);
    // No type keyword: taken from the name, as POV-Ray 3.7.
    EXPECT_EQ(std::get<sg::HeightField>(parse_ok("height_field { \"" + image + "\" }").objects[0].shape).path, image);
    const Diagnostic missing = first_error(R"(height_field { png "no-such-map.png" })");
    EXPECT_TRUE(contains(missing.message, "cannot find image file")) << missing.message;
    EXPECT_EQ(missing.location.column, 20);
    EXPECT_TRUE(contains(first_error("height_field { smooth }").message, "needs an image file"));
    EXPECT_TRUE(contains(first_error(R"(height_field { sys "a.sys" })").message, "convert the file to png"));
}

TEST(ParserCurvedShapes, PolynomialTermsInPovOrder) {
    // x^2 + y^2 + z^2 - 1 as POV 3.7's polynomial and as poly: the same
    // coefficients.
    auto scene = parse_ok(R"(
        polynomial { 2, xyz(2, 0, 0): 1, xyz(0, 2, 0): 1 xyz(0, 0, 2): 1, xyz(0, 0, 0): -1 }
        poly { 2, <1, 0, 0, 0, 1, 0, 0, 1, 0, -1> })");
    const auto& terms = std::get<sg::Polynomial>(scene.objects[0].shape);
    const auto& poly = std::get<sg::Polynomial>(scene.objects[1].shape);
    EXPECT_EQ(terms.order, 2);
    EXPECT_EQ(terms.coefficients, poly.coefficients);
    // POV: "Coefficient of polynom is out of range."
    const Diagnostic out = first_error("polynomial { 2, xyz(2, 1, 0): 1 }");
    EXPECT_TRUE(contains(out.message, "not a term of a polynomial of order 2")) << out.message;
    EXPECT_EQ(out.location.column, 21);
}

// POV reads an object's arguments without relational operators at their
// top level and with optional commas, so these sample-scene spellings parse:
// radiosity/cornell.pov's box and triangle, objects/prism3a.pov's prism.
TEST(ParserCurvedShapes, ArgumentsWithoutCommas) {
    auto scene = parse_ok(R"(
        box { <21.3, 54.87, 33.2><34.3, 54.88, 22.7> }
        triangle { <42.3, 33, 24.7>, <31.4, 33, 45.6>, <47.2 33.00 40.6> }
        prism { 0.0, 1.0, 4 <-1, -1>, <1, -1>, <0, 1>, <-1, -1> }
        sphere { <1 -2, 0, 0> 0.5 })");
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_DOUBLE_EQ(std::get<sg::Box>(scene.objects[0].shape).corner2.y, 54.88);
    EXPECT_EQ(std::get<sg::MeshRef>(scene.objects[1].shape)->positions[2], sg::Vec3(47.2, 33, 40.6));
    EXPECT_EQ(std::get<sg::Prism>(scene.objects[2].shape).points.size(), 4u);
    EXPECT_EQ(std::get<sg::Sphere>(scene.objects[3].shape).center, sg::Vec3(-1, 0, 0));  // "1 -2" is 1 - 2, as POV
}

// What review found: POV's patch objects include polygons and bicubic
// patches; values POV accepts are accepted; no cast of a huge number to int.
TEST(ParserCurvedShapes, PatchObjectsAndEdgeValues) {
    EXPECT_TRUE(
        contains(first_error("sphere { 0, 1 clipped_by { polygon { 4, <0,0>, <1,0>, <1,1>, <0,0> } } }").message,
                 "cannot clip"));
    EXPECT_TRUE(contains(first_error("sphere { 0, 1 bounded_by { triangle { 0, x, y } } }").message, "cannot bound"));
    // A negative sphere_sweep radius counts as its magnitude (POV does not check it).
    auto sweep = parse_ok("sphere_sweep { linear_spline 2, <0,0,0>, -0.5, <1,0,0>, 0.5 }");
    EXPECT_DOUBLE_EQ(std::get<sg::SphereSweep>(sweep.objects[0].shape).spheres[0].radius, 0.5);
    ParseResult fine = test::parse_snippet("julia_fractal { <0,0,0,0> precision 1e9 max_iteration -1e30 }");
    ASSERT_TRUE(fine.ok()) << test::all_diagnostics(fine);
    const auto& julia = std::get<sg::JuliaFractal>(fine.scene->objects[0].shape);
    EXPECT_DOUBLE_EQ(julia.precision, 10000.0);  // one ray's cost bounded, with a warning
    EXPECT_EQ(julia.max_iteration, 1);
    EXPECT_EQ(test::count_warnings(fine), 1);
    EXPECT_TRUE(contains(first_error("bicubic_patch { 1e30, 3, 3, 0,1,2,3,4,5,6,7,8,9,10,11,12,13,14,15 }").message,
                         "16 control points"));
    // The point at fault is named.
    const Diagnostic sor = first_error("sor { 4, <1, 0>, <1, 1>, <1, 0.5>, <1, 2> }");
    EXPECT_TRUE(contains(sor.message, "point 3 is not above point 2")) << sor.message;
    EXPECT_EQ(sor.location.column, 26);
    // Optional commas where POV's Parse_Comma is optional.
    auto blob = parse_ok("blob { threshold 0.5 component 1 1 <0, 0, 0> sphere { <1, 0, 0> 1 strength 1 } }");
    EXPECT_EQ(std::get<sg::Blob>(blob.objects[0].shape).components.size(), 2u);
    auto terms = parse_ok("polynomial { 2 xyz(2 0 0): 1 xyz(0, 0, 0): -1 }");
    EXPECT_DOUBLE_EQ(std::get<sg::Polynomial>(terms.objects[0].shape).coefficients[0], 1.0);
}

TEST(ParserCurvedShapes, HeightFieldOfAFunction) {
    auto scene = parse_ok(R"(
        height_field { function 64, 48.4 { x * y } smooth water_level 0.1 }
        height_field { function 3, 2 { pigment { rgb 0.5 } } })");
    const auto& field = std::get<sg::HeightField>(scene.objects[0].shape);
    ASSERT_TRUE(field.function);
    EXPECT_EQ(field.function_width, 64);
    EXPECT_EQ(field.function_height, 48);  // POV rounds the size
    EXPECT_TRUE(field.smooth);
    EXPECT_TRUE(std::get<sg::HeightField>(scene.objects[1].shape).function->pigment);
    EXPECT_TRUE(contains(first_error("height_field { function 1, 5 { x } }").message, "2..16384"));
    EXPECT_TRUE(contains(first_error("height_field { function 5 { x } }").message, "W, H"));
}

}  // namespace
}  // namespace lancer
