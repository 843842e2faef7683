// Closed-form checks of POV's bicubic_patch (bicubic_patch.h): the flat
// pieces POV's subdivision makes, their normals and (u,v), flatness,
// scales, grazing rays and rays from the surface.
#include "geometry/bicubic_patch.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

namespace lancer {
namespace {

// Control points over [-1, 1]^2 evenly spaced in x (row i) and y (column
// j), so x = 2u - 1 and y = 2v - 1 exactly; z as given.
BicubicPatchParameters patch_with_heights(const double (&z)[4][4], int u_steps, int v_steps) {
    BicubicPatchParameters patch;
    patch.type = 1;
    patch.u_steps = u_steps;
    patch.v_steps = v_steps;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j)
            patch.points[4 * i + j] = DVec3(-1.0 + 2.0 * i / 3.0, -1.0 + 2.0 * j / 3.0, z[i][j]);
    return patch;
}

BicubicPatchParameters flat_patch(int steps = 0) {
    const double z[4][4] = {};
    return patch_with_heights(z, steps, steps);
}

// The inner four control points raised by h: a dome over a flat square.
BicubicPatchParameters dome_patch(double h, int steps) {
    const double z[4][4] = {{0, 0, 0, 0}, {0, h, h, 0}, {0, h, h, 0}, {0, 0, 0, 0}};
    return patch_with_heights(z, steps, steps);
}

double bernstein(int i, double s) {
    const double c[4] = {1, 3, 3, 1};
    return c[i] * std::pow(s, i) * std::pow(1.0 - s, 3 - i);
}

double patch_height(const BicubicPatchParameters& patch, double u, double v) {
    double z = 0.0;
    for (int i = 0; i < 4; ++i)
        for (int j = 0; j < 4; ++j) z += bernstein(i, u) * bernstein(j, v) * patch.points[4 * i + j].z;
    return z;
}

std::vector<ShapeCrossing> all_crossings(const Shape& shape, const DVec3& o, const DVec3& d, double t_min = 0.0,
                                         double t_max = INFINITY) {
    ShapeCrossings found;
    shape.crossings(o, d, t_min, t_max, found);
    std::vector<ShapeCrossing> items(found.items, found.items + found.count);
    std::sort(items.begin(), items.end(), [](const auto& a, const auto& b) { return a.t < b.t; });
    return items;
}

TEST(BicubicPatch, RefusesWhatPovRefuses) {
    BicubicPatchParameters patch = flat_patch();
    patch.type = -1;
    EXPECT_EQ(make_bicubic_patch_shape(patch), nullptr);  // "Undefined bicubic patch type."
    patch.type = 3;                                       // POV: "no longer supported. Using type 1."
    EXPECT_NE(make_bicubic_patch_shape(patch), nullptr);
    patch.type = 0;
    patch.points[5].y = NAN;
    EXPECT_EQ(make_bicubic_patch_shape(patch), nullptr);
}

TEST(BicubicPatch, FlatPatchHitNormalAndUv) {
    const auto shape = make_bicubic_patch_shape(flat_patch(2));
    ASSERT_NE(shape, nullptr);
    const DVec3 o(0.3, -0.6, 5.0), d(0.0, 0.0, -2.0);
    const auto hits = all_crossings(*shape, o, d);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 2.5, 1e-14);
    const SurfaceGeometry g = shape->surface(o + hits[0].t * d, hits[0].face);
    EXPECT_NEAR(g.point.z, 0.0, 1e-15);
    // dP/du x dP/dv = x x y: +z.
    EXPECT_NEAR(g.normal.z, 1.0, 1e-12);
    // POV's texture (u, v) is the patch's (v, u): ((y + 1) / 2, (x + 1) / 2).
    EXPECT_NEAR(g.uv.x, 0.2, 1e-6);
    EXPECT_NEAR(g.uv.y, 0.65, 1e-6);
    EXPECT_FALSE(shape->inside(DVec3(0.3, -0.6, 0.0)));
    EXPECT_FALSE(shape->inside(DVec3(0.3, -0.6, -0.1)));
    // Outside the square: no hit.
    EXPECT_TRUE(all_crossings(*shape, DVec3(1.01, 0.0, 5.0), d).empty());
}

