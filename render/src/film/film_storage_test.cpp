// Film::Storage::MeanOnly and Sums against Totals: what a one-sample render
// reads back is the same, bit for bit, a fixed-count render's the same up to
// float sums, and which storage a render asks for.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "lancer/host/film.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;

// One sample a pixel, some of them non-finite, into both storages.
void fill(Film& film) {
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            if (x == 2 && y == 1) continue;  // a pixel without samples
            const float value = 0.1f * float(x) + 0.37f * float(y) + 1e-3f;
            film.add_sample(x, y, (x + y) % 5 == 4 ? Color(value, NAN, 0.0f) : Color(value, 2.0f * value, 0.5f));
        }
}

TEST(FilmStorage, MeanOnlyReadsBackWhatTotalsReadsForOneSampleAPixel) {
    Film totals(6, 4), mean_only(6, 4, Film::Storage::MeanOnly);
    fill(totals);
    fill(mean_only);
    EXPECT_EQ(mean_only.storage(), Film::Storage::MeanOnly);
    EXPECT_EQ(mean_only.nonfinite_samples(), totals.nonfinite_samples());
    EXPECT_GT(totals.nonfinite_samples(), 0u);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x) {
            const std::size_t index = std::size_t(y) * 6 + std::size_t(x);
            EXPECT_EQ(mean_only.mean(x, y), totals.mean(x, y)) << x << "," << y;
            EXPECT_EQ(mean_only.sample_count(x, y), totals.sample_count(x, y));
            EXPECT_EQ(mean_only.samples_taken(x, y), totals.samples_taken(x, y));
            EXPECT_EQ(mean_only.variance_of_mean(x, y), Color(0.0f));
            const Film::Accumulator a = mean_only.accumulator(index), b = totals.accumulator(index);
            EXPECT_EQ(a.sum, b.sum);
            EXPECT_EQ(a.sum_squares, b.sum_squares);
            EXPECT_EQ(a.count, b.count);
            EXPECT_EQ(a.nonfinite, b.nonfinite);
        }
}

TEST(FilmStorage, RestoringMeanOnlyTotalsGivesTheSameFilm) {
    Film mean_only(6, 4, Film::Storage::MeanOnly);
    fill(mean_only);
    Film restored(6, 4, Film::Storage::MeanOnly);
    restored.restore(mean_only.accumulators());
    EXPECT_EQ(restored.storage(), Film::Storage::Totals);
    Film region(6, 4, Film::Storage::MeanOnly);
    const std::vector<Film::Accumulator> all = mean_only.accumulators();
    region.restore_region(0, 0, 6, 4, all.data());
    EXPECT_EQ(region.storage(), Film::Storage::MeanOnly);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x) {
            EXPECT_EQ(restored.mean(x, y), mean_only.mean(x, y));
            EXPECT_EQ(region.mean(x, y), mean_only.mean(x, y));
            EXPECT_EQ(region.sample_count(x, y), mean_only.sample_count(x, y));
        }
    EXPECT_EQ(restored.nonfinite_samples(), mean_only.nonfinite_samples());
    EXPECT_EQ(region.nonfinite_samples(), mean_only.nonfinite_samples());
}

// Several samples a pixel, some non-finite, into Totals and Sums.
void fill_several(Film& film) {
    for (int round = 0; round < 5; ++round)
        for (int y = 0; y < film.height(); ++y)
            for (int x = 0; x < film.width(); ++x) {
                if (x == 2 && y == 1) continue;  // a pixel without samples
                const float value = 0.1f * float(x) + 0.37f * float(y) + 0.013f * float(round * round) + 1e-3f;
                const bool bad = (x + y + round) % 7 == 3;
                film.add_sample(x, y, bad ? Color(value, INFINITY, 0.0f) : Color(value, 2.0f * value, 0.5f));
            }
}

void expect_close(const Color& a, const Color& b) {
    for (int c = 0; c < 3; ++c) EXPECT_NEAR(a[c], b[c], 1e-6f * std::fabs(b[c]));
}

