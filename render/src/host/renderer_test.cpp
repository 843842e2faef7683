// The pixel loop, film and image output: determinism across thread counts,
// crop windows, non-finite samples, PNG/EXR round trips, atomic writes.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>

#include <OpenImageIO/imageio.h>

#include "image_compare.h"
#include "lancer/host/camera_ray.h"
#include "lancer/host/film.h"
#include "lancer/host/image_io.h"
#include "lancer/host/renderer.h"
#include "lancer/host/scene_compiler.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;
namespace fs = std::filesystem;

// Returns random numbers drawn from the sampler plus the hit distance: any
// dependence on thread or tile order would show.
class NoisyIntegrator final : public Integrator {
  public:
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene&, Sampler& sampler) const override {
        const float depth = hit ? hit->t : 0.0f;
        return Color(sampler.next_1d(), sampler.next_1d() * depth, ray.direction.x);
    }
};

class NanIntegrator final : public Integrator {
  public:
    Color shade_camera_hit(const Ray&, const Hit*, const RenderScene&, Sampler& sampler) const override {
        return sampler.next_1d() < 0.5f ? Color(NAN) : Color(1.0f);
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
    return options;
}

class WhiteIntegrator final : public Integrator {
  public:
    Color shade_camera_hit(const Ray&, const Hit*, const RenderScene&, Sampler&) const override { return Color(1.0f); }
    bool is_deterministic() const override { return true; }
};

// Outside a fisheye's circle POV-Ray traces no ray and writes black, not
// the background: the host adds a black sample without asking the plugin.
TEST(Renderer, PixelsACameraCannotSeeAreBlack) {
    sg::SceneGraph graph;
    graph.camera = sg::Camera{};
    graph.camera->projection = sg::Camera::Projection::Fisheye;
    graph.camera->right = {1.0, 0.0, 0.0};
    graph.camera->angle = 180.0;
    auto scene = compile_scene(graph);
    Film film(20, 20);
    render_image(*scene, WhiteIntegrator(), quiet_options(20, 20), film);
    EXPECT_EQ(film.mean(0, 0), Color(0.0f));
    EXPECT_EQ(film.mean(19, 19), Color(0.0f));
    EXPECT_EQ(film.samples_taken(0, 0), 1u);
    EXPECT_EQ(film.mean(10, 10), Color(1.0f));
    EXPECT_EQ(film.mean(0, 10), Color(1.0f));  // on the circle's rim
}

// White where the camera ray meets something, black elsewhere.
class CoverageIntegrator final : public Integrator {
  public:
    Color shade_camera_hit(const Ray&, const Hit* hit, const RenderScene&, Sampler&) const override {
        return Color(hit ? 1.0f : 0.0f);
    }
    bool is_deterministic() const override { return true; }
};

std::unique_ptr<RenderScene> blurred_sphere(int least, int most, double variance) {
    sg::SceneGraph graph;
    graph.objects.push_back(sphere_object({0, 0, 5}, 1.0));
    graph.camera = sg::Camera{};
    graph.camera->aperture = 0.4;
    graph.camera->focal_distance = 4.0;  // the sphere's near side: sharp
    graph.camera->blur_samples = most;
    graph.camera->blur_samples_min = least;
    graph.camera->variance = variance;
    return compile_scene(graph);
}

// A camera with focal blur takes its blur_samples per pixel when the count
// is fixed, as POV-Ray traces them; a larger count asked for is kept.
TEST(Renderer, FocalBlurTakesItsBlurSamplesPerPixel) {
    auto scene = blurred_sphere(0, 7, 1.0 / 10000.0);
    Film film(6, 4);
    render_image(*scene, WhiteIntegrator(), quiet_options(6, 4), film);
    EXPECT_EQ(film.samples_taken(3, 2), 7u);
    RenderOptions options = quiet_options(6, 4);
    options.samples_per_pixel = 9;
    Film more(6, 4);
    render_image(*scene, WhiteIntegrator(), options, more);
    EXPECT_EQ(more.samples_taken(3, 2), 9u);
}

// POV-Ray's confidence test: a pixel whose first batch (the 7 points of the
// inner hexagon of its 37-point grid) all agree stops there; one on the
// blurred rim of the sphere, whose lens points disagree, takes all 37.
TEST(Renderer, FocalBlurStopsWhereTheConfidenceTestPasses) {
    const auto scene = blurred_sphere(0, 37, 1.0 / 10000.0);
    Film film(24, 18);
    const RenderStats stats = render_image(*scene, CoverageIntegrator(), quiet_options(24, 18), film);
    EXPECT_EQ(film.samples_taken(0, 0), 7u);   // background only
    EXPECT_EQ(film.samples_taken(12, 9), 7u);  // the sphere's middle
    EXPECT_EQ(stats.max_samples_per_pixel, 37u);
    EXPECT_LT(stats.mean_samples_per_pixel, 30.0);
    // Every batch ends on one of POV's ring ends (7, 13, 19, 23, ..., 37).
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 24; ++x) {
            const std::uint32_t n = film.samples_taken(x, y);
            EXPECT_TRUE(n == 7 || n == 13 || n == 19 || n == 23 || n == 27 || n == 31 || n == 35 || n == 37)
                << n << " at " << x << "," << y;
        }

