// Files a scene names (#include, obj_mesh, MTL, image_map): one search, one
// safe-mode check (ParseOptions::safe), one size-checked read, and the
// scene-wide triangle budget.
#include <filesystem>
#include <fstream>
#include <sstream>

#include "evaluator.h"
#include "huge_pages.h"

namespace lancer::parse {

namespace fs = std::filesystem;

namespace {

// True when `path` is `root` or lies below it; both canonical.
bool is_within(const fs::path& root, const fs::path& path) {
    auto r = root.begin(), p = path.begin();
    for (; r != root.end(); ++r, ++p) {
        if (p == path.end() || *r != *p) return false;
    }
    return true;
}

// The path with symlinks and ".." resolved; for a file that does not exist,
// its existing prefix is resolved and the rest normalised lexically.
fs::path resolved(const fs::path& path) {
    std::error_code ec;
    fs::path absolute = fs::absolute(path, ec);
    if (ec) return {};
    fs::path canonical = fs::weakly_canonical(absolute, ec);
    if (ec) return {};
    canonical = canonical.lexically_normal();
    // "/a/b/" iterates as a, b, "": drop the empty last part so prefixes compare.
    if (!canonical.has_filename() && canonical != canonical.root_path()) canonical = canonical.parent_path();
    return canonical;
}

}  // namespace

void Evaluator::init_safe_roots(const std::string& scene_folder) {
    m_safe_roots.clear();
    if (!m_options.safe) return;
    std::error_code ec;
    std::vector<std::string> roots;
    if (!m_options.safe_root.empty())
        roots.push_back(m_options.safe_root);
    else
        roots.push_back(scene_folder.empty() ? fs::current_path(ec).string() : scene_folder);
    for (const auto& dir : m_options.include_path) roots.push_back(dir);
    for (const auto& root : roots) {
        if (root.empty() || !fs::is_directory(root, ec)) continue;
        fs::path canonical = resolved(root);
        if (!canonical.empty()) m_safe_roots.push_back(canonical.string());
    }
}

bool Evaluator::allowed_file(const std::string& path) const {
    if (!m_options.safe) return true;
    fs::path target = resolved(path);
    if (target.empty()) return false;
    for (const auto& root : m_safe_roots) {
        if (is_within(fs::path(root), target)) return true;
    }
    return false;
}

bool Evaluator::allowed_write(const std::string& path) const {
    if (!m_options.safe) return true;
    if (m_safe_roots.empty()) return false;
    const fs::path target = resolved(path);
    return !target.empty() && is_within(fs::path(m_safe_roots.front()), target);
}

void Evaluator::refuse_file(const sg::SourceLocation& where, const std::string& what, const std::string& name) {
    error(where, what + " \"" + name + "\" is outside the scene's folder and the include path (refused by --safe)");
}

std::vector<std::string> Evaluator::search_folders(const sg::SourceLocation& where) const {
    std::vector<std::string> folders;
    auto buffer = m_buffers.find(where.file.get());
    if (buffer != m_buffers.end()) folders.push_back(buffer->second->folder);
    for (const auto& dir : m_options.include_path) folders.push_back(dir);
    return folders;
}

Evaluator::FileSearch Evaluator::find_file(const std::string& name, const std::vector<std::string>& folders,
                                           const sg::SourceLocation& where, const std::string& what,
                                           std::string& found) {
    std::vector<fs::path> candidates;
    if (fs::path(name).is_absolute()) {
        candidates.push_back(name);
    } else {
        for (const auto& folder : folders)
            candidates.push_back(folder.empty() ? fs::path(name) : fs::path(folder) / name);
    }
    std::error_code ec;
    for (const auto& candidate : candidates) {
        if (!fs::is_regular_file(candidate, ec)) continue;
        if (!allowed_file(candidate.string())) {
            refuse_file(where, what, name);
            return FileSearch::Refused;
        }
        found = candidate.string();
        m_scene.input_files.push_back(found);
        return FileSearch::Found;
    }
    // A name that escapes is refused even when nothing is there, so that
    // "not found" versus "refused" cannot probe the disk outside.
    if (m_options.safe && !candidates.empty() && !allowed_file(candidates.front().string())) {
        refuse_file(where, what, name);
        return FileSearch::Refused;
    }
    return FileSearch::Missing;
}

bool Evaluator::within_file_limit(const std::string& path, const sg::SourceLocation& where, const std::string& what) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    if (ec || size <= static_cast<std::uintmax_t>(m_options.max_file_bytes)) return true;
    error(where, what + " \"" + path + "\" is too large: " + std::to_string(size) + " bytes (the limit is " +
                     std::to_string(m_options.max_file_bytes) + ")");
    return false;
}

bool Evaluator::read_file(const std::string& path, const sg::SourceLocation& where, const std::string& what,
                          std::string& text) {
    if (!within_file_limit(path, where, what)) return false;
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        error(where, "cannot read " + what + " \"" + path + "\"");
        return false;
    }
    return read_open_file(in, path, where, what, text);
}

bool Evaluator::read_open_file(std::ifstream& in, const std::string& path, const sg::SourceLocation& where,
                               const std::string& what, std::string& text) {
    std::error_code ec;
    const auto size = fs::file_size(path, ec);
    // Read straight into a string of the file's size (a stream copy would
    // grow and copy it several times), then whatever follows; the limit
    // holds also for what has no size to ask first (a pipe, a device).
    std::string content;
    if (!ec) {
        // Room for the two NULs scan_text appends, so it copies nothing.
        content.reserve(static_cast<std::size_t>(size) + 2);
        advise_huge_pages(content.data(), content.capacity());
        content.resize(static_cast<std::size_t>(size));
        in.read(content.data(), static_cast<std::streamsize>(size));
        content.resize(static_cast<std::size_t>(in.gcount()));
    }
    std::vector<char> chunk(1 << 16);
    while (in.read(chunk.data(), static_cast<std::streamsize>(chunk.size())) || in.gcount() > 0) {
        content.append(chunk.data(), static_cast<std::size_t>(in.gcount()));
        if (content.size() > static_cast<std::size_t>(m_options.max_file_bytes)) {
            error(where, what + " \"" + path + "\" is too large: over " + std::to_string(m_options.max_file_bytes) +
                             " bytes (the limit)");
            return false;
        }
    }
    if (in.bad()) {
        error(where, "cannot read " + what + " \"" + path + "\"");
        return false;
    }
    text = std::move(content);
    return true;
}

bool Evaluator::add_triangles(long count, const sg::SourceLocation& where) {
    if (count <= m_options.max_triangles - m_triangles) {
        m_triangles += count;
        return true;
    }
    if (!m_triangle_limit_reported) {
        error(where, "the scene has more than " + std::to_string(m_options.max_triangles) +
                         " triangles (the limit; ParseOptions::max_triangles)");
        m_triangle_limit_reported = true;
    }
    // Stop reading: every further triangle would only grow memory.
    abort_parse();
    return false;
}

}  // namespace lancer::parse
