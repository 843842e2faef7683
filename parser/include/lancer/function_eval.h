// The interpreter of lancer::sg::Function (included by function.h).
#pragma once

#include <algorithm>

namespace lancer::sg {

namespace function_detail {

constexpr double kPi = 3.14159265358979323846;

inline double math1(int code, double a) {
    switch (code) {
    case Function::Abs: return std::fabs(a);
    case Function::Acos: return std::acos(a);
    case Function::Acosh: return std::acosh(a);
    case Function::Asin: return std::asin(a);
    case Function::Asinh: return std::asinh(a);
    case Function::Atan: return std::atan(a);
    case Function::Atanh: return std::atanh(a);
    case Function::Ceil: return std::ceil(a);
    case Function::Cos: return std::cos(a);
    case Function::Cosh: return std::cosh(a);
    case Function::Degrees: return a * 180.0 / kPi;
    case Function::Exp: return std::exp(a);
    case Function::Floor: return std::floor(a);
    case Function::Int: return std::trunc(a);
    case Function::Ln: return std::log(a);
    case Function::Log: return std::log10(a);
    case Function::Radians: return a * kPi / 180.0;
    case Function::Sin: return std::sin(a);
    case Function::Sinh: return std::sinh(a);
    case Function::Sqrt: return std::sqrt(a);
    case Function::Sqr: return a * a;
    case Function::Tan: return std::tan(a);
    case Function::Tanh: return std::tanh(a);
    case Function::Sign: return a > 0.0 ? 1.0 : a < 0.0 ? -1.0 : 0.0;
    }
    return 0.0;
}

inline double math2(int code, double a, double b) {
    switch (code) {
    case Function::Atan2: return std::atan2(a, b);
    case Function::Mod: return std::fmod(a, b);
    case Function::Pow: return std::pow(a, b);
    case Function::Div: return std::trunc(a / b);
    }
    return 0.0;
}

// POV's internal functions lancer has (functions.inc names them), from
// POV-Ray's documented definitions. a: x, y, z, then the extra parameters.
inline double internal_function(int number, const double* a, int count, const FunctionNatives* natives) {
    auto p = [&](int i) { return 3 + i < count ? a[3 + i] : 0.0; };
    const double x = count > 0 ? a[0] : 0.0, y = count > 1 ? a[1] : 0.0, z = count > 2 ? a[2] : 0.0;
    switch (number) {
    case 17: return std::sqrt(x * x * p(0) * p(0) + y * y * p(1) * p(1) + z * z * p(2) * p(2));  // f_ellipsoid
    case 47: return std::atan2(std::sqrt(x * x + z * z), y);                                     // f_ph
    case 57: return std::sqrt(x * x + y * y + z * z);                                            // f_r
    case 60: {  // f_rounded_box: radius p0, half sizes p1..p3
        const double r = p(0);
        const double ex = std::max({0.0, x - (p(1) - r), (r - p(1)) - x});
        const double ey = std::max({0.0, y - (p(2) - r), (r - p(2)) - y});
        const double ez = std::max({0.0, z - (p(3) - r), (r - p(3)) - z});
        return std::sqrt(ex * ex + ey * ey + ez * ez) - r - 1e-6;
    }
    case 61: return std::sqrt(x * x + y * y + z * z) - p(0);  // f_sphere
    case 68: {                                                // f_superellipsoid: e p0, n p1
        const double e = p(0), n = p(1);
        const double xy = std::pow(std::pow(std::fabs(x), 2.0 / e) + std::pow(std::fabs(y), 2.0 / e), e / n);
        return 1.0 - std::pow(xy + std::pow(std::fabs(z), 2.0 / n), n * 0.5);
    }
    case 69: return std::atan2(x, z);  // f_th
    case 70: {                         // f_torus: major p0, minor p1
        const double ring = std::sqrt(x * x + z * z) - p(0);
        return std::sqrt(ring * ring + y * y) - p(1);
    }
    case 76:  // f_noise3d: the scene's noise generator
    case 78:  // f_noise_generator: the generator p0
        if (!natives) throw FunctionError("f_noise3d needs the renderer's noise");
        return natives->noise(glm::dvec3(x, y, z), number == 76 ? 0 : (int(p(0)) & 3));
    }
    throw FunctionError("POV-Ray's internal function " + std::to_string(number) + " is not supported yet");
}

inline bool internal_function_supported(int number) {
    switch (number) {
    case 17:
    case 47:
    case 57:
    case 60:
    case 61:
    case 68:
    case 69:
    case 70:
    case 76:
    case 78: return true;
    default: return false;
    }
}

}  // namespace function_detail

// The first internal function lancer lacks that f or anything it calls
// needs; -1 when there is none.
inline int first_unsupported_internal(const Function& f) {
    if (f.internal >= 0 && !function_detail::internal_function_supported(f.internal)) return f.internal;
    for (const auto& callee : f.callees)
        if (int missing = first_unsupported_internal(*callee); missing >= 0) return missing;
    return -1;
}

inline double evaluate_function(const Function& f, const double* arguments, int count, const FunctionNatives* natives,
                                int channel) {
    using Op = Function::Op;
    if (f.internal >= 0) return function_detail::internal_function(f.internal, arguments, count, natives);
    auto argument = [&](int i) { return i < count ? arguments[i] : 0.0; };
    if (f.pattern) {
        if (!natives) throw FunctionError("a pattern function needs the renderer");
        return natives->pattern(*f.pattern, glm::dvec3(argument(0), argument(1), argument(2)));
    }
    if (f.pigment) {
        if (!natives) throw FunctionError("a pigment function needs the renderer");
        const std::array<double, 5> c = natives->pigment(*f.pigment, glm::dvec3(argument(0), argument(1), argument(2)));
        if (channel == 5) return 0.297 * c[0] + 0.589 * c[1] + 0.114 * c[2];  // POV's grey
        return c[std::clamp(channel, 0, 4)];
    }
    // A small fixed stack serves nearly every function; deeper ones use
    // the heap.
    double local[32];
    std::vector<double> heap;
    double* stack = local;
    if (f.stack_size > 32) {
        heap.resize(f.stack_size);
        stack = heap.data();
    }
    int top = 0;  // the number of values on the stack
    const std::size_t size = f.code.size();
    for (std::size_t pc = 0; pc < size; ++pc) {
        const Function::Instruction& in = f.code[pc];
        switch (in.op) {
        case Op::Constant: stack[top++] = f.constants[in.index]; break;
        case Op::Parameter: stack[top++] = argument(in.index); break;
        case Op::Add:
            --top;
            stack[top - 1] += stack[top];
            break;
        case Op::Subtract:
            --top;
            stack[top - 1] -= stack[top];
            break;
        case Op::Multiply:
            --top;
            stack[top - 1] *= stack[top];
            break;
        case Op::Divide:
            --top;
            stack[top - 1] /= stack[top];
            break;
        case Op::Negate: stack[top - 1] = -stack[top - 1]; break;
        case Op::Not: stack[top - 1] = stack[top - 1] == 0.0 ? 1.0 : 0.0; break;
        case Op::Less:
            --top;
            stack[top - 1] = stack[top - 1] < stack[top] ? 1.0 : 0.0;
            break;
        case Op::LessEqual:
            --top;
            stack[top - 1] = stack[top - 1] <= stack[top] ? 1.0 : 0.0;
            break;
        case Op::Greater:
            --top;
            stack[top - 1] = stack[top - 1] > stack[top] ? 1.0 : 0.0;
            break;
        case Op::GreaterEqual:
            --top;
            stack[top - 1] = stack[top - 1] >= stack[top] ? 1.0 : 0.0;
            break;
        case Op::Equal:
            --top;
            stack[top - 1] = stack[top - 1] == stack[top] ? 1.0 : 0.0;
            break;
        case Op::NotEqual:
            --top;
            stack[top - 1] = stack[top - 1] != stack[top] ? 1.0 : 0.0;
            break;
        case Op::And:
            --top;
            stack[top - 1] = (stack[top - 1] != 0.0 && stack[top] != 0.0) ? 1.0 : 0.0;
            break;
        case Op::Or:
            --top;
            stack[top - 1] = (stack[top - 1] != 0.0 || stack[top] != 0.0) ? 1.0 : 0.0;
            break;
        case Op::Math1: stack[top - 1] = function_detail::math1(in.index, stack[top - 1]); break;
        case Op::Math2:
            --top;
            stack[top - 1] = function_detail::math2(in.index, stack[top - 1], stack[top]);
            break;
        case Op::Minimum:
        case Op::Maximum: {
            top -= in.count;
            double value = stack[top];
            for (int i = 1; i < in.count; ++i)
                value = in.op == Op::Minimum ? std::min(value, stack[top + i]) : std::max(value, stack[top + i]);
            stack[top++] = value;
            break;
        }
        case Op::Select: {
            // POV's select(a, b, c [, d]): b where a < 0, c where a = 0 (or
            // a >= 0 with three), d where a > 0.
            top -= in.count;
            const double a = stack[top];
            double value;
            if (in.count == 3)
                value = a < 0.0 ? stack[top + 1] : stack[top + 2];
            else
                value = a < 0.0 ? stack[top + 1] : a == 0.0 ? stack[top + 2] : stack[top + 3];
            stack[top++] = value;
            break;
        }
        case Op::Call: {
            top -= in.count;
            const double value = evaluate_function(*f.callees[in.index], stack + top, in.count, natives, in.channel);
            stack[top++] = value;
            break;
        }
        }
    }
    return top > 0 ? stack[top - 1] : 0.0;
}

}  // namespace lancer::sg
