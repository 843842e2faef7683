// An OBJ's text as tinyobjloader is given it: every line but the faces,
// which are read here and handed straight to the ObjFaceReader.
//
// tinyobjloader reads a face line a character at a time and its indices
// with atoi and strcspn: about a third of reading a million-triangle OBJ
// with normals and texture coordinates. Here a face line is read in one
// pass, meaning exactly what tinyobjloader's parseRawTriple makes of it.
//
// Order is kept: the text is handed over in runs of lines that end before a
// face line, and tinyobjloader asks for more only when it has read the run
// (it peeks at the next character before each line), so the faces see the
// vertices, `usemtl` and groups before them, as from tinyobjloader itself.
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

namespace lancer::parse {

class ObjTextWithoutFaces : public std::streambuf {
  public:
    // The first `limit` bytes of the file at `path` (what the text check
    // read), through a buffer of `piece_bytes` (grown for a longer line).
    ObjTextWithoutFaces(const std::filesystem::path& path, std::uintmax_t limit, ObjFaceReader& faces,
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
    // The face line that ended the run handed over last, as line_at found it.
    bool m_face_waits = false;
    std::size_t m_waiting_face = 0, m_waiting_face_end = 0, m_waiting_face_next = 0;
    std::vector<tinyobj::index_t> m_corners;
};

}  // namespace lancer::parse