    // The picture is the one every sample gives, to within its noise.
    const auto exact_scene = blurred_sphere(0, 37, 0.0);  // variance 0: never stops early
    Film exact(24, 18);
    const RenderStats all = render_image(*exact_scene, CoverageIntegrator(), quiet_options(24, 18), exact);
    EXPECT_EQ(all.min_samples_per_pixel, 37u);
    double difference = 0.0;
    for (int y = 0; y < 18; ++y)
        for (int x = 0; x < 24; ++x) difference += std::fabs(film.mean(x, y).r - exact.mean(x, y).r);
    EXPECT_LT(difference / (24 * 18), 0.01);
}

// blur_samples MIN, MAX: no pixel stops before MIN (at the end of the batch
// that reaches it); a Monte Carlo integrator takes every sample.
TEST(Renderer, FocalBlurConfidenceHonoursMinimumAndMonteCarlo) {
    const auto scene = blurred_sphere(10, 37, 1.0 / 10000.0);
    Film film(24, 18);
    render_image(*scene, CoverageIntegrator(), quiet_options(24, 18), film);
    EXPECT_EQ(film.samples_taken(0, 0), 13u);

    Film monte_carlo(24, 18);
    EXPECT_EQ(render_image(*scene, NoisyIntegrator(), quiet_options(24, 18), monte_carlo).min_samples_per_pixel, 37u);
}

TEST(Renderer, BitIdenticalForOneAndTwoThreads) {
    auto scene = small_scene();
    NoisyIntegrator integrator;
    RenderOptions options;
    options.width = 37;
    options.height = 23;
    options.samples_per_pixel = 3;
    options.seed = 99;
    options.tile_size = 5;
    options.progress = ProgressMode::Quiet;
    Film one(37, 23), two(37, 23);
    options.threads = 1;
    render_image(*scene, integrator, options, one);
    options.threads = 2;
    options.tile_size = 7;  // tile order and size must not matter either
    const RenderStats stats = render_image(*scene, integrator, options, two);
    EXPECT_EQ(stats.samples, 37u * 23u * 3u);
    for (int y = 0; y < 23; ++y)
        for (int x = 0; x < 37; ++x) {
            ASSERT_EQ(one.mean(x, y), two.mean(x, y)) << x << "," << y;
            ASSERT_EQ(one.sample_count(x, y), 3u);
        }
    // Another seed changes the image.
    Film other(37, 23);
    options.seed = 100;
    render_image(*scene, integrator, options, other);
    EXPECT_NE(one.mean(3, 3), other.mean(3, 3));
}

TEST(Renderer, BatchedCameraHitsGiveTheSameImage) {
    auto scene = small_scene();
    RenderOptions options;
    options.width = 37;
    options.height = 23;
    options.samples_per_pixel = 3;
    options.seed = 5;
    options.tile_size = 7;  // blocks of 4x4 pixels cut by tile edges
    options.threads = 2;
    options.progress = ProgressMode::Quiet;
    // The host traces batches of camera rays in packets and positions each
    // sample's stream; the same samples one by one (intersect(), the
    // stream started here and past the jitter) must give the same film.
    const NoisyIntegrator integrator;
    Film one_by_one(37, 23), batched(37, 23);
    const std::unique_ptr<Sampler> sampler = integrator.make_sampler(options.seed);
    for (int y = 0; y < 23; ++y)
        for (int x = 0; x < 37; ++x)
            for (std::uint32_t s = 0; s < 3; ++s) {
                sampler->start_sample(x, y, s);
                const Vec2 jitter = sampler->next_2d();
                Ray ray;
                ASSERT_TRUE(scene->camera().generate_ray(float(x) + jitter.x, float(y) + jitter.y, 37, 23, ray));
                one_by_one.add_sample(x, y, shade_camera_ray(integrator, ray, *scene, *sampler));
            }
    const RenderStats stats = render_image(*scene, integrator, options, batched);
    EXPECT_EQ(stats.samples, 37u * 23u * 3u);
    for (int y = 0; y < 23; ++y)
        for (int x = 0; x < 37; ++x) {
            ASSERT_EQ(one_by_one.mean(x, y), batched.mean(x, y)) << x << "," << y;
            ASSERT_EQ(batched.sample_count(x, y), 3u);
        }
}

