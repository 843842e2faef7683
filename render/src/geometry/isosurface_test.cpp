// Checks of POV-Ray's isosurface (isosurface.h) against surfaces with known
// crossings: spheres and planes written as functions, in box and sphere
// containers, closed and open, with one or all crossings; rays from on the
// surface; far origins; functions that are NaN or never cross; and POV's
// max_gradient advice.
#include "geometry/isosurface.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace lancer {
namespace {

using Op = sg::Function::Op;

sg::Function::Instruction op(Op code, int index = 0) {
    sg::Function::Instruction in;
    in.op = code;
    in.index = index;
    return in;
}

// scale * (x^2 + y^2 + z^2 - r^2): a sphere of radius r about the origin.
std::shared_ptr<sg::Function> sphere_function(double r, double scale = 1.0) {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    f->constants = {r * r, scale};
    f->code = {op(Op::Parameter, 0), op(Op::Parameter, 0), op(Op::Multiply), op(Op::Parameter, 1),
               op(Op::Parameter, 1), op(Op::Multiply),     op(Op::Add),      op(Op::Parameter, 2),
               op(Op::Parameter, 2), op(Op::Multiply),     op(Op::Add),      op(Op::Constant, 0),
               op(Op::Subtract),     op(Op::Constant, 1),  op(Op::Multiply)};
    f->stack_size = 3;
    return f;
}

// y - h: the solid is the half-space below y = h.
std::shared_ptr<sg::Function> below_function(double h) {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    f->constants = {h};
    f->code = {op(Op::Parameter, 1), op(Op::Constant, 0), op(Op::Subtract)};
    f->stack_size = 2;
    return f;
}

// 0 / 0 everywhere.
std::shared_ptr<sg::Function> nan_function() {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    f->constants = {0.0};
    f->code = {op(Op::Constant, 0), op(Op::Constant, 0), op(Op::Divide)};
    f->stack_size = 2;
    return f;
}

IsosurfaceParameters in_box(std::shared_ptr<sg::Function> f, double half = 2.0) {
    IsosurfaceParameters p;
    p.function = std::move(f);
    p.container.box_lower = DVec3(-half);
    p.container.box_upper = DVec3(half);
    p.max_gradient = 4.0;
    return p;
}

std::vector<ShapeCrossing> crossings_of(const Shape& shape, const DVec3& o, const DVec3& d, double t_min = 0.0,
                                        double t_max = 1e30) {
    ShapeCrossings all;
    shape.crossings(o, d, t_min, t_max, all);
    std::vector<ShapeCrossing> hits(all.items, all.items + all.count);
    std::sort(hits.begin(), hits.end(), [](const ShapeCrossing& a, const ShapeCrossing& b) { return a.t < b.t; });
    return hits;
}

TEST(Isosurface, FindsTheFirstCrossingWithinAccuracyBeyondIt) {
    // POV's root is the far end of the first interval shorter than
    // `accuracy` where the function is below zero: just inside the solid.
    auto p = in_box(sphere_function(1.0));
    p.accuracy = 1e-4;
    const auto shape = make_isosurface_shape(p);
    ASSERT_TRUE(shape);
    const auto hits = crossings_of(*shape, DVec3(0.3, 0.2, -5.0), DVec3(0.0, 0.0, 1.0));
    ASSERT_EQ(hits.size(), 1u);
    const double surface = 5.0 - std::sqrt(1.0 - 0.3 * 0.3 - 0.2 * 0.2);
    EXPECT_GE(hits[0].t, surface);
    EXPECT_LT(hits[0].t, surface + p.accuracy);
    // POV's normal: forward differences one accuracy step long.
    const DVec3 point(0.3, 0.2, -5.0 + hits[0].t);
    const SurfaceGeometry g = shape->surface(point, hits[0].face);
    EXPECT_NEAR(glm::length(g.normal), 1.0, 1e-12);
    EXPECT_GT(glm::dot(g.normal, glm::normalize(point)), 1.0 - 1e-3);
}

TEST(Isosurface, AllIntersectionsFindsEntryAndExit) {
    auto p = in_box(sphere_function(1.0));
    p.max_trace = 10;
    const auto shape = make_isosurface_shape(p);
    const auto hits = crossings_of(*shape, DVec3(0.0, 0.0, -5.0), DVec3(0.0, 0.0, 1.0));
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 4.0, p.accuracy);
    EXPECT_NEAR(hits[1].t, 6.0, p.accuracy);
}

