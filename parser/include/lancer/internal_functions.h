// POV-Ray's internal functions: the `function { internal(N) }` bodies that
// POV's functions.inc names (f_algbr_cyl1 = 0 … f_witch_of_agnesi_2d = 75,
// f_noise3d = 76, f_noise_generator = 78). Each follows POV-Ray 3.7's
// definition (source/backend/vm/fnintern.cpp), quirks included, so that an
// isosurface built on them is POV's shape. They run per isosurface step:
// no allocation, one small function per number found in a table.
#pragma once

namespace lancer::sg {

class FunctionNatives;

// The highest internal function number POV-Ray 3.7 has (f_noise_generator).
constexpr int kLastInternalFunction = 78;

// Whether lancer evaluates POV's internal function `number`: every one
// functions.inc declares; not 77 (POV's own body of `function { pattern
// { … } }`, which lancer keeps as Function::pattern) nor any other number.
constexpr bool internal_function_supported(int number) {
    return number >= 0 && number <= kLastInternalFunction && number != 77;
}

// The number of parameters after x, y, z that POV's internal function
// `number` takes (f_helix1: 7), or -1 for a number it lacks.
int internal_function_parameter_count(int number);

// The value of POV's internal function `number` at `arguments`: x, y, z, then
// its extra parameters; an argument not passed counts as 0. `natives` gives
// the noise (f_noise3d, f_noise_generator, f_ridge, f_ridged_mf, f_hetero_mf)
// and may be null for the others. Throws FunctionError for a number
// internal_function_supported refuses, or noise asked for without natives.
double internal_function(int number, const double* arguments, int count, const FunctionNatives* natives);

}  // namespace lancer::sg
