// Diagnostics: located errors and warnings with the source line, a caret,
// the include chain, and "did you mean" suggestions.
#include <algorithm>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "evaluator.h"

namespace lancer {

namespace {

const char* severity_name(Diagnostic::Severity severity) {
    switch (severity) {
    case Diagnostic::Severity::Error: return "error";
    case Diagnostic::Severity::Warning: return "warning";
    case Diagnostic::Severity::Note: return "note";
    }
    return "error";
}

std::string location_text(const sg::SourceLocation& where) {
    std::string text = where.file ? *where.file : std::string("<unknown>");
    if (where.line > 0) text += ":" + std::to_string(where.line);
    if (where.column > 0) text += ":" + std::to_string(where.column);
    return text;
}

std::string read_line(const sg::SourceLocation& where) {
    if (!where.file || where.line <= 0) return "";
    std::ifstream in(*where.file);
    std::string line;
    for (int i = 0; i < where.line && std::getline(in, line); ++i) {
    }
    return in ? line : "";
}

// One character of a source line as the terminal is shown it: itself when
// printable (valid UTF-8 included), else an escape such as \x1b, so a scene
// cannot move the cursor, recolour or retitle the user's terminal.
struct ShownChar {
    std::string text;
    int width;  // columns it takes; a tab is kept and counted as one
};

std::vector<ShownChar> shown_chars(std::string_view line) {
    std::vector<ShownChar> chars;
    auto escaped = [](unsigned char byte) {
        static const char* hex = "0123456789abcdef";
        return ShownChar{std::string("\\x") + hex[byte >> 4] + hex[byte & 15], 4};
    };
    for (std::size_t i = 0; i < line.size();) {
        const unsigned char lead = static_cast<unsigned char>(line[i]);
        if (lead < 0x80) {
            if (lead == '\t')
                chars.push_back({"\t", 1});
            else if (lead < 0x20 || lead == 0x7f)
                chars.push_back(escaped(lead));
            else
                chars.push_back({std::string(1, char(lead)), 1});
            ++i;
            continue;
        }
        const std::size_t length = lead >= 0xF0 ? 4 : lead >= 0xE0 ? 3 : lead >= 0xC2 ? 2 : 0;
        bool valid = length > 0 && lead < 0xF5 && i + length <= line.size();
        for (std::size_t k = 1; valid && k < length; ++k)
            valid = (static_cast<unsigned char>(line[i + k]) & 0xC0) == 0x80;
        // C1 controls (U+0080..U+009F) are terminal escapes too.
        if (valid && length == 2 && lead == 0xC2 && static_cast<unsigned char>(line[i + 1]) < 0xA0) valid = false;
        if (!valid) {
            chars.push_back(escaped(lead));
            ++i;
            continue;
        }
        chars.push_back({std::string(line.substr(i, length)), 1});
        i += length;
    }
    return chars;
}

// Source lines longer than this are shown as a window around the caret.
constexpr std::size_t kShownColumns = 100;

}  // namespace

std::string escape_for_terminal(std::string_view text) {
    std::string out;
    for (const ShownChar& c : shown_chars(text)) out += c.text == "\t" ? std::string("\\t") : c.text;
    return out;
}

std::string format_diagnostic(const Diagnostic& diagnostic) {
    std::ostringstream out;
    out << escape_for_terminal(location_text(diagnostic.location)) << ": " << severity_name(diagnostic.severity) << ": "
        << escape_for_terminal(diagnostic.message) << "\n";
    std::string line = diagnostic.source_line.empty() ? read_line(diagnostic.location) : diagnostic.source_line;
    if (!line.empty() && diagnostic.location.column > 0) {
        if (line.back() == '\r') line.pop_back();
        const std::vector<ShownChar> chars = shown_chars(line);
        // The caret goes under the column-th code point.
        const std::size_t caret = std::min(std::size_t(diagnostic.location.column - 1), chars.size());
        std::size_t first = 0, last = chars.size();
        if (chars.size() > kShownColumns) {
            first = caret > kShownColumns / 2 ? caret - kShownColumns / 2 : 0;
            last = std::min(chars.size(), first + kShownColumns);
        }
        std::string text = first > 0 ? "..." : "", pad = first > 0 ? "   " : "";
        for (std::size_t i = first; i < last; ++i) {
            text += chars[i].text;
            if (i < caret)
                pad += chars[i].text == "\t" ? std::string("\t") : std::string(std::size_t(chars[i].width), ' ');
        }
        if (last < chars.size()) text += "...";
        out << "  " << text << "\n  " << pad << "^\n";
    }
    for (const auto& from : diagnostic.include_chain)
        out << escape_for_terminal(location_text(from)) << ": note: included from here\n";
    return out.str();
}

namespace parse {

size_t edit_distance(const std::string& a, const std::string& b) {
    std::vector<size_t> previous(b.size() + 1), current(b.size() + 1);
    for (size_t j = 0; j <= b.size(); ++j) previous[j] = j;
    for (size_t i = 1; i <= a.size(); ++i) {
        current[0] = i;
        for (size_t j = 1; j <= b.size(); ++j) {
            size_t substitution = previous[j - 1] + (std::tolower(a[i - 1]) == std::tolower(b[j - 1]) ? 0 : 1);
            current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
        }
        std::swap(previous, current);
    }
    return previous[b.size()];
}

std::string Evaluator::suggestion(const std::string& name) const {
    std::vector<std::string> candidates;
    // In each table's alphabetical order, so that a tie goes to the same
    // name on every run.
    auto add_sorted = [&candidates](const auto& table) {
        const std::size_t first = candidates.size();
        for (const auto& entry : table) candidates.push_back(entry.first);
        std::sort(candidates.begin() + std::ptrdiff_t(first), candidates.end());
    };
    for (const auto& scope : m_scopes) add_sorted(scope);
    add_sorted(m_macros);
    for (int k = Parser::symbol_kind::S_SPHERE; k < Parser::symbol_kind::YYNTOKENS; ++k)
        candidates.push_back(Parser::symbol_name(static_cast<Parser::symbol_kind_type>(k)));
    std::string best;
    // Short names tolerate one edit: two would make "Nope" a "cone".
    size_t best_distance = std::max<size_t>(1, name.size() / 3) + 1;
    for (const auto& candidate : candidates) {
        if (candidate == name) continue;
        // The distance is at least the difference in length: most
        // candidates are ruled out without the quadratic comparison.
        const size_t length_gap =
            candidate.size() > name.size() ? candidate.size() - name.size() : name.size() - candidate.size();
        if (length_gap >= best_distance) continue;
        size_t distance = edit_distance(name, candidate);
        if (distance < best_distance) {
            best_distance = distance;
            best = candidate;
        }
    }
    return best;
}

bool Evaluator::add_diagnostic(Diagnostic::Severity severity, const sg::SourceLocation& where,
                               const std::string& message) {
    if (severity != Diagnostic::Severity::Error) {
        // A warning inside a loop repeats every iteration: keep the first
        // ones and drop the rest, so a long loop cannot fill memory.
        if (++m_warning_count > kMaxWarnings) return false;
    }
    Diagnostic diagnostic;
    diagnostic.severity = severity;
    diagnostic.location = where;
    diagnostic.message = message;
    if (where.file) {
        auto chain = m_include_chains.find(where.file.get());
        if (chain != m_include_chains.end()) diagnostic.include_chain = chain->second;
        auto buffer = m_buffers.find(where.file.get());
        if (buffer != m_buffers.end() && where.line >= 1 && where.line <= buffer->second->line_count())
            diagnostic.source_line = std::string(buffer->second->line(where.line));
    }
    m_diagnostics.push_back(std::move(diagnostic));
    if (m_warning_count == kMaxWarnings && severity != Diagnostic::Severity::Error) {
        Diagnostic last;
        last.severity = Diagnostic::Severity::Note;
        last.location = where;
        last.location.column = 0;
        last.message = "more than " + std::to_string(kMaxWarnings) + " warnings and notes; the rest are not shown";
        m_diagnostics.push_back(std::move(last));
    }
    return true;
}

void Evaluator::error(const sg::SourceLocation& where, const std::string& message) {
    add_diagnostic(Diagnostic::Severity::Error, where, message);
    if (++m_error_count >= 30) {
        if (m_error_count == 30) note(where, "too many errors; stopping");
        abort_parse();
    }
}

void Evaluator::warning(const sg::SourceLocation& where, const std::string& message) {
    add_diagnostic(Diagnostic::Severity::Warning, where, message);
}

void Evaluator::note(const sg::SourceLocation& where, const std::string& message) {
    add_diagnostic(Diagnostic::Severity::Note, where, message);
}

void Evaluator::ignored(const sg::SourceLocation& where, const std::string& what) {
    warning(where, what + " is accepted but ignored by lancer");
}

void Evaluator::dispersion_samples(const sg::SourceLocation& keyword, const Value& count, const SourceRange& where) {
    const double n = to_float(count, where, "a number of dispersion samples");
    if (count.kind == Value::Kind::Float && !(int(std::clamp(n, -1e9, 1e9)) >= 2)) {
        error(where.begin, "dispersion_samples must be at least 2, got " + std::to_string(n) + " (as in POV-Ray)");
        return;
    }
    ignored(keyword, "dispersion_samples");
}

void Evaluator::unknown_identifier(const std::string& name, const sg::SourceLocation& where,
                                   const std::string& expected) {
    std::string near = suggestion(name);
    error(where, "unknown identifier '" + name + "' (expected " + expected + ")" +
                     (near.empty() ? "" : "; did you mean '" + near + "'?"));
}

void Evaluator::syntax_error(const SourceRange& where, const std::string& message) {
    if (m_aborted || m_suppress_syntax_errors) {
        abort_parse();
        return;
    }
    // Bison says "syntax error, unexpected X, expecting A or B".
    std::string text = message;
    const std::string prefix = "syntax error, ";
    if (text.rfind(prefix, 0) == 0) text = text.substr(prefix.size());
    size_t expecting = text.find(", expecting ");
    std::string unexpected = expecting == std::string::npos ? text : text.substr(0, expecting);
    std::string expected = expecting == std::string::npos ? "" : text.substr(expecting + 12);
    if (unexpected == "unexpected undeclared identifier" && !m_last_undeclared.empty()) {
        std::string near = suggestion(m_last_undeclared);
        unexpected = "unknown identifier '" + m_last_undeclared + "'";
        if (!near.empty()) unexpected += "; did you mean '" + near + "'?";
    }
    if (expected.empty()) {
        // Bison lists expectations only when there are few; say where we are instead.
        if (unexpected == "unexpected }" && !m_last_closed_block.empty()) {
            unexpected += " closing " + m_last_closed_block + " { }: a value or item is missing before it";
        } else if (m_block_names.empty()) {
            expected = "an object, light_source, camera, background, global_settings, render_settings or a directive";
        } else if (!m_block_names.back().empty()) {
            unexpected += " inside " + m_block_names.back() + " { }";
        }
    }
    text = unexpected + (expected.empty() ? "" : " (expected " + expected + ")");
    sg::SourceLocation at = where.begin;
    if (!at.file) at = m_last_location;
    error(at, text);
    abort_parse();
}

}  // namespace parse
}  // namespace lancer
