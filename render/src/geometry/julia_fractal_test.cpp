// Closed-form checks of POV's julia_fractal (julia_fractal.h). With c = 0
// the sets are known exactly: z -> z^2 keeps |z_k| = |z_0|^(2^k), so the
// set is the ball |z_0|^(2^N) <= bailout (N = max_iteration); the
// hypercomplex ones, in duplex form (a, b), bound |a| and |b| separately.
#include "geometry/julia_fractal.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace lancer {
namespace {

using Parameters = JuliaFractalParameters;
using Algebra = Parameters::Algebra;
using Function = Parameters::Function;

constexpr double kQuaternionUnitBailout = (1.0 + 1e-7) * (1.0 + 1e-7) + 1e-7;  // c = 0

std::vector<ShapeCrossing> sorted_crossings(const Shape& shape, const DVec3& o, const DVec3& d, double t_min = 0.0,
                                            double t_max = INFINITY) {
    ShapeCrossings all;
    shape.crossings(o, d, t_min, t_max, all);
    std::vector<ShapeCrossing> result(all.items, all.items + all.count);
    std::sort(result.begin(), result.end(), [](const ShapeCrossing& a, const ShapeCrossing& b) { return a.t < b.t; });
    return result;
}

std::shared_ptr<const Shape> make(Algebra algebra, Function function, glm::dvec4 c, int iterations = 20) {
    Parameters p;
    p.algebra = algebra;
    p.function = function;
    p.julia_parameter = c;
    p.max_iteration = iterations;
    return make_julia_fractal_shape(p);
}

// The radius of |x|^(2 degree^(N-1)) <= bailout: where the last test fails.
double ball_radius(double bailout, double degree, int iterations) {
    return std::pow(bailout, 1.0 / (2.0 * std::pow(degree, iterations - 1)));
}

TEST(JuliaFractal, QuaternionSqrOfZeroIsTheUnitBall) {
    const auto ball = make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.0));
    ASSERT_TRUE(ball);
    const double radius = ball_radius(kQuaternionUnitBailout, 2.0, 20);
    EXPECT_GT(radius - 1.0, 1e-13);  // the 20 tests leave 3e-13 of slack
    const auto t = sorted_crossings(*ball, {-3, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0].t, 3.0 - radius, 1e-13);
    EXPECT_NEAR(t[1].t, 3.0 + radius, 1e-13);
    for (const ShapeCrossing& c : t) {
        const SurfaceGeometry g = ball->surface(DVec3(-3.0 + c.t, 0, 0), c.face);
        EXPECT_NEAR(std::fabs(g.point.x), radius, 1e-13);
        EXPECT_NEAR(g.normal.x, g.point.x > 0 ? 1.0 : -1.0, 1e-12);
        EXPECT_EQ(g.uv.x, 0.0f);
        EXPECT_EQ(g.uv.y, 0.0f);
    }
    EXPECT_TRUE(ball->inside({0, 0, 0}));
    EXPECT_TRUE(ball->inside({0, 0.999, 0}));
    EXPECT_FALSE(ball->inside({0, 0, 1.001}));
    EXPECT_FALSE(ball->inside({3, 0, 0}));
}

TEST(JuliaFractal, BallIsRoundFromEveryDirection) {
    const auto ball = make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.0));
    std::mt19937 random(7);
    std::normal_distribution<double> gauss;
    for (int i = 0; i < 50; ++i) {
        const DVec3 direction = glm::normalize(DVec3(gauss(random), gauss(random), gauss(random)));
        const DVec3 offset = 0.5 * glm::normalize(glm::cross(direction, DVec3(gauss(random), 1, 0)));
        const DVec3 o = offset - 3.0 * direction;
        const auto t = sorted_crossings(*ball, o, direction);
        ASSERT_EQ(t.size(), 2u);
        const double half_chord = std::sqrt(1.0 - 0.25);
        EXPECT_NEAR(t[0].t, 3.0 - half_chord, 1e-9);
        EXPECT_NEAR(t[1].t, 3.0 + half_chord, 1e-9);
        const SurfaceGeometry g = ball->surface(o + t[0].t * direction, t[0].face);
        EXPECT_NEAR(glm::length(g.normal - g.point), 0.0, 1e-9);
    }
}

