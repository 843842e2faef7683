#include "host/shared_height_fields.h"

#include <cstdint>
#include <cstring>
#include <fstream>
#include <mutex>
#include <string>
#include <system_error>
#include <vector>

namespace lancer {
namespace {

// What a height field's shape is made from, besides its smoothing and
// water level: a function (its identity and size, the noise generator) or
// a file (its path and its bytes' length and hash: a scene may #write an
// image again under the same name, size and, on a coarse clock, time).
struct Source {
    std::weak_ptr<const sg::Function> function;  // expired: its address may be another function's
    const sg::Function* address = nullptr;
    int width = 0, height = 0, noise_generator = 0;
    std::string path;
    std::uint64_t file_size = 0, file_hash = 0;
    double gamma = 0.0;

    bool same(const Source& other) const {
        if (address != other.address) return false;
        // (Entries whose function has expired are dropped before matching.)
        if (address != nullptr)
            return width == other.width && height == other.height && noise_generator == other.noise_generator;
        return path == other.path && file_size == other.file_size && file_hash == other.file_hash &&
               gamma == other.gamma;
    }
};

struct SharedField {
    Source source;
    bool smooth = false;
    double water_level = 0.0;
    std::weak_ptr<const Shape> shape;
};

std::mutex g_mutex;
std::vector<SharedField> g_fields;

std::shared_ptr<const Shape> shared(const Source& source, const sg::HeightField& field, const MakeShape& make) {
    {
        const std::lock_guard<std::mutex> lock(g_mutex);
        std::erase_if(g_fields, [](const SharedField& f) {
            return f.shape.expired() || (f.source.address != nullptr && f.source.function.expired());
        });
        for (const SharedField& f : g_fields)
            if (f.source.same(source) && f.smooth == field.smooth && f.water_level == field.water_level)
                if (auto shape = f.shape.lock()) return shape;
    }
    // Made outside the lock: two threads asking at once each make one.
    std::shared_ptr<const Shape> shape = make();
    const std::lock_guard<std::mutex> lock(g_mutex);
    g_fields.push_back(SharedField{source, field.smooth, field.water_level, shape});
    return shape;
}

// The file's length and a 64-bit hash of its bytes (FNV-1a over 8-byte
// words), read in blocks; false if it cannot be read. Much cheaper than
// decoding the image.
bool file_fingerprint(const std::string& path, std::uint64_t& size, std::uint64_t& hash) {
    std::ifstream in(path, std::ios::binary);
    if (!in) return false;
    std::vector<char> block(1 << 20);
    size = 0;
    hash = 0xcbf29ce484222325ull;
    while (in) {
        in.read(block.data(), std::streamsize(block.size()));
        const std::size_t got = std::size_t(in.gcount());
        std::size_t i = 0;
        for (; i + 8 <= got; i += 8) {
            std::uint64_t word;
            std::memcpy(&word, block.data() + i, 8);
            hash = (hash ^ word) * 0x100000001b3ull;
        }
        for (; i < got; ++i) hash = (hash ^ std::uint8_t(block[i])) * 0x100000001b3ull;
        size += got;
    }
    return in.eof();
}

}  // namespace

std::shared_ptr<const Shape> shared_function_height_field(const sg::HeightField& field, const MakeShape& make) {
    Source source;
    source.function = field.function;
    source.address = field.function.get();
    source.width = field.function_width;
    source.height = field.function_height;
    source.noise_generator = field.function_noise_generator;
    return shared(source, field, make);
}

std::shared_ptr<const Shape> shared_image_height_field(const sg::HeightField& field, const MakeShape& make) {
    Source source;
    source.path = field.path;
    source.gamma = field.gamma;
    // A file that cannot be read is left to make(), which says why.
    if (!file_fingerprint(field.path, source.file_size, source.file_hash)) return make();
    return shared(source, field, make);
}

}  // namespace lancer
