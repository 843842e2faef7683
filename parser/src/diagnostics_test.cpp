// Malformed scenes: each must fail with a located error (message substring,
// line and column), never a crash, a hang or an exception.
#include <string>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

struct BadScene {
    const char* name;
    std::string text;
    const char* message;  // substring of the first error
    int line;
    int column;
};

class MalformedScene : public ::testing::TestWithParam<BadScene> {};

TEST_P(MalformedScene, GivesALocatedError) {
    const BadScene& bad = GetParam();
    ParseOptions options;
    options.max_loop_iterations = 10'000;
    Diagnostic d = test::first_error(bad.text, options);
    EXPECT_NE(d.message.find(bad.message), std::string::npos) << "message: " << d.message;
    EXPECT_EQ(d.location.line, bad.line) << d.message;
    EXPECT_EQ(d.location.column, bad.column) << d.message;
    std::string shown = format_diagnostic(d);
    EXPECT_EQ(shown.rfind("bad.pov:" + std::to_string(bad.line) + ":" + std::to_string(bad.column) + ": error: ", 0),
              0u)
        << shown;
}

std::string with_nul() {
    std::string text = "sphere { 0, 1 }\nab";
    text += '\0';
    return text;
}

const BadScene kBadScenes[] = {
    {"DivisionByZero", "sphere { 0, 1/0 }", "division by zero", 1, 14},
    {"HugeNumber", "#declare A = 1e999;", "too large", 1, 14},
    {"SqrtOfNegative", "#declare A = sqrt(-1);", "square root of a negative", 1, 14},
    {"LogOfZero", "#declare A = log(0);", "logarithm", 1, 14},
    {"AcosOutOfDomain", "\n#declare A = acos(2);", "outside [-1, 1]", 2, 14},
    {"ColourWhereVectorExpected", "box { 0, 1 translate rgb 1 }", "expected a vector, found a colour", 1, 22},
    {"VectorWhereFloatExpected", "sphere { 0, <1, 2, 3> }", "expected a float radius, found a 3-component vector", 1,
     13},
    {"StringInArithmetic", "#declare A = \"a\" + 1;", "needs numbers", 1, 18},
    {"UnknownIdentifierSuggests", "#declare Radius = 1;\nsphere { 0, Raduis }", "did you mean 'Radius'", 2, 13},
    {"UnknownColourSuggests", "#include \"colors.inc\"\nsphere { 0, 1 pigment { color Whitte } }",
     "did you mean 'White'", 2, 31},
    {"MisspelledKeyword", "sphre { 0, 1 }", "did you mean 'sphere'", 1, 1},
    {"MissingClosingBrace", "sphere { 0, 1\n", "unexpected end of file", 1, 14},
    {"ExtraValue", "sphere { 0 1 2 }", "unexpected number inside sphere", 1, 14},
    {"StrayClosingBrace", "sphere { 0, 1 } }", "unexpected }", 1, 17},
    {"TopLevelModifier", "\n\ntranslate x", "expected an object", 3, 1},
    {"MissingValueInFinish", "sphere { 0, 1 finish { phong } }", "closing finish", 1, 30},
    {"UnterminatedString", "#include \"colors.inc", "unterminated string", 1, 10},
    {"UnterminatedComment", "sphere { 0, 1 }\n/* never closed", "unterminated comment", 2, 1},
    {"StrayCharacter", "sphere { 0, 1 } @", "unexpected character '@'", 1, 17},
    {"StrayLetterOutsideAscii", "sphere { 0, 1 } // caf\xC3\xA9\n#declare A = \xC3\xA9;",
     "unexpected character '\xC3\xA9'", 2, 14},
    {"InvalidUtf8", "sphere { 0, 1 }\n// caf\xE9\n", "invalid UTF-8", 2, 7},
    // Past runs of ASCII read eight bytes at a time, and UTF-8 counted
    // as one column a character.
    {"OverlongUtf8", "sphere { 0, 1 } // \xC0\x80", "invalid UTF-8 sequence starting with byte 0xC0", 1, 20},
    {"Utf8Surrogate", "// \xED\xA0\x80", "invalid UTF-8 sequence starting with byte 0xED", 1, 4},
    {"Utf8PastTheLastCodePoint", "// \xF4\x90\x80\x80", "invalid UTF-8 sequence starting with byte 0xF4", 1, 4},
    {"InvalidUtf8AfterAByteOrderMark",
     "\xEF\xBB\xBF"
     "abc\xFF",
     "invalid UTF-8", 1, 4},
    {"InvalidUtf8AfterLongRuns", "sphere { 0, 1 } // a comment long enough for words\n// \xC3\xA9t\xC3\xA9 then \xFF\n",
     "invalid UTF-8", 2, 13},
    {"Mesh2SectionLinesAndColumns",
     "mesh2 { vertex_vectors { 3, <0,0,0>,\n <1,0,0>,\n <0,1,0> } face_indices { 1, <0,1,2> } } #declare S = "
     "\"\xC3\xA9\"; @",
     "unexpected character '@'", 3, 60},
    {"BinaryFile", with_nul(), "NUL byte", 2, 3},
    {"RunawayWhile", "#while (1)\n#end", "exceeded 10000 iterations", 1, 1},
    {"MacroRecursion", "#macro F(N) F(N + 1) #end\nF(0)", "macro recursion too deep", 1, 13},
    {"MacroArgumentCount", "#macro F(A, B) sphere { A, B } #end\nF(1)", "takes 2 argument(s), but 1", 2, 1},
    {"NestingTooDeep", "#declare A = " + std::string(300, '(') + "1" + std::string(300, ')') + ";", "nesting too deep",
     1, 270},
    {"IfWithoutEnd", "sphere { 0, 1 }\n#if (1)\nsphere { 0, 2 }", "#if has no matching #end", 2, 1},
    {"EndWithoutIf", "#end", "#end without", 1, 1},
    {"ElseWithoutIf", "\n  #else", "#else without a matching #if", 2, 3},
    {"UnknownDirective", "#decalre A = 1;", "did you mean '#declare'", 1, 1},
    {"DeclareKeyword", "#declare sphere = 1;", "reserved word", 1, 10},
    {"DeclareWithoutEquals", "#declare A 1;", "expected '='", 1, 12},
    {"ErrorDirective", "#error \"stop here\"", "stop here", 1, 1},
    {"UnsupportedShape", "lemon { 0, y, 1, 0.5, 1 }", "does not support", 1, 1},
    {"EmptyBlob", "blob { threshold 0.5 }", "at least one component", 1, 1},
    {"DegenerateCylinder", "cylinder { 0, 0, 1 }", "degenerate cylinder", 1, 15},
    {"DegenerateCone", "cone { x, 1, x, 0.5 }", "degenerate cone", 1, 14},
    {"BothConeRadiiZero", "cone { 0, 0, y, 0 }", "both radii are 0", 1, 17},
    {"ZeroTorusMinorRadius", "torus { 1, 0 }", "minor radius must be positive", 1, 12},
    {"ZeroDiscNormal", "disc { 0, 0, 1 }", "must not be a zero vector", 1, 11},
    {"NegativeRadius", "sphere { 0, -1 }", "radius must be positive", 1, 13},
    {"ZeroPlaneNormal", "plane { <0, 0, 0>, 1 }", "must not be a zero vector", 1, 9},
    {"VectorTooLong", "#declare V = <1, 2, 3, 4, 5, 6>;", "2 to 5 components", 1, 14},
    {"BadComponent", "#declare V = <1, 2>.z;", "'.z' needs", 1, 21},
    {"Mesh2IndexOutOfRange",
     "mesh2 {\n vertex_vectors { 3, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0, 1, 7> }\n}",
     "index 7 is out of range", 3, 20},
    {"Mesh2CountMismatch", "mesh2 {\n vertex_vectors { 4, <0,0,0>, <1,0,0>, <0,1,0> }\n face_indices { 1, <0,1,2> } }",
     "declares 4 entries but lists 3", 2, 2},
    {"Mesh2NormalIndexRange",
     "mesh2 { vertex_vectors { 3, 0, x, y } normal_vectors { 1, z }\n face_indices { 1, <0,1,2> }\n normal_indices { "
     "1, <0,0,1> } }",
     "index 1 is out of range: normal_vectors has 1", 3, 22},
    {"EmptyMesh", "mesh { }", "mesh has no triangles", 1, 1},
    {"CameraAngleTooWide", "camera { angle 180 }", "between 0 and 180", 1, 16},
    {"CameraAngleNegative", "camera { fisheye angle -10 }", "must not be negative", 1, 24},
    {"CameraTypeAfterItems", "camera { location <0, 1, -3> fisheye }", "must come first", 1, 30},
    {"CylinderCameraType", "camera { cylinder 5 }", "the types are 1 to 4", 1, 19},
    {"CameraAngleWithoutValue", "camera { fisheye angle }", "angle needs a value", 1, 18},
    {"TwoAnglesNotSpherical", "camera { panoramic angle 90, 45 }", "only the spherical camera", 1, 26},
    {"BlurSamplesZero", "camera { aperture 1 blur_samples 0 }", "at least 1", 1, 34},
    {"BlurSamplesLeastAboveMost", "camera { aperture 1 blur_samples 20, 10 }", "must not be larger", 1, 38},
    {"ColourBeyondSinglePrecision", "sphere { 0, 1 pigment { color rgb 1e39 } }", "beyond what lancer renders", 1, 31},
    {"VectorBeyondSinglePrecision", "sphere { <1e39, 0, 0>, 1 }", "beyond what lancer renders", 1, 10},
    {"FinishBeyondSinglePrecision", "sphere { 0, 1 finish { phong 1e39 } }", "phong 1e+39 is beyond", 1, 30},
    {"RadiusBeyondSinglePrecision", "sphere { 0, 1e39 }", "sphere radius 1e+39", 1, 13},
    {"CameraLooksAtItself", "camera { location <1,2,3> look_at <1,2,3> }", "must be different", 1, 1},
    {"CameraFrameIsFlat", "camera { direction x right x up y }", "lie in one plane", 1, 1},
    {"CameraTooFarOut", "camera { location <0, 0, -1e19> look_at 0 }", "more than 1e18 from the origin", 1, 1},
    {"CameraMovedTooFarOut", "camera { translate 2e18 * x }", "more than 1e18 from the origin", 1, 1},
    {"AreaLightZeroSamples", "light_source { 0, 1 area_light x, z, 0, 2 }", "at least 1", 1, 38},
    {"AreaRectangleParallelAxes", "light_source { 0, 1 area_rectangle x, x*2 }", "not parallel", 1, 36},
    {"CircularAreaLightOfOneRow", "light_source { 0, 1 area_light x, z, 4, 1 circular }", "more than one sample", 1, 1},
    {"AreaLightOnAPhysicalLamp", "light_source { 0, 1 area_sphere 1 area_light x, z, 2, 2 }", "cannot be combined", 1,
     1},
    {"ParallelAtSamePoint", "light_source { <1,1,1>, 1 parallel point_at <1,1,1> }", "point_at must differ", 1, 1},
    {"UnknownRenderSetting", "render_settings { widht 640 }", "did you mean 'width'", 1, 19},
    {"BadRenderSize", "render_settings { width 0 }", "at least 1", 1, 25},
    {"MissingObjFile", "obj_mesh { \"no_such.obj\" }", "cannot find OBJ file", 1, 12},
    {"RgbfNeedsFour", "#declare C = rgbf <1, 1, 1>;", "rgbf expects", 1, 19},
    {"SingularMatrix", "sphere { 0, 1 matrix <0,0,0, 0,0,0, 0,0,0, 0,0,0> }", "singular", 1, 23},
    {"ForStepZero", "#for (I, 0, 10, 0) #end", "step is 0", 1, 1},
    {"ElementOfNoArray", "#declare A[3] = 1;", "'A' is not an array", 1, 10},
    {"DirectiveInsideValue", "#declare A = 1 + #if (1) 2 #end;", "unexpected directive", 1, 18},
    {"MeshCameraNoRays", "camera { mesh_camera { 0 0 mesh { triangle { 0, x, y } } } }", "at least 1 ray per pixel", 1,
     24},
    {"MeshCameraUnknownType", "camera { mesh_camera { 1 4 mesh { triangle { 0, x, y } } } }", "the types are 0 to 3", 1,
     26},
    {"MeshCameraSideBySideOneRay",
     "camera { mesh_camera { 2 2 mesh { triangle { 0, x, y } } mesh { triangle { 0, x, y } } } }",
     "must be 1 for distribution type 2", 1, 24},
    {"MeshCameraSmoothNeedsUv", "camera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } smooth } }",
     "distribution type 3", 1, 58},
    {"MeshCameraWithoutMesh", "camera { mesh_camera { 1 0 } }", "at least one mesh", 1, 28},
    {"MeshCameraTakesMeshesOnly", "camera { mesh_camera { 1 0 sphere { 0, 1 } } }", "mesh and mesh2 objects only", 1,
     28},
    {"MeshCameraRaysNeedMeshes", "camera { mesh_camera { 2 0 mesh { triangle { 0, x, y } } } }", "need as many meshes",
     1, 24},
    {"MeshCameraUvNeedsUvs", "camera { mesh_camera { 1 3 mesh { triangle { 0, x, y } } } }", "has none", 1, 28},
    {"MeshCameraTakesNoAngle", "camera { mesh_camera { 1 0 mesh { triangle { 0, x, y } } } angle 30 }",
     "takes no angle", 1, 66},
    {"DeclaredMeshMustBeAMesh", "#declare S = sphere { 0, 1 }\nmesh { S }", "is not a mesh", 2, 1},
};

