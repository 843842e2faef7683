// `lancer check SCENE`: parse, evaluate, summarise.
#include "commands.h"

namespace lancer::app {

Command add_check_command(CLI::App& app) {
    Command command;
    command.cli = app.add_subcommand("check", "Parse and evaluate a scene, print a summary");
    command.run = [] { return 1; };  // TODO(parser): implemented with the front end
    return command;
}

}  // namespace lancer::app
