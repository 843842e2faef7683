// An error a user can fix in the scene, thrown by any stage after parsing
// (compiling the render scene, loading an image, validating a parameter).
// apps/ formats it like a parser diagnostic: file:line:col, line, caret.
#pragma once

#include <stdexcept>
#include <string>

#include "lancer/scene_graph.h"

namespace lancer {

class SceneError : public std::runtime_error {
  public:
    SceneError(sg::SourceLocation location, const std::string& message)
        : std::runtime_error(message), m_location(std::move(location)) {}
    const sg::SourceLocation& location() const { return m_location; }

  private:
    sg::SourceLocation m_location;
};

}  // namespace lancer