INSTANTIATE_TEST_SUITE_P(ParserDiagnostics, MalformedScene, ::testing::ValuesIn(kBadScenes),
                         [](const ::testing::TestParamInfo<BadScene>& info) { return std::string(info.param.name); });

TEST(ParserDiagnostics, SeveralSemanticErrorsAreCollected) {
    ParseResult result =
        test::parse_snippet("sphere { 0, -1 }\nsphere { 0, -2 }\nbox { 0, 1 translate rgb 1 }", "many.pov");
    ASSERT_FALSE(result.ok());
    int errors = 0;
    for (const auto& d : result.diagnostics) errors += d.severity == Diagnostic::Severity::Error;
    EXPECT_EQ(errors, 3);
}

TEST(ParserDiagnostics, FormatShowsLineAndCaret) {
    ParseResult result = test::parse_snippet("sphere {\n\t0, Nope }", "caret.pov");
    ASSERT_FALSE(result.ok());
    std::string text = format_diagnostic(result.diagnostics.front());
    EXPECT_EQ(text, "caret.pov:2:5: error: unknown identifier 'Nope' (expected a value)\n  \t0, Nope }\n  \t   ^\n");
}

// Bytes above 127 are scanned as themselves (flex's full tables are 7-bit
// unless told otherwise): UTF-8 in comments and strings reads, and the
// caret line of an error after them is the line as written, from the file's
// line table.
TEST(ParserDiagnostics, Utf8InCommentsAndStringsAndTheirCaretLines) {
    const auto scene = test::parse_ok(
        "// caf\xC3\xA9 \xE2\x80\xA6\n#declare S = \"na\xC3\xAFve \xE2\x86\x92\";\n"
        "/* \xE2\x80\xA6 */ sphere { 0, 1 }");
    EXPECT_EQ(scene.objects.size(), 1u);
    ParseResult result =
        test::parse_snippet("// \xE2\x80\xA6\r\nsphere {\r\n 0, Nope } // caf\xC3\xA9\r\n", "utf8.pov");
    ASSERT_FALSE(result.ok());
    const Diagnostic& error = result.diagnostics.front();
    EXPECT_EQ(error.location.line, 3);
    EXPECT_EQ(error.location.column, 5);
    EXPECT_EQ(error.source_line, " 0, Nope } // caf\xC3\xA9");
}

