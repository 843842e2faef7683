// Literal vectors are single tokens, and a mesh2 section of literal data is
// read without the grammar (mesh2_sections.cpp): both must read exactly as
// the grammar reads the same text written with expressions.
#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

sg::MeshRef only_mesh(const sg::SceneGraph& scene) {
    EXPECT_EQ(scene.objects.size(), 1u);
    return std::get<sg::MeshRef>(scene.objects.at(0).shape);
}

// `0+` in one entry of each section sends that section to the grammar.
const char* const kLiteralMesh = R"(mesh2 {
    vertex_vectors { 4, <0,0,0>, < -1.5 , +2, - -3 >,
                     <1e-1, .5, 7.>  <0,1,0> }
    normal_vectors { 2, <0,0,-2>, <0,3,4> }
    uv_vectors { 4 <0,0>, <1,0>, <1,1>, <0,1>, }
    face_indices { 2, <0,1,2>, <0,2,3> }
    normal_indices { 2, <0,1,0>, <1,1,1> }
    uv_indices { 2, <0,1,2>, <0,2,3> }
})";
const char* const kExpressionMesh = R"(mesh2 {
    vertex_vectors { 4, <0+0,0,0>, < -1.5 , +2, - -3 >,
                     <1e-1, .5, 7.>  <0,1,0> }
    normal_vectors { 2, <0+0,0,-2>, <0,3,4> }
    uv_vectors { 4 <0+0,0>, <1,0>, <1,1>, <0,1>, }
    face_indices { 2, <0+0,1,2>, <0,2,3> }
    normal_indices { 2, <0+0,1,0>, <1,1,1> }
    uv_indices { 2, <0+0,1,2>, <0,2,3> }
})";

TEST(ParserMesh2Sections, LiteralSectionsReadAsTheGrammarReadsThem) {
    const auto literal = parse_ok(kLiteralMesh);
    const auto expression = parse_ok(kExpressionMesh);
    const auto a = only_mesh(literal);
    const auto b = only_mesh(expression);
    ASSERT_EQ(a->positions.size(), 4u);
    EXPECT_EQ(a->positions, b->positions);
    EXPECT_EQ(a->positions[1], sg::Vec3(-1.5, 2.0, 3.0));
    EXPECT_EQ(a->positions[2], sg::Vec3(0.1, 0.5, 7.0));
    ASSERT_EQ(a->normals.size(), 2u);
    EXPECT_EQ(a->normals, b->normals);
    EXPECT_NEAR(a->normals[1].z, 0.8, 1e-15);  // normalised, as POV does
    EXPECT_EQ(a->uvs, b->uvs);
    ASSERT_EQ(a->faces.size(), 2u);
    ASSERT_EQ(b->faces.size(), 2u);
    for (std::size_t f = 0; f < 2; ++f) {
        for (int i = 0; i < 3; ++i) {
            EXPECT_EQ(a->faces[f].position[i], b->faces[f].position[i]);
            EXPECT_EQ(a->faces[f].normal[i], b->faces[f].normal[i]);
            EXPECT_EQ(a->faces[f].uv[i], b->faces[f].uv[i]);
        }
    }
    EXPECT_EQ(a->faces[1].position[2], 3);
    EXPECT_EQ(a->faces[0].normal[1], 1);
}

// Every number too large for a double is an error of its own, in a literal
// vector as among tokens.
TEST(ParserMesh2Sections, EachNumberTooLargeIsReported) {
    const auto literal = test::parse_snippet("sphere { <1e400, 2  , 1e999>, 1 }");
    const auto expression = test::parse_snippet("sphere { <1e400, 2+0, 1e999>, 1 }");
    ASSERT_EQ(literal.diagnostics.size(), 2u) << test::all_diagnostics(literal);
    ASSERT_EQ(expression.diagnostics.size(), 2u) << test::all_diagnostics(expression);
    for (std::size_t i = 0; i < 2; ++i) {
        EXPECT_EQ(literal.diagnostics[i].message, expression.diagnostics[i].message);
        EXPECT_EQ(literal.diagnostics[i].location.column, expression.diagnostics[i].location.column);
    }
}

// Indices with a point, a sign or leading zeros, and numbers of hundreds
// of digits, are what the grammar makes of them too.
TEST(ParserMesh2Sections, NumbersWrittenUnusuallyReadAsTheGrammarReadsThem) {
    const std::string digits = std::string(305, '0') + "1";  // past what the text alone answers for
    auto mesh = [&](const char* plus) {
        return "mesh2 { vertex_vectors { 4, <0" + std::string(plus) + ",0,0>, <1,0,0>, <0,1,0>, <0," + digits +
               ".5,1e2> }\n face_indices { 2, <0,1.0,2" + plus + ">, <-0,+3,0002.> } }";
    };
    const auto literal = parse_ok(mesh(""));
    const auto expression = parse_ok(mesh("+0"));
    const auto a = only_mesh(literal);
    const auto b = only_mesh(expression);
    EXPECT_EQ(a->positions, b->positions);
    EXPECT_EQ(a->positions[3], sg::Vec3(0.0, 1.5, 100.0));
    ASSERT_EQ(a->faces.size(), 2u);
    ASSERT_EQ(b->faces.size(), 2u);
    for (std::size_t f = 0; f < 2; ++f)
        for (int i = 0; i < 3; ++i) EXPECT_EQ(a->faces[f].position[i], b->faces[f].position[i]);
    EXPECT_EQ(a->faces[1].position[1], 3);
    EXPECT_EQ(a->faces[1].position[2], 2);
}

