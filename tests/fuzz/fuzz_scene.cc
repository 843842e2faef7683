// libFuzzer target: the whole scene front end (lexer, token stream,
// directives, grammar, evaluator) on arbitrary bytes.
//
// The contract under test is parser.h's: parse_scene_string never crashes,
// never throws, and stops within its resource limits. Loop and macro limits
// are lowered so a runaway #while costs milliseconds, not seconds, per input
// (the default limits are tested in parser/src/diagnostics_test.cpp); files
// are confined to the current folder with safe_root so a fuzzed #include
// cannot wander the disk.
#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

#include "lancer/parser.h"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string root = std::filesystem::current_path().string();
    lancer::ParseOptions options;
    options.max_loop_iterations = 2000;
    options.max_objects = 2000;  // nested loops: see fuzz_regression_test.cpp
    // A macro recursing inside a nested parse (#debug F(N + 1)) stacks one
    // parser per level. The parse's own stack (parse_stack.h) holds the
    // default 200 levels under ASan too; 50 keeps each such input fast.
    options.max_macro_depth = 50;
    options.safe = true;
    options.safe_root = root;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    lancer::ParseResult result = lancer::parse_scene_string(text, "<fuzz>", options);
    // Formatting diagnostics is part of the front end too (source lines, carets).
    for (const auto& diagnostic : result.diagnostics) (void)lancer::format_diagnostic(diagnostic);
    return 0;
}
