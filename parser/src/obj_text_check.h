// What lancer checks in an OBJ's text before tinyobjloader reads it, fed a
// piece at a time so that a large file need not be held whole: that it is
// text at all (tinyobjloader reads a PNG as an OBJ without faces), and that
// no face line would be misread (an index outside int, which tinyobjloader
// wraps, or more vertices than lancer triangulates).
#pragma once

#include <cstddef>
#include <string>

namespace lancer::parse {

// Why text starting with `head` (its first bytes, at least 4 when the text
// has them) cannot be an OBJ or MTL file, or null when it may be one.
// `has_nul`: a NUL byte occurs anywhere in the text.
const char* not_text(const std::string& head, bool has_nul);
inline const char* not_text(const std::string& text) {
    return not_text(text.substr(0, 4), text.find('\0') != std::string::npos);
}

// An OBJ line's kind as tinyobjloader tells them apart, from the line's
// first character after its blanks to its end.
enum class ObjLineKind { Vertex, Normal, TextureCoordinate, Face, Other };
ObjLineKind obj_line_kind(const char* line, const char* end);

class ObjTextCheck {
  public:
    // Vertices one face may have. Faces are triangulated in O(n log n)
    // (polygon_triangulation.h); a concave face of a million vertices (a
    // star) took 3.4 s and 150 MB on a loaded two-core machine.
    static constexpr std::size_t kMaxFaceVertices = 1000000;

    // The next piece of the text.
    void feed(const char* data, std::size_t size);
    // After the last piece.
    void finish();
    // Why the text cannot be an OBJ ("is a PNG image, not text"), or null.
    const char* why_not_text() const { return not_text(m_head, m_has_nul); }
    // The first face line tinyobjloader would misread ("line N: why"), or empty.
    const std::string& face_problem() const { return m_face_problem; }

    // What the lines written declare, for reserving the mesh before it is
    // read: a million-triangle mesh grown as read copied its arrays and
    // faulted their pages in twice. Estimates only (a polygon with no area
    // gives fewer triangles than its corners less two).
    struct Counts {
        std::size_t positions = 0, normals = 0, uvs = 0;
        std::size_t faces = 0;      // of three or more vertices
        std::size_t triangles = 0;  // each face's vertices less two
    };
    const Counts& counts() const { return m_counts; }

  private:
    void scan_line(const char* begin, const char* end);

    std::string m_head;  // the first bytes, for not_text
    bool m_has_nul = false;
    bool m_after_cr = false;     // the last piece ended with a \r
    std::string m_partial;       // a line not yet ended
    std::size_t m_line = 0;      // lines scanned
    std::string m_face_problem;  // the first, as "line N: why"
    Counts m_counts;
};

}  // namespace lancer::parse
