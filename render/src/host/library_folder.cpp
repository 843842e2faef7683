#include "host/library_folder.h"

#include <dlfcn.h>

#include <filesystem>

namespace lancer {

std::string folder_of_liblancer() {
    Dl_info info{};
    if (dladdr(reinterpret_cast<const void*>(&folder_of_liblancer), &info) == 0 || info.dli_fname == nullptr) return {};
    std::error_code error;
    const std::filesystem::path library = std::filesystem::canonical(info.dli_fname, error);
    return error ? std::filesystem::path(info.dli_fname).parent_path().string() : library.parent_path().string();
}

}  // namespace lancer
