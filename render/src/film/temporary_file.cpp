#include "lancer/host/temporary_file.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <string>

namespace lancer {
namespace fs = std::filesystem;

namespace {

std::string temporary_prefix(const fs::path& target) {
    return "." + target.stem().string() + ".tmp";
}

}  // namespace

fs::path temporary_path_for(const fs::path& target) {
    static std::atomic<unsigned> counter{0};
    return target.parent_path() / (temporary_prefix(target) + std::to_string(::getpid()) + "-" +
                                   std::to_string(counter++) + target.extension().string());
}

int remove_stale_temporaries(const fs::path& target) {
    const std::string prefix = temporary_prefix(target);
    const std::string extension = target.extension().string();
    const fs::path folder = target.parent_path().empty() ? fs::path(".") : target.parent_path();
    int removed = 0;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.size() <= prefix.size() + extension.size() || name.compare(0, prefix.size(), prefix) != 0 ||
            name.compare(name.size() - extension.size(), extension.size(), extension) != 0)
            continue;
        // <pid>-<n> between the prefix and the extension, digits only.
        const std::string middle = name.substr(prefix.size(), name.size() - prefix.size() - extension.size());
        const std::size_t dash = middle.find('-');
        if (dash == 0 || dash == std::string::npos || dash > 9 ||
            middle.find_first_not_of("0123456789-") != std::string::npos)
            continue;
        const long pid = std::stol(middle.substr(0, dash));
        if (pid == ::getpid()) continue;
        if (::kill(pid_t(pid), 0) == 0 || errno != ESRCH) continue;  // still running, or not ours to judge
        std::error_code removing;
        if (fs::remove(it->path(), removing)) ++removed;
    }
    return removed;
}

}  // namespace lancer
