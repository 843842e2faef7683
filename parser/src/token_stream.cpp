// The token stream: frames of raw tokens (files, macro bodies) read in
// order, directives executed on the way, identifiers resolved to typed
// tokens. See evaluator.h for why the directive layer sits here.
#include <algorithm>
#include <chrono>
#include <cstdint>
#include <unordered_map>
#include <unordered_set>

#include "evaluator.h"

namespace lancer::parse {

namespace {

using Kind = Parser::token_kind_type;
using SymbolKind = Parser::symbol_kind_type;

// Keywords are exactly the grammar's token aliases from "sphere" onwards.
const std::unordered_map<std::string, Kind>& keyword_table() {
    static const auto table = [] {
        std::unordered_map<std::string, Kind> map;
        for (int k = Parser::symbol_kind::S_SPHERE; k < Parser::symbol_kind::YYNTOKENS; ++k) {
            map.emplace(Parser::symbol_name(static_cast<SymbolKind>(k)), static_cast<Kind>(k));
        }
        return map;
    }();
    return table;
}

const std::unordered_map<std::string, Kind>& punct_table() {
    static const std::unordered_map<std::string, Kind> table = {
        {"{", Parser::token::TOK_LBRACE}, {"}", Parser::token::TOK_RBRACE},   {"(", Parser::token::TOK_LPAREN},
        {")", Parser::token::TOK_RPAREN}, {"[", Parser::token::TOK_LBRACKET}, {"]", Parser::token::TOK_RBRACKET},
        {"<", Parser::token::TOK_LT},     {">", Parser::token::TOK_GT},       {"<=", Parser::token::TOK_LE},
        {">=", Parser::token::TOK_GE},    {"=", Parser::token::TOK_EQ},       {"!=", Parser::token::TOK_NE},
        {"+", Parser::token::TOK_PLUS},   {"-", Parser::token::TOK_MINUS},    {"*", Parser::token::TOK_STAR},
        {"/", Parser::token::TOK_SLASH},  {",", Parser::token::TOK_COMMA},    {";", Parser::token::TOK_SEMI},
        {".", Parser::token::TOK_DOT},    {"?", Parser::token::TOK_QUESTION}, {":", Parser::token::TOK_COLON},
        {"&", Parser::token::TOK_AND},    {"|", Parser::token::TOK_OR},       {"!", Parser::token::TOK_NOT},
    };
    return table;
}

const std::unordered_set<std::string>& builtin_names() {
    // clang-format off
    static const std::unordered_set<std::string> names = {
        "abs",         "sqrt",         "pow",         "exp",        "log",           "ln",         "sin",    "cos",
        "tan",         "asin",         "acos",        "atan",       "atan2",         "sinh",       "cosh",   "tanh",
        "asinh",       "acosh",        "atanh",       "min",        "max",           "floor",      "ceil",   "mod",
        "int",         "div",          "radians",     "degrees",    "vlength",       "vnormalize", "vcross", "vdot",
        "vrotate",     "vaxis_rotate", "seed",        "rand",       "select",        "concat",     "str",    "strlen",
        "substr",      "chr",          "val",         "strupr",     "strlwr",        "vstr",       "asc",    "sqr",
        "bitwise_and", "bitwise_or",   "file_exists", "dimensions", "dimension_size", "vturbulence",
        "bitwise_xor", "strcmp",       "datetime"};
    // clang-format on
    return names;
}

// Ignored POV blocks: swallowed with a warning so nothing is dropped silently.
const std::unordered_set<std::string>& ignored_blocks() {
    static const std::unordered_set<std::string> names = {"photons", "radiosity", "subsurface", "mm_per_unit"};
    return names;
}

// POV-Ray words lancer does not implement: a clear error beats "unknown identifier".
const std::unordered_set<std::string>& unsupported_words() {
    static const std::unordered_set<std::string> names = {"lemon", "layered", "dictionary"};
    return names;
}

bool is_valued(Kind kind) {
    return kind >= Parser::token::TOK_NUMBER && kind <= Parser::token::TOK_MESH2_SECTION;
}

const std::unordered_set<std::string>& constant_names() {
    static const std::unordered_set<std::string> names = {"x",
                                                          "y",
                                                          "z",
                                                          "t",
                                                          "u",
                                                          "v",
                                                          "pi",
                                                          "tau",
                                                          "true",
                                                          "yes",
                                                          "on",
                                                          "false",
                                                          "no",
                                                          "off",
                                                          "clock",
                                                          "clock_delta",
                                                          "frame_number",
                                                          "clock_on",
                                                          "now",
                                                          "initial_clock",
                                                          "final_clock",
                                                          "initial_frame",
                                                          "final_frame",
                                                          "version",
                                                          "image_width",
                                                          "image_height",
                                                          "defined"};
    return names;
}

}  // namespace

bool is_reserved_word(const std::string& name) {
    return keyword_table().count(name) || builtin_names().count(name) || constant_names().count(name) ||
           unsupported_words().count(name);
}

Evaluator::Evaluator(const ParseOptions& options) : m_options(options) {
    push_scope();  // the global scope
    // LANCER_INCLUDE_PATH and lancer's include/ are always searched last.
    for (const auto& dir : default_include_path()) {
        if (std::find(m_options.include_path.begin(), m_options.include_path.end(), dir) ==
            m_options.include_path.end())
            m_options.include_path.push_back(dir);
    }
    if (m_options.language_version) {
        m_language_version = *m_options.language_version;
        m_saw_version = true;
    }
}

SourceRange Evaluator::token_range(const RawToken& raw) const {
    SourceRange range{raw.location, raw.location};
    range.end.column += static_cast<int>(std::max<size_t>(raw.text.size(), 1)) - 1;
    return range;
}

Evaluator::Symbol Evaluator::make_symbol(Kind kind, const RawToken& raw, Value value) {
    const SourceRange range = token_range(raw);
    if (is_valued(kind)) return Symbol(kind, TokenValue{raw.text, std::move(value)}, range);
    return Symbol(kind, range);
}

bool Evaluator::push_file(std::string text, const std::string& label, const std::string& path,
                          const std::string& folder, const sg::SourceLocation& included_from) {
    auto buffer = std::make_shared<TokenBuffer>();
    buffer->label = std::make_shared<const std::string>(label);
    buffer->path = path;
    buffer->folder = folder;
    // The include chain of this inclusion: where it was included, then that file's chain.
    std::vector<sg::SourceLocation> chain;
    if (included_from.file) {
        chain.push_back(included_from);
        auto outer = m_include_chains.find(included_from.file.get());
        if (outer != m_include_chains.end()) chain.insert(chain.end(), outer->second.begin(), outer->second.end());
    }
    m_include_chains[buffer->label.get()] = chain;
    size_t first_new = m_diagnostics.size();
    bool scanned = scan_text(std::move(text), *buffer, m_diagnostics);
    for (size_t i = first_new; i < m_diagnostics.size(); ++i) {
        m_diagnostics[i].include_chain = chain;
        if (m_diagnostics[i].severity == Diagnostic::Severity::Error) ++m_error_count;
    }
    m_buffers[buffer->label.get()] = buffer;
    if (!scanned) return false;
    auto frame = std::make_shared<Frame>();
    frame->buffer = buffer;
    frame->end = buffer->tokens.size();
    frame->owns_scope = true;
    frame->name = label;
    frame->called_from = included_from;
    m_frames.push_back(frame);
    push_scope();
    return true;
}

void Evaluator::pop_frame() {
    Frame& frame = *m_frames.back();
    if (!frame.controls.empty() && !m_aborted) {
        const Control& open = frame.controls.back();
        static const char* names[] = {"#if", "#while", "#for", "#switch", "#macro"};
        error(open.opened_at,
              std::string(names[static_cast<int>(open.kind)]) + " has no matching #end" +
                  (frame.is_macro ? " inside macro '" + frame.name + "'" : " before the end of the file"));
        abort_parse();
    }
    if (frame.owns_scope && m_scopes.size() > 1) pop_scope();
    if (frame.is_macro) --m_macro_depth;
    m_frames.pop_back();
}

const RawToken* Evaluator::peek_raw() {
    if (m_frames.empty()) return nullptr;
    Frame& frame = *m_frames.back();
    return frame.position < frame.end ? &frame.buffer->tokens[frame.position] : nullptr;
}

const RawToken* Evaluator::take_raw() {
    while (!m_frames.empty()) {
        Frame& frame = *m_frames.back();
        if (frame.position < frame.end) return &frame.buffer->tokens[frame.position++];
        pop_frame();
    }
    return nullptr;
}

bool Evaluator::directives_blocked() const {
    return m_barrier_depth >= 0 && static_cast<int>(m_frames.size()) <= m_barrier_depth;
}

void Evaluator::abort_parse() {
    m_aborted = true;
}

Evaluator::Symbol Evaluator::next_token() {
    Symbol symbol = read_token();
    m_previous_kind = symbol.kind();
    return symbol;
}

// POV-Ray checks for the ';' after a declared value without invoking a
// macro (its Ok_To_Declare): `#declare C = "" M(C)` declares C, then calls
// M. Here the lookahead that ends a declared value is read while its
// barrier holds; a macro name right after a complete operand at the
// value's own nesting waits, like a directive, until the value is stored;
// so does one after the '}' that closes a declared block (screen.pov:
// `#declare T = texture { … }` then `Screen_Plane(T, …)`).
bool Evaluator::macro_waits_for_value_end() const {
    if (!directives_blocked() || m_nesting != m_barrier_nesting) return false;
    using T = Parser::symbol_kind;
    switch (m_previous_kind) {
    case T::S_NUMBER:
    case T::S_STRING:
    case T::S_CONSTANT:
    case T::S_VALUE_ID:
    case T::S_RPAREN:
    case T::S_RBRACE:
    case T::S_RBRACKET: return true;
    default: return false;
    }
}

Evaluator::Symbol Evaluator::read_token() {
    while (true) {
        if (m_aborted) {
            return Symbol(Parser::token::TOK_END, SourceRange{m_last_location, m_last_location});
        }
        const RawToken* raw = nullptr;
        const void* frame = nullptr;
        size_t index = 0;
        if (!m_pending.empty()) {
            Pending pending = std::move(m_pending.back());
            m_pending.pop_back();
            if (!pending.raw) {
                m_last_returned.reset();
                return *pending.symbol;
            }
            raw = pending.raw;
            frame = pending.frame;
            index = pending.index;
        } else {
            raw = take_raw();
            if (!raw) {
                m_last_returned.reset();
                return Symbol(Parser::token::TOK_END, SourceRange{m_last_location, m_last_location});
            }
            frame = m_frames.back().get();
            index = m_frames.back()->position - 1;
        }
        m_last_location = raw->location;
        m_last_location.column += static_cast<int>(raw->text.size());
        if (++m_tokens_read > 50'000'000L + 20 * m_options.max_loop_iterations) {
            error(raw->location, "the scene produces too many tokens (runaway loop or recursion?)");
            abort_parse();
            continue;
        }
        if (raw->kind == RawKind::Directive) {
            if (directives_blocked()) {
                m_last_returned = Pending{raw, nullptr, frame, index, false};
                return make_symbol(Parser::token::TOK_DIRECTIVE, *raw, Value::string("#" + raw->text));
            }
            run_directive(*raw);
            continue;
        }
        if (raw->kind == RawKind::Identifier) {
            const NameLookup found = find_name(HashedName(raw->text));
            if (!found.value && skip_ignored_block(*raw)) continue;
            // POV still reads the old `default { … }` as #default.
            if (raw->text == "default" && !found.value && !directives_blocked()) {
                const RawToken* next = peek_raw();
                if (next && next->kind == RawKind::Punct && next->text == "{") {
                    directive_default(*raw);
                    continue;
                }
            }
            if (raw->text == "function" && !found.value) {
                if (std::optional<Symbol> function = read_function(*raw)) {
                    m_last_returned.reset();
                    return std::move(*function);
                }
                continue;
            }
            if (const Value* named = found.value; named && named->kind == Value::Kind::Array) {
                const RawToken* next = peek_raw();
                if (next && next->kind == RawKind::Punct && next->text == "[") {
                    const std::shared_ptr<ArrayData> data = named->array();
                    std::size_t flat = 0;
                    Value element = array_element(*named, raw->location, &flat);
                    m_last_returned.reset();
                    if (m_aborted) continue;
                    m_previous_word = raw->text;
                    Symbol symbol = make_symbol(token_for_value(element), *raw, std::move(element));
                    m_last_identifier = IdentifierUse{symbol.location, VariableReference{0, "", data, flat}};
                    return symbol;
                }
            }
            auto macro = found.value || m_macros.empty() ? m_macros.end() : m_macros.find(HashedName(raw->text));
            if (macro != m_macros.end()) {
                if (macro_waits_for_value_end()) {
                    m_last_returned = Pending{raw, nullptr, frame, index, false};
                    return make_symbol(Parser::token::TOK_DIRECTIVE, *raw, Value::string(raw->text));
                }
                auto keep = macro->second;
                expand_macro(*raw, *keep);
                continue;
            }
            m_last_returned = Pending{raw, nullptr, frame, index, false};
            m_previous_word = raw->text;
            return symbol_for_identifier(*raw, found);
        }
        m_last_returned = Pending{raw, nullptr, frame, index, raw->kind == RawKind::Punct};
        return classify(*raw);
    }
}

Value Evaluator::vector_literal(const RawToken& raw) const {
    Value result;
    result.kind = Value::Kind::Vector;
    result.size = static_cast<int>(raw.vector_size);
    const auto buffer = m_buffers.find(raw.location.file.get());
    if (buffer == m_buffers.end() || raw.vector_size < 2 || raw.vector_size > 5) return Value::vector({0, 0, 0});
    const double* components = buffer->second->components(raw);
    for (std::uint32_t i = 0; i < raw.vector_size; ++i) result.v[i] = components[i];
    return result;
}

Evaluator::Symbol Evaluator::classify(const RawToken& raw) {
    switch (raw.kind) {
    case RawKind::Number: return make_symbol(Parser::token::TOK_NUMBER, raw, Value::number(raw.number));
    case RawKind::String: return make_symbol(Parser::token::TOK_STRING, raw, Value::string(raw.text));
    case RawKind::Vector: return make_symbol(Parser::token::TOK_VECTOR_LITERAL, raw, vector_literal(raw));
    case RawKind::Mesh2Section: return make_symbol(Parser::token::TOK_MESH2_SECTION, raw, mesh2_section_token(raw));
    case RawKind::Punct: {
        const char bracket = raw.text.size() == 1 ? raw.text[0] : '\0';
        if (bracket == '{') m_block_names.push_back(m_previous_word);
        if (bracket == '}' && !m_block_names.empty()) {
            m_last_closed_block = m_block_names.back();
            m_block_names.pop_back();
        }
        if (bracket == '{' || bracket == '(' || bracket == '[') {
            if (++m_nesting > m_options.max_nesting_depth) {
                error(raw.location,
                      "nesting too deep: more than " + std::to_string(m_options.max_nesting_depth) + " open brackets");
                abort_parse();
            }
        } else if (bracket == '}' || bracket == ')' || bracket == ']') {
            --m_nesting;
        }
        return make_symbol(punct_table().at(raw.text), raw);
    }
    case RawKind::Identifier: m_previous_word = raw.text; return symbol_for_identifier(raw);
    case RawKind::Directive: break;
    }
    return make_symbol(Parser::token::TOK_DIRECTIVE, raw);
}

WordClass word_class_of(const RawToken& raw) {
    if (raw.word_class != WordClass::Unknown) return raw.word_class;
    const std::string& name = raw.text;
    if (auto keyword = keyword_table().find(name); keyword != keyword_table().end()) {
        raw.keyword_token = static_cast<std::int16_t>(keyword->second);
        raw.word_class = ignored_blocks().count(name) ? WordClass::IgnoredKeyword : WordClass::Keyword;
    } else {
        raw.word_class = ignored_blocks().count(name)      ? WordClass::IgnoredBlock
                         : builtin_names().count(name)     ? WordClass::Builtin
                         : constant_names().count(name)    ? WordClass::Constant
                         : unsupported_words().count(name) ? WordClass::Unsupported
                                                           : WordClass::Name;
    }
    return raw.word_class;
}

Evaluator::Symbol Evaluator::symbol_for_identifier(const RawToken& raw) {
    return symbol_for_identifier(raw, find_name(HashedName(raw.text)));
}

Evaluator::Symbol Evaluator::symbol_for_identifier(const RawToken& raw, const NameLookup& found) {
    const std::string& name = raw.text;
    WordClass word = word_class_of(raw);
    if (word == WordClass::IgnoredKeyword) word = WordClass::Keyword;
    // Integrator parameter names are free words, even when they spell a
    // keyword (whitted { fresnel on }); colour keywords stay values.
    if (word == WordClass::Keyword && !m_block_names.empty() && m_block_names.back() == "integrator" &&
        name.find("rgb") == std::string::npos && name != "color" && name != "colour") {
        m_last_undeclared = name;
        return make_symbol(Parser::token::TOK_UNDECLARED_ID, raw);
    }
    if (word == WordClass::Keyword) return make_symbol(static_cast<Kind>(raw.keyword_token), raw);
    if (word == WordClass::Builtin) return make_symbol(Parser::token::TOK_BUILTIN, raw);
    if (word == WordClass::Constant) return symbol_for_constant(raw);
    if (found.value) {
        if (!m_deprecated.empty())
            if (auto deprecated = m_deprecated.find(name); deprecated != m_deprecated.end()) {
                Deprecation& d = deprecated->second;
                if (!d.once || !d.warned)
                    warning(raw.location, "'" + name + "' is deprecated" + (d.message.empty() ? "" : ": " + d.message));
                d.warned = true;
            }
        Value copy = *found.value;
        copy.boolean_literal = false;
        Symbol symbol = make_symbol(token_for_value(copy), raw, std::move(copy));
        remember_identifier(symbol.location, name, found);
        return symbol;
    }
    if (word == WordClass::Unsupported) {
        error(raw.location, "'" + name + "' is a POV-Ray feature that lancer does not support");
        m_suppress_syntax_errors = true;
        abort_parse();
        return make_symbol(Parser::token::TOK_UNSUPPORTED, raw);
    }
    m_last_undeclared = name;
    return make_symbol(Parser::token::TOK_UNDECLARED_ID, raw);
}

// A constant or read-only built-in identifier (constant_names()).
Evaluator::Symbol Evaluator::symbol_for_constant(const RawToken& raw) {
    const std::string& name = raw.text;
    auto constant = [&](Value v) { return make_symbol(Parser::token::TOK_CONSTANT, raw, std::move(v)); };
    auto boolean = [&](bool on) {
        Value v = Value::number(on ? 1.0 : 0.0);
        v.boolean_literal = true;
        return constant(v);
    };
    if (name == "x") return constant(Value::vector({1, 0, 0}));
    if (name == "y") return constant(Value::vector({0, 1, 0}));
    if (name == "z") return constant(Value::vector({0, 0, 1}));
    if (name == "t") return constant(Value::vector({0, 0, 0, 1}));
    if (name == "u") return constant(Value::vector({1, 0}));
    if (name == "v") return constant(Value::vector({0, 1}));
    if (name == "pi") return constant(Value::number(3.14159265358979323846));
    if (name == "tau") return constant(Value::number(2.0 * 3.14159265358979323846));
    if (name == "true" || name == "yes" || name == "on") return boolean(true);
    if (name == "false" || name == "no" || name == "off") return boolean(false);
    {
        const AnimationFrame& a = m_options.animation;
        if (name == "clock") return constant(Value::number(a.clock));
        if (name == "clock_delta") return constant(Value::number(a.clock_delta));
        if (name == "clock_on") return boolean(a.clock_on);
        if (name == "frame_number") return constant(Value::number(a.frame_number));
        if (name == "initial_frame") return constant(Value::number(a.initial_frame));
        if (name == "final_frame") return constant(Value::number(a.final_frame));
        if (name == "initial_clock") return constant(Value::number(a.initial_clock));
        if (name == "final_clock") return constant(Value::number(a.final_clock));
    }
    if (name == "now") {
        // POV's: days since 2000-01-01 00:00 UTC, to the microsecond.
        constexpr std::int64_t kMicrosecondsFrom1970To2000 = 946684800LL * 1000000;
        const auto since_1970 =
            std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::system_clock::now().time_since_epoch());
        return constant(Value::number(double(since_1970.count() - kMicrosecondsFrom1970To2000) * 1e-6 / 86400.0));
    }
    if (name == "version") return constant(Value::number(m_language_version));
    if (name == "image_width" || name == "image_height") {
        bool width = name == "image_width";
        int size = width ? m_options.image_width : m_options.image_height;
        const auto& chosen = width ? m_scene.render.width : m_scene.render.height;
        if (!m_options.image_size_from_command_line && chosen) size = *chosen;
        return constant(Value::number(size));
    }
    if (name == "defined") {
        // defined(Name) must not resolve Name: read the raw tokens.
        bool ok = take_punct("(");
        sg::SourceLocation where;
        std::string target = ok ? expect_raw_identifier("in defined()", &where) : "";
        const bool defined_target = !target.empty() && identifier_defined(target, where);
        ok = ok && !target.empty() && !m_aborted && take_punct(")");
        if (!ok) {
            error(raw.location, "expected defined(identifier)");
            return boolean(false);
        }
        return boolean(defined_target);
    }
    error(raw.location, "internal: '" + name + "' is listed as a constant but has no value");
    abort_parse();
    return make_symbol(Parser::token::TOK_UNDECLARED_ID, raw);
}

