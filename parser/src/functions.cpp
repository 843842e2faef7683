// POV-Ray's function { … }: read straight from the token stream (its body
// is an expression language of its own, where x, y and z are the
// arguments, not vectors) and compiled to sg::Function's stack program.
// Declared floats are read at definition, as POV binds them; declared
// functions are called; macros expand as anywhere else.
#include <algorithm>
#include <cmath>
#include <map>
#include <optional>

#include "evaluator.h"

namespace lancer::parse {
namespace {

using Op = sg::Function::Op;

const std::map<std::string, int>& math1_names() {
    static const std::map<std::string, int> names = {
        {"abs", sg::Function::Abs},     {"acos", sg::Function::Acos},       {"acosh", sg::Function::Acosh},
        {"asin", sg::Function::Asin},   {"asinh", sg::Function::Asinh},     {"atan", sg::Function::Atan},
        {"atanh", sg::Function::Atanh}, {"ceil", sg::Function::Ceil},       {"cos", sg::Function::Cos},
        {"cosh", sg::Function::Cosh},   {"degrees", sg::Function::Degrees}, {"exp", sg::Function::Exp},
        {"floor", sg::Function::Floor}, {"int", sg::Function::Int},         {"ln", sg::Function::Ln},
        {"log", sg::Function::Log},     {"radians", sg::Function::Radians}, {"sin", sg::Function::Sin},
        {"sinh", sg::Function::Sinh},   {"sqrt", sg::Function::Sqrt},       {"sqr", sg::Function::Sqr},
        {"tan", sg::Function::Tan},     {"tanh", sg::Function::Tanh},       {"sgn", sg::Function::Sign}};
    return names;
}

const std::map<std::string, int>& math2_names() {
    static const std::map<std::string, int> names = {{"atan2", sg::Function::Atan2},
                                                     {"mod", sg::Function::Mod},
                                                     {"pow", sg::Function::Pow},
                                                     {"div", sg::Function::Div}};
    return names;
}

int channel_of(const std::string& member) {
    if (member == "x" || member == "u" || member == "red") return 0;
    if (member == "y" || member == "v" || member == "green") return 1;
    if (member == "z" || member == "blue") return 2;
    if (member == "t" || member == "filter") return 3;
    if (member == "transmit") return 4;
    if (member == "gray" || member == "grey") return 5;
    return -1;
}

Value function_value(const sg::FunctionRef& f, const sg::SourceLocation& at) {
    Value value;
    value.kind = Value::Kind::Function;
    value.payload = f;
    value.location = at;
    return value;
}

}  // namespace

// The compiler: recursive descent over the raw tokens of one body, with
// one token of lookahead.
class FunctionCompiler {
  public:
    FunctionCompiler(Evaluator& ev, sg::Function& f) : m_ev(ev), m_f(&f) {}

    // Reads the body after its "{" through the matching "}".
    bool compile(const sg::SourceLocation& at) {
        m_at = at;
        if (!fetch()) return false;
        if (is_word("internal")) return compile_internal();
        if (is_punct("}")) return fail("the function has no body");
        expression();
        if (!m_failed && !is_punct("}")) fail("expected } at the end of the function, got '" + m_token.text + "'");
        return !m_failed;
    }

  private:
    bool compile_internal() {
        fetch();
        if (!is_punct("(")) return fail("expected internal(number)");
        fetch();
        if (m_token.kind != RawKind::Number) return fail("expected internal(number)");
        m_f->internal = int(m_token.number);
        fetch();
        if (!is_punct(")")) return fail("expected ) after internal(number");
        fetch();
        if (!is_punct("}")) return fail("expected } after internal(number)");
        return true;
    }

    // The next token after macros and directives; false at the end of input.
    bool fetch() {
        while (true) {
            const RawToken* raw = m_ev.take_raw();
            if (!raw) {
                m_token = RawToken{};
                m_token.text = "end of file";
                fail("the function's body is not closed by }");
                return false;
            }
            if (raw->kind == RawKind::Directive) {
                m_ev.run_directive(*raw);
                continue;
            }
            if (raw->kind == RawKind::Identifier && !m_ev.lookup(raw->text) && !is_parameter(raw->text)) {
                auto macro = m_ev.m_macros.find(raw->text);
                if (macro != m_ev.m_macros.end()) {
                    auto keep = macro->second;
                    m_ev.expand_macro(*raw, *keep);
                    continue;
                }
            }
            m_token = *raw;
            return true;
        }
    }

