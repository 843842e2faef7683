// POV-Ray's user functions as the parser compiles and evaluates them.
#include <gtest/gtest.h>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

// The value of a float #declare'd by the scene.
double declared(const std::string& scene_text, const std::string& name) {
    ParseResult result = test::parse_snippet(scene_text + "\n#debug str(" + name + ", 0, 9)", "f.pov");
    EXPECT_TRUE(result.ok()) << test::all_diagnostics(result);
    for (const auto& d : result.diagnostics)
        if (d.message.rfind("#debug: ", 0) == 0) return std::stod(d.message.substr(8));
    ADD_FAILURE() << "no #debug output";
    return 0.0;
}

TEST(ParserFunctions, ArithmeticPrecedenceAndParameters) {
    EXPECT_DOUBLE_EQ(declared("#declare F = function(a, b) { a * a + b * 2 - 1 }\n#declare R = F(3, 4);", "R"), 16.0);
    // Default parameters x, y, z; unary minus binds tighter than *.
    EXPECT_DOUBLE_EQ(declared("#declare F = function { -x * 2 + y / 4 - z }\n#declare R = F(1, 2, 3);", "R"), -4.5);
    // Comparisons and logic give 0 or 1.
    EXPECT_DOUBLE_EQ(declared("#declare F = function { (x < 1) + (x >= 1) * 10 + (y = 2 & z != 0) * 100 }\n"
                              "#declare R = F(0.5, 2, 1);",
                              "R"),
                     101.0);
}

TEST(ParserFunctions, BuiltinsSelectAndCalls) {
    EXPECT_NEAR(declared("#declare F = function { sin(pi / 2) + pow(2, 3) + sqrt(16) + abs(-1) + min(3, 1, 2) + "
                         "max(1, 5) + mod(7, 3) + floor(-0.5) }\n#declare R = F(0, 0, 0);",
                         "R"),
                1 + 8 + 4 + 1 + 1 + 5 + 1 - 1, 1e-12);
    // select(a, negative, zero, positive); with three, a >= 0 takes the third.
    EXPECT_DOUBLE_EQ(declared("#declare F = function { select(x, 1, 2, 3) }\n#declare R = F(0, 0, 0);", "R"), 2.0);
    EXPECT_DOUBLE_EQ(declared("#declare F = function { select(x, 1, 2) }\n#declare R = F(0, 0, 0);", "R"), 2.0);
    // A function calls another; a declared float is bound at definition.
    EXPECT_DOUBLE_EQ(declared("#declare K = 3;\n#declare G = function(a) { a * K }\n#declare K = 100;\n"
                              "#declare F = function { G(x) + 1 }\n#declare R = F(2, 0, 0);",
                              "R"),
                     7.0);
}

TEST(ParserFunctions, FunctionsIncLoadsAndItsInternalsEvaluate) {
    EXPECT_DOUBLE_EQ(declared("#include \"functions.inc\"\n#declare R = f_sphere(3, 4, 0, 1);", "R"), 4.0);
    EXPECT_NEAR(declared("#include \"functions.inc\"\n#declare R = f_torus(2, 0, 0, 1.5, 0.25);", "R"), 0.25, 1e-12);
    EXPECT_NEAR(declared("#include \"functions.inc\"\n#declare R = f_rounded_box(2, 0, 0, 0.1, 1, 1, 1);", "R"), 1.0,
                1e-5);
    // f_noise3d needs the renderer's noise: a located error while parsing.
    const Diagnostic noise = first_error("#include \"functions.inc\"\n#declare R = f_noise3d(1, 2, 3);");
    EXPECT_NE(noise.message.find("noise"), std::string::npos);
    EXPECT_EQ(noise.location.line, 2);
}

