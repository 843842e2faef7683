// `lancer plugins`.
#include "commands.h"

namespace lancer::app {

Command add_plugins_command(CLI::App& app) {
    Command command;
    command.cli = app.add_subcommand("plugins", "plugins");
    command.run = [] { return 1; };  // TODO(host): implemented with the plugin host
    return command;
}

}  // namespace lancer::app
