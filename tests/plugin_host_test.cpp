// The plugin host's contract: where plugins are found, every way loading can
// fail (each with a message naming the file and the reason), and how
// parameters from the scene and the command line are checked and merged.
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <memory>
#include <set>
#include <string>

#include <gtest/gtest.h>

#include "lancer/host/plugin_host.h"
#include "lancer/scene_error.h"

namespace lancer::test {
namespace {

// Message checks read better as "contains" than as equality.
#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

// Sets an environment variable for one test and restores it after.
class ScopedEnvironment {
  public:
    ScopedEnvironment(const char* name, const std::string& value) : m_name(name) {
        if (const char* previous = std::getenv(name)) m_previous = previous;
        m_had_previous = std::getenv(name) != nullptr;
        setenv(name, value.c_str(), 1);
    }
    ~ScopedEnvironment() {
        if (m_had_previous) {
            setenv(m_name, m_previous.c_str(), 1);
        } else {
            unsetenv(m_name);
        }
    }

  private:
    const char* m_name;
    std::string m_previous;
    bool m_had_previous = false;
};

std::string plugin_error_of(const std::string& name) {
    try {
        load_plugin(name);
    } catch (const PluginError& error) {
        return error.what();
    }
    return "(no error)";
}

bool ends_with(const std::string& text, const std::string& suffix) {
    return text.size() >= suffix.size() && text.compare(text.size() - suffix.size(), suffix.size(), suffix) == 0;
}

// ------------------------------------------------------------ search path

TEST(PluginSearchPath, EnvironmentFoldersComeFirstThenBesideTheLibrary) {
    ScopedEnvironment path("LANCER_PLUGIN_PATH", "/first::/second");
    const auto folders = plugin_search_path();
    ASSERT_EQ(folders.size(), 3u);
    EXPECT_EQ(folders[0], "/first");
    EXPECT_EQ(folders[1], "/second");
    EXPECT_TRUE(ends_with(folders[2], "lib/lancer/plugins")) << folders[2];
}

TEST(PluginSearchPath, FindsTheBuiltInPluginsInTheBuildTree) {
    const Plugin plugin = load_plugin("raycast");
    ASSERT_NE(plugin.descriptor, nullptr);
    EXPECT_STREQ(plugin.descriptor->name, "raycast");
    EXPECT_EQ(plugin.descriptor->abi_version, kPluginAbiVersion);
    EXPECT_TRUE(ends_with(plugin.path, "lancer/plugins/raycast.so")) << plugin.path;
    EXPECT_NE(plugin.library, nullptr);
}

TEST(PluginSearchPath, DiscoversEveryBuiltInPlugin) {
    std::vector<std::string> problems;
    const auto plugins = discover_plugins(&problems);
    std::set<std::string> names;
    for (const auto& plugin : plugins) names.insert(plugin.descriptor->name);
    for (const char* expected : {"raycast", "normal", "albedo", "depth"}) {
        EXPECT_TRUE(names.count(expected)) << expected;
    }
}

TEST(PluginSearchPath, AnEarlierFolderShadowsALaterOne) {
    // The fixture folder has no raycast.so, so the built-in one still loads;
    // and a path with '/' loads that file directly.
    ScopedEnvironment path("LANCER_PLUGIN_PATH", LANCER_PLUGIN_FIXTURE_DIR);
    EXPECT_TRUE(ends_with(load_plugin("raycast").path, "lib/lancer/plugins/raycast.so"));
    const std::string builtin = load_plugin("raycast").path;
    EXPECT_EQ(load_plugin(builtin).path, builtin);
}

// ---------------------------------------------------------- load failures

TEST(PluginLoading, MissingPluginNamesTheFoldersSearchedAndWhatIsAvailable) {
    ScopedEnvironment path("LANCER_PLUGIN_PATH", "/nonexistent/lancer-plugins");
    const std::string message = plugin_error_of("no_such_integrator");
    EXPECT_CONTAINS(message, "no integrator plugin 'no_such_integrator'");
    EXPECT_CONTAINS(message, "no_such_integrator.so");
    EXPECT_CONTAINS(message, "/nonexistent/lancer-plugins");
    EXPECT_CONTAINS(message, "lib/lancer/plugins");
    EXPECT_CONTAINS(message, "raycast");  // the available list
}

TEST(PluginLoading, MissingFileGivenByPath) {
    EXPECT_CONTAINS(plugin_error_of("/nonexistent/x.so"), "'/nonexistent/x.so' does not exist");
}

TEST(PluginLoading, FileWithoutTheDescriptorSymbolQuotesDlerror) {
    ScopedEnvironment path("LANCER_PLUGIN_PATH", LANCER_PLUGIN_FIXTURE_DIR);
    const std::string message = plugin_error_of("no_symbol");
    EXPECT_CONTAINS(message, std::string(LANCER_PLUGIN_FIXTURE_DIR) + "/no_symbol.so");
    EXPECT_CONTAINS(message, "not a lancer integrator plugin");
    EXPECT_CONTAINS(message, "lancer_integrator_descriptor");
    EXPECT_CONTAINS(message, "undefined symbol");  // dlerror()'s own words
}

TEST(PluginLoading, OtherAbiVersionIsRefusedWithBothNumbers) {
    ScopedEnvironment path("LANCER_PLUGIN_PATH", LANCER_PLUGIN_FIXTURE_DIR);
    const std::string message = plugin_error_of("wrong_abi");
    EXPECT_CONTAINS(message, "wrong_abi.so");
    EXPECT_CONTAINS(message, "ABI version " + std::to_string(kPluginAbiVersion + 1000));
    EXPECT_CONTAINS(message, "this lancer uses ABI version " + std::to_string(kPluginAbiVersion));
    EXPECT_CONTAINS(message, "rebuild");
}

TEST(PluginLoading, NameMustMatchTheFile) {
    ScopedEnvironment path("LANCER_PLUGIN_PATH", LANCER_PLUGIN_FIXTURE_DIR);
    const std::string message = plugin_error_of("misnamed");
    EXPECT_CONTAINS(message, "misnamed.so");
    EXPECT_CONTAINS(message, "'something_else'");
}

TEST(PluginLoading, TextFileIsNotALibrary) {
    const std::string path = std::string(LANCER_BINARY_DIR) + "/tests/not_a_library.so";
    FILE* file = std::fopen(path.c_str(), "w");
    ASSERT_NE(file, nullptr);
    std::fputs("this is text, not ELF, and long enough to hold an ELF header's sixty-four bytes\n", file);
    std::fclose(file);
    const std::string message = plugin_error_of(path);
    EXPECT_CONTAINS(message, "cannot load plugin file '" + path + "'");
    EXPECT_CONTAINS(message, "not an ELF shared library");
    std::remove(path.c_str());
}

// A plugin still being copied onto the search path: dlopen of a cut file
// faults (SIGBUS) when the loader touches a page past its end, so every
// cut is refused with a message before dlopen sees it.
TEST(PluginLoading, CutShortFileIsRefusedBeforeLoading) {
    const Plugin whole = load_plugin("whitted");
    std::ifstream in(whole.path, std::ios::binary);
    const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    ASSERT_GT(bytes.size(), 1000u);
    const std::string path = std::string(LANCER_BINARY_DIR) + "/tests/cut_short.so";
    for (std::size_t length :
         {std::size_t(0), std::size_t(63), std::size_t(64), std::size_t(4096), bytes.size() / 2, bytes.size() - 1}) {
        std::ofstream(path, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(length));
        const std::string message = plugin_error_of(path);
        EXPECT_CONTAINS(message, "cannot load plugin file '" + path + "'");
        EXPECT_TRUE(message.find("cut short") != std::string::npos || message.find("too short") != std::string::npos)
            << length << ": " << message;
    }
    std::remove(path.c_str());
}

TEST(PluginLoading, DiscoveryReportsBrokenFilesWithoutStopping) {
    ScopedEnvironment path("LANCER_PLUGIN_PATH", LANCER_PLUGIN_FIXTURE_DIR);
    std::vector<std::string> problems;
    const auto plugins = discover_plugins(&problems);
    EXPECT_EQ(problems.size(), 3u);
    std::string all;
    for (const auto& problem : problems) all += problem + "\n";
    EXPECT_CONTAINS(all, "no_symbol.so");
    EXPECT_CONTAINS(all, "wrong_abi.so");
    EXPECT_CONTAINS(all, "misnamed.so");
    bool found_raycast = false;
    for (const auto& plugin : plugins) found_raycast |= std::string(plugin.descriptor->name) == "raycast";
    EXPECT_TRUE(found_raycast);
}

// ------------------------------------------------------------- parameters

const ParameterDecl kTestParameters[] = {
    {"samples", ParameterType::Int, "8", "how many"},
    {"radius", ParameterType::Float, "0.5", "how far"},
    {"shadows", ParameterType::Bool, "true", "whether"},
    {"mode", ParameterType::String, "fast", "which"},
};
const IntegratorDescriptor kTestDescriptor = {
    kPluginAbiVersion, "tester", "for tests", kTestParameters, std::size(kTestParameters), nullptr,
};

sg::ParameterValue scene_value(std::variant<double, sg::Vec3, std::string, bool> value, int line = 3, int column = 5) {
    sg::ParameterValue parameter;
    parameter.value = std::move(value);
    parameter.location.file = std::make_shared<const std::string>("scenes/test.pov");
    parameter.location.line = line;
    parameter.location.column = column;
    return parameter;
}

TEST(PluginParameters, DefaultsComeFromTheDeclarations) {
    const ParameterSet parameters = resolve_parameters(kTestDescriptor, {}, {});
    EXPECT_EQ(parameters.get_int("samples", -1), 8);
    EXPECT_DOUBLE_EQ(parameters.get_float("radius", -1.0), 0.5);
    EXPECT_TRUE(parameters.get_bool("shadows", false));
    EXPECT_EQ(parameters.get_string("mode", ""), "fast");
}

TEST(PluginParameters, CommandLineOverridesSceneOverridesDefault) {
    const std::map<std::string, sg::ParameterValue> scene = {
        {"samples", scene_value(16.0)},
        {"radius", scene_value(2.0)},
        {"shadows", scene_value(false)},
        {"mode", scene_value(std::string("slow"))},
    };
    const ParameterSet parameters = resolve_parameters(kTestDescriptor, scene, {"samples=32", "shadows=on"});
    EXPECT_EQ(parameters.get_int("samples", -1), 32);
    EXPECT_DOUBLE_EQ(parameters.get_float("radius", -1.0), 2.0);
    EXPECT_TRUE(parameters.get_bool("shadows", false));
    EXPECT_EQ(parameters.get_string("mode", ""), "slow");
}

TEST(PluginParameters, PovStyleOnOffNumbersAreBooleans) {
    const ParameterSet parameters = resolve_parameters(kTestDescriptor, {{"shadows", scene_value(0.0)}}, {});
    EXPECT_FALSE(parameters.get_bool("shadows", true));
}

TEST(PluginParameters, UndeclaredSceneParameterIsASceneErrorAtItsLocation) {
    try {
        resolve_parameters(kTestDescriptor, {{"sampels", scene_value(4.0, 7, 12)}}, {});
        FAIL() << "expected SceneError";
    } catch (const SceneError& error) {
        ASSERT_TRUE(error.location().file);
        EXPECT_EQ(*error.location().file, "scenes/test.pov");
        EXPECT_EQ(error.location().line, 7);
        EXPECT_EQ(error.location().column, 12);
        const std::string message = error.what();
        EXPECT_CONTAINS(message, "integrator 'tester' has no parameter 'sampels'");
        EXPECT_CONTAINS(message, "samples (int)");
        EXPECT_CONTAINS(message, "mode (string)");
    }
}

TEST(PluginParameters, UndeclaredCommandLineParameterNamesTheArgument) {
    try {
        resolve_parameters(kTestDescriptor, {}, {"sampels=4"});
        FAIL() << "expected PluginError";
    } catch (const PluginError& error) {
        const std::string message = error.what();
        EXPECT_CONTAINS(message, "-p sampels=4");
        EXPECT_CONTAINS(message, "no parameter 'sampels'");
        EXPECT_CONTAINS(message, "samples (int), radius (float), shadows (bool), mode (string)");
    }
}

TEST(PluginParameters, CommandLineValueMustParseAsTheDeclaredType) {
    const auto message_for = [](const std::string& assignment) -> std::string {
        try {
            resolve_parameters(kTestDescriptor, {}, {assignment});
        } catch (const PluginError& error) {
            return error.what();
        }
        return "(accepted)";
    };
    EXPECT_CONTAINS(message_for("samples=many"), "expects an integer, got 'many'");
    EXPECT_CONTAINS(message_for("samples=2.5"), "expects an integer");
    EXPECT_CONTAINS(message_for("radius=1.5cm"), "expects a finite number");
    EXPECT_CONTAINS(message_for("shadows=maybe"), "expects a boolean");
    EXPECT_CONTAINS(message_for("samples"), "expected key=value");
    EXPECT_EQ(message_for("radius=+1e-3"), "(accepted)");
    EXPECT_EQ(message_for("mode="), "(accepted)");  // an empty string is a string
}

TEST(PluginParameters, SceneValueOfTheWrongKindIsLocated) {
    const auto error_for = [](const char* name, sg::ParameterValue value) -> std::string {
        try {
            resolve_parameters(kTestDescriptor, {{name, std::move(value)}}, {});
        } catch (const SceneError& error) {
            EXPECT_EQ(error.location().line, 9);
            return error.what();
        }
        return "(accepted)";
    };
    EXPECT_CONTAINS(error_for("samples", scene_value(2.5, 9)), "expects an integer, got 2.5");
    EXPECT_CONTAINS(error_for("radius", scene_value(sg::Vec3(1.0), 9)), "expects a finite number, got a vector");
    EXPECT_CONTAINS(error_for("shadows", scene_value(3.0, 9)), "expects a boolean");
    EXPECT_CONTAINS(error_for("samples", scene_value(std::string("ten"), 9)), "got \"ten\"");
}

TEST(PluginParameters, GettersParseTheirType) {
    ParameterSet parameters;
    parameters.set("n", "-12");
    parameters.set("x", "1e-3");
    parameters.set("b", "Off");
    EXPECT_EQ(parameters.get_int("n", 0), -12);
    EXPECT_DOUBLE_EQ(parameters.get_float("x", 0.0), 1e-3);
    EXPECT_FALSE(parameters.get_bool("b", true));
    EXPECT_EQ(parameters.get_int("absent", 5), 5);
    EXPECT_THROW(parameters.get_int("x", 0), std::invalid_argument);
}

TEST(PluginParameters, BuiltInPluginsDeclareParsableDefaults) {
    for (const char* name : {"raycast", "normal", "albedo", "depth"}) {
        const Plugin plugin = load_plugin(name);
        const ParameterSet parameters = resolve_parameters(*plugin.descriptor, {}, {});
        EXPECT_NE(plugin.descriptor->create(parameters), nullptr) << name;
    }
}

TEST(PluginParameters, DepthRejectsANegativeMaxDistance) {
    const Plugin plugin = load_plugin("depth");
    const ParameterSet parameters = resolve_parameters(*plugin.descriptor, {}, {"max_distance=-1"});
    EXPECT_THROW(plugin.descriptor->create(parameters), std::invalid_argument);
}

}  // namespace
}  // namespace lancer::test