TEST(ParserFunctions, PatternsAndPigmentsAsFunctions) {
    auto scene = parse_ok(
        "#declare P = function { pattern { agate scale 2 } }\n"
        "#declare C = function { pigment { checker rgb 1, rgb 0 } }\n"
        "plane { z, 0 pigment { function { P(x, y, z) * C(x, y, z).red } color_map { [0 rgb 0] [1 rgb 1] } } }");
    const sg::Pattern& p = *scene.objects[0].material->pigment.pattern;
    EXPECT_EQ(p.kind, sg::Pattern::Kind::Function);
    ASSERT_TRUE(p.function);
    ASSERT_EQ(p.function->callees.size(), 2u);
    ASSERT_TRUE(p.function->callees[0]->pattern);
    EXPECT_EQ(p.function->callees[0]->pattern->kind, sg::Pattern::Kind::Agate);
    EXPECT_TRUE(p.function->callees[1]->pigment);
}

TEST(ParserExpressions, StringsCompareAsStrcmp) {
    EXPECT_DOUBLE_EQ(declared("#declare R = (\"a\" != \"\") + (\"abc\" < \"abd\") * 2 + (\"x\" = \"x\") * 4 + "
                              "(\"b\" <= \"a\") * 8;",
                              "R"),
                     7.0);
}

// POV-Ray keeps a line break inside a string; a backslash ending the line
// there is its "unterminated string literal".
TEST(ParserExpressions, StringsMaySpanLines) {
    EXPECT_DOUBLE_EQ(declared("#declare S = \"two\nlines\";\n#declare R = strlen(S) + 10 * (S = \"two\\nlines\");\n"
                              "sphere { 0, R }",
                              "R"),
                     19.0);
    const Diagnostic backslash = test::first_error("#declare S = \"one \\\n two\";");
    EXPECT_EQ(backslash.location.line, 1);
    EXPECT_EQ(backslash.location.column, 19);
    EXPECT_NE(backslash.message.find("backslash"), std::string::npos) << backslash.message;
}

// POV's sum(i, b, e, expr) and prod(…): i from b by 1 while i <= e; the
// body reads the function's parameters; sums nest. Values from POV-Ray 3.7.
TEST(ParserFunctions, SumAndProd) {
    EXPECT_DOUBLE_EQ(declared("#declare F = function { sum(i, 1, 10, i) }\n#declare R = F(0, 0, 0);", "R"), 55.0);
    EXPECT_DOUBLE_EQ(declared("#declare F = function { prod(k, 1, 5, k) }\n#declare R = F(0, 0, 0);", "R"), 120.0);
    EXPECT_DOUBLE_EQ(declared("#declare F = function(x) { sum(i, 1, 3, x * i) }\n#declare R = F(2);", "R"), 12.0);
    EXPECT_DOUBLE_EQ(
        declared("#declare F = function { sum(i, 1, 3, sum(j, 1, i, j * y)) }\n#declare R = F(0, 2, 0);", "R"), 20.0);
    EXPECT_DOUBLE_EQ(declared("#declare F = function { sum(i, 2.5, 1, 7) + prod(i, 0.5, 2.6, i) }\n"
                              "#declare R = F(0, 0, 0);",
                              "R"),
                     1.875);
    // A function of more parameters than the evaluator keeps on its stack
    // for a term's arguments: 20 here, the sum reading the last.
    std::string many = "#declare F = function(a0";
    for (int i = 1; i < 20; ++i) many += ", a" + std::to_string(i);
    many += ") { sum(i, 1, 4, i * a19) }\n#declare R = F(0";
    for (int i = 1; i < 20; ++i) many += i == 19 ? ", 3" : ", 0";
    EXPECT_DOUBLE_EQ(declared(many + ");", "R"), 30.0);
    const Diagnostic variable = test::first_error("#declare F = function { sum(x, 1, 3, x) }");
    EXPECT_NE(variable.message.find("loop variable"), std::string::npos) << variable.message;
    const Diagnostic three = test::first_error("#declare F = function { prod(i, 1, 3) }");
    EXPECT_NE(three.message.find("four arguments"), std::string::npos) << three.message;
}

