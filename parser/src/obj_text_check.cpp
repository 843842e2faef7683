#include "obj_text_check.h"

#include <algorithm>
#include <cstdint>
#include <cstring>

namespace lancer::parse {

const char* not_text(const std::string& head, bool has_nul) {
    if (head.size() >= 2 && ((head[0] == '\xFF' && head[1] == '\xFE') || (head[0] == '\xFE' && head[1] == '\xFF')))
        return "is UTF-16 text; save it as UTF-8 or ASCII";
    if (has_nul) {
        if (head.compare(0, 4, "\x89PNG") == 0) return "is a PNG image, not text";
        return "is a binary file, not text (or UTF-16 without a byte order mark)";
    }
    return nullptr;
}

ObjLineKind obj_line_kind(const char* line, const char* end) {
    // In tinyobjloader's order: "v ", "vn ", "vt ", "f ".
    auto blank_or_tab = [](char c) { return c == ' ' || c == '\t'; };
    const std::ptrdiff_t size = end - line;
    if (size >= 2 && line[0] == 'v' && blank_or_tab(line[1])) return ObjLineKind::Vertex;
    if (size >= 3 && line[0] == 'v' && line[1] == 'n' && blank_or_tab(line[2])) return ObjLineKind::Normal;
    if (size >= 3 && line[0] == 'v' && line[1] == 't' && blank_or_tab(line[2])) return ObjLineKind::TextureCoordinate;
    if (size >= 2 && line[0] == 'f' && blank_or_tab(line[1])) return ObjLineKind::Face;
    return ObjLineKind::Other;
}

void ObjTextCheck::feed(const char* data, std::size_t size) {
    if (size == 0) return;
    if (m_head.size() < 4) m_head.append(data, std::min(4 - m_head.size(), size));
    if (!m_has_nul && std::memchr(data, '\0', size) != nullptr) m_has_nul = true;
    if (m_has_nul || !m_face_problem.empty()) return;  // the answer is known
    const char* at = data;
    const char* const end = data + size;
    // A line ended by a \r at the end of the last piece: a \n starting this
    // one belongs to it.
    if (m_after_cr && at < end && *at == '\n') ++at;
    m_after_cr = false;
    // Lines end at \n, \r\n or a lone \r, as tinyobjloader reads them.
    // The next \n is kept, not searched for again at each line: a file of
    // lone \r would make that quadratic.
    const char* newline = nullptr;
    while (at < end) {
        if (newline == nullptr || newline < at) {
            const void* found = std::memchr(at, '\n', std::size_t(end - at));
            newline = found ? static_cast<const char*>(found) : end;
        }
        const void* cr = std::memchr(at, '\r', std::size_t(newline - at));
        const char* const line_end = cr ? static_cast<const char*>(cr) : newline;
        if (line_end == end) {
            m_partial.append(at, end);
            return;
        }
        if (m_partial.empty()) {
            scan_line(at, line_end);
        } else {
            m_partial.append(at, line_end);
            scan_line(m_partial.data(), m_partial.data() + m_partial.size());
            m_partial.clear();
        }
        if (!m_face_problem.empty()) return;
        at = line_end + 1;
        if (*line_end == '\r') {
            if (at == end)
                m_after_cr = true;
            else if (*at == '\n')
                ++at;
        }
    }
}

void ObjTextCheck::finish() {
    if (!m_partial.empty() && !m_has_nul && m_face_problem.empty())
        scan_line(m_partial.data(), m_partial.data() + m_partial.size());
    m_partial.clear();
}

void ObjTextCheck::scan_line(const char* begin, const char* end) {
    ++m_line;
    const char* i = begin;
    while (i < end && (*i == ' ' || *i == '\t')) ++i;
    switch (obj_line_kind(i, end)) {
    case ObjLineKind::Vertex: ++m_counts.positions; return;
    case ObjLineKind::Normal: ++m_counts.normals; return;
    case ObjLineKind::TextureCoordinate: ++m_counts.uvs; return;
    case ObjLineKind::Other: return;
    case ObjLineKind::Face: break;
    }
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    auto problem = [&](const std::string& why) { m_face_problem = "line " + std::to_string(m_line) + ": " + why; };
    std::size_t vertices = 0;
    auto is_digit = [](char c) { return c >= '0' && c <= '9'; };
    constexpr std::uint64_t kIntMax = 2147483647;
    // v, v/t, v//n, v/t/n, as tinyobjloader reads them (atoi): every number
    // written must fit an int and not be 0, and what is not a number reads
    // as 0. A texture or normal index may be left out; the vertex may not.
    // OBJ has no comments after a face's indices.
    for (i += 1; i < end;) {
        while (i < end && blank(*i)) ++i;
        if (i >= end) break;
        ++vertices;
        const char* const corner = i;
        for (int k = 0; k < 3; ++k) {
            const char* const part = i;
            if (i < end && (*i == '-' || *i == '+')) ++i;
            const char* const digits_begin = i;
            // Kept exact up to past INT_MAX, then no longer grown.
            std::uint64_t value = 0;
            for (; i < end && is_digit(*i); ++i)
                if (value <= kIntMax) value = value * 10 + std::uint64_t(*i - '0');
            const char* const digits_end = i;
            while (i < end && !blank(*i) && *i != '/') ++i;
            if (k == 0 || i > part) {
                if (digits_end == digits_begin)
                    return problem("face index \"" + std::string(part, i) + "\" is not a number");
                if (value > kIntMax)
                    return problem("face index " + std::string(digits_begin, digits_end) + " is out of range");
                if (value == 0) return problem("face index 0 (OBJ counts from 1)");
            }
            if (i == end || *i != '/') break;
            // tinyobjloader reads what follows a third number's '/' as
            // another corner, of vertex 0: say what is wrong with the text.
            if (k == 2) {
                while (i < end && !blank(*i)) ++i;
                return problem("face corner \"" + std::string(corner, i) +
                               "\" has more than three parts (OBJ writes v, v/vt, v//vn or v/vt/vn)");
            }
            ++i;
        }
    }
    if (vertices >= 3) {
        ++m_counts.faces;
        m_counts.triangles += vertices - 2;
    }
    if (vertices > kMaxFaceVertices)
        problem("a face of " + std::to_string(vertices) + " vertices (lancer takes at most " +
                std::to_string(kMaxFaceVertices) + " per face; split it into smaller polygons)");
}

}  // namespace lancer::parse