TEST(BicubicPatch, UvVectorsMapBilinearly) {
    BicubicPatchParameters patch = flat_patch();
    // Texture corners for the patch corners (u,v) = (0,0), (0,1), (1,1), (1,0).
    patch.uv_corners = {glm::dvec2(2, 3), glm::dvec2(4, 3), glm::dvec2(4, 7), glm::dvec2(2, 7)};
    const auto shape = make_bicubic_patch_shape(patch);
    const DVec3 o(0.5, -0.5, 1.0), d(0, 0, -1);  // u = 0.75, v = 0.25
    const auto hits = all_crossings(*shape, o, d);
    ASSERT_EQ(hits.size(), 1u);
    const SurfaceGeometry g = shape->surface(o + hits[0].t * d, hits[0].face);
    EXPECT_NEAR(g.uv.x, 2.0 + 2.0 * 0.25, 1e-5);
    EXPECT_NEAR(g.uv.y, 3.0 + 4.0 * 0.75, 1e-5);
}

TEST(BicubicPatch, StepsZeroIsTwoFlatTriangles) {
    // POV's default: no halving, so the dome shows as the plane of its corners.
    const auto shape = make_bicubic_patch_shape(dome_patch(1.0, 0));
    const DVec3 o(0.1, 0.2, 3.0), d(0, 0, -1);
    const auto hits = all_crossings(*shape, o, d);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 3.0, 1e-14);
    EXPECT_LE(hits[0].face, 1);
    // The shading normal is still the patch's, interpolated: the corner
    // normals are all +z here, so +z.
    const SurfaceGeometry g = shape->surface(o + hits[0].t * d, hits[0].face);
    EXPECT_NEAR(g.normal.z, 1.0, 1e-12);
}

TEST(BicubicPatch, StepsPutPieceCornersOnTheSurface) {
    const double h = 0.8;
    for (int steps : {1, 3}) {
        const BicubicPatchParameters patch = dome_patch(h, steps);
        const auto shape = make_bicubic_patch_shape(patch);
        // (u,v) = (1/2, 1/2) is a corner of the pieces: P(1/2,1/2) = 9/16 h.
        const auto hits = all_crossings(*shape, DVec3(0.0, 0.0, 3.0), DVec3(0, 0, -1));
        ASSERT_EQ(hits.size(), 1u) << steps;  // four pieces meet there: one crossing
        EXPECT_NEAR(3.0 - hits[0].t, 9.0 / 16.0 * h, 1e-13) << steps;
        // Between corners the facet lies below the curved (concave) surface.
        const auto between = all_crossings(*shape, DVec3(0.25, 0.0, 3.0), DVec3(0, 0, -1));
        ASSERT_EQ(between.size(), 1u);
        EXPECT_LT(3.0 - between[0].t, patch_height(patch, 0.625, 0.5) + 1e-12) << steps;
    }
}

TEST(BicubicPatch, UnequalStepsHalveEachDirectionSeparately) {
    // u_steps 2, v_steps 0: four pieces along u, eight triangles.
    const auto shape =
        make_bicubic_patch_shape(patch_with_heights({{0, 0, 0, 0}, {1, 1, 1, 1}, {1, 1, 1, 1}, {0, 0, 0, 0}}, 2, 0));
    int max_face = 0;
    for (double x = -0.95; x < 1.0; x += 0.1)
        for (double y = -0.95; y < 1.0; y += 0.1) {
            const auto hits = all_crossings(*shape, DVec3(x, y, 3.0), DVec3(0, 0, -1));
            ASSERT_EQ(hits.size(), 1u);
            max_face = std::max(max_face, hits[0].face);
            // The arch is along u only, so pieces along u make it exact at u = k/4.
        }
    EXPECT_EQ(max_face, 7);
    const auto at_quarter = all_crossings(*shape, DVec3(-0.5, 0.3, 3.0), DVec3(0, 0, -1));
    ASSERT_EQ(at_quarter.size(), 1u);
    // z(u) = 3 u (1-u) (u + 1 - u) = 3u(1-u) at u = 1/4.
    EXPECT_NEAR(3.0 - at_quarter[0].t, 3.0 * 0.25 * 0.75, 1e-13);
}

