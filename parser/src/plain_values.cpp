// A value that is a plain expression (numbers, strings, float, vector,
// colour and string variables, constants, built-in calls, trace(),
// arithmetic, comparisons, logic, ?:, parentheses, vectors and their
// components) is read here from the raw tokens, without the grammar: a
// #declare or #local value ending in ';', an #if/#elseif/#while condition in
// its parentheses, a #write item ending in ',' or ')'. A loop's values are
// most of its tokens, and the grammar's own steps (a symbol pushed, moved
// and popped per rule) cost ten times the arithmetic. The value is evaluated
// by the same Evaluator calls, in the same order and with the same source
// ranges as the grammar's actions, so results, warnings and errors are the
// grammar's.
//
// A first pass only checks: anything else (a keyword, a macro, an array,
// a user function, a directive, a value that ends in another frame or
// without its terminator, a comparison at a vector's own level) leaves
// every token unread and the grammar reads the value. Only then does the
// second pass evaluate, so a value read here has no side effect the grammar
// would repeat (rand() advances its stream once, trace() stores its normal
// once).
#include <string>
#include <string_view>
#include <vector>

#include "evaluator.h"

namespace lancer::parse {

namespace {

constexpr int kDeepestNesting = 32;  // deeper values are left to the grammar and its limit

bool is_punct(const RawToken& token, char c) {
    return token.kind == RawKind::Punct && token.text.size() == 1 && token.text[0] == c;
}

// Binding power of a binary operator (the grammar's %left/%right order),
// 0 for a token that is none.
int binary_power(const RawToken& token) {
    if (token.kind != RawKind::Punct) return 0;
    const std::string& t = token.text;
    if (t.size() == 2) return t[1] == '=' && (t[0] == '!' || t[0] == '<' || t[0] == '>') ? 4 : 0;
    if (t.size() != 1) return 0;
    switch (t[0]) {
    case '?': return 1;
    case '|': return 2;
    case '&': return 3;
    case '=':
    case '<':
    case '>': return 4;
    case '+':
    case '-': return 5;
    case '*':
    case '/': return 6;
    default: return 0;
    }
}

constexpr int kComparisonPower = 4;

}  // namespace

// One value's tokens, read twice: `evaluating` false checks, true evaluates.
class Evaluator::PlainValueReader {
  public:
    PlainValueReader(Evaluator& ev, const std::vector<RawToken>& tokens, std::size_t first, std::size_t end)
        : m_ev(ev), m_tokens(tokens), m_first(first), m_end(end) {}

    // Checks the value; on success, the index of the terminator after it
    // (one of `terminators`' punctuation characters).
    std::optional<std::size_t> check(std::string_view terminators) {
        m_evaluating = false;
        m_at = m_first;
        m_ok = true;
        m_names.clear();
        expression(0, false);
        if (!m_ok || m_at >= m_end) return std::nullopt;
        const RawToken& last = m_tokens[m_at];
        if (last.kind != RawKind::Punct || last.text.size() != 1 ||
            terminators.find(last.text[0]) == std::string_view::npos)
            return std::nullopt;
        return m_at;
    }

    Value evaluate() {
        m_evaluating = true;
        m_at = m_first;
        m_name_index = 0;
        return std::move(expression(0, false).value);
    }

  private:
    struct Operand {
        Value value;
        SourceRange range;
    };

    SourceRange token_range(std::size_t index) const { return m_ev.token_range(m_tokens[index]); }
    static SourceRange spanning(const SourceRange& first, const SourceRange& last) { return {first.begin, last.end}; }

    bool fail() {
        m_ok = false;
        return false;
    }
    bool more() const { return m_ok && m_at < m_end; }
    const RawToken& next() const { return m_tokens[m_at]; }

