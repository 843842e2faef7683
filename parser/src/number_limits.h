// What the scene language accepts of a number where a whole number or a
// renderable value is wanted: the grammar's checks and the scanner's
// reading of literal mesh2 sections (lexer.l) must agree on it.
#pragma once

#include <cmath>
#include <limits>

namespace lancer::parse {

// The renderer stores geometry and colours in single precision, where 1e39
// is infinity and turns a surface black or NaN.
inline bool fits_single_precision(double x) {
    return std::isfinite(x) && std::fabs(x) <= double(std::numeric_limits<float>::max());
}

// A whole number in int's range, stored in `out` (0 when it is not one:
// a cast of any other value is undefined).
inline bool whole_int(double x, int& out) {
    out = 0;
    if (!(x == std::floor(x)) || x < double(std::numeric_limits<int>::min()) ||
        x > double(std::numeric_limits<int>::max()))
        return false;
    out = static_cast<int>(x);
    return true;
}

}  // namespace lancer::parse
