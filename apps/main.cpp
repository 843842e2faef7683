// lancer: parse arguments, run one subcommand. Everything else is library code.
#include <cstdio>
#include <exception>
#include <string>
#include <vector>

#include "commands.h"
#include "lancer/parser.h"

int main(int argc, char** argv) {
    CLI::App app{"lancer: a ray tracer for hand-written POV-Ray-like scenes"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "lancer 0.1.0");
    // Usage errors look like every other error of lancer's.
    app.failure_message([](const CLI::App*, const CLI::Error& error) {
        return "lancer: error: " + std::string(error.what()) + "\nRun with --help for more information.\n";
    });
    std::vector<lancer::app::Command> commands = {
        lancer::app::add_check_command(app),   lancer::app::add_render_command(app),
        lancer::app::add_plugins_command(app), lancer::app::add_trade_command(app),
        lancer::app::add_live_command(app),
    };
    // POV-Ray's switches for alpha output, as its users type them: the
    // last of +UA and -UA decides, as in POV-Ray.
    std::vector<std::string> arguments;
    bool last_alpha_switch_seen = false;
    for (int i = argc - 1; i >= 1; --i) {
        const std::string argument = argv[i];
        const bool plus = argument == "+UA" || argument == "+ua", minus = argument == "-UA" || argument == "-ua";
        if (plus || minus) {
            if (!last_alpha_switch_seen && plus) arguments.push_back("--alpha");
            last_alpha_switch_seen = true;  // seen from the end: this one is the last
        } else {
            arguments.push_back(argument);
        }
    }
    try {
        app.parse(arguments);  // CLI11 takes them last first
    } catch (const CLI::ParseError& error) {
        // Printed by the failure message above, with the offending argument.
        int status = app.exit(error);
        return status == 0 ? 0 : 2;
    }
    try {
        for (const auto& command : commands) {
            if (command.cli->parsed()) return command.run();
        }
    } catch (const std::exception& error) {
        std::fprintf(stderr, "lancer: error: %s\n", lancer::escape_for_terminal(error.what()).c_str());
        return 1;
    }
    return 2;
}