    // expr at or above `least` binding power. Inside a vector's own level
    // a comparison, logic or ?: is left to the grammar ('>' closes it).
    Operand expression(int least, bool in_vector) {
        Operand left = unary();
        while (more()) {
            const int power = binary_power(next());
            if (power == 0 || power < least) break;
            if (in_vector && power <= kComparisonPower) {
                if (!is_punct(next(), '>')) fail();  // '>' closes the vector
                break;
            }
            const std::size_t op = m_at++;
            const std::string& text = m_tokens[op].text;
            if (text == "?") {
                Operand yes = expression(0, false);
                if (!more() || !is_punct(next(), ':')) {
                    fail();
                    break;
                }
                ++m_at;
                Operand no = expression(1, false);  // right-associative
                if (m_evaluating) {
                    const SourceRange range = spanning(left.range, no.range);
                    const bool chosen = m_ev.to_float(left.value, left.range, "a condition") != 0.0;
                    left.value = chosen ? yes.value : no.value;
                    left.range = range;
                }
                continue;
            }
            // Left-associative: the right operand binds tighter.
            Operand right = expression(power + 1, in_vector);
            if (m_evaluating) {
                const SourceRange range = spanning(left.range, right.range);
                if (power == kComparisonPower)
                    left.value = m_ev.compare(text, left.value, left.range, right.value, right.range);
                else if (power <= 3)
                    left.value = m_ev.logical(text[0], left.value, left.range, right.value, right.range);
                else
                    left.value = m_ev.arithmetic(text[0], left.value, right.value, token_range(op));
                left.range = range;
            }
        }
        return left;
    }

    // A unary operator binds tighter than every binary one (%prec UNARY):
    // -a * b is (-a) * b; a component binds tighter still (-v.x).
    Operand unary() {
        if (!more()) {
            fail();
            return {};
        }
        const RawToken& token = next();
        if (is_punct(token, '-') || is_punct(token, '+') || is_punct(token, '!')) {
            const std::size_t op = m_at++;
            Operand operand = unary();
            if (!m_evaluating) return operand;
            Operand result;
            result.range = spanning(token_range(op), operand.range);
            const char sign = m_tokens[op].text[0];
            if (sign == '-')
                result.value = m_ev.negate(operand.value, operand.range);
            else if (sign == '+')
                result.value = std::move(operand.value);
            else
                result.value =
                    Value::number(m_ev.to_float(operand.value, operand.range, "an operand of '!'") == 0.0 ? 1.0 : 0.0);
            return result;
        }
        return postfix();
    }

    Operand postfix() {
        Operand value = primary();
        while (more() && is_punct(next(), '.')) {
            ++m_at;
            if (!more() || next().kind != RawKind::Identifier) {
                fail();
                break;
            }
            const std::size_t name_at = m_at++;
            std::string name;
            if (!component_name(m_tokens[name_at], name)) {
                fail();
                break;
            }
            if (m_evaluating) {
                const SourceRange name_range = token_range(name_at);
                value.value = m_ev.component(value.value, value.range, name, name_range);
                value.range = spanning(value.range, name_range);
            }
        }
        return value;
    }

    // What the grammar's `component` accepts after '.': a constant's name,
    // an undeclared word, or a colour channel.
    bool component_name(const RawToken& token, std::string& name) {
        const WordClass word = word_class_of(token);
        if (word == WordClass::Keyword || word == WordClass::IgnoredKeyword) {
            static const char* const kChannels[] = {"red", "green", "blue", "filter", "transmit", "gray", "grey"};
            for (const char* channel : kChannels)
                if (token.text == channel) {
                    name = token.text == "grey" ? "gray" : token.text;
                    return true;
                }
            return false;
        }
        if (word == WordClass::Constant) {
            name = token.text;
            return token.text != "defined";
        }
        if (word != WordClass::Name && word != WordClass::IgnoredBlock) return false;
        if (m_ev.find_name(HashedName(token.text)).value) return false;
        if (m_evaluating) m_ev.m_last_undeclared = token.text;
        name = token.text;
        return true;
    }

    // Takes the bracket that closes what `result` began (one nesting level
    // less), which `result` then spans.
    bool take_closing(char bracket, Operand& result) {
        --m_depth;
        if (!more() || !is_punct(next(), bracket)) return fail();
        const std::size_t close = m_at++;
        if (m_evaluating) result.range = spanning(result.range, token_range(close));
        return true;
    }

    Operand primary() {
        if (!more()) {
            fail();
            return {};
        }
        const std::size_t at = m_at++;
        const RawToken& token = m_tokens[at];
        Operand result;
        if (m_evaluating) result.range = token_range(at);
        switch (token.kind) {
        case RawKind::Number:
            if (m_evaluating) result.value = Value::number(token.number);
            return result;
        case RawKind::String:
            if (m_evaluating) result.value = Value::string(token.text);
            return result;
        case RawKind::Vector:
            if (m_evaluating) result.value = m_ev.vector_literal(token);
            return result;
        case RawKind::Identifier: return named(at, std::move(result));
        case RawKind::Punct: break;
        default: fail(); return result;
        }
        if (is_punct(token, '(')) {
            if (++m_depth > kDeepestNesting) {
                fail();
                return result;
            }
            Operand inner = expression(0, false);
            if (take_closing(')', result) && m_evaluating) {
                result.value = std::move(inner.value);
                result.value.boolean_literal = false;
            }
            return result;
        }
        if (is_punct(token, '<')) return vector(std::move(result));
        fail();
        return result;
    }

