// The rule for every file `lancer render` writes: never the scene or a file
// the scene read, never two outputs at one path, every output path checked
// before rendering, so nothing a user owns is replaced by a render.
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "run_command.h"
#include "temp_folder.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

std::string contents(const fs::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream out;
    out << in.rdbuf();
    return out.str();
}

class OutputFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        fs::create_directories(m_folder.path() / "sub");
        m_include = m_folder.write("colours.inc", "#declare Orange = rgb <1, 0.5, 0.2>;\n");
        m_scene = m_folder.write("ball.pov",
                                 "#include \"colours.inc\"\n"
                                 "camera { location <0, 0, -5> look_at <0, 0, 0> angle 40 }\n"
                                 "light_source { <5, 5, -5> color rgb 1 }\n"
                                 "sphere { 0, 1 pigment { color Orange } }\n");
        m_scene_text = contents(m_scene);
    }
    CommandResult render(const std::string& outputs) {
        return run_lancer("render '" + m_scene + "' --width 16 --height 12 -q " + outputs);
    }
    std::string in_folder(const std::string& name) const { return (m_folder.path() / name).string(); }
    void expect_refused(const CommandResult& result, const std::string& why) {
        EXPECT_NE(result.exit_code, 0) << result.output;
        EXPECT_CONTAINS(result.output, why);
        EXPECT_EQ(contents(m_scene), m_scene_text) << "the scene was overwritten";
    }

    TempFolder m_folder;
    std::string m_scene, m_include, m_scene_text;
};

TEST_F(OutputFiles, NeverTheSceneUnderAnyName) {
    expect_refused(render("-o '" + in_folder("out.png") + "' --stats '" + m_scene + "'"), "it is the scene file");
    expect_refused(render("-o '" + in_folder("out.png") + "' --stats '" + in_folder("sub/../ball.pov") + "'"),
                   "it is the scene file");
    fs::create_symlink(m_scene, in_folder("alias.png"));
    expect_refused(render("-o '" + in_folder("alias.png") + "'"), "it is the scene file");
}

// An image the scene maps is an input too: -o naming it is refused.
TEST_F(OutputFiles, NeverATextureTheSceneMaps) {
    const std::string texture = in_folder("texture.png");
    ASSERT_EQ(render("-o '" + texture + "'").exit_code, 0);
    const std::string before = contents(texture);
    const std::string mapped = m_folder.write("mapped.pov",
                                              "camera { location <0, 0, -5> look_at 0 }\n"
                                              "light_source { <5, 5, -5> color rgb 1 }\n"
                                              "sphere { 0, 1 pigment { image_map { png \"texture.png\" } } }\n");
    const CommandResult result = run_lancer("render '" + mapped + "' --width 16 --height 12 -q -o '" + texture + "'");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_CONTAINS(result.output, "which the scene reads");
    EXPECT_EQ(contents(texture), before);
}

TEST_F(OutputFiles, NeverAFileTheSceneRead) {
    const std::string before = contents(m_include);
    const CommandResult result = render("-o '" + in_folder("out.png") + "' --stats '" + m_include + "'");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_CONTAINS(result.output, "which the scene reads");
    EXPECT_EQ(contents(m_include), before);
    EXPECT_FALSE(fs::exists(in_folder("out.png"))) << "nothing is rendered when an output is refused";
}

TEST_F(OutputFiles, NeverTwoOutputsAtOnePath) {
    const std::string image = in_folder("out.png");
    const CommandResult result = render("-o '" + image + "' --stats '" + in_folder("sub/../out.png") + "'");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_CONTAINS(result.output, "name the same file");
    EXPECT_FALSE(fs::exists(image));
}

// A --stats path that cannot be written fails the run before the existing
// image is replaced.
TEST_F(OutputFiles, AnUnwritableStatsPathFailsBeforeTheImageIsTouched) {
    const std::string image = m_folder.write("out.png", "the user's old image");
    const CommandResult result = render("-o '" + image + "' --stats '" + in_folder("missing/stats.json") + "'");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_CONTAINS(result.output, "does not exist");
    EXPECT_EQ(contents(image), "the user's old image");
}

