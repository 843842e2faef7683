// chi_square_upper_quantile by bisection on the regularized incomplete
// gamma function, P(X > x) = Q(k/2, x/2), which is evaluated by its power
// series below a + 1 and by its continued fraction above (where each
// converges fast).
#include "sampling/chi_square.h"

#include <cmath>
#include <limits>

namespace lancer {
namespace {

constexpr double kRelativeEpsilon = 1e-15;
constexpr int kMostTerms = 100000;

// e^-x x^a / Gamma(a), the factor both expansions share, in logs so that it
// does not overflow for large a.
double gamma_prefactor(double a, double x) {
    return std::exp(-x + a * std::log(x) - std::lgamma(a));
}

// Q(a, x) = Gamma(a, x) / Gamma(a), the regularized upper incomplete gamma.
double regularized_upper_gamma(double a, double x) {
    if (x <= 0.0) return 1.0;
    if (x < a + 1.0) {
        // P(a, x) = prefactor * sum_n x^n / (a (a+1) ... (a+n)).
        double term = 1.0 / a, sum = term;
        for (int n = 1; n < kMostTerms; ++n) {
            term *= x / (a + n);
            sum += term;
            if (std::fabs(term) < std::fabs(sum) * kRelativeEpsilon) break;
        }
        return 1.0 - gamma_prefactor(a, x) * sum;
    }
    // Q(a, x) = prefactor * 1/(x+1-a- 1(1-a)/(x+3-a- 2(2-a)/(x+5-a- ...))),
    // by the modified Lentz method.
    constexpr double kTiny = 1e-300;
    double b = x + 1.0 - a, c = 1.0 / kTiny, d = 1.0 / b, fraction = d;
    for (int i = 1; i < kMostTerms; ++i) {
        const double an = -i * (i - a);
        b += 2.0;
        d = an * d + b;
        if (std::fabs(d) < kTiny) d = kTiny;
        c = b + an / c;
        if (std::fabs(c) < kTiny) c = kTiny;
        d = 1.0 / d;
        const double step = d * c;
        fraction *= step;
        if (std::fabs(step - 1.0) < kRelativeEpsilon) break;
    }
    return gamma_prefactor(a, x) * fraction;
}

// The standard normal quantile: z with P(Z < z) = p, by bisection on erfc.
double normal_quantile(double p) {
    double low = -40.0, high = 40.0;
    for (int i = 0; i < 200; ++i) {
        const double middle = 0.5 * (low + high);
        if (0.5 * std::erfc(-middle / std::sqrt(2.0)) < p)
            low = middle;
        else
            high = middle;
    }
    return 0.5 * (low + high);
}

}  // namespace

double chi_square_upper_quantile(double degrees_of_freedom, double upper_tail) {
    const double k = degrees_of_freedom;
    if (!(k > 0.0) || !std::isfinite(k) || !(upper_tail > 0.0 && upper_tail < 1.0))
        return std::numeric_limits<double>::quiet_NaN();
    if (k > 1000.0) {
        const double z = normal_quantile(1.0 - upper_tail), s = 2.0 / (9.0 * k);
        const double cube_root = 1.0 - s + z * std::sqrt(s);
        return k * cube_root * cube_root * cube_root;
    }
    const double a = 0.5 * k;
    // Q falls from 1 to 0 as x grows: widen until it is below the tail.
    double low = 0.0, high = k + 10.0 * std::sqrt(k) + 50.0;
    while (regularized_upper_gamma(a, 0.5 * high) > upper_tail) high *= 2.0;
    for (int i = 0; i < 200 && high - low > 1e-12 * high; ++i) {
        const double middle = 0.5 * (low + high);
        if (regularized_upper_gamma(a, 0.5 * middle) > upper_tail)
            low = middle;
        else
            high = middle;
    }
    return 0.5 * (low + high);
}

}  // namespace lancer