// Values measured with POV-Ray 3.7 (#debug of the same expressions).
TEST(ParserExpressions, StrcmpBitwiseXorDatetimeAndNow) {
    EXPECT_DOUBLE_EQ(declared("#declare R = strcmp(\"abc\", \"abd\");", "R"), -1.0);
    EXPECT_DOUBLE_EQ(declared("#declare R = strcmp(\"b\", \"abc\");", "R"), 1.0);
    EXPECT_DOUBLE_EQ(declared("#declare R = strcmp(\"ab\", \"abc\");", "R"), -99.0);
    EXPECT_DOUBLE_EQ(declared("#declare R = strcmp(\"same\", \"same\");", "R"), 0.0);
    EXPECT_DOUBLE_EQ(declared("#declare R = bitwise_xor(12, 10, 1);", "R"), 7.0);
    EXPECT_DOUBLE_EQ(declared("#declare R = (datetime(0) = \"2000-01-01 00:00:00Z\") + "
                              "2 * (datetime(366.5, \"%A %d %B %Y %H:%M\") = \"Monday 01 January 2001 12:00\") + "
                              "4 * (datetime(-10957.25) = \"1969-12-31 18:00:00Z\");",
                              "R"),
                     7.0);
    // now: days since 2000 (9000 days is 2024-08-23).
    EXPECT_GT(declared("#declare R = now;", "R"), 9000.0);
    const Diagnostic far = test::first_error("#declare S = datetime(1e12);");
    EXPECT_NE(far.message.find("1400 to 9999"), std::string::npos) << far.message;
    const Diagnostic empty = test::first_error("#declare S = datetime(0, \"\");");
    EXPECT_NE(empty.message.find("format is empty"), std::string::npos) << empty.message;
}

TEST(ParserFunctions, MacrosPassAndBuildFunctions) {
    EXPECT_DOUBLE_EQ(declared("#declare G = function { x + 1 }\n"
                              "#macro Twice(F) function { F(x, y, z) * 2 } #end\n"
                              "#declare H = Twice(G)\n"
                              "#macro Apply(F) F(1, 0, 0) #end\n"
                              "#declare R = Apply(H) + Apply(function { x * 10 });",
                              "R"),
                     14.0);
    // A macro call inside an expression and in a directive's argument.
    EXPECT_DOUBLE_EQ(declared("#macro Sq(A) (A * A) #end\n#declare R = 1 + Sq(3);", "R"), 10.0);
}

// function { spline { } } (language/splinefunction.pov): the spline at the
// first argument, a vector in the scene language and its .x to .t inside
// functions.
TEST(ParserFunctions, SplinesAsFunctions) {
    const std::string spline =
        "#declare S = function { spline { linear_spline 0, <0, 0, 0> 1, <2, 4, 6> } }\n"
        "#declare V = S(0.5);\n";
    EXPECT_DOUBLE_EQ(declared(spline + "#declare R = V.y;", "R"), 2.0);
    EXPECT_DOUBLE_EQ(declared(spline + "#declare R = S(0.25).z;", "R"), 1.5);
    EXPECT_DOUBLE_EQ(declared(spline + "#declare G = function { S(x).z * 2 + S(y).x }\n#declare R = G(0.5, 1);", "R"),
                     6.0 + 2.0);
    // A declared spline: past its last time it holds its end value; made
    // a cubic_spline, two entries give 2 there (POV-Ray prints the same).
    const std::string declared_spline = "#declare P = spline { 0, 1 1, 3 }\n";
    EXPECT_DOUBLE_EQ(declared(declared_spline + "#declare S = function { spline { P } }\n#declare R = S(2).x;", "R"),
                     3.0);
    EXPECT_DOUBLE_EQ(
        declared(declared_spline + "#declare S = function { spline { P cubic_spline } }\n#declare R = S(2).x;", "R"),
        2.0);
    EXPECT_NE(first_error(spline + "#declare G = function { S(x).gray }").message.find("of a spline function"),
              std::string::npos);
}

