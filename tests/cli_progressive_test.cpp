// `lancer render` with --time, --noise, --stats, signals, --checkpoint and
// --resume, run as a user runs it: the real binary, killed for real.
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "run_command.h"

extern char** environ;

namespace lancer::test {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

std::string read_file(const fs::path& path) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// All channels of an image as floats, plus its channel names and metadata.
struct Pixels {
    int width = 0, height = 0;
    std::vector<std::string> channels;
    std::vector<float> values;
    OIIO::ImageSpec spec;
};

Pixels read_pixels(const fs::path& path) {
    Pixels pixels;
    auto input = OIIO::ImageInput::open(path.string());
    if (!input) return pixels;
    pixels.spec = input->spec();
    pixels.width = pixels.spec.width;
    pixels.height = pixels.spec.height;
    pixels.channels = pixels.spec.channelnames;
    pixels.values.resize(std::size_t(pixels.width) * pixels.height * pixels.spec.nchannels);
    input->read_image(0, 0, 0, pixels.spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.values.data());
    return pixels;
}

// A lancer process running in the background, its output in a file.
class Background {
  public:
    Background(const std::vector<std::string>& arguments, const fs::path& log) {
        std::vector<std::string> argv = {binary_path("bin/lancer")};
        argv.insert(argv.end(), arguments.begin(), arguments.end());
        std::vector<char*> pointers;
        for (auto& argument : argv) pointers.push_back(argument.data());
        pointers.push_back(nullptr);
        posix_spawn_file_actions_t actions;
        posix_spawn_file_actions_init(&actions);
        posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
        posix_spawn_file_actions_adddup2(&actions, STDOUT_FILENO, STDERR_FILENO);
        if (posix_spawn(&m_pid, pointers[0], &actions, nullptr, pointers.data(), environ) != 0) m_pid = -1;
        posix_spawn_file_actions_destroy(&actions);
    }
    ~Background() {
        if (m_pid > 0 && !m_reaped) {
            ::kill(m_pid, SIGKILL);
            wait();
        }
    }
    bool started() const { return m_pid > 0; }
    bool running() {
        if (m_reaped) return false;
        int status = 0;
        if (::waitpid(m_pid, &status, WNOHANG) == m_pid) {
            m_reaped = true;
            m_status = status;
            return false;
        }
        return true;
    }
    void signal(int number) { ::kill(m_pid, number); }
    int wait() {
        if (!m_reaped) {
            ::waitpid(m_pid, &m_status, 0);
            m_reaped = true;
        }
        return m_status;
    }

