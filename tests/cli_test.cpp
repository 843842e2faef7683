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

}  // namespace lancer::test
