// The live preview's HTTP side, on Debian's cpp-httplib: see preview_server.h.
#include "preview_server.h"

#include <httplib.h>
#include <sys/socket.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <mutex>
#include <thread>

#include "preview_page.h"
#include "render_report.h"

namespace lancer::app {

struct PreviewServer::State {
    httplib::Server server;
    std::thread thread;
    int port = 0;

    std::mutex mutex;  // guards what follows
    PreviewStatus status;
    std::vector<unsigned char> png;
    long image_version = 0;
    std::atomic<double> progress{0.0};

    std::string status_json() {
        std::lock_guard<std::mutex> lock(mutex);
        std::string errors;
        for (const std::string& error : status.errors) errors += (errors.empty() ? "" : ", ") + json_string(error);
        char numbers[96];
        const double shown = status.state == "rendering" ? progress.load() : status.progress;
        std::snprintf(numbers, sizeof numbers, "\"progress\": %.4f, \"image_version\": %ld",
                      std::isfinite(shown) ? shown : 0.0, image_version);
        return "{\"state\": " + json_string(status.state) + ", \"scene\": " + json_string(status.scene) + ", " +
               numbers + ", \"message\": " + json_string(status.message) + ", \"errors\": [" + errors + "]}";
    }
};

PreviewServer::PreviewServer() : m_state(std::make_unique<State>()) {}

PreviewServer::~PreviewServer() {
    m_state->server.stop();
    if (m_state->thread.joinable()) m_state->thread.join();
}

bool PreviewServer::start(int port, std::string& problem) {
    State& state = *m_state;
    httplib::Server& server = state.server;
    // Only this machine's own pages, by the address it was given: a
    // foreign Host header (DNS rebinding) gets nothing.
    server.set_pre_routing_handler([&state](const httplib::Request& request, httplib::Response& response) {
        const std::string host = request.get_header_value("Host");
        const std::string port_text = std::to_string(state.port);
        if (host == "127.0.0.1:" + port_text || host == "localhost:" + port_text)
            return httplib::Server::HandlerResponse::Unhandled;
        response.status = 403;
        response.set_content("lancer preview: only http://127.0.0.1:" + port_text + "/ is served\n", "text/plain");
        return httplib::Server::HandlerResponse::Handled;
    });
    server.Get("/", [](const httplib::Request&, httplib::Response& response) {
        response.set_header("Cache-Control", "no-store");
        response.set_content(kPreviewPage, "text/html; charset=utf-8");
    });
    server.Get("/status", [&state](const httplib::Request&, httplib::Response& response) {
        response.set_header("Cache-Control", "no-store");
        response.set_content(state.status_json(), "application/json");
    });
    server.Get("/image.png", [&state](const httplib::Request&, httplib::Response& response) {
        std::string bytes;
        {
            std::lock_guard<std::mutex> lock(state.mutex);
            bytes.assign(state.png.begin(), state.png.end());
        }
        response.set_header("Cache-Control", "no-store");
        if (bytes.empty()) {
            response.status = 404;
            response.set_content("no image yet\n", "text/plain");
            return;
        }
        response.set_content(bytes, "image/png");
    });
    // httplib's default also sets SO_REUSEPORT, which lets a second lancer
    // bind the same port and take half of the first one's requests.
    server.set_socket_options([](socket_t socket) {
        int yes = 1;
        ::setsockopt(socket, SOL_SOCKET, SO_REUSEADDR, &yes, sizeof yes);
    });
    // The page sends nothing but GETs; anything else, and any body, is refused.
    server.set_payload_max_length(0);

    if (port < 0 || port > 65535) {
        problem = "--port must be 0 (any free port) to 65535, got " + std::to_string(port);
        return false;
    }
    if (port == 0) {
        state.port = server.bind_to_any_port("127.0.0.1");
        if (state.port < 0) {
            problem = "the preview cannot bind a port on 127.0.0.1";
            return false;
        }
    } else {
        if (!server.bind_to_port("127.0.0.1", port)) {
            problem = "the preview cannot listen on 127.0.0.1:" + std::to_string(port) +
                      " (in use? choose another with --port, or 0 for any free one)";
            return false;
        }
        state.port = port;
    }
    state.thread = std::thread([&server] { server.listen_after_bind(); });
    // stop() only stops a server that is listening: wait until it is, so a
    // server destroyed at once does not leave its thread listening forever.
    while (!server.is_running()) std::this_thread::sleep_for(std::chrono::milliseconds(1));
    return true;
}

int PreviewServer::port() const {
    return m_state->port;
}

std::string PreviewServer::url() const {
    return "http://127.0.0.1:" + std::to_string(m_state->port) + "/";
}

void PreviewServer::publish_image(std::vector<unsigned char> png) {
    std::lock_guard<std::mutex> lock(m_state->mutex);
    m_state->png = std::move(png);
    ++m_state->image_version;
}

void PreviewServer::publish_status(const PreviewStatus& status) {
    std::lock_guard<std::mutex> lock(m_state->mutex);
    m_state->status = status;
    m_state->progress.store(status.progress);
}

void PreviewServer::publish_progress(double progress) {
    m_state->progress.store(progress);
}

}  // namespace lancer::app
