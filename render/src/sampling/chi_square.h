// The chi-square distribution's quantile, for statistical stopping tests
// (POV-Ray's focal blur confidence test among them). Internal to liblancer.
#pragma once

namespace lancer {

// The x for which a chi-square variable with `degrees_of_freedom` (> 0)
// exceeds x with probability `upper_tail` (in (0, 1)): Cephes' chdtri.
// With upper_tail 0.9 it is the distribution's 10th percentile. Accurate to
// about 1e-9 relative up to 1000 degrees of freedom; beyond, Wilson and
// Hilferty's cube-root normal approximation (better than 1e-5 relative
// there). NaN for arguments outside those ranges.
double chi_square_upper_quantile(double degrees_of_freedom, double upper_tail);

}  // namespace lancer
