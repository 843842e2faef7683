// The command line's own contract: version, usage errors.
#include <gtest/gtest.h>

#include <fstream>

#include "run_command.h"
#include "temp_folder.h"

namespace lancer::test {

TEST(Cli, PrintsVersion) {
    const CommandResult result = run_lancer("--version");
    EXPECT_EQ(result.exit_code, 0);
    EXPECT_NE(result.output.find("lancer 0."), std::string::npos) << result.output;
}

TEST(Cli, UnknownSubcommandIsAUsageError) {
    const CommandResult result = run_lancer("frobnicate");
    EXPECT_EQ(result.exit_code, 2) << result.output;
}

// `check` says which integrator a render of the scene would use: the
// scene's own, or the default when it names none.
TEST(Cli, CheckNamesTheIntegratorARenderWouldUse) {
    const std::string scenes = std::string(LANCER_SOURCE_DIR) + "/scenes/";
    CommandResult result = run_lancer("check " + scenes + "language/meshes.pov");  // names none
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("integrator: whitted (the default: the scene names none)"), std::string::npos)
        << result.output;
    result = run_lancer("check " + scenes + "hard_shadows.pov");  // render_settings names shadow
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("integrator: shadow\n"), std::string::npos) << result.output;
}

// Noise and pattern functions called while parsing are the renderer's,
// with POV-Ray's values (povray 3.7 #debug prints 0.612779047 0.512266456).
TEST(Cli, FunctionsCalledWhileParsingUseTheRenderersNoiseAndPatterns) {
    TempFolder folder;
    const std::string scene = (folder.path() / "noise.pov").string();
    std::ofstream(scene) << "#include \"functions.inc\"\n#declare P = function { pattern { agate } }\n"
                            "#debug concat(str(f_noise3d(0.3, 0.6, 0.9), 0, 9), \" \", str(P(0.3, 0.6, 0.9), 0, 9))\n";
    const CommandResult result = run_lancer("check '" + scene + "'");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("#debug: 0.612779047 0.512266456"), std::string::npos) << result.output;
}

}  // namespace lancer::test
