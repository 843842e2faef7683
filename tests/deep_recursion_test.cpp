// fuzz_scene found a macro recursing inside #debug's nested parse: each
// level stacks a parser, and under AddressSanitizer's larger frames the
// 8 MiB main-thread stack overflowed before the depth limit of 200. A parse
// now runs on a thread of its own with a large stack (parser/src/
// parse_stack.h), and a macro call that finds three quarters of it used
// stops with a located error, so the limit holds in every build; this test
// runs in the sanitizer stage too (tests/sanitize).
#include <string>

#include <gtest/gtest.h>

#include "lancer/parser.h"

namespace lancer {
namespace {

std::string all_text(const ParseResult& result) {
    std::string text;
    for (const Diagnostic& d : result.diagnostics) text += format_diagnostic(d);
    return text;
}

TEST(DeepRecursion, MacroRecursingInsideDebugStopsAtTheDepthLimit) {
    ParseResult result = parse_scene_string("#macro F(N)#debug F(N + 1) #end\nF(0)\n", "recursion.pov");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("recursion.pov:1:"), std::string::npos) << all_text(result);
    EXPECT_NE(all_text(result).find("macro recursion too deep: more than 200 nested calls"), std::string::npos)
        << all_text(result);
}

// With the depth limit out of the way, the stack itself is the limit: a
// located error, not a crash.
TEST(DeepRecursion, RecursionBeyondTheStackIsALocatedError) {
    ParseOptions options;
    options.max_macro_depth = 100'000'000;
    ParseResult result = parse_scene_string("#macro F(N)#debug F(N + 1) #end\nF(0)\n", "recursion.pov", options);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("recursion.pov:1:"), std::string::npos) << all_text(result);
    EXPECT_NE(all_text(result).find("macro recursion too deep for the parser's stack"), std::string::npos)
        << all_text(result);
}

}  // namespace
}  // namespace lancer