TEST(BicubicPatch, NormalIsInterpolatedPatchNormal) {
    // An arch along v at steps 0: the facet is flat (z = 0), the corner
    // normals lean out along y: dP/du x dP/dv at (0,0) is (2,0,0) x (0,2,3h).
    const double h = 0.5;
    const auto shape =
        make_bicubic_patch_shape(patch_with_heights({{0, h, h, 0}, {0, h, h, 0}, {0, h, h, 0}, {0, h, h, 0}}, 0, 0));
    const DVec3 o(-1.0 + 1e-9, -1.0 + 1e-9, 1.0), d(0, 0, -1);  // at the corner (0,0)
    const auto hits = all_crossings(*shape, o, d);
    ASSERT_EQ(hits.size(), 1u);
    const SurfaceGeometry corner = shape->surface(o + hits[0].t * d, hits[0].face);
    const DVec3 expected = glm::normalize(glm::cross(DVec3(2, 0, 0), DVec3(0, 2, 3 * h)));
    EXPECT_NEAR(glm::dot(corner.normal, expected), 1.0, 1e-8);
    // Midway along u on the edge v = 1/2 it is +z: the arch's symmetric normals average.
    const auto middle_hits = all_crossings(*shape, DVec3(0.0, 0.0, 1.0), d);
    ASSERT_EQ(middle_hits.size(), 1u);
    const SurfaceGeometry middle = shape->surface(DVec3(0, 0, 1.0 - middle_hits[0].t), middle_hits[0].face);
    EXPECT_NEAR(middle.normal.z, 1.0, 1e-12);
    EXPECT_NEAR(glm::length(middle.normal), 1.0, 1e-12);
}

TEST(BicubicPatch, CollapsedEdgeGivesPovsFallbackNormal) {
    // Row i = 0 collapsed to one point: at u = 0 dP/dv vanishes, POV takes +x
    // there (its world +x; here a rotation about z maps object +y to world +x).
    BicubicPatchParameters patch = flat_patch();
    for (int j = 0; j < 4; ++j) patch.points[j] = DVec3(-1, 0, 0);
    patch.u_steps = patch.v_steps = 1;
    const auto plain = make_bicubic_patch_shape(patch);
    patch.world_from_object =
        DMat4(glm::dvec4(0, -1, 0, 0), glm::dvec4(1, 0, 0, 0), glm::dvec4(0, 0, 1, 0), glm::dvec4(0, 0, 0, 1));
    const auto rotated = make_bicubic_patch_shape(patch);
    const DVec3 o(-0.9, 0.0, 1.0), d(0, 0, -1);  // close to the collapsed corner
    for (const auto* shape : {plain.get(), rotated.get()}) {
        const auto hits = all_crossings(*shape, o, d);
        ASSERT_EQ(hits.size(), 1u);
        const SurfaceGeometry g = shape->surface(o + hits[0].t * d, hits[0].face);
        EXPECT_NEAR(glm::length(g.normal), 1.0, 1e-12);
        EXPECT_TRUE(std::isfinite(g.uv.x) && std::isfinite(g.uv.y));
        // Leaning towards the fallback: x for the plain, y for the rotated one.
        if (shape == plain.get())
            EXPECT_GT(g.normal.x, 0.3);
        else
            EXPECT_GT(g.normal.y, 0.3);
    }
}

