// POV-Ray's arrays: `array[n1][n2]… [{ … }]`, elements read as A[i][j]…
// anywhere a value of their kind may stand (the token stream hands the
// grammar the element as if it were a declared name), assigned with
// `#declare A[i] = …`, measured by dimensions() and dimension_size().
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {
namespace {

// The most elements one array may hold: a few bytes of text must not ask
// for gigabytes.
constexpr long long kMaxArrayElements = 10'000'000;

std::string index_text(const std::vector<int>& indices) {
    std::string text;
    for (int i : indices) text += "[" + std::to_string(i) + "]";
    return text;
}

}  // namespace

int Evaluator::array_size(const Value& size, const SourceRange& where) {
    const double n = to_float(size, where, "an array size");
    if (!(n >= 1.0) || n > double(kMaxArrayElements)) {
        error(where.begin,
              "an array size must lie in 1.." + std::to_string(kMaxArrayElements) + ", got " + std::to_string(n));
        return 1;
    }
    return int(n);
}

Value Evaluator::make_array(const std::vector<int>& sizes, const ArrayInit& init, const sg::SourceLocation& at) {
    auto data = std::make_shared<ArrayData>();
    data->sizes = sizes;
    long long count = 1;
    for (int n : sizes) count *= n;
    if (count > kMaxArrayElements) {
        error(at, "the array would hold " + std::to_string(count) + " elements; lancer's limit is " +
                      std::to_string(kMaxArrayElements));
        data->sizes.assign(sizes.size(), 1);
        count = 1;
    }
    if (memory_exhausted(at, count * static_cast<long long>(sizeof(std::optional<Value>)))) {
        data->sizes.assign(sizes.size(), 1);
        count = 1;
    }
    data->elements.resize(std::size_t(count));
    if (!init.items.empty()) {
        // Each level of braces lists one dimension, in full.
        std::size_t next = 0;
        auto fill = [&](auto& self, const ArrayInit& list, std::size_t dimension) -> void {
            if (list.items.size() != std::size_t(data->sizes[dimension])) {
                error(list.location, "this array dimension has " + std::to_string(data->sizes[dimension]) +
                                         " elements, the initializer lists " + std::to_string(list.items.size()));
                return;
            }
            for (const ArrayInit& item : list.items) {
                const bool last = dimension + 1 == data->sizes.size();
                if (last != item.value.has_value()) {
                    error(item.location, last ? "expected a value, not a nested list, in the array's last dimension"
                                              : "expected a braced list for the array's next dimension");
                    return;
                }
                if (last) {
                    if (next < data->elements.size()) data->elements[next] = *item.value;
                    ++next;
                } else {
                    self(self, item, dimension + 1);
                }
            }
        };
        fill(fill, init, 0);
    }
    Value value;
    value.kind = Value::Kind::Array;
    value.payload = data;
    value.size = int(sizes.size());
    value.location = at;
    return value;
}

// Reads [i][j]… (one per dimension) after the array's name; false after
// an error.
bool Evaluator::read_array_indices(const ArrayData& data, const sg::SourceLocation& at, std::size_t& flat,
                                   std::vector<int>& indices) {
    flat = 0;
    for (std::size_t d = 0; d < data.sizes.size(); ++d) {
        const RawToken* next = peek_raw();
        if (!next || next->kind != RawKind::Punct || next->text != "[") {
            error(next ? next->location : at, "the array has " + std::to_string(data.sizes.size()) +
                                                  " dimensions; give an index for each ([i][j]…)");
            return false;
        }
        const sg::SourceLocation where = next->location;
        const Value index = parse_nested(Parser::token::TOK_START_INDEX, where, true);
        if (m_aborted) return false;
        const double i = to_float(index, SourceRange{where, where}, "an array index");
        if (!(i >= 0.0) || i >= double(data.sizes[d])) {
            error(where, "array index " + std::to_string(i) + " is outside 0.." + std::to_string(data.sizes[d] - 1));
            return false;
        }
        indices.push_back(int(i));
        flat = flat * std::size_t(data.sizes[d]) + std::size_t(i);
    }
    return true;
}

Value Evaluator::array_element(const Value& array, const sg::SourceLocation& at, std::size_t* flat_index) {
    const std::shared_ptr<ArrayData> data = array.array();  // the element outlives a reassignment
    std::size_t flat = 0;
    std::vector<int> indices;
    if (!data || !read_array_indices(*data, at, flat, indices)) {
        abort_parse();
        return Value::number(0.0);
    }
    if (!data->elements[flat]) {
        error(at, "array element " + index_text(indices) + " has not been given a value");
        abort_parse();
        return Value::number(0.0);
    }
    if (flat_index) *flat_index = flat;
    return *data->elements[flat];
}

bool Evaluator::identifier_defined(const std::string& name, const sg::SourceLocation& at) {
    const Value* found = lookup(name);
    if (!found) return m_macros.count(name) > 0;
    // #ifdef (A[i]) and defined(A[i]): whether the element has a value.
    const RawToken* next = peek_raw();
    if (found->kind != Value::Kind::Array || !found->array() || !next || next->kind != RawKind::Punct ||
        next->text != "[")
        return true;
    const std::shared_ptr<ArrayData> data = found->array();
    std::size_t flat = 0;
    std::vector<int> indices;
    if (!read_array_indices(*data, at, flat, indices)) {
        abort_parse();
        return false;
    }
    return data->elements[flat].has_value();
}

void Evaluator::assign_array_element(const std::string& name, const RawToken& directive, bool local,
                                     const sg::SourceLocation& where) {
    const Value* found = lookup(name);
    if (!found || found->kind != Value::Kind::Array || !found->array()) {
        error(where, "'" + name + "' is not an array; declare it first: #declare " + name + " = array[N];");
        return abort_parse();
    }
    const std::shared_ptr<ArrayData> data = found->array();
    std::size_t flat = 0;
    std::vector<int> indices;
    if (!read_array_indices(*data, where, flat, indices)) return abort_parse();
    if (!expect_raw_punct("=", "after '" + name + index_text(indices) + "'")) return;
    Value value = parse_nested(Parser::token::TOK_START_VALUE, directive.location, false);
    if (m_aborted) return;
    take_punct(";");
    (void)local;  // the element belongs to the array wherever it was declared
    data->elements[flat] = std::move(value);
}

}  // namespace lancer::parse
