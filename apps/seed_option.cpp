#include <charconv>
#include <string>

#include "commands.h"

namespace lancer::app {

CLI::Option* add_seed_option(CLI::App& command, std::uint64_t& seed) {
    return command.add_option_function<std::string>(
        "--seed",
        [&seed](const std::string& text) {
            std::uint64_t value = 0;
            const char* end = text.data() + text.size();
            const auto [stop, error] = std::from_chars(text.data(), end, value);
            if (text.empty() || error != std::errc() || stop != end)
                throw CLI::ValidationError("--seed",
                                           "expects a whole number from 0 to 18446744073709551615, got '" + text + "'");
            seed = value;
        },
        "Random seed (default: the scene's, else 0)");
}

}  // namespace lancer::app
