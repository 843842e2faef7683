// Every file lancer writes goes first to a temporary beside its target and
// is renamed over it when whole, so a failure or a kill leaves the old file
// or the new one, never a partial one. The temporary's name is
// .<stem>.tmp<pid>-<n><extension> (the extension kept: image writers pick
// the format from it).
#pragma once

#include <filesystem>

namespace lancer {

std::filesystem::path temporary_path_for(const std::filesystem::path& target);

// Removes the temporaries of `target` that processes no longer running
// left behind (a SIGKILL or a second SIGINT during a write, which no code
// of lancer's can see). Returns how many it removed.
int remove_stale_temporaries(const std::filesystem::path& target);

}  // namespace lancer
