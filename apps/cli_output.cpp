#include "cli_output.h"

#include <cstdio>

namespace lancer::app {

void print_error(const std::string& message) {
    // Messages quote file names and values the user (or a scene) chose.
    std::fprintf(stderr, "lancer: error: %s\n", escape_for_terminal(message).c_str());
}

void print_diagnostic(const Diagnostic& diagnostic) {
    if (!diagnostic.location.file) {
        const char* severity = diagnostic.severity == Diagnostic::Severity::Error     ? "error"
                               : diagnostic.severity == Diagnostic::Severity::Warning ? "warning"
                                                                                      : "note";
        std::fprintf(stderr, "lancer: %s: %s\n", severity, escape_for_terminal(diagnostic.message).c_str());
        return;
    }
    std::string text = format_diagnostic(diagnostic);
    if (text.empty() || text.back() != '\n') text += '\n';
    std::fputs(text.c_str(), stderr);
}

void print_scene_error(const SceneError& error) {
    Diagnostic diagnostic;
    diagnostic.severity = Diagnostic::Severity::Error;
    diagnostic.location = error.location();
    diagnostic.message = error.what();
    print_diagnostic(diagnostic);
}

}  // namespace lancer::app
