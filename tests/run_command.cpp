#include "run_command.h"

#include <sys/wait.h>
#include <array>
#include <cstdio>

namespace lancer::test {

std::string source_path(const std::string& relative) {
    return std::string(LANCER_SOURCE_DIR) + "/" + relative;
}

std::string binary_path(const std::string& relative) {
    return std::string(LANCER_BINARY_DIR) + "/" + relative;
}

CommandResult run_lancer(const std::string& arguments) {
    const std::string command =
        "cd '" + std::string(LANCER_SOURCE_DIR) + "' && '" + binary_path("bin/lancer") + "' " + arguments + " 2>&1";
    CommandResult result;
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) return result;
    std::array<char, 4096> buffer;
    std::size_t n;
    while ((n = fread(buffer.data(), 1, buffer.size(), pipe)) > 0) result.output.append(buffer.data(), n);
    const int status = pclose(pipe);
    result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    return result;
}

}  // namespace lancer::test
