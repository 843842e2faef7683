// POV-Ray's julia_fractal: a 3D slice of a 4D Julia set (internal to
// liblancer; see julia_fractal.cpp for the method).
//
//   julia_fractal { <julia_parameter> [quaternion | hypercomplex] [function]
//                   [max_iteration N] [precision P] [slice <normal>, distance] }
#pragma once

#include <memory>

#include <glm/glm.hpp>

#include "geometry/shape.h"

namespace lancer {

struct JuliaFractalParameters {
    enum class Algebra { Quaternion, Hypercomplex };
    // POV's function keywords; Pwr takes `power` (pwr(X, Y) = z^(X + iY)).
    enum class Function {
        Sqr,
        Cube,
        Reciprocal,
        Exp,
        Ln,
        Sin,
        Asin,
        Cos,
        Acos,
        Tan,
        Atan,
        Sinh,
        Asinh,
        Cosh,
        Acosh,
        Tanh,
        Atanh,
        Pwr
    };
    glm::dvec4 julia_parameter{1.0, 0.0, 0.0, 0.0};  // c of z -> f(z) + c, as <x, y, z, t>
    Algebra algebra = Algebra::Quaternion;
    Function function = Function::Sqr;
    glm::dvec2 power{0.0, 0.0};  // pwr's exponent (real, imaginary)
    int max_iteration = 20;      // below 1 counts as 1 (POV)
    double precision = 20.0;     // as written; the march's least step is 1 / max(precision, 1) (POV)
    // The 4D hyperplane dot(slice_normal, q) = slice_distance that holds the
    // 3D object; the normal as written (the shape normalizes it).
    glm::dvec4 slice_normal{0.0, 0.0, 0.0, 1.0};
    double slice_distance = 0.0;
};

// Null for what POV-Ray refuses: a quaternion function other than sqr and
// cube ("Illegal function: quaternion only supports sqr and cube"), a slice
// normal with |normal|^2 < 1e-10 ("Slice vector is zero.") or |t| < 1e-10
// before normalizing ("Slice t component is zero."), and for non-finite
// parameters.
std::shared_ptr<const Shape> make_julia_fractal_shape(const JuliaFractalParameters& parameters);

}  // namespace lancer