TEST(Isosurface, UnitLengthOfTheDirectionDoesNotMatter) {
    // A scaled object hands the shape a direction of another length: the
    // search runs in the ray's own parameter.
    auto p = in_box(sphere_function(1.0));
    const auto shape = make_isosurface_shape(p);
    const auto hits = crossings_of(*shape, DVec3(0.0, 0.0, -5.0), DVec3(0.0, 0.0, 0.25));
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t * 0.25, 4.0, 4.0 * p.accuracy);
}

TEST(Isosurface, ClosedContainerWallsCutTheSolid) {
    // Below y = 0 inside the box [-1, 1]^3: a ray at y = -0.5 enters the
    // solid through the box's -x side.
    auto p = in_box(below_function(0.0), 1.0);
    const auto shape = make_isosurface_shape(p);
    const auto hits = crossings_of(*shape, DVec3(-5.0, -0.5, 0.0), DVec3(1.0, 0.0, 0.0));
    ASSERT_FALSE(hits.empty());
    EXPECT_DOUBLE_EQ(hits[0].t, 4.0);
    const SurfaceGeometry wall = shape->surface(DVec3(-1.0, -0.5, 0.0), hits[0].face);
    EXPECT_EQ(wall.normal, DVec3(-1.0, 0.0, 0.0));
    // From above, the function's own surface at y = 0.
    const auto down = crossings_of(*shape, DVec3(0.2, 5.0, 0.1), DVec3(0.0, -1.0, 0.0));
    ASSERT_EQ(down.size(), 1u);
    EXPECT_NEAR(down[0].t, 5.0, p.accuracy);
    EXPECT_GT(shape->surface(DVec3(0.2, 0.0, 0.1), down[0].face).normal.y, 0.999);
}

TEST(Isosurface, OpenContainerHasNoWalls) {
    auto p = in_box(below_function(0.0), 1.0);
    p.open = true;
    const auto shape = make_isosurface_shape(p);
    EXPECT_TRUE(crossings_of(*shape, DVec3(-5.0, -0.5, 0.0), DVec3(1.0, 0.0, 0.0)).empty());
    const auto down = crossings_of(*shape, DVec3(0.2, 5.0, 0.1), DVec3(0.0, -1.0, 0.0));
    ASSERT_EQ(down.size(), 1u);
    EXPECT_NEAR(down[0].t, 5.0, p.accuracy);
    // From below, inside the solid, an open isosurface is crossed going out.
    const auto up = crossings_of(*shape, DVec3(0.2, -5.0, 0.1), DVec3(0.0, 1.0, 0.0));
    ASSERT_EQ(up.size(), 1u);
    EXPECT_NEAR(up[0].t, 5.0, p.accuracy);
}

TEST(Isosurface, SphereContainer) {
    IsosurfaceParameters p;
    p.function = below_function(0.0);
    p.container.sphere = true;
    p.container.sphere_center = DVec3(0.0, 0.0, 0.0);
    p.container.sphere_radius = 1.0;
    const auto shape = make_isosurface_shape(p);
    // A ray at y = -0.5 meets the container's lower cap first.
    const auto hits = crossings_of(*shape, DVec3(-5.0, -0.5, 0.0), DVec3(1.0, 0.0, 0.0));
    ASSERT_FALSE(hits.empty());
    const double x = -std::sqrt(1.0 - 0.25);
    EXPECT_NEAR(hits[0].t, 5.0 + x, 1e-12);
    const SurfaceGeometry wall = shape->surface(DVec3(x, -0.5, 0.0), hits[0].face);
    EXPECT_NEAR(wall.normal.x, x, 1e-12);
    EXPECT_NEAR(wall.normal.y, -0.5, 1e-12);
    DVec3 lower, upper;
    ASSERT_TRUE(shape->bounds(lower, upper));
    EXPECT_EQ(lower, DVec3(-1.0));
    EXPECT_EQ(upper, DVec3(1.0));
}

