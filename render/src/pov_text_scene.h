// The render scene of a POV-Ray scene written in a test, for tests that
// check what the compiled scene answers (parser and compiler involved).
#pragma once

#include <memory>
#include <stdexcept>
#include <string>

#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"
#include "lancer/render_scene.h"

namespace lancer::testing {

// `text` as a 3.7 scene; throws with the first diagnostic if it fails.
inline std::unique_ptr<RenderScene> compile_pov_text(const std::string& text, const std::string& name = "<test>") {
    ParseResult parsed = parse_scene_string("#version 3.7;\n" + text, name);
    if (!parsed.ok()) throw std::runtime_error(format_diagnostic(parsed.diagnostics.front()));
    return compile_scene(*parsed.scene);
}

}  // namespace lancer::testing
