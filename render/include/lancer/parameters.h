// Integrator parameters: declared by the plugin, given by the scene's
// render_settings and the command line (-p key=value), read with typed
// getters. A parameter the plugin does not declare is an error at its source.
#pragma once

#include <cstdint>
#include <map>
#include <string>

namespace lancer {

enum class ParameterType { Int, Float, Bool, String };

// "int", "float", "bool", "string": as docs and messages name them.
const char* parameter_type_name(ParameterType type);

struct ParameterDecl {
    const char* name;
    ParameterType type;
    const char* default_value;  // as text, parsed with the declared type
    const char* meaning;        // one line for `lancer plugins` and the docs
};

// Values already validated against the declarations by the host: every
// name is declared and every value parses as its type.
class ParameterSet {
  public:
    void set(const std::string& name, const std::string& value) { m_values[name] = value; }
    bool has(const std::string& name) const { return m_values.count(name) != 0; }

    std::int64_t get_int(const std::string& name, std::int64_t fallback) const;
    double get_float(const std::string& name, double fallback) const;
    bool get_bool(const std::string& name, bool fallback) const;
    std::string get_string(const std::string& name, const std::string& fallback) const;

    const std::map<std::string, std::string>& values() const { return m_values; }

  private:
    std::map<std::string, std::string> m_values;
};

}  // namespace lancer
