// Raw tokens: what the flex scanner produces for one file, before directives
// run and identifiers are looked up. A whole file is scanned up front into a
// vector so #while and #macro can replay token ranges by index.
#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "lancer/parser.h"
#include "lancer/scene_graph.h"

namespace lancer::parse {

enum class RawKind : std::uint8_t {
    Number,  // number holds the value
    Vector,  // a literal <a, b, …> of 2 to 5 signed numbers: see RawToken
    // A mesh2 section of literal data, keyword to '}' (`vertex_vectors { 3,
    // <…>, <…>, <…> }`): text is the keyword; `number` is where the keyword
    // starts in TokenBuffer::text, and its vector_size entries (<u, v> in
    // uv_vectors, else 3 numbers) are read from there again when the mesh
    // is made (visit_mesh2_entries), not kept as numbers beside the text.
    // Only a section the grammar would read without complaint is one token.
    Mesh2Section,
    String,      // text holds the decoded string
    Identifier,  // text: keyword or user name (classified later)
    Directive,   // text: the name after '#', e.g. "declare"
    Punct,       // text: one of { } ( ) [ ] < > <= >= = != + - * / , ; . ? : & | !
};

// A literal vector such as a mesh's `<0.25, -1, 3>` is one token, not seven:
// mesh data is most of a big scene's text, and a token costs far more than
// its numbers. Its text is "<"; its components are TokenBuffer::vector_components
// from index `number`, `vector_size` of them.
// What an identifier's spelling makes it, whatever the scene declares:
// found in the word tables the first time the token is read and kept, as a
// loop reads the same token again at each pass.
enum class WordClass : std::uint8_t {
    Unknown,  // not looked up yet
    Keyword,  // RawToken::keyword_token holds its token kind
    // Before a '{', a block lancer skips with a warning (radiosity { … }):
    IgnoredBlock,    // a word that is nothing else
    IgnoredKeyword,  // a keyword too (mm_per_unit), as Keyword otherwise
    Builtin,         // a built-in function
    Constant,        // x, pi, clock, true ...
    Unsupported,     // a POV-Ray word lancer refuses with a clear error
    Name,            // none of these: a scene's own name (or undeclared)
};

struct RawToken {
    RawKind kind = RawKind::Punct;
    // Identifiers only. Both fit in what would be padding before vector_size.
    mutable WordClass word_class = WordClass::Unknown;
    mutable std::int16_t keyword_token = 0;
    std::uint32_t vector_size = 0;
    std::string text;
    double number = 0.0;
    sg::SourceLocation location;
};

// One scanned file (or string). Lines are kept for diagnostics (caret lines).
struct TokenBuffer {
    std::shared_ptr<const std::string> label;  // file name as shown to the user
    std::string path;                          // resolved path ("" for strings)
    std::string folder;                        // where relative paths resolve
    std::vector<RawToken> tokens;
    std::vector<double> vector_components;  // of the Vector tokens

    const double* components(const RawToken& vector) const {
        return vector_components.data() + static_cast<std::size_t>(vector.number);
    }
    // Line `line` (1-based) of the text, without its line break; empty past the end.
    std::string_view line(int line) const;
    int line_count() const { return static_cast<int>(line_starts().size()); }
    // Offset of each line in text: found at the first diagnostic that
    // shows a line of this file, not for every file (a mesh written a
    // vertex a line has millions of lines). The parser runs on one thread.
    const std::vector<std::size_t>& line_starts() const;

    std::string text;  // as scanned, for diagnostics' caret lines

  private:
    mutable std::vector<std::size_t> m_line_starts;
    mutable bool m_lines_found = false;
};

// Scans `text` into `buffer.tokens`. Invalid UTF-8, NUL bytes, unterminated
// strings or comments and stray characters become located errors appended
// to `diagnostics`; returns false if any error was found.
bool scan_text(std::string text, TokenBuffer& buffer, std::vector<Diagnostic>& diagnostics);

// Calls visit(numbers) with each entry of a RawKind::Mesh2Section token of
// `buffer`, in order: the numbers the grammar would read (2 for uv_vectors,
// else 3).
void visit_mesh2_entries(const TokenBuffer& buffer, const RawToken& section,
                         const std::function<void(const double*)>& visit);

}  // namespace lancer::parse