TEST(JuliaFractal, QuaternionCubeOfZeroIsTheUnitBall) {
    const auto ball = make(Algebra::Quaternion, Function::Cube, glm::dvec4(0.0), 8);
    const double radius = ball_radius(kQuaternionUnitBailout, 3.0, 8);
    const auto t = sorted_crossings(*ball, {0, 5, 0}, {0, -1, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0].t, 5.0 - radius, 1e-13);
    EXPECT_NEAR(t[1].t, 5.0 + radius, 1e-13);
    EXPECT_NEAR(ball->surface({0, radius, 0}, t[0].face).normal.y, 1.0, 1e-12);
}

TEST(JuliaFractal, FewerIterationsLeaveALargerBall) {
    // max_iteration 5: |x|^32 <= 16 for hypercomplex sqr.
    const auto ball = make(Algebra::Hypercomplex, Function::Sqr, glm::dvec4(0.0), 5);
    const double radius = ball_radius(16.0, 2.0, 5);
    EXPECT_NEAR(radius, std::pow(16.0, 1.0 / 32.0), 1e-15);
    const auto t = sorted_crossings(*ball, {-3, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0].t, 3.0 - radius, 1e-13);
    EXPECT_TRUE(ball->inside({radius - 1e-9, 0, 0}));
    EXPECT_FALSE(ball->inside({radius + 1e-9, 0, 0}));
}

TEST(JuliaFractal, HypercomplexSqrOfZeroBoundsEachDuplexHalf) {
    // Along x, a = b = x: |x|^(2^20) <= 16. Along y = z, a = 2iy and b = 0:
    // |2y|^(2^20) / 2 <= 16. The set is no ball.
    const auto set = make(Algebra::Hypercomplex, Function::Sqr, glm::dvec4(0.0));
    const double along_x = std::pow(16.0, std::ldexp(1.0, -20));
    const auto t = sorted_crossings(*set, {-3, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0].t, 3.0 - along_x, 1e-13);
    EXPECT_NEAR(t[1].t, 3.0 + along_x, 1e-13);
    const double along_diagonal = 0.5 * std::pow(32.0, std::ldexp(1.0, -20)) * std::sqrt(2.0);
    const DVec3 diagonal = glm::normalize(DVec3(0, 1, 1));
    const auto s = sorted_crossings(*set, -3.0 * diagonal, diagonal);
    ASSERT_EQ(s.size(), 2u);
    EXPECT_NEAR(s[0].t, 3.0 - along_diagonal, 1e-12);
    EXPECT_NEAR(s[1].t, 3.0 + along_diagonal, 1e-12);
    EXPECT_LT(along_diagonal, 0.75);
    EXPECT_TRUE(set->inside({0.9, 0, 0}));
    EXPECT_FALSE(set->inside({0, 0.6, 0.6}));
}

TEST(JuliaFractal, HypercomplexCubeIteratesTheSquareAsPovDoes) {
    const auto cube = make(Algebra::Hypercomplex, Function::Cube, glm::dvec4(0.0));
    const double along_x = std::pow(16.0, std::ldexp(1.0, -20));
    const auto t = sorted_crossings(*cube, {-3, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0].t, 3.0 - along_x, 1e-13);
    // z^3 would give |x|^(2 3^19) <= 16: a radius of 1 + 1e-9.
    EXPECT_GT(t[1].t - 3.0, 1.0 + 2e-6);
}

