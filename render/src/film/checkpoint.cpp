// Checkpoint files: magic, version, identity text, film size, every pixel's
// raw totals, and a trailing FNV-1a hash of all of it so a torn or foreign
// file is refused rather than resumed.
#include "lancer/host/checkpoint.h"
#include "lancer/host/temporary_file.h"

#include <fcntl.h>
#include <unistd.h>

#include <atomic>
#include <bit>
#include <cerrno>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <vector>

namespace lancer {
namespace {

namespace fs = std::filesystem;

static_assert(std::endian::native == std::endian::little, "checkpoints are written little-endian");

constexpr char kMagic[8] = {'L', 'A', 'N', 'C', 'E', 'R', 'C', 'K'};
constexpr std::uint32_t kVersion = 1;

std::uint64_t fnv1a(const char* data, std::size_t size, std::uint64_t hash = 14695981039346656037ull) {
    for (std::size_t i = 0; i < size; ++i) {
        hash ^= std::uint8_t(data[i]);
        hash *= 1099511628211ull;
    }
    return hash;
}

std::string identity_text(const CheckpointIdentity& identity) {
    std::string text;
    for (const auto& [key, value] : identity) text += key + "=" + value + "\n";
    return text;
}

CheckpointIdentity parse_identity(const std::string& text) {
    CheckpointIdentity identity;
    std::istringstream lines(text);
    std::string line;
    while (std::getline(lines, line)) {
        const auto equals = line.find('=');
        if (equals != std::string::npos) identity[line.substr(0, equals)] = line.substr(equals + 1);
    }
    return identity;
}

template <typename T>
void put(std::string& out, const T& value) {
    out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

// Reads from a byte buffer, failing cleanly past its end.
class Reader {
  public:
    explicit Reader(const std::string& bytes) : m_bytes(bytes) {}
    template <typename T>
    bool get(T& value) {
        if (m_offset + sizeof(T) > m_bytes.size()) return false;
        std::memcpy(&value, m_bytes.data() + m_offset, sizeof(T));
        m_offset += sizeof(T);
        return true;
    }
    bool get_text(std::string& text, std::size_t size) {
        if (m_offset + size > m_bytes.size()) return false;
        text.assign(m_bytes.data() + m_offset, size);
        m_offset += size;
        return true;
    }
    std::size_t offset() const { return m_offset; }

  private:
    const std::string& m_bytes;
    std::size_t m_offset = 0;
};

}  // namespace

std::string checkpoint_path_for(const std::string& output) {
    return output + ".lancer-checkpoint";
}

std::string content_hash_of_file(const std::string& path) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw CheckpointError("cannot read '" + path + "' to hash it");
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    char hex[17];
    std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a(bytes.data(), bytes.size())));
    return hex;
}

void write_checkpoint(const std::string& path, const CheckpointIdentity& identity, const Film& film) {
    // The whole file in memory first: one write, one fsync.
    std::string bytes(kMagic, sizeof kMagic);
    put(bytes, kVersion);
    const std::string text = identity_text(identity);
    put(bytes, std::uint32_t(text.size()));
    bytes += text;
    put(bytes, std::int32_t(film.width()));
    put(bytes, std::int32_t(film.height()));
    for (std::size_t index = 0; index < std::size_t(film.width()) * std::size_t(film.height()); ++index) {
        const Film::Accumulator pixel = film.accumulator(index);
        for (int c = 0; c < 3; ++c) put(bytes, pixel.sum[c]);
        for (int c = 0; c < 3; ++c) put(bytes, pixel.sum_squares[c]);
        put(bytes, pixel.count);
        put(bytes, pixel.nonfinite);
    }
    put(bytes, fnv1a(bytes.data(), bytes.size()));

    // Temporary beside the target, flushed to disk, then renamed over it:
    // a crash at any moment leaves the old checkpoint or the new one.
    const fs::path target(path);
    const fs::path temporary = temporary_path_for(target);
    auto fail = [&](const std::string& why) {
        std::error_code ignored;
        fs::remove(temporary, ignored);
        throw CheckpointError("cannot write checkpoint '" + path + "': " + why);
    };
    const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
    if (fd < 0) fail(std::strerror(errno));
    std::size_t written = 0;
    while (written < bytes.size()) {
        const ssize_t n = ::write(fd, bytes.data() + written, bytes.size() - written);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) {
            const std::string why = std::strerror(errno);
            ::close(fd);
            fail(why);
        }
        written += std::size_t(n);
    }
    if (::fsync(fd) != 0 || ::close(fd) != 0) fail(std::strerror(errno));
    std::error_code renamed;
    fs::rename(temporary, target, renamed);
    if (renamed) fail(renamed.message());
}