// Declared values reach the grammar as tokens of their kind.
Evaluator::Kind Evaluator::token_for_value(const Value& value) {
    using VK = Value::Kind;
    switch (value.kind) {
    case VK::Object: return Parser::token::TOK_OBJECT_ID;
    case VK::Texture: return Parser::token::TOK_TEXTURE_ID;
    case VK::Pigment: return Parser::token::TOK_PIGMENT_ID;
    case VK::Finish: return Parser::token::TOK_FINISH_ID;
    case VK::Interior: return Parser::token::TOK_INTERIOR_ID;
    case VK::Media: return Parser::token::TOK_MEDIA_ID;
    case VK::SkySphere: return Parser::token::TOK_SKY_SPHERE_ID;
    case VK::Fog: return Parser::token::TOK_FOG_ID;
    case VK::Rainbow: return Parser::token::TOK_RAINBOW_ID;
    case VK::Camera: return Parser::token::TOK_CAMERA_ID;
    case VK::Light: return Parser::token::TOK_LIGHT_ID;
    case VK::Transform: return Parser::token::TOK_TRANSFORM_ID;
    case VK::Normal: return Parser::token::TOK_NORMAL_ID;
    case VK::ColorMap: return Parser::token::TOK_COLOR_MAP_ID;
    case VK::PigmentMap: return Parser::token::TOK_PIGMENT_MAP_ID;
    case VK::NormalMap: return Parser::token::TOK_NORMAL_MAP_ID;
    case VK::Function: return Parser::token::TOK_FUNCTION_ID;
    case VK::Spline: return Parser::token::TOK_SPLINE_ID;
    default: return Parser::token::TOK_VALUE_ID;
    }
}

