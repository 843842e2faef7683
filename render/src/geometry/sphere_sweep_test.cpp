// Closed-form checks of POV's sphere_sweep (sphere_sweep.h): capsules and
// tangent cones for linear segments, straight B-spline and Catmull-Rom
// tubes whose ends are known, and for curved cubic sweeps a brute-force
// comparison of the crossings with the inside test marched along the ray,
// and of the normals with the gradient of a densely sampled distance.
#include "geometry/sphere_sweep.h"
#include "geometry/shape_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace lancer {
namespace {

using test::sorted_crossings;

std::shared_ptr<const Shape> capsule(double scale = 1.0) {
    return make_sphere_sweep_shape(SphereSweepSpline::Linear,
                                   {{-1 * scale, 0, 0, 0.5 * scale}, {1 * scale, 0, 0, 0.5 * scale}}, 1e-6 * scale);
}

// A wavy cubic sweep in the plane z = 0 with varying radius.
std::vector<glm::dvec4> wave() {
    return {{-3, 0, 0, 0.3},   {-2, 1, 0, 0.4},   {-1, -0.5, 0, 0.25}, {0, 0.8, 0, 0.5},
            {1, -0.6, 0, 0.3}, {2, 0.4, 0, 0.35}, {3, -0.2, 0, 0.2}};
}

// A point near the wave's curve: on the polyline of its middle spheres.
DVec3 near_wave(std::mt19937& rng) {
    const auto spheres = wave();
    std::uniform_real_distribution<double> u(1.0, 5.0);
    const double x = u(rng);
    const int i = int(x);
    return glm::mix(DVec3(spheres[i]), DVec3(spheres[i + 1]), x - i);
}

// Signed distance to the union of the sweep's spheres, by dense sampling of
// the spline written out independently of the shape.
double sampled_distance(SphereSweepSpline spline, const std::vector<glm::dvec4>& spheres, const DVec3& p) {
    static const double b[4][4] = {{1 / 6.0, 4 / 6.0, 1 / 6.0, 0},
                                   {-3 / 6.0, 0, 3 / 6.0, 0},
                                   {3 / 6.0, -1, 3 / 6.0, 0},
                                   {-1 / 6.0, 3 / 6.0, -3 / 6.0, 1 / 6.0}};
    static const double cr[4][4] = {{0, 1, 0, 0}, {-0.5, 0, 0.5, 0}, {1, -2.5, 2, -0.5}, {-0.5, 1.5, -1.5, 0.5}};
    const auto& m = spline == SphereSweepSpline::BSpline ? b : cr;
    double best = INFINITY;
    for (std::size_t i = 0; i + 3 < spheres.size(); ++i)
        for (int step = 0; step <= 4000; ++step) {
            const double s = step / 4000.0, pw[4] = {1, s, s * s, s * s * s};
            glm::dvec4 c(0.0);
            for (int k = 0; k < 4; ++k)
                for (int j = 0; j < 4; ++j) c += pw[k] * m[k][j] * spheres[i + j];
            best = std::min(best, glm::length(p - DVec3(c)) - std::fabs(c.w));
        }
    return best;
}

TEST(SphereSweep, RefusesWhatPovRefuses) {
    EXPECT_EQ(make_sphere_sweep_shape(SphereSweepSpline::Linear, {{0, 0, 0, 1}}, 1e-6), nullptr);
    const std::vector<glm::dvec4> three = {{0, 0, 0, 1}, {1, 0, 0, 1}, {2, 0, 0, 1}};
    EXPECT_NE(make_sphere_sweep_shape(SphereSweepSpline::Linear, three, 1e-6), nullptr);
    EXPECT_EQ(make_sphere_sweep_shape(SphereSweepSpline::BSpline, three, 1e-6), nullptr);
    EXPECT_EQ(make_sphere_sweep_shape(SphereSweepSpline::CubicSpline, three, 1e-6), nullptr);
    EXPECT_EQ(make_sphere_sweep_shape(SphereSweepSpline::Linear, {{0, 0, 0, 1}, {1, NAN, 0, 1}}, 1e-6), nullptr);
    EXPECT_EQ(make_sphere_sweep_shape(SphereSweepSpline::Linear, {{0, 0, 0, 1}, {1, 0, 0, 1}}, INFINITY), nullptr);
}

TEST(SphereSweep, LinearCapsuleHitsNormalsUvAndInside) {
    const auto shape = capsule();
    ASSERT_NE(shape, nullptr);
    // Across the middle: y = -0.5 and y = 0.5.
    auto t = sorted_crossings(*shape, {0, -3, 0}, {0, 1, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 2.5, 1e-12);
    EXPECT_NEAR(t[1], 3.5, 1e-12);
    ShapeCrossing hit;
    ASSERT_TRUE(shape->nearest({0.3, -3, 0.2}, {0, 1, 0}, 0, INFINITY, hit));
    const DVec3 p = DVec3(0.3, -3, 0.2) + hit.t * DVec3(0, 1, 0);
    EXPECT_NEAR(p.y, -std::sqrt(0.25 - 0.04), 1e-12);
    const SurfaceGeometry g = shape->surface(p, hit.face);
    EXPECT_NEAR(g.normal.x, 0.0, 1e-12);
    EXPECT_NEAR(g.normal.y, p.y / 0.5, 1e-12);
    EXPECT_NEAR(g.normal.z, 0.4, 1e-12);
    EXPECT_EQ(g.uv, Vec2(0.0f));
    // Along the axis: the end spheres' poles.
    t = sorted_crossings(*shape, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 3.5, 1e-12);
    EXPECT_NEAR(t[1], 6.5, 1e-12);
    // Obliquely through a cap and the side.
    t = sorted_crossings(*shape, {-3, 0.1, 0}, glm::normalize(DVec3(1, 0.1, 0)));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_TRUE(shape->inside({1.4, 0, 0}));
    EXPECT_TRUE(shape->inside({0, 0.49, 0}));
    EXPECT_FALSE(shape->inside({0, 0.51, 0}));
    EXPECT_FALSE(shape->inside({1.51, 0, 0}));
    DVec3 lower, upper;
    ASSERT_TRUE(shape->bounds(lower, upper));
    EXPECT_LE(lower.x, -1.5);
    EXPECT_GE(upper.x, 1.5);
    EXPECT_LE(upper.y, 1.5);  // not absurdly loose
}

// Spheres r0 = 1 at x = 0 and r1 = 0.5 at x = 4: the envelope is the cone
// tangent to both. With k = (r1 - r0) / 4, the sphere at x_c touches it on
// the circle at x = x_c - r(x_c) k of radius r(x_c) sqrt(1 - k^2).
TEST(SphereSweep, LinearSegmentIsTheTangentCone) {
    const auto shape = make_sphere_sweep_shape(SphereSweepSpline::Linear, {{0, 0, 0, 1}, {4, 0, 0, 0.5}}, 1e-6);
    const double k = -0.125;
    for (double x0 : {0.5, 2.0, 3.5}) {
        const double xc = (x0 + 1.0 * k) / (1 - k * k);
        const double rc = 1.0 + k * xc;
        const double rho = rc * std::sqrt(1 - k * k);
        auto t = sorted_crossings(*shape, {x0, -3, 0}, {0, 1, 0});
        ASSERT_EQ(t.size(), 2u) << x0;
        EXPECT_NEAR(t[0], 3 - rho, 1e-12) << x0;
        EXPECT_NEAR(t[1], 3 + rho, 1e-12) << x0;
        // Also seen square on along z (A' = 0: P's double root).
        t = sorted_crossings(*shape, {x0, 0, -3}, {0, 0, 1});
        ASSERT_EQ(t.size(), 2u) << x0;
        EXPECT_NEAR(t[0], 3 - rho, 1e-12) << x0;
        const SurfaceGeometry g = shape->surface({x0, rho, 0}, 0);
        EXPECT_NEAR(g.normal.x, -k, 1e-12);
        EXPECT_NEAR(g.normal.y, std::sqrt(1 - k * k), 1e-12);
    }
    // Behind the big sphere's tangent circle the sphere itself is the surface.
    auto t = sorted_crossings(*shape, {-0.5, -3, 0}, {0, 1, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 3 - std::sqrt(0.75), 1e-12);
}

// One sphere swallowing the next (|r'| > |c'|): the union is the big sphere.
TEST(SphereSweep, SphereInsideTheNextLeavesTheBigOne) {
    const auto shape = make_sphere_sweep_shape(SphereSweepSpline::Linear, {{0, 0, 0, 0.1}, {1, 0, 0, 2}}, 1e-6);
    auto t = sorted_crossings(*shape, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4, 1e-12);
    EXPECT_NEAR(t[1], 8, 1e-12);
    t = sorted_crossings(*shape, {1, -5, 0.5}, {0, 1, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5 - std::sqrt(3.75), 1e-12);
}

// Equally spaced collinear spheres of one radius: straight tubes. The
// B-spline runs from (P0 + 4 P1 + P2) / 6 to the mirror image at the far
// end; Catmull-Rom from P1 to P(n-2).
TEST(SphereSweep, StraightCubicSweepsEndWhereTheSplinesDo) {
    std::vector<glm::dvec4> spheres;
    for (int i = 0; i < 6; ++i) spheres.push_back({i, 0, 0, 0.25});
    const auto bspline = make_sphere_sweep_shape(SphereSweepSpline::BSpline, spheres, 1e-6);
    auto t = sorted_crossings(*bspline, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5 + 1 - 0.25, 1e-12);
    EXPECT_NEAR(t[1], 5 + 4 + 0.25, 1e-12);
    const auto catmull = make_sphere_sweep_shape(SphereSweepSpline::CubicSpline, spheres, 1e-6);
    t = sorted_crossings(*catmull, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5 + 1 - 0.25, 1e-12);
    EXPECT_NEAR(t[1], 5 + 4 + 0.25, 1e-12);
    // Across the tube, seen square on and obliquely: radius 0.25 everywhere.
    for (const auto& shape : {bspline, catmull})
        for (double x : {1.3, 2.5, 3.9}) {
            t = sorted_crossings(*shape, {x, 0, -2}, {0, 0, 1});
            ASSERT_EQ(t.size(), 2u) << x;
            EXPECT_NEAR(t[0], 1.75, 1e-12);
            EXPECT_NEAR(t[1], 2.25, 1e-12);
            t = sorted_crossings(*shape, {x - 1, -1, -2}, glm::normalize(DVec3(0.5, 0.5, 1)) * 3.0);
            ASSERT_EQ(t.size(), 2u) << x;
        }
    EXPECT_TRUE(catmull->inside({2.5, 0.2, 0}));
    EXPECT_FALSE(catmull->inside({2.5, 0.3, 0}));
    EXPECT_FALSE(bspline->inside({0.7, 0, 0}));  // P0 is not on a B-spline
}

TEST(SphereSweep, GrazingRaysFindCloseCrossingPairs) {
    const auto shape = capsule();
    for (double gap : {1e-4, 1e-7, 1e-10}) {
        const double y = 0.5 - gap;
        const double half = std::sqrt(0.25 - y * y);
        // Square on to the axis (the double-root case) and along the cap.
        auto t = sorted_crossings(*shape, {0.2, y, -3}, {0, 0, 1});
        ASSERT_EQ(t.size(), 2u) << gap;
        EXPECT_NEAR(t[0], 3 - half, 1e-9) << gap;
        EXPECT_NEAR(t[1], 3 + half, 1e-9) << gap;
        EXPECT_TRUE(sorted_crossings(*shape, {0.2, 0.5 + gap, -3}, {0, 0, 1}).empty()) << gap;
    }
    // Along the side, skimming it: either nothing or a pair, never one.
    const auto t = sorted_crossings(*shape, {-3, 0.5 - 1e-9, 0}, {1, 0, 0});
    EXPECT_EQ(t.size() % 2, 0u);
}

TEST(SphereSweep, RaysFromTheSurfaceDoNotFindTheirStart) {
    const auto shape = make_sphere_sweep_shape(SphereSweepSpline::BSpline, wave(), 1e-6);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    int checked = 0;
    for (int i = 0; i < 300; ++i) {
        const DVec3 o(3 * u(rng), 3 * u(rng), -6);
        const DVec3 d = glm::normalize(near_wave(rng) + 0.2 * DVec3(u(rng), u(rng), u(rng)) - o);
        ShapeCrossing first;
        if (!shape->nearest(o, d, 0, INFINITY, first)) continue;
        const DVec3 p = o + first.t * d;
        const SurfaceGeometry g = shape->surface(p, first.face);
        EXPECT_LT(glm::length(g.point - p), 1e-9);
        // Leaving outward: nothing near; going in: the far side, not ~0.
        ShapeCrossing next;
        if (shape->nearest(g.point, g.normal, 1e-9, INFINITY, next)) {
            EXPECT_GT(next.t, 1e-3);
        }
        ASSERT_TRUE(shape->nearest(g.point, -g.normal, 1e-9, INFINITY, next));
        EXPECT_GT(next.t, 1e-3);
        ++checked;
    }
    EXPECT_GT(checked, 200);
}

// Every crossing where the inside test changes along the ray, and no other.
void expect_crossings_match_inside(const Shape& shape, const DVec3& o, const DVec3& d, double t_far) {
    const auto t = sorted_crossings(shape, o, d);
    const int steps = 4000;
    const double step = t_far / steps;
    std::vector<double> changes;
    bool was = shape.inside(o);
    for (int i = 1; i <= steps; ++i) {
        const bool now = shape.inside(o + (i * step) * d);
        if (now != was) changes.push_back((i - 0.5) * step);
        was = now;
    }
    // Pairs closer than a step are invisible to the march: skip those rays.
    for (std::size_t i = 1; i < t.size(); ++i)
        if (t[i] - t[i - 1] < 2 * step) return;
    ASSERT_EQ(t.size(), changes.size()) << "ray " << o.x << " " << o.y << " " << o.z;
    for (std::size_t i = 0; i < t.size(); ++i) EXPECT_NEAR(t[i], changes[i], step);
}

TEST(SphereSweep, CurvedCrossingsAgreeWithTheInsideTest) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (SphereSweepSpline spline : {SphereSweepSpline::BSpline, SphereSweepSpline::CubicSpline}) {
        const auto shape = make_sphere_sweep_shape(spline, wave(), 1e-6);
        ASSERT_NE(shape, nullptr);
        for (int i = 0; i < 60; ++i) {
            // Square on to the plane of the curve (A' = 0 throughout)...
            expect_crossings_match_inside(*shape, {3.5 * u(rng), 1.2 * u(rng), -2}, {0, 0, 1}, 4);
            // ... nearly so (perspective), and along it.
            expect_crossings_match_inside(*shape, {3.5 * u(rng), 1.2 * u(rng), -2},
                                          glm::normalize(DVec3(1e-4 * u(rng), 1e-4 * u(rng), 1)), 4);
            expect_crossings_match_inside(*shape, {-4, 1.2 * u(rng), 0.3 * u(rng)},
                                          glm::normalize(DVec3(1, 0.2 * u(rng), 0.05 * u(rng))), 8);
        }
    }
}

TEST(SphereSweep, NormalsAreTheDistanceGradient) {
    const auto spheres = wave();
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (SphereSweepSpline spline : {SphereSweepSpline::BSpline, SphereSweepSpline::CubicSpline}) {
        const auto shape = make_sphere_sweep_shape(spline, spheres, 1e-6);
        int checked = 0;
        for (int i = 0; i < 40; ++i) {
            const DVec3 o(2.5 * u(rng), u(rng), -3);
            const DVec3 d = glm::normalize(near_wave(rng) + 0.2 * DVec3(u(rng), u(rng), 0) - o);
            ShapeCrossing hit;
            if (!shape->nearest(o, d, 0, INFINITY, hit)) continue;
            const DVec3 p = o + hit.t * d;
            EXPECT_NEAR(sampled_distance(spline, spheres, p), 0.0, 1e-6);
            const SurfaceGeometry g = shape->surface(p, hit.face);
            const double h = 1e-4;
            DVec3 gradient;
            for (int axis = 0; axis < 3; ++axis) {
                DVec3 e(0.0);
                e[axis] = h;
                gradient[axis] =
                    (sampled_distance(spline, spheres, p + e) - sampled_distance(spline, spheres, p - e)) / (2 * h);
            }
            EXPECT_GT(glm::dot(glm::normalize(gradient), g.normal), 0.9999);
            EXPECT_LT(glm::dot(g.normal, d), 0.0);
            ++checked;
        }
        EXPECT_GT(checked, 25);
    }
}

TEST(SphereSweep, ScaledRaysAndScaledSweeps) {
    for (double scale : {1e-4, 1.0, 1e4}) {
        const auto shape = capsule(scale);
        // The ray direction scaled too (as an object transform does).
        for (double d_scale : {1e-3, 1.0, 1e3}) {
            auto t =
                sorted_crossings(*shape, DVec3(0.3, -3, 0.1) * scale, DVec3(0, d_scale, 0), 1e-6 * scale / d_scale);
            ASSERT_EQ(t.size(), 2u) << scale << " " << d_scale;
            const double half = std::sqrt(0.25 - 0.01);
            EXPECT_NEAR(t[0] * d_scale / scale, 3 - half, 1e-11);
            EXPECT_NEAR(t[1] * d_scale / scale, 3 + half, 1e-11);
        }
        EXPECT_TRUE(shape->inside(DVec3(1.2, 0.1, 0) * scale));
        EXPECT_FALSE(shape->inside(DVec3(1.2, 0.5, 0) * scale));
    }
}

// POV's own inside test sees no root in [0, 1] for a point inside every
// sphere of a segment and calls it outside; the solid here is the union.
TEST(SphereSweep, InsideIsTheUnionOfTheSpheres) {
    const auto shape = make_sphere_sweep_shape(SphereSweepSpline::Linear, {{0, 0, 0, 1}, {0.5, 0, 0, 1}}, 1e-6);
    EXPECT_TRUE(shape->inside({0.25, 0, 0}));
    EXPECT_TRUE(shape->inside({0.25, 0.99, 0}));
    EXPECT_FALSE(shape->inside({0.25, 1.01, 0}));
    EXPECT_TRUE(shape->inside({1.45, 0, 0}));
    EXPECT_FALSE(shape->inside({-1.01, 0, 0}));
}

TEST(SphereSweep, DepthToleranceDropsNearCrossings) {
    const auto shape = make_sphere_sweep_shape(SphereSweepSpline::Linear, {{-1, 0, 0, 0.5}, {1, 0, 0, 0.5}}, 3.0);
    const auto t = sorted_crossings(*shape, {0, -3, 0}, {0, 1, 0});
    ASSERT_EQ(t.size(), 1u);
    EXPECT_NEAR(t[0], 3.5, 1e-12);
}

TEST(SphereSweep, DegenerateSweepsStayFinite) {
    // All radii 0: a curve, no surface.
    const auto curve = make_sphere_sweep_shape(SphereSweepSpline::CubicSpline,
                                               {{0, 0, 0, 0}, {1, 0, 0, 0}, {2, 1, 0, 0}, {3, 0, 0, 0}}, 1e-6);
    ASSERT_NE(curve, nullptr);
    EXPECT_TRUE(sorted_crossings(*curve, {1.5, -2, 0.1}, {0, 1, 0}).empty());
    EXPECT_FALSE(curve->inside({1.5, 0.5, 0}));
    // Every sphere the same: a sphere.
    const auto same = make_sphere_sweep_shape(SphereSweepSpline::BSpline,
                                              {{1, 1, 1, 0.5}, {1, 1, 1, 0.5}, {1, 1, 1, 0.5}, {1, 1, 1, 0.5}}, 1e-6);
    auto t = sorted_crossings(*same, {1, 1, -2}, {0, 0, 1});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 2.5, 1e-12);
    EXPECT_NEAR(t[1], 3.5, 1e-12);
    const SurfaceGeometry g = same->surface({1, 1, 0.5}, 0);
    EXPECT_NEAR(g.normal.z, -1.0, 1e-12);
    // All at one point with radius 0, and negative radii (their magnitude).
    const auto point = make_sphere_sweep_shape(SphereSweepSpline::Linear, {{0, 0, 0, 0}, {0, 0, 0, 0}}, 1e-6);
    ASSERT_NE(point, nullptr);
    EXPECT_TRUE(sorted_crossings(*point, {0, 0, -1}, {0, 0, 1}).empty());
    const auto negative = make_sphere_sweep_shape(SphereSweepSpline::Linear, {{-1, 0, 0, -0.5}, {1, 0, 0, -0.5}}, 1e-6);
    t = sorted_crossings(*negative, {0, -3, 0}, {0, 1, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 2.5, 1e-12);
    // A zero direction, huge and tiny inputs: no NaN.
    EXPECT_TRUE(sorted_crossings(*negative, {0, -3, 0}, {0, 0, 0}).empty());
    t = sorted_crossings(*negative, {0, -1e12, 0}, {0, 1, 0});
    for (double v : t) EXPECT_TRUE(std::isfinite(v));
    const SurfaceGeometry centre = negative->surface({0, 0, 0}, 0);
    EXPECT_TRUE(std::isfinite(centre.normal.x + centre.normal.y + centre.normal.z));
}

}  // namespace
}  // namespace lancer
