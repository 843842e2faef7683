// Checks of POV-Ray's parametric (parametric.h) on a unit sphere written
// as x = sin v cos u, y = cos v, z = sin v sin u: crossings within a few
// accuracy steps of the true ones, normals along the radius, (u, v) that
// lead back to the point, rays along an axis, misses, a container that cuts
// the surface, precompute finding the same crossings, an accuracy far below
// what doubles resolve, and settings refused.
#include "geometry/parametric.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace lancer {
namespace {

using Op = sg::Function::Op;
using M = sg::Function;

std::shared_ptr<sg::Function> function_of(std::vector<sg::Function::Instruction> code) {
    auto f = std::make_shared<sg::Function>();
    f->parameters = {"x", "y", "z"};
    f->code = std::move(code);
    f->stack_size = 2;
    return f;
}

ParametricParameters unit_sphere() {
    ParametricParameters p;
    p.functions[0] =
        function_of({{Op::Parameter, 1}, {Op::Math1, M::Sin}, {Op::Parameter, 0}, {Op::Math1, M::Cos}, {Op::Multiply}});
    p.functions[1] = function_of({{Op::Parameter, 1}, {Op::Math1, M::Cos}});
    p.functions[2] =
        function_of({{Op::Parameter, 1}, {Op::Math1, M::Sin}, {Op::Parameter, 0}, {Op::Math1, M::Sin}, {Op::Multiply}});
    p.uv_min = {0.0, 0.0};
    p.uv_max = {2.0 * M_PI, M_PI};
    p.container.sphere = true;
    p.container.sphere_radius = 1.05;
    p.max_gradient = 1.2;
    p.accuracy = 0.001;
    return p;
}

// The nearest crossing of the unit sphere for t > 0, or -1.
double sphere_crossing(const DVec3& o, const DVec3& d) {
    const double a = glm::dot(d, d), b = glm::dot(o, d), c = glm::dot(o, o) - 1.0;
    const double disc = b * b - a * c;
    if (disc < 0.0) return -1.0;
    const double near = (-b - std::sqrt(disc)) / a;
    return near > 0.0 ? near : (-b + std::sqrt(disc)) / a;
}

// POV-Ray's crossing is where the ray enters the last coordinate's slab
// (z's) of a piece smaller than `accuracy` in (u, v): early by up to the
// piece's size over |d.z|, so rays here keep |d.z| > 0.8.
TEST(Parametric, CrossingsNormalsAndUvOfASphere) {
    const auto shape = make_parametric_shape(unit_sphere());
    ASSERT_TRUE(shape);
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
        const DVec3 from(1.5 * unit(random), 1.5 * unit(random), -4.0);
        const DVec3 target = 0.5 * DVec3(unit(random), unit(random), unit(random));
        const DVec3 d = glm::normalize(target - from);
        ShapeCrossing hit;
        ASSERT_TRUE(shape->nearest(from, d, 1e-6, 100.0, hit)) << "ray " << i;
        const double truth = sphere_crossing(from, d);
        EXPECT_NEAR(hit.t, truth, 0.006) << "ray " << i;
        const DVec3 p = from + hit.t * d;
        const SurfaceGeometry g = shape->surface(p, hit.face);
        EXPECT_GT(std::fabs(glm::dot(g.normal, glm::normalize(p))), 0.995) << "ray " << i;
        const double u = g.uv.x, v = g.uv.y;
        const DVec3 at_uv(std::sin(v) * std::cos(u), std::cos(v), std::sin(v) * std::sin(u));
        EXPECT_LT(glm::length(at_uv - p), 0.01) << "ray " << i;
    }
}

TEST(Parametric, RaysAlongAnAxisAndMisses) {
    const auto shape = make_parametric_shape(unit_sphere());
    ASSERT_TRUE(shape);
    ShapeCrossing hit;
    const DVec3 along_z(0.3, 0.2, -5.0);
    ASSERT_TRUE(shape->nearest(along_z, DVec3(0, 0, 1), 1e-6, 100.0, hit));
    EXPECT_NEAR(hit.t, 5.0 - std::sqrt(1.0 - 0.13), 0.006);
    ASSERT_TRUE(shape->nearest(DVec3(0, -7, 0), DVec3(0, 1, 0), 1e-6, 100.0, hit));
    EXPECT_NEAR(hit.t, 6.0, 0.006);
    EXPECT_FALSE(shape->nearest(DVec3(1.2, 0, -5), DVec3(0, 0, 1), 1e-6, 100.0, hit));
    EXPECT_FALSE(shape->nearest(DVec3(0, 0, -5), DVec3(0, 0, -1), 1e-6, 100.0, hit));  // facing away
    EXPECT_FALSE(shape->nearest(along_z, DVec3(0, 0, 1), 1e-6, 4.0, hit));             // beyond t_max
    // A patch: no inside, in or out of the sphere.
    EXPECT_FALSE(shape->inside(DVec3(0.0)));
    EXPECT_FALSE(shape->solid());
}

