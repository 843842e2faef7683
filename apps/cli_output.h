// How every subcommand reports a problem: located diagnostics in the
// parser's format, everything else as "lancer: error: ...".
#pragma once

#include <string>

#include "lancer/parser.h"
#include "lancer/scene_error.h"

namespace lancer::app {

void print_error(const std::string& message);
// A diagnostic without a file (a setting that came from no scene text) is
// printed as a plain "lancer: <severity>:" line.
void print_diagnostic(const Diagnostic& diagnostic);
// A SceneError from any stage after parsing, shown like a parser diagnostic.
void print_scene_error(const SceneError& error);

}  // namespace lancer::app
