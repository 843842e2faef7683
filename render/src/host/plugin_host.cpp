// Finding, loading and checking integrator plugins (plugin_host.h).
//
// A plugin is `<name>.so` in one of the search folders. Loading it is three
// checks, each with its own message because each has its own fix: the file
// must load (dlerror says why not), must export lancer_integrator_descriptor
// (else it is not a lancer plugin), and must have been built for this ABI
// version (else it must be rebuilt). Parameters are checked against the
// plugin's declarations before the plugin ever sees them.
#include "lancer/host/plugin_host.h"

#include <dlfcn.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "host/library_folder.h"
#include "lancer/scene_error.h"

#ifndef LANCER_PLUGIN_RELATIVE_DIR
#define LANCER_PLUGIN_RELATIVE_DIR "lancer/plugins"
#endif

namespace lancer {
namespace {

namespace fs = std::filesystem;

constexpr const char* kDescriptorSymbol = "lancer_integrator_descriptor";
constexpr const char* kPluginExtension = ".so";

std::string dl_error_text() {
    const char* error = dlerror();
    return error ? error : "no detail from dlerror()";
}

std::string join(const std::vector<std::string>& items, const char* separator) {
    std::string joined;
    for (const auto& item : items) {
        if (!joined.empty()) joined += separator;
        joined += item;
    }
    return joined;
}

const char* expected_text(ParameterType type);
bool parses_as(const ParameterDecl& decl, const std::string& text);

// Why the file is not a whole shared library, or empty. dlopen maps the
// segments its headers name; a file cut short (one still being copied)
// then faults with SIGBUS when the loader touches a page past its end, so
// every header and loaded segment must lie inside the file first.
std::string incomplete_library(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::error_code error;
    const std::uintmax_t size = fs::file_size(path, error);
    if (!in || error) return "cannot read it";
    unsigned char header[64] = {};
    if (size < sizeof header || !in.read(reinterpret_cast<char*>(header), sizeof header))
        return "it is too short to be a shared library";
    if (header[0] != 0x7f || header[1] != 'E' || header[2] != 'L' || header[3] != 'F')
        return "it is not an ELF shared library";
    if (header[4] != 2 || header[5] != 1) return {};  // not 64-bit little-endian: dlopen explains
    auto read = [](const unsigned char* at, int bytes) {
        std::uint64_t value = 0;
        for (int i = bytes - 1; i >= 0; --i) value = value << 8 | at[i];
        return value;
    };
    const std::uint64_t program_offset = read(header + 32, 8), section_offset = read(header + 40, 8);
    const std::uint64_t program_entry = read(header + 54, 2), program_count = read(header + 56, 2);
    const std::uint64_t section_entry = read(header + 58, 2), section_count = read(header + 60, 2);
    auto inside = [size](std::uint64_t offset, std::uint64_t length) {
        return offset <= size && length <= size - offset;
    };
    const std::string truncated = "it is cut short (" + std::to_string(size) + " bytes; is it still being written?)";
    if (!inside(program_offset, program_entry * program_count) ||
        !inside(section_offset, section_entry * section_count))
        return truncated;
    if (program_entry < 56) return program_count == 0 ? std::string() : "its program headers are malformed";
    for (std::uint64_t i = 0; i < program_count; ++i) {
        unsigned char entry[56];
        in.seekg(std::streamoff(program_offset + i * program_entry));
        if (!in.read(reinterpret_cast<char*>(entry), sizeof entry)) return truncated;
        constexpr std::uint64_t kLoadable = 1;  // PT_LOAD
        if (read(entry, 4) == kLoadable && !inside(read(entry + 8, 8), read(entry + 32, 8))) return truncated;
    }
    return {};
}

// Opens one file and runs every check; `expected_name` empty means any name.
Plugin open_plugin_file(const std::string& path, const std::string& expected_name) {
    if (const std::string why = incomplete_library(path); !why.empty())
        throw PluginError("cannot load plugin file '" + path + "': " + why);
    // RTLD_NOW: an unresolved symbol is reported here, not mid-render.
    // RTLD_LOCAL: two plugins may define the same internal names.
    dlerror();
    void* handle = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
    if (handle == nullptr) {
        throw PluginError("cannot load plugin file '" + path + "': " + dl_error_text());
    }
    std::shared_ptr<void> library(handle, [](void* h) { dlclose(h); });

    dlerror();
    void* symbol = dlsym(handle, kDescriptorSymbol);
    if (symbol == nullptr) {
        throw PluginError("'" + path + "' is not a lancer integrator plugin: it does not export '" + kDescriptorSymbol +
                          "' (" + dl_error_text() +
                          "); end the plugin's .cpp with LANCER_EXPORT_INTEGRATOR(descriptor)");
    }
    using DescriptorFunction = const IntegratorDescriptor* (*)();
    const auto descriptor_function = reinterpret_cast<DescriptorFunction>(symbol);
    const IntegratorDescriptor* descriptor = descriptor_function();
    if (descriptor == nullptr) {
        throw PluginError("plugin '" + path + "': " + kDescriptorSymbol + "() returned null");
    }
    // abi_version is the descriptor's first field in every ABI version, so it
    // is safe to read before anything else is trusted.
    if (descriptor->abi_version != kPluginAbiVersion) {
        throw PluginError("plugin '" + path + "' was built for plugin ABI version " +
                          std::to_string(descriptor->abi_version) + ", but this lancer uses ABI version " +
                          std::to_string(kPluginAbiVersion) + "; rebuild the plugin against this lancer's headers");
    }
    if (descriptor->name == nullptr || descriptor->create == nullptr ||
        (descriptor->parameter_count > 0 && descriptor->parameters == nullptr)) {
        throw PluginError("plugin '" + path +
                          "' has an incomplete descriptor (name, create and parameters are required)");
    }
    if (!expected_name.empty() && expected_name != descriptor->name) {
        throw PluginError("plugin '" + path + "' calls itself '" + descriptor->name +
                          "'; a plugin's name must match its file name (" + expected_name + kPluginExtension + ")");
    }
    // A default that does not parse is the plugin author's bug; say so now
    // rather than when a user's render reads it.
    for (std::size_t i = 0; i < descriptor->parameter_count; ++i) {
        const ParameterDecl& decl = descriptor->parameters[i];
        if (decl.name == nullptr || decl.default_value == nullptr) {
            throw PluginError("plugin '" + path + "': parameter " + std::to_string(i) + " has no name or no default");
        }
        if (!parses_as(decl, decl.default_value)) {
            throw PluginError("plugin '" + path + "': the default of parameter '" + decl.name + "' is '" +
                              decl.default_value + "', not " + expected_text(decl.type));
        }
    }

    Plugin plugin;
    plugin.library = std::move(library);
    plugin.descriptor = descriptor;
    plugin.path = path;
    return plugin;
}

// Names of the *.so files in the search path, first folder wins.
std::vector<std::string> available_plugin_names() {
    std::set<std::string> names;
    for (const auto& folder : plugin_search_path()) {
        std::error_code error;
        for (const auto& entry : fs::directory_iterator(folder, error)) {
            if (entry.path().extension() == kPluginExtension) names.insert(entry.path().stem().string());
        }
    }
    return {names.begin(), names.end()};
}

const ParameterDecl* find_declaration(const IntegratorDescriptor& descriptor, const std::string& name) {
    for (std::size_t i = 0; i < descriptor.parameter_count; ++i) {
        if (name == descriptor.parameters[i].name) return &descriptor.parameters[i];
    }
    return nullptr;
}

std::string declared_names(const IntegratorDescriptor& descriptor) {
    if (descriptor.parameter_count == 0) return "it declares no parameters";
    std::vector<std::string> names;
    for (std::size_t i = 0; i < descriptor.parameter_count; ++i) {
        names.push_back(std::string(descriptor.parameters[i].name) + " (" +
                        parameter_type_name(descriptor.parameters[i].type) + ")");
    }
    return "it declares: " + join(names, ", ");
}

const char* expected_text(ParameterType type) {
    switch (type) {
    case ParameterType::Int: return "an integer";
    case ParameterType::Float: return "a finite number";
    case ParameterType::Bool: return "a boolean (true/false, on/off, yes/no, 1/0)";
    case ParameterType::String: return "a string";
    }
    return "?";
}

bool parses_as(const ParameterDecl& decl, const std::string& text) {
    ParameterSet probe;
    probe.set(decl.name, text);
    try {
        switch (decl.type) {
        case ParameterType::Int: probe.get_int(decl.name, 0); break;
        case ParameterType::Float: probe.get_float(decl.name, 0.0); break;
        case ParameterType::Bool: probe.get_bool(decl.name, false); break;
        case ParameterType::String: break;
        }
    } catch (const std::invalid_argument&) {
        return false;
    }
    return true;
}

// Shortest text that reads back as the same double.
std::string number_text(double value) {
    char buffer[32];
    for (int precision = 6; precision <= 17; ++precision) {
        std::snprintf(buffer, sizeof buffer, "%.*g", precision, value);
        if (std::strtod(buffer, nullptr) == value) break;
    }
    return buffer;
}

// A scene value as text of the declared type. On a mismatch (a vector for a
// number, 2.5 for an integer...) returns false and describes the value in `got`.
bool scene_value_text(const ParameterDecl& decl, const sg::ParameterValue& value, std::string& text, std::string& got) {
    const auto& v = value.value;
    if (const auto* number = std::get_if<double>(&v)) {
        got = number_text(*number);
        switch (decl.type) {
        case ParameterType::Int:
            if (*number != std::floor(*number) || std::abs(*number) > 9.0e15) return false;
            text = std::to_string(std::int64_t(*number));
            return true;
        case ParameterType::Bool:
            // POV-Ray's on/off are the numbers 1 and 0.
            if (*number != 0.0 && *number != 1.0) return false;
            text = *number != 0.0 ? "true" : "false";
            return true;
        case ParameterType::Float:
        case ParameterType::String: text = got; return true;
        }
    }
    if (const auto* flag = std::get_if<bool>(&v)) {
        got = *flag ? "true" : "false";
        text = got;
        return decl.type == ParameterType::Bool || decl.type == ParameterType::String;
    }
    if (const auto* string = std::get_if<std::string>(&v)) {
        got = "\"" + *string + "\"";
        text = *string;
        return parses_as(decl, text);
    }
    got = "a vector";
    return false;
}

}  // namespace

std::vector<std::string> plugin_search_path() {
    std::vector<std::string> folders;
    if (const char* from_environment = std::getenv("LANCER_PLUGIN_PATH")) {
        std::stringstream stream(from_environment);
        std::string folder;
        while (std::getline(stream, folder, ':')) {
            if (!folder.empty()) folders.push_back(folder);
        }
    }
    const std::string library_folder = folder_of_liblancer();
    if (!library_folder.empty()) {
        folders.push_back((fs::path(library_folder) / LANCER_PLUGIN_RELATIVE_DIR).string());
    }
    return folders;
}

Plugin load_plugin(const std::string& name) {
    // A path (with a '/') names the file itself: handy for testing a build.
    if (name.find('/') != std::string::npos) {
        if (!fs::exists(name)) throw PluginError("plugin file '" + name + "' does not exist");
        return open_plugin_file(name, {});
    }
    const std::vector<std::string> folders = plugin_search_path();
    for (const auto& folder : folders) {
        const fs::path candidate = fs::path(folder) / (name + kPluginExtension);
        std::error_code error;
        if (fs::is_regular_file(candidate, error)) return open_plugin_file(candidate.string(), name);
    }
    const std::vector<std::string> available = available_plugin_names();
    throw PluginError("no integrator plugin '" + name + "': looked for " + name + kPluginExtension + " in " +
                      (folders.empty() ? std::string("(no folders)") : join(folders, ", ")) +
                      " (LANCER_PLUGIN_PATH adds folders); available: " +
                      (available.empty() ? std::string("none") : join(available, ", ")));
}

std::vector<Plugin> discover_plugins(std::vector<std::string>* problems) {
    std::vector<Plugin> plugins;
    std::set<std::string> seen;
    for (const auto& folder : plugin_search_path()) {
        std::error_code error;
        std::vector<fs::path> files;
        for (const auto& entry : fs::directory_iterator(folder, error)) {
            if (entry.path().extension() == kPluginExtension) files.push_back(entry.path());
        }
        std::sort(files.begin(), files.end());
        for (const auto& file : files) {
            const std::string name = file.stem().string();
            // An earlier folder shadows a later one, broken or not, exactly
            // as load_plugin would pick it.
            if (!seen.insert(name).second) continue;
            try {
                plugins.push_back(open_plugin_file(file.string(), name));
            } catch (const PluginError& failure) {
                if (problems) problems->push_back(failure.what());
            }
        }
    }
    return plugins;
}

ParameterSet resolve_parameters(const IntegratorDescriptor& descriptor,
                                const std::map<std::string, sg::ParameterValue>& from_scene,
                                const std::vector<std::string>& from_command_line) {
    const std::string integrator = std::string("integrator '") + descriptor.name + "'";
    ParameterSet parameters;
    // Declared defaults first, so a plugin can read every declared name.
    for (std::size_t i = 0; i < descriptor.parameter_count; ++i) {
        parameters.set(descriptor.parameters[i].name, descriptor.parameters[i].default_value);
    }

    // The scene's render_settings: errors point at the scene text.
    for (const auto& [name, value] : from_scene) {
        const ParameterDecl* decl = find_declaration(descriptor, name);
        if (decl == nullptr) {
            throw SceneError(value.location,
                             integrator + " has no parameter '" + name + "'; " + declared_names(descriptor));
        }
        std::string text, got;
        if (!scene_value_text(*decl, value, text, got)) {
            throw SceneError(value.location, "parameter '" + name + "' of " + integrator + " expects " +
                                                 expected_text(decl->type) + ", got " + got);
        }
        parameters.set(name, text);
    }

    // The command line overrides the scene.
    for (const auto& assignment : from_command_line) {
        const auto equals = assignment.find('=');
        if (equals == std::string::npos || equals == 0) {
            throw PluginError("-p " + assignment + ": expected key=value");
        }
        const std::string name = assignment.substr(0, equals);
        const std::string text = assignment.substr(equals + 1);
        const ParameterDecl* decl = find_declaration(descriptor, name);
        if (decl == nullptr) {
            throw PluginError("-p " + assignment + ": " + integrator + " has no parameter '" + name + "'; " +
                              declared_names(descriptor));
        }
        if (!parses_as(*decl, text)) {
            throw PluginError("-p " + assignment + ": parameter '" + name + "' of " + integrator + " expects " +
                              expected_text(decl->type) + ", got '" + text + "'");
        }
        parameters.set(name, text);
    }
    return parameters;
}

}  // namespace lancer
