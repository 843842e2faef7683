// Reference renders kept between `lancer trade` runs. A reference is costly
// (path at hundreds or thousands of samples per pixel) and depends only on
// the scene and the settings, so it is stored under a hash of both and
// reused while neither changes.
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "lancer/host/rgb_image.h"

namespace lancer::app {

// A hex digest (FNV-1a, 64 bits) of the scene's text, of every file it names
// in quotes that exists (includes, meshes, textures; followed recursively
// through .pov/.inc files), and of `settings` (size, integrator parameters,
// seed, lancer's version: whatever else changes the image). Not
// cryptographic: it only has to tell scene revisions apart.
std::string reference_key(const std::filesystem::path& scene, const std::vector<std::string>& include_path,
                          const std::string& settings);

// The reference's own noise, from its film's per-pixel variance of the
// mean: measured against a noisy reference r, a render x's expected squared
// error is (x − truth)² + Var(r), so these are the floors under which no
// render's RMSE or relative MSE can be measured.
struct ReferenceNoise {
    double rmse = 0.0;     // sqrt(mean over pixels and channels of Var(r))
    double rel_mse = 0.0;  // mean of Var(r) / (r² + ε)
};

struct CachedReference {
    RgbImage image;
    int samples_per_pixel = 0;
    ReferenceNoise noise;
    double render_seconds = 0.0;  // what it cost to render, as recorded
    std::filesystem::path file;
};

// One folder; each entry is "<key>-spp<N>.exr" with a "<key>-spp<N>.txt"
// beside it holding its noise. Several sample counts may sit under one key.
class ReferenceCache {
  public:
    explicit ReferenceCache(std::filesystem::path folder) : m_folder(std::move(folder)) {}

    const std::filesystem::path& folder() const { return m_folder; }

    // The entry under `key` with the most samples, if any is readable.
    std::optional<CachedReference> find(const std::string& key) const;

    // Writes the entry (creating the folder) and returns it. Throws on I/O failure.
    CachedReference store(const std::string& key, const RgbImage& image, int samples_per_pixel,
                          const ReferenceNoise& noise, double render_seconds) const;

  private:
    std::filesystem::path m_folder;
};

// $XDG_CACHE_HOME/lancer/references, else ~/.cache/lancer/references, else
// `fallback` (no home: a CI sandbox).
std::filesystem::path default_reference_cache_folder(const std::filesystem::path& fallback);

}  // namespace lancer::app
