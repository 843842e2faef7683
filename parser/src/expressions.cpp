// Expressions: type conversions with located errors, arithmetic with
// POV-Ray's promotions (a float stands for a vector or colour with every
// component equal), comparisons, components and colour keywords.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "evaluator.h"
#include "number_limits.h"

namespace lancer::parse {

namespace {

bool all_finite(const Value& v) {
    for (int i = 0; i < v.size; ++i)
        if (!std::isfinite(v.v[i])) return false;
    return true;
}

// sRGB-encoded channel -> linear.
double srgb_to_linear(double c) {
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

}  // namespace

Value Evaluator::checked(Value value, const SourceRange& where, const std::string& what) {
    if (value.is_numeric() && !all_finite(value)) {
        error(where.begin, what + " is not a finite number");
        for (auto& c : value.v) c = 0.0;
    }
    return value;
}

double Evaluator::to_float(const Value& value, const SourceRange& where, const std::string& what) {
    if (value.kind == Value::Kind::Float) return value.v[0];
    error(where.begin, "expected " + what + ", found " + describe(value));
    return 0.0;
}

int saturated_int(double value) {
    if (!(value == value)) return 0;
    return static_cast<int>(std::clamp(value, -2.0e9, 2.0e9));
}

int Evaluator::to_int(const Value& value, const SourceRange& where) {
    double f = to_float(value, where, "an integer");
    if (std::fabs(f) > 2e9) {
        error(where.begin, "integer out of range: " + std::to_string(f));
        return 0;
    }
    return static_cast<int>(std::floor(f + 1e-9));
}

double Evaluator::positive(const Value& value, const SourceRange& where, const std::string& what) {
    double f = to_float(value, where, "a float for " + what);
    if (value.kind == Value::Kind::Float && !check_renderable(&f, 1, where, what)) return 1.0;
    if (f <= 0.0 && value.kind == Value::Kind::Float) {
        error(where.begin, what + " must be positive, got " + std::to_string(f));
        return 1.0;
    }
    return f;
}

bool Evaluator::check_renderable(const double* values, int count, const SourceRange& where, const std::string& what) {
    for (int i = 0; i < count; ++i) {
        if (fits_single_precision(values[i])) continue;
        char shown[32];
        std::snprintf(shown, sizeof shown, "%g", values[i]);
        error(where.begin, what + " " + shown + " is beyond what lancer renders (finite, magnitude at most 3.4e38)");
        return false;
    }
    return true;
}

sg::Vec3 Evaluator::to_vec3(const Value& value, const SourceRange& where) {
    sg::Vec3 v(0.0);
    switch (value.kind) {
    case Value::Kind::Float: v = sg::Vec3(value.v[0]); break;
    case Value::Kind::Vector:
        if (value.size == 2) {
            v = {value.v[0], value.v[1], 0.0};
            break;
        }
        if (value.size == 3) {
            v = {value.v[0], value.v[1], value.v[2]};
            break;
        }
        error(where.begin, "expected a 3-component vector, found " + describe(value));
        return sg::Vec3(0.0);
    default: error(where.begin, "expected a vector, found " + describe(value)); return sg::Vec3(0.0);
    }
    if (!check_renderable(&v.x, 3, where, "a vector component")) return sg::Vec3(0.0);
    return v;
}

sg::Vec3 Evaluator::nonzero_vec3(const Value& value, const SourceRange& where, const std::string& what) {
    sg::Vec3 v = to_vec3(value, where);
    if (glm::length(v) == 0.0 && value.is_numeric()) {
        error(where.begin, what + " must not be a zero vector");
        return {0.0, 1.0, 0.0};
    }
    return v;
}

sg::Color Evaluator::to_color(const Value& value, const SourceRange& where) {
    sg::Color c;
    switch (value.kind) {
    case Value::Kind::Float: c.rgb = sg::Vec3(value.v[0]); break;
    case Value::Kind::Color: c = {{value.v[0], value.v[1], value.v[2]}, value.v[3], value.v[4]}; break;
    case Value::Kind::Vector:
        if (value.size >= 3) {
            c.rgb = {value.v[0], value.v[1], value.v[2]};
            if (value.size >= 4) c.filter = value.v[3];
            if (value.size >= 5) c.transmit = value.v[4];
            break;
        }
        [[fallthrough]];
    default: error(where.begin, "expected a colour, found " + describe(value)); return c;
    }
    const double channels[5] = {c.rgb.x, c.rgb.y, c.rgb.z, c.filter, c.transmit};
    if (!check_renderable(channels, 5, where, "a colour channel")) return sg::Color{};
    return c;
}

std::string Evaluator::to_string(const Value& value, const SourceRange& where) {
    if (value.kind == Value::Kind::String) return value.text;
    error(where.begin, "expected a string, found " + describe(value));
    return "";
}

Value Evaluator::arithmetic(char op, const Value& a, const Value& b, const SourceRange& where) {
    if (!a.is_numeric() || !b.is_numeric()) {
        const Value& bad = a.is_numeric() ? b : a;
        error(where.begin,
              std::string("operator '") + op + "' needs numbers, vectors or colours, found " + describe(bad));
        return Value::number(0.0);
    }
    // Result shape: a colour wins, else the longer vector, else a float.
    Value result;
    if (a.kind == Value::Kind::Color || b.kind == Value::Kind::Color) {
        result.kind = Value::Kind::Color;
        result.size = 5;
    } else if (a.kind == Value::Kind::Vector || b.kind == Value::Kind::Vector) {
        result.kind = Value::Kind::Vector;
        result.size = std::max(a.kind == Value::Kind::Vector ? a.size : 0, b.kind == Value::Kind::Vector ? b.size : 0);
    }
    auto component = [](const Value& v, int i) {
        if (v.kind == Value::Kind::Float) return v.v[0];
        return i < v.size ? v.v[i] : 0.0;
    };
    for (int i = 0; i < result.size; ++i) {
        double x = component(a, i), y = component(b, i);
        switch (op) {
        case '+': result.v[i] = x + y; break;
        case '-': result.v[i] = x - y; break;
        case '*': result.v[i] = x * y; break;
        case '/':
            if (y == 0.0) {
                error(where.begin, "division by zero");
                result.v[i] = 0.0;
                continue;
            }
            result.v[i] = x / y;
            break;
        }
    }
    return checked(result, where, std::string("the result of '") + op + "'");
}

Value Evaluator::compare(const std::string& op, const Value& a, const SourceRange& wa, const Value& b,
                         const SourceRange& wb) {
    if (a.kind == Value::Kind::String && b.kind == Value::Kind::String) {
        // POV compares strings as strcmp does.
        const int order = a.text.compare(b.text);
        const bool r = op == "<"    ? order < 0
                       : op == "<=" ? order <= 0
                       : op == ">"  ? order > 0
                       : op == ">=" ? order >= 0
                       : op == "="  ? order == 0
                                    : order != 0;
        return Value::number(r ? 1.0 : 0.0);
    }
    double x = to_float(a, wa, "a float operand of '" + op + "'");
    double y = to_float(b, wb, "a float operand of '" + op + "'");
    bool r = op == "<"    ? x < y
             : op == "<=" ? x <= y
             : op == ">"  ? x > y
             : op == ">=" ? x >= y
             : op == "="  ? x == y
                          : x != y;
    return Value::number(r ? 1.0 : 0.0);
}

Value Evaluator::logical(char op, const Value& a, const SourceRange& wa, const Value& b, const SourceRange& wb) {
    bool x = to_float(a, wa, std::string("a float operand of '") + op + "'") != 0.0;
    bool y = to_float(b, wb, std::string("a float operand of '") + op + "'") != 0.0;
    return Value::number((op == '&' ? x && y : x || y) ? 1.0 : 0.0);
}

Value Evaluator::negate(const Value& a, const SourceRange& where) {
    if (!a.is_numeric()) {
        error(where.begin, "cannot negate " + describe(a));
        return Value::number(0.0);
    }
    Value result = a;
    result.boolean_literal = false;
    for (int i = 0; i < result.size; ++i) result.v[i] = -result.v[i];
    return result;
}

Value Evaluator::component(const Value& a, const SourceRange& wa, const std::string& name, const SourceRange& wn) {
    int index = -1;
    if (name == "x" || name == "u" || name == "red")
        index = 0;
    else if (name == "y" || name == "v" || name == "green")
        index = 1;
    else if (name == "z" || name == "blue")
        index = 2;
    else if (name == "t" || name == "filter")
        index = 3;
    else if (name == "transmit")
        index = 4;
    if (a.kind == Value::Kind::Color && name == "gray") {
        return Value::number(0.297 * a.v[0] + 0.589 * a.v[1] + 0.114 * a.v[2]);
    }
    if (index < 0) {
        error(wn.begin,
              "unknown component '." + name + "' (use .x .y .z .t .u .v .red .green .blue .filter .transmit .gray)");
        return Value::number(0.0);
    }
    if (!(a.kind == Value::Kind::Vector || a.kind == Value::Kind::Color) || index >= a.size) {
        error(wn.begin, "'." + name + "' needs a vector or colour with that component, found " + describe(a));
        return Value::number(0.0);
    }
    return Value::number(a.v[index]);
}

Value Evaluator::make_vector(const std::vector<Value>& items, const SourceRange& where) {
    if (items.size() < 2 || items.size() > 5) {
        error(where.begin, "a vector has 2 to 5 components, this one has " + std::to_string(items.size()));
        return Value::vector({0, 0, 0});
    }
    Value result;
    result.kind = Value::Kind::Vector;
    result.size = static_cast<int>(items.size());
    for (size_t i = 0; i < items.size(); ++i) {
        if (items[i].kind != Value::Kind::Float) {
            error(where.begin,
                  "vector component " + std::to_string(i + 1) + " must be a float, found " + describe(items[i]));
            continue;
        }
        result.v[i] = items[i].v[0];
    }
    return result;
}

Value Evaluator::colour_keyword(const std::string& keyword, const Value& operand, const SourceRange& where) {
    bool srgb = keyword.rfind("srgb", 0) == 0;
    std::string channels = keyword.substr(srgb ? 4 : 3);  // "", "f", "t", "ft"
    int needed = 3 + static_cast<int>(channels.size());
    Value result;
    result.kind = Value::Kind::Color;
    result.size = 5;
    result.v = {0, 0, 0, 0, 0};
    if (operand.kind == Value::Kind::Float) {
        for (int i = 0; i < needed; ++i) result.v[i] = operand.v[0];
    } else if ((operand.kind == Value::Kind::Vector || operand.kind == Value::Kind::Color) &&
               (operand.size == needed || operand.kind == Value::Kind::Color)) {
        for (int i = 0; i < needed; ++i) result.v[i] = operand.v[i];
    } else {
        error(where.begin, keyword + " expects a float or a " + std::to_string(needed) + "-component vector, found " +
                               describe(operand));
        return result;
    }
    // rgbt's fourth value is transmit, not filter.
    if (channels == "t") {
        result.v[4] = result.v[3];
        result.v[3] = 0.0;
    }
    // POV 3.7: srgb colours are decoded into the working space, which
    // assumed_gamma G makes linear (G = 1) or gamma-encoded.
    if (srgb) {
        const double gamma = scene().global.assumed_gamma;
        for (int i = 0; i < 3; ++i) {
            result.v[i] = srgb_to_linear(result.v[i]);
            if (gamma != 1.0) result.v[i] = std::pow(std::max(result.v[i], 0.0), 1.0 / gamma);
        }
    }
    return result;
}

Value Evaluator::colour_from(const Value& operand, const SourceRange& where) {
    sg::Color c = to_color(operand, where);
    return Value::color(c);
}

Value Evaluator::colour_component(const Value& colour, const SourceRange& wc, int channel, const Value& v,
                                  const SourceRange& wv) {
    Value result = Value::color(to_color(colour, wc));
    result.v[channel] = to_float(v, wv, "a float colour component");
    return result;
}

}  // namespace lancer::parse