TEST(Renderer, CropWindowRendersOnlyItsPixels) {
    auto scene = small_scene();
    NoisyIntegrator integrator;
    RenderOptions options;
    options.width = 20;
    options.height = 10;
    options.crop = CropWindow{5, 2, 12, 6};
    options.progress = ProgressMode::Quiet;
    Film film(20, 10);
    const RenderStats stats = render_image(*scene, integrator, options, film);
    EXPECT_EQ(stats.samples, 7u * 4u);
    EXPECT_EQ(film.sample_count(5, 2), 1u);
    EXPECT_EQ(film.sample_count(11, 5), 1u);
    EXPECT_EQ(film.sample_count(12, 5), 0u);
    EXPECT_EQ(film.sample_count(4, 2), 0u);
}

TEST(Renderer, NonFiniteSamplesAreCountedAndDropped) {
    auto scene = small_scene();
    NanIntegrator integrator;
    RenderOptions options;
    options.width = 8;
    options.height = 8;
    options.samples_per_pixel = 16;
    options.progress = ProgressMode::Quiet;
    Film film(8, 8);
    const RenderStats stats = render_image(*scene, integrator, options, film);
    EXPECT_GT(stats.nonfinite_samples, 0u);
    EXPECT_EQ(stats.nonfinite_samples, film.nonfinite_samples());
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) EXPECT_EQ(film.mean(x, y), film.sample_count(x, y) ? Color(1.0f) : Color(0.0f));
}

// The host plans a fixed render's first pass on an empty film without
// sweeping it (Film::has_samples): a second render on the same film, or on
// its restored copy, must still see the samples already taken.
TEST(Renderer, FixedRenderOnAFilmWithSamplesAddsOnlyWhatIsMissing) {
    auto scene = small_scene();
    NoisyIntegrator integrator;
    RenderOptions options;
    options.width = 9;
    options.height = 7;
    options.samples_per_pixel = 2;
    options.progress = ProgressMode::Quiet;
    Film film(9, 7);
    EXPECT_FALSE(film.has_samples());
    EXPECT_EQ(render_image(*scene, integrator, options, film).samples, 9u * 7u * 2u);
    EXPECT_TRUE(film.has_samples());
    EXPECT_EQ(render_image(*scene, integrator, options, film).samples, 0u);
    Film restored(9, 7);
    restored.restore(film.accumulators());
    EXPECT_TRUE(restored.has_samples());
    options.samples_per_pixel = 3;
    EXPECT_EQ(render_image(*scene, integrator, options, restored).samples, 9u * 7u);
    EXPECT_EQ(restored.samples_taken(4, 3), 3u);
}

TEST(Sampler, DeterministicPerPixelSampleAndDimension) {
    auto a = make_independent_sampler(7);
    auto b = a->clone();
    a->start_sample(3, 4, 5);
    const float first = a->next_1d();
    const Vec2 second = a->next_2d();
    b->start_sample(9, 9, 9);
    b->next_1d();
    b->start_sample(3, 4, 5);
    EXPECT_EQ(b->next_1d(), first);
    EXPECT_EQ(b->next_2d(), second);
    // Uniform on [0,1): mean and range over many values.
    double sum = 0.0;
    for (int i = 0; i < 100000; ++i) {
        a->start_sample(i % 317, i / 317, std::uint32_t(i));
        const float v = a->next_1d();
        ASSERT_GE(v, 0.0f);
        ASSERT_LT(v, 1.0f);
        sum += v;
    }
    EXPECT_NEAR(sum / 100000.0, 0.5, 0.005);
}

class ImageOutput : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("lancer_image_io_test_" + std::to_string(::getpid()));
        fs::create_directories(m_dir);
    }
    void TearDown() override { fs::remove_all(m_dir); }
    fs::path m_dir;
};

Film gradient_film() {
    Film film(4, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x) film.add_sample(x, y, Color(x / 3.0f, y / 2.0f, 2.0f));
    return film;
}