    bool is_punct(const char* p) const { return m_token.kind == RawKind::Punct && m_token.text == p; }
    bool is_word(const char* w) const { return m_token.kind == RawKind::Identifier && m_token.text == w; }
    bool fail(const std::string& message) {
        if (!m_failed) m_ev.error(m_token.location.file ? m_token.location : m_at, message);
        m_failed = true;
        return false;
    }

    int parameter_index(const std::string& name) const {
        for (std::size_t i = 0; i < m_f->parameters.size(); ++i)
            if (m_f->parameters[i] == name) return int(i);
        return -1;
    }
    bool is_parameter(const std::string& name) const { return parameter_index(name) >= 0; }

    void emit(Op op, int index = 0, int count = 0, int channel = 0) {
        m_f->code.push_back({op, index, count, channel});
        // Track the deepest the stack gets.
        switch (op) {
        case Op::Constant:
        case Op::Parameter: ++m_depth; break;
        case Op::Negate:
        case Op::Not:
        case Op::Math1: break;
        case Op::Minimum:
        case Op::Maximum:
        case Op::Select:
        case Op::Call: m_depth -= count - 1; break;
        default: --m_depth; break;
        }
        m_f->stack_size = std::max(m_f->stack_size, m_depth + 1);
    }
    void constant(double value) {
        m_f->constants.push_back(value);
        emit(Op::Constant, int(m_f->constants.size()) - 1);
    }

    // POV's function language has no ?: (select() does that).
    void expression() { logical_or(); }

    void logical_or() {
        logical_and();
        while (!m_failed && is_punct("|")) {
            fetch();
            logical_and();
            emit(Op::Or);
        }
    }
    void logical_and() {
        comparison();
        while (!m_failed && is_punct("&")) {
            fetch();
            comparison();
            emit(Op::And);
        }
    }
    void comparison() {
        additive();
        while (!m_failed && m_token.kind == RawKind::Punct) {
            Op op;
            const std::string& p = m_token.text;
            if (p == "<")
                op = Op::Less;
            else if (p == "<=")
                op = Op::LessEqual;
            else if (p == ">")
                op = Op::Greater;
            else if (p == ">=")
                op = Op::GreaterEqual;
            else if (p == "=")
                op = Op::Equal;
            else if (p == "!=")
                op = Op::NotEqual;
            else
                break;
            fetch();
            additive();
            emit(op);
        }
    }
    void additive() {
        multiplicative();
        while (!m_failed && (is_punct("+") || is_punct("-"))) {
            const Op op = is_punct("+") ? Op::Add : Op::Subtract;
            fetch();
            multiplicative();
            emit(op);
        }
    }
    void multiplicative() {
        unary();
        while (!m_failed && (is_punct("*") || is_punct("/"))) {
            const Op op = is_punct("*") ? Op::Multiply : Op::Divide;
            fetch();
            unary();
            emit(op);
        }
    }
    void unary() {
        if (is_punct("-")) {
            fetch();
            unary();
            emit(Op::Negate);
        } else if (is_punct("+")) {
            fetch();
            unary();
        } else if (is_punct("!")) {
            fetch();
            unary();
            emit(Op::Not);
        } else {
            primary();
        }
    }

    // "(" args ")" after a name; returns how many.
    int arguments(const std::string& name) {
        if (!is_punct("(")) {
            fail("expected ( after " + name);
            return 0;
        }
        fetch();
        int count = 0;
        if (is_punct(")")) {
            fetch();
            return 0;
        }
        while (!m_failed) {
            expression();
            ++count;
            if (is_punct(",")) {
                fetch();
                continue;
            }
            if (!is_punct(")")) {
                fail("expected , or ) in the arguments of " + name);
                return count;
            }
            fetch();
            break;
        }
        return count;
    }