// The caller has found that no variable has the keyword's name.
bool Evaluator::skip_ignored_block(const RawToken& keyword) {
    const WordClass word = word_class_of(keyword);
    if (word != WordClass::IgnoredBlock && word != WordClass::IgnoredKeyword) return false;
    const RawToken* next = peek_raw();
    if (!next || next->kind != RawKind::Punct || next->text != "{") return false;
    Frame& frame = *m_frames.back();
    int depth = 0;
    while (frame.position < frame.end) {
        const RawToken& token = frame.buffer->tokens[frame.position++];
        if (token.kind != RawKind::Punct) continue;
        if (token.text == "{") ++depth;
        if (token.text == "}" && --depth == 0) {
            warning(keyword.location, keyword.text + " { ... } is accepted but ignored by lancer");
            return true;
        }
    }
    error(next->location, "'{' after " + keyword.text + " has no matching '}'");
    abort_parse();
    return true;
}

void Evaluator::push_scope() {
    m_scopes.emplace_back();
    m_references.emplace_back();
}

void Evaluator::pop_scope() {
    m_scopes.pop_back();
    m_references.pop_back();
}

// Assigned in place: the last use's strings keep their room, so a loop
// that reads names allocates nothing here.
void Evaluator::remember_identifier(const SourceRange& range, const std::string& name, const NameLookup& found) {
    IdentifierUse& use = m_last_identifier ? *m_last_identifier : m_last_identifier.emplace();
    use.range = range;
    if (found.reference) {
        use.variable = *found.reference;
        return;
    }
    use.variable.scope = found.scope;
    use.variable.name.assign(name);
    use.variable.array.reset();
    use.variable.element = 0;
}

