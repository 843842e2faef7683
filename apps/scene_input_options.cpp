#include "scene_input_options.h"

#include <charconv>
#include <cmath>

namespace lancer::app {

void add_scene_input_options(CLI::App& command, SceneInputOptions& options) {
    command
        .add_option("-I,--include-path", options.include_path,
                    "Folder searched for #include files (repeatable); searched before LANCER_INCLUDE_PATH")
        ->take_last()
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    command
        .add_option("-D,--declare", options.declarations,
                    "Declare Name=value before the scene is read (a float, or a \"string\"; repeatable), as "
                    "POV-Ray's Declare=")
        ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll);
    command
        .add_option("--language-version", options.language_version,
                    "POV-Ray language version of the scene until its first #version, as POV-Ray's Version= "
                    "(+MV). Without it, a scene with no #version is read as 3.62, as POV-Ray 3.7 does: no gamma "
                    "correction unless it sets assumed_gamma")
        ->check(CLI::Range(1.0, 99.99));
}

bool apply_scene_input_options(const SceneInputOptions& options, ParseOptions& parse, std::string& error) {
    std::vector<std::string> folders = options.include_path;
    folders.insert(folders.end(), parse.include_path.begin(), parse.include_path.end());
    parse.include_path = std::move(folders);
    if (options.language_version) parse.language_version = options.language_version;
    for (const std::string& text : options.declarations) {
        const std::size_t equals = text.find('=');
        CommandLineDeclaration declaration;
        declaration.name = text.substr(0, equals);
        const std::string value = equals == std::string::npos ? std::string() : text.substr(equals + 1);
        double number = 0.0;
        const auto [end, failure] = std::from_chars(value.data(), value.data() + value.size(), number);
        if (equals != std::string::npos && failure == std::errc() && end == value.data() + value.size() &&
            !value.empty() && std::isfinite(number)) {
            declaration.value = number;
        } else if (value.size() >= 2 && value.front() == '"' && value.back() == '"') {
            declaration.value = value.substr(1, value.size() - 2);
        } else {
            error = "-D expects Name=value with a finite number or a \"string\", got '" + text + "'";
            return false;
        }
        parse.declarations.push_back(std::move(declaration));
    }
    return true;
}

std::string describe_scene_input_options(const SceneInputOptions& options) {
    std::string text;
    for (const auto& folder : options.include_path) text += " -I " + folder;
    for (const auto& declaration : options.declarations) text += " -D " + declaration;
    if (options.language_version) text += " --language-version " + std::to_string(*options.language_version);
    return text;
}

}  // namespace lancer::app
