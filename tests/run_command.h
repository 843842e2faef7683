// Runs the built `lancer` binary for integration tests and captures its
// exit status and output.
#pragma once

#include <string>

namespace lancer::test {

struct CommandResult {
    int exit_code = -1;
    std::string output;  // stdout and stderr, interleaved
};

// `arguments` is appended to the path of the built lancer binary and run by
// the shell from the source tree (so scenes/... paths work).
CommandResult run_lancer(const std::string& arguments);

std::string source_path(const std::string& relative);  // LANCER_SOURCE_DIR/relative
std::string binary_path(const std::string& relative);  // LANCER_BINARY_DIR/relative

}  // namespace lancer::test
