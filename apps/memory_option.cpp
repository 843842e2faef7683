// `--max-memory SIZE`: the scene evaluation's memory budget
// (ParseOptions::max_memory_bytes) for render, check and trade.
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <string>

#include "commands.h"

namespace lancer::app {

namespace {

// "512M", "4G", "1.5GiB", "300000000": bytes, or -1 when it is none of them.
long long parse_size(const std::string& text) {
    const char* begin = text.c_str();
    char* end = nullptr;
    const double number = std::strtod(begin, &end);
    if (end == begin || !std::isfinite(number) || number <= 0.0) return -1;
    std::string unit;
    for (const char* c = end; *c; ++c)
        if (*c != ' ') unit += static_cast<char>(std::toupper(static_cast<unsigned char>(*c)));
    double scale = 1.0;
    if (!unit.empty() && unit.find_first_of("KMGT") == 0) {
        scale = std::pow(1024.0, std::string("KMGT").find(unit[0]) + 1.0);
        unit.erase(0, 1);
        if (unit == "IB" || unit == "B") unit.clear();
    } else if (unit == "B") {
        unit.clear();
    }
    const double bytes = number * scale;
    if (!unit.empty() || bytes < 1.0 || bytes > 9.0e18) return -1;
    return static_cast<long long>(bytes);
}

}  // namespace

CLI::Option* add_max_memory_option(CLI::App& command, long long& bytes) {
    return command.add_option_function<std::string>(
        "--max-memory",
        [&bytes](const std::string& text) {
            const long long value = parse_size(text);
            if (value < (1LL << 20))
                throw CLI::ValidationError("--max-memory",
                                           "expects a size of at least 1M, such as 512M or 8G, got '" + text + "'");
            bytes = value;
        },
        "Memory the scene's evaluation may use (arrays, objects, macros, strings), such as 512M or 8G; a scene "
        "that needs more stops with an error (default 4G)");
}

}  // namespace lancer::app
