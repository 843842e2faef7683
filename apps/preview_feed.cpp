// The render's side of the live preview: see preview_feed.h.
#include "preview_feed.h"

#include "lancer/scene_error.h"

namespace lancer::app {

PreviewStatus preview_errors(const std::string& scene, const std::vector<Diagnostic>& diagnostics) {
    PreviewStatus status;
    status.state = "error";
    status.scene = scene;
    for (const Diagnostic& diagnostic : diagnostics)
        if (diagnostic.severity == Diagnostic::Severity::Error) status.errors.push_back(format_diagnostic(diagnostic));
    if (status.errors.empty()) status.errors.push_back("the scene has errors (see the terminal)");
    return status;
}

PreviewStatus preview_failure(const std::string& scene, const std::exception& error) {
    Diagnostic diagnostic;
    if (const auto* located = dynamic_cast<const SceneError*>(&error)) diagnostic.location = located->location();
    diagnostic.message = error.what();
    return preview_errors(scene, {diagnostic});
}

void feed_preview(PreviewServer& preview, const std::string& scene, const std::string& label,
                  const ImageWriteOptions& look, RenderOptions& options) {
    PreviewStatus status;
    status.state = "rendering";
    status.scene = scene;
    status.message = label;
    preview.publish_status(status);
    options.on_pass = [&preview, look](const Film& film, double fraction) {
        preview.publish_image(encode_png(film, look));
        preview.publish_progress(fraction);
    };
    options.on_progress = [&preview](double fraction) { preview.publish_progress(fraction); };
}

}  // namespace lancer::app
