// POV-Ray's user files, as POV-Ray 3.7 reads and writes them (Parse_Fopen,
// Parse_Read, Parse_Write, Parse_Fclose in its tokenize.cpp):
//
//   #fopen Name "file" read | write | append
//   #read (Name, Var1, Var2, …)    floats, vectors and strings, comma-separated
//   #write (Name, item, …)         strings as they are, floats %g, vectors <%g,…>
//   #fclose Name
//
// A file read to its end (its last value read) is closed and Name
// undefined, so `#while (defined(Name)) #read (Name, V) … #end` reads every
// value once.
// Writing follows the user's rights, as in POV; --safe confines reads to the
// scene's folder and the include path, and writes to the scene's folder.
#include <cmath>
#include <cstdio>
#include <fstream>

#include "evaluator.h"

namespace lancer::parse {

struct UserFile {
    std::string name;  // as the scene wrote it
    std::string path;
    bool reading = false;
    std::ofstream out;
    TokenBuffer data;  // a read file's values, scanned as scene text
    std::size_t position = 0;
    bool open = true;
};

namespace {

std::string format_number(double x) {
    char text[64];
    std::snprintf(text, sizeof text, "%g", x);
    return text;
}

}  // namespace

// `#read (F, …` / `#write (F, …`: the opening parenthesis and the handle,
// which must name a file open the directive's way. Null (reported) if not.
std::shared_ptr<UserFile> Evaluator::user_file_argument(const RawToken& d, bool reading, std::string& handle) {
    if (!expect_raw_punct("(", "after #" + d.text)) {
        abort_parse();
        return nullptr;
    }
    sg::SourceLocation where = d.location;
    handle = expect_raw_identifier("in #" + d.text, &where);
    const Value* value = handle.empty() ? nullptr : lookup(handle);
    if (!value || value->kind != Value::Kind::File || !value->file() || !value->file()->open) {
        error(where, "#" + d.text + " needs a file opened with #fopen" +
                         (handle.empty() ? std::string() : ", and '" + handle + "' is none"));
        abort_parse();
        return nullptr;
    }
    if (value->file()->reading != reading) {
        error(where, reading ? "cannot #read from \"" + value->file()->name + "\": it was opened to write"
                             : "cannot #write to \"" + value->file()->name + "\": it was opened to read");
        abort_parse();
        return nullptr;
    }
    return value->file();
}

void Evaluator::directive_fopen(const RawToken& d) {
    sg::SourceLocation where = d.location;
    const std::string handle = expect_raw_identifier("after #fopen", &where);
    if (handle.empty() || is_reserved_word(handle)) {
        error(where, "expected a new identifier for the file after #fopen");
        return abort_parse();
    }
    Value name_value = parse_nested(Parser::token::TOK_START_STRING, d.location, true);
    rewind_lookahead();
    if (m_aborted) return;
    if (name_value.kind != Value::Kind::String || name_value.text.empty()) {
        error(d.location, "expected a file name string after #fopen " + handle);
        return abort_parse();
    }
    sg::SourceLocation mode_at = d.location;
    const std::string mode = expect_raw_identifier("after the file name", &mode_at);
    if (mode != "read" && mode != "write" && mode != "append") {
        error(mode_at, "#fopen expects read, write or append after the file name");
        return abort_parse();
    }
    auto file = std::make_shared<UserFile>();
    file->name = name_value.text;
    file->reading = mode == "read";
    if (file->reading) {
        // POV looks in the current folder, then where the scene's files are.
        std::vector<std::string> folders{""};
        for (const auto& folder : search_folders(d.location)) folders.push_back(folder);
        const FileSearch search = find_file(file->name, folders, d.location, "user file", file->path);
        if (search == FileSearch::Refused) return abort_parse();
        if (search == FileSearch::Missing) {
            error(d.location, "cannot open user file \"" + file->name + "\" to read: it is not there");
            return abort_parse();
        }
        std::string text;
        if (!read_file(file->path, d.location, "user file", text)) return abort_parse();
        file->data.label = std::make_shared<const std::string>(file->name);
        file->data.path = file->path;
        std::vector<Diagnostic> problems;
        if (!scan_text(std::move(text), file->data, problems)) {
            for (Diagnostic& problem : problems) add_diagnostic(problem.severity, problem.location, problem.message);
            return abort_parse();
        }
    } else {
        file->path = file->name;
        if (!allowed_write(file->path)) {
            error(d.location,
                  "user file \"" + file->name + "\" is outside the scene's folder: --safe refuses to write it");
            return abort_parse();
        }
        file->out.open(file->path, mode == "append" ? std::ios::binary | std::ios::app : std::ios::binary);
        if (!file->out) {
            error(d.location, "cannot open user file \"" + file->name + "\" to " + mode);
            return abort_parse();
        }
    }
    Value value;
    value.kind = Value::Kind::File;
    value.payload = std::move(file);
    value.location = where;
    store(handle, std::move(value), false, where);
}

void Evaluator::directive_fclose(const RawToken& d) {
    sg::SourceLocation where = d.location;
    const std::string handle = expect_raw_identifier("after #fclose", &where);
    // POV quietly accepts #fclose of a file already closed by reading it out.
    const Value* value = handle.empty() ? nullptr : lookup(handle);
    if (!value) return;
    if (value->kind != Value::Kind::File || !value->file()) {
        error(where, "#fclose needs a file opened with #fopen, and '" + handle + "' is none");
        return abort_parse();
    }
    close_user_file(handle);
}

void Evaluator::close_user_file(const std::string& handle) {
    const Value* value = lookup(handle);
    if (value && value->kind == Value::Kind::File && value->file()) {
        value->file()->open = false;
        if (value->file()->out.is_open()) value->file()->out.close();
    }
    for (auto scope = m_scopes.rbegin(); scope != m_scopes.rend(); ++scope)
        if (scope->erase(handle)) return;
}

void Evaluator::directive_write(const RawToken& d) {
    std::string handle;
    const auto file = user_file_argument(d, false, handle);
    if (!file) return;
    std::string text;
    while (!m_aborted) {
        if (take_punct(")")) break;
        if (take_punct(",")) continue;
        if (const int type = take_binary_type(); type >= 0) {
            write_binary_values(d, type, text);
            continue;
        }
        std::optional<Value> plain = read_plain_item();
        Value item = plain ? std::move(*plain) : parse_nested(Parser::token::TOK_START_VALUE, d.location, false);
        if (m_aborted) return;
        if (item.kind == Value::Kind::String) {
            text += item.text;
        } else if (item.kind == Value::Kind::Float) {
            text += format_number(item.v[0]);
        } else if (item.kind == Value::Kind::Vector || item.kind == Value::Kind::Color) {
            const int size = item.kind == Value::Kind::Color ? 5 : item.size;
            text += "<";
            for (int i = 0; i < size; ++i) text += (i ? "," : "") + format_number(item.v[std::size_t(i)]);
            text += "> ";
        } else {
            error(d.location, "#write writes strings, floats and vectors, not " + describe(item));
            return abort_parse();
        }
    }
    file->out << text;
    if (!file->out) {
        error(d.location, "cannot write to user file \"" + file->name + "\"");
        return abort_parse();
    }
}

namespace {

// POV-Ray's binary items of #write: `uint8 v`, `sint16le <a, b>` … write
// each number rounded and clamped to the type, in its byte order.
struct BinaryTypeSpec {
    const char* name;
    long lowest, highest;
    int bytes;
    bool big_endian;
};
constexpr BinaryTypeSpec kBinaryTypes[] = {
    {"sint8", -128, 127, 1, false},
    {"uint8", 0, 255, 1, false},
    {"sint16le", -32768, 32767, 2, false},
    {"sint16be", -32768, 32767, 2, true},
    {"uint16le", 0, 65535, 2, false},
    {"uint16be", 0, 65535, 2, true},
    {"sint32le", -2147483648L, 2147483647L, 4, false},
    {"sint32be", -2147483648L, 2147483647L, 4, true},
};

}  // namespace

int Evaluator::take_binary_type() {
    for (std::size_t i = 0; i < std::size(kBinaryTypes); ++i)
        if (take_raw(RawKind::Identifier, kBinaryTypes[i].name)) return int(i);
    return -1;
}

// After a binary type, numbers and vectors up to the next `,` or `)`, each
// component in that type.
void Evaluator::write_binary_values(const RawToken& d, int type_index, std::string& out) {
    const BinaryTypeSpec& type = kBinaryTypes[type_index];
    int written = 0;
    while (!m_aborted) {
        if (next_is_raw(RawKind::Punct, ",") || next_is_raw(RawKind::Punct, ")")) break;
        const Value item = parse_nested(Parser::token::TOK_START_VALUE, d.location, false);
        if (m_aborted) return;
        int terms = 0;
        if (item.kind == Value::Kind::Float)
            terms = 1;
        else if (item.kind == Value::Kind::Vector)
            terms = item.size;
        else if (item.kind == Value::Kind::Color)
            terms = 5;
        if (terms < 1 || terms > 5) {
            error(d.location,
                  std::string("#write: ") + type.name + " writes numbers and vectors, not " + describe(item));
            return abort_parse();
        }
        for (int i = 0; i < terms; ++i) {
            const double x = item.v[std::size_t(i)];
            const long value = x <= double(type.lowest)    ? type.lowest
                               : x >= double(type.highest) ? type.highest
                               : x == x                    ? long(std::floor(x + 0.5))
                                                           : 0;
            for (int byte = 0; byte < type.bytes; ++byte) {
                const int shift = (type.big_endian ? type.bytes - 1 - byte : byte) * 8;
                out += char((value >> shift) & 0xFF);
            }
        }
        ++written;
    }
    if (written == 0 && !m_aborted) {
        error(d.location, std::string("#write: ") + type.name + " needs a number or vector after it");
        abort_parse();
    }
}

void Evaluator::directive_read(const RawToken& d) {
    std::string handle;
    const auto file = user_file_argument(d, true, handle);
    if (!file) return;
    bool at_end = false;
    while (!m_aborted) {
        if (take_punct(")")) break;
        if (take_punct(",")) continue;
        sg::SourceLocation variable_at = d.location;
        const std::string variable = expect_raw_identifier("in #read", &variable_at);
        if (variable.empty() || is_reserved_word(variable)) {
            error(variable_at, "#read expects identifiers to read values into");
            return abort_parse();
        }
        if (at_end) continue;
        std::optional<Value> value = read_user_value(*file);
        if (m_aborted) return;
        if (!value) {
            at_end = true;
            continue;
        }
        store(variable, std::move(*value), false, variable_at);
        // POV-Ray notices the end right after the last value (its check for
        // a comma meets it), so the loop idiom reads no value twice.
        at_end = at_user_file_end(*file);
    }
    if (at_end) close_user_file(handle);
}

bool Evaluator::at_user_file_end(UserFile& file) {
    const std::vector<RawToken>& tokens = file.data.tokens;
    while (file.position < tokens.size() && tokens[file.position].kind == RawKind::Punct &&
           tokens[file.position].text == ",")
        ++file.position;
    return file.position >= tokens.size();
}

// The next value of a read file: a signed float, a vector <a, b, …> of 2 to
// 5 floats, or a string; commas between values are skipped. Nothing at the
// end of the file.
std::optional<Value> Evaluator::read_user_value(UserFile& file) {
    const std::vector<RawToken>& tokens = file.data.tokens;
    auto punct = [&](const char* p) {
        return file.position < tokens.size() && tokens[file.position].kind == RawKind::Punct &&
               tokens[file.position].text == p;
    };
    auto fail = [&](const std::string& message) -> std::optional<Value> {
        const sg::SourceLocation at =
            file.position < tokens.size() ? tokens[file.position].location : sg::SourceLocation{file.data.label};
        error(at, message);
        abort_parse();
        return std::nullopt;
    };
    auto signed_number = [&](double& out) {
        double sign = 1.0;
        while (punct("+") || punct("-")) {
            if (tokens[file.position].text == "-") sign = -sign;
            ++file.position;
        }
        if (file.position >= tokens.size() || tokens[file.position].kind != RawKind::Number) return false;
        out = sign * tokens[file.position++].number;
        return true;
    };
    if (at_user_file_end(file)) return std::nullopt;
    const RawToken& first = tokens[file.position];
    if (first.kind == RawKind::String) {
        ++file.position;
        return Value::string(first.text);
    }
    if (first.kind == RawKind::Vector) {
        ++file.position;
        const double* components = file.data.components(first);
        Value value;
        value.kind = first.vector_size == 5 ? Value::Kind::Color : Value::Kind::Vector;
        value.size = static_cast<int>(first.vector_size);
        for (std::uint32_t i = 0; i < first.vector_size; ++i) value.v[i] = components[i];
        return value;
    }
    if (punct("<")) {
        ++file.position;
        std::vector<double> components;
        while (!punct(">")) {
            double x = 0.0;
            if (!signed_number(x)) return fail("expected a number in the vector read from \"" + file.name + "\"");
            components.push_back(x);
            if (components.size() > 5) return fail("a vector read from \"" + file.name + "\" has over 5 components");
            while (punct(",")) ++file.position;
        }
        ++file.position;
        if (components.size() < 2) return fail("a vector read from \"" + file.name + "\" needs 2 components or more");
        Value value;
        value.kind = Value::Kind::Vector;
        value.size = int(components.size());
        for (std::size_t i = 0; i < components.size(); ++i) value.v[i] = components[i];
        if (components.size() == 5) value.kind = Value::Kind::Color;
        return value;
    }
    double x = 0.0;
    if (!signed_number(x)) return fail("expected a float, vector or string in \"" + file.name + "\"");
    return Value::number(x);
}

}  // namespace lancer::parse
