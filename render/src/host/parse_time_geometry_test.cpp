// trace(), inside(), min_extent() and max_extent() while parsing, answered
// by the render core: the values POV-Ray 3.7 prints (#debug) for the same
// scenes, misses, unbounded objects, CSG, and the error without a renderer.
#include <gtest/gtest.h>

#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"

namespace lancer {
namespace {

struct Parsed {
    std::unique_ptr<sg::GeometryQueries> queries = make_parse_time_geometry_queries();
    ParseResult result;
};

Parsed parse_with_queries(const std::string& text) {
    Parsed parsed;
    ParseOptions options;
    options.geometry_queries = parsed.queries.get();
    parsed.result = parse_scene_string(text, "queries.pov", options);
    return parsed;
}

// The sphere radius the scene computes, where the tests put the answer.
sg::Vec3 answer(const Parsed& parsed, std::size_t i) {
    EXPECT_TRUE(parsed.result.ok());
    if (!parsed.result.ok() || parsed.result.scene->objects.size() <= i) return sg::Vec3(NAN);
    return std::get<sg::Sphere>(parsed.result.scene->objects[i].shape).center;
}

void expect_near(const sg::Vec3& got, const sg::Vec3& want, double tolerance = 1e-5) {
    for (int axis = 0; axis < 3; ++axis) EXPECT_NEAR(got[axis], want[axis], tolerance) << axis;
}

TEST(ParseTimeGeometry, TraceGivesPointAndNormalOrZerosOnAMiss) {
    const Parsed parsed = parse_with_queries(R"(
        #declare Ball = sphere { <0, 1, 0>, 1 scale <2, 1, 1> }
        #declare N = <9, 9, 9>;
        sphere { trace(Ball, <5, 1, 0>, <-1, 0, 0>, N), 1 }
        sphere { N, 1 }
        sphere { trace(Ball, <5, 5, 0>, <1, 0, 0>, M), 1 }
        sphere { M + 0.5, 1 })");
    expect_near(answer(parsed, 0), sg::Vec3(2, 1, 0));
    expect_near(answer(parsed, 1), sg::Vec3(1, 0, 0));
    expect_near(answer(parsed, 2), sg::Vec3(0));
    expect_near(answer(parsed, 3), sg::Vec3(0.5));  // an undeclared normal name is declared
}

// A terrain made from a function is traced with the noise_generator set so
// far, as POV-Ray traces it: the heights POV-Ray 3.7 prints (#debug of the
// same trace(), to 12 digits) for generators 1, 2 and 3. The shape is
// traced in float, so 1e-4 of the 0..1 height.
TEST(ParseTimeGeometry, AFunctionTerrainIsTracedWithTheNoiseGeneratorSetSoFar) {
    const double pov_height[3] = {0.134311523437, 0.336383514404, 0.769644622803};
    for (int generator = 1; generator <= 3; ++generator) {
        const Parsed parsed = parse_with_queries("global_settings { noise_generator " + std::to_string(generator) +
                                                 R"( }
            #declare Field = height_field {
              function 64, 64 { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 } }
            }
            sphere { trace(Field, <0.37, 5, 0.61>, -y), 1 })");
        const sg::Vec3 point = answer(parsed, 0);
        EXPECT_NEAR(point.y, pov_height[generator - 1], 1e-4) << "noise_generator " << generator;
    }
}

// POV-Ray makes a function height field's image where the height field is
// written, with the noise_generator set by then: one set later changes
// neither trace() nor the render. POV-Ray's heights for the field written
// before and after `noise_generator 1`; the render's from a ray of the
// compiled scene.
TEST(ParseTimeGeometry, AFunctionTerrainKeepsTheNoiseGeneratorWhereItIsWritten) {
    const std::string field = R"(
        #declare Field = height_field {
          function 64, 64 { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 } }
        })";
    const std::string use = R"(
        sphere { trace(Field, <0.37, 5, 0.61>, -y), 0.001 }
        object { Field })";
    const std::string later = "global_settings { noise_generator 1 }";
    const struct {
        std::string text;
        double pov_height;
    } cases[] = {{later + field + use, 0.134311523437},
                 {field + later + use, 0.336383514404},
                 {field + use + later, 0.336383514404}};
    for (const auto& c : cases) {
        Parsed parsed = parse_with_queries(c.text);
        EXPECT_NEAR(answer(parsed, 0).y, c.pov_height, 1e-4) << c.text;
        ASSERT_TRUE(parsed.result.ok());
        // The render's field: the same ray meets the small sphere just above
        // it (the generators' heights differ by 0.2).
        const std::unique_ptr<RenderScene> scene = compile_scene(std::move(*parsed.result.scene));
        Ray ray;
        ray.origin = Vec3(0.37f, 5.0f, 0.61f);
        ray.direction = Vec3(0.0f, -1.0f, 0.0f);
        Hit hit;
        ASSERT_TRUE(scene->intersect(ray, hit));
        EXPECT_NEAR(hit.position.y, c.pov_height, 3e-3) << c.text;
    }
}

