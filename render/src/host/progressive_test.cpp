// Progressive rendering: the film depends only on per-pixel sample counts
// (any pass schedule, thread count or continuation gives the same sums),
// time budgets stop in time, noise targets stop pixels where they are
// converged, cancellation returns quickly, rays are counted, checkpoints
// round-trip bit for bit and refuse another render's state.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <thread>

#include "lancer/host/checkpoint.h"
#include "lancer/host/counting_scene.h"
#include "lancer/host/estimate.h"
#include "lancer/host/film.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;
namespace fs = std::filesystem;

// Noise whose amplitude depends on the pixel: constant on the left half of
// the image, very noisy on the right. One ray query per sample: the
// host's camera ray.
class HalfNoisyIntegrator final : public Integrator {
  public:
    Color shade_camera_hit(const Ray& ray, const Hit*, const RenderScene&, Sampler& sampler) const override {
        const float u = sampler.next_1d();
        if (ray.direction.x < 0.0f) return Color(0.5f);
        return Color(0.5f + 0.45f * (2.0f * u - 1.0f));
    }
};

// Slow on purpose, so that time budgets are measurable.
class SlowIntegrator final : public Integrator {
  public:
    Color shade_camera_hit(const Ray&, const Hit*, const RenderScene&, Sampler& sampler) const override {
        std::this_thread::sleep_for(std::chrono::microseconds(200));
        return Color(sampler.next_1d());
    }
};

std::unique_ptr<RenderScene> small_scene() {
    sg::SceneGraph graph;
    graph.objects.push_back(sphere_object({0, 0, 5}, 1.0));
    graph.objects.push_back(plane_object({0, 1, 0}, -1.0));
    return compile_scene(graph);
}

RenderOptions quiet_options(int width, int height) {
    RenderOptions options;
    options.width = width;
    options.height = height;
    options.progress = ProgressMode::Quiet;
    options.seed = 5;
    return options;
}

void expect_identical(const Film& a, const Film& b) {
    ASSERT_EQ(a.accumulators().size(), b.accumulators().size());
    for (std::size_t i = 0; i < a.accumulators().size(); ++i) {
        const Film::Accumulator &p = a.accumulators()[i], &q = b.accumulators()[i];
        ASSERT_EQ(p.count, q.count) << "pixel " << i;
        ASSERT_EQ(p.nonfinite, q.nonfinite) << "pixel " << i;
        for (int c = 0; c < 3; ++c) {
            ASSERT_EQ(p.sum[c], q.sum[c]) << "pixel " << i;  // bit for bit, not approximately
            ASSERT_EQ(p.sum_squares[c], q.sum_squares[c]) << "pixel " << i;
        }
    }
}

TEST(Progressive, AnyPassScheduleGivesTheSameFilm) {
    auto scene = small_scene();
    HalfNoisyIntegrator integrator;
    RenderOptions options = quiet_options(29, 17);
    options.samples_per_pixel = 12;
    options.threads = 1;
    Film single(29, 17);
    render_image(*scene, integrator, options, single);

    // In instalments (3, then 7, then up to 12) on two threads, other tiles.
    Film continued(29, 17);
    options.threads = 2;
    options.tile_size = 5;
    for (int spp : {3, 7, 12}) {
        options.samples_per_pixel = spp;
        render_image(*scene, integrator, options, continued);
    }
    expect_identical(single, continued);

    // Time-limited passes (checkpointing) do not change it either.
    Film checkpointed(29, 17);
    int checkpoints = 0;
    options.checkpoint_interval_seconds = 1e-6;
    options.on_checkpoint = [&](const Film&) { ++checkpoints; };
    const RenderStats stats = render_image(*scene, integrator, options, checkpointed);
    expect_identical(single, checkpointed);
    EXPECT_GT(stats.passes, 1);
    EXPECT_GE(checkpoints, 1);
}

TEST(Progressive, TimeBudgetStopsWithinIt) {
    auto scene = small_scene();
    SlowIntegrator integrator;
    RenderOptions options = quiet_options(16, 16);
    options.threads = 2;
    options.time_budget_seconds = 0.4;
    Film film(16, 16);
    const auto start = std::chrono::steady_clock::now();
    const RenderStats stats = render_image(*scene, integrator, options, film);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_GT(seconds, 0.2);
    EXPECT_LT(seconds, 1.2);
    EXPECT_GE(stats.min_samples_per_pixel, 1u);
    EXPECT_GT(stats.passes, 1);
    // A cap stops it earlier.
    Film capped(16, 16);
    options.max_samples_per_pixel = 2;
    const RenderStats capped_stats = render_image(*scene, integrator, options, capped);
    EXPECT_EQ(capped_stats.max_samples_per_pixel, 2u);
}

TEST(Progressive, NoiseTargetSpendsSamplesWhereThePictureIsNoisy) {
    auto scene = small_scene();
    HalfNoisyIntegrator integrator;
    RenderOptions options = quiet_options(24, 12);
    options.noise_target = 0.05;
    options.max_samples_per_pixel = 2048;
    Film film(24, 12);
    const RenderStats stats = render_image(*scene, integrator, options, film);
    // Constant pixels stop at the minimum, noisy ones go on.
    EXPECT_EQ(film.samples_taken(0, 6), 16u);
    EXPECT_GT(film.samples_taken(23, 6), 100u);
    EXPECT_EQ(stats.min_samples_per_pixel, 16u);
    EXPECT_LT(stats.estimated_rel_rmse, 0.05);
    EXPECT_GT(stats.estimated_rel_rmse, 0.01);
    // Deterministic: the same again, and on one thread.
    Film again(24, 12);
    options.threads = 1;
    render_image(*scene, integrator, options, again);
    expect_identical(film, again);
}