    void primary() {
        if (m_failed) return;
        if (m_token.kind == RawKind::Number) {
            constant(m_token.number);
            fetch();
            return;
        }
        if (is_punct("(")) {
            fetch();
            expression();
            if (!is_punct(")")) {
                fail("expected )");
                return;
            }
            fetch();
            return;
        }
        if (m_token.kind != RawKind::Identifier) {
            fail("unexpected '" + m_token.text + "' in a function");
            return;
        }
        const std::string name = m_token.text;
        const sg::SourceLocation where = m_token.location;
        fetch();
        if (int index = parameter_index(name); index >= 0) {
            emit(Op::Parameter, index);
            return;
        }
        // Without a parameter list, u and v are x and y.
        if (m_default_parameters && (name == "u" || name == "v")) {
            emit(Op::Parameter, name == "u" ? 0 : 1);
            return;
        }
        if (auto m1 = math1_names().find(name); m1 != math1_names().end() && !m_ev.lookup(name)) {
            if (arguments(name) != 1) {
                fail(name + " takes one argument");
                return;
            }
            emit(Op::Math1, m1->second);
            return;
        }
        if (auto m2 = math2_names().find(name); m2 != math2_names().end() && !m_ev.lookup(name)) {
            if (arguments(name) != 2) {
                fail(name + " takes two arguments");
                return;
            }
            emit(Op::Math2, m2->second);
            return;
        }
        if ((name == "min" || name == "max") && !m_ev.lookup(name)) {
            const int count = arguments(name);
            if (count < 1) {
                fail(name + " needs arguments");
                return;
            }
            emit(name == "min" ? Op::Minimum : Op::Maximum, 0, count);
            return;
        }
        if ((name == "sum" || name == "prod") && !m_ev.lookup(name)) return sequence(name);
        if (name == "select" && !m_ev.lookup(name)) {
            const int count = arguments(name);
            if (count != 3 && count != 4) {
                fail("select takes 3 or 4 arguments");
                return;
            }
            emit(Op::Select, 0, count);
            return;
        }
        if (name == "pi") return constant(3.14159265358979323846);
        if (name == "tau") return constant(2.0 * 3.14159265358979323846);
        if (name == "true" || name == "yes" || name == "on") return constant(1.0);
        if (name == "false" || name == "no" || name == "off") return constant(0.0);
        if (const Value* value = m_ev.lookup(name)) {
            if (value->kind == Value::Kind::Function && value->function()) {
                call(value->function(), name);
                return;
            }
            if (value->kind == Value::Kind::Float) return constant(value->v[0]);
            if ((value->kind == Value::Kind::Vector || value->kind == Value::Kind::Color) && is_punct(".")) {
                fetch();
                const int channel = channel_of(m_token.text);
                if (channel < 0 || channel > 4 || channel >= (value->kind == Value::Kind::Color ? 5 : value->size)) {
                    fail("no component '" + m_token.text + "' of " + name);
                    return;
                }
                constant(value->v[channel]);
                fetch();
                return;
            }
            m_ev.error(where, "'" + name + "' is " + describe(*value) + "; a function takes floats and functions");
            m_failed = true;
            return;
        }
        // A built-in value the token stream knows (clock, version, …).
        RawToken raw;
        raw.kind = RawKind::Identifier;
        raw.text = name;
        raw.location = where;
        if (name == "clock" || name == "version" || name == "image_width" || name == "image_height" ||
            name == "frame_number" || name == "clock_delta") {
            const auto symbol = m_ev.symbol_for_identifier(raw);
            constant(symbol.value.as<TokenValue>().value.v[0]);
            return;
        }
        m_ev.error(where, "unknown identifier '" + name + "' in a function");
        m_failed = true;
    }

    // POV's sum(i, b, e, expr) and prod(…): expr for i = b, b + 1, … while
    // i <= e, added or multiplied. The body is a function of this one's
    // parameters and i, called once per step.
    void sequence(const std::string& name) {
        if (!is_punct("(")) {
            fail("expected ( after " + name);
            return;
        }
        fetch();
        if (m_token.kind != RawKind::Identifier || is_parameter(m_token.text)) {
            fail(name + "(): its first argument names the new loop variable, e.g. " + name + "(i, 1, 10, x * i)");
            return;
        }
        const std::string variable = m_token.text;
        fetch();
        for (int bound = 0; bound < 2 && !m_failed; ++bound) {
            if (!is_punct(",")) {
                fail(name + "() takes four arguments: a variable, its first and last values and an expression");
                return;
            }
            fetch();
            expression();
        }
        if (m_failed) return;
        if (!is_punct(",")) {
            fail(name + "() takes four arguments: a variable, its first and last values and an expression");
            return;
        }
        fetch();
        auto body = std::make_shared<sg::Function>();
        body->parameters = m_f->parameters;
        body->parameters.push_back(variable);
        body->name = m_f->name;
        sg::Function* const outer = m_f;
        const int outer_depth = m_depth;
        m_f = body.get();
        m_depth = 0;
        expression();
        m_f = outer;
        m_depth = outer_depth;
        if (m_failed) return;
        if (!is_punct(")")) {
            fail(name + "() takes four arguments: a variable, its first and last values and an expression");
            return;
        }
        fetch();
        m_f->callees.push_back(body);
        emit(name == "sum" ? Op::Sum : Op::Product, int(m_f->callees.size()) - 1, int(outer->parameters.size()));
    }