TEST(JuliaFractal, HypercomplexReciprocalCrossesFourTimes) {
    // z -> 1/z: inside where 1/4 <= |x| <= 4 on the x axis; the outer
    // boundary is the bounding sphere itself.
    const auto set = make(Algebra::Hypercomplex, Function::Reciprocal, glm::dvec4(0.0));
    const auto t = sorted_crossings(*set, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 4u);
    EXPECT_NEAR(t[0].t, 1.0, 1e-12);
    EXPECT_NEAR(t[1].t, 4.75, 1e-12);
    EXPECT_NEAR(t[2].t, 5.25, 1e-12);
    EXPECT_NEAR(t[3].t, 9.0, 1e-12);
    // The inner boundary |z_1|^2 = 16 faces the hole, the outer one out.
    EXPECT_NEAR(set->surface({-0.25, 0, 0}, t[1].face).normal.x, 1.0, 1e-9);
    EXPECT_NEAR(set->surface({4, 0, 0}, t[3].face).normal.x, 1.0, 1e-9);
    EXPECT_TRUE(set->inside({1, 0, 0}));
    EXPECT_FALSE(set->inside({0.2, 0, 0}));
}

// nearest() stops the march at the first crossing: the same crossing, face
// included, as the least of all of them, from outside the set and from
// inside it, with t_min and t_max cutting the ray.
TEST(JuliaFractal, TheNearestCrossingIsTheFirstOfAll) {
    std::mt19937 random(9);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    const std::shared_ptr<const Shape> sets[] = {
        make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.49, 0.5, -0.34, 0.1), 7),
        make(Algebra::Hypercomplex, Function::Reciprocal, glm::dvec4(0.0)),
        make(Algebra::Hypercomplex, Function::Sqr, glm::dvec4(-0.2, 0.6, 0.2, 0.0), 8),
    };
    for (const auto& set : sets) {
        int hits = 0;
        for (int i = 0; i < 300; ++i) {
            const DVec3 o = i % 3 == 0 ? DVec3(0.3 * u(random), 0.3 * u(random), 0.3 * u(random))
                                       : DVec3(5.0 * u(random), 5.0 * u(random), -6.0);
            const DVec3 d = DVec3(0.5 * u(random), 0.5 * u(random), 0.5 * u(random)) - o;
            const double t_min = i % 2 ? 0.0 : 0.3, t_max = i % 5 ? INFINITY : 0.9;
            const auto all = sorted_crossings(*set, o, d, t_min, t_max);
            ShapeCrossing first;
            ASSERT_EQ(set->nearest(o, d, t_min, t_max, first), !all.empty()) << i;
            if (all.empty()) continue;
            ++hits;
            EXPECT_EQ(first.t, all[0].t) << i;
            EXPECT_EQ(first.face, all[0].face) << i;
        }
        EXPECT_GT(hits, 60);
    }
}

TEST(JuliaFractal, SliceDistanceAndTiltedSlice) {
    Parameters p;
    p.julia_parameter = glm::dvec4(0.0);
    // w = 0.6 cuts the unit 4-ball in a ball of radius 0.8; POV normalizes
    // the slice normal but not the distance.
    p.slice_normal = {0, 0, 0, 2};
    p.slice_distance = 0.6;
    const auto cut = make_julia_fractal_shape(p);
    auto t = sorted_crossings(*cut, {-3, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0].t, 2.2, 1e-6);
    EXPECT_NEAR(t[1].t, 3.8, 1e-6);
    // Normal (0, 0, 1, 1): w = -z, the ellipsoid x^2 + y^2 + 2 z^2 <= 1.
    p.slice_normal = {0, 0, 1, 1};
    p.slice_distance = 0.0;
    const auto ellipsoid = make_julia_fractal_shape(p);
    t = sorted_crossings(*ellipsoid, {0, 0, -3}, {0, 0, 1});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0].t, 3.0 - std::sqrt(0.5), 1e-6);
    EXPECT_NEAR(t[1].t, 3.0 + std::sqrt(0.5), 1e-6);
    EXPECT_TRUE(ellipsoid->inside({0.9, 0, 0}));
    EXPECT_FALSE(ellipsoid->inside({0, 0, 0.75}));
    // Off the axes the hit lands on the ellipsoid (polished by its exact
    // gradient) and the normal is POV's, with w held fixed: radial.
    const DVec3 o(0.3, -3, 0.2), d(0, 1, 0);
    t = sorted_crossings(*ellipsoid, o, d);
    ASSERT_EQ(t.size(), 2u);
    const SurfaceGeometry g = ellipsoid->surface(o + t[0].t * d, t[0].face);
    EXPECT_NEAR(g.point.x * g.point.x + g.point.y * g.point.y + 2.0 * g.point.z * g.point.z, 1.0, 1e-9);
    EXPECT_NEAR(glm::length(g.normal - glm::normalize(g.point)), 0.0, 1e-9);
}

