// The live preview: a page on the loopback interface that shows a render
// refining pass by pass, its progress and stats, and the located errors of
// a scene that does not parse (`lancer render --preview`, `lancer live`).
// It serves three things, from whatever thread renders:
//   GET /            the page (preview_page.h), which polls the other two
//   GET /status      JSON: state, progress, message, errors, image version
//   GET /image.png   the newest image
// Only 127.0.0.1 is bound, and a request whose Host is not the loopback
// address with this port is refused (a web page elsewhere cannot reach it
// through DNS rebinding).
#pragma once

#include <memory>
#include <string>
#include <vector>

namespace lancer::app {

// What the page shows beside the image.
struct PreviewStatus {
    // "parsing", "rendering", "done", "error" or "interrupted".
    std::string state = "parsing";
    std::string scene;
    double progress = 0.0;            // of the current render, 0 to 1
    std::string message;              // e.g. the summary line of a finished render
    std::vector<std::string> errors;  // located, as the terminal prints them
};

class PreviewServer {
  public:
    PreviewServer();
    ~PreviewServer();  // stops serving
    PreviewServer(const PreviewServer&) = delete;
    PreviewServer& operator=(const PreviewServer&) = delete;

    // Binds 127.0.0.1:`port` (0: a free port) and serves from a thread of
    // its own. False with `problem` set when the port cannot be bound.
    bool start(int port, std::string& problem);
    int port() const;
    std::string url() const;  // "http://127.0.0.1:PORT/"

    // Thread-safe; each new image gets a new version the page reloads by.
    void publish_image(std::vector<unsigned char> png);
    void publish_status(const PreviewStatus& status);
    void publish_progress(double progress);  // cheap: called per tile

  private:
    struct State;
    std::unique_ptr<State> m_state;
};

}  // namespace lancer::app