TEST(ParserDiagnostics, MissingFileIsAnErrorNotAnException) {
    ParseResult result = parse_scene_file("/nonexistent/scene.pov");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(result.diagnostics.front().message.find("not found"), std::string::npos);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// What the terminal is shown of a scene: control characters escaped, in
// the source line and in the message, and a long line cut to a window
// around the caret.
TEST(DiagnosticEcho, ControlCharactersAreEscapedAndLongLinesWindowed) {
    Diagnostic d;
    d.location.file = std::make_shared<const std::string>("evil\x1b]0;t\x07.pov");
    d.location.line = 1;
    d.location.column = 5;
    d.message = "unknown identifier '\x1b[2Jx'";
    d.source_line = "ab\x1b[c \xff\xfe y";
    const std::string shown = format_diagnostic(d);
    EXPECT_EQ(shown.find('\x1b'), std::string::npos) << shown;
    EXPECT_EQ(shown.find('\x07'), std::string::npos) << shown;
    EXPECT_NE(shown.find("ab\\x1b[c \\xff\\xfe y"), std::string::npos) << shown;
    EXPECT_NE(shown.find("'\\x1b[2Jx'"), std::string::npos) << shown;
    // The caret sits under column 5 ('c'): "ab" + the 4-wide escape + "[".
    EXPECT_NE(shown.find("\n         ^"), std::string::npos) << shown;

    d.source_line = std::string(5'000'000, 'x') + " here " + std::string(5'000'000, 'y');
    d.location.column = 5'000'002;
    d.message = "somewhere";
    const std::string windowed = format_diagnostic(d);
    EXPECT_LT(windowed.size(), 400u);
    EXPECT_NE(windowed.find("...xxxx"), std::string::npos);
    EXPECT_NE(windowed.find("here"), std::string::npos);
}

}  // namespace
}  // namespace lancer
