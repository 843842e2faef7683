// Raw tokens: what the flex scanner produces for one file, before directives
// run and identifiers are looked up. A whole file is scanned up front into a
// vector so #while and #macro can replay token ranges by index.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "lancer/parser.h"
#include "lancer/scene_graph.h"

namespace lancer::parse {

enum class RawKind {
    Number,      // number holds the value
    String,      // text holds the decoded string
    Identifier,  // text: keyword or user name (classified later)
    Directive,   // text: the name after '#', e.g. "declare"
    Punct,       // text: one of { } ( ) [ ] < > <= >= = != + - * / , ; . ? : & | !
};

struct RawToken {
    RawKind kind = RawKind::Punct;
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
    std::vector<std::string> lines;
};

// Scans `text` into `buffer.tokens`. Invalid UTF-8, NUL bytes, unterminated
// strings or comments and stray characters become located errors appended
// to `diagnostics`; returns false if any error was found.
bool scan_text(const std::string& text, TokenBuffer& buffer, std::vector<Diagnostic>& diagnostics);

}  // namespace lancer::parse
