// POV-Ray's parametric: three functions of (u, v), the rectangle of (u, v)
// they are drawn over, and the search settings, as POV-Ray 3.7 reads them
// (Parse_Parametric in its parse.cpp). Its contained_by is the
// isosurface's (contained_by.cpp).
#include <algorithm>
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {

namespace {

constexpr int kDeepestPrecompute = 20;  // POV-Ray's limit: 2^20 bounds per coordinate

}  // namespace

std::function<void(sg::Parametric&)> Evaluator::parametric_number(const std::string& keyword, const Value& value,
                                                                  const SourceRange& where) {
    double number = to_float(value, where, "a float " + keyword);
    if (!check_renderable(&number, 1, where, "parametric " + keyword)) return [](sg::Parametric&) {};
    // POV-Ray takes any number here; with one not positive its search
    // never ends (accuracy) or skips the whole surface (max_gradient).
    if (keyword == "accuracy") {
        if (!(number > 0.0)) {
            warning(where.begin, "parametric 'accuracy' is not positive; using 0.001 (POV-Ray's default)");
            number = 0.001;
        }
        return [number](sg::Parametric& p) { p.accuracy = number; };
    }
    if (!(number > 0.0)) {
        warning(where.begin, "parametric 'max_gradient' is not positive; using 1 (POV-Ray's default)");
        number = 1.0;
    }
    return [number](sg::Parametric& p) { p.max_gradient = number; };
}

std::function<void(sg::Parametric&)> Evaluator::parametric_precompute(const Value& depth_value,
                                                                      const SourceRange& where,
                                                                      const std::vector<std::string>& axes,
                                                                      const sg::SourceLocation& axes_at) {
    int mask = 0;
    for (const std::string& axis : axes) {
        if (axis == "x")
            mask |= 1;
        else if (axis == "y")
            mask |= 2;
        else if (axis == "z")
            mask |= 4;
        else {
            error(axes_at, "parametric: precompute names the coordinates x, y and z, not '" + axis + "'");
            return [](sg::Parametric&) {};
        }
    }
    // POV truncates the depth, and checks it only when a coordinate is named.
    const double depth = std::trunc(to_float(depth_value, where, "a float depth"));
    if (mask && !(depth >= 1.0 && depth <= kDeepestPrecompute)) {
        error(where.begin, "parametric: precompute's depth must be 1 to 20 (POV-Ray's \"invalid depth\")");
        return [](sg::Parametric&) {};
    }
    return [depth = mask ? int(depth) : 0, mask](sg::Parametric& p) {
        p.precompute_depth = depth;
        p.precompute_axes = mask;
    };
}

ShapePtr Evaluator::make_parametric(const std::array<Value, 3>& functions, const std::array<SourceRange, 3>& where,
                                    const Value& uv_min, const SourceRange& wmin, const Value& uv_max,
                                    const SourceRange& wmax, const Edits<sg::Parametric>& items,
                                    const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Parametric, at);
    sg::Parametric parametric;
    parametric.location = at;
    static const char* const kCoordinate[3] = {"x", "y", "z"};
    for (std::size_t i = 0; i < 3; ++i) {
        const Value& function = functions[i];
        const std::string which = std::string("parametric: the ") + kCoordinate[i] + " function";
        if (function.kind != Value::Kind::Function || !function.function()) {
            error(where[i].begin, which + " must be a function { … } of u and v");
        } else if (function.function()->pigment) {
            error(where[i].begin, which +
                                      " is a pigment function: it has a colour, not a value; use one of its "
                                      "channels");
        } else {
            parametric.functions[i] = function.function();
            if (const int missing = sg::first_unsupported_internal(*function.function()); missing >= 0)
                error(where[i].begin, "POV-Ray 3.7 has no internal function " + std::to_string(missing));
        }
    }
    const auto uv = [&](const Value& value, const SourceRange& range, sg::Vec2& out) {
        if (value.kind == Value::Kind::Vector && value.size >= 2)
            out = sg::Vec2(value.v[0], value.v[1]);
        else if (value.kind == Value::Kind::Float)
            out = sg::Vec2(value.v[0]);
        else {
            error(range.begin, "parametric: the (u, v) range is two 2-D vectors, <u1, v1>, <u2, v2>");
            return false;
        }
        const double both[2] = {out.x, out.y};
        return check_renderable(both, 2, range, "the (u, v) corner");
    };
    sg::Vec2 low{0.0}, high{1.0};
    if (uv(uv_min, wmin, low) && uv(uv_max, wmax, high)) {
        // POV orders each coordinate's bounds.
        parametric.uv_min = glm::min(low, high);
        parametric.uv_max = glm::max(low, high);
    }
    for (const auto& item : items) item(parametric);
    shape->object.shape = parametric;
    return shape;
}

}  // namespace lancer::parse
