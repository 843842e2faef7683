// Each `lancer` subcommand lives in its own file and registers itself here.
#pragma once

#include <cstdint>
#include <functional>

#include <CLI/CLI.hpp>

namespace lancer::app {

struct Command {
    CLI::App* cli = nullptr;
    std::function<int()> run;  // exit status: 0 ok, 1 bad input, 2 usage
};

// `--seed S` for the commands that render: a whole number that fits 64
// bits, checked as such (a plain unsigned option would take -1 or 2^64 and
// wrap them).
CLI::Option* add_seed_option(CLI::App& command, std::uint64_t& seed);
// `--max-memory SIZE` (512M, 8G, bytes) for the commands that parse a
// scene: ParseOptions::max_memory_bytes.
CLI::Option* add_max_memory_option(CLI::App& command, long long& bytes);

Command add_check_command(CLI::App& app);
Command add_render_command(CLI::App& app);
Command add_plugins_command(CLI::App& app);
Command add_trade_command(CLI::App& app);
Command add_live_command(CLI::App& app);

}  // namespace lancer::app
