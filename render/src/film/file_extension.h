// A file name's extension in lower case, with its dot (".png"), by which
// the film's readers and writers choose a format (internal to liblancer).
#pragma once

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <string>

namespace lancer {

inline std::string lower_extension(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return char(std::tolower(c)); });
    return ext;
}

}  // namespace lancer
