// What the commands that render hand the live preview (preview_server.h):
// a scene's errors as the page shows them, and a render's passes and
// progress as they happen. Shared by `lancer render --preview` and
// `lancer live`.
#pragma once

#include <exception>
#include <string>
#include <vector>

#include "lancer/host/image_io.h"
#include "lancer/host/renderer.h"
#include "lancer/parser.h"
#include "preview_server.h"

namespace lancer::app {

// The "error" status: each error of `diagnostics`, located and formatted as
// the terminal prints it (warnings and notes are left to the terminal).
PreviewStatus preview_errors(const std::string& scene, const std::vector<Diagnostic>& diagnostics);

// The "error" status of what a render threw: a SceneError keeps its
// location, any other exception is its message.
PreviewStatus preview_failure(const std::string& scene, const std::exception& error);

// Publishes the "rendering" status, and sets `options` so that every pass
// publishes the film (encoded as `look` says: the scene's gamma) and every
// tile the progress. `label` says what renders ("whitted, 320x240").
void feed_preview(PreviewServer& preview, const std::string& scene, const std::string& label,
                  const ImageWriteOptions& look, RenderOptions& options);

}  // namespace lancer::app
