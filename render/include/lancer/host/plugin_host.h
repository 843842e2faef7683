// Finding and loading integrator plugins. Search order: each folder of
// LANCER_PLUGIN_PATH (colon-separated), then lancer/plugins beside the
// directory holding liblancer.so (the build tree and the install prefix
// share that layout).
#pragma once

#include <map>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "lancer/integrator.h"
#include "lancer/scene_graph.h"

namespace lancer {

class PluginError : public std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A loaded plugin; the library stays loaded while any copy lives.
struct Plugin {
    std::shared_ptr<void> library;  // dlopen handle
    const IntegratorDescriptor* descriptor = nullptr;
    std::string path;
};

std::vector<std::string> plugin_search_path();
// Throws PluginError naming the file (or the folders searched) and dlerror().
Plugin load_plugin(const std::string& name);
// Every loadable plugin in the search path; unloadable files are reported in
// `problems` instead of aborting the listing.
std::vector<Plugin> discover_plugins(std::vector<std::string>* problems = nullptr);

// Checks and merges parameters: the scene's render_settings first, then the
// command line's key=value pairs. Throws SceneError at the scene parameter's
// location, or PluginError naming a command-line parameter, for an
// undeclared name or a value that does not parse as the declared type.
ParameterSet resolve_parameters(const IntegratorDescriptor& descriptor,
                                const std::map<std::string, sg::ParameterValue>& from_scene,
                                const std::vector<std::string>& from_command_line);

}  // namespace lancer
