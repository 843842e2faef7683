// Each `lancer` subcommand lives in its own file and registers itself here.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace lancer::app {

struct Command {
    CLI::App* cli = nullptr;
    std::function<int()> run;  // exit status: 0 ok, 1 bad input, 2 usage
};

Command add_check_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_plugins_command(CLI::App& app);
Command add_trade_command(CLI::App& app);

}  // namespace lancer::app