// Only what lies inside the container is drawn: with the box's top at
// y = 0.5 a ray down the axis meets the sphere's bottom, not its top.
TEST(Parametric, TheContainerCutsTheSurface) {
    ParametricParameters p = unit_sphere();
    p.container.sphere = false;
    p.container.box_lower = DVec3(-1.1, -1.1, -1.1);
    p.container.box_upper = DVec3(1.1, 0.5, 1.1);
    const auto shape = make_parametric_shape(p);
    ASSERT_TRUE(shape);
    ShapeCrossing hit;
    ASSERT_TRUE(shape->nearest(DVec3(0, 5, 0), DVec3(0, -1, 0), 1e-6, 100.0, hit));
    EXPECT_NEAR(hit.t, 6.0, 0.006);
    // Beside the sphere but inside the box: nothing.
    EXPECT_FALSE(shape->nearest(DVec3(1.05, 0, -5), DVec3(0, 0, 1), 1e-6, 100.0, hit));
    DVec3 lower, upper;
    ASSERT_TRUE(shape->bounds(lower, upper));
    EXPECT_EQ(upper, DVec3(1.1, 0.5, 1.1));
}

// A flat box (fuzz_shapes found it) lets through no surface outside it:
// the ray meets the sphere at x = -1, outside the slab x = 0.5.
TEST(Parametric, AFlatContainerHoldsNoSurfaceOutsideIt) {
    ParametricParameters p = unit_sphere();
    p.container.sphere = false;
    p.container.box_lower = DVec3(0.5, -1.1, -1.1);
    p.container.box_upper = DVec3(0.5, 1.1, 1.1);
    const auto shape = make_parametric_shape(p);
    ASSERT_TRUE(shape);
    ShapeCrossing hit;
    EXPECT_FALSE(shape->nearest(DVec3(-3, 0.1, 0.05), DVec3(1, 0, 0.02), 1e-6, 100.0, hit));
}

TEST(Parametric, PrecomputeFindsTheSameCrossings) {
    ParametricParameters p = unit_sphere();
    const auto plain = make_parametric_shape(p);
    p.precompute_depth = 12;
    p.precompute_axes = 7;
    const auto precomputed = make_parametric_shape(p);
    ASSERT_TRUE(plain && precomputed);
    std::mt19937 random(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (int i = 0; i < 100; ++i) {
        const DVec3 from(unit(random), unit(random), -4.0);
        const DVec3 d = glm::normalize(DVec3(unit(random), unit(random), 0.0) * 0.6 - from);
        ShapeCrossing a, b;
        const bool hit_a = plain->nearest(from, d, 1e-6, 100.0, a);
        const bool hit_b = precomputed->nearest(from, d, 1e-6, 100.0, b);
        ASSERT_EQ(hit_a, hit_b) << "ray " << i;
        if (hit_a) {
            EXPECT_NEAR(a.t, b.t, 0.004) << "ray " << i;
        }
    }
}

// An accuracy no halving reaches: the search stops at its deepest level
// (pieces 2^-15 of the range across) and still finds the surface.
TEST(Parametric, AccuracyBelowWhatDoublesResolveStillEnds) {
    ParametricParameters p = unit_sphere();
    p.accuracy = 1e-300;
    const auto shape = make_parametric_shape(p);
    ASSERT_TRUE(shape);
    ShapeCrossing hit;
    ASSERT_TRUE(shape->nearest(DVec3(0.3, 0.2, -5.0), DVec3(0, 0, 1), 1e-6, 100.0, hit));
    EXPECT_NEAR(hit.t, 5.0 - std::sqrt(1.0 - 0.13), 0.001);
}

TEST(Parametric, UnusableSettingsAreRefused) {
    ParametricParameters p = unit_sphere();
    p.functions[1] = nullptr;
    EXPECT_FALSE(make_parametric_shape(p));
    p = unit_sphere();
    p.accuracy = 0.0;
    EXPECT_FALSE(make_parametric_shape(p));
    p = unit_sphere();
    p.max_gradient = NAN;
    EXPECT_FALSE(make_parametric_shape(p));
    p = unit_sphere();
    p.uv_max.x = INFINITY;
    EXPECT_FALSE(make_parametric_shape(p));
    p = unit_sphere();
    p.precompute_axes = 1;
    p.precompute_depth = 21;
    EXPECT_FALSE(make_parametric_shape(p));
}

}  // namespace
}  // namespace lancer