    // "<" items ">" with a comma between items and at most one after the last.
    Operand vector(Operand result) {
        if (++m_depth > kDeepestNesting) {
            fail();
            return result;
        }
        std::vector<Value> items;
        while (m_ok) {
            Operand item = expression(0, true);
            if (m_evaluating) items.push_back(std::move(item.value));
            if (!more()) break;
            if (is_punct(next(), ',')) {
                ++m_at;
                if (more() && is_punct(next(), '>')) break;
                continue;
            }
            break;
        }
        if (take_closing('>', result) && m_evaluating) result.value = m_ev.make_vector(items, result.range);
        return result;
    }

    Operand named(std::size_t at, Operand result) {
        const RawToken& token = m_tokens[at];
        const WordClass word = word_class_of(token);
        if (word == WordClass::Constant) {
            if (token.text == "defined") {
                fail();
                return result;
            }
            if (m_evaluating) result.value = m_ev.symbol_for_constant(token).value.as<TokenValue>().value;
            return result;
        }
        if (word == WordClass::Builtin) return builtin_call(at, std::move(result));
        if (word == WordClass::Keyword && token.keyword_token == Parser::token::TOK_TRACE)
            return trace_call(std::move(result));
        if (word != WordClass::Name && word != WordClass::IgnoredBlock) {
            fail();
            return result;
        }
        // A variable: looked up once, when checking (nothing the value
        // does can declare or remove one).
        const Value* value = nullptr;
        if (m_evaluating) {
            value = m_names[m_name_index++];
        } else {
            value = m_ev.find_name(HashedName(token.text)).value;
            const bool plain = value && (value->kind == Value::Kind::Float || value->kind == Value::Kind::Vector ||
                                         value->kind == Value::Kind::Color || value->kind == Value::Kind::String);
            if (!plain || deprecated(token)) {
                fail();
                return result;
            }
            m_names.push_back(value);
            return result;
        }
        result.value = *value;
        result.value.boolean_literal = false;
        return result;
    }

    // Using a deprecated name warns: the grammar's.
    bool deprecated(const RawToken& name) const {
        return !m_ev.m_deprecated.empty() && m_ev.m_deprecated.count(name.text) > 0;
    }

    bool take_comma() {
        if (!more() || !is_punct(next(), ',')) return fail();
        ++m_at;
        return true;
    }

    // trace(Object, start, direction [, Name]): Name receives the normal
    // (as a #declare), before anything after the call is read.
    Operand trace_call(Operand result) {
        if (!more() || !is_punct(next(), '(') || ++m_depth > kDeepestNesting) {
            fail();
            return result;
        }
        ++m_at;
        if (!more() || next().kind != RawKind::Identifier) {
            fail();
            return result;
        }
        const std::size_t object_at = m_at++;
        const Value* object = nullptr;
        if (m_evaluating) {
            object = m_names[m_name_index++];
        } else {
            const RawToken& name = m_tokens[object_at];
            const WordClass word = word_class_of(name);
            if (word == WordClass::Name || word == WordClass::IgnoredBlock)
                object = m_ev.find_name(HashedName(name.text)).value;
            if (!object || object->kind != Value::Kind::Object || deprecated(name)) {
                fail();
                return result;
            }
            m_names.push_back(object);
        }
        if (!take_comma()) return result;
        Operand from = expression(0, false);
        if (!take_comma()) return result;
        Operand along = expression(0, false);
        std::optional<std::size_t> normal_at;
        if (more() && is_punct(next(), ',')) {
            ++m_at;
            if (!more() || next().kind != RawKind::Identifier) {
                fail();
                return result;
            }
            normal_at = m_at++;
            if (!m_evaluating && !normal_name(m_tokens[*normal_at])) {
                fail();
                return result;
            }
        }
        if (!take_closing(')', result) || !m_evaluating) return result;
        const std::string normal = normal_at ? m_tokens[*normal_at].text : std::string();
        if (normal_at && !m_ev.find_name(HashedName(normal)).value) m_ev.m_last_undeclared = normal;
        result.value = m_ev.trace(*object, token_range(object_at), from.value, from.range, along.value, along.range,
                                  normal, result.range);
        return result;
    }