const Value* Evaluator::referenced_value(const VariableReference& reference) const {
    if (reference.array) {
        if (reference.element >= reference.array->elements.size()) return nullptr;
        const std::optional<Value>& element = reference.array->elements[reference.element];
        return element ? &*element : nullptr;
    }
    if (reference.scope >= m_scopes.size()) return nullptr;
    auto found = m_scopes[reference.scope].find(reference.name);
    return found == m_scopes[reference.scope].end() ? nullptr : &found->second;
}

void Evaluator::write_reference(const VariableReference& reference, Value value) {
    if (reference.array) {
        if (reference.element < reference.array->elements.size())
            reference.array->elements[reference.element] = std::move(value);
        return;
    }
    if (reference.scope < m_scopes.size()) m_scopes[reference.scope][reference.name] = std::move(value);
}

Evaluator::NameLookup Evaluator::find_name(const HashedName& name) const {
    for (std::size_t i = m_scopes.size(); i-- > 0;) {
        if (!m_references[i].empty())
            if (auto reference = m_references[i].find(name); reference != m_references[i].end())
                return NameLookup{referenced_value(reference->second), i, &reference->second};
        auto found = m_scopes[i].find(name);
        if (found != m_scopes[i].end()) return NameLookup{&found->second, i, nullptr};
    }
    return NameLookup{};
}