    void call(const sg::FunctionRef& callee, const std::string& name) {
        const int count = arguments(name);
        int channel = 0;
        if (!m_failed && is_punct(".")) {
            fetch();
            channel = channel_of(m_token.text);
            const bool fits =
                callee->pigment || (callee->transform && channel <= 2) || (callee->spline && channel <= 4);
            if (channel < 0 || !fits) {
                fail("'." + m_token.text +
                     "' needs a pigment function (or .x, .y, .z of a transform function, .x to .t of a spline "
                     "function)");
                return;
            }
            fetch();
        }
        m_f->callees.push_back(callee);
        emit(Op::Call, int(m_f->callees.size()) - 1, count, channel);
    }

  public:
    bool m_default_parameters = true;

  private:
    Evaluator& m_ev;
    sg::Function* m_f;  // the function being written: a sum's or prod's body while it is read
    RawToken m_token;
    sg::SourceLocation m_at;
    bool m_failed = false;
    int m_depth = 0;
};

std::optional<Evaluator::Symbol> Evaluator::read_function(const RawToken& keyword) {
    auto f = std::make_shared<sg::Function>();
    bool default_parameters = true;
    // POV's image of a function, `function W, H { … }` (height_field,
    // image_map): its size comes first.
    std::optional<std::pair<int, int>> image_size;
    if (const RawToken* first = peek_raw();
        first && !(first->kind == RawKind::Punct && (first->text == "(" || first->text == "{"))) {
        const SourceRange at{keyword.location, keyword.location};
        const double width = to_float(parse_nested(Parser::token::TOK_START_EXPR, keyword.location, true), at);
        rewind_lookahead();
        if (m_aborted || !take_punct(",")) {
            if (!m_aborted)
                error(keyword.location, "expected function W, H { … } (an image's size, then its function)");
            abort_parse();
            return std::nullopt;
        }
        const double height = to_float(parse_nested(Parser::token::TOK_START_EXPR, keyword.location, true), at);
        rewind_lookahead();
        if (m_aborted) return std::nullopt;
        // POV rounds each to the nearest integer; 2 x 2 is the least image a
        // height field can use, and the size is bounded like image files.
        const double w = std::floor(width + 0.5), h = std::floor(height + 0.5);
        if (!(w >= 2.0 && h >= 2.0 && w <= 16384.0 && h <= 16384.0)) {
            error(keyword.location, "function W, H: the image size must lie in 2..16384 each way");
            abort_parse();
            return std::nullopt;
        }
        image_size = std::make_pair(int(w), int(h));
    }
    const RawToken* next = peek_raw();
    if (next && next->kind == RawKind::Punct && next->text == "(") {
        take_raw();
        default_parameters = false;
        while (true) {
            const RawToken* token = take_raw();
            if (!token) break;
            if (token->kind == RawKind::Punct && token->text == ")") break;
            if (token->kind == RawKind::Punct && token->text == ",") continue;
            if (token->kind != RawKind::Identifier) {
                error(token->location, "expected a parameter name in function(…)");
                break;
            }
            f->parameters.push_back(token->text);
        }
    } else {
        f->parameters = {"x", "y", "z"};
    }
    const RawToken* open = take_raw();
    if (!open || open->kind != RawKind::Punct || open->text != "{") {
        error(open ? open->location : keyword.location, "expected { after function");
        return std::nullopt;
    }
    const RawToken* first = peek_raw();
    if (first && first->kind == RawKind::Identifier &&
        (first->text == "pattern" || first->text == "pigment" || first->text == "transform" ||
         first->text == "spline") &&
        default_parameters) {
        // The grammar reads function { pattern { … } }, { pigment { … } },
        // { transform { … } } and { spline { … } }.
        m_block_names.push_back("function");
        ++m_nesting;
        Value sized;
        sized.image_size = image_size;
        return make_symbol(Parser::token::TOK_FUNCTION_OPEN, keyword, std::move(sized));
    }
    FunctionCompiler compiler(*this, *f);
    compiler.m_default_parameters = default_parameters;
    if (!compiler.compile(keyword.location)) {
        abort_parse();
        m_suppress_syntax_errors = true;
    }
    Value literal = function_value(f, keyword.location);
    literal.image_size = image_size;
    return make_symbol(Parser::token::TOK_FUNCTION_LITERAL, keyword, std::move(literal));
}

Value Evaluator::call_function(const Value& function, const std::vector<Value>& arguments, const SourceRange& where) {
    std::vector<double> numbers;
    for (std::size_t i = 0; i < arguments.size(); ++i) numbers.push_back(to_float(arguments[i], where, "an argument"));
    try {
        const sg::Function& f = *function.function();
        // The renderer's answers under the noise_generator set so far, as
        // POV-Ray evaluates a function called while parsing.
        const sg::FunctionNatives* natives =
            m_options.function_natives
                ? &m_options.function_natives->with_noise_generator(m_scene.global.noise_generator)
                : nullptr;
        if (f.pigment) {
            if (!natives) throw sg::FunctionError("a pigment function is evaluated only while rendering");
            sg::Color colour;
            double c[5];
            for (int k = 0; k < 5; ++k)
                c[k] = sg::evaluate_function(f, numbers.data(), int(numbers.size()), natives, k);
            colour.rgb = sg::Vec3(c[0], c[1], c[2]);
            colour.filter = c[3];
            colour.transmit = c[4];
            return Value::color(colour);
        }
        if (f.transform) {
            double c[3];
            for (int k = 0; k < 3; ++k)
                c[k] = sg::evaluate_function(f, numbers.data(), int(numbers.size()), nullptr, k);
            return Value::vector({c[0], c[1], c[2]});
        }
        if (f.spline) {
            Value result;
            result.kind = Value::Kind::Vector;
            result.size = f.spline_terms;
            result.v = f.spline(numbers.empty() ? 0.0 : numbers[0]);
            return result;
        }
        return Value::number(sg::evaluate_function(f, numbers.data(), int(numbers.size()), natives));
    } catch (const sg::FunctionError& e) {
        error(where.begin, e.what());
        return Value::number(0.0);
    }
}

}  // namespace lancer::parse

