// The interpreter of lancer::sg::Function (included by function.h).
#pragma once

#include <algorithm>
#include <vector>

#include "lancer/internal_functions.h"

namespace lancer::sg {

namespace function_detail {

constexpr double kPi = 3.14159265358979323846;
// The most steps of one sum() or prod(); the parser's #while loops stop at
// the same count (ParseOptions).
constexpr long kMostSequenceSteps = 1000000;

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

}  // namespace function_detail

// The first internal function lancer lacks (a number POV has no function for) that f or anything it calls
// needs; -1 when there is none.
inline int first_unsupported_internal(const Function& f) {
    if (f.internal >= 0 && !internal_function_supported(f.internal)) return f.internal;
    for (const auto& callee : f.callees)
        if (int missing = first_unsupported_internal(*callee); missing >= 0) return missing;
    return -1;
}

inline double evaluate_function(const Function& f, const double* arguments, int count, const FunctionNatives* natives,
                                int channel) {
    using Op = Function::Op;
    if (f.internal >= 0) return internal_function(f.internal, arguments, count, natives);
    auto argument = [&](int i) { return i < count ? arguments[i] : 0.0; };
    if (f.pattern) {
        if (!natives) throw FunctionError("a pattern function needs the renderer");
        return natives->pattern(*f.pattern, glm::dvec3(argument(0), argument(1), argument(2)));
    }
    if (f.transform) {
        const glm::dvec4 moved = *f.transform * glm::dvec4(argument(0), argument(1), argument(2), 1.0);
        return moved[std::clamp(channel, 0, 2)];
    }
    if (f.spline) return f.spline(argument(0))[std::size_t(std::clamp(channel, 0, 4))];
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
        case Op::Sum:
        case Op::Product: {
            top -= 2;
            const double first = stack[top], last = stack[top + 1];
            // The term's arguments: the function's own, then the index. On
            // the stack like the evaluator's own, as a sum is evaluated for
            // every point of a pattern or isosurface.
            const std::size_t count = std::size_t(in.count) + 1;
            double local_values[16];
            std::vector<double> heap_values;
            double* values = local_values;
            if (count > std::size(local_values)) {
                heap_values.resize(count);
                values = heap_values.data();
            }
            for (int i = 0; i < in.count; ++i) values[std::size_t(i)] = argument(i);
            const bool sum = in.op == Op::Sum;
            double total = sum ? 0.0 : 1.0;
            // Bounded as the parser's loops are: a sum over 10^12 steps in
            // a pattern would otherwise never end.
            long steps = 0;
            for (double i = first; i <= last && steps < function_detail::kMostSequenceSteps; i += 1.0, ++steps) {
                values[count - 1] = i;
                const double term = evaluate_function(*f.callees[in.index], values, in.count + 1, natives, 0);
                total = sum ? total + term : total * term;
            }
            stack[top++] = total;
            break;
        }
        }
    }
    return top > 0 ? stack[top - 1] : 0.0;
}

}  // namespace lancer::sg