// A #declare'd trace() is read without the grammar when its value is a
// plain expression (parser/src/plain_values.cpp): the same values, normals
// stored at the same moment, the same messages.
TEST(ParseTimeGeometry, DeclaredTracesReadAsTheGrammarReadsThem) {
    const std::string scene = R"(
        #declare Ball = sphere { <0, 1, 0>, 1 scale <2, 1, 1> }
        #declare N = <9, 9, 9>;
        #declare P = trace(Ball, <5, 1, 0>, <-1, 0, 0>, N) + N;
        #declare Q = N + trace(Ball, <1, 5, 0>, <0, -1, 0>, N);
        #declare R = trace(Ball, <5, 5, 0>, <1, 0, 0>, M) + 2 * trace(Ball, <0, 1, -5>, z);
        #declare S = trace(Ball, <5, 1, 0>, <0, 0, 0>);
        #if (vlength(trace(Ball, <0, 9, 0>, -y, N)) > 1) #debug "hit" #end
        #debug concat(vstr(3, P, ",", 0, 17), " ", vstr(3, Q, ",", 0, 17), " ", vstr(3, R, ",", 0, 17))
        #debug concat(vstr(3, N, ",", 0, 17), " ", vstr(3, M, ",", 0, 17), " ", vstr(3, S, ",", 0, 17))
        #declare T = trace(N, <5, 1, 0>, x);
        #declare U = trace(Ball, <5, 1, 0>, x, Ball);
    )";
    auto read = [&scene](bool plain) {
        Parsed parsed;
        ParseOptions options;
        options.geometry_queries = parsed.queries.get();
        options.plain_values = plain;
        const ParseResult result = parse_scene_string(scene, "queries.pov", options);
        std::string text = result.ok() ? "ok\n" : "failed\n";
        for (const Diagnostic& d : result.diagnostics) text += format_diagnostic(d);
        return text;
    };
    const std::string plain = read(true);
    EXPECT_EQ(plain, read(false));
    EXPECT_NE(plain.find("#debug: hit"), std::string::npos) << plain;
    // P: the point <2, 1, 0> plus the normal trace() has just stored in N.
    EXPECT_NE(plain.find("#debug: 3.00000000000000000,1.00000000000000000,0.00000000000000000"), std::string::npos)
        << plain;
}

TEST(ParseTimeGeometry, TraceThroughCsg) {
    const Parsed parsed = parse_with_queries(R"(
        #declare D = difference { box { -1, 1 } sphere { 0, 0.5 } }
        sphere { trace(D, <0, 0, -5>, z, N), 1 }
        sphere { N, 1 }
        sphere { trace(D, <0, 0, 0>, <0, 0, 2>, M), 1 }
        sphere { M, 1 })");
    expect_near(answer(parsed, 0), sg::Vec3(0, 0, -1));
    expect_near(answer(parsed, 1), sg::Vec3(0, 0, -1));
    // From inside the hole: the sphere's surface, its normal facing into
    // the hole (the subtracted sphere's outside is the hole's wall).
    expect_near(answer(parsed, 2), sg::Vec3(0, 0, 0.5));
    EXPECT_NEAR(glm::length(answer(parsed, 3)), 1.0, 1e-5);
}

