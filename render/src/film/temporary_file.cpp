#include "lancer/host/temporary_file.h"

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cerrno>
#include <fstream>
#include <string>

namespace lancer {
namespace fs = std::filesystem;

namespace {

std::string temporary_prefix(const fs::path& target) {
    return "." + target.stem().string() + ".tmp";
}

// A process that has exited but that no one has reaped yet (its parent
// gone, in a container whose first process reaps no orphans) still answers
// kill(pid, 0); its open files are closed all the same.
bool is_running(long pid) {
    if (::kill(pid_t(pid), 0) != 0) return errno != ESRCH;  // EPERM: someone else's, not ours to judge
    std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
    std::string line;
    if (!std::getline(stat, line)) return true;
    // pid (comm) state ...: comm may itself hold ") ".
    const std::size_t end_of_name = line.rfind(") ");
    return end_of_name == std::string::npos || end_of_name + 2 >= line.size() || line[end_of_name + 2] != 'Z';
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
        if (is_running(pid)) continue;
        std::error_code removing;
        if (fs::remove(it->path(), removing)) ++removed;
    }
    return removed;
}

}  // namespace lancer
