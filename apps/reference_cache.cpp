// The reference cache: content hashing and the folder of EXR entries.
#include "reference_cache.h"

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <set>
#include <sstream>

namespace lancer::app {
namespace {

namespace fs = std::filesystem;

class Fnv1a {
  public:
    void add(const std::string& bytes) {
        for (unsigned char c : bytes) {
            m_state ^= c;
            m_state *= 0x100000001b3ull;
        }
        // A separator, so ("ab", "c") and ("a", "bc") differ.
        m_state ^= 0xff;
        m_state *= 0x100000001b3ull;
    }
    std::string hex() const {
        char text[17];
        std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(m_state));
        return text;
    }

  private:
    std::uint64_t m_state = 0xcbf29ce484222325ull;
};

std::string read_file(const fs::path& path) {
    std::ifstream stream(path, std::ios::binary);
    std::ostringstream text;
    text << stream.rdbuf();
    return text.str();
}

// Every "quoted string" in a scene's text: the candidates for file names.
std::vector<std::string> quoted_strings(const std::string& text) {
    std::vector<std::string> strings;
    std::size_t at = 0;
    while ((at = text.find('"', at)) != std::string::npos) {
        const std::size_t end = text.find('"', at + 1);
        if (end == std::string::npos) break;
        const std::string inside = text.substr(at + 1, end - at - 1);
        if (!inside.empty() && inside.size() < 512 && inside.find('\n') == std::string::npos) strings.push_back(inside);
        at = end + 1;
    }
    return strings;
}

// Hashes `file` and, through its quoted names, the files it uses; scene
// files (.pov, .inc) are followed recursively, others hashed as bytes.
void hash_file_and_dependencies(const fs::path& file, const std::vector<std::string>& include_path, Fnv1a& hash,
                                std::set<fs::path>& visited) {
    const fs::path canonical = fs::weakly_canonical(file);
    if (!visited.insert(canonical).second) return;
    const std::string text = read_file(file);
    hash.add(canonical.filename().string());
    hash.add(text);
    const std::string extension = file.extension().string();
    if (extension != ".pov" && extension != ".inc") return;
    for (const std::string& name : quoted_strings(text)) {
        std::vector<fs::path> candidates = {file.parent_path() / name};
        for (const std::string& folder : include_path) candidates.push_back(fs::path(folder) / name);
        for (const fs::path& candidate : candidates) {
            std::error_code error;
            if (fs::is_regular_file(candidate, error)) {
                hash_file_and_dependencies(candidate, include_path, hash, visited);
                break;
            }
        }
    }
}

fs::path entry_stem(const fs::path& folder, const std::string& key, int spp) {
    return folder / (key + "-spp" + std::to_string(spp));
}

}  // namespace

std::string reference_key(const fs::path& scene, const std::vector<std::string>& include_path,
                          const std::string& settings) {
    Fnv1a hash;
    hash.add("lancer trade reference 1");
    hash.add(settings);
    std::set<fs::path> visited;
    hash_file_and_dependencies(scene, include_path, hash, visited);
    return hash.hex();
}

std::optional<CachedReference> ReferenceCache::find(const std::string& key) const {
    std::error_code error;
    if (!fs::is_directory(m_folder, error)) return std::nullopt;
    // The entry with the most samples under this key.
    int best_spp = 0;
    const std::string prefix = key + "-spp";
    for (const auto& entry : fs::directory_iterator(m_folder, error)) {
        const std::string name = entry.path().filename().string();
        if (name.rfind(prefix, 0) != 0 || entry.path().extension() != ".exr") continue;
        const int spp = std::atoi(name.c_str() + prefix.size());
        if (spp > best_spp) best_spp = spp;
    }
    if (best_spp <= 0) return std::nullopt;
    CachedReference reference;
    reference.samples_per_pixel = best_spp;
    reference.file = entry_stem(m_folder, key, best_spp).replace_extension(".exr");
    try {
        reference.image = read_rgb_image(reference.file.string());
    } catch (const std::exception&) {
        return std::nullopt;
    }
    std::ifstream noise(entry_stem(m_folder, key, best_spp).replace_extension(".txt"));
    std::string word;
    while (noise >> word)
        if (word.rfind("noise_rmse=", 0) == 0)
            reference.noise.rmse = std::atof(word.c_str() + 11);
        else if (word.rfind("noise_rel_mse=", 0) == 0)
            reference.noise.rel_mse = std::atof(word.c_str() + 14);
        else if (word.rfind("seconds=", 0) == 0)
            reference.render_seconds = std::atof(word.c_str() + 8);
    return reference;
}

CachedReference ReferenceCache::store(const std::string& key, const RgbImage& image, int samples_per_pixel,
                                      const ReferenceNoise& noise, double render_seconds) const {
    fs::create_directories(m_folder);
    CachedReference reference;
    reference.image = image;
    reference.samples_per_pixel = samples_per_pixel;
    reference.noise = noise;
    reference.render_seconds = render_seconds;
    reference.file = entry_stem(m_folder, key, samples_per_pixel).replace_extension(".exr");
    // The note first: an entry is found by its EXR, which is written atomically.
    std::ofstream(entry_stem(m_folder, key, samples_per_pixel).replace_extension(".txt"))
        << "spp=" << samples_per_pixel << " noise_rmse=" << noise.rmse << " noise_rel_mse=" << noise.rel_mse
        << " seconds=" << render_seconds << "\n";
    write_rgb_image(image, reference.file.string());
    return reference;
}

fs::path default_reference_cache_folder(const fs::path& fallback) {
    if (const char* xdg = std::getenv("XDG_CACHE_HOME"); xdg && *xdg) return fs::path(xdg) / "lancer" / "references";
    if (const char* home = std::getenv("HOME"); home && *home)
        return fs::path(home) / ".cache" / "lancer" / "references";
    return fallback;
}

}  // namespace lancer::app
