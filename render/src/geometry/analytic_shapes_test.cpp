// Closed-form checks of the analytic shapes (shape.h): hits, normals,
// (u,v), inside tests, grazing rays and rays from on the surface, and the
// polynomial root finder they stand on.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "geometry/planar_spline.h"
#include "geometry/polynomial_roots.h"
#include "geometry/revolution_bands.h"
#include "geometry/shape.h"
#include "geometry/shape_test_support.h"

namespace lancer {
namespace {

using test::sorted_crossings;

TEST(PolynomialRoots, QuarticWithKnownRoots) {
    // (t - 1)(t - 2)(t - 3)(t - 4) = t^4 - 10 t^3 + 35 t^2 - 50 t + 24
    const double c[5] = {24, -50, 35, -10, 1};
    double roots[kMaxPolynomialDegree];
    ASSERT_EQ(polynomial_roots_in(c, 4, -100, 100, roots), 4);
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(roots[i], i + 1.0, 1e-12);
    // Only the roots inside the interval.
    ASSERT_EQ(polynomial_roots_in(c, 4, 1.5, 3.5, roots), 2);
    EXPECT_NEAR(roots[0], 2.0, 1e-12);
    EXPECT_NEAR(roots[1], 3.0, 1e-12);
}

TEST(PolynomialRoots, CloseRootPairsStayApart) {
    // Roots 1 - e, 1 + e, 5, 7: the pair a ray grazing a torus' tube gives.
    for (double e : {1e-2, 1e-4, 1e-6}) {
        const double r[4] = {1 - e, 1 + e, 5, 7};
        // Expand the product.
        double c[5] = {1, 0, 0, 0, 0};
        int degree = 0;
        for (double root : r) {
            for (int i = degree + 1; i > 0; --i) c[i] = c[i - 1] - root * c[i];
            c[0] = -root * c[0];
            ++degree;
        }
        double roots[kMaxPolynomialDegree];
        ASSERT_EQ(polynomial_roots_in(c, 4, 0, 10, roots), 4) << "e " << e;
        EXPECT_NEAR(roots[0], 1 - e, 1e-3 * e);
        EXPECT_NEAR(roots[1], 1 + e, 1e-3 * e);
    }
}

TEST(PolynomialRoots, StableQuadratic) {
    double roots[2];
    // Roots 1e-9 and 1e9: the small one is lost by the textbook formula.
    ASSERT_EQ(solve_quadratic(1.0, -0.5 * (1e9 + 1e-9), 1.0, roots), 2);
    EXPECT_NEAR(roots[0], 1e-9, 1e-21);
    EXPECT_NEAR(roots[1], 1e9, 1e-3);
    EXPECT_EQ(solve_quadratic(1.0, 0.0, 1.0, roots), 0);
}

TEST(Cylinder, HitsNormalsUvAndInside) {
    const auto cylinder = make_cone_shape({{0, 0, 0}, {0, 2, 0}, 0.5, 0.5, false});
    // Across the side: x = -0.5 and x = +0.5.
    auto t = sorted_crossings(*cylinder, {-3, 1, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 2.5, 1e-12);
    EXPECT_NEAR(t[1], 3.5, 1e-12);
    SurfaceGeometry g = cylinder->surface({-0.5, 1, 0}, 0);
    EXPECT_NEAR(g.normal.x, -1.0, 1e-12);
    EXPECT_NEAR(g.uv.y, 0.5, 1e-6);
    // Along the axis: the two end discs, with normals -y and +y.
    ShapeCrossings ends;
    cylinder->crossings({0.1, -1, 0.1}, {0, 1, 0}, 0, INFINITY, ends);
    ASSERT_EQ(ends.count, 2);
    for (int i = 0; i < 2; ++i) {
        const ShapeCrossing& c = ends.items[i];
        const DVec3 p = DVec3(0.1, -1, 0.1) + c.t * DVec3(0, 1, 0);
        EXPECT_NEAR(cylinder->surface(p, c.face).normal.y, p.y < 1 ? -1.0 : 1.0, 1e-12);
    }
    EXPECT_TRUE(cylinder->inside({0.2, 1.9, 0.2}));
    EXPECT_FALSE(cylinder->inside({0.4, 1, 0.4}));
    EXPECT_FALSE(cylinder->inside({0, 2.1, 0}));
    // Open: no end discs, the same solid for POV's inside test.
    const auto open = make_cone_shape({{0, 0, 0}, {0, 2, 0}, 0.5, 0.5, true});
    EXPECT_TRUE(sorted_crossings(*open, {0.1, -1, 0.1}, {0, 1, 0}).empty());
    EXPECT_TRUE(open->inside({0.2, 1.0, 0.2}));
    DVec3 lower, upper;
    ASSERT_TRUE(cylinder->bounds(lower, upper));
    EXPECT_NEAR(lower.x, -0.5, 1e-12);
    EXPECT_NEAR(upper.y, 2.0, 1e-12);
}

TEST(Cone, SlantedSideAndApex) {
    // Apex at y = 1 (cap radius 0), base radius 1 at y = 0: the side is x = 1 - y.
    const auto cone = make_cone_shape({{0, 0, 0}, {0, 1, 0}, 1.0, 0.0, false});
    auto t = sorted_crossings(*cone, {-3, 0.25, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 3 - 0.75, 1e-12);
    EXPECT_NEAR(t[1], 3 + 0.75, 1e-12);
    const SurfaceGeometry g = cone->surface({0.75, 0.25, 0}, 0);
    EXPECT_NEAR(g.normal.x, std::sqrt(0.5), 1e-12);
    EXPECT_NEAR(g.normal.y, std::sqrt(0.5), 1e-12);
    // The mirrored sheet above the apex is not part of the cone.
    EXPECT_TRUE(sorted_crossings(*cone, {-3, 1.5, 0}, {1, 0, 0}).empty());
    EXPECT_TRUE(cone->inside({0.1, 0.5, 0.1}));
    EXPECT_FALSE(cone->inside({0.45, 0.6, 0.0}));
}

TEST(Torus, EdgeOnRayCrossesFourTimes) {
    const double R = 2.0, r = 0.5;
    const auto torus = make_torus_shape(R, r);
    auto t = sorted_crossings(*torus, {-10, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 4u);
    const double expected[4] = {10 - R - r, 10 - R + r, 10 + R - r, 10 + R + r};
    for (int i = 0; i < 4; ++i) EXPECT_NEAR(t[i], expected[i], 1e-10);
    EXPECT_TRUE(torus->inside({R, 0, 0}));
    EXPECT_FALSE(torus->inside({0, 0, 0}));
    const SurfaceGeometry g = torus->surface({R + r, 0, 0}, 0);
    EXPECT_NEAR(g.normal.x, 1.0, 1e-12);
    // POV's (u,v): u = 1 - (atan2(z, x) + pi) / 2pi, v = (atan2(y, ring - R) + pi) / 2pi.
    EXPECT_NEAR(g.uv.x, 0.5f, 1e-6);
    EXPECT_NEAR(g.uv.y, 0.5f, 1e-6);
}

// A ray skimming the top of the tube (y just below r) crosses it twice
// close together near x = -R and x = R: x = +-R +- sqrt(r^2 - y^2).
TEST(Torus, GrazingRaysFindCloseRootPairs) {
    const double R = 2.0, r = 0.5;
    const auto torus = make_torus_shape(R, r);
    for (double gap : {1e-3, 1e-5, 1e-7}) {
        const double y = r - gap;
        const double half = std::sqrt(r * r - y * y);
        auto t = sorted_crossings(*torus, {-10, y, 0}, {1, 0, 0});
        ASSERT_EQ(t.size(), 4u) << "gap " << gap;
        EXPECT_NEAR(t[0], 10 - R - half, 1e-6 * half + 1e-12) << "gap " << gap;
        EXPECT_NEAR(t[1], 10 - R + half, 1e-6 * half + 1e-12) << "gap " << gap;
    }
    // Just above the tube: nothing.
    EXPECT_TRUE(sorted_crossings(*torus, {-10, r + 1e-9, 0}, {1, 0, 0}).empty());
}

TEST(Torus, FarOriginsAndScaledDirectionsAgree) {
    const auto torus = make_torus_shape(1.0, 0.3);
    const DVec3 target(0.9, 0.1, 0.4);
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 200; ++i) {
        DVec3 direction = glm::normalize(DVec3(u(rng), u(rng), u(rng)));
        for (double distance : {10.0, 1e4, 1e7}) {
            const DVec3 o = target - distance * direction;
            // A direction of length 3: t shrinks by 3, the point is the same.
            auto t = sorted_crossings(*torus, o, 3.0 * direction);
            ASSERT_FALSE(t.empty()) << distance;
            const DVec3 p = o + t[0] * 3.0 * direction;
            const double ring = std::sqrt(p.x * p.x + p.z * p.z) - 1.0;
            // On the surface to within the origin's own rounding.
            EXPECT_NEAR(std::sqrt(ring * ring + p.y * p.y), 0.3, 1e-14 * distance + 1e-12) << distance;
        }
    }
}

TEST(Torus, RayFromTheSurfaceDoesNotFindItAgainAtZero) {
    const auto torus = make_torus_shape(1.0, 0.25);
    const DVec3 on(1.25, 0, 0);
    // Leaving outward: nothing beyond (the ray points away from the torus).
    EXPECT_TRUE(sorted_crossings(*torus, on + 1e-9 * DVec3(1, 0, 0), {1, 0, 0}, 0.0).empty());
    // Leaving inward: the far side of the tube at x = 0.75, t = 0.5.
    auto t = sorted_crossings(*torus, on - 1e-9 * DVec3(1, 0, 0), {-1, 0, 0}, 0.0);
    ASSERT_FALSE(t.empty());
    EXPECT_NEAR(t[0], 0.5, 1e-8);
}

TEST(Disc, RingHitsAndHalfSpace) {
    const auto disc = make_disc_shape({{0, 1, 0}, {0, 1, 0}, 2.0, 0.5});
    EXPECT_EQ(sorted_crossings(*disc, {1, 5, 0}, {0, -1, 0}), std::vector<double>{4.0});
    EXPECT_TRUE(sorted_crossings(*disc, {0.2, 5, 0}, {0, -1, 0}).empty());  // in the hole
    EXPECT_TRUE(sorted_crossings(*disc, {2.5, 5, 0}, {0, -1, 0}).empty());  // beyond the rim
    EXPECT_TRUE(disc->inside({0, 0.5, 0}));                                 // POV: behind the normal
    EXPECT_FALSE(disc->inside({0, 1.5, 0}));
    EXPECT_NEAR(disc->surface({1, 1, 0}, 0).normal.y, 1.0, 1e-12);
}

TEST(Quadric, EllipsoidHitsAndExactBox) {
    // x^2/4 + y^2 + z^2 - 1 = 0: an ellipsoid with semi-axes 2, 1, 1.
    const auto ellipsoid = make_quadric_shape({{0.25, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1});
    EXPECT_EQ(sorted_crossings(*ellipsoid, {-5, 0, 0}, {1, 0, 0}), (std::vector<double>{3.0, 7.0}));
    DVec3 lower, upper;
    ASSERT_TRUE(ellipsoid->bounds(lower, upper));
    EXPECT_NEAR(lower.x, -2.0, 1e-12);
    EXPECT_NEAR(upper.y, 1.0, 1e-12);
    EXPECT_TRUE(ellipsoid->inside({1.9, 0, 0}));
    EXPECT_FALSE(ellipsoid->inside({0, 1.1, 0}));
    EXPECT_NEAR(ellipsoid->surface({0, 1, 0}, 0).normal.y, 1.0, 1e-12);
}

TEST(Quadric, InfiniteCylinderAndMixedTerms) {
    // shapes.inc's Cylinder_Y: x^2 + z^2 - 1 = 0, unbounded.
    const auto cylinder = make_quadric_shape({{1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1});
    DVec3 lower, upper;
    EXPECT_FALSE(cylinder->bounds(lower, upper));
    auto t = sorted_crossings(*cylinder, {-3, 1e6, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 2.0, 1e-9);
    // xy - 1 = 0 (a hyperbola extruded along z): on the line y = x at x = 1.
    const auto saddle = make_quadric_shape({{0, 0, 0}, {1, 0, 0}, {0, 0, 0}, -1});
    t = sorted_crossings(*saddle, {0, 0, 0}, glm::normalize(DVec3(1, 1, 0)));
    ASSERT_EQ(t.size(), 1u);
    EXPECT_NEAR(t[0], std::sqrt(2.0), 1e-12);
    // A far origin (1e8 away along the ray) loses no digits.
    t = sorted_crossings(*cylinder, {-1e8, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 1e8 - 1.0, 1e-7);
}

// Shape::narrow_box must keep every point of the solid that lies in the
// box it is given: sampled over quadrics with and without linear terms, and
// planes across an axis, upright and inverted, in boxes with infinite sides.
TEST(Quadric, NarrowedBoxesKeepTheSolidTheyHold) {
    struct Case {
        std::shared_ptr<const Shape> shape;
        bool inverted;
        DVec3 lower, upper;         // the box given
        bool narrows_x, narrows_y;  // whether those axes come out finite
    };
    const double inf = INFINITY;
    const std::vector<Case> cases = {
        // Cylinder_Y across its axis, however long.
        {make_quadric_shape({{1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1}), false, DVec3(-inf), DVec3(inf), true, false},
        // Hyperboloid_Y between y = -2 and y = 3: its waist widens to sqrt(10).
        {make_quadric_shape({{1, -1, 1}, {0, 0, 0}, {0, 0, 0}, -1}),
         false,
         {-inf, -2, -inf},
         {inf, 3, inf},
         true,
         true},
        // The same without the planes: nothing to narrow.
        {make_quadric_shape({{1, -1, 1}, {0, 0, 0}, {0, 0, 0}, -1}), false, DVec3(-inf), DVec3(inf), false, false},
        // A moved paraboloid y >= (x - 1)^2 + z^2 (linear terms), cut at y = 4.
        {make_quadric_shape({{1, 0, 1}, {0, 0, 0}, {-2, -1, 0}, 1}),
         false,
         {-inf, -inf, -inf},
         {inf, 4, inf},
         true,
         true},
        // An ellipsoid, upright: its own box.
        {make_quadric_shape({{0.25, 1, 1}, {0, 0, 0}, {0, 0, 0}, -1}), false, DVec3(-inf), DVec3(inf), true, true},
        // Inverted, a quadric's solid is all space around it.
        {make_quadric_shape({{1, 0, 1}, {0, 0, 0}, {0, 0, 0}, -1}), true, DVec3(-inf), DVec3(inf), false, false},
        // Planes across an axis, either way round; a slanted one narrows nothing.
        {make_plane_shape(AnalyticPlane(DVec3(-1, 0, 0), 2.0)), false, {-inf, -1, -inf}, {inf, 1, inf}, false, true},
        {make_plane_shape(AnalyticPlane(DVec3(0, 1, 0), 0.5)), true, {-3, -inf, -inf}, {3, inf, inf}, true, false},
        {make_plane_shape(AnalyticPlane(glm::normalize(DVec3(1, 1, 0)), 0.0)), false, DVec3(-inf), DVec3(inf), false,
         false},
    };
    std::mt19937 random(11);
    std::uniform_real_distribution<double> coordinate(-5.0, 5.0);
    for (std::size_t k = 0; k < cases.size(); ++k) {
        const Case& c = cases[k];
        DVec3 lower = c.lower, upper = c.upper;
        c.shape->narrow_box(lower, upper, c.inverted);
        EXPECT_EQ(std::isfinite(lower.x) && std::isfinite(upper.x), c.narrows_x) << "case " << k;
        EXPECT_EQ(std::isfinite(lower.y) && std::isfinite(upper.y), c.narrows_y) << "case " << k;
        int kept = 0;
        for (int i = 0; i < 40000; ++i) {
            const DVec3 p(coordinate(random), coordinate(random), coordinate(random));
            const bool in_given = glm::all(glm::lessThanEqual(c.lower, p)) && glm::all(glm::lessThanEqual(p, c.upper));
            if (!in_given || c.shape->inside(p) == c.inverted) continue;
            ++kept;
            ASSERT_TRUE(glm::all(glm::lessThanEqual(lower, p)) && glm::all(glm::lessThanEqual(p, upper)))
                << "case " << k << " point " << p.x << ", " << p.y << ", " << p.z;
        }
        EXPECT_GT(kept, 100) << "case " << k;
    }
    // The hyperboloid's box between its planes is as tight as its widest ring.
    DVec3 lower(-inf, -2, -inf), upper(inf, 3, inf);
    cases[1].shape->narrow_box(lower, upper, false);
    EXPECT_NEAR(upper.x, std::sqrt(10.0), 1e-12);
    EXPECT_NEAR(lower.z, -std::sqrt(10.0), 1e-12);
}

// A sor's or lathe's segment is skipped when the ray never comes within
// its band (revolution_bands.h): the band must hold every point the ray
// has at its heights within its radius, and the cubic's range every value.
TEST(RevolutionBand, NeverSkipsARayThatComesWithinIt) {
    std::mt19937 random(5);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
        const double c[4] = {unit(random), unit(random) * 3.0, unit(random) * 3.0, unit(random) * 3.0};
        const double s0 = unit(random), s1 = s0 + 0.1 + std::fabs(unit(random));
        double lowest, highest;
        cubic_range(c, s0, s1, lowest, highest);
        for (int i = 0; i <= 200; ++i) {
            const double s = s0 + (s1 - s0) * i / 200.0;
            const double value = ((c[3] * s + c[2]) * s + c[1]) * s + c[0];
            ASSERT_GE(value, lowest - 1e-12) << k;
            ASSERT_LE(value, highest + 1e-12) << k;
        }
    }
    // A cubic whose leading coefficient is a rounding error (as a curve
    // segment's often is): its turning point must not be lost.
    {
        const double c[4] = {0.228311, 0.228311, -0.228311, -2.77555756e-17};
        double lowest, highest;
        cubic_range(c, 0.0, 1.0, lowest, highest);
        EXPECT_NEAR(highest, 0.228311 + 0.228311 / 4.0, 1e-12);
    }
    int met = 0, missed = 0;
    for (int k = 0; k < 4000; ++k) {
        const double y = unit(random);
        const RevolutionBand band{y, y + 0.2 + 0.5 * std::fabs(unit(random)), 0.1 + std::fabs(unit(random))};
        const DVec3 o(3.0 * unit(random), 3.0 * unit(random), 3.0 * unit(random));
        DVec3 d(unit(random), k % 7 == 0 ? 0.0 : unit(random), unit(random));
        if (k % 11 == 0) d = DVec3(0.0, 1.0, 0.0);  // along the axis
        const double t_low = -2.0 * std::fabs(unit(random)), t_high = 6.0 * std::fabs(unit(random));
        bool comes_within = false;
        for (int i = 0; i <= 4000 && !comes_within; ++i) {
            const DVec3 p = o + (t_low + (t_high - t_low) * i / 4000.0) * d;
            comes_within =
                p.y >= band.y_low && p.y <= band.y_high && p.x * p.x + p.z * p.z <= band.radius * band.radius;
        }
        const bool may = band.may_meet(o, d, t_low, t_high);
        if (comes_within) {
            ASSERT_TRUE(may) << "ray " << k;
        }
        (may ? met : missed) += 1;
    }
    EXPECT_GT(missed, 1000);  // and it does skip
    EXPECT_GT(met, 50);
}

TEST(Polygon, EvenOddAcrossLoops) {
    // A 2 x 2 square with a 1 x 1 hole, in the plane z = 1, loops closed by
    // repeating their first point (POV's form).
    const std::vector<DVec3> points = {{0, 0, 1},     {2, 0, 1},     {2, 2, 1},     {0, 2, 1},     {0, 0, 1},
                                       {0.5, 0.5, 1}, {1.5, 0.5, 1}, {1.5, 1.5, 1}, {0.5, 1.5, 1}, {0.5, 0.5, 1}};
    const auto polygon = make_polygon_shape(points);
    ASSERT_TRUE(polygon);
    EXPECT_EQ(sorted_crossings(*polygon, {0.25, 0.25, -1}, {0, 0, 1}), std::vector<double>{2.0});
    EXPECT_TRUE(sorted_crossings(*polygon, {1, 1, -1}, {0, 0, 1}).empty());  // the hole
    EXPECT_TRUE(sorted_crossings(*polygon, {2.5, 1, -1}, {0, 0, 1}).empty());
    EXPECT_FALSE(polygon->inside({1, 1, 1}));  // POV: a polygon is no solid
    EXPECT_NEAR(std::fabs(polygon->surface({1, 0.2, 1}, 0).normal.z), 1.0, 1e-12);
    // Collinear points span no plane.
    EXPECT_FALSE(make_polygon_shape({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 0, 0}}));
}

TEST(Polynomial, QuarticTorusMatchesTheTorus) {
    // (x^2 + y^2 + z^2 + R^2 - r^2)^2 - 4 R^2 (x^2 + z^2), R = 2, r = 0.5, in POV's order.
    const double R = 2.0, r = 0.5, A = R * R - r * r;
    std::vector<double> c(35, 0.0);
    c[0] = 1;                   // x^4
    c[4] = 2;                   // x^2 y^2
    c[7] = 2;                   // x^2 z^2
    c[9] = 2 * A - 4 * R * R;   // x^2
    c[20] = 1;                  // y^4
    c[23] = 2;                  // y^2 z^2
    c[25] = 2 * A;              // y^2
    c[30] = 1;                  // z^4
    c[32] = 2 * A - 4 * R * R;  // z^2
    c[34] = A * A;
    const auto quartic = make_polynomial_shape(4, c);
    ASSERT_TRUE(quartic);
    const auto torus = make_torus_shape(R, r);
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    int compared = 0;
    for (int i = 0; i < 300; ++i) {
        const DVec3 o(6 * u(rng), 6 * u(rng), 6 * u(rng));
        const DVec3 d = glm::normalize(DVec3(u(rng), u(rng), u(rng)) * 3.0 - o);
        const auto expected = sorted_crossings(*torus, o, d);
        const auto found = sorted_crossings(*quartic, o, d);
        ASSERT_EQ(found.size(), expected.size()) << i;
        for (std::size_t k = 0; k < found.size(); ++k) EXPECT_NEAR(found[k], expected[k], 1e-7) << i;
        compared += int(found.size());
    }
    EXPECT_GT(compared, 100);
    EXPECT_TRUE(quartic->inside({R, 0, 0}));
    EXPECT_FALSE(quartic->inside({0, 0, 0}));
    const SurfaceGeometry g = quartic->surface({R + r, 0, 0}, 0);
    EXPECT_NEAR(g.normal.x, 1.0, 1e-9);
    // Wrong coefficient counts and out-of-range orders are refused.
    EXPECT_FALSE(make_polynomial_shape(4, std::vector<double>(34, 1.0)));
    EXPECT_FALSE(make_polynomial_shape(16, std::vector<double>(polynomial_term_count(16), 1.0)));
}

TEST(Superellipsoid, SphereBoxAndGrazingRays) {
    // <1, 1> is the unit sphere: every crossing agrees with the sphere's.
    const auto round = make_superellipsoid_shape(1.0, 1.0);
    const auto sphere = make_sphere_shape(AnalyticSphere{DVec3(0.0), 1.0});
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int i = 0; i < 200; ++i) {
        const DVec3 o(4 * u(rng), 4 * u(rng), -4.0);
        const DVec3 d = glm::normalize(DVec3(0.8 * u(rng), 0.8 * u(rng), 0.0) - o);
        const auto expected = sorted_crossings(*sphere, o, d);
        const auto found = sorted_crossings(*round, o, d);
        ASSERT_EQ(found.size(), expected.size()) << i;
        for (std::size_t k = 0; k < found.size(); ++k) EXPECT_NEAR(found[k], expected[k], 1e-9) << i;
    }
    // A ray grazing the sphere 1e-6 inside its rim still finds both crossings.
    const double y = 1.0 - 1e-6;
    auto t = sorted_crossings(*round, {-3, y, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[1] - t[0], 2.0 * std::sqrt(1.0 - y * y), 1e-6);
    // Small exponents approach the cube: its faces at +-1, normals along the axes.
    const auto boxy = make_superellipsoid_shape(0.1, 0.1);
    t = sorted_crossings(*boxy, {-3, 0.3, 0.2}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 2.0, 1e-6);
    EXPECT_NEAR(boxy->surface({-1, 0.3, 0.2}, 0).normal.x, -1.0, 1e-6);
    EXPECT_TRUE(boxy->inside({0.9, 0.9, 0.0}));
    EXPECT_FALSE(round->inside({0.9, 0.9, 0.0}));
}

// A line just inside a convex superellipsoid's surface, along the surface,
// crosses it twice however shallow; a line just outside does not. The
// search for the minimum of N along the line must tell them apart.
TEST(Superellipsoid, GrazingLinesAreToldApartAtAnyDepth) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> u(-1, 1);
    const double exponents[][2] = {{1, 1}, {0.3, 0.3}, {0.5, 1.0}, {2, 2}, {1.5, 0.4}, {0.2, 2}};
    for (const auto& e : exponents) {
        const auto shape = make_superellipsoid_shape(e[0], e[1]);
        int checked = 0;
        for (int i = 0; i < 400; ++i) {
            const DVec3 on = shape->surface(DVec3(u(rng), u(rng), u(rng)), 0).point;
            const DVec3 normal = shape->surface(on, 0).normal;
            DVec3 along = glm::cross(normal, DVec3(u(rng), u(rng), u(rng)));
            if (glm::length(along) < 0.1) continue;
            along = glm::normalize(along);
            for (const double depth : {1e-2, 1e-4, 1e-6}) {
                const DVec3 in = on - depth * normal, out = on + depth * normal;
                // Where the surface bends too sharply (near an edge) the inner
                // point may not be inside: check only lines that pass inside.
                if (!shape->inside(in) || shape->inside(out)) continue;
                ++checked;
                const auto through = sorted_crossings(*shape, in - 3.0 * along, along, 0.0, 1e9);
                ASSERT_EQ(through.size(), 2u) << e[0] << " " << e[1] << " ray " << i << " depth " << depth;
                EXPECT_LT(through[0], 3.0);
                EXPECT_GT(through[1], 3.0);
                ShapeCrossing first;
                ASSERT_TRUE(shape->nearest(in - 3.0 * along, along, 0.0, 1e9, first));
                EXPECT_EQ(first.t, through[0]);
                // Outside, a tangent plane stays outside a convex solid.
                EXPECT_TRUE(sorted_crossings(*shape, out - 3.0 * along, along, 0.0, 1e9).empty());
            }
        }
        EXPECT_GT(checked, 600) << e[0] << " " << e[1];
    }
}

// Rays that start or stop exactly on the surface (N = 1 to the last bit):
// no crossing where they start, the way out for one heading in, and none
// short of where it stops.
TEST(Superellipsoid, RaysEndingOnTheSurface) {
    const auto round = make_superellipsoid_shape(1.0, 1.0);
    // From (1.8, 2.4, 0) towards the centre, stopping at (0.6, 0.8, 0).
    EXPECT_TRUE(sorted_crossings(*round, {1.8, 2.4, 0}, {-0.6, -0.8, 0}, 0.0, 2.0).empty());
    const auto through = sorted_crossings(*round, {1.8, 2.4, 0}, {-0.6, -0.8, 0}, 0.0, 10.0);
    ASSERT_EQ(through.size(), 2u);
    EXPECT_NEAR(through[0], 2.0, 1e-12);
    EXPECT_NEAR(through[1], 4.0, 1e-12);
    for (const double e : {1.0, 0.1, 0.5}) {
        const auto shape = make_superellipsoid_shape(e, e);
        // Leaving the surface outwards: nothing; inwards: the far side.
        EXPECT_TRUE(sorted_crossings(*shape, {1, 0, 0}, {1, 0, 0}, 0.0, 10.0).empty()) << e;
        const auto back = sorted_crossings(*shape, {1, 0, 0}, {-1, 0, 0}, 0.0, 10.0);
        ASSERT_EQ(back.size(), 1u) << e;
        EXPECT_NEAR(back[0], 2.0, 1e-12) << e;
        ShapeCrossing first;
        ASSERT_TRUE(shape->nearest({1, 0, 0}, {-1, 0, 0}, 0.0, 10.0, first)) << e;
        EXPECT_NEAR(first.t, 2.0, 1e-12) << e;
    }
    // A flat face of a boxy one met head on, then left through the far face.
    const auto boxy = make_superellipsoid_shape(0.1, 0.1);
    const auto across = sorted_crossings(*boxy, {0.3, -3, 0.2}, {0, 1, 0}, 0.0, 10.0);
    ASSERT_EQ(across.size(), 2u);
    EXPECT_NEAR(across[0], 2.0, 1e-9);
    EXPECT_NEAR(across[1], 4.0, 1e-9);
}

// Every crossing reported is a change of inside(); the nearest is the
// least crossing; the normal is N's gradient (by differences here).
TEST(Superellipsoid, CrossingsNearestAndNormalsAgree) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<double> u(-1, 1);
    const double exponents[][2] = {{1, 1}, {0.3, 0.5}, {2, 1}, {3, 3}, {0.5, 2.5}, {2.5, 0.3}};
    for (const auto& e : exponents) {
        const auto shape = make_superellipsoid_shape(e[0], e[1]);
        int hits = 0;
        for (int i = 0; i < 2000; ++i) {
            // Half the rays start inside the unit box, half far outside it.
            const DVec3 o =
                i % 2 ? DVec3(1.2 * u(rng), 1.2 * u(rng), 1.2 * u(rng)) : DVec3(4 * u(rng), 4 * u(rng), -4.0);
            const DVec3 d = glm::normalize(DVec3(u(rng), u(rng), u(rng)) - o);
            const auto found = sorted_crossings(*shape, o, d, 1e-9, 1e9);
            ShapeCrossing first;
            ASSERT_EQ(shape->nearest(o, d, 1e-9, 1e9, first), !found.empty()) << i;
            if (found.empty()) continue;
            ++hits;
            EXPECT_EQ(first.t, found[0]) << i;
            for (const double t : found)
                EXPECT_NE(shape->inside(o + (t - 1e-7) * d), shape->inside(o + (t + 1e-7) * d)) << i << " " << t;
            const SurfaceGeometry g = shape->surface(o + found[0] * d, 0);
            const auto n_at = [&](const DVec3& p) {
                const double p_ = 2.0 / e[0], q = 2.0 / e[1];
                const double a = std::pow(std::pow(std::fabs(p.x), p_) + std::pow(std::fabs(p.y), p_), 1.0 / p_);
                return std::pow(std::pow(a, q) + std::pow(std::fabs(p.z), q), 1.0 / q);
            };
            DVec3 gradient;
            for (int axis = 0; axis < 3; ++axis) {
                DVec3 plus = g.point, minus = g.point;
                plus[axis] += 1e-7;
                minus[axis] -= 1e-7;
                gradient[axis] = n_at(plus) - n_at(minus);
            }
            // Away from creases (where a coordinate is near 0 and the
            // gradient jumps) the two agree.
            if (glm::min(glm::abs(g.point.x), glm::min(glm::abs(g.point.y), glm::abs(g.point.z))) > 1e-3) {
                EXPECT_LT(glm::length(glm::normalize(gradient) - g.normal), 1e-5) << i;
            }
        }
        EXPECT_GT(hits, 300) << e[0] << " " << e[1];
    }
}

// One component: s (1 - r^2/R^2)^2 = T at r = R sqrt(1 - sqrt(T/s)).
TEST(Blob, SingleComponentsHaveClosedFormRadii) {
    const double R = 2.0, s = 1.5, T = 0.5;
    const double r = R * std::sqrt(1.0 - std::sqrt(T / s));
    BlobParameters sphere;
    sphere.threshold = T;
    sphere.components.push_back(BlobComponent{BlobComponent::Kind::Sphere, {1, 0, 0}, {1, 0, 0}, R, s, DMat4(1.0)});
    const auto blob = make_blob_shape(sphere);
    auto t = sorted_crossings(*blob, {-5, 0, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 6.0 - r, 1e-9);
    EXPECT_NEAR(t[1], 6.0 + r, 1e-9);
    EXPECT_NEAR(blob->surface({1 - r, 0, 0}, 0).normal.x, -1.0, 1e-9);
    EXPECT_TRUE(blob->inside({1, 0, 0}));
    EXPECT_FALSE(blob->inside({1 + 1.01 * r, 0, 0}));
    // A cylinder component: the same radius about its segment, and about its ends.
    BlobParameters cylinder;
    cylinder.threshold = T;
    cylinder.components.push_back(
        BlobComponent{BlobComponent::Kind::Cylinder, {0, -1, 0}, {0, 1, 0}, R, s, DMat4(1.0)});
    const auto capsule = make_blob_shape(cylinder);
    t = sorted_crossings(*capsule, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 5.0 - r, 1e-9);
    t = sorted_crossings(*capsule, {0, 5, 0}, {0, -1, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.0 - r, 1e-9);  // the hemisphere about the end (0, 1, 0)
    // A negative component subtracts: a hole through the middle.
    BlobParameters dented = sphere;
    dented.components.push_back(BlobComponent{BlobComponent::Kind::Sphere, {1, 0, 0}, {1, 0, 0}, 0.5, -10, DMat4(1.0)});
    EXPECT_FALSE(make_blob_shape(dented)->inside({1, 0, 0}));
}

// Hundreds of components, found through the blob's tree of their boxes:
// each isolated sphere keeps its closed-form radius along any ray through
// it, and every point query (inside, the normal) finds the one it is near.
TEST(Blob, EveryComponentOfAManyComponentBlobIsFound) {
    const double R = 1.0, s = 1.0, T = 0.25;
    const double r = R * std::sqrt(1.0 - std::sqrt(T / s));
    BlobParameters grid;
    grid.threshold = T;
    // 12 x 12 x 3 spheres, 3 apart (no two reach each other), some of them
    // stretched into ellipsoids, which the tree bounds by their placed boxes.
    std::vector<DVec3> centres;
    for (int i = 0; i < 12; ++i)
        for (int j = 0; j < 12; ++j)
            for (int k = 0; k < 3; ++k) {
                const DVec3 centre(3.0 * i, 3.0 * j, 3.0 * k);
                centres.push_back(centre);
                grid.components.push_back(BlobComponent{BlobComponent::Kind::Sphere, centre, centre, R, s, DMat4(1.0)});
            }
    const auto blob = make_blob_shape(grid);
    for (std::size_t n = 0; n < centres.size(); n += 7) {
        const DVec3& c = centres[n];
        // Along z through the column of three: six crossings, the pair of
        // this sphere among them.
        const auto along_z = sorted_crossings(*blob, {c.x, c.y, -5.0}, {0, 0, 1});
        ASSERT_EQ(along_z.size(), 6u) << n;
        const double t_in = c.z + 5.0 - r;
        EXPECT_TRUE(std::any_of(along_z.begin(), along_z.end(), [&](double t) { return std::fabs(t - t_in) < 1e-9; }))
            << n;
        // Along x from just before it: it and the rest of its row (a shape
        // keeps its first 16 crossings).
        const auto along_x = sorted_crossings(*blob, {c.x - 1.5, c.y, c.z}, {1, 0, 0});
        const std::size_t rest = std::size_t(12 - int(c.x / 3.0));
        ASSERT_EQ(along_x.size(), std::min<std::size_t>(2 * rest, ShapeCrossings::kCapacity)) << n;
        EXPECT_NEAR(along_x[0], 1.5 - r, 1e-9) << n;
        EXPECT_TRUE(blob->inside(c)) << n;
        EXPECT_FALSE(blob->inside(c + DVec3(1.5, 0.0, 0.0))) << n;
        EXPECT_NEAR(blob->surface(c + DVec3(0.0, r, 0.0), 0).normal.y, 1.0, 1e-9) << n;
    }
}

// Prisms and text skip the curve segments whose boxes a ray or the even-
// odd test's ray cannot meet (planar_spline.h): every point of a segment
// lies in its box, and the even-odd answer is the one without boxes.
TEST(Prism, SegmentBoxesHoldTheCurveAndChangeNoInsideAnswer) {
    std::mt19937 random(9);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (const SplineKind kind : {SplineKind::Bezier, SplineKind::Cubic, SplineKind::Quadratic, SplineKind::Linear}) {
        // A star-like loop of random radii about the origin.
        std::vector<glm::dvec2> points;
        const int count = kind == SplineKind::Bezier ? 4 * 9 : 14;
        for (int i = 0; i < count; ++i) {
            const double angle = 2.0 * kPiD * i / count, radius = 0.4 + unit(random);
            points.push_back(radius * glm::dvec2(std::cos(angle), std::sin(angle)));
        }
        if (kind == SplineKind::Bezier) {
            for (int i = 3; i < count; i += 4) points[std::size_t(i)] = points[std::size_t((i + 1) % count)];
        } else {
            // Closed: the first point again (and the spline's control points around it).
            const std::size_t extra = kind == SplineKind::Linear ? 1 : kind == SplineKind::Quadratic ? 2 : 3;
            for (std::size_t i = 0; i < extra; ++i) points.push_back(points[i]);
        }
        const std::vector<SplineSegment> segments = spline_segments(kind, points);
        ASSERT_FALSE(segments.empty());
        const std::vector<SegmentBox> boxes = segment_boxes(segments);
        ASSERT_EQ(boxes.size(), segments.size());
        for (std::size_t k = 0; k < segments.size(); ++k)
            for (int i = 0; i <= 200; ++i) {
                const glm::dvec2 p = segments[k].at(i / 200.0);
                ASSERT_TRUE(p.x >= boxes[k].lower.x && p.x <= boxes[k].upper.x && p.y >= boxes[k].lower.y &&
                            p.y <= boxes[k].upper.y);
            }
        const std::vector<SegmentBox> everywhere(segments.size(),
                                                 SegmentBox{glm::dvec2(-INFINITY), glm::dvec2(INFINITY)});
        int inside = 0;
        for (int i = 0; i < 5000; ++i) {
            const glm::dvec2 q(3.0 * unit(random) - 1.5, 3.0 * unit(random) - 1.5);
            const bool answer = inside_curves(segments, everywhere, q);
            ASSERT_EQ(inside_curves(segments, boxes, q), answer) << q.x << ", " << q.y;
            inside += answer;
        }
        EXPECT_GT(inside, 500);
    }
}

// A prism's side whose segment lies on an axis (a glyph's baseline at
// z = 0) is still met by rays from far away, whose shadow on the x-z
// plane rounds by more than that segment's own size would allow.
TEST(Prism, FarRaysStillMeetASideLyingOnAnAxis) {
    PrismParameters glyph;
    glyph.points = {{-1, 0}, {1, 0}, {1, 1}, {-1, 1}, {-1, 0}};
    glyph.height1 = 0.0;
    glyph.height2 = 0.2;
    const auto prism = make_prism_shape(glyph);
    ASSERT_TRUE(prism);
    std::mt19937 random(13);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int k = 0; k < 4000; ++k) {
        const DVec3 target(
            k % 3 ? unit(random) : (k % 2 ? 1.0 : -1.0) * (1.0 - 1e-6 * (0.01 + std::fabs(unit(random)))),
            0.1 + 0.09 * unit(random), 0.0);
        const double distance = k % 4 < 2 ? 1e5 : 1e6;
        const DVec3 from = target + distance * glm::normalize(DVec3(unit(random), 0.3 * unit(random), -1.0));
        const std::vector<double> t = sorted_crossings(*prism, from, target - from);
        ASSERT_EQ(t.size(), 2u) << "ray " << k;
        EXPECT_NEAR(t[0], 1.0, 1e-6) << "ray " << k;  // the baseline's face first
    }
}

TEST(Prism, LinearAndConicSweeps) {
    PrismParameters square;
    square.points = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}, {-1, -1}};
    square.height1 = 0.0;
    square.height2 = 2.0;
    const auto prism = make_prism_shape(square);
    ASSERT_TRUE(prism);
    EXPECT_EQ(sorted_crossings(*prism, {-5, 1, 0.2}, {1, 0, 0}), (std::vector<double>{4.0, 6.0}));
    EXPECT_EQ(sorted_crossings(*prism, {0.3, 5, 0.1}, {0, -1, 0}), (std::vector<double>{3.0, 5.0}));
    EXPECT_NEAR(prism->surface({-1, 1, 0.2}, 2 + 3).normal.x, -1.0, 1e-9);  // out of the solid
    EXPECT_TRUE(prism->inside({0.5, 1, 0.5}));
    EXPECT_FALSE(prism->inside({0.5, 2.5, 0.5}));
    // Conic: the square scales with y, a pyramid with its apex at the origin.
    PrismParameters pyramid = square;
    pyramid.conic = true;
    pyramid.height1 = 0.0;
    pyramid.height2 = 1.0;
    const auto cone = make_prism_shape(pyramid);
    auto t = sorted_crossings(*cone, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.5, 1e-9);  // at y = 0.5 the half-width is 0.5
    EXPECT_TRUE(cone->inside({0.2, 0.5, 0.2}));
    EXPECT_FALSE(cone->inside({0.7, 0.5, 0.0}));
    // A Bezier circle-ish loop: the ray through its middle crosses twice.
    PrismParameters bezier;
    bezier.spline = SplineKind::Bezier;
    bezier.points = {{1, 0},  {1, 0.55},   {0.55, 1},   {0, 1},  {0, 1},  {-0.55, 1}, {-1, 0.55}, {-1, 0},
                     {-1, 0}, {-1, -0.55}, {-0.55, -1}, {0, -1}, {0, -1}, {0.55, -1}, {1, -0.55}, {1, 0}};
    const auto round = make_prism_shape(bezier);
    t = sorted_crossings(*round, {-5, 0.5, 0}, {1, 0, 0});
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 4.0, 1e-9);
}

}  // namespace
}  // namespace lancer
