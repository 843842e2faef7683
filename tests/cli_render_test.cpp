// `lancer render` and `lancer plugins` as a user meets them: bad arguments
// get an "error:" line and a non-zero status, and nothing is written unless
// the whole render succeeds.
#include <sys/wait.h>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "run_command.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

class CliRender : public ::testing::Test {
  protected:
    void SetUp() override {
        m_folder =
            binary_path("tests/cli_render_out/") + ::testing::UnitTest::GetInstance()->current_test_info()->name();
        fs::remove_all(m_folder);
        fs::create_directories(m_folder);
        m_scene = m_folder / "ball.pov";
        std::ofstream(m_scene) << "camera { location <0, 0, -5> look_at <0, 0, 0> angle 40 }\n"
                                  "light_source { <5, 5, -5> color rgb <1, 1, 1> }\n"
                                  "sphere { <0, 0, 0>, 1 pigment { color rgb <1, 0.5, 0.2> } }\n";
    }

    // The scene, a small size and the output in this test's folder.
    CommandResult render(const std::string& extra, const std::string& output = "out.png") {
        return run_lancer("render '" + m_scene.string() + "' --width 32 --height 24 -o '" +
                          (m_folder / output).string() + "' " + extra);
    }
    bool wrote(const std::string& output = "out.png") const { return fs::exists(m_folder / output); }
    bool folder_holds_only_the_scene() const {
        int count = 0;
        for ([[maybe_unused]] const auto& entry : fs::directory_iterator(m_folder)) ++count;
        return count == 1;
    }

    fs::path m_folder;
    fs::path m_scene;
};

TEST_F(CliRender, WritesTheImageAndASummary) {
    const CommandResult result = render("");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    EXPECT_TRUE(wrote());
    EXPECT_CONTAINS(result.output, "32x24");
    EXPECT_CONTAINS(result.output, "1 spp");
    // The scene names no integrator: it renders with the one that shows
    // what POV-Ray shows (shadows, mirrors, refraction).
    EXPECT_CONTAINS(result.output, "whitted");
}

TEST_F(CliRender, FramesAreNumberedAsPovRayNamesThem) {
    // Frames 8..12: the number padded to the final frame's digits.
    const CommandResult result =
        render("-q --frames 8..12 --clock 0..2 --stats '" + (m_folder / "run.json").string() + "'", "anim.png");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    for (const char* name : {"anim08.png", "anim09.png", "anim10.png", "anim11.png", "anim12.png"})
        EXPECT_TRUE(wrote(name)) << name;
    EXPECT_FALSE(wrote("anim.png"));
    EXPECT_FALSE(wrote("anim7.png"));
    EXPECT_TRUE(wrote("run08.json"));
    EXPECT_TRUE(wrote("run12.json"));
}

TEST_F(CliRender, ResumingAnAnimationSkipsTheFramesWritten) {
    ASSERT_EQ(render("-q --frames 1..3", "a.png").exit_code, 0);
    const auto written = fs::last_write_time(m_folder / "a1.png");
    fs::remove(m_folder / "a3.png");
    const CommandResult resumed = render("--frames 1..3 --resume", "a.png");
    ASSERT_EQ(resumed.exit_code, 0) << resumed.output;
    EXPECT_EQ(fs::last_write_time(m_folder / "a1.png"), written);
    EXPECT_TRUE(wrote("a3.png"));
    EXPECT_EQ(resumed.output.find("frame 1 of"), std::string::npos) << resumed.output;
    EXPECT_CONTAINS(resumed.output, "frame 3 of 1..3");
}

TEST_F(CliRender, BadFramesAndClockAreUsageErrors) {
    for (const char* bad : {"--frames 3..1", "--frames 1..", "--frames a..b", "--frames -2..3",
                            "--frames 1..3 --clock 0", "--frames 1..3 --clock 0..inf", "--clock 0..1"}) {
        const CommandResult result = render(bad);
        EXPECT_EQ(result.exit_code, 2) << bad;
        EXPECT_CONTAINS(result.output, "error:");
        EXPECT_TRUE(folder_holds_only_the_scene()) << bad;
    }
}

TEST_F(CliRender, EveryBuiltInIntegratorRenders) {
    for (const std::string name : {"raycast", "normal", "albedo", "depth"}) {
        const CommandResult result = render("-i " + name + " --quiet", name + ".exr");
        EXPECT_EQ(result.exit_code, 0) << name << ": " << result.output;
        EXPECT_TRUE(wrote(name + ".exr")) << name;
    }
}