// The same mistakes give the same located errors whichever reads them.
TEST(ParserMesh2Sections, ErrorsAreTheGrammarsErrors) {
    const char* const cases[][2] = {
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0> } face_indices { 0 } }",
         "mesh2 { vertex_vectors { 3, <0+0,0,0>, <1,0,0> } face_indices { 0 } }"},
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,1,3> } }",
         "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,1,3+0> } }"},
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,1,1.5> } }",
         "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,1,1.5+0> } }"},
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> }\n"
         " uv_vectors { 1, <0,0,0> } }",
         "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 1, <0,1,2> }\n"
         " uv_vectors { 1, <0+0,0,0> } }"},
        {"sphere { <1,\n  1e999, 0>, 1 }", "sphere { <1+0,\n  1e999, 0>, 1 }"},
        {"mesh2 { vertex_vectors { 1, <0,\n 1e999, 0> } }", "mesh2 { vertex_vectors { 1, <0+0,\n 1e999, 0> } }"},
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,-1,2> } }",
         "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,-1,2+0> } }"},
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,2147483648,2> } }",
         "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,2147483648,2+0> } }"},
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,999999999,2> } }",
         "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,999999999,2+0> } }"},
        // Beyond single precision, which the mesh stores: written with an
        // exponent, and in 39 digits.
        {"mesh2 { vertex_vectors { 3, <0,0,0>, <1e39,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }",
         "mesh2 { vertex_vectors { 3, <0,0,0>, <1e39+0,0,0>, <0,1,0> } face_indices { 1, <0,1,2> } }"},
        {"mesh2 { uv_vectors { 1, <0,999999999999999999999999999999999999999> } }",
         "mesh2 { uv_vectors { 1, <0+0,999999999999999999999999999999999999999> } }"},
    };
    for (const auto& pair : cases) {
        const Diagnostic literal = first_error(pair[0]);
        const Diagnostic expression = first_error(pair[1]);
        EXPECT_FALSE(literal.message.empty()) << pair[0];
        EXPECT_EQ(literal.message, expression.message) << pair[0];
        EXPECT_EQ(literal.location.line, expression.location.line) << pair[0];
        EXPECT_EQ(literal.location.column, expression.location.column) << pair[0];
    }
}

// After an operator or a comma a '<' starts a vector, signs and all (the
// values are what Debian's povray prints for the same declarations); after
// a name or a number it may compare, and is left to the grammar.
TEST(ParserMesh2Sections, LiteralVectorsReadAsInPovRay) {
    const auto scene = parse_ok(R"(
        #declare A = 0;
        #declare M = (A<1) + (A <1) + 0;
        #declare V = 2*<1, -2, - -3>;
        #declare W = <1,2,3> + <4, 5, 6>;
        sphere { <M, 0, 0>, 1 translate V + W }
    )");
    ASSERT_EQ(scene.objects.size(), 1u);
    const auto& object = scene.objects[0];
    const sg::Vec3 centre(object.parent_from_object * glm::dvec4(std::get<sg::Sphere>(object.shape).center, 1.0));
    EXPECT_EQ(centre, sg::Vec3(2.0 + 2.0 + 5.0, -4.0 + 7.0, 6.0 + 9.0));
}

// After a keyword that takes a vector or colour a literal is one token too:
// the same object as written with expressions.
TEST(ParserMesh2Sections, LiteralVectorsAfterKeywords) {
    const auto literal = parse_ok(
        "sphere { 0, 1 pigment { color rgb <0.25, -0.5, 1e-1> } scale <1, 2, 3> rotate < -90, 0, 0>"
        " translate <+1, - -2, 3> }");
    const auto expression = parse_ok(
        "sphere { 0, 1 pigment { color rgb <0.25+0, -0.5, 1e-1> } scale <1+0, 2, 3> rotate < -90+0, 0, 0>"
        " translate <+1+0, - -2, 3> }");
    ASSERT_EQ(literal.objects.size(), 1u);
    ASSERT_EQ(expression.objects.size(), 1u);
    EXPECT_EQ(literal.objects[0].parent_from_object, expression.objects[0].parent_from_object);
    EXPECT_EQ(literal.objects[0].material->pigment.color.rgb, sg::Vec3(0.25, -0.5, 0.1));
    EXPECT_EQ(literal.objects[0].parent_from_object * glm::dvec4(0, 0, 0, 1), glm::dvec4(1, 2, 3, 1));
}

}  // namespace
}  // namespace lancer
