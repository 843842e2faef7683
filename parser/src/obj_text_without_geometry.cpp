#include "obj_text_without_geometry.h"

#include <algorithm>
#include <charconv>
#include <climits>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <string>

namespace lancer::parse {
namespace {

bool blank_or_tab(char c) {
    return c == ' ' || c == '\t';
}

bool is_digit(char c) {
    return unsigned(c - '0') < 10u;
}

// atoi of the text from `at` (C's isspace skipped first, as atoi does),
// which may run past `end`'s corner into the next: tinyobjloader reads
// "1/ 2" as vertex 1 with texture coordinate 2, then a corner 2.
int atoi_like(const char* at, const char* end) {
    // Most indices: up to nine digits, which cannot overflow.
    {
        unsigned value = 0;
        const char* i = at;
        for (; i < end && i - at < 9 && is_digit(*i); ++i) value = value * 10 + unsigned(*i - '0');
        if (i > at && (i == end || !is_digit(*i))) return int(value);
    }
    while (at < end && (*at == ' ' || *at == '\t' || *at == '\n' || *at == '\v' || *at == '\f' || *at == '\r')) ++at;
    bool negative = false;
    if (at < end && (*at == '+' || *at == '-')) negative = *at++ == '-';
    // strtol's value saturated to long, then narrowed to int as glibc's atoi.
    unsigned long magnitude = 0;
    const unsigned long most =
        negative ? 0UL - static_cast<unsigned long>(LONG_MIN) : static_cast<unsigned long>(LONG_MAX);
    for (; at < end && is_digit(*at); ++at) {
        const unsigned d = unsigned(*at - '0');
        magnitude = magnitude > (most - d) / 10 ? most : magnitude * 10 + d;
    }
    const long value = negative ? (magnitude == most ? LONG_MIN : -long(magnitude)) : long(magnitude);
    return int(value);
}

// strcspn(at, "/ \t\r") within the line.
const char* past_number(const char* at, const char* end) {
    while (at < end && *at != '/' && *at != ' ' && *at != '\t' && *at != '\r') ++at;
    return at;
}

// One number field where tinyobjloader's parseReal (its tryParseDouble)
// finds one: [+-], digits or a point, [. digits], [e [+-] digits], whatever
// follows ignored; any other field is `fallback`. The value is the decimal
// written, rounded once to the float kept. tinyobjloader's sum of digits,
// rounded to a double and then to a float, can land one float away near a
// tie, and its arithmetic overflows on fields of hundreds of digits or
// exponents past 2^31 (0e999 is not a number there, 0 here).
float obj_real(const char* s, const char* e, float fallback) {
    if (s >= e) return fallback;
    const char* i = s;
    const bool negative = *i == '-';
    if (*i == '+' || *i == '-') ++i;
    const char* const number = i;
    bool nonzero = false;
    if (!(i < e && *i == '.')) {
        const char* const digits = i;
        for (; i < e && is_digit(*i); ++i) nonzero = nonzero || *i != '0';
        if (i == digits) return fallback;
    }
    if (i < e && *i == '.')
        for (++i; i < e && is_digit(*i); ++i) nonzero = nonzero || *i != '0';
    if (i < e && (*i == 'e' || *i == 'E')) {
        ++i;
        if (i < e && (*i == '+' || *i == '-')) ++i;
        const char* const digits = i;
        std::int64_t exponent = 0;
        for (; i < e && is_digit(*i); ++i) {
            if (exponent > INT_MAX / 10) return fallback;  // tinyobjloader refuses such a field
            exponent = exponent * 10 + (*i - '0');
        }
        if (i == digits) return fallback;
    }
    if (!nonzero) return negative ? -0.0f : 0.0f;
    float value = 0.0f;
    const std::from_chars_result read = std::from_chars(number, i, value);
    // Past the floats: infinity, or zero (a denormal where there is one).
    if (read.ec == std::errc::result_out_of_range) value = std::strtof(std::string(number, i).c_str(), nullptr);
    return negative ? -value : value;
}

// The fields of a v, vn or vt line after its keyword: tinyobjloader's
// parseReal for each, blanks before it skipped, the field up to a blank.
class NumberFields {
  public:
    NumberFields(const char* at, const char* end) : m_at(at), m_end(end) {}
    float next(float fallback) {
        while (m_at < m_end && blank_or_tab(*m_at)) ++m_at;
        const char* const field = m_at;
        while (m_at < m_end && !blank_or_tab(*m_at) && *m_at != '\r') ++m_at;
        return obj_real(field, m_at, fallback);
    }