TEST_F(CliRender, DefaultOutputIsTheSceneNameInTheCurrentFolder) {
    const fs::path elsewhere = m_folder / "cwd";
    fs::create_directories(elsewhere);
    const std::string command = "cd '" + elsewhere.string() + "' && '" + binary_path("bin/lancer") +
                                "' render ../ball.pov --width 8 --height 6 --quiet";
    const int status = std::system(command.c_str());
    EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << command;
    EXPECT_TRUE(fs::exists(elsewhere / "ball.png"));
}

TEST_F(CliRender, UnknownIntegratorListsWhatExists) {
    const CommandResult result = render("-i no_such_integrator");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "error:");
    EXPECT_CONTAINS(result.output, "no integrator plugin 'no_such_integrator'");
    EXPECT_CONTAINS(result.output, "raycast");
    EXPECT_TRUE(folder_holds_only_the_scene());
}

TEST_F(CliRender, BadArgumentsAreUsageErrors) {
    const struct {
        const char* arguments;
        const char* message;
    } cases[] = {
        {"--crop 1,2,3", "--crop expects four integers"},
        {"--crop a,b,c,d", "--crop expects four integers"},
        {"--crop 10,10,5,20", "not a non-empty rectangle"},
        {"--crop 0,0,33,24", "not a non-empty rectangle"},
        {"--width 0", "--width must be a positive"},
        {"--height -3", "--height must be a positive"},
        {"--spp 0", "--spp must be at least 1"},
        {"-p ambient", "-p expects key=value"},
        {"-p =1", "-p expects key=value"},
        {"--time inf", "--time must be a positive, finite"},
        {"--time nan", "--time must be a positive, finite"},
        {"--noise inf", "--noise must be a positive"},
        {"--seed -1", "--seed: expects a whole number"},
        {"--seed 18446744073709551616", "--seed: expects a whole number"},
    };
    for (const auto& c : cases) {
        const CommandResult result = render(c.arguments);
        EXPECT_EQ(result.exit_code, 2) << c.arguments << ": " << result.output;
        EXPECT_CONTAINS(result.output, "error:");
        EXPECT_CONTAINS(result.output, c.message);
    }
    EXPECT_TRUE(folder_holds_only_the_scene());
}

TEST_F(CliRender, UnknownOutputExtension) {
    const CommandResult result = render("", "out.xyz");
    EXPECT_EQ(result.exit_code, 2) << result.output;
    EXPECT_CONTAINS(result.output, "unknown image extension");
    EXPECT_TRUE(folder_holds_only_the_scene());
}

// path has no fog or rainbow to add (they are POV-Ray's effects, not light
// in a volume): it says so, where the scene asks for them; whitted does not.
TEST_F(CliRender, PathSaysItIgnoresFogAndRainbows) {
    std::ofstream(m_scene, std::ios::app) << "fog { distance 3 color rgb 0.5 }\n"
                                             "rainbow { angle 42.5 width 5 distance 1e3 direction <0, 0, 1>\n"
                                             "  color_map { [0 rgbt <1, 0, 0, 0.5>] [1 rgbt <0, 0, 1, 0.5>] } }\n";
    const CommandResult path = render("-i path --spp 1 -q");
    ASSERT_EQ(path.exit_code, 0) << path.output;
    EXPECT_CONTAINS(path.output, "ball.pov:4:1: warning: path ignores fog");
    EXPECT_CONTAINS(path.output, "ball.pov:5:1: warning: path ignores rainbow");
    const CommandResult whitted = render("-i whitted -q");
    ASSERT_EQ(whitted.exit_code, 0) << whitted.output;
    EXPECT_EQ(whitted.output.find("ignores"), std::string::npos) << whitted.output;
}

// double_illuminate, inside a union too, is POV-Ray's lighting of the
// classic integrators: path says it ignores it; whitted does not warn.
TEST_F(CliRender, PathSaysItIgnoresDoubleIlluminate) {
    std::ofstream(m_scene, std::ios::app) << "union { disc { <0, 0, 3>, z, 1 double_illuminate } }\n";
    const CommandResult path = render("-i path --spp 1 -q");
    ASSERT_EQ(path.exit_code, 0) << path.output;
    EXPECT_CONTAINS(path.output, "ball.pov:4:9: warning: path ignores double_illuminate");
    const CommandResult whitted = render("-i whitted -q");
    ASSERT_EQ(whitted.exit_code, 0) << whitted.output;
    EXPECT_EQ(whitted.output.find("double_illuminate"), std::string::npos) << whitted.output;
}