TEST(ParseTimeGeometry, ExtentsAsPovRay) {
    const Parsed parsed = parse_with_queries(R"(
        #declare Ball = sphere { <0, 1, 0>, 1 scale <2, 1, 1> }
        #declare U = union { object { Ball } box { <-1, -3, -1>, <0, -2, 0> } rotate y*30 }
        #declare I = intersection { sphere { 0, 1 } box { <0, 0, 0>, <2, 2, 2> } }
        #declare Pl = plane { y, 0 }
        sphere { min_extent(Ball), 1 } sphere { max_extent(Ball), 1 }
        sphere { min_extent(U), 1 } sphere { max_extent(U), 1 }
        sphere { min_extent(I), 1 } sphere { max_extent(I), 1 }
        sphere { min_extent(Pl), 1 } sphere { max_extent(Pl), 1 })");
    expect_near(answer(parsed, 0), sg::Vec3(-2, 0, -1));
    expect_near(answer(parsed, 1), sg::Vec3(2, 2, 1));
    expect_near(answer(parsed, 2), sg::Vec3(-2.2321, -3, -1.8660), 1e-4);
    expect_near(answer(parsed, 3), sg::Vec3(2.2321, 2, 1.8660), 1e-4);
    expect_near(answer(parsed, 4), sg::Vec3(0, 0, 0));
    expect_near(answer(parsed, 5), sg::Vec3(1, 1, 1));
    EXPECT_DOUBLE_EQ(answer(parsed, 6).y, -1e10);  // POV's bound for what has none
    EXPECT_DOUBLE_EQ(answer(parsed, 7).x, 1e10);
}

// The boxes POV-Ray 3.7 prints (#debug of vstr(min_extent(...), 5
// digits)) for curves, text and turned spheres: a prism's, a lathe's and
// a surface of revolution's are their curves' extremes (lancer's were
// padded by 5%, which put Circle_Text's letters off by a letter's width),
// a text's its outlines', and a sphere moved and turned stays a sphere.
TEST(ParseTimeGeometry, ExtentsOfCurvesTextAndTurnedSpheresAsPovRay) {
    const Parsed parsed = parse_with_queries(R"(
        #declare Q = prism { quadratic_spline 0, 1, 5, <0,0>, <1,0>, <1,1>, <0,1>, <1,0> }
        #declare C = prism { cubic_spline 0, 1, 8, <0,0>, <2,0>, <3,3>, <0,4>, <-2, 2>, <2,0>, <3,3>, <0,4> }
        #declare L = lathe { cubic_spline 6, <0,-1>, <1,0>, <3,1>, <0.5,1.5>, <0.8,2>, <0,2.5> }
        #declare S = sor { 5, <0,0>, <1,0>, <0.5,1>, <0.8,2>, <0,3> }
        #declare T = text { ttf "timrom.ttf" "Jy" 0.5, 0 }
        #declare Turned = sphere { 0, 1 rotate 45*y translate x }
        #declare Stretched = sphere { 0, 1 scale <1,2,1> rotate 45*x }
        sphere { min_extent(Q), 1 } sphere { max_extent(Q), 1 }
        sphere { min_extent(C), 1 } sphere { max_extent(C), 1 }
        sphere { min_extent(L), 1 } sphere { max_extent(L), 1 }
        sphere { min_extent(S), 1 } sphere { max_extent(S), 1 }
        sphere { min_extent(T), 1 } sphere { max_extent(T), 1 }
        sphere { min_extent(Turned), 1 } sphere { max_extent(Turned), 1 }
        sphere { min_extent(Stretched), 1 } sphere { max_extent(Stretched), 1 })");
    constexpr double kPrinted = 3e-5;  // POV's 5 digits, its boxes' and lancer's margins
    expect_near(answer(parsed, 0), sg::Vec3(0, 0, 0), kPrinted);
    expect_near(answer(parsed, 1), sg::Vec3(1.125, 1, 1.125), kPrinted);
    expect_near(answer(parsed, 2), sg::Vec3(-2.04753, 0, -0.01283), kPrinted);
    expect_near(answer(parsed, 3), sg::Vec3(3.07655, 1, 4.03230), kPrinted);
    expect_near(answer(parsed, 4), sg::Vec3(-3.00317, 0, -3.00317), kPrinted);
    expect_near(answer(parsed, 5), sg::Vec3(3.00317, 2, 3.00317), kPrinted);
    expect_near(answer(parsed, 6), sg::Vec3(-1.03212, 0, -1.03212), kPrinted);
    expect_near(answer(parsed, 7), sg::Vec3(1.03212, 2, 1.03212), kPrinted);
    expect_near(answer(parsed, 8), sg::Vec3(-0.00001, -0.21201, -0.00002), kPrinted);
    expect_near(answer(parsed, 9), sg::Vec3(0.89001, 0.68002, 0.50001), kPrinted);
    expect_near(answer(parsed, 10), sg::Vec3(0, -1, -1), kPrinted);
    expect_near(answer(parsed, 11), sg::Vec3(2, 1, 1), kPrinted);
    expect_near(answer(parsed, 12), sg::Vec3(-1, -2.12132, -2.12132), kPrinted);
    expect_near(answer(parsed, 13), sg::Vec3(1, 2.12132, 2.12132), kPrinted);
}

