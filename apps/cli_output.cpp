#include "cli_output.h"

#include <cstdio>

namespace lancer::app {

void print_error(const std::string& message) {
    std::fprintf(stderr, "lancer: error: %s\n", message.c_str());
}

void print_diagnostic(const Diagnostic& diagnostic) {
    if (!diagnostic.location.file) {
        const char* severity = diagnostic.severity == Diagnostic::Severity::Error     ? "error"
                               : diagnostic.severity == Diagnostic::Severity::Warning ? "warning"
                                                                                      : "note";
        std::fprintf(stderr, "lancer: %s: %s\n", severity, diagnostic.message.c_str());
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
