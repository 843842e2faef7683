// Golden images: every (scene, integrator) pair of tests/golden/matrix.txt
// rendered small and compared with tests/golden/<scene>/<integrator>.exr.
// docs/testing.md explains the tolerances, the failure images and how (and
// when) to regenerate goldens.
#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <map>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "golden_matrix.h"
#include "stat_compare.h"

namespace lancer::golden {
namespace {

// Deterministic integrators: a channel matches when within 1e-3 of the
// golden, relative above 1 (lamps are bright, and a relative error is what
// the eye sees there). The goldens are float EXR, so storage adds nothing.
// What differs between compilers and CPUs is float rounding (FMA
// contraction, libm, Embree's SIMD width): ~1e-6 relative on smooth
// surfaces, far under 1e-3, but a pixel centre lying within rounding of a
// silhouette, shadow edge or mirror edge can take the other side and change
// wholly. So up to 0.2% of the pixels (14 of 96x72), and at least 2, may
// differ by any amount; more than that is a change in the renderer.
constexpr double kChannelTolerance = 1e-3;
constexpr double kEdgePixelFraction = 0.002;
// Stochastic integrators: the golden is a high-spp mean with the variance
// of each pixel's mean; the test renders few spp with another seed and
// asks, per block of pixels and for the whole image, whether the two could
// differ by noise alone (tests/stat_compare.h, Šidák-corrected at 1%).
constexpr double kFamilyAlpha = 0.01;
constexpr int kDefaultTestSpp = 16;
constexpr int kDefaultGoldenSpp = 256;
constexpr int kDefaultBlock = 2;

int test_spp(const MatrixEntry& e) {
    return e.test_spp > 0 ? e.test_spp : kDefaultTestSpp;
}
int golden_spp(const MatrixEntry& e) {
    return e.golden_spp > 0 ? e.golden_spp : kDefaultGoldenSpp;
}
int block(const MatrixEntry& e) {
    return e.block > 0 ? e.block : kDefaultBlock;
}

// Every pixel's mean finite and no sample dropped as non-finite by the film.
void expect_finite(const std::string& id, const Film& film) {
    EXPECT_EQ(film.nonfinite_samples(), 0u) << id << ": the integrator returned NaN/Inf samples";
    long bad = 0;
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Color c = film.mean(x, y);
            if (!std::isfinite(c.r) || !std::isfinite(c.g) || !std::isfinite(c.b)) ++bad;
        }
    EXPECT_EQ(bad, 0) << id << ": non-finite pixels";
}

std::string test_name(const ::testing::TestParamInfo<MatrixEntry>& info) {
    std::string name = info.param.id();
    for (char& c : name)
        if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
    return name;
}

std::vector<MatrixEntry> matrix_or_empty() {
    try {
        return load_matrix();
    } catch (const std::exception& e) {
        // GoldenMatrix.Loads reports the error; instantiate nothing here.
        return {};
    }
}

class GoldenImage : public ::testing::TestWithParam<MatrixEntry> {};

TEST_P(GoldenImage, MatchesGolden) {
    const MatrixEntry& entry = GetParam();
    const std::string id = entry.id();

    // Regeneration: render at golden quality, check finiteness, write.
    if (regenerating()) {
        RenderResult probe = render_entry(entry, 4, 3, 1, kGoldenSeed);
        const bool deterministic = probe.deterministic;
        const int width = deterministic ? kDeterministicWidth : kStochasticWidth;
        const int height = deterministic ? kDeterministicHeight : kStochasticHeight;
        const int spp = deterministic ? 1 : golden_spp(entry);
        const RenderResult golden = render_entry(entry, width, height, spp, kGoldenSeed);
        expect_finite(id, golden.film);
        if (HasFailure()) return;
        std::ostringstream parameters;
        for (const auto& [key, value] : entry.parameters) parameters << key << "=" << value << " ";
        write_golden(entry.golden_path(), golden.film, !deterministic,
                     {{"scene", "scenes/" + entry.scene + ".pov"},
                      {"integrator", entry.integrator},
                      {"parameters", parameters.str()},
                      {"spp", std::to_string(spp)},
                      {"seed", std::to_string(kGoldenSeed)}});
        std::cout << "regenerated " << entry.golden_path() << "\n";
        return;
    }

    GoldenFile golden_file;  // not const: metadata[] below
    try {
        golden_file = read_golden(entry.golden_path());
    } catch (const std::exception& e) {
        FAIL() << id << ": " << e.what()
               << "\n(new matrix entry? render its golden with scripts/regenerate-goldens.sh, see docs/testing.md)";
    }
    const test::PixelStatistics& golden = golden_file.statistics;

    if (!golden_file.has_variance) {
        // Deterministic: one sample through each pixel centre is exact.
        const RenderResult result = render_entry(entry, golden.width, golden.height, 1, kTestSeed);
        ASSERT_TRUE(result.deterministic) << id << ": golden has no variance but the integrator is stochastic";
        expect_finite(id, result.film);
        const auto render = test::PixelStatistics::from_film(result.film);
        long over = 0;
        double worst = 0.0, sum = 0.0;
        int worst_x = 0, worst_y = 0;
        for (std::size_t i = 0; i < render.mean.size(); ++i) {
            double excess = 0.0;
            for (int c = 0; c < 3; ++c) {
                const double d = std::abs(render.mean[i][c] - golden.mean[i][c]);
                sum += d;
                excess = std::max(excess, d / std::max(1.0, std::abs(golden.mean[i][c])));
            }
            if (excess > kChannelTolerance) ++over;
            if (excess > worst) {
                worst = excess;
                worst_x = int(i % render.width);
                worst_y = int(i / render.width);
            }
        }
        const long allowed = std::max(2L, long(kEdgePixelFraction * double(render.mean.size())));
        if (over > allowed) {
            ADD_FAILURE() << id << ": " << over << " pixels differ by more than " << kChannelTolerance << " (allowed "
                          << allowed << "); worst " << worst << " at (" << worst_x << ", " << worst_y
                          << "), mean |diff| " << sum / (3.0 * double(render.mean.size()))
                          << "\nrender | golden | 4x|diff| written to "
                          << write_failure_image(id, render, golden, 4.0f);
        }
        return;
    }

    // Stochastic: few samples, another seed, z-test against the golden.
    const RenderResult result = render_entry(entry, golden.width, golden.height, test_spp(entry), kTestSeed);
    ASSERT_FALSE(result.deterministic) << id << ": golden has a variance but the integrator is deterministic";
    expect_finite(id, result.film);
    auto render = test::PixelStatistics::from_film(result.film);
    // The z-test trusts the render's variance estimates, but 16 samples of a
    // heavy-tailed estimator (glossy paths, small lamps found by BSDF
    // sampling) rarely contain the rare large sample, so their variance is
    // underestimated and a pixel can look 5 sigma off by luck. Under the
    // hypothesis being tested both renders run the same estimator, so the
    // golden's per-sample variance, measured with 16x the samples, is also
    // an estimate of the render's: use the larger of the two.
    const double golden_samples = std::stod(golden_file.metadata.count("spp") ? golden_file.metadata["spp"] : "0");
    if (golden_samples > 0.0) {
        const double ratio = golden_samples / double(test_spp(entry));
        for (std::size_t i = 0; i < render.variance_of_mean.size(); ++i)
            render.variance_of_mean[i] = glm::max(render.variance_of_mean[i], golden.variance_of_mean[i] * ratio);
    }
    const test::ImageComparison comparison =
        test::compare_images(render, golden, kFamilyAlpha, block(entry), entry.absolute_tolerance);
    if (!comparison.passed) {
        ADD_FAILURE() << id << " (" << test_spp(entry) << " spp vs golden's " << golden_file.metadata["spp"]
                      << "): " << comparison.summary << "\nrender | golden | 4x|diff| written to "
                      << write_failure_image(id, render, golden, 4.0f);
    }
}

// Before a stochastic golden is trusted (scripts/regenerate-goldens.sh runs
// this after regenerating; LANCER_VERIFY_GOLDENS=1): an independent render
// at 4x the golden's samples with another seed must agree with it under the
// same z-test, per pixel. For path this is the reference itself; for the
// others it shows the golden is converged. Also prints the relative
// difference from the scene's path golden, for the commit message.
class GoldenVerify : public ::testing::TestWithParam<MatrixEntry> {};

double relative_l1(const test::PixelStatistics& a, const test::PixelStatistics& b) {
    double difference = 0.0, total = 0.0;
    for (std::size_t i = 0; i < a.mean.size(); ++i)
        for (int c = 0; c < 3; ++c) {
            difference += std::abs(a.mean[i][c] - b.mean[i][c]);
            total += std::abs(b.mean[i][c]);
        }
    return total > 0.0 ? difference / total : difference;
}

TEST_P(GoldenVerify, AgreesWithIndependentHighSppRender) {
    const MatrixEntry& entry = GetParam();
    const GoldenFile golden = read_golden(entry.golden_path());
    const auto& g = golden.statistics;
    for (const MatrixEntry& other : load_matrix())
        if (other.scene == entry.scene && other.integrator == "path" && other.id() != entry.id()) {
            const GoldenFile path = read_golden(other.golden_path());
            const auto& p = path.statistics;
            // Deterministic goldens are larger: render this one at path's size.
            const auto same_size =
                g.width == p.width
                    ? g
                    : test::PixelStatistics::from_film(render_entry(entry, p.width, p.height, 1, kTestSeed).film);
            std::cout << "[ vs path  ] " << entry.id() << ": relative L1 difference from " << other.id() << ": "
                      << relative_l1(same_size, p) << "\n";
        }
    if (!golden.has_variance) return;  // deterministic: nothing to converge
    const int spp = 4 * std::stoi(golden.metadata.at("spp"));
    const RenderResult reference = render_entry(entry, g.width, g.height, spp, kReferenceSeed);
    expect_finite(entry.id(), reference.film);
    const auto r = test::PixelStatistics::from_film(reference.film);
    const test::ImageComparison comparison = test::compare_images(g, r, kFamilyAlpha, 1, entry.absolute_tolerance);
    std::cout << "[ verify   ] " << entry.id() << " vs " << spp << " spp: " << comparison.summary << "; relative L1 "
              << relative_l1(g, r) << "\n";
    EXPECT_TRUE(comparison.passed) << entry.id() << ": golden vs independent " << spp
                                   << " spp render: " << comparison.summary << "\nwritten to "
                                   << write_failure_image(entry.id() + "_verify", g, r, 4.0f);
}

// Where the models agree, the goldens' integrators agree with path: direct
// light only (path max_depth 1, every light sampled) against shadow without
// its ambient term (hard: point lights exactly; area_samples: area lights
// exactly). Verification mode only, like GoldenVerify; prints the numbers.
TEST(GoldenConsistency, ShadowMatchesPathDirectLight) {
    const char* verify = std::getenv("LANCER_VERIFY_GOLDENS");
    if (verify == nullptr || std::string(verify) != "1") GTEST_SKIP() << "set LANCER_VERIFY_GOLDENS=1";
    struct Case {
        const char* scene;
        std::map<std::string, std::string> shadow;
    };
    const Case cases[] = {{"hard_shadows", {{"ambient", "false"}}},
                          {"sphere_lights", {{"ambient", "false"}, {"area_samples", "4"}}},
                          {"cornell_box", {{"ambient", "false"}, {"area_samples", "4"}}}};
    for (const Case& c : cases) {
        MatrixEntry shadow{c.scene, "shadow", c.shadow};
        MatrixEntry path{c.scene, "path", {{"max_depth", "1"}, {"light_sampling", "all"}}};
        const auto a = test::PixelStatistics::from_film(
            render_entry(shadow, kStochasticWidth, kStochasticHeight, 64, kTestSeed).film);
        const auto b = test::PixelStatistics::from_film(
            render_entry(path, kStochasticWidth, kStochasticHeight, 256, kReferenceSeed).film);
        const double difference = relative_l1(a, b);
        std::cout << "[ direct   ] " << c.scene << ": shadow vs path max_depth=1: relative L1 " << difference << "\n";
        EXPECT_LT(difference, 0.05) << c.scene << "\nwritten to "
                                    << write_failure_image(std::string(c.scene) + "_direct", a, b, 4.0f);
    }
}

// Instantiated only when verifying, so ordinary runs do not list 54 skips.
std::vector<MatrixEntry> rows_to_verify() {
    const char* verify = std::getenv("LANCER_VERIFY_GOLDENS");
    return verify != nullptr && std::string(verify) == "1" ? matrix_or_empty() : std::vector<MatrixEntry>{};
}
INSTANTIATE_TEST_SUITE_P(Corpus, GoldenVerify, ::testing::ValuesIn(rows_to_verify()), test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GoldenVerify);

INSTANTIATE_TEST_SUITE_P(Corpus, GoldenImage, ::testing::ValuesIn(matrix_or_empty()), test_name);
GTEST_ALLOW_UNINSTANTIATED_PARAMETERIZED_TEST(GoldenImage);

}  // namespace
}  // namespace lancer::golden