TEST(Isosurface, ThresholdMovesTheSurface) {
    auto p = in_box(sphere_function(1.0));
    p.threshold = 0.44;  // x^2 + y^2 + z^2 = 1.44
    const auto shape = make_isosurface_shape(p);
    const auto hits = crossings_of(*shape, DVec3(0.0, 0.0, -5.0), DVec3(0.0, 0.0, 1.0));
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 5.0 - 1.2, p.accuracy);
}

TEST(Isosurface, InsideIsBelowTheThresholdAndWithinTheContainer) {
    const auto shape = make_isosurface_shape(in_box(below_function(0.0), 1.0));
    EXPECT_TRUE(shape->inside(DVec3(0.0, -0.5, 0.0)));
    EXPECT_FALSE(shape->inside(DVec3(0.0, 0.5, 0.0)));
    EXPECT_FALSE(shape->inside(DVec3(0.0, -1.5, 0.0)));  // below, but outside the box
}

TEST(Isosurface, RaysLeavingTheSurfaceDoNotMeetItAgain) {
    auto p = in_box(sphere_function(1.0));
    const auto shape = make_isosurface_shape(p);
    // A hit point from the search lies just inside: a shadow ray from there
    // heading out finds nothing; one heading in finds the far side.
    const DVec3 on_surface(0.0, 0.0, -1.0 + 0.5 * p.accuracy);
    EXPECT_TRUE(crossings_of(*shape, on_surface, DVec3(0.0, 0.0, -1.0)).empty());
    EXPECT_TRUE(crossings_of(*shape, on_surface, glm::normalize(DVec3(1.0, 0.0, -1.0))).empty());
    const auto through = crossings_of(*shape, on_surface, DVec3(0.0, 0.0, 1.0));
    ASSERT_EQ(through.size(), 1u);
    EXPECT_NEAR(through[0].t, 2.0, 2.0 * p.accuracy);
}

TEST(Isosurface, FarOriginsKeepTheirAccuracy) {
    auto p = in_box(sphere_function(1.0));
    const auto shape = make_isosurface_shape(p);
    const auto hits = crossings_of(*shape, DVec3(0.0, 0.0, -1e5), DVec3(0.0, 0.0, 1.0));
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 1e5 - 1.0, 2.0 * p.accuracy);
}

TEST(Isosurface, GrazingRaysFindTheSurfaceOrMissCleanly) {
    // Tangent to the unit sphere at z = 0: a crossing, if any, lies on it.
    auto p = in_box(sphere_function(1.0));
    p.max_trace = 10;
    const auto shape = make_isosurface_shape(p);
    for (double y : {0.999, 0.9999, 1.0, 1.0001}) {
        for (const ShapeCrossing& hit : crossings_of(*shape, DVec3(-3.0, y, 0.0), DVec3(1.0, 0.0, 0.0))) {
            ASSERT_TRUE(std::isfinite(hit.t));
            const DVec3 point(-3.0 + hit.t, y, 0.0);
            EXPECT_LT(std::fabs(glm::length(point) - 1.0), 0.01) << y;
        }
    }
}