TEST(Progressive, CancelStopsQuicklyAndSaysSo) {
    auto scene = small_scene();
    SlowIntegrator integrator;
    RenderOptions options = quiet_options(32, 32);
    options.samples_per_pixel = 1000;  // minutes, uninterrupted
    std::atomic<bool> cancel{false};
    options.cancel = &cancel;
    std::thread canceller([&] {
        std::this_thread::sleep_for(std::chrono::milliseconds(150));
        cancel = true;
    });
    Film film(32, 32);
    const RenderStats stats = render_image(*scene, integrator, options, film);
    canceller.join();
    EXPECT_TRUE(stats.interrupted);
    EXPECT_LT(stats.seconds, 1.0);
    EXPECT_GT(stats.samples, 0u);
    EXPECT_LT(stats.max_samples_per_pixel, 1000u);
}

TEST(Progressive, CountingSceneCountsEveryQuery) {
    auto inner = small_scene();
    CountingScene scene(*inner);
    HalfNoisyIntegrator integrator;  // one intersect per sample
    RenderOptions options = quiet_options(20, 10);
    options.samples_per_pixel = 4;
    options.threads = 2;
    Film film(20, 10);
    options.ray_counter = &scene;
    const RenderStats stats = render_image(scene, integrator, options, film);
    EXPECT_EQ(stats.rays, 20u * 10u * 4u);
    EXPECT_EQ(scene.rays(), 20u * 10u * 4u);
    EXPECT_GT(stats.rays_per_second, 0.0);
    // Without the wrapper nothing is counted.
    Film plain(20, 10);
    options.ray_counter = nullptr;
    EXPECT_EQ(render_image(*inner, integrator, options, plain).rays, 0u);
}

TEST(Progressive, EstimateMatchesTheTrueErrorOfAKnownNoise) {
    // Uniform noise of known variance around 0.5: the estimate and the
    // error against the exact answer agree closely over many pixels.
    auto scene = small_scene();
    HalfNoisyIntegrator integrator;
    RenderOptions options = quiet_options(64, 32);
    options.samples_per_pixel = 16;
    Film film(64, 32), exact(64, 32);
    render_image(*scene, integrator, options, film);
    for (int y = 0; y < 32; ++y)
        for (int x = 0; x < 64; ++x) exact.add_sample(x, y, Color(0.5f));
    const double estimate = estimated_relative_rmse(film), truth = relative_rmse(film, exact);
    EXPECT_GT(truth, 0.0);
    EXPECT_NEAR(estimate / truth, 1.0, 0.1) << estimate << " vs " << truth;
}

class CheckpointFiles : public ::testing::Test {
  protected:
    void SetUp() override {
        m_path = (fs::temp_directory_path() / ("lancer_checkpoint_test_" + std::to_string(::getpid()))).string();
    }
    void TearDown() override { fs::remove(m_path); }
    std::string m_path;
};

TEST_F(CheckpointFiles, RoundTripBitForBitAndContinue) {
    auto scene = small_scene();
    HalfNoisyIntegrator integrator;
    RenderOptions options = quiet_options(13, 11);
    options.samples_per_pixel = 5;
    Film partial(13, 11);
    render_image(*scene, integrator, options, partial);
    const CheckpointIdentity identity = {{"seed", "5"}, {"integrator", "half"}};
    write_checkpoint(m_path, identity, partial);

    Film restored(13, 11);
    read_checkpoint(m_path, identity, restored);
    expect_identical(partial, restored);
    options.samples_per_pixel = 9;
    render_image(*scene, integrator, options, restored);
    Film straight(13, 11);
    render_image(*scene, integrator, options, straight);
    expect_identical(straight, restored);
}

TEST_F(CheckpointFiles, RefusesAnotherRenderOrADamagedFile) {
    Film film(4, 3);
    film.add_sample(1, 1, Color(0.25f));
    write_checkpoint(m_path, {{"seed", "5"}, {"width", "4"}}, film);
    Film target(4, 3);
    try {
        read_checkpoint(m_path, {{"seed", "6"}, {"width", "4"}}, target);
        FAIL() << "accepted another seed";
    } catch (const CheckpointError& error) {
        EXPECT_NE(std::string(error.what()).find("seed: checkpoint has '5', this render '6'"), std::string::npos)
            << error.what();
    }
    Film other_size(5, 3);
    EXPECT_THROW(read_checkpoint(m_path, {{"seed", "5"}}, other_size), CheckpointError);
    fs::resize_file(m_path, fs::file_size(m_path) - 20);
    EXPECT_THROW(read_checkpoint(m_path, {{"seed", "5"}}, target), CheckpointError);
    std::ofstream(m_path) << "not a checkpoint";
    EXPECT_THROW(read_checkpoint(m_path, {}, target), CheckpointError);
    fs::remove(m_path);
    EXPECT_THROW(read_checkpoint(m_path, {}, target), CheckpointError);
}

}  // namespace
}  // namespace lancer