  private:
    pid_t m_pid = -1;
    bool m_reaped = false;
    int m_status = 0;
};

// Polls until `condition` holds or `seconds` pass.
template <typename Condition>
bool wait_for(Condition condition, double seconds) {
    const auto give_up = Clock::now() + std::chrono::duration<double>(seconds);
    while (Clock::now() < give_up) {
        if (condition()) return true;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return condition();
}

class CliProgressive : public ::testing::Test {
  protected:
    void SetUp() override {
        m_folder =
            binary_path("tests/cli_progressive_out/") + ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(m_folder);
        fs::create_directories(m_folder);
        m_scene = source_path("scenes/cornell_box.pov");
    }
    std::string out(const std::string& name) const { return (m_folder / name).string(); }
    // The Cornell box with path at a small size.
    CommandResult render(const std::string& extra, int size = 24) {
        return run_lancer("render scenes/cornell_box.pov -i path --width " + std::to_string(size) + " --height " +
                          std::to_string(size) + " " + extra);
    }
    std::vector<std::string> render_arguments(const std::string& output, std::vector<std::string> extra) {
        std::vector<std::string> arguments = {"render", m_scene,    "-i", "path", "--width",
                                              "32",     "--height", "32", "-o",   output};
        arguments.insert(arguments.end(), extra.begin(), extra.end());
        return arguments;
    }
    fs::path m_folder;
    std::string m_scene;
};

TEST_F(CliProgressive, TimeBudgetEndsWithinIt) {
    const auto start = Clock::now();
    const CommandResult result = render("--time 1 -o '" + out("t.png") + "' --stats '" + out("t.json") + "'", 64);
    const double seconds = std::chrono::duration<double>(Clock::now() - start).count();
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_GT(seconds, 0.5);
    EXPECT_LT(seconds, 3.0);
    const std::string json = read_file(out("t.json"));
    EXPECT_CONTAINS(json, "\"mode\": \"time\"");
    EXPECT_CONTAINS(json, "\"time_seconds\": 1,");
}

TEST_F(CliProgressive, StatsFileMetadataAndSummaryAgree) {
    const CommandResult result = render("--spp 4 --seed 3 -o '" + out("s.exr") + "' --stats '" + out("s.json") + "'");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_CONTAINS(result.output, "24x24, 4 spp, path");
    EXPECT_CONTAINS(result.output, "Mrays/s");
    EXPECT_CONTAINS(result.output, "est. rel. error");
    const std::string json = read_file(out("s.json"));
    for (const char* field : {"\"integrator\": \"path\"", "\"max_depth\": \"8\"", "\"width\": 24", "\"height\": 24",
                              "\"seed\": 3", "\"samples\": {\"mean\": 4, \"min\": 4, \"max\": 4, \"taken\": 2304}",
                              "\"seconds\": {\"total\": ", "\"render\": ", "\"rays\": ", "\"rays_per_second\": ",
                              "\"nonfinite_samples\": 0", "\"estimated_rel_rmse\": ", "\"interrupted\": false"})
        EXPECT_CONTAINS(json, field);
    // Path traces at least the camera ray of each sample.
    const auto rays_at = json.find("\"rays\": ");
    ASSERT_NE(rays_at, std::string::npos);
    EXPECT_GE(std::stoull(json.substr(rays_at + 8)), 2304u);
    const Pixels image = read_pixels(out("s.exr"));
    EXPECT_EQ(image.spec.get_string_attribute("lancer:integrator"), "path");
    EXPECT_EQ(image.spec.get_string_attribute("lancer:spp_min"), "4");
    EXPECT_FALSE(image.spec.get_string_attribute("lancer:estimated_rel_rmse").empty());
    EXPECT_FALSE(image.spec.get_string_attribute("lancer:rays").empty());
}

// Under a noise target the progress counts samples against the total the
// render predicts it needs, not the share of pixels already done (which
// runs far ahead: the last pixels take most of the samples). So the ETA
// at half way, added to the time spent, foretells the render's length.
// Both ends are measured in one run: a loaded machine slows them alike.
TEST_F(CliProgressive, EtaUnderANoiseTargetForetellsTheEnd) {
    const CommandResult result = render("--noise 0.05 -o '" + out("eta.png") + "'", 64);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    std::istringstream lines(result.output);
    std::string line;
    double predicted_total = -1.0, last_elapsed = -1.0;
    while (std::getline(lines, line)) {
        int percent = 0;
        double elapsed = 0.0, eta = 0.0;
        if (std::sscanf(line.c_str(), "progress: %d%% elapsed %lfs ETA %lfs", &percent, &elapsed, &eta) == 3) {
            if (percent == 50) predicted_total = elapsed + eta;
            last_elapsed = elapsed;
        } else if (std::sscanf(line.c_str(), "progress: %d%% elapsed %lfs", &percent, &elapsed) == 2) {
            last_elapsed = elapsed;
        }
    }
    ASSERT_GT(predicted_total, 0.0) << result.output;
    ASSERT_GT(last_elapsed, 0.5) << "too short a render to measure: " << result.output;
    EXPECT_GT(predicted_total, 0.6 * last_elapsed) << result.output;
    EXPECT_LT(predicted_total, 1.6 * last_elapsed) << result.output;
}

TEST_F(CliProgressive, NoiseTargetVariesSamplesAndRecordsThem) {
    const CommandResult result =
        render("--noise 0.1 --spp 256 -o '" + out("n.exr") + "' --stats '" + out("n.json") + "'", 32);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const std::string json = read_file(out("n.json"));
    EXPECT_CONTAINS(json, "\"mode\": \"noise\"");
    EXPECT_CONTAINS(json, "\"min\": 16,");
    EXPECT_CONTAINS(json, "\"max\": 256,");
    const Pixels image = read_pixels(out("n.exr"));
    ASSERT_EQ(image.channels.size(), 4u);
    EXPECT_EQ(image.channels[3], "samples");
}

TEST_F(CliProgressive, BadValuesAreUsageErrors) {
    for (const char* arguments : {"--time 0", "--noise -1", "--checkpoint 0"}) {
        const CommandResult result = render(std::string(arguments) + " -o '" + out("x.png") + "'");
        EXPECT_EQ(result.exit_code, 2) << arguments << ": " << result.output;
        EXPECT_CONTAINS(result.output, "error:");
    }
    // Killed before its first checkpoint: --resume starts over.
    const CommandResult result = render("--spp 2 --resume -o '" + out("x.png") + "'");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_CONTAINS(result.output, "no checkpoint");
    EXPECT_TRUE(fs::exists(out("x.png")));
}

TEST_F(CliProgressive, SignalsWriteTheImageSoFar) {
    for (const int number : {SIGINT, SIGTERM}) {
        const std::string image = out("sig" + std::to_string(number) + ".exr");
        const fs::path log = m_folder / ("sig" + std::to_string(number) + ".log");
        Background lancer(render_arguments(image, {"--spp", "100000"}), log);
        ASSERT_TRUE(lancer.started());
        // The render has started once progress is reported.
        ASSERT_TRUE(wait_for([&] { return read_file(log).find("progress:") != std::string::npos; }, 30.0))
            << read_file(log);
        std::this_thread::sleep_for(std::chrono::milliseconds(100));
        lancer.signal(number);
        const int status = lancer.wait();
        ASSERT_TRUE(WIFEXITED(status)) << read_file(log);
        EXPECT_EQ(WEXITSTATUS(status), 128 + number);
        EXPECT_CONTAINS(read_file(log), number == SIGINT ? "interrupted by SIGINT" : "interrupted by SIGTERM");
        // The progress says where it stopped, never that it finished.
        EXPECT_CONTAINS(read_file(log), "progress: interrupted at");
        EXPECT_EQ(read_file(log).find("progress: 100%"), std::string::npos) << read_file(log);
        const Pixels pixels = read_pixels(image);
        ASSERT_EQ(pixels.width, 32) << read_file(log);
        ASSERT_EQ(pixels.channels.size(), 4u);
        float most = 0.0f;
        for (std::size_t i = 3; i < pixels.values.size(); i += 4) most = std::max(most, pixels.values[i]);
        EXPECT_GT(most, 0.0f);
        EXPECT_LT(most, 100000.0f);
        EXPECT_EQ(pixels.spec.get_string_attribute("lancer:interrupted"), "true");
    }
}

TEST_F(CliProgressive, ResumeAfterKillNineIsBitIdentical) {
    // Killed with -9 as soon as its first checkpoint is written (mid-pass:
    // passes are kept to the checkpoint interval), on two threads ...
    const std::string resumed = out("resumed.exr");
    const std::string checkpoint = resumed + ".lancer-checkpoint";
    // Enough samples (about 1 s on an idle 2-core machine) that the render
    // cannot end between its first checkpoint and the kill.
    const std::vector<std::string> settings = {"--spp", "1536", "--seed", "7", "--checkpoint", "0.2"};
    {
        Background lancer(render_arguments(resumed, settings), m_folder / "killed.log");
        ASSERT_TRUE(lancer.started());
        ASSERT_TRUE(wait_for([&] { return fs::exists(checkpoint) || !lancer.running(); }, 60.0));
        ASSERT_TRUE(lancer.running()) << "finished before it could be killed: " << read_file(m_folder / "killed.log");
        lancer.signal(SIGKILL);
        EXPECT_TRUE(WIFSIGNALED(lancer.wait()));
    }
    ASSERT_TRUE(fs::exists(checkpoint));
    EXPECT_FALSE(fs::exists(resumed));

    auto command = [&](const std::string& output, const std::string& extra) {
        return "render scenes/cornell_box.pov -i path --width 32 --height 32 --spp 1536 --checkpoint 0.2 -o '" +
               output + "' " + extra;
    };
    // ... another seed is refused, naming what differs ...
    CommandResult result = run_lancer(command(resumed, "--seed 8 --resume -q"));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "seed: checkpoint has '7', this render '8'");
    // ... as is --stats, whose error estimate needs a film of another kind ...
    result = run_lancer(command(resumed, "--seed 7 --resume -q --stats '" + out("resumed.json") + "'"));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "film: checkpoint has 'float sums (without --stats)', this render 'double totals'");
    // ... the same settings continue, on one thread ...
    result = run_lancer(command(resumed, "--seed 7 --resume --threads 1 -q"));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_FALSE(fs::exists(checkpoint));
    // ... and give the uninterrupted render's pixels, bit for bit.
    const std::string straight = out("straight.exr");
    result = run_lancer(command(straight, "--seed 7 -q"));
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const Pixels a = read_pixels(resumed), b = read_pixels(straight);
    ASSERT_EQ(a.values.size(), std::size_t(32 * 32 * 3));
    ASSERT_EQ(a.values.size(), b.values.size());
    EXPECT_EQ(std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(float)), 0);
}

}  // namespace
}  // namespace lancer::test
