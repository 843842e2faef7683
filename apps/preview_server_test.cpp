// The live preview's server as a client meets it: the page, the status
// JSON, the image, and what it refuses (tests/browser/ drives the page
// itself in a browser).
#include "preview_server.h"

#include <httplib.h>

#include <gtest/gtest.h>

#include "preview_feed.h"

namespace lancer::app {
namespace {

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

class Preview : public ::testing::Test {
  protected:
    void SetUp() override {
        std::string problem;
        ASSERT_TRUE(m_server.start(0, problem)) << problem;
        ASSERT_GT(m_server.port(), 0);
    }
    httplib::Result get(const std::string& path, const std::string& host = "") {
        httplib::Client client("127.0.0.1", m_server.port());
        httplib::Headers headers;
        if (!host.empty()) headers.emplace("Host", host);
        return client.Get(path.c_str(), headers);
    }
    PreviewServer m_server;
};

TEST_F(Preview, ServesThePageTheStatusAndTheImage) {
    EXPECT_EQ(m_server.url(), "http://127.0.0.1:" + std::to_string(m_server.port()) + "/");
    auto page = get("/");
    ASSERT_TRUE(page);
    EXPECT_EQ(page->status, 200);
    EXPECT_CONTAINS(page->body, "<img id=\"image\"");

    // No image yet: a 404 the page never asks for (version 0).
    auto image = get("/image.png");
    ASSERT_TRUE(image);
    EXPECT_EQ(image->status, 404);
    auto status = get("/status");
    ASSERT_TRUE(status);
    EXPECT_CONTAINS(status->body, "\"image_version\": 0");

    m_server.publish_image({0x89, 'P', 'N', 'G'});
    image = get("/image.png");
    ASSERT_TRUE(image);
    EXPECT_EQ(image->status, 200);
    EXPECT_EQ(image->get_header_value("Content-Type"), "image/png");
    EXPECT_EQ(image->body, std::string("\x89PNG"));
    EXPECT_CONTAINS(get("/status")->body, "\"image_version\": 1");
}

TEST_F(Preview, ProgressShowsWhileRendering) {
    PreviewStatus rendering;
    rendering.state = "rendering";
    rendering.scene = "room.pov";
    m_server.publish_status(rendering);
    m_server.publish_progress(0.25);
    const std::string body = get("/status")->body;
    EXPECT_CONTAINS(body, "\"state\": \"rendering\"");
    EXPECT_CONTAINS(body, "\"scene\": \"room.pov\"");
    EXPECT_CONTAINS(body, "\"progress\": 0.2500");
}

// Errors keep their location and survive JSON: quotes, backslashes, newlines.
TEST_F(Preview, ErrorsAreLocatedAndEscaped) {
    Diagnostic error;
    error.location.file = std::make_shared<const std::string>("scene \"one\".pov");
    error.location.line = 3;
    error.location.column = 7;
    error.message = "expected '}' \\ here";
    error.source_line = "sphere { 0, 1";
    Diagnostic warning = error;
    warning.severity = Diagnostic::Severity::Warning;
    m_server.publish_status(preview_errors("scene.pov", {error, warning}));
    const std::string body = get("/status")->body;
    EXPECT_CONTAINS(body, "\"state\": \"error\"");
    EXPECT_CONTAINS(body, "scene \\\"one\\\".pov:3:7: error: expected '}' \\\\ here\\n");
    EXPECT_EQ(body.find("warning"), std::string::npos) << "warnings stay in the terminal";
}

TEST_F(Preview, RefusesForeignHostsAndUnknownPaths) {
    auto rebound = get("/status", "attacker.example:" + std::to_string(m_server.port()));
    ASSERT_TRUE(rebound);
    EXPECT_EQ(rebound->status, 403);
    auto other_port = get("/status", "127.0.0.1:1");
    ASSERT_TRUE(other_port);
    EXPECT_EQ(other_port->status, 403);
    EXPECT_EQ(get("/status", "localhost:" + std::to_string(m_server.port()))->status, 200);
    EXPECT_EQ(get("/../../etc/passwd")->status, 404);
    httplib::Client client("127.0.0.1", m_server.port());
    auto posted = client.Post("/status", std::string(1000, 'x'), "text/plain");
    ASSERT_TRUE(posted);
    EXPECT_GE(posted->status, 400);
}

TEST(PreviewPort, ATakenPortIsAClearError) {
    PreviewServer first, second;
    std::string problem;
    ASSERT_TRUE(first.start(0, problem)) << problem;
    EXPECT_FALSE(second.start(first.port(), problem));
    EXPECT_CONTAINS(problem, "cannot listen on 127.0.0.1:" + std::to_string(first.port()));
    EXPECT_FALSE(second.start(70000, problem));
    EXPECT_CONTAINS(problem, "--port must be 0");
}

}  // namespace
}  // namespace lancer::app