TEST(Isosurface, NotANumberOrNoCrossingEndsTheSearch) {
    const auto nan_shape = make_isosurface_shape(in_box(nan_function()));
    EXPECT_TRUE(crossings_of(*nan_shape, DVec3(0.0, 0.0, -5.0), DVec3(0.0, 0.0, 1.0)).empty());
    // A function that never falls below zero, with a max_gradient that
    // forbids no interval: the search still ends.
    auto never = in_box(sphere_function(1.0), 1e4);
    never.threshold = -1.0;  // f = x^2 + y^2 + z^2, at least 0.5 on this ray
    never.max_gradient = 1e12;
    never.open = true;
    const auto shape = make_isosurface_shape(never);
    EXPECT_TRUE(crossings_of(*shape, DVec3(0.5, 0.5, -2e4), DVec3(0.0, 0.0, 1.0)).empty());
}

TEST(Isosurface, AHugeScaleEndsTheSearchWithinTheStack) {
    // An isosurface scaled by 1e30 hands the shape a direction of length
    // 1e-30: the chord is 4e30 long in the ray's parameter, where doubles
    // are 1e14 apart, so no interval is ever shorter than `accuracy`. The
    // search halved such an interval into itself until the stack overflowed.
    auto p = in_box(sphere_function(1.0));
    const auto shape = make_isosurface_shape(p);
    for (double scale : {1e20, 1e30}) {
        const auto hits = crossings_of(*shape, DVec3(0.1, 0.2, -5.0), DVec3(0.0, 0.0, 1.0 / scale), 0.0, HUGE_VAL);
        ASSERT_EQ(hits.size(), 1u) << scale;
        EXPECT_NEAR(hits[0].t / scale, 5.0 - std::sqrt(1.0 - 0.05), 1e-3) << scale;
    }
    // Past what a direction's squared length can hold, the search only
    // has to end.
    crossings_of(*shape, DVec3(0.1, 0.2, -5.0), DVec3(0.0, 0.0, 1e-300), 0.0, HUGE_VAL);
}

// x - 0.5 through a spline function of x, counting its evaluations.
std::shared_ptr<sg::Function> counted_plane_function(std::shared_ptr<long> evaluations) {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    f->spline = [evaluations](double x) {
        ++*evaluations;
        return std::array<double, 5>{x - 0.5, 0.0, 0.0, 0.0, 0.0};
    };
    f->spline_terms = 1;
    return f;
}

TEST(Isosurface, AnAccuracyFinerThanTheDoublesCostsWhatTheirSpacingCosts) {
    // From a point on the plane x = 0.5, rays leaving it at first stay on
    // it: x + t d.x rounds to 0.5 for t below 1e-16, and there the function
    // is 0 at both ends of every interval. An accuracy of 1e-20 halved that
    // stretch down to 1e-20, about 20,000 evaluations a ray, where the
    // doubles hold no more than an accuracy of 1e-16 finds.
    auto cost = [](double accuracy, const DVec3& d, size_t& hits) {
        auto evaluations = std::make_shared<long>(0);
        auto p = in_box(counted_plane_function(evaluations));
        p.accuracy = accuracy;
        p.max_trace = 4;
        const auto shape = make_isosurface_shape(p);
        hits = crossings_of(*shape, DVec3(0.5, d.y == 1e-17 ? 0.0 : 0.1, 0.2), d).size();
        return *evaluations;
    };
    // The last has a trace of y, as a turned direction has, from y = 0:
    // that axis does not tell points apart.
    for (const DVec3 d : {DVec3(1.0, 0.3, 0.1), DVec3(1e-3, 1.0, 0.0), DVec3(-1.0, 0.2, 0.0), DVec3(1.0, 1e-17, 0.1)}) {
        size_t fine_hits = 0, coarse_hits = 0;
        const long fine = cost(1e-20, d, fine_hits), coarse = cost(1e-16, d, coarse_hits);
        EXPECT_LE(fine, 2 * coarse) << d.x;
        EXPECT_EQ(fine_hits, coarse_hits) << d.x;
    }
    // Still found where it is, from off the surface.
    auto evaluations = std::make_shared<long>(0);
    auto p = in_box(counted_plane_function(evaluations));
    p.accuracy = 1e-20;
    const auto shape = make_isosurface_shape(p);
    const auto found = crossings_of(*shape, DVec3(-1.0, 0.1, 0.2), DVec3(1.0, 0.0, 0.0));
    ASSERT_EQ(found.size(), 1u);
    EXPECT_NEAR(found[0].t, 1.5, 1e-14);
}