const Value* Evaluator::lookup(const std::string& name) const {
    return find_name(HashedName(name)).value;
}

void Evaluator::store(const std::string& name, Value value, bool local, const sg::SourceLocation& where,
                      std::optional<std::size_t> local_scope) {
    m_macros.erase(name);
    if (local) {
        const std::size_t scope = local_scope ? std::min(*local_scope, m_scopes.size() - 1) : m_scopes.size() - 1;
        if (auto reference = m_references[scope].find(name); reference != m_references[scope].end())
            return write_reference(reference->second, std::move(value));
        m_scopes[scope][name] = std::move(value);
        return;
    }
    // #declare updates the innermost existing local of that name (so a loop
    // counter made with #local can be advanced with #declare), or the
    // variable a macro parameter stands for; else the global.
    for (size_t i = m_scopes.size(); i-- > 1;) {
        if (auto reference = m_references[i].find(name); reference != m_references[i].end())
            return write_reference(reference->second, std::move(value));
        auto found = m_scopes[i].find(name);
        if (found != m_scopes[i].end()) {
            found->second = std::move(value);
            return;
        }
    }
    m_scopes.front()[name] = std::move(value);
}

// ---------------------------------------------------------------- nesting

Value Evaluator::parse_nested(Kind start, const sg::SourceLocation& at, bool barrier) {
    int saved_barrier = m_barrier_depth;
    int saved_base = m_nested_base_depth;
    m_nested_base_depth = static_cast<int>(m_frames.size());
    if (barrier) m_barrier_depth = m_nested_base_depth;
    m_nested_result.reset();
    m_nested_had_lookahead = false;
    m_pending.push_back(
        Pending{nullptr, std::make_shared<const Symbol>(start, SourceRange{at, at}), nullptr, 0, false});
    // Parsers are reused per nesting level: building one reserves its stack.
    size_t level = m_parser_depth++;
    if (m_parsers.size() <= level) m_parsers.push_back(std::make_unique<Parser>(*this));
    m_parsers[level]->parse();
    --m_parser_depth;
    m_barrier_depth = saved_barrier;
    m_nested_base_depth = saved_base;
    if (m_nested_result) {
        Value value = std::move(*m_nested_result);
        m_nested_result.reset();
        return value;
    }
    abort_parse();
    return Value::number(0.0);
}