TEST(JuliaFractal, RefusesWhatPovRefuses) {
    Parameters p;
    for (Function f : {Function::Reciprocal, Function::Exp, Function::Sin, Function::Pwr}) {
        p.function = f;
        p.algebra = Algebra::Quaternion;
        EXPECT_EQ(make_julia_fractal_shape(p), nullptr);
        p.algebra = Algebra::Hypercomplex;
        EXPECT_NE(make_julia_fractal_shape(p), nullptr);
    }
    p = Parameters();
    EXPECT_NE(make_julia_fractal_shape(p), nullptr);
    p.slice_normal = glm::dvec4(0.0);
    EXPECT_EQ(make_julia_fractal_shape(p), nullptr);  // "Slice vector is zero."
    p.slice_normal = {1, 0, 0, 0};
    EXPECT_EQ(make_julia_fractal_shape(p), nullptr);  // "Slice t component is zero."
    p = Parameters();
    p.julia_parameter.y = NAN;
    EXPECT_EQ(make_julia_fractal_shape(p), nullptr);
}

TEST(JuliaFractal, IterationsAndPrecisionBelowOneCountAsOne) {
    const auto reference = make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.0), 1);
    const double expected = sorted_crossings(*reference, {-3, 0, 0}, {1, 0, 0}).at(0).t;
    // One test: |z_0|^2 <= bailout, a ball a little larger than the bounding
    // sphere, so the ray meets the sphere.
    EXPECT_NEAR(expected, 2.0 - 1e-7, 1e-12);
    for (int iterations : {0, -4}) {
        const auto shape = make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.0), iterations);
        EXPECT_EQ(sorted_crossings(*shape, {-3, 0, 0}, {1, 0, 0}).at(0).t, expected);
    }
    Parameters coarse;
    coarse.julia_parameter = {0.2, 0.3, 0, 0};
    coarse.precision = 1.0;
    const auto one = make_julia_fractal_shape(coarse);
    coarse.precision = 0.01;
    const auto below = make_julia_fractal_shape(coarse);
    const DVec3 o(-3, 0.1, 0.05), d(1, 0.02, 0);
    const auto a = sorted_crossings(*one, o, d), b = sorted_crossings(*below, o, d);
    ASSERT_EQ(a.size(), b.size());
    for (std::size_t i = 0; i < a.size(); ++i) EXPECT_EQ(a[i].t, b[i].t);
}

TEST(JuliaFractal, BoundsAreTheBoundingSphere) {
    DVec3 lower, upper;
    ASSERT_TRUE(make(Algebra::Quaternion, Function::Sqr, {0.5, 0, 0, 0})->bounds(lower, upper));
    EXPECT_NEAR(upper.x, 1.5, 1e-6);
    EXPECT_NEAR(lower.z, -1.5, 1e-6);
    make(Algebra::Quaternion, Function::Sqr, {1, 1, 1, 0})->bounds(lower, upper);
    EXPECT_EQ(upper.y, 2.0);
    make(Algebra::Hypercomplex, Function::Exp, {0.1, 0, 0, 0})->bounds(lower, upper);
    EXPECT_EQ(upper.x, 4.0);
    EXPECT_EQ(lower.y, -4.0);
}

