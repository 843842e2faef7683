// Typed reads of integrator parameters. Values are kept as text (as the user
// wrote them on the command line, or as the host rendered a scene value) and
// parsed on each read; the host has already checked that every value parses
// as its declared type, so a getter throwing here means a plugin read a
// parameter with another type than it declared.
#include "lancer/parameters.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <stdexcept>
#include <string_view>
#include <system_error>

namespace lancer {
namespace {

// from_chars over the whole text: "12abc" or "" is not a number.
template <typename T>
bool parse_whole(std::string_view text, T& value) {
    // from_chars rejects a leading '+', which users do write ("+0.5").
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    const char* end = text.data() + text.size();
    const auto [stop, error] = std::from_chars(text.data(), end, value);
    return error == std::errc() && stop == end;
}

std::string lowercase(std::string_view text) {
    std::string result(text);
    std::transform(result.begin(), result.end(), result.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return result;
}

[[noreturn]] void throw_bad_value(const std::string& name, const std::string& text, const char* expected) {
    throw std::invalid_argument("parameter '" + name + "' = '" + text + "' is not " + expected);
}

}  // namespace

std::int64_t ParameterSet::get_int(const std::string& name, std::int64_t fallback) const {
    const auto found = m_values.find(name);
    if (found == m_values.end()) return fallback;
    std::int64_t value = 0;
    if (!parse_whole(found->second, value)) throw_bad_value(name, found->second, "an integer");
    return value;
}

double ParameterSet::get_float(const std::string& name, double fallback) const {
    const auto found = m_values.find(name);
    if (found == m_values.end()) return fallback;
    double value = 0.0;
    // nan and inf parse, but no integrator's setting means them.
    if (!parse_whole(found->second, value) || !std::isfinite(value))
        throw_bad_value(name, found->second, "a finite number");
    return value;
}

bool ParameterSet::get_bool(const std::string& name, bool fallback) const {
    const auto found = m_values.find(name);
    if (found == m_values.end()) return fallback;
    // POV-Ray spells booleans on/off and yes/no as well as true/false.
    const std::string text = lowercase(found->second);
    if (text == "true" || text == "on" || text == "yes" || text == "1") return true;
    if (text == "false" || text == "off" || text == "no" || text == "0") return false;
    throw_bad_value(name, found->second, "a boolean (true/false, on/off, yes/no, 1/0)");
}

std::string ParameterSet::get_string(const std::string& name, const std::string& fallback) const {
    const auto found = m_values.find(name);
    return found == m_values.end() ? fallback : found->second;
}

const char* parameter_type_name(ParameterType type) {
    switch (type) {
    case ParameterType::Int: return "int";
    case ParameterType::Float: return "float";
    case ParameterType::Bool: return "bool";
    case ParameterType::String: return "string";
    }
    return "?";
}

}  // namespace lancer
