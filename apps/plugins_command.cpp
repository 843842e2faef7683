// `lancer plugins [NAME]`: every integrator plugin in the search path, with
// its description, file and parameters (name, type, default, meaning).
// Files that fail to load are listed as warnings with the reason, so a user
// whose plugin "does not show up" sees why.
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "commands.h"
#include "lancer/host/plugin_host.h"

namespace lancer::app {
namespace {

const char* type_name(ParameterType type) {
    switch (type) {
        case ParameterType::Int: return "int";
        case ParameterType::Float: return "float";
        case ParameterType::Bool: return "bool";
        case ParameterType::String: return "string";
    }
    return "?";
}

void print_plugin(const Plugin& plugin) {
    const IntegratorDescriptor& descriptor = *plugin.descriptor;
    std::printf("%s\n    %s\n    file: %s\n", descriptor.name, descriptor.description ? descriptor.description : "",
                plugin.path.c_str());
    if (descriptor.parameter_count == 0) {
        std::printf("    parameters: none\n");
        return;
    }
    // Columns sized to the longest entry so the table reads at a glance.
    std::size_t name_width = 4, default_width = 7;
    for (std::size_t i = 0; i < descriptor.parameter_count; ++i) {
        name_width = std::max(name_width, std::string(descriptor.parameters[i].name).size());
        default_width = std::max(default_width, std::string(descriptor.parameters[i].default_value).size());
    }
    std::printf("    parameters:\n      %-*s  %-6s  %-*s  %s\n", int(name_width), "name", "type", int(default_width),
                "default", "meaning");
    for (std::size_t i = 0; i < descriptor.parameter_count; ++i) {
        const ParameterDecl& decl = descriptor.parameters[i];
        std::printf("      %-*s  %-6s  %-*s  %s\n", int(name_width), decl.name, type_name(decl.type),
                    int(default_width), decl.default_value, decl.meaning ? decl.meaning : "");
    }
}

int run_plugins(const std::string& only) {
    std::vector<std::string> problems;
    const std::vector<Plugin> plugins = discover_plugins(&problems);
    const std::vector<std::string> folders = plugin_search_path();

    std::printf("integrator plugins (search path:");
    for (const auto& folder : folders) std::printf(" %s", folder.c_str());
    std::printf(")\n\n");

    bool found = false;
    for (const auto& plugin : plugins) {
        if (!only.empty() && only != plugin.descriptor->name) continue;
        print_plugin(plugin);
        std::printf("\n");
        found = true;
    }
    for (const auto& problem : problems) std::fprintf(stderr, "lancer: warning: %s\n", problem.c_str());
    if (!only.empty() && !found) {
        std::fprintf(stderr, "lancer: error: no integrator plugin '%s' in the search path\n", only.c_str());
        return 1;
    }
    if (plugins.empty()) {
        std::fprintf(stderr, "lancer: warning: no integrator plugins found (set LANCER_PLUGIN_PATH?)\n");
    }
    return 0;
}

}  // namespace

Command add_plugins_command(CLI::App& app) {
    auto only = std::make_shared<std::string>();
    CLI::App* plugins =
        app.add_subcommand("plugins", "List integrator plugins with their descriptions and parameters");
    plugins->add_option("name", *only, "Show only this plugin");

    Command command;
    command.cli = plugins;
    command.run = [only] { return run_plugins(*only); };
    return command;
}

}  // namespace lancer::app
