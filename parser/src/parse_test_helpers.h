// Helpers shared by the parser tests.
#pragma once

#include <string>
#include <string_view>

#include <gtest/gtest.h>

#include "lancer/parser.h"

namespace lancer::test {

inline std::string all_diagnostics(const ParseResult& result) {
    std::string text;
    for (const auto& d : result.diagnostics) text += format_diagnostic(d);
    return text;
}

// Parses a snippet written for POV-Ray 3.7, as if run with POV's +MV3.7:
// without that, a snippet with no #version is a legacy 3.62 scene (gamma
// off, and a warning about it).
inline ParseResult parse_snippet(std::string_view text, const std::string& name = "<string>",
                                 ParseOptions options = {}) {
    if (!options.language_version) options.language_version = 3.7;
    return parse_scene_string(text, name, options);
}

// Parses `text`, failing the test (with every diagnostic) if it has errors.
inline sg::SceneGraph parse_ok(const std::string& text, ParseOptions options = {}) {
    ParseResult result = parse_snippet(text, "test.pov", options);
    EXPECT_TRUE(result.ok()) << all_diagnostics(result);
    return result.ok() ? *result.scene : sg::SceneGraph{};
}

// The first error of a scene that must fail.
inline Diagnostic first_error(const std::string& text, ParseOptions options = {}) {
    ParseResult result = parse_snippet(text, "bad.pov", options);
    EXPECT_FALSE(result.ok()) << "expected an error for:\n" << text;
    for (const auto& d : result.diagnostics)
        if (d.severity == Diagnostic::Severity::Error) return d;
    return {};
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

inline int count_warnings(const ParseResult& result) {
    int n = 0;
    for (const auto& d : result.diagnostics) n += d.severity == Diagnostic::Severity::Warning;
    return n;
}

}  // namespace lancer::test