void Evaluator::finish_nested(Value value, const SourceRange& where, bool had_lookahead) {
    m_nested_result = std::move(value);
    m_nested_had_lookahead = had_lookahead;
    if (had_lookahead && m_last_returned) {
        m_pending.push_back(*m_last_returned);
        m_last_returned.reset();
        rewind_lookahead();
    }
}

void Evaluator::finish_arguments(std::vector<MacroArgument> arguments) {
    m_nested_arguments = std::move(arguments);
    m_nested_result = Value::number(0.0);
}

MacroArgument Evaluator::macro_argument(Value value, const SourceRange& where) {
    MacroArgument argument{std::move(value), std::nullopt};
    auto same = [](const sg::SourceLocation& a, const sg::SourceLocation& b) {
        return a.line == b.line && a.column == b.column && a.file == b.file;
    };
    if (m_last_identifier && same(m_last_identifier->range.begin, where.begin) &&
        same(m_last_identifier->range.end, where.end))
        argument.reference = m_last_identifier->variable;
    return argument;
}

void Evaluator::begin_value_barrier() {
    m_barrier_depth = m_nested_base_depth;
    m_barrier_nesting = m_nesting;
}
void Evaluator::end_value_barrier() {
    m_barrier_depth = -1;
}

// Puts an unread lookahead back into its frame when it was the last token
// read there, so frame changes (includes, skipped branches) see it in order.
void Evaluator::rewind_lookahead() {
    if (m_pending.empty() || m_frames.empty()) return;
    const Pending& top = m_pending.back();
    Frame& frame = *m_frames.back();
    if (!top.raw || top.frame != &frame || top.index + 1 != frame.position) return;
    if (top.classified) {
        const std::string& p = top.raw->text;
        if (p == "{" || p == "(" || p == "[") --m_nesting;
        if (p == "}" || p == ")" || p == "]") ++m_nesting;
    }
    frame.position = top.index;
    m_pending.pop_back();
}