// A camera inside a solid object sees no fog (POV-Ray's rule, which it
// applies silently): lancer says which object, where it is written.
TEST_F(CliRender, ACameraInsideASolidObjectIsToldItSeesNoFog) {
    std::ofstream(m_scene, std::ios::app) << "fog { distance 3 color rgb 0.5 }\n"
                                             "box { -50, 50 pigment { rgbt 1 } }\n";
    const CommandResult solid = render("-i whitted -q");
    ASSERT_EQ(solid.exit_code, 0) << solid.output;
    EXPECT_CONTAINS(solid.output, "ball.pov:5:1: warning: the camera is inside this object, which is not hollow");
    std::ofstream(m_scene, std::ios::app) << "sphere { 0, 100 hollow }\n";  // hollow: no warning of its own
    const CommandResult both = render("-i whitted -q");
    EXPECT_EQ(both.output.find("ball.pov:6:1"), std::string::npos) << both.output;
}

TEST_F(CliRender, ParametersAreCheckedAgainstThePlugin) {
    CommandResult result = render("-i raycast -p no_such_parameter=1");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "-p no_such_parameter=1");
    EXPECT_CONTAINS(result.output, "ambient (bool)");  // what raycast does declare
    result = render("-i raycast -p ambient=maybe");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "expects a boolean");
    EXPECT_TRUE(folder_holds_only_the_scene());
    // nan and inf parse as doubles, but no setting means them.
    result = render("-i path -p clamp=nan");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "expects a finite number");
    EXPECT_TRUE(folder_holds_only_the_scene());
    result = render("-i raycast -p ambient=off -p specular=false");
    EXPECT_EQ(result.exit_code, 0) << result.output;
}

TEST_F(CliRender, IntegratorRejectingAValueWritesNothing) {
    const CommandResult result = render("-i depth -p max_distance=-1");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "error:");
    EXPECT_CONTAINS(result.output, "max_distance");
    EXPECT_TRUE(folder_holds_only_the_scene());
}

TEST_F(CliRender, SceneErrorIsLocatedAndWritesNothing) {
    std::ofstream(m_scene) << "camera { location <0, 0, -5> look_at <0, 0, 0> }\n"
                              "sphere { <0, 0, 0>, 1 pigment { color rgb <1, 0, 0> }\n";  // missing '}'
    const CommandResult result = render("");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "ball.pov:");
    EXPECT_CONTAINS(result.output, "error:");
    EXPECT_TRUE(folder_holds_only_the_scene());
}

TEST_F(CliRender, MissingSceneFile) {
    const CommandResult result = run_lancer("render /nonexistent/scene.pov -o '" + (m_folder / "x.png").string() + "'");
    EXPECT_NE(result.exit_code, 0);
    EXPECT_CONTAINS(result.output, "error");
    EXPECT_FALSE(wrote("x.png"));
}

TEST_F(CliRender, MissingOutputFolderFailsBeforeRendering) {
    const CommandResult result = render("", "no/such/folder/out.png");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_CONTAINS(result.output, "does not exist");
}

TEST_F(CliRender, SceneRenderSettingsAreDefaultsTheCommandLineOverrides) {
    std::ofstream(m_scene) << "camera { location <0, 0, -5> look_at <0, 0, 0> angle 40 }\n"
                              "light_source { <5, 5, -5> color rgb <1, 1, 1> }\n"
                              "sphere { <0, 0, 0>, 1 pigment { color rgb <1, 0.5, 0.2> } }\n"
                              "render_settings { integrator \"depth\" { max_distance 10 } width 20 height 10 }\n";
    CommandResult result = run_lancer("render '" + m_scene.string() + "' -o '" + (m_folder / "a.png").string() + "'");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_CONTAINS(result.output, "20x10");
    EXPECT_CONTAINS(result.output, "depth");
    result =
        run_lancer("render '" + m_scene.string() + "' --width 16 -i normal -o '" + (m_folder / "b.png").string() + "'");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_CONTAINS(result.output, "16x10");
    EXPECT_CONTAINS(result.output, "normal");
    EXPECT_CONTAINS(result.output, "warning");  // depth's max_distance does not apply to normal
}

TEST(CliPlugins, ListsEveryBuiltInPluginWithItsParameters) {
    const CommandResult result = run_lancer("plugins");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    for (const char* expected : {"raycast", "normal", "albedo", "depth", "ambient", "max_distance",
                                 "lancer/plugins/raycast.so", "bool", "float"}) {
        EXPECT_CONTAINS(result.output, expected);
    }
}

TEST(CliPlugins, ShowsOnePluginOrFails) {
    CommandResult result = run_lancer("plugins depth");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_CONTAINS(result.output, "max_distance");
    EXPECT_EQ(result.output.find("raycast.so"), std::string::npos);
    result = run_lancer("plugins nope");
    EXPECT_EQ(result.exit_code, 1) << result.output;
}

}  // namespace
}  // namespace lancer::test