TEST_F(OutputFiles, EmptyNamesAreUsageErrors) {
    const CommandResult empty_output = render("-o ''");
    EXPECT_NE(empty_output.exit_code, 0);
    EXPECT_CONTAINS(empty_output.output, "-o needs a file name");
    const CommandResult empty_stats = render("-o '" + in_folder("out.png") + "' --stats ''");
    EXPECT_NE(empty_stats.exit_code, 0);
    EXPECT_CONTAINS(empty_stats.output, "--stats needs a file name");
    EXPECT_FALSE(fs::exists(in_folder("ball.png")));
    // "-" is not taken as a file name, as standard output is not offered.
    const CommandResult dash_stats = render("-o '" + in_folder("out.png") + "' --stats -");
    EXPECT_EQ(dash_stats.exit_code, 2) << dash_stats.output;
    EXPECT_CONTAINS(dash_stats.output, "'-' (standard output) is not offered");
    EXPECT_FALSE(fs::exists(source_path("-")));  // where lancer runs here
    EXPECT_FALSE(fs::exists(in_folder("out.png")));
}

// A render killed during its final write (SIGKILL, a second SIGINT) runs
// no code to clean up: the next render beside it removes what it left.
TEST_F(OutputFiles, TemporariesOfDeadRendersAreRemovedAtTheNextStart) {
    const std::string dead = m_folder.write(".out.tmp999999999-0.png", "a partial image");
    const std::string alive = m_folder.write(".out.tmp1-0.png", "pid 1 is always running");
    const std::string other = m_folder.write(".other.tmp999999999-0.png", "another file's");
    ASSERT_EQ(render("-o '" + in_folder("out.png") + "'").exit_code, 0);
    EXPECT_FALSE(fs::exists(dead));
    EXPECT_TRUE(fs::exists(alive));
    EXPECT_TRUE(fs::exists(other));
}

// A killed writer whose parent exited first stays a zombie where nothing
// reaps orphans (a container's first process often does not): it answers
// kill(pid, 0) yet writes nothing more.
TEST_F(OutputFiles, TemporariesOfUnreapedDeadProcessesAreRemoved) {
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) ::_exit(0);
    // Until the child has exited it is not a zombie yet.
    for (int tries = 0; tries < 500; ++tries) {
        siginfo_t info{};
        if (::waitid(P_PID, id_t(child), &info, WEXITED | WNOHANG | WNOWAIT) == 0 && info.si_pid == child) break;
        ::usleep(2000);
    }
    const std::string left = m_folder.write(".out.tmp" + std::to_string(child) + "-0.png", "a partial image");
    const CommandResult result = render("-o '" + in_folder("out.png") + "'");
    ::waitpid(child, nullptr, 0);
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_FALSE(fs::exists(left));
}

// lancer trade writes results.csv, index.html, plots and images into its
// folder: a scene that reads a file there under one of those names is
// refused before anything renders.
TEST_F(OutputFiles, TradeNeverWritesOverWhatTheSceneReads) {
    const std::string csv = m_folder.write("results.csv", "#declare Size = 1;\n");
    const std::string scene = m_folder.write("traded.pov",
                                             "#include \"results.csv\"\n"
                                             "camera { location <0, 0, -5> look_at 0 }\n"
                                             "light_source { <5, 5, -5> color rgb 1 }\n"
                                             "sphere { 0, Size }\n");
    const CommandResult result = run_lancer("trade '" + scene + "' -o '" + m_folder.path().string() + "' --quick");
    EXPECT_NE(result.exit_code, 0) << result.output;
    EXPECT_CONTAINS(result.output, "refusing to write the report");
    EXPECT_EQ(contents(csv), "#declare Size = 1;\n");
}

TEST_F(OutputFiles, AllowedOutputsAreWritten) {
    const CommandResult result = render("-o '" + in_folder("out.png") + "' --stats '" + in_folder("stats.json") + "'");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(fs::exists(in_folder("out.png")));
    EXPECT_CONTAINS(contents(in_folder("stats.json")), "\"integrator\"");
}

}  // namespace
}  // namespace lancer::test