TEST_F(ImageOutput, PngIsSrgbEncodedAndClamped) {
    const Film film = gradient_film();
    const std::string path = (m_dir / "out.png").string();
    ImageWriteOptions options;
    options.metadata = {{"integrator", "test"}};
    write_image(film, path, options);
    const Image image = load_image(path);
    ASSERT_EQ(image.width, 4);
    ASSERT_EQ(image.height, 3);
    EXPECT_NEAR(image.at(1, 0, 0), std::round(linear_to_srgb(1.0f / 3.0f) * 255.0f) / 255.0f, 1e-6f);
    EXPECT_NEAR(image.at(0, 0, 2), 1.0f, 1e-6f);  // 2.0 clamped
    EXPECT_NEAR(srgb_to_linear(linear_to_srgb(0.25f)), 0.25f, 1e-6f);
    // No temporary file is left behind.
    int files = 0;
    for (const auto& entry : fs::directory_iterator(m_dir)) files += entry.is_regular_file();
    EXPECT_EQ(files, 1);
}

TEST_F(ImageOutput, PngInMemoryHoldsWhatTheFileHolds) {
    const Film film = gradient_film();
    const std::string path = (m_dir / "file.png").string();
    write_image(film, path);
    const std::vector<unsigned char> bytes = encode_png(film);
    ASSERT_GT(bytes.size(), 8u);
    EXPECT_EQ(bytes[1], 'P');  // the PNG signature
    const std::string copy = (m_dir / "memory.png").string();
    std::ofstream(copy, std::ios::binary).write(reinterpret_cast<const char*>(bytes.data()), bytes.size());
    const Image from_file = load_image(path), from_memory = load_image(copy);
    ASSERT_EQ(from_memory.width, 4);
    ASSERT_EQ(from_memory.height, 3);
    for (int y = 0; y < 3; ++y)
        for (int x = 0; x < 4; ++x)
            for (int c = 0; c < 3; ++c) EXPECT_EQ(from_memory.at(x, y, c), from_file.at(x, y, c));
}

TEST_F(ImageOutput, ExrKeepsLinearValuesAndSampleCounts) {
    const Film film = gradient_film();
    const std::string path = (m_dir / "out.exr").string();
    ImageWriteOptions options;
    options.sample_count_channel = true;
    write_image(film, path, options);
    const Image image = load_image(path);
    EXPECT_FLOAT_EQ(image.at(1, 0, 0), 1.0f / 3.0f);
    EXPECT_FLOAT_EQ(image.at(0, 0, 2), 2.0f);
    auto input = OIIO::ImageInput::open(path);
    ASSERT_TRUE(input);
    EXPECT_EQ(input->spec().nchannels, 4);
    EXPECT_EQ(input->spec().channelnames[3], "samples");
}

TEST_F(ImageOutput, HdrAndTiffAreWritten) {
    const Film film = gradient_film();
    for (const char* name : {"out.hdr", "out.tif"}) {
        const std::string path = (m_dir / name).string();
        write_image(film, path);
        EXPECT_EQ(load_image(path).width, 4) << name;
    }
}

TEST_F(ImageOutput, FailedWriteLeavesNoFile) {
    const Film film = gradient_film();
    EXPECT_THROW(write_image(film, (m_dir / "missing" / "out.png").string()), std::runtime_error);
    EXPECT_THROW(write_image(film, (m_dir / "out.bmpx").string()), std::runtime_error);
    // A directory in the way of the rename: the write fails, nothing partial stays.
    fs::create_directories(m_dir / "blocked.png" / "inside");
    EXPECT_THROW(write_image(film, (m_dir / "blocked.png").string()), std::runtime_error);
    int files = 0;
    for (const auto& entry : fs::directory_iterator(m_dir)) files += entry.is_regular_file();
    EXPECT_EQ(files, 0);
}

TEST_F(ImageOutput, CompareHelperMeasuresAndWritesSideBySide) {
    Image a;
    a.width = 2;
    a.height = 1;
    a.rgb = {0.5f, 0.5f, 0.5f, 1.0f, 1.0f, 1.0f};
    Image b = a;
    b.rgb[3] = 0.0f;
    const ImageDifference d = compare_images(a, b, 0.1);
    EXPECT_NEAR(d.mean_absolute, 1.0 / 6.0, 1e-9);
    EXPECT_NEAR(d.max_absolute, 1.0, 1e-9);
    EXPECT_EQ(d.pixels_over_threshold, 1);
    std::string message;
    const std::string stem = (m_dir / "failure").string();
    EXPECT_FALSE(images_match(a, b, 0.01, 0.1, 0, stem, &message));
    EXPECT_TRUE(fs::exists(stem + ".png")) << message;
    EXPECT_EQ(load_image(stem + ".png").width, 6);
    EXPECT_TRUE(images_match(a, a, 0.0, 0.0, 0, stem + "_ok", &message));
}

}  // namespace
}  // namespace lancer
