// POV-Ray's user-defined functions (`function { expr }`, `function(a, b)
// { expr }`, `function { internal(N) }`, `function { pattern { … } }`,
// `function { pigment { … } }`, `function { transform { … } }`), compiled by the parser into a small stack
// program that the parser (for calls in expressions) and the renderer (for
// the function pattern and isosurfaces) run alike. Header-only: the scene
// graph is headers, and both sides interpret the same code.
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include <glm/glm.hpp>

namespace lancer::sg {

struct Pattern;
struct Pigment;
struct SourceLocation;

// What a function may ask of the renderer: noise, patterns and pigments
// live there. The parser evaluates functions that need none of them.
class FunctionNatives {
  public:
    virtual ~FunctionNatives() = default;
    // POV's Noise() in [0, 1] with noise_generator 1, 2 or 3.
    virtual double noise(const glm::dvec3& p, int generator) const = 0;
    // The pattern's value (function { pattern { … } }) at p.
    virtual double pattern(const Pattern& pattern, const glm::dvec3& p) const = 0;
    // The pigment's colour (r, g, b, filter, transmit) at p.
    virtual std::array<double, 5> pigment(const Pigment& pigment, const glm::dvec3& p) const = 0;
    // POV's DTurbulence(), the SDL's vturbulence(lambda, omega, octaves, p).
    virtual glm::dvec3 turbulence_vector(const glm::dvec3& p, double omega, double lambda, int octaves) const;
    // The answers under global_settings' `noise_generator` (1-3: what
    // patterns and f_noise3d that choose none take). The render's natives
    // are made for one scene and answer as they are; those that answer while
    // a scene is parsed follow the setting as the text changes it.
    virtual const FunctionNatives& with_noise_generator(int /*noise_generator*/) const { return *this; }
};

struct Function {
    enum class Op : std::uint8_t {
        Constant,   // push constants[index]
        Parameter,  // push the argument `index`
        Add,
        Subtract,
        Multiply,
        Divide,
        Negate,
        Not,
        Less,
        LessEqual,
        Greater,
        GreaterEqual,
        Equal,
        NotEqual,
        And,
        Or,
        Math1,    // index: a Math1 code; one operand
        Math2,    // index: a Math2 code; two operands
        Minimum,  // count operands
        Maximum,  // count operands
        Select,   // count 3 or 4: POV's select(a, b, c [, d])
        Call,     // callees[index] with count arguments (a pigment function: its `channel`)
        Sum,      // POV's sum(i, b, e, body): callees[index] (the body) with this function's first count
                  // arguments and i, added for i = b, b + 1, … up to e (b and e on the stack)
        Product,  // POV's prod(…): the same, multiplied
    };
    enum Math1Code {
        Abs,
        Acos,
        Acosh,
        Asin,
        Asinh,
        Atan,
        Atanh,
        Ceil,
        Cos,
        Cosh,
        Degrees,
        Exp,
        Floor,
        Int,
        Ln,
        Log,
        Radians,
        Sin,
        Sinh,
        Sqrt,
        Sqr,
        Tan,
        Tanh,
        Sign
    };
    enum Math2Code { Atan2, Mod, Pow, Div };
    struct Instruction {
        Op op = Op::Constant;
        int index = 0;
        int count = 0;
        int channel = 0;
    };

    std::vector<std::string> parameters;  // x, y, z unless written
    std::vector<Instruction> code;
    std::vector<double> constants;
    std::vector<std::shared_ptr<const Function>> callees;
    // The function's own body when it is not an expression.
    int internal = -1;                       // function { internal(N) }
    std::shared_ptr<const Pattern> pattern;  // function { pattern { … } }
    std::shared_ptr<const Pigment> pigment;  // function { pigment { … } }: a colour
    // function { transform { … } }: the point moved by the transform, a
    // vector (.x .y .z; POV's vtransform in transforms.inc).
    std::shared_ptr<const glm::dmat4> transform;
    // function { spline { … } }: the spline's value at the first argument,
    // up to 5 components (.x .y .z .t and the fifth), `spline_terms` of them
    // written. The parser keeps how splines are evaluated to itself.
    std::function<std::array<double, 5>(double)> spline;
    int spline_terms = 0;
    int stack_size = 0;
    std::string name;  // the #declare'd name, for messages
};
using FunctionRef = std::shared_ptr<const Function>;

// Thrown for what a function cannot do: an internal function lancer lacks,
// a pattern asked for without a renderer.
struct FunctionError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// POV's channel of a pigment function: .red .green .blue .filter .transmit
// (.x .y .z .t, .gray as POV's grey weights); 0..4 and 5 for grey. A
// transform function's .x .y .z are 0..2.
double evaluate_function(const Function& f, const double* arguments, int count, const FunctionNatives* natives,
                         int channel = 0);

}  // namespace lancer::sg

#include "lancer/function_eval.h"