namespace lancer::parse {

Value Evaluator::pattern_function(const Edits<sg::Pigment>& edits, const sg::SourceLocation& at) {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    f->pattern = std::make_shared<sg::Pattern>(pigment_pattern_of(*build_pigment(edits, at)));
    return function_value(f, at);
}

Value Evaluator::pigment_function(const std::shared_ptr<sg::Pigment>& pigment, const sg::SourceLocation& at) {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    f->pigment = pigment;
    return function_value(f, at);
}

Value Evaluator::spline_function(const Value& spline, const sg::SourceLocation& at) {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    if (spline.kind == Value::Kind::Spline && spline.spline() && !spline.spline()->entries.empty()) {
        std::shared_ptr<const SplineData> data = spline.spline();
        f->spline = [data](double t) { return spline_at(*data, data->kind, t); };
        f->spline_terms = data->terms;
    } else {
        f->spline = [](double) { return std::array<double, 5>{}; };
        f->spline_terms = 2;
    }
    return function_value(f, at);
}

Value Evaluator::transform_function(const sg::Mat4& transform, const sg::SourceLocation& at) {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    f->transform = std::make_shared<const glm::dmat4>(transform);
    return function_value(f, at);
}

Evaluator::PatternEdit Evaluator::function_pattern(const Value& function, const sg::SourceLocation& at) {
    sg::FunctionRef f = function.function();
    if (f)
        if (const int missing = sg::first_unsupported_internal(*f); missing >= 0)
            error(at, "POV-Ray 3.7 has no internal function " + std::to_string(missing));
    return [f](sg::Pattern& p) {
        p.kind = sg::Pattern::Kind::Function;
        p.function = f;
    };
}

}  // namespace lancer::parse