TEST(Isosurface, AFarCoordinateOffTheRaysAxisCostsNoDigits) {
    // The ray moves along y from x = 1e15: the doubles of x are 0.125
    // apart there, but only y changes along the ray, and y keeps its digits.
    auto p = in_box(below_function(0.3), 2e15);
    p.accuracy = 1e-6;
    p.open = true;  // no wall where the ray leaves the box
    const auto shape = make_isosurface_shape(p);
    for (double x : {1e10, 1e13, 1e15}) {
        const auto hits = crossings_of(*shape, DVec3(x, 2.0, 0.1), DVec3(0.0, -1.0, 0.0));
        ASSERT_EQ(hits.size(), 1u) << x;
        EXPECT_NEAR(hits[0].t, 1.7, 2.0 * p.accuracy) << x;
    }
}

TEST(Isosurface, RefusesWhatCannotBeSearched) {
    IsosurfaceParameters p;
    EXPECT_FALSE(make_isosurface_shape(p));  // no function
    p.function = sphere_function(1.0);
    p.accuracy = 0.0;
    EXPECT_FALSE(make_isosurface_shape(p));
    p.accuracy = 1e-3;
    p.container.box_upper = DVec3(INFINITY);
    EXPECT_FALSE(make_isosurface_shape(p));
}

TEST(Isosurface, RecordsTheSteepestSlopeForPovsAdvice) {
    // r^2 - 1 is no steeper than 2 r <= 7 in the box; the search meets
    // slopes above 1 on its way to the surface.
    auto p = in_box(sphere_function(1.0));
    auto record = std::make_shared<IsosurfaceGradientRecord>();
    const auto shape = make_isosurface_shape(p, record);
    ASSERT_EQ(crossings_of(*shape, DVec3(0.1, 0.0, -5.0), DVec3(0.0, 0.0, 1.0)).size(), 1u);
    EXPECT_GT(record->steepest(), 1.0);
    EXPECT_LT(record->steepest(), 7.0);
    p.max_gradient = 0.5;
    const auto advice = isosurface_gradient_advice(p, *record);
    ASSERT_TRUE(advice);
    EXPECT_NE(advice->find("holes"), std::string::npos);

    // 10 (r^2 - 1) through the centre: f is 30 at both ends of the chord,
    // so with max_gradient 4 no interval can hold a root and POV-Ray, like
    // lancer, shows nothing there (and measures no slope).
    auto steep = in_box(sphere_function(1.0, 10.0));
    const auto steep_shape = make_isosurface_shape(steep);
    EXPECT_TRUE(crossings_of(*steep_shape, DVec3(0.0, 0.0, -5.0), DVec3(0.0, 0.0, 1.0)).empty());
    steep.max_gradient = 25.0;
    EXPECT_EQ(crossings_of(*make_isosurface_shape(steep), DVec3(0.0, 0.0, -5.0), DVec3(0.0, 0.0, 1.0)).size(), 1u);

    IsosurfaceGradientRecord gentle;
    gentle.record(1.0);
    p.max_gradient = 50.0;
    const auto faster = isosurface_gradient_advice(p, gentle);
    ASSERT_TRUE(faster);
    EXPECT_NE(faster->find("faster"), std::string::npos);
    p.max_gradient = 1.05;
    EXPECT_FALSE(isosurface_gradient_advice(p, gentle));
    p.max_gradient = 0.5;
    p.evaluate = true;  // evaluate chooses max_gradient itself
    EXPECT_FALSE(isosurface_gradient_advice(p, gentle));
}

}  // namespace
}  // namespace lancer