TEST(JuliaFractal, ScaledRaysAndFarOrigins) {
    const auto ball = make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.0));
    const double radius = ball_radius(kQuaternionUnitBailout, 2.0, 20);
    for (double scale : {1e-4, 1e4}) {
        const auto t = sorted_crossings(*ball, {-3, 0.2, 0}, {scale, 0, 0});
        ASSERT_EQ(t.size(), 2u);
        const double half_chord = std::sqrt(radius * radius - 0.04);
        EXPECT_NEAR(t[0].t * scale, 3.0 - half_chord, 1e-12);
        EXPECT_NEAR(t[1].t * scale, 3.0 + half_chord, 1e-12);
    }
    const auto far = sorted_crossings(*ball, {0, 0, -1e6}, {0, 0, 1});
    ASSERT_EQ(far.size(), 2u);
    EXPECT_NEAR(far[0].t, 1e6 - radius, 1e-9);
    EXPECT_NEAR(far[1].t, 1e6 + radius, 1e-9);
}

TEST(JuliaFractal, RaysFromTheSurfaceAndFromInside) {
    const auto ball = make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.0));
    const DVec3 o(-3, 0.3, 0.1), d(1, 0, 0);
    const auto t = sorted_crossings(*ball, o, d);
    ASSERT_EQ(t.size(), 2u);
    const DVec3 hit = ball->surface(o + t[0].t * d, t[0].face).point;
    // Leaving outwards finds nothing; inwards only the far side.
    EXPECT_TRUE(sorted_crossings(*ball, hit, -d, 1e-9).empty());
    const auto through = sorted_crossings(*ball, hit, d, 1e-9);
    ASSERT_EQ(through.size(), 1u);
    EXPECT_NEAR(through[0].t, t[1].t - t[0].t, 1e-12);
    // From the centre: one crossing, at the radius.
    const auto out = sorted_crossings(*ball, {0, 0, 0}, {0, 0, -2});
    ASSERT_EQ(out.size(), 1u);
    EXPECT_NEAR(out[0].t, 0.5, 1e-12);
    // t_max short of the far side keeps only the near crossing.
    EXPECT_EQ(sorted_crossings(*ball, o, d, 0.0, 3.5).size(), 1u);
}

TEST(JuliaFractal, GrazingRays) {
    const auto ball = make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.0));
    // A chord of 0.09 is longer than the least step (0.05): found.
    for (double height : {0.9, 0.999}) {
        const auto t = sorted_crossings(*ball, {-3, height, 0}, {1, 0, 0});
        ASSERT_EQ(t.size(), 2u) << height;
        const double half_chord = std::sqrt(1.0 - height * height);
        EXPECT_NEAR(t[0].t, 3.0 - half_chord, 1e-9);
    }
    EXPECT_TRUE(sorted_crossings(*ball, {-3, 1.01, 0}, {1, 0, 0}).empty());
    // Tangent: nothing or a pair, all finite.
    for (const ShapeCrossing& c : sorted_crossings(*ball, {-3, 1, 0}, {1, 0, 0})) EXPECT_TRUE(std::isfinite(c.t));
}

TEST(JuliaFractal, DegenerateRays) {
    const auto ball = make(Algebra::Quaternion, Function::Sqr, glm::dvec4(0.0));
    EXPECT_TRUE(sorted_crossings(*ball, {-3, 0, 0}, {0, 0, 0}).empty());
    EXPECT_TRUE(sorted_crossings(*ball, {NAN, 0, 0}, {1, 0, 0}).empty());
    EXPECT_TRUE(sorted_crossings(*ball, {-3, 0, 0}, {INFINITY, 0, 0}).empty());
    EXPECT_TRUE(sorted_crossings(*ball, {-3, 0, 0}, {1, 0, 0}, 5.0, 1.0).empty());
}