// function { transform { } } moves a point: transforms.inc's vtransform
// and vinv_transform, with the values POV-Ray 3.7 prints for them.
TEST(ParserFunctions, TransformsAsFunctions) {
    const std::string moved =
        "#include \"transforms.inc\"\n"
        "#declare T = transform { rotate 90 * z translate <10, 0, 0> }\n"
        "#declare V = vtransform(<1, 2, 3>, T);\n"
        "#declare W = vinv_transform(V, transform { T });\n";
    EXPECT_NEAR(declared(moved + "#declare R = V.x;", "R"), 8.0, 1e-12);
    EXPECT_NEAR(declared(moved + "#declare R = V.y;", "R"), 1.0, 1e-12);
    EXPECT_NEAR(declared(moved + "#declare R = W.y;", "R"), 2.0, 1e-12);
    // Inside a function its channels are .x, .y and .z.
    EXPECT_DOUBLE_EQ(declared("#declare F = function { transform { scale 2 translate z } }\n"
                              "#declare G = function { F(x, y, z).y + F(x, y, z).z }\n#declare R = G(1, 2, 3);",
                              "R"),
                     4.0 + 7.0);
    EXPECT_NE(
        first_error("#declare F = function { transform { scale 2 } }\n#declare G = function { F(x, y, z).filter }")
            .message.find(".x, .y, .z of a transform function"),
        std::string::npos);
}

// Values measured with POV-Ray 3.7: `#declare G = F;` copies a function,
// a spline copies the same way, and either passes uncalled to a macro.
TEST(ParserFunctions, FunctionsAndSplinesAreValuesToCopy) {
    const std::string copied =
        "#declare F = function(x, y) { x * 2 + y }\n#declare G = F;\n"
        "#declare H = function { G(x, 1) }\n"
        "#declare S = spline { linear_spline 0, <0, 0, 0>, 1, <2, 4, 6> }\n#declare T = S;\n"
        "#macro Apply(Q) Q(1, 1) #end\n";
    EXPECT_DOUBLE_EQ(declared(copied + "#declare R = G(3, 1);", "R"), 7.0);
    EXPECT_DOUBLE_EQ(declared(copied + "#declare R = H(2, 0, 0);", "R"), 5.0);
    EXPECT_DOUBLE_EQ(declared(copied + "#declare R = T(0.5).z;", "R"), 3.0);
    EXPECT_DOUBLE_EQ(declared(copied + "#declare R = Apply(G);", "R"), 3.0);
    // Followed by "(" a function is called, never juxtaposed with a vector.
    EXPECT_DOUBLE_EQ(declared(copied + "#declare R = G (3, 1);", "R"), 7.0);
    const Diagnostic arithmetic = first_error(copied + "#declare R = G + 1;");
    EXPECT_NE(arithmetic.message.find("found a function"), std::string::npos);
    EXPECT_EQ(arithmetic.location.line, 7);
}

TEST(ParserFunctions, VturbulenceWithoutTheRendererIsALocatedError) {
    const Diagnostic missing = first_error("#declare V = 1;\n#declare V = vturbulence(2, 0.5, 3, <1, 2, 3>);");
    EXPECT_NE(missing.message.find("vturbulence() needs the renderer's noise"), std::string::npos);
    EXPECT_EQ(missing.location.line, 2);
    EXPECT_NE(first_error("#declare V = vturbulence(2, 0.5, <1, 2, 3>);").message.find("takes 4 argument(s)"),
              std::string::npos);
}

TEST(ParserFunctions, BadBodiesAreLocatedErrors) {
    const Diagnostic unknown = first_error("#declare F = function { x + nothing_here }");
    EXPECT_NE(unknown.message.find("unknown identifier 'nothing_here'"), std::string::npos);
    EXPECT_EQ(unknown.location.column, 29);
    EXPECT_NE(first_error("#declare F = function { sin(1, 2) }").message.find("one argument"), std::string::npos);
    EXPECT_NE(first_error("#declare F = function { x + }").message.find("unexpected '}'"), std::string::npos);
    EXPECT_NE(first_error("#declare F = function { x").message.find("not closed"), std::string::npos);
    EXPECT_NE(first_error("#declare V = <1, 2, 3>;\n#declare F = function { V }").message.find("a 3-component vector"),
              std::string::npos);
    // An internal function POV-Ray lacks is an error where it is used, not
    // where it is declared.
    const Diagnostic missing =
        first_error("#declare F = function { internal(79) }\nplane { z, 0 pigment { function { F(x, y, z) } } }");
    EXPECT_NE(missing.message.find("no internal function 79"), std::string::npos) << missing.message;
    EXPECT_EQ(missing.location.line, 2);
}

}  // namespace
}  // namespace lancer
