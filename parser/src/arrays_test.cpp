// POV-Ray's arrays as the parser reads them.
#include <gtest/gtest.h>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

std::string debug_output(const std::string& scene_text) {
    ParseResult result = test::parse_snippet(scene_text, "a.pov");
    EXPECT_TRUE(result.ok()) << test::all_diagnostics(result);
    std::string out;
    for (const auto& d : result.diagnostics)
        if (d.message.rfind("#debug: ", 0) == 0) out += d.message.substr(8);
    return out;
}

TEST(ParserArrays, InitializersIndicesAndSizes) {
    EXPECT_EQ(debug_output("#declare B = array[2][3] { {1, 2, 3}, {4, 5, 6,} }\n"
                           "#declare S = 0;\n"
                           "#for (I, 0, dimension_size(B, 1) - 1) #for (J, 0, dimension_size(B, 2) - 1)\n"
                           "  #declare S = S + B[I][J] * (I + 1);\n"
                           "#end #end\n"
                           "#debug concat(str(S, 0, 0), \" \", str(dimensions(B), 0, 0), \" \", str(B[1][2], 0, 0))"),
              "36 2 6");
    // Vectors and their components; an index is any expression.
    EXPECT_EQ(debug_output("#declare V = array[2] { <1, 2, 3>, <4, 5, 6> }\n#declare K = 0;\n"
                           "#debug str(V[K + 1].y * 10 + V[0].x, 0, 0)"),
              "51");
}

// POV reads an initialiser's commas as optional (lemon.inc, tiling.pov,
// allnormals.pov); `<a> <b>` are two items, a comparison needs ( ).
// povray 3.7 prints the same "-8b0.513" for this scene.
TEST(ParserArrays, InitializerCommasAreOptional) {
    EXPECT_EQ(debug_output("#declare V = array[4] { <1, 2>, <3, 4>\n <5, 6> <7, -8> }\n"
                           "#declare S = array[3] { \"a\" \"b\", \"c\" }\n"
                           "#declare C = array[3] { rgb 1 red 0.5, rgb 0.5 rgb (1 < 2) }\n"
                           "#declare P = pigment { rgb 1 }\n"
                           "#declare Q = array[3] { P P, P }\n"
                           "#debug concat(str(V[3].v, 0, 0), S[1], str(C[0].red, 0, 1), str(C[2].green, 0, 0), "
                           "str(dimension_size(Q, 1), 0, 0))"),
              "-8b0.513");
}

TEST(ParserArrays, ElementsOfAnyKindStandWhereTheirKindMay) {
    auto scene = parse_ok(
        "#declare O = array[2]\n"  // POV needs no ';' after array[N]
        "#declare O[0] = sphere { 0, 1 }\n"
        "#declare O[1] = box { -1, 1 }\n"
        "#declare T = array[2] { texture { pigment { rgb 1 } }, texture { pigment { rgb x } } }\n"
        "object { O[1] texture { T[1] } }\n"
        "object { O[0] translate x * 2 texture { T[0] } }");
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_TRUE(std::holds_alternative<sg::Box>(scene.objects[0].shape));
    ASSERT_TRUE(scene.objects[0].material);
    EXPECT_EQ(scene.objects[0].material->pigment.color.rgb, sg::Vec3(1, 0, 0));
    EXPECT_TRUE(std::holds_alternative<sg::Sphere>(scene.objects[1].shape));
}

TEST(ParserArrays, MacrosTakeArraysByReferenceAndDeclareCopies) {
    EXPECT_EQ(debug_output("#declare A = array[3] { 1, 2, 3 }\n"
                           "#macro Fill(Arr) #declare Arr[1] = 20; #end\n"
                           "Fill(A)\n"
                           "#declare C = A;\n#declare C[0] = 100;\n"
                           "#debug concat(str(A[0], 0, 0), \" \", str(A[1], 0, 0), \" \", str(C[0], 0, 0))"),
              "1 20 100");
}

TEST(ParserArrays, MistakesAreLocatedErrors) {
    const Diagnostic outside = first_error("#declare A = array[3]\n#declare B = A[3];");
    EXPECT_NE(outside.message.find("outside 0..2"), std::string::npos);
    EXPECT_EQ(outside.location.line, 2);
    EXPECT_NE(first_error("#declare A = array[3]\n#declare B = A[1];").message.find("has not been given a value"),
              std::string::npos);
    EXPECT_NE(first_error("#declare A = array[2] { 1, 2, 3 }").message.find("the initializer lists 3"),
              std::string::npos);
    EXPECT_NE(first_error("#declare A = array[2][2]\n#declare B = A[1];").message.find("give an index for each"),
              std::string::npos);
    EXPECT_NE(first_error("#declare A = array[100000][100000]").message.find("lancer's limit"), std::string::npos);
    EXPECT_NE(first_error("#declare N = 3;\n#declare N[0] = 1;").message.find("'N' is not an array"),
              std::string::npos);
    EXPECT_NE(first_error("#declare N = dimension_size(3, 1);").message.find("needs an array"), std::string::npos);
}

}  // namespace
}  // namespace lancer
