// A plugin written outside lancer's tree builds against an installed lancer
// and loads like a built-in one. The test does what a user does:
//   1. cmake --install the build into a fresh prefix,
//   2. configure and build tests/out_of_tree_plugin with find_package(lancer),
//   3. run the installed bin/lancer with -i on the new plugin, found through
//      LANCER_PLUGIN_PATH, and check the image it wrote.
// It takes a few seconds (one small CMake project).
#include <sys/wait.h>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <string>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "run_command.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

struct ShellResult {
    int exit_code = -1;
    std::string output;
};

// Runs the words joined by spaces; each word is already shell-quoted if needed.
ShellResult run_shell(std::initializer_list<std::string> words) {
    std::string command;
    for (const auto& word : words) {
        command += word;
        command += ' ';
    }
    command += "2>&1";
    ShellResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer;
    std::size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

std::string shell_quoted(const fs::path& path) {
    std::string quoted = "'";
    quoted += path.string();
    quoted += '\'';
    return quoted;
}

TEST(OutOfTreePlugin, BuildsAgainstTheInstalledPackageAndLoads) {
    const fs::path work = binary_path("tests/out_of_tree_work");
    const fs::path prefix = work / "prefix";
    const fs::path plugin_build = work / "plugin-build";
    fs::remove_all(work);
    fs::create_directories(work);
    const std::string cmake = LANCER_CMAKE_COMMAND;

    // 1. Install.
    const ShellResult install = run_shell(
        {shell_quoted(cmake), "--install", shell_quoted(LANCER_BINARY_DIR), "--prefix", shell_quoted(prefix)});
    ASSERT_EQ(install.exit_code, 0) << install.output;
    for (const char* installed :
         {"bin/lancer", "lib/liblancer.so", "lib/lancer/plugins/raycast.so", "lib/lancer/plugins/depth.so",
          "include/lancer/integrator.h", "include/lancer/scene_graph.h", "lib/cmake/lancer/lancerConfig.cmake",
          "lib/cmake/lancer/lancerConfigVersion.cmake", "lib/cmake/lancer/lancerTargets.cmake",
          "lib/cmake/lancer/LancerPlugin.cmake"}) {
        EXPECT_TRUE(fs::exists(prefix / installed)) << installed;
    }
    if (fs::exists(source_path("include/colors.inc"))) {
        EXPECT_TRUE(fs::exists(prefix / "share/lancer/include/colors.inc"));
    }

    // 2. Configure and build the sample plugin against the installed package only.
    const ShellResult configure =
        run_shell({shell_quoted(cmake), "-S", shell_quoted(source_path("tests/out_of_tree_plugin")), "-B",
                   shell_quoted(plugin_build), "-G", shell_quoted(LANCER_CMAKE_GENERATOR), "-DCMAKE_BUILD_TYPE=Release",
                   "-DCMAKE_PREFIX_PATH=" + shell_quoted(prefix)});
    ASSERT_EQ(configure.exit_code, 0) << configure.output;
    const ShellResult build = run_shell({shell_quoted(cmake), "--build", shell_quoted(plugin_build), "-j", "2"});
    ASSERT_EQ(build.exit_code, 0) << build.output;
    ASSERT_TRUE(fs::exists(plugin_build / "silhouette.so")) << build.output;

    // 3. Render with the installed lancer: the new plugin through LANCER_PLUGIN_PATH.
    const fs::path scene = work / "sphere.pov";
    std::ofstream(scene) << "camera { location <0, 0, -5> look_at <0, 0, 0> angle 40 }\n"
                            "light_source { <5, 5, -5> color rgb <1, 1, 1> }\n"
                            "sphere { <0, 0, 0>, 1 pigment { color rgb <1, 0, 0> } }\n";
    const fs::path image = work / "sphere.exr";
    const ShellResult render = run_shell(
        {"LANCER_PLUGIN_PATH=" + shell_quoted(plugin_build), shell_quoted(prefix / "bin/lancer"), "render",
         shell_quoted(scene), "-i silhouette -p level=0.25 --width 32 --height 24 --quiet -o", shell_quoted(image)});
    ASSERT_EQ(render.exit_code, 0) << render.output;

    auto input = OIIO::ImageInput::open(image.string());
    ASSERT_TRUE(input) << OIIO::geterror();
    const OIIO::ImageSpec& spec = input->spec();
    ASSERT_EQ(spec.width, 32);
    ASSERT_EQ(spec.height, 24);
    std::vector<float> pixels(std::size_t(spec.width) * spec.height * spec.nchannels);
    ASSERT_TRUE(input->read_image(0, 0, 0, spec.nchannels, OIIO::TypeDesc::FLOAT, pixels.data()));
    const auto channel = [&](int x, int y, int c) {
        return pixels[(std::size_t(y) * spec.width + x) * spec.nchannels + c];
    };
    // The sphere fills the centre with the plugin's level; the corner is background (black).
    EXPECT_NEAR(channel(16, 12, 0), 0.25f, 1e-3f);
    EXPECT_NEAR(channel(16, 12, 1), 0.25f, 1e-3f);
    EXPECT_NEAR(channel(0, 0, 0), 0.0f, 1e-6f);

    // `lancer plugins` lists it with its parameter, beside the built-in ones.
    const ShellResult listing =
        run_shell({"LANCER_PLUGIN_PATH=" + shell_quoted(plugin_build), shell_quoted(prefix / "bin/lancer"), "plugins"});
    EXPECT_EQ(listing.exit_code, 0) << listing.output;
    EXPECT_NE(listing.output.find("silhouette"), std::string::npos) << listing.output;
    EXPECT_NE(listing.output.find("level"), std::string::npos) << listing.output;
    EXPECT_NE(listing.output.find((prefix / "lib/lancer/plugins/raycast.so").string()), std::string::npos)
        << listing.output;
}

}  // namespace
}  // namespace lancer::test
