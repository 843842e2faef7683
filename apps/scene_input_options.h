// What every command that reads a scene takes about its input: include
// folders (-I, POV-Ray's Library_Path), declarations (-D Name=value,
// POV-Ray's Declare=Name=value) and the language version a scene without
// #version is read as (--language-version, POV-Ray's Version= / +MV), on
// render, check and trade alike.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "lancer/parser.h"

namespace lancer::app {

struct SceneInputOptions {
    std::vector<std::string> include_path;
    std::vector<std::string> declarations;  // "Name=value" as given
    std::optional<double> language_version;
};

void add_scene_input_options(CLI::App& command, SceneInputOptions& options);

// Puts them into `parse`: -I folders before the default include path, and
// the declarations (a float, or a string in double quotes), the language
// version. False with `error` set for a -D that is not Name=value.
bool apply_scene_input_options(const SceneInputOptions& options, ParseOptions& parse, std::string& error);

// The options as text, for keys that must change when they do (trade's
// reference cache).
std::string describe_scene_input_options(const SceneInputOptions& options);

}  // namespace lancer::app
