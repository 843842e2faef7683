// POV-Ray's fractal patterns in the x-y plane: mandel and julia (any
// exponent 2..33) and the two magnet formulas in their mandel and julia
// forms, coloured outside by exterior_type and inside by interior_type.
#include <cmath>

#include "materials/pattern_functions.h"

namespace lancer::pattern_detail {

namespace {

double exterior_value(const PatternSetup& s, int iterations, double a, double b) {
    const double f = s.exterior_factor;
    switch (s.exterior_type) {
    case 0: return f;
    case 1: return double(iterations) / double(s.fractal_iterations);
    case 2: return a * f;
    case 3: return b * f;
    case 4: return a * a * f;
    case 5: return b * b * f;
    case 6: return std::sqrt(a * a + b * b) * f;
    case 7: return double(unsigned(iterations) % unsigned(f)) / f;        // 0 .. (n-1)/n
    case 8: return double(unsigned(iterations) % unsigned(1.0 + f)) / f;  // 0 .. 1
    default: return 0.0;
    }
}

double interior_value(const PatternSetup& s, double a, double b, double min_distance2) {
    const double f = s.interior_factor;
    switch (s.interior_type) {
    case 0: return f;
    case 1: return std::sqrt(min_distance2) * f;
    case 2: return a * f;
    case 3: return b * f;
    case 4: return a * a * f;
    case 5: return b * b * f;
    case 6: return a * a + b * b * f;  // POV's precedence: only b^2 is scaled
    default: return 0.0;
    }
}

// z -> z^n + c until |z|^2 > 4. Exponents 2, 3 and 4 use POV's expanded
// forms (their rounding differs from the general binomial sum).
double escape_time(const PatternSetup& s, double a, double b, double cr, double ci) {
    double a2 = a * a, b2 = b * b;
    double min_distance2 = a2 + b2;
    const int n = s.fractal_exponent;
    for (int i = 0; i < s.fractal_iterations; ++i) {
        if (n == 2) {
            b = 2.0 * a * b + ci;
            a = a2 - b2 + cr;
        } else if (n == 3) {
            b = 3.0 * a2 * b - b2 * b + ci;
            a = a2 * a - 3.0 * a * b2 + cr;
        } else if (n == 4) {
            b = 4.0 * (a2 * a * b - a * b2 * b) + ci;
            a = a2 * a2 - 6.0 * a2 * b2 + b2 * b2 + cr;
        } else {
            double real = std::pow(a, n);
            for (int k = 2; k <= n; k += 2) real += s.binomial[std::size_t(k)] * std::pow(a, n - k) * std::pow(b, k);
            double imaginary = 0.0;
            for (int k = 1; k <= n; k += 2)
                imaginary += s.binomial[std::size_t(k)] * std::pow(a, n - k) * std::pow(b, k);
            a = real + cr;
            b = imaginary + ci;
        }
        a2 = a * a;
        b2 = b * b;
        const double distance2 = a2 + b2;
        if (distance2 < min_distance2) min_distance2 = distance2;
        if (distance2 > 4.0) return exterior_value(s, i, a, b);
    }
    return interior_value(s, a, b, min_distance2);
}

// Magnet type 1: z -> ((z^2 + c - 1) / (2z + c - 2))^2; type 2 its cubic
// counterpart. Escapes when |z|^2 > 10000 or z nears 1.
double magnet(const PatternSetup& s, double a, double b, double cr, double ci, double min_distance2) {
    double a2 = a * a, b2 = b * b;
    const double c1r = cr - 1.0, c2r = cr - 2.0;
    const double c1c2r = c1r * c2r - ci * ci;
    const double c1c2i = (c1r + c2r) * ci;
    for (int i = 0; i < s.fractal_iterations; ++i) {
        double num_r, num_i, den_r, den_i;
        if (s.magnet_type == 1) {
            num_r = a2 - b2 + cr - 1;
            num_i = 2 * a * b + ci;
            den_r = 2 * a + cr - 2;
            den_i = 2 * b + ci;
        } else {
            num_r = a2 * a - 3 * a * b2 + 3 * (a * c1r - b * ci) + c1c2r;
            num_i = 3 * a2 * b - b2 * b + 3 * (a * ci + b * c1r) + c1c2i;
            den_r = 3 * (a2 - b2) + 3 * (a * c2r - b * ci) + c1c2r + 1;
            den_i = 6 * a * b + 3 * (a * ci + b * c2r) + c1c2i;
        }
        const double den = den_r * den_r + den_i * den_i;
        // A pole of the map: z would be infinite (POV divides by zero and
        // carries infinities or NaNs on). It escapes here, coloured by the
        // z that reached the pole.
        if (den == 0.0) return exterior_value(s, i, a, b);
        a = (num_r * den_r + num_i * den_i) / den;
        b = (num_i * den_r - num_r * den_i) / den;
        // Square the quotient.
        b2 = b * b;
        b = 2 * a * b;
        a = a * a - b2;
        a2 = a * a;
        b2 = b * b;
        const double distance2 = a2 + b2;
        if (distance2 < min_distance2) min_distance2 = distance2;
        const double to_one = a - 1;
        if (distance2 > 10000.0 || to_one * to_one + b2 < 1 / 10000.0) return exterior_value(s, i, a, b);
    }
    return interior_value(s, a, b, min_distance2);
}

}  // namespace

double fractal_pattern(const PatternSetup& s, const glm::dvec3& p) {
    switch (s.kind) {
    case sg::Pattern::Kind::Mandel: return escape_time(s, p.x, p.y, p.x, p.y);
    case sg::Pattern::Kind::Julia: return escape_time(s, p.x, p.y, s.julia_parameter.x, s.julia_parameter.y);
    case sg::Pattern::Kind::Magnet:
        if (s.magnet_julia) return magnet(s, p.x, p.y, s.julia_parameter.x, s.julia_parameter.y, p.x * p.x + p.y * p.y);
        // The mandel form starts at z = 0 with c the point.
        return magnet(s, 0.0, 0.0, p.x, p.y, 10000.0);
    default: return 0.0;
    }
}

}  // namespace lancer::pattern_detail
