// The gather integrator: the distribution of its gathered directions, its
// lamps, and its extremes of n.
#include <cmath>
#include <random>
#include <vector>

#include "../seed_integrators_test.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/shading/local_shading.h"
#include "sphere_lattice.h"

namespace lancer {
namespace {

using namespace seed_test;

// Chi-square critical value for `dof` degrees of freedom at upper-tail
// probability 0.01 (Wilson-Hilferty; within 0.1 % for dof > 30).
double chi_square_critical_01(int dof) {
    const double z = 2.3263478740;  // standard normal quantile at 0.99
    const double k = 2.0 / (9.0 * dof);
    return dof * std::pow(1.0 - k + z * std::sqrt(k), 3.0);
}

// Chi-square statistic of normalize(s + N) against the density
// cos(theta)/pi about N: under it, cos^2(theta) and the azimuth are
// independent and uniform, so both are binned evenly (16 x 16 bins). Each
// draw takes a fresh jitter (as one hit does) and one lattice point at
// random, so draws are independent samples of the pooled distribution the
// plugin's mean averages over.
constexpr int kCosBins = 16;
constexpr int kAzimuthBins = 16;
constexpr int kDegreesOfFreedom = kCosBins * kAzimuthBins - 1;

double cosine_chi_square(const Vec3& normal, int lattice_size, float jitter) {
    constexpr int kDraws = 400'000;
    const SphereLattice lattice(lattice_size);
    const Vec3 tangent = glm::normalize(glm::cross(std::abs(normal.x) < 0.9f ? Vec3(1, 0, 0) : Vec3(0, 1, 0), normal));
    const Vec3 bitangent = glm::cross(normal, tangent);

    std::mt19937_64 random(20261122);
    std::uniform_real_distribution<float> uniform(0.0f, 1.0f);
    std::uniform_int_distribution<int> pick(0, lattice_size - 1);
    std::vector<int> counts(kCosBins * kAzimuthBins, 0);
    for (int draw = 0; draw < kDraws; ++draw) {
        const SphereLattice::Turn turn = SphereLattice::turn(jitter, uniform(random));
        const Vec3 wi = glm::normalize(lattice.point(pick(random), jitter, uniform(random), turn) + normal);
        const float cos_theta = glm::clamp(glm::dot(wi, normal), 0.0f, 1.0f);
        const float azimuth = std::atan2(glm::dot(wi, bitangent), glm::dot(wi, tangent)) + kPi;
        const int cos_bin = glm::min(int(cos_theta * cos_theta * kCosBins), kCosBins - 1);
        const int azimuth_bin = glm::min(int(azimuth / (2.0f * kPi) * kAzimuthBins), kAzimuthBins - 1);
        ++counts[cos_bin * kAzimuthBins + azimuth_bin];
    }
    const double expected = double(kDraws) / counts.size();
    double chi_square = 0.0;
    for (int count : counts) chi_square += (count - expected) * (count - expected) / expected;
    return chi_square;
}

const Vec3 kNormals[] = {Vec3(0, 1, 0), Vec3(0, -1, 0), glm::normalize(Vec3(0.3f, 0.8f, -0.5f)), Vec3(1, 0, 0)};

TEST(GatherLattice, JitteredSPlusNormalIsCosineDistributed) {
    for (const Vec3& normal : kNormals)
        for (int n : {1, 64, 149})
            EXPECT_LT(cosine_chi_square(normal, n, 1.0f), chi_square_critical_01(kDegreesOfFreedom))
                << "N = (" << normal.x << ", " << normal.y << ", " << normal.z << "), n = " << n;
}

TEST(GatherLattice, ChiSquareTestRejectsPartialJitter) {
    // The same test has the power to see a lattice that is not moved
    // enough: its directions cluster around the fixed points.
    for (float jitter : {0.0f, 0.5f})
        EXPECT_GT(cosine_chi_square(kNormals[2], 64, jitter), chi_square_critical_01(kDegreesOfFreedom))
            << "jitter " << jitter;
}

TEST(GatherLattice, PointsAreUnitAndEvenlySpread) {
    const SphereLattice lattice(100);
    Vec3 centroid(0.0f);
    for (int i = 0; i < lattice.size(); ++i) {
        const Vec3 s = lattice.point(i, 0.0f, 0.5f, SphereLattice::Turn{});
        EXPECT_NEAR(glm::length(s), 1.0f, 1e-5f);
        centroid += s;
    }
    EXPECT_LT(glm::length(centroid / 100.0f), 0.02f);
}

// A white diffuse floor under a square lamp of side `size` at height h.
sg::SceneGraph floor_under_lamp(double height, double size = 1.0) {
    sg::SceneGraph graph;
    graph.camera = camera({0.0, 2.0, -4.0}, {0.0, -0.4, 1.0});
    graph.objects.push_back(plane({0.0, 1.0, 0.0}, 0.0, default_material()));
    graph.lights.push_back(square_light({0.0, height, 0.0}, size, sg::Vec3(10.0)));
    return graph;
}
// The floor point under the lamp, seen from the side under the lamp.
const Ray kToFloorCentre = ray_towards(Vec3(0.0f, 0.3f, -3.0f), Vec3(0.0f));

// Configuration factor from a floor point to a parallel square of side a
// centred above it at height h (four corner rectangles of a/2 x a/2).
double view_factor_to_square(double a, double h) {
    const double x = 0.5 * a / h, y = 0.5 * a / h;
    const double corner = (x / std::sqrt(1 + x * x) * std::atan(y / std::sqrt(1 + x * x)) +
                           y / std::sqrt(1 + y * y) * std::atan(x / std::sqrt(1 + y * y))) /
                          (2.0 * 3.14159265358979);
    return 4.0 * corner;
}

TEST(GatherIntegrator, CloserLampLightsThePlaneMore) {
    float previous = 0.0f;
    for (double height : {4.0, 2.0, 1.0}) {
        const auto scene = compile_scene(floor_under_lamp(height));
        const auto gather = load_integrator("gather", *scene);
        const float seen = mean_radiance(*gather, *scene, kToFloorCentre, 32).g;
        EXPECT_GT(seen, previous) << "lamp at height " << height;
        previous = seen;
    }
}

TEST(GatherIntegrator, FloorUnderLampMatchesTheViewFactor) {
    // Only the lamp is in view of the floor, so the gathered diffuse is
    // unbiased here: rho * Le * F, with the lamp's radiance Le = pi C / area.
    const double height = 1.0, size = 1.0;
    const auto scene = compile_scene(floor_under_lamp(height, size));
    const auto gather = load_integrator("gather", *scene);
    const double lamp_radiance = 3.14159265358979 * 10.0 / (size * size);
    const double expected = 0.6 * lamp_radiance * view_factor_to_square(size, height);
    EXPECT_NEAR(mean_radiance(*gather, *scene, kToFloorCentre, 256).g, expected, 0.015 * expected);
}

TEST(GatherIntegrator, ExtremeLatticeSizesGiveFiniteImages) {
    sg::SceneGraph graph = floor_under_lamp(1.5);
    graph.objects.push_back(sphere({0.0, 0.5, 0.0}, 0.5, default_material()));
    graph.lights.push_back(point_light({2.0, 3.0, -2.0}, sg::Vec3(5.0)));
    const auto scene = compile_scene(graph);
    for (const char* n : {"1", "10000"}) {
        const auto gather = load_integrator("gather", *scene, {{"n", n}});
        const Film film = render_small(*scene, *gather, 8, 6);
        EXPECT_EQ(film.nonfinite_samples(), 0u) << "n = " << n;
        float brightest = 0.0f;
        for (int y = 0; y < 6; ++y)
            for (int x = 0; x < 8; ++x) {
                const Color c = film.mean(x, y);
                EXPECT_TRUE(is_finite(c) && c.r >= 0.0f && c.g >= 0.0f && c.b >= 0.0f) << "n = " << n;
                brightest = glm::max(brightest, max_component(c));
            }
        EXPECT_GT(brightest, 0.0f) << "n = " << n;
    }
}

TEST(GatherIntegrator, JitterComesOnlyFromThePixelSampler) {
    // Same seed, different thread counts and tile orders: the same image, bit for bit.
    const auto scene = compile_scene(floor_under_lamp(1.5));
    const auto gather = load_integrator("gather", *scene, {{"n", "16"}});
    const Film one_thread = render_small(*scene, *gather, 12, 9, 2, 1);
    const Film two_threads = render_small(*scene, *gather, 12, 9, 2, 2);
    for (int y = 0; y < 9; ++y)
        for (int x = 0; x < 12; ++x) ASSERT_EQ(one_thread.mean(x, y), two_threads.mean(x, y)) << x << "," << y;
}

TEST(GatherIntegrator, RejectsOutOfRangeParameters) {
    const Plugin plugin = load_plugin("gather");
    for (const char* bad : {"n=0", "jitter=1.5", "jitter=-0.1", "max_depth=-1"})
        EXPECT_THROW(plugin.descriptor->create(resolve_parameters(*plugin.descriptor, {}, {bad})),
                     std::invalid_argument)
            << bad;
}

}  // namespace
}  // namespace lancer
