#include "obj_text_check.h"

#include <algorithm>
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
    while (at < end) {
        const char* line_end = std::find_if(at, end, [](char c) { return c == '\n' || c == '\r'; });
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
    if (!(i + 1 < end && *i == 'f' && (i[1] == ' ' || i[1] == '\t'))) return;
    auto blank = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    auto problem = [&](const std::string& why) { m_face_problem = "line " + std::to_string(m_line) + ": " + why; };
    std::size_t vertices = 0;
    for (i += 1; i < end;) {
        while (i < end && blank(*i)) ++i;
        if (i >= end) break;
        ++vertices;
        const char* const corner_end = std::find_if(i, end, blank);
        // v, v/t, v//n, v/t/n, as tinyobjloader reads them (atoi): every
        // number written must fit an int and not be 0, and what is not a
        // number reads as 0. A texture or normal index may be left out; the
        // vertex may not. OBJ has no comments after a face's indices.
        const char* part = i;
        for (int k = 0; k < 3 && part <= corner_end; ++k) {
            const char* const part_end = std::find(part, corner_end, '/');
            if (k == 0 || part_end > part) {
                const char* c = part;
                if (c < part_end && (*c == '-' || *c == '+')) ++c;
                const char* const digits_begin = c;
                double value = 0.0;
                for (; c < part_end && *c >= '0' && *c <= '9'; ++c) value = value * 10.0 + (*c - '0');
                if (c == digits_begin)
                    return problem("face index \"" + std::string(part, part_end) + "\" is not a number");
                if (value > 2147483647.0)
                    return problem("face index " + std::string(digits_begin, c) + " is out of range");
                if (value == 0.0) return problem("face index 0 (OBJ counts from 1)");
            }
            part = part_end + 1;
        }
        i = corner_end;
    }
    if (vertices > kMaxFaceVertices)
        problem("a face of " + std::to_string(vertices) + " vertices (lancer takes at most " +
                std::to_string(kMaxFaceVertices) + " per face; split it into smaller polygons)");
}

}  // namespace lancer::parse
