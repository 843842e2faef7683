// Directives, executed by the token stream as it meets them: #declare,
// #local, #undef, conditionals, loops, #switch, #macro, #include, #version,
// #default and the message directives.
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "evaluator.h"
#include "parse_stack.h"

namespace lancer::parse {

namespace fs = std::filesystem;

namespace {

const char* control_name(Evaluator::Control::Kind kind) {
    switch (kind) {
    case Evaluator::Control::Kind::If: return "#if";
    case Evaluator::Control::Kind::While: return "#while";
    case Evaluator::Control::Kind::For: return "#for";
    case Evaluator::Control::Kind::Switch: return "#switch";
    case Evaluator::Control::Kind::Macro: return "#macro";
    }
    return "#if";
}

bool opens_block(const std::string& name) {
    return name == "if" || name == "ifdef" || name == "ifndef" || name == "while" || name == "for" ||
           name == "switch" || name == "macro";
}

}  // namespace

void Evaluator::run_directive(const RawToken& d) {
    const std::string& n = d.text;
    if (n == "declare") return directive_declare(d, false);
    if (n == "local") return directive_declare(d, true);
    if (n == "if") return directive_if(d, false, false);
    if (n == "ifdef") return directive_if(d, true, false);
    if (n == "ifndef") return directive_if(d, true, true);
    if (n == "else") return directive_else(d, false);
    if (n == "elseif") return directive_else(d, true);
    if (n == "while") return directive_while(d);
    if (n == "for") return directive_for(d);
    if (n == "switch") return directive_switch(d);
    if (n == "case") return directive_case(d, false);
    if (n == "range") return directive_case(d, true);
    if (n == "break") return directive_break(d);
    if (n == "end") return directive_end(d);
    if (n == "macro") return directive_macro(d);
    if (n == "include") return directive_include(d);
    if (n == "debug" || n == "warning" || n == "error") return directive_message(d);
    if (n == "undef") return directive_undef(d);
    if (n == "version") return directive_version(d);
    if (n == "default") return directive_default(d);
    if (n == "fopen") return directive_fopen(d);
    if (n == "fclose") return directive_fclose(d);
    if (n == "read") return directive_read(d);
    if (n == "write") return directive_write(d);
    if (n == "render") {
        error(d.location, "#" + n + " is a POV-Ray directive that lancer does not support");
    } else {
        static const std::vector<std::string> known = {
            "declare", "local",   "undef", "include", "if",    "ifdef",  "ifndef", "elseif", "else",
            "end",     "while",   "for",   "switch",  "case",  "range",  "break",  "macro",  "version",
            "debug",   "warning", "error", "default", "fopen", "fclose", "read",   "write"};
        std::string best;
        size_t best_distance = 3;
        for (const auto& k : known) {
            size_t distance = edit_distance(k, n);
            if (distance < best_distance) best_distance = distance, best = k;
        }
        error(d.location, "unknown directive '#" + n + "'" + (best.empty() ? "" : "; did you mean '#" + best + "'?"));
    }
    abort_parse();
}

// #declare Name = value [;]   /   #local Name = value [;]
void Evaluator::directive_declare(const RawToken& d, bool local) {
    sg::SourceLocation where = d.location;
    std::string name = expect_raw_identifier("after #" + d.text, &where);
    // POV 3.7's `#declare deprecated [once] "message" Name = ...`: using
    // Name later warns with the message (glass_old.inc marks its textures so).
    std::optional<Deprecation> deprecation;
    if (name == "deprecated" && !lookup(name)) {
        deprecation = Deprecation{};
        const RawToken* next = peek_raw();
        if (next && next->kind == RawKind::Identifier && next->text == "once") {
            deprecation->once = true;
            expect_raw_identifier("after 'deprecated'");
            next = peek_raw();
        }
        if (next && next->kind == RawKind::String) {
            deprecation->message = next->text;
            ++m_frames.back()->position;
        }
        name = expect_raw_identifier("after #" + d.text + " deprecated", &where);
    }
    if (name.empty()) {
        const RawToken* next = peek_raw();
        error(next ? next->location : d.location, "expected an identifier after #" + d.text);
        return abort_parse();
    }
    if (is_reserved_word(name)) {
        error(where, "cannot #" + d.text + " '" + name + "': it is a reserved word of the scene language");
        return abort_parse();
    }
    if (m_aborted) return;
    if (const RawToken* next = peek_raw(); next && next->kind == RawKind::Punct && next->text == "[")
        return assign_array_element(name, d, local, where);
    if (!expect_raw_punct("=", "after '#" + d.text + " " + name + "'")) return;
    // A block lancer ignores (sky_sphere, fog, media …) declares nothing;
    // the declaration must not read on into what follows.
    if (const RawToken* next = peek_raw(); next && next->kind == RawKind::Identifier && !lookup(next->text)) {
        const RawToken keyword = *next;
        ++m_frames.back()->position;
        if (skip_ignored_block(keyword)) {
            take_punct(";");
            return;
        }
        --m_frames.back()->position;
    }
    const std::size_t directive_depth = m_frames.size();
    const std::size_t directive_scope = m_scopes.size() - 1;
    std::optional<Value> plain = read_plain_value();
    Value value = plain ? std::move(*plain) : parse_nested(Parser::token::TOK_START_VALUE, d.location, false);
    if (m_aborted) return;
    // A value that a macro wrote (#local M = Matrix_Trans(…)) may end where
    // the macro's text does: leave the macro first, so the ';' is looked for
    // and the name stored where the directive stands, not in the macro's
    // own scope.
    while (m_frames.size() > directive_depth && m_pending.empty() && m_frames.back()->position >= m_frames.back()->end)
        pop_frame();
    bool terminated = take_punct(";");
    if (!terminated && (value.is_numeric() || value.kind == Value::Kind::String)) {
        warning(where, "missing ';' after the value of #" + d.text + " " + name +
                           " (POV-Ray 3.5+ requires it for floats, vectors, colours and strings)");
    }
    if (value.kind == Value::Kind::Texture && value.texture() && value.texture()->name.empty()) {
        auto named = std::make_shared<sg::Material>(*value.texture());
        named->name = name;
        value.payload = named;
    }
    // #declare B = A copies the array (a macro's argument stays A itself).
    if (value.kind == Value::Kind::Array && value.array()) value.payload = std::make_shared<ArrayData>(*value.array());
    // The ';' may close the value inside the macro (`Q;` as its last
    // words): the name still belongs where the directive stands.
    store(name, std::move(value), local, where, directive_scope);
    if (deprecation) m_deprecated[name] = *deprecation;
}

void Evaluator::directive_undef(const RawToken& d) {
    std::string name = expect_raw_identifier("after #undef");
    if (name.empty()) {
        error(d.location, "expected an identifier after #undef");
        return abort_parse();
    }
    m_macros.erase(name);
    for (std::size_t i = m_scopes.size(); i-- > 0;) {
        if (m_references[i].erase(name) || m_scopes[i].erase(name)) return;
    }
}

bool Evaluator::evaluate_condition(const RawToken& d, const std::string& what) {
    std::optional<Value> plain = read_plain_condition();
    Value value = plain ? std::move(*plain) : parse_nested(Parser::token::TOK_START_COND, d.location, true);
    rewind_lookahead();
    if (m_aborted) return false;
    SourceRange where{d.location, d.location};
    return to_float(value, where, "a float condition for " + what) != 0.0;
}

const RawToken* Evaluator::skip_block(const sg::SourceLocation& opened_at, const std::string& opener, SkipStop stop) {
    rewind_lookahead();
    m_pending.clear();
    Frame& frame = *m_frames.back();
    int depth = 0;
    while (frame.position < frame.end) {
        const RawToken& token = frame.buffer->tokens[frame.position++];
        if (token.kind != RawKind::Directive) continue;
        if (opens_block(token.text)) {
            ++depth;
        } else if (token.text == "end") {
            if (depth == 0) return &token;
            --depth;
        } else if (depth == 0) {
            if (stop == SkipStop::ElseOrEnd && (token.text == "else" || token.text == "elseif")) return &token;
            if (stop == SkipStop::CaseOrEnd && (token.text == "case" || token.text == "range" || token.text == "else"))
                return &token;
        }
    }
    error(opened_at, opener + " has no matching #end" + (frame.is_macro ? " inside macro '" + frame.name + "'" : ""));
    abort_parse();
    return nullptr;
}

// #if (cond) / #ifdef (Name) / #ifndef (Name)
void Evaluator::directive_if(const RawToken& d, bool ifdef, bool negate) {
    bool taken;
    if (ifdef) {
        sg::SourceLocation where = d.location;
        if (!expect_raw_punct("(", "after #" + d.text)) return;
        std::string name = expect_raw_identifier("in #" + d.text, &where);
        if (name.empty()) {
            error(d.location, "expected an identifier in #" + d.text + " (Name)");
            return abort_parse();
        }
        const bool defined = identifier_defined(name, where);
        if (m_aborted) return;
        if (!expect_raw_punct(")", "after the identifier of #" + d.text)) return;
        taken = defined != negate;
    } else {
        taken = evaluate_condition(d, "#if");
    }
    if (m_aborted) return;
    Control control;
    control.kind = Control::Kind::If;
    control.opened_at = d.location;
    m_frames.back()->controls.push_back(control);
    while (!taken) {
        const RawToken* stop = skip_block(d.location, "#" + d.text, SkipStop::ElseOrEnd);
        if (!stop) return;
        if (stop->text == "end") {
            m_frames.back()->controls.pop_back();
            return;
        }
        if (stop->text == "else") return;
        taken = evaluate_condition(*stop, "#elseif");  // #elseif
        if (m_aborted) return;
    }
}

// Reached #else/#elseif while running a taken branch: skip to the #end.
void Evaluator::directive_else(const RawToken& d, bool elseif) {
    auto& controls = m_frames.back()->controls;
    if (controls.empty() ||
        (controls.back().kind != Control::Kind::If && controls.back().kind != Control::Kind::Switch)) {
        error(d.location, "#" + d.text + " without a matching #if");
        return abort_parse();
    }
    if (controls.back().kind == Control::Kind::Switch) {
        if (elseif) {
            error(d.location, "#elseif inside #switch; use #case");
            return abort_parse();
        }
        return;  // falling through from a #case into #else: keep going
    }
    if (!skip_block(controls.back().opened_at, "#if", SkipStop::End)) return;
    controls.pop_back();
}

void Evaluator::directive_while(const RawToken& d) {
    Frame& frame = *m_frames.back();
    size_t condition_at = frame.position;
    if (!evaluate_condition(d, "#while")) {
        if (!m_aborted) skip_block(d.location, "#while", SkipStop::End);
        return;
    }
    Control control;
    control.kind = Control::Kind::While;
    control.opened_at = d.location;
    control.loop_position = condition_at;
    control.iterations = 1;
    m_frames.back()->controls.push_back(control);
}

// #for (Name, Start, End [, Step])
void Evaluator::directive_for(const RawToken& d) {
    if (!expect_raw_punct("(", "after #for")) return;
    sg::SourceLocation where = d.location;
    std::string name = expect_raw_identifier("in #for", &where);
    if (name.empty()) {
        error(d.location, "expected #for (Identifier, Start, End [, Step])");
        return abort_parse();
    }
    if (!expect_raw_punct(",", "after the #for variable")) return;
    SourceRange range{d.location, d.location};
    double start =
        to_float(parse_nested(Parser::token::TOK_START_EXPR, d.location, true), range, "a float start for #for");
    if (m_aborted || !expect_raw_punct(",", "after the start value of #for")) return;
    double end = to_float(parse_nested(Parser::token::TOK_START_EXPR, d.location, true), range, "a float end for #for");
    if (m_aborted) return;
    double step = 1.0;
    if (take_punct(",")) {
        step = to_float(parse_nested(Parser::token::TOK_START_EXPR, d.location, true), range, "a float step for #for");
        if (m_aborted) return;
    }
    if (!expect_raw_punct(")", "to close #for (...)")) return;
    if (step == 0.0) {
        error(d.location, "#for step is 0: the loop would never end");
        return abort_parse();
    }
    store(name, Value::number(start), true, where);
    if (step > 0 ? start > end : start < end) {
        skip_block(d.location, "#for", SkipStop::End);
        return;
    }
    Control control;
    control.kind = Control::Kind::For;
    control.opened_at = d.location;
    control.loop_position = m_frames.back()->position;
    control.variable = name;
    control.end = end;
    control.step = step;
    control.iterations = 1;
    m_frames.back()->controls.push_back(control);
}

void Evaluator::directive_switch(const RawToken& d) {
    Value value = parse_nested(Parser::token::TOK_START_COND, d.location, true);
    rewind_lookahead();
    if (m_aborted) return;
    Control control;
    control.kind = Control::Kind::Switch;
    control.opened_at = d.location;
    control.switch_value = to_float(value, SourceRange{d.location, d.location}, "a float for #switch");
    m_frames.back()->controls.push_back(control);
    // Find the first clause that matches.
    while (true) {
        const RawToken* stop = skip_block(d.location, "#switch", SkipStop::CaseOrEnd);
        if (!stop) return;
        if (stop->text == "end") {
            m_frames.back()->controls.pop_back();
            return;
        }
        if (stop->text == "else") {
            m_frames.back()->controls.back().case_matched = true;
            return;
        }
        bool range = stop->text == "range";
        SourceRange where{stop->location, stop->location};
        bool matched;
        if (range) {
            // #range (low, high)
            RawToken at = *stop;
            if (!expect_raw_punct("(", "after #range")) return;
            double low =
                to_float(parse_nested(Parser::token::TOK_START_EXPR, at.location, true), where, "a float for #range");
            if (m_aborted || !expect_raw_punct(",", "between the bounds of #range")) return;
            double high =
                to_float(parse_nested(Parser::token::TOK_START_EXPR, at.location, true), where, "a float for #range");
            if (m_aborted || !expect_raw_punct(")", "to close #range (low, high)")) return;
            matched = control.switch_value >= low && control.switch_value <= high;
        } else {
            Value value = parse_nested(Parser::token::TOK_START_COND, stop->location, true);
            if (m_aborted) return;
            matched = control.switch_value == to_float(value, where, "a float for #case");
        }
        rewind_lookahead();
        if (matched) {
            m_frames.back()->controls.back().case_matched = true;
            return;
        }
    }
}

// A #case/#range reached while running a matched clause: POV-Ray falls through.
void Evaluator::directive_case(const RawToken& d, bool range) {
    auto& controls = m_frames.back()->controls;
    if (controls.empty() || controls.back().kind != Control::Kind::Switch) {
        error(d.location, "#" + d.text + " outside #switch");
        return abort_parse();
    }
    if (range) {
        if (!expect_raw_punct("(", "after #range")) return;
        parse_nested(Parser::token::TOK_START_EXPR, d.location, true);
        if (m_aborted || !expect_raw_punct(",", "between the bounds of #range")) return;
        parse_nested(Parser::token::TOK_START_EXPR, d.location, true);
        if (!m_aborted) expect_raw_punct(")", "to close #range (low, high)");
        return;
    }
    parse_nested(Parser::token::TOK_START_COND, d.location, true);
    rewind_lookahead();
}

void Evaluator::directive_break(const RawToken& d) {
    auto& controls = m_frames.back()->controls;
    size_t target = controls.size();
    while (target > 0 && controls[target - 1].kind == Control::Kind::If) --target;
    if (target == 0) {
        error(d.location, "#break outside #switch, #while or #for");
        return abort_parse();
    }
    while (controls.size() >= target) {
        if (!skip_block(controls.back().opened_at, control_name(controls.back().kind), SkipStop::End)) return;
        controls.pop_back();
    }
}

void Evaluator::directive_end(const RawToken& d) {
    Frame& frame = *m_frames.back();
    auto& controls = frame.controls;
    if (controls.empty()) {
        error(d.location, "#end without an open #if, #while, #for, #switch or #macro");
        return abort_parse();
    }
    Control& control = controls.back();
    if (control.kind == Control::Kind::While) {
        frame.position = control.loop_position;
        RawToken at;
        at.location = control.opened_at;
        at.text = "while";
        if (!evaluate_condition(at, "#while")) {
            if (m_aborted) return;
            sg::SourceLocation opened = controls.back().opened_at;
            controls.pop_back();
            skip_block(opened, "#while", SkipStop::End);
        } else if (++controls.back().iterations > m_options.max_loop_iterations) {
            error(controls.back().opened_at, "#while loop exceeded " + std::to_string(m_options.max_loop_iterations) +
                                                 " iterations (runaway loop?)");
            abort_parse();
        } else {
            memory_exhausted(controls.back().opened_at);
        }
        return;
    }
    if (control.kind == Control::Kind::For) {
        if (++control.iterations > m_options.max_loop_iterations) {
            error(control.opened_at,
                  "#for loop exceeded " + std::to_string(m_options.max_loop_iterations) + " iterations");
            return abort_parse();
        }
        if (memory_exhausted(control.opened_at)) return;
        const Value* current = lookup(control.variable);
        double value = (current && current->kind == Value::Kind::Float ? current->v[0] : control.end) + control.step;
        store(control.variable, Value::number(value), false, control.opened_at);
        double slack = 1e-9 * std::max(1.0, std::abs(control.end));
        if (control.step > 0 ? value <= control.end + slack : value >= control.end - slack) {
            frame.position = control.loop_position;
        } else {
            controls.pop_back();
        }
        return;
    }
    controls.pop_back();
}

// #macro Name(P1, P2, ...) body #end
void Evaluator::directive_macro(const RawToken& d) {
    sg::SourceLocation where = d.location;
    std::string name = expect_raw_identifier("after #macro", &where);
    if (name.empty()) {
        error(d.location, "expected a macro name after #macro");
        return abort_parse();
    }
    auto macro = std::make_shared<Macro>();
    macro->name = name;
    macro->defined_at = where;
    if (!expect_raw_punct("(", "after the macro name '" + name + "'")) return;
    if (!take_punct(")")) {
        while (true) {
            sg::SourceLocation at;
            std::string parameter = expect_raw_identifier("in #macro parameters", &at);
            if (parameter.empty()) {
                error(where, "expected a parameter name in #macro " + name + "(...)");
                return abort_parse();
            }
            macro->parameters.push_back(parameter);
            if (take_punct(")")) break;
            if (!expect_raw_punct(",", "between macro parameters")) return;
        }
    }
    Frame& frame = *m_frames.back();
    macro->buffer = frame.buffer;
    macro->body_begin = frame.position;
    const RawToken* end = skip_block(d.location, "#macro " + name, SkipStop::End);
    if (!end) return;
    macro->body_end = frame.position - 1;
    for (auto& scope : m_scopes) scope.erase(name);
    m_macros[name] = macro;
}

void Evaluator::expand_macro(const RawToken& name, const Macro& macro) {
    if (m_macro_depth >= m_options.max_macro_depth) {
        error(name.location, "macro recursion too deep: more than " + std::to_string(m_options.max_macro_depth) +
                                 " nested calls of '" + macro.name + "'");
        return abort_parse();
    }
    // The depth limit holds whatever a build's frame sizes (parse_stack.h).
    if (parse_stack_nearly_full()) {
        error(name.location, "macro recursion too deep for the parser's stack: " + std::to_string(m_macro_depth) +
                                 " nested calls of '" + macro.name + "'");
        return abort_parse();
    }
    if (memory_exhausted(name.location)) return;
    const RawToken* next = m_pending.empty() ? peek_raw() : nullptr;
    if (!next || next->kind != RawKind::Punct || next->text != "(") {
        error(name.location, "expected '(' after the macro name '" + macro.name + "'");
        return abort_parse();
    }
    m_nested_arguments.reset();
    parse_nested(Parser::token::TOK_START_ARGS, name.location, true);
    if (m_aborted || !m_nested_arguments) return;
    std::vector<MacroArgument> arguments = std::move(*m_nested_arguments);
    m_nested_arguments.reset();
    if (arguments.size() != macro.parameters.size()) {
        error(name.location, "macro '" + macro.name + "' takes " + std::to_string(macro.parameters.size()) +
                                 " argument(s), but " + std::to_string(arguments.size()) + " were given");
        note(macro.defined_at, "'" + macro.name + "' is defined here");
        return abort_parse();
    }
    auto frame = std::make_shared<Frame>();
    frame->buffer = macro.buffer;
    frame->position = macro.body_begin;
    frame->end = macro.body_end;
    frame->is_macro = true;
    frame->owns_scope = true;
    frame->name = macro.name;
    frame->called_from = name.location;
    m_frames.push_back(frame);
    push_scope();
    for (size_t i = 0; i < arguments.size(); ++i) {
        if (arguments[i].reference)
            m_references.back()[macro.parameters[i]] = std::move(*arguments[i].reference);
        else
            m_scopes.back()[macro.parameters[i]] = std::move(arguments[i].value);
    }
    ++m_macro_depth;
}

void Evaluator::directive_include(const RawToken& d) {
    Value name_value = parse_nested(Parser::token::TOK_START_STRING, d.location, true);
    rewind_lookahead();
    if (m_aborted) return;
    if (name_value.kind != Value::Kind::String) {
        error(d.location, "expected a file name string after #include, found " + describe(name_value));
        return abort_parse();
    }
    const std::string& name = name_value.text;
    // Search: the including file's folder, then the include path, then the
    // current folder, where POV-Ray looks and where #fopen writes (so that
    // strings.inc's Parse_String finds the file it has just written).
    std::vector<std::string> folders;
    folders.push_back(m_frames.back()->buffer->folder);
    for (const auto& dir : m_options.include_path) folders.push_back(dir);
    if (std::find(folders.begin(), folders.end(), std::string()) == folders.end()) folders.push_back("");
    std::string found_name;
    FileSearch search = find_file(name, folders, d.location, "include file", found_name);
    if (search == FileSearch::Refused) return abort_parse();
    if (search == FileSearch::Missing) {
        std::string searched;
        for (const auto& folder : folders)
            searched += (searched.empty() ? "" : ", ") + (folder.empty() ? std::string(".") : folder);
        error(d.location, "cannot find include file \"" + name + "\" (searched: " + searched + ")");
        return abort_parse();
    }
    fs::path found = found_name;
    std::error_code ec;
    std::string canonical = fs::weakly_canonical(found, ec).string();
    int file_depth = 0;
    for (const auto& frame : m_frames) {
        if (frame->is_macro) continue;
        ++file_depth;
        if (!frame->buffer->path.empty() && fs::weakly_canonical(frame->buffer->path, ec).string() == canonical) {
            error(d.location, "include cycle: \"" + name + "\" is already being read (included from " +
                                  *frame->buffer->label + ")");
            return abort_parse();
        }
    }
    if (file_depth >= m_options.max_include_depth) {
        error(d.location,
              "#include nested too deeply (more than " + std::to_string(m_options.max_include_depth) + " files)");
        return abort_parse();
    }
    std::string text;
    if (!read_file(found.string(), d.location, "include file", text)) return abort_parse();
    if (!push_file(std::move(text), found.lexically_normal().string(), found.string(), found.parent_path().string(),
                   d.location)) {
        abort_parse();
    }
}

void Evaluator::directive_message(const RawToken& d) {
    Value message = parse_nested(Parser::token::TOK_START_STRING, d.location, true);
    rewind_lookahead();
    if (m_aborted) return;
    std::string text = message.kind == Value::Kind::String ? message.text : describe(message);
    while (!text.empty() && (text.back() == '\n' || text.back() == '\r')) text.pop_back();
    if (d.text == "debug") {
        sg::SourceLocation where = d.location;
        where.column = 0;  // a message, not a place to point at
        note(where, "#debug: " + text);
    } else if (d.text == "warning") {
        warning(d.location, text);
    } else {
        error(d.location, "#error: " + text);
        abort_parse();
    }
}

void Evaluator::directive_version(const RawToken& d) {
    Value version = parse_nested(Parser::token::TOK_START_EXPR, d.location, true);
    rewind_lookahead();
    if (m_aborted) return;
    const double number = to_float(version, SourceRange{d.location, d.location}, "a version number");
    take_punct(";");
    m_saw_version = true;
    if (!(number >= 1.0 && number < 100.0)) {
        error(d.location, "#version must be a POV-Ray version such as 3.7, got " + std::to_string(number));
        return;
    }
    m_language_version = number;
}

// POV-Ray's end of parsing (parser.cpp): version-dependent defaults follow
// the #version in force when the scene ends. A scene with no #version at
// all is 3.62 there (EffectiveLanguageVersion), though `version` reads 3.7.
int Evaluator::effective_language_version() const {
    const double version = m_saw_version ? m_language_version : 3.62;
    return int(version * 100.0 + 0.5);
}

void Evaluator::settle_version_defaults() {
    m_scene.global.language_version = m_saw_version ? m_language_version : 3.62;
    const bool before_3_7 = effective_language_version() < 370;
    if (!m_saw_assumed_gamma && before_3_7) {
        m_scene.global.gamma_correction = false;
        sg::SourceLocation where;
        where.file = std::make_shared<const std::string>(m_scene.main_file);
        char version[32];
        std::snprintf(version, sizeof version, "%g", m_language_version);
        const std::string why = m_saw_version ? std::string("this pre-3.7 scene (#version ") + version + ")"
                                              : std::string("a scene without #version, which POV-Ray reads as 3.62");
        warning(where, "assumed_gamma not specified, so gamma correction is turned off for compatibility with " + why +
                           ": image files receive the colours unchanged, as POV-Ray 3.6 wrote them (start the "
                           "scene with #version 3.7; and global_settings { assumed_gamma 1 } for POV-Ray 3.7's "
                           "gamma)");
    }
}

// #default { texture {...} | pigment {...} | normal {...} | finish {...} }
void Evaluator::directive_default(const RawToken& d) {
    if (!expect_raw_punct("{", "after #default")) return;
    // Several items may follow one another: #default { pigment {…} finish {…} }.
    auto texture = std::make_shared<sg::Material>(m_default_texture ? *m_default_texture : sg::Material{});
    while (!take_punct("}")) {
        if (peek_raw() == nullptr) {
            error(d.location, "'{' after #default has no matching '}'");
            return abort_parse();
        }
        Value value = parse_nested(Parser::token::TOK_START_VALUE, d.location, false);
        if (m_aborted) return;
        take_punct(";");
        switch (value.kind) {
        case Value::Kind::Texture: *texture = *value.texture(); break;
        case Value::Kind::Pigment: texture->pigment = *value.pigment(); break;
        case Value::Kind::Finish: texture->finish = *value.finish(); break;
        case Value::Kind::Normal: texture->normal = value.normal(); break;
        default:
            error(d.location, "#default expects a texture, pigment, normal or finish, found " + describe(value));
            return;
        }
        // The next item starts from what this one set (a finish { } reads
        // the default finish).
        texture->name = "#default";
        m_default_texture = texture;
        texture = std::make_shared<sg::Material>(*m_default_texture);
    }
}

}  // namespace lancer::parse