TEST(BicubicPatch, FlatnessStopsSubdivisionInWorldUnits) {
    // Control points 0.4 off the corner plane: flat enough for 0.5, so one
    // piece, unless the object is scaled by 2 before POV measures it.
    BicubicPatchParameters patch = dome_patch(0.4, 4);
    patch.flatness = 0.5;
    const auto flat_enough = make_bicubic_patch_shape(patch);
    auto hits = all_crossings(*flat_enough, DVec3(0, 0, 3), DVec3(0, 0, -1));
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 3.0, 1e-14);
    EXPECT_LE(hits[0].face, 1);
    patch.world_from_object = DMat4(2.0);
    patch.world_from_object[3][3] = 1.0;
    const auto subdivided = make_bicubic_patch_shape(patch);
    hits = all_crossings(*subdivided, DVec3(0, 0, 3), DVec3(0, 0, -1));
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(3.0 - hits[0].t, 9.0 / 16.0 * 0.4, 1e-13);
    // Flatness 0 never stops early, even for a plane.
    const auto plane = make_bicubic_patch_shape(flat_patch(2));
    int max_face = 0;
    for (double x = -0.9; x < 1.0; x += 0.2)
        for (double y = -0.9; y < 1.0; y += 0.2)
            for (const auto& c : all_crossings(*plane, DVec3(x, y, 1), DVec3(0, 0, -1)))
                max_face = std::max(max_face, c.face);
    EXPECT_EQ(max_face, 31);
}

TEST(BicubicPatch, RayThroughSharedEdgeCrossesOnce) {
    const auto shape = make_bicubic_patch_shape(dome_patch(0.7, 3));
    // Through a piece corner (x = y = 0.5: u = v = 3/4) and along a diagonal.
    for (const DVec3& o : {DVec3(0.5, 0.5, 3), DVec3(0.25, 0.25, 3), DVec3(-0.125, 0.125, 3)}) {
        const auto hits = all_crossings(*shape, o, DVec3(0, 0, -1));
        EXPECT_EQ(hits.size(), 1u) << o.x << " " << o.y;
    }
}

TEST(BicubicPatch, ObliqueRayMeetsArchTwice) {
    // An arch along u (height 1.5 at the top): a horizontal ray along x
    // under the top crosses it going up and coming down.
    const auto shape =
        make_bicubic_patch_shape(patch_with_heights({{0, 0, 0, 0}, {2, 2, 2, 2}, {2, 2, 2, 2}, {0, 0, 0, 0}}, 5, 1));
    const auto hits = all_crossings(*shape, DVec3(-3, 0.1, 1.0), DVec3(1, 0, 0));
    ASSERT_EQ(hits.size(), 2u);
    // z(u) = 6 u (1 - u) = 1 at u = (1 -+ sqrt(1/3)) / 2, x = 2u - 1.
    const double root = std::sqrt(1.0 / 3.0);
    EXPECT_NEAR(hits[0].t - 3.0, -root, 2e-3);
    EXPECT_NEAR(hits[1].t - 3.0, root, 2e-3);
    // Each hit is on its piece's plane to rounding.
    for (const auto& c : hits) {
        const DVec3 p = DVec3(-3, 0.1, 1.0) + c.t * DVec3(1, 0, 0);
        EXPECT_NEAR(glm::length(shape->surface(p, c.face).point - p), 0.0, 1e-14);
    }
}

TEST(BicubicPatch, RaysFromTheSurfaceDoNotFindIt) {
    const auto shape = make_bicubic_patch_shape(dome_patch(1.0, 3));
    std::mt19937 random(7);
    std::uniform_real_distribution<double> unit(-0.95, 0.95);
    for (int k = 0; k < 200; ++k) {
        const DVec3 o(unit(random), unit(random), 4.0), d(0, 0, -1);
        ShapeCrossing hit;
        ASSERT_TRUE(shape->nearest(o, d, 0.0, INFINITY, hit));
        const SurfaceGeometry g = shape->surface(o + hit.t * d, hit.face);
        // Leaving upwards along the normal and down through it: the start point
        // is never found again beyond a tiny t_min.
        const DVec3 up = g.normal, down = -g.normal;
        ASSERT_GT(up.z, 0.0);
        EXPECT_TRUE(all_crossings(*shape, g.point, up, 1e-9).empty());
        EXPECT_TRUE(all_crossings(*shape, g.point, down, 1e-9).empty());
    }
}

