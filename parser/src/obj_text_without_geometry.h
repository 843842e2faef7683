// An OBJ's text as tinyobjloader is given it: every line but the
// geometry (`v`, `vn`, `vt` and `f`), which is read here and handed straight
// to the ObjFaceReader. tinyobjloader is left the materials, groups and
// objects.
//
// tinyobjloader reads a line a character at a time, a face's indices with
// atoi and strcspn and a number digit by digit: nearly all of reading a
// million-triangle OBJ. Here each line is read in one pass, meaning what
// tinyobjloader makes of it: a face as its parseRawTriple (atoi's quirks
// kept), a number field as its parseReal (the same fields accepted, the
// same defaults), valued as the decimal written rounded once to the float
// tinyobjloader keeps. Its own sum of digits, rounded to a double and then
// to a float, lands one float away near a tie (38 of 200,000 random
// numbers of up to 17 digits), and its arithmetic overflows on fields of
// hundreds of digits or exponents past 2^31.
//
// Order is kept: the text is handed over in runs of lines that end before a
// line read here, and tinyobjloader asks for more only when it has read the
// run (it peeks at the next character before each line), so a face sees the
// vertices, `usemtl` and groups before it, as from tinyobjloader itself.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <memory>
#include <streambuf>
#include <vector>

#include <tiny_obj_loader.h>

#include "obj_faces.h"
#include "obj_text_check.h"

namespace lancer::parse {

class ObjTextWithoutGeometry : public std::streambuf {
  public:
    // The first `limit` bytes of the file at `path` (what the text check
    // read), through a buffer of `piece_bytes` (grown for a longer line).
    ObjTextWithoutGeometry(const std::filesystem::path& path, std::uintmax_t limit, ObjFaceReader& faces,
                           std::size_t piece_bytes = std::size_t(1) << 20);
    bool is_open() const { return m_file.is_open(); }
    // A read failed (not the end of the file).
    bool failed() const { return m_file.bad(); }

  protected:
    int_type underflow() override;

  private:
    // More of the file after what is kept; false at its end.
    bool read_more();
    // The line starting at m_text[at]: where it ends and where the next one
    // starts (a lone \r it ends with is made a \n). False when its end is
    // not read yet.
    bool line_at(std::size_t at, std::size_t& end, std::size_t& next);
    // A line of a kind read here, from its keyword.
    void read_line(ObjLineKind kind, const char* begin, const char* end);
    void read_face(const char* begin, const char* end);

    std::ifstream m_file;
    std::uintmax_t m_left;
    bool m_at_end = false;
    ObjFaceReader& m_faces;
    std::size_t m_capacity;          // of m_text
    std::unique_ptr<char[]> m_text;  // [m_start, m_filled): read, not yet handed over or taken
    std::size_t m_start = 0, m_filled = 0;
    std::size_t m_newline = 0;  // the first \n at or after the line being found, or m_filled
    bool m_newline_known = false;
    // The line not yet ended holds no \n or \r before this.
    std::size_t m_unended_from = 0;
    // The line read here that ended the run handed over last, as line_at
    // found it.
    bool m_line_waits = false;
    std::size_t m_waiting_line = 0, m_waiting_line_end = 0, m_waiting_line_next = 0;
    std::vector<tinyobj::index_t> m_corners;
};

}  // namespace lancer::parse