  private:
    const char* m_at;
    const char* m_end;
};

}  // namespace

ObjTextWithoutGeometry::ObjTextWithoutGeometry(const std::filesystem::path& path, std::uintmax_t limit,
                                               ObjFaceReader& faces, std::size_t piece_bytes)
    : m_file(path, std::ios::binary),
      m_left(limit),
      m_faces(faces),
      m_capacity(std::max<std::size_t>(1, piece_bytes)),
      m_text(new char[m_capacity]) {}

bool ObjTextWithoutGeometry::read_more() {
    if (m_at_end) return false;
    // What is left moves to the front; a line longer than the buffer grows
    // it, and is then read in pieces of the buffer's room.
    if (m_start > 0) {
        std::memmove(m_text.get(), m_text.get() + m_start, m_filled - m_start);
        m_filled -= m_start;
        m_unended_from -= std::min(m_unended_from, m_start);
        m_start = 0;
    }
    m_newline_known = false;
    if (m_filled == m_capacity) {
        // Not zeroed first: every byte is read into before it is used.
        std::unique_ptr<char[]> grown(new char[2 * m_capacity]);
        std::memcpy(grown.get(), m_text.get(), m_filled);
        m_text = std::move(grown);
        m_capacity *= 2;
    }
    std::streamsize got = 0;
    if (m_left > 0 && m_file) {
        m_file.read(m_text.get() + m_filled, std::streamsize(std::min<std::uintmax_t>(m_capacity - m_filled, m_left)));
        got = m_file.gcount();
    }
    if (got <= 0) {
        m_at_end = true;
        return false;
    }
    m_left -= std::uintmax_t(got);
    m_filled += std::size_t(got);
    return true;
}

bool ObjTextWithoutGeometry::line_at(std::size_t at, std::size_t& end, std::size_t& next) {
    // Lines end at \n, \r\n or a lone \r, as tinyobjloader reads them.
    if (m_line_waits && at == m_waiting_line) {
        // Found before, its \r perhaps made a \n since.
        m_line_waits = false;
        end = m_waiting_line_end;
        next = m_waiting_line_next;
        return true;
    }
    // Searches resume where the last one stopped: the next \n is kept
    // rather than searched for at each line (a file of lone \r), and a line
    // longer than what is read is not searched again from its start.
    char* const text = m_text.get();
    const std::size_t from = std::max(at, m_unended_from);
    if (!m_newline_known || m_newline < at) {
        const void* newline = std::memchr(text + from, '\n', m_filled - from);
        m_newline = newline ? std::size_t(static_cast<const char*>(newline) - text) : m_filled;
        m_newline_known = true;
    }
    const std::size_t newline_at = m_newline;
    const void* cr = std::memchr(text + from, '\r', newline_at - std::min(newline_at, from));
    end = cr ? std::size_t(static_cast<const char*>(cr) - text) : newline_at;
    if (end == m_filled) {
        next = end;
        m_unended_from = m_filled;
        return m_at_end && at < m_filled;  // the last line, unended
    }
    if (text[end] == '\n') {
        next = end + 1;
        return true;
    }
    if (end + 1 == m_filled && !m_at_end) {  // a \n may follow
        m_unended_from = end;
        return false;
    }
    if (end + 1 < m_filled && text[end + 1] == '\n') {
        next = end + 2;
        return true;
    }
    // A lone \r becomes \n: tinyobjloader peeks past a \r for its \n, which
    // at the end of a run would ask for the text after it too early.
    text[end] = '\n';
    next = end + 1;
    return true;
}

ObjTextWithoutGeometry::int_type ObjTextWithoutGeometry::underflow() {
    if (gptr() < egptr()) return traits_type::to_int_type(*gptr());
    // Everything handed over before has been read.
    for (;;) {
        std::size_t at = m_start, run_end = m_start;
        std::size_t end = 0, next = 0;
        while (line_at(at, end, next)) {
            const char* line = m_text.get() + at;
            const char* const line_end = m_text.get() + end;
            while (line < line_end && blank_or_tab(*line)) ++line;
            const ObjLineKind kind = obj_line_kind(line, line_end);
            if (kind != ObjLineKind::Other) {
                if (run_end > m_start) {
                    // The lines before it are read first.
                    m_line_waits = true;
                    m_waiting_line = at;
                    m_waiting_line_end = end;
                    m_waiting_line_next = next;
                    break;
                }
                read_line(kind, line, line_end);
                m_start = run_end = next;
            } else {
                run_end = next;
            }
            at = next;
        }
        if (run_end > m_start) {
            char* const begin = m_text.get() + m_start;
            setg(begin, begin, m_text.get() + run_end);
            m_start = run_end;
            return traits_type::to_int_type(*gptr());
        }
        if (!read_more()) {
            // At the end every line has been taken or handed over.
            if (m_start == m_filled) return traits_type::eof();
        }
    }
}

void ObjTextWithoutGeometry::read_line(ObjLineKind kind, const char* at, const char* end) {
    switch (kind) {
    case ObjLineKind::Vertex: {
        NumberFields fields(at + 2, end);
        const float x = fields.next(0.0f), y = fields.next(0.0f), z = fields.next(0.0f);
        m_faces.add_vertex(x, y, z);  // a fourth number (w) is read by nobody
        return;
    }
    case ObjLineKind::Normal: {
        NumberFields fields(at + 3, end);
        const float x = fields.next(0.0f), y = fields.next(0.0f), z = fields.next(0.0f);
        m_faces.add_normal(x, y, z);
        return;
    }
    case ObjLineKind::TextureCoordinate: {
        NumberFields fields(at + 3, end);
        const float u = fields.next(0.0f), v = fields.next(0.0f);
        m_faces.add_uv(u, v);
        return;
    }
    case ObjLineKind::Face: read_face(at, end); return;
    case ObjLineKind::Other: return;
    }
}

void ObjTextWithoutGeometry::read_face(const char* at, const char* end) {
    // As tinyobjloader: past "f" and the blank after it, then corners
    // v, v/vt, v//vn or v/vt/vn until the line's end.
    at += 2;
    while (at < end && blank_or_tab(*at)) ++at;
    m_corners.clear();
    while (at < end) {
        tinyobj::index_t corner{0, 0, 0};
        corner.vertex_index = atoi_like(at, end);
        at = past_number(at, end);
        if (at < end && *at == '/') {
            ++at;
            if (at < end && *at == '/') {
                ++at;
                corner.normal_index = atoi_like(at, end);
                at = past_number(at, end);
            } else {
                corner.texcoord_index = atoi_like(at, end);
                at = past_number(at, end);
                if (at < end && *at == '/') {
                    ++at;
                    corner.normal_index = atoi_like(at, end);
                    at = past_number(at, end);
                }
            }
        }
        m_corners.push_back(corner);
        while (at < end && (blank_or_tab(*at) || *at == '\r')) ++at;
    }
    if (!m_corners.empty()) m_faces.add_face(m_corners.data(), int(m_corners.size()));
}

}  // namespace lancer::parse
