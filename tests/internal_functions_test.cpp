// lancer's POV-Ray internal functions (f_algbr_cyl1 … f_noise_generator)
// against POV-Ray 3.7's own values: tests/reference/pov/internal_functions.pov
// makes POV #write each function on 14 points with representative
// parameters (internal_functions.txt; the command is in the scene). POV
// writes 15 decimals, so the closed forms are held to 1e-6 of the value's
// size (at least 1e-6 absolute), far above the last digit and far below any
// wrong term; the noise-based ones (f_noise3d, f_noise_generator, f_ridge,
// f_ridged_mf, f_hetero_mf) rest on lancer's noise, which matches POV's to
// its printed digits (render/src/materials/noise_test.cpp; generator 3 to
// ~1e-14), and so are held to 1e-12. Measured: closed forms within 6e-16,
// noise within 2.1e-14 (the test records both).
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <set>
#include <sstream>
#include <string>
#include <vector>

#include "lancer/function.h"
#include "lancer/internal_functions.h"
#include "materials/noise.h"
#include "run_command.h"

namespace lancer {
namespace {

// POV's Noise() as a function sees it while parsing: generator 0 is the
// scene's, and POV's default noise_generator is 2.
class PovNoise final : public sg::FunctionNatives {
  public:
    double noise(const glm::dvec3& p, int generator) const override {
        return pov_noise(p, generator == 0 ? NoiseGenerator::RangeCorrected : NoiseGenerator(generator));
    }
    double pattern(const sg::Pattern&, const glm::dvec3&) const override { return 0.0; }
    std::array<double, 5> pigment(const sg::Pigment&, const glm::dvec3&) const override { return {}; }
};

struct Sample {
    int number = 0;
    std::vector<double> arguments;  // x, y, z, the parameters
    double value = 0.0;             // POV's
};

std::vector<Sample> read_table() {
    const std::string path = test::source_path("tests/reference/pov/internal_functions.txt");
    std::ifstream in(path);
    EXPECT_TRUE(in.good()) << "cannot read " << path;
    std::vector<Sample> samples;
    std::string line;
    while (std::getline(in, line)) {
        std::istringstream fields(line);
        Sample s;
        int parameters = 0;
        if (!(fields >> s.number >> parameters)) continue;
        s.arguments.resize(3 + parameters);
        for (double& a : s.arguments) fields >> a;
        fields >> s.value;
        EXPECT_FALSE(fields.fail()) << line;
        samples.push_back(s);
    }
    return samples;
}

bool noise_based(int number) {
    return number == 29 || number == 58 || number == 59 || number == 76 || number == 78;
}

TEST(InternalFunctions, MatchPovRayOnEveryFunctionFunctionsIncDeclares) {
    const std::vector<Sample> samples = read_table();
    ASSERT_GT(samples.size(), 1000u);
    const PovNoise natives;
    std::set<int> seen;
    double worst_closed = 0.0, worst_noise = 0.0;
    for (const Sample& s : samples) {
        seen.insert(s.number);
        ASSERT_EQ(int(s.arguments.size()) - 3, sg::internal_function_parameter_count(s.number)) << s.number;
        const double value = sg::internal_function(s.number, s.arguments.data(), int(s.arguments.size()), &natives);
        const double difference = std::fabs(value - s.value) / std::max(1.0, std::fabs(s.value));
        const double bound = noise_based(s.number) ? 1e-12 : 1e-6;
        (noise_based(s.number) ? worst_noise : worst_closed) =
            std::max(noise_based(s.number) ? worst_noise : worst_closed, difference);
        EXPECT_LE(difference, bound) << "internal(" << s.number << ") at " << s.arguments[0] << ", " << s.arguments[1]
                                     << ", " << s.arguments[2] << ": lancer " << value << ", POV " << s.value;
    }
    // Every function functions.inc declares (0 to 76 and 78) was compared.
    for (int n = 0; n <= sg::kLastInternalFunction; ++n)
        EXPECT_EQ(seen.count(n) == 1, sg::internal_function_supported(n)) << n;
    std::ostringstream worst;
    worst << "closed forms " << worst_closed << ", noise " << worst_noise;
    RecordProperty("worst_relative_difference", worst.str());
}

TEST(InternalFunctions, MissingParametersCountAsZeroAndUnknownNumbersAreRefused) {
    // f_sphere with no radius: the distance from the origin.
    const double at[3] = {3.0, 4.0, 0.0};
    EXPECT_DOUBLE_EQ(sg::internal_function(61, at, 3, nullptr), 5.0);
    EXPECT_FALSE(sg::internal_function_supported(77));  // POV's own pattern-function body
    EXPECT_FALSE(sg::internal_function_supported(79));
    EXPECT_FALSE(sg::internal_function_supported(-1));
    EXPECT_THROW(sg::internal_function(79, at, 3, nullptr), sg::FunctionError);
    // Noise without a renderer is an error, not a crash.
    EXPECT_THROW(sg::internal_function(76, at, 3, nullptr), sg::FunctionError);
    // A wild octave count is bounded, not a hang.
    const double wild[9] = {0.1, 0.2, 0.3, 0.5, 2.0, 1e300, 1.0, 2.0, 2.0};
    const PovNoise natives;
    EXPECT_NO_THROW(sg::internal_function(59, wild, 9, &natives));
    EXPECT_NO_THROW(sg::internal_function(29, wild, 9, &natives));
}

}  // namespace
}  // namespace lancer