TEST(FilmStorage, SumsReadBackTotalsMeansWithoutTheVariance) {
    Film totals(6, 4), sums(6, 4, Film::Storage::Sums);
    fill_several(totals);
    fill_several(sums);
    EXPECT_EQ(sums.storage(), Film::Storage::Sums);
    EXPECT_GT(totals.nonfinite_samples(), 0u);
    EXPECT_EQ(sums.nonfinite_samples(), totals.nonfinite_samples());
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x) {
            SCOPED_TRACE(::testing::Message() << x << "," << y);
            // A non-finite sample is dropped alone, as in Totals.
            EXPECT_EQ(sums.sample_count(x, y), totals.sample_count(x, y));
            EXPECT_EQ(sums.samples_taken(x, y), totals.samples_taken(x, y));
            expect_close(sums.mean(x, y), totals.mean(x, y));
            EXPECT_EQ(sums.variance_of_mean(x, y), Color(0.0f));
            const std::size_t index = std::size_t(y) * 6 + std::size_t(x);
            const Film::Accumulator a = sums.accumulator(index), b = totals.accumulator(index);
            EXPECT_EQ(a.count, b.count);
            EXPECT_EQ(a.nonfinite, b.nonfinite);
        }
    EXPECT_EQ(sums.sample_count(2, 1), 0u);
    EXPECT_EQ(sums.mean(2, 1), Color(0.0f));
}

TEST(FilmStorage, SumsRestoreAndChangeStorageKeepTheImage) {
    Film sums(6, 4, Film::Storage::Sums);
    fill_several(sums);
    const std::vector<Film::Accumulator> all = sums.accumulators();
    // Checkpoints and tiles of a distributed render: the same film, bit for bit.
    Film restored(6, 4, Film::Storage::Sums), region(6, 4, Film::Storage::Sums);
    restored.restore(all);
    region.restore_region(0, 0, 6, 4, all.data());
    EXPECT_EQ(restored.storage(), Film::Storage::Sums);
    EXPECT_EQ(region.storage(), Film::Storage::Sums);
    EXPECT_EQ(restored.nonfinite_samples(), sums.nonfinite_samples());
    EXPECT_EQ(region.nonfinite_samples(), sums.nonfinite_samples());
    Film totals = sums;
    totals.change_storage(Film::Storage::Totals);
    EXPECT_EQ(totals.storage(), Film::Storage::Totals);
    EXPECT_EQ(totals.nonfinite_samples(), sums.nonfinite_samples());
    Film back = totals;
    back.change_storage(Film::Storage::Sums);
    for (int y = 0; y < 4; ++y)
        for (int x = 0; x < 6; ++x) {
            SCOPED_TRACE(::testing::Message() << x << "," << y);
            EXPECT_EQ(restored.mean(x, y), sums.mean(x, y));
            EXPECT_EQ(region.mean(x, y), sums.mean(x, y));
            EXPECT_EQ(back.mean(x, y), sums.mean(x, y));
            EXPECT_EQ(restored.samples_taken(x, y), sums.samples_taken(x, y));
            EXPECT_EQ(back.sample_count(x, y), sums.sample_count(x, y));
            expect_close(totals.mean(x, y), sums.mean(x, y));
            // Sums kept no variance to pass on (none but the rounding of
            // sum^2 / n over n).
            const Color variance = totals.variance_of_mean(x, y), mean = totals.mean(x, y);
            for (int c = 0; c < 3; ++c) EXPECT_LE(variance[c], 1e-12f * (mean[c] * mean[c] + 1.0f));
        }
}

TEST(FilmStorage, SumsTakeTwentyBytesAPixel) {
    // What the memory target counts (bench/README.md): the film's
    // own vectors, measured through their capacity.
    EXPECT_EQ(sizeof(Color) + 2 * sizeof(std::uint32_t), 20u);
}

class ConstantIntegrator final : public Integrator {
  public:
    explicit ConstantIntegrator(bool deterministic) : m_deterministic(deterministic) {}
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene&, Sampler&) const override {
        return Color(hit ? hit->t : 0.0f, ray.direction.x, ray.direction.y);
    }
    bool is_deterministic() const override { return m_deterministic; }

  private:
    bool m_deterministic;
};

RenderOptions options_of(int spp) {
    RenderOptions options;
    options.width = 12;
    options.height = 9;
    options.samples_per_pixel = spp;
    options.progress = ProgressMode::Quiet;
    return options;
}