bool Evaluator::take_punct(const char* punct) {
    return take_raw(RawKind::Punct, punct);
}

bool Evaluator::next_is_raw(RawKind kind, std::string_view text) {
    rewind_lookahead();
    const RawToken* next = m_pending.empty() ? peek_raw() : m_pending.back().raw;
    return next && next->kind == kind && next->text == text;
}

bool Evaluator::take_raw(RawKind kind, std::string_view text) {
    if (!next_is_raw(kind, text)) return false;
    if (!m_pending.empty())
        m_pending.pop_back();
    else
        ++m_frames.back()->position;
    return true;
}

std::string Evaluator::expect_raw_identifier(const std::string& context, sg::SourceLocation* where) {
    rewind_lookahead();
    const RawToken* next = m_pending.empty() ? peek_raw() : nullptr;
    if (!next || next->kind != RawKind::Identifier) {
        return "";
    }
    ++m_frames.back()->position;
    if (where) *where = next->location;
    return next->text;
}

bool Evaluator::expect_raw_punct(const char* punct, const std::string& context) {
    if (take_punct(punct)) return true;
    sg::SourceLocation where;
    const RawToken* next = m_pending.empty() ? peek_raw() : m_pending.back().raw;
    if (next)
        where = next->location;
    else if (!m_frames.empty() && !m_frames.back()->buffer->tokens.empty())
        where = m_frames.back()->buffer->tokens.back().location;
    error(where,
          std::string("expected '") + punct + "' " + context +
              (next ? ", found '" +
                          (next->kind == RawKind::String ? "\"" + next->text + "\""
                                                         : (next->kind == RawKind::Directive ? "#" : "") + next->text) +
                          "'"
                    : ", found the end of the file"));
    abort_parse();
    return false;
}

}  // namespace lancer::parse
