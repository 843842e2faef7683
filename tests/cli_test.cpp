// The command line's own contract: version, usage errors.
#include <gtest/gtest.h>

#include "run_command.h"

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

}  // namespace lancer::test