    // The grammar's trace_normal: a value's name or an undeclared word
    // (not a macro's, which would be called).
    bool normal_name(const RawToken& name) const {
        const WordClass word = word_class_of(name);
        if (word != WordClass::Name && word != WordClass::IgnoredBlock) return false;
        if (deprecated(name)) return false;
        const Value* value = m_ev.find_name(HashedName(name.text)).value;
        if (value) return m_ev.token_for_value(*value) == Parser::token::TOK_VALUE_ID;
        return m_ev.m_macros.find(name.text) == m_ev.m_macros.end();
    }

    Operand builtin_call(std::size_t at, Operand result) {
        if (!more() || !is_punct(next(), '(') || ++m_depth > kDeepestNesting) {
            fail();
            return result;
        }
        ++m_at;
        std::vector<Value> arguments;
        if (more() && !is_punct(next(), ')')) {
            while (m_ok) {
                Operand argument = expression(0, false);
                if (m_evaluating) arguments.push_back(std::move(argument.value));
                if (!more() || !is_punct(next(), ',')) break;
                ++m_at;
            }
        }
        if (take_closing(')', result) && m_evaluating)
            result.value = m_ev.call_builtin(m_tokens[at].text, arguments, result.range);
        return result;
    }

    Evaluator& m_ev;
    const std::vector<RawToken>& m_tokens;
    std::size_t m_first;
    std::size_t m_end;
    std::size_t m_at = 0;
    bool m_evaluating = false;
    bool m_ok = true;
    int m_depth = 0;
    std::vector<const Value*> m_names;  // the variables met, in order
    std::size_t m_name_index = 0;
};

// The expression from `first` to one of `terminators` in the innermost
// frame, or none (nothing read). `take_terminator`: whether it is read too
// (else it is left for the caller to take, as the grammar leaves its
// lookahead).
std::optional<Value> Evaluator::read_plain(std::size_t first, std::string_view terminators, bool take_terminator) {
    Frame& frame = *m_frames.back();
    PlainValueReader reader(*this, frame.buffer->tokens, first, frame.end);
    const std::optional<std::size_t> end = reader.check(terminators);
    if (!end) return std::nullopt;
    const std::size_t read = *end - frame.position + 1;  // with the terminator the grammar reads
    if (m_tokens_read + long(read) > 50'000'000L + 20 * m_options.max_loop_iterations) return std::nullopt;
    Value value = reader.evaluate();
    m_tokens_read += long(read);
    // What reading the tokens one by one would have left behind.
    for (std::size_t i = *end; i-- > frame.position;)
        if (frame.buffer->tokens[i].kind == RawKind::Identifier) {
            m_previous_word = frame.buffer->tokens[i].text;
            break;
        }
    const RawToken& last = frame.buffer->tokens[*end];
    m_last_location = last.location;
    m_last_location.column += static_cast<int>(last.text.size());
    m_previous_kind = last.text[0] == ';'   ? Parser::symbol_kind::S_SEMI
                      : last.text[0] == ',' ? Parser::symbol_kind::S_COMMA
                                            : Parser::symbol_kind::S_RPAREN;
    frame.position = take_terminator ? *end + 1 : *end;
    return value;
}

bool Evaluator::may_read_plain() const {
    if (!m_options.plain_values || !m_pending.empty() || m_frames.empty() || m_aborted) return false;
    // Keywords are free words inside an integrator's block: the grammar's.
    if (!m_block_names.empty() && m_block_names.back() == "integrator") return false;
    return m_nesting + 1 + kDeepestNesting <= m_options.max_nesting_depth;
}

std::optional<Value> Evaluator::read_plain_value() {
    if (!may_read_plain()) return std::nullopt;
    return read_plain(m_frames.back()->position, ";", false);
}

std::optional<Value> Evaluator::read_plain_item() {
    if (!may_read_plain()) return std::nullopt;
    return read_plain(m_frames.back()->position, ",)", false);
}

std::optional<Value> Evaluator::read_plain_condition() {
    if (!may_read_plain()) return std::nullopt;
    const Frame& frame = *m_frames.back();
    if (frame.position >= frame.end || !is_punct(frame.buffer->tokens[frame.position], '(')) return std::nullopt;
    return read_plain(frame.position + 1, ")", true);
}

}  // namespace lancer::parse