TEST(FilmStorage, ARenderAsksForTheLeastStorageItReads) {
    sg::SceneGraph graph;
    graph.objects.push_back(sphere_object({0, 0, 5}, 1.0));
    const auto scene = compile_scene(graph);
    const ConstantIntegrator deterministic(true), monte_carlo(false);
    EXPECT_EQ(film_storage_for(*scene, deterministic, options_of(1)), Film::Storage::MeanOnly);
    EXPECT_EQ(film_storage_for(*scene, monte_carlo, options_of(1)), Film::Storage::MeanOnly);
    // More samples, a fixed count: no variance unless the estimate is wanted.
    EXPECT_EQ(film_storage_for(*scene, deterministic, options_of(4)), Film::Storage::Sums);
    EXPECT_EQ(film_storage_for(*scene, monte_carlo, options_of(4)), Film::Storage::Sums);
    EXPECT_EQ(film_storage_for(*scene, monte_carlo, options_of(4), true), Film::Storage::Totals);
    EXPECT_EQ(film_storage_for(*scene, monte_carlo, options_of(1), true), Film::Storage::MeanOnly);
    RenderOptions budget = options_of(1);
    budget.time_budget_seconds = 1.0;
    EXPECT_EQ(film_storage_for(*scene, monte_carlo, budget), Film::Storage::Totals);
    EXPECT_EQ(film_storage_for(*scene, deterministic, budget), Film::Storage::MeanOnly);  // ignores budgets
    budget.samples_per_pixel = 4;
    EXPECT_EQ(film_storage_for(*scene, deterministic, budget), Film::Storage::Sums);
    RenderOptions noise = options_of(1);
    noise.noise_target = 0.1;
    EXPECT_EQ(film_storage_for(*scene, monte_carlo, noise), Film::Storage::Totals);

    graph.camera = sg::Camera{};
    graph.camera->aperture = 0.4;
    graph.camera->focal_distance = 4.0;
    graph.camera->blur_samples = 7;
    const auto blurred = compile_scene(graph);
    // A deterministic focal blur stops each pixel by its confidence.
    EXPECT_EQ(film_storage_for(*blurred, deterministic, options_of(1)), Film::Storage::Totals);
    EXPECT_EQ(film_storage_for(*blurred, monte_carlo, options_of(1)), Film::Storage::Sums);
}

TEST(FilmStorage, TheSameImageInEitherStorageAndMoreSamplesConvertIt) {
    sg::SceneGraph graph;
    graph.objects.push_back(sphere_object({0, 0, 5}, 1.0));
    graph.objects.push_back(plane_object({0, 1, 0}, -1.0));
    const auto scene = compile_scene(graph);
    const ConstantIntegrator integrator(true);
    Film totals(12, 9), mean_only(12, 9, Film::Storage::MeanOnly);
    render_image(*scene, integrator, options_of(1), totals);
    render_image(*scene, integrator, options_of(1), mean_only);
    EXPECT_EQ(mean_only.storage(), Film::Storage::MeanOnly);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x) ASSERT_EQ(mean_only.mean(x, y), totals.mean(x, y)) << x << "," << y;
    // Four samples a pixel need sums: the film becomes Sums first; a noise
    // target needs variances: then Totals, whose variances are those of
    // the samples taken since.
    render_image(*scene, integrator, options_of(4), mean_only);
    render_image(*scene, integrator, options_of(4), totals);
    EXPECT_EQ(mean_only.storage(), Film::Storage::Sums);
    EXPECT_EQ(totals.storage(), Film::Storage::Totals);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x) {
            ASSERT_EQ(mean_only.samples_taken(x, y), 4u);
            const Color a = mean_only.mean(x, y), b = totals.mean(x, y);
            for (int c = 0; c < 3; ++c) ASSERT_NEAR(a[c], b[c], 1e-6f * std::fabs(b[c])) << x << "," << y;
        }
    const ConstantIntegrator monte_carlo(false);
    RenderOptions noise = options_of(4);
    noise.noise_target = 0.1;
    noise.max_samples_per_pixel = 8;
    render_image(*scene, monte_carlo, noise, mean_only);
    EXPECT_EQ(mean_only.storage(), Film::Storage::Totals);
}

}  // namespace
}  // namespace lancer
