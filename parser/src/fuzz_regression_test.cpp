// Inputs found by fuzzing (tests/fuzz, docs/robustness.md) and the bugs they
// led to, kept so they stay fixed. Each input is inline; the longer ones are
// also seeds in tests/fuzz/regressions/.
#include <string>

#include <gtest/gtest.h>

#include "parse_test_helpers.h"

namespace lancer::test {

namespace {

int count(const ParseResult& result, Diagnostic::Severity severity) {
    int n = 0;
    for (const auto& d : result.diagnostics) n += d.severity == severity;
    return n;
}

}  // namespace

// fuzz_scene timeout (slow_unknown_identifier_in_loop.pov): an unknown
// 120-character name inside a #for body is reported every iteration, each
// time with a "did you mean" search over colors.inc. Not a hang (the
// fuzzing machine was loaded), but errors must stay bounded: 30, then stop.
TEST(FuzzRegression, ErrorsInALoopStopAtThirty) {
    std::string name = "St" + std::string(120, 'z') + "eps";
    ParseResult result = test::parse_snippet(
        "#include \"colors.inc\"\n#for (I, 0, 100000)\n#local F = I / (" + name + " - 1);\n#end\n", "loop.pov");
    ASSERT_FALSE(result.ok());
    EXPECT_EQ(count(result, Diagnostic::Severity::Error), 30);
    EXPECT_NE(all_diagnostics(result).find("too many errors; stopping"), std::string::npos);
}

// Found while triaging the above: warnings were not bounded at all, so a
// warning in a long loop stored one diagnostic (with its source line) per
// iteration: 10^6 iterations, hundreds of MB. Now the first 200 are kept.
TEST(FuzzRegression, WarningsInALoopAreBounded) {
    ParseResult result =
        test::parse_snippet("#for (I, 0, 99999)\n#warning \"again\"\n#end\nsphere { 0, 1 }\n", "loop.pov");
    ASSERT_TRUE(result.ok()) << all_diagnostics(result);
    EXPECT_EQ(count(result, Diagnostic::Severity::Warning), 200);
    EXPECT_NE(all_diagnostics(result).find("more than 200 warnings and notes; the rest are not shown"),
              std::string::npos);
}

// Also from that triage: a warning used to count as an error for the
// 30-error stop, so 29 errors and one warning ended the parse early.
TEST(FuzzRegression, AWarningDoesNotCountAsAnError) {
    std::string scene;
    for (int i = 0; i < 29; ++i) scene += "sphere { 0, -1 }\n";
    scene += "#warning \"only a warning\"\nsphere { 0, -2 }\n";
    ParseResult result = test::parse_snippet(scene, "many.pov");
    EXPECT_EQ(count(result, Diagnostic::Severity::Error), 30);
    EXPECT_NE(all_diagnostics(result).find("only a warning"), std::string::npos);
}

// fuzz_scene timeout (procedural.pov with "#local L = L + 0"): an outer
// #while that never ends, around inner loops that create spheres. Each
// loop's own cap restarts for every inner loop, so objects grew until the
// token budget; max_objects now stops them.
TEST(FuzzRegression, NestedLoopsStopAtTheObjectLimit) {
    ParseOptions options;
    options.max_objects = 500;
    ParseResult result = test::parse_snippet(
        "#declare L = 0;\n#while (L < 5)\n#declare A = 0;\n#while (A < 3)\n  sphere { <A, L, 0>, 0.5 }\n"
        "#declare A = A + 1;\n#end\n#declare L = L + 0;\n#end\n",
        "nested.pov", options);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_diagnostics(result).find("nested.pov:5:3: error: the scene has more than 500 objects"),
              std::string::npos)
        << all_diagnostics(result);
}

// #debug prints a message without a caret (its location has no column).
TEST(FuzzRegression, DebugMessageHasNoCaret) {
    ParseResult result = test::parse_snippet("#debug \"hello\"\nsphere { 0, 1 }\n", "debug.pov");
    ASSERT_TRUE(result.ok());
    ASSERT_FALSE(result.diagnostics.empty());
    EXPECT_EQ(format_diagnostic(result.diagnostics.front()), "debug.pov:1: note: #debug: hello\n");
}

// fuzz_scene, UBSan (mesh2_huge_face_texture_index.pov): a face's texture
// index of 3.3e12 was cast to int, which is undefined. Every number the
// parser truncates to an int (mesh2 indices, str() and vstr() widths,
// blur_samples, cylinder types, area_light sizes) now saturates first, and
// the callers' range checks report it.
TEST(FuzzRegression, HugeNumbersTruncatedToIntsAreReported) {
    ParseResult mesh = test::parse_snippet(
        "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <1,1,0> }\n"
        "texture_list { 1, texture { pigment { rgb 1 } } }\n"
        "face_indices { 1, <0,1,2>3333333333333 } }\n",
        "mesh.pov");
    ASSERT_FALSE(mesh.ok());
    EXPECT_NE(all_diagnostics(mesh).find("mesh.pov:3:"), std::string::npos) << all_diagnostics(mesh);
    ParseResult vertex = test::parse_snippet(
        "mesh2 { vertex_vectors { 3, <0,0,0>, <1,0,0>, <1,1,0> } face_indices { 1, <0,1,3e12> } }\n", "vertex.pov");
    EXPECT_FALSE(vertex.ok());
    for (const char* text :
         {"#declare S = str(1, 1e300, -1e300);\n", "#declare S = vstr(1e300, <1,2,3>, \",\", 1e300, 1e300);\n",
          "camera { cylinder 1e300 }\n", "camera { aperture 1 blur_samples 1e300 }\n",
          "light_source { 0, 1 area_light x, y, 1e300, -1e300 }\n"})
        test::parse_snippet(text, "huge.pov");  // no undefined behaviour (the sanitizer build)
}

}  // namespace lancer::test