// Every crossing of a real fractal flips the inside state, lies within the
// bounding sphere, and comes with a finite unit normal; crossings pair up.
void check_crossings_are_state_changes(const Shape& shape, int rays, unsigned seed, int least_found) {
    std::mt19937 random(seed);
    std::uniform_real_distribution<double> uniform(-1.0, 1.0);
    DVec3 lower, upper;
    shape.bounds(lower, upper);
    const double radius = upper.x;
    int found = 0;
    for (int i = 0; i < rays; ++i) {
        const DVec3 target = 0.5 * radius * DVec3(uniform(random), uniform(random), uniform(random));
        const DVec3 o = 3.0 * radius * glm::normalize(DVec3(uniform(random), uniform(random), uniform(random)));
        const DVec3 d = target - o;
        const auto t = sorted_crossings(shape, o, d);
        if (t.size() < ShapeCrossings::kCapacity) {
            EXPECT_EQ(t.size() % 2, 0u);
        }
        for (const ShapeCrossing& c : t) {
            ++found;
            ASSERT_TRUE(std::isfinite(c.t));
            const DVec3 p = o + c.t * d;
            EXPECT_LE(glm::length(p), radius * (1.0 + 1e-9));
            const double delta = 1e-9 * radius / glm::length(d);
            const bool on_surface_sphere = c.face == 0 && std::fabs(glm::length(p) - radius) < 1e-9;
            if (!on_surface_sphere) {
                EXPECT_NE(shape.inside(p - delta * d), shape.inside(p + delta * d));
            }
            const SurfaceGeometry g = shape.surface(p, c.face);
            EXPECT_NEAR(glm::length(g.normal), 1.0, 1e-12);
            EXPECT_LT(glm::length(g.point - p), 1e-8 * radius);
        }
    }
    EXPECT_GE(found, least_found) << "seed " << seed;
}

TEST(JuliaFractal, ReferenceSceneFractalsCrossCleanly) {
    Parameters p;
    p.julia_parameter = {-0.083, 0, -0.83, -0.025};
    p.max_iteration = 8;
    check_crossings_are_state_changes(*make_julia_fractal_shape(p), 200, 1, 100);
    p.julia_parameter = {-0.03, 0.5, -0.2, -0.5};
    p.function = Function::Cube;
    check_crossings_are_state_changes(*make_julia_fractal_shape(p), 200, 2, 100);
    p.julia_parameter = {-0.745, 0, 0.113, 0.05};
    p.algebra = Algebra::Hypercomplex;
    p.function = Function::Sqr;
    p.max_iteration = 9;
    p.precision = 40;
    check_crossings_are_state_changes(*make_julia_fractal_shape(p), 200, 3, 40);
    p = Parameters();
    p.julia_parameter = {-0.2, 0.6, 0.2, 0};
    p.max_iteration = 10;
    p.slice_normal = {0.5, 0, 0.3, 1};
    p.slice_distance = 0.2;
    check_crossings_are_state_changes(*make_julia_fractal_shape(p), 200, 4, 100);
}

TEST(JuliaFractal, EveryHypercomplexFunctionStaysFinite) {
    for (int f = int(Function::Sqr); f <= int(Function::Pwr); ++f) {
        Parameters p;
        p.algebra = Algebra::Hypercomplex;
        p.function = Function(f);
        p.julia_parameter = {-0.5, 0.4, 0.1, 0};
        p.power = {2.5, 0.3};
        p.max_iteration = 6;
        const auto shape = make_julia_fractal_shape(p);
        ASSERT_TRUE(shape) << f;
        check_crossings_are_state_changes(*shape, 40, 10 + f, 4);
    }
}

}  // namespace
}  // namespace lancer