TEST(BicubicPatch, GrazingAndEdgeOnRaysAreFinite) {
    const auto flat = make_bicubic_patch_shape(flat_patch(1));
    // In the plane of a flat patch: POV skips pieces the ray runs along.
    EXPECT_TRUE(all_crossings(*flat, DVec3(-3, 0.2, 0.0), DVec3(1, 0, 0)).empty());
    // Nearly in it: one hit, where the plane is.
    const DVec3 o(-0.5, 0.2, 1e-6), d(1, 0, -1e-6);
    const auto hits = all_crossings(*flat, o, d);
    ASSERT_EQ(hits.size(), 1u);
    EXPECT_NEAR(hits[0].t, 1.0, 1e-9);
    // A degenerate patch (every point equal) is never hit and never NaN.
    BicubicPatchParameters point_patch;
    point_patch.u_steps = point_patch.v_steps = 3;
    point_patch.flatness = 0.1;
    const auto dot = make_bicubic_patch_shape(point_patch);
    ASSERT_NE(dot, nullptr);
    EXPECT_TRUE(all_crossings(*dot, DVec3(0, 0, 1), DVec3(0, 0, -1)).empty());
    DVec3 lower, upper;
    ASSERT_TRUE(dot->bounds(lower, upper));
    EXPECT_EQ(lower, DVec3(0.0));
    // A zero direction: nothing.
    EXPECT_TRUE(all_crossings(*flat, DVec3(0, 0, 1), DVec3(0.0)).empty());
}

TEST(BicubicPatch, BoundsAreTheControlPointsBox) {
    const auto shape = make_bicubic_patch_shape(dome_patch(2.0, 2));
    DVec3 lower, upper;
    ASSERT_TRUE(shape->bounds(lower, upper));
    EXPECT_EQ(lower, DVec3(-1, -1, 0));
    EXPECT_EQ(upper, DVec3(1, 1, 2));
}

TEST(BicubicPatch, ScalesAndScaledRays) {
    for (double scale : {1e-4, 1.0, 1e4}) {
        BicubicPatchParameters patch = dome_patch(0.6, 3);
        for (DVec3& p : patch.points) p *= scale;
        const auto shape = make_bicubic_patch_shape(patch);
        for (double ray_scale : {1e-3, 1.0, 1e3}) {
            const DVec3 o = scale * DVec3(0.0, 0.0, 2.0), d = DVec3(0, 0, -ray_scale * scale);
            const auto hits = all_crossings(*shape, o, d);
            ASSERT_EQ(hits.size(), 1u) << scale << " " << ray_scale;
            EXPECT_NEAR(hits[0].t * ray_scale, 2.0 - 9.0 / 16.0 * 0.6, 1e-12);
            // From the hit, a tiny relative t_min keeps the start point out.
            const DVec3 p = o + hits[0].t * d;
            EXPECT_TRUE(all_crossings(*shape, p, -d, 1e-9 / ray_scale).empty());
        }
    }
}

TEST(BicubicPatch, FineStepsFollowTheSurface) {
    const double z[4][4] = {{0, 1, -1, 0}, {1, 2, 0, -1}, {-1, 0, 2, 1}, {0.5, -1, 1, 0}};
    const BicubicPatchParameters patch = patch_with_heights(z, 8, 8);
    const auto shape = make_bicubic_patch_shape(patch);
    std::mt19937 random(3);
    std::uniform_real_distribution<double> unit(0.01, 0.99);
    double worst = 0.0;
    for (int k = 0; k < 20000; ++k) {
        const double u = unit(random), v = unit(random);
        ShapeCrossing hit;
        ASSERT_TRUE(shape->nearest(DVec3(2 * u - 1, 2 * v - 1, 10), DVec3(0, 0, -1), 0, INFINITY, hit));
        worst = std::max(worst, std::fabs((10 - hit.t) - patch_height(patch, u, v)));
    }
    EXPECT_LT(worst, 2e-4);  // pieces 1/256 wide: second-order error
    EXPECT_GT(worst, 0.0);   // and still facets, as POV's
}

}  // namespace
}  // namespace lancer