void read_checkpoint(const std::string& path, const CheckpointIdentity& expected, Film& film) {
    std::ifstream file(path, std::ios::binary);
    if (!file) throw CheckpointError("cannot resume: no checkpoint '" + path + "'");
    const std::string bytes((std::istreambuf_iterator<char>(file)), std::istreambuf_iterator<char>());
    auto corrupt = [&](const std::string& why) { throw CheckpointError("cannot resume from '" + path + "': " + why); };

    // Header and integrity.
    if (bytes.size() < sizeof kMagic + 8 || std::memcmp(bytes.data(), kMagic, sizeof kMagic) != 0)
        corrupt("not a lancer checkpoint");
    std::uint64_t stored_hash = 0;
    std::memcpy(&stored_hash, bytes.data() + bytes.size() - 8, 8);
    if (fnv1a(bytes.data(), bytes.size() - 8) != stored_hash) corrupt("the file is truncated or damaged");
    Reader reader(bytes);
    char magic[8];
    std::uint32_t version = 0, text_size = 0;
    std::string text;
    reader.get(magic);
    if (!reader.get(version) || version != kVersion)
        corrupt("checkpoint format version " + std::to_string(version) + ", this lancer reads " +
                std::to_string(kVersion));
    if (!reader.get(text_size) || !reader.get_text(text, text_size)) corrupt("the file is truncated");

    // Identity: every field that differs, by name.
    const CheckpointIdentity stored = parse_identity(text);
    std::string differences;
    for (const auto& [key, value] : expected) {
        const auto found = stored.find(key);
        const std::string was = found == stored.end() ? "(missing)" : found->second;
        if (was != value) differences += "\n  " + key + ": checkpoint has '" + was + "', this render '" + value + "'";
    }
    if (!differences.empty())
        throw CheckpointError("cannot resume from '" + path + "': it belongs to another render;" + differences +
                              "\n  (render without --resume to start over)");

    // Pixels.
    std::int32_t width = 0, height = 0;
    if (!reader.get(width) || !reader.get(height)) corrupt("the file is truncated");
    if (width != film.width() || height != film.height())
        corrupt("film is " + std::to_string(width) + "x" + std::to_string(height) + ", this render " +
                std::to_string(film.width()) + "x" + std::to_string(film.height()));
    std::vector<Film::Accumulator> pixels(std::size_t(width) * std::size_t(height));
    for (Film::Accumulator& pixel : pixels) {
        bool ok = true;
        for (int c = 0; c < 3; ++c) ok = ok && reader.get(pixel.sum[c]);
        for (int c = 0; c < 3; ++c) ok = ok && reader.get(pixel.sum_squares[c]);
        ok = ok && reader.get(pixel.count) && reader.get(pixel.nonfinite);
        if (!ok) corrupt("the file is truncated");
        // The film counts samples taken in 32 bits.
        if (std::uint64_t(pixel.count) + pixel.nonfinite > UINT32_MAX) corrupt("a pixel's sample counts overflow");
    }
    if (reader.offset() + 8 != bytes.size()) corrupt("unexpected data after the pixels");
    film.restore(std::move(pixels));
}

}  // namespace lancer