// Boxes POV-Ray finds for unbounded shapes in CSG, as POV-Ray 3.7 printed
// them (#debug of vstr(min_extent(...)), this file's objects): a quadric
// between two planes turned off the axes has one; a quartic clipped by a
// cylinder and two planes (POV's Helix) has none, though lancer culls its
// rays by one.
TEST(ParseTimeGeometry, ExtentsOfUnboundedShapesInCsgAsPovRay) {
    const Parsed parsed = parse_with_queries(R"(
        #declare B = intersection { plane { y, 5.5 } quadric { <1, -1, 1>, 0, 0, -1 translate 5*y scale <0.5, 1, 0.5> }
                                    plane { -y, -2.5 } rotate <-30, 0, 25> }
        #declare H = quartic { <0,0,0,0,0,0,0,0,0,0, 0,0,0,0,0,0,-0.1666,0,1,0, 0,0,0,0,0,0,0,0.5,0,-1, 0,0,0,0,0>
                               clipped_by { quadric { <1, 1, 0>, 0, 0, -1 scale 2 } plane { z, 1.4142 } plane { -z, 0 } }
                               rotate 160*z rotate -90*x translate <0, -2, 5> }
        sphere { min_extent(B), 1 } sphere { max_extent(B), 1 }
        sphere { min_extent(H), 1 } sphere { max_extent(H), 1 })");
    expect_near(answer(parsed, 0), sg::Vec3(-3.5176, 0.7832, -3.9159), 1e-4);
    expect_near(answer(parsed, 1), sg::Vec3(0.5896, 5.4959, -0.0841), 1e-4);
    EXPECT_DOUBLE_EQ(answer(parsed, 2).y, -1e10);
    EXPECT_DOUBLE_EQ(answer(parsed, 3).x, 1e10);
}

TEST(ParseTimeGeometry, InsideTestsTheSolid) {
    const Parsed parsed = parse_with_queries(R"(
        #declare Ball = sphere { <0, 1, 0>, 1 scale <2, 1, 1> }
        #declare Hollow = difference { box { -1, 1 } sphere { 0, 0.5 } }
        sphere { <inside(Ball, <1.5, 1, 0>), inside(Ball, <2.5, 1, 0>), 0>, 1 }
        sphere { <inside(Hollow, <0.8, 0, 0>), inside(Hollow, 0), inside(Hollow, 2)>, 1 })");
    expect_near(answer(parsed, 0), sg::Vec3(1, 0, 0));
    expect_near(answer(parsed, 1), sg::Vec3(1, 0, 0));
}

TEST(ParseTimeGeometry, LocatedErrors) {
    const ParseResult without = parse_scene_string("#declare B = sphere { 0, 1 }\n#declare P = trace(B, -5*z, z);\n",
                                                   "bare.pov", ParseOptions{});
    ASSERT_FALSE(without.ok());
    EXPECT_EQ(without.diagnostics.front().location.line, 2);
    const Parsed zero = parse_with_queries("#declare B = sphere { 0, 1 }\n#declare P = trace(B, -5*z, 0);\n");
    ASSERT_FALSE(zero.result.ok());
    EXPECT_NE(zero.result.diagnostics.front().message.find("zero length"), std::string::npos);
    const Parsed not_object = parse_with_queries("#declare P = trace(1, -5*z, z);\n");
    EXPECT_FALSE(not_object.result.ok());
}

}  // namespace
}  // namespace lancer
