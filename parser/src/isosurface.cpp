// POV-Ray's isosurface: its function and search settings as POV-Ray 3.7
// reads them (Parse_Isosurface in its parse.cpp), with POV's warnings and
// fallbacks for values it cannot use. Its contained_by is in
// contained_by.cpp.
#include <algorithm>
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {

namespace {

constexpr int kMostTraces = 10;  // POV's ISOSURFACE_MAXTRACE

}  // namespace

std::function<void(sg::Isosurface&)> Evaluator::isosurface_number(const std::string& keyword, const Value& value,
                                                                  const SourceRange& where) {
    double number = to_float(value, where, "a float " + keyword);
    if (!check_renderable(&number, 1, where, "isosurface " + keyword)) return [](sg::Isosurface&) {};
    if (keyword == "threshold") return [number](sg::Isosurface& iso) { iso.threshold = number; };
    if (keyword == "accuracy") {
        if (!(number > 0.0)) {
            warning(where.begin, "isosurface 'accuracy' is not positive; using 0.001 (POV-Ray's default)");
            number = 0.001;
        }
        return [number](sg::Isosurface& iso) { iso.accuracy = number; };
    }
    if (keyword == "max_gradient") {
        if (!(number > 0.0)) {
            warning(where.begin, "isosurface 'max_gradient' is not positive; using 1.1 (POV-Ray's default)");
            number = 1.1;
        }
        return [number](sg::Isosurface& iso) { iso.max_gradient = number; };
    }
    // max_trace: POV truncates to a short, then keeps it within 1..10.
    int traces = int(std::clamp(std::trunc(number), -1.0, double(kMostTraces) + 1.0));
    if (traces > kMostTraces) {
        warning(where.begin, "isosurface 'max_trace' exceeds POV-Ray's maximum of 10; using 10");
        traces = kMostTraces;
    } else if (traces < 1) {
        warning(where.begin, "isosurface 'max_trace' is not positive; using 1 (POV-Ray's default)");
        traces = 1;
    }
    return [traces](sg::Isosurface& iso) { iso.max_trace = traces; };
}

std::function<void(sg::Isosurface&)> Evaluator::isosurface_evaluate(const std::array<Value, 3>& values,
                                                                    const std::array<SourceRange, 3>& where) {
    sg::Vec3 parameters;
    for (int i = 0; i < 3; ++i) {
        parameters[i] = to_float(values[std::size_t(i)], where[std::size_t(i)], "a float");
        if (!check_renderable(&parameters[i], 1, where[std::size_t(i)], "isosurface evaluate"))
            return [](sg::Isosurface&) {};
    }
    return [parameters](sg::Isosurface& iso) {
        iso.evaluate = true;
        iso.evaluate_parameters = parameters;
    };
}

ShapePtr Evaluator::make_isosurface(const Value& function, const SourceRange& where, const Edits<sg::Isosurface>& items,
                                    const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Isosurface, at);
    sg::Isosurface iso;
    iso.location = where.begin;
    if (function.kind != Value::Kind::Function || !function.function()) {
        error(where.begin, "isosurface needs a function { … } first");
    } else if (function.function()->pigment) {
        error(where.begin, "isosurface: a pigment function has a colour, not a value; use one of its channels");
    } else {
        iso.function = function.function();
        if (const int missing = sg::first_unsupported_internal(*iso.function); missing >= 0)
            error(where.begin, "POV-Ray 3.7 has no internal function " + std::to_string(missing));
    }
    for (const auto& item : items) item(iso);
    shape->object.shape = iso;
    return shape;
}

}  // namespace lancer::parse
