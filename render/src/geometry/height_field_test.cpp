// Height fields over small grids whose surfaces are known planes and
// ridges, and the image reader on PNGs written here.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include "geometry/height_field.h"
#include "geometry/shape_test_support.h"
#include "materials/palette_png_test_support.h"

namespace lancer {
namespace {

// A grid sampling f(x, z) at its points.
template <class F>
HeightFieldGrid grid_of(int columns, int rows, F f) {
    HeightFieldGrid grid;
    grid.columns = columns;
    grid.rows = rows;
    for (int r = 0; r < rows; ++r)
        for (int c = 0; c < columns; ++c)
            grid.heights.push_back(float(f(double(c) / (columns - 1), double(r) / (rows - 1))));
    return grid;
}

using test::sorted_crossings;

// A ramp y = 0.25 + 0.5 x (exact in float at every point of a 5-point grid).
auto ramp = [](double x, double) { return 0.25 + 0.5 * x; };

TEST(HeightField, DegenerateGridsAreRefused) {
    EXPECT_EQ(make_height_field_shape(HeightFieldGrid{1, 5, std::vector<float>(5, 0.f)}, false, 0.0), nullptr);
    EXPECT_EQ(make_height_field_shape(HeightFieldGrid{3, 3, std::vector<float>(8, 0.f)}, false, 0.0), nullptr);
    HeightFieldGrid bad{2, 2, {0.f, 0.f, NAN, 0.f}};
    EXPECT_EQ(make_height_field_shape(bad, false, 0.0), nullptr);
    EXPECT_NE(make_height_field_shape(HeightFieldGrid{2, 2, {0.f, 0.f, 0.f, 0.f}}, false, 0.0), nullptr);
}

TEST(HeightField, VerticalRayOnARampHitsThePlane) {
    auto shape = make_height_field_shape(grid_of(5, 5, ramp), false, 0.0);
    for (double x : {0.1, 0.37, 0.5, 0.75, 0.99})
        for (double z : {0.05, 0.25, 0.6}) {
            const auto ts = sorted_crossings(*shape, DVec3(x, 2.0, z), DVec3(0, -1, 0));
            ASSERT_EQ(ts.size(), 1u) << x << " " << z;
            EXPECT_NEAR(2.0 - ts[0], ramp(x, z), 1e-12);
            ShapeCrossing hit;
            ASSERT_TRUE(shape->nearest(DVec3(x, 2.0, z), DVec3(0, -1, 0), 0.0, 1e30, hit));
            const SurfaceGeometry g = shape->surface(DVec3(x, 2.0 - hit.t, z), hit.face);
            const DVec3 expected = glm::normalize(DVec3(-0.5, 1.0, 0.0));
            EXPECT_NEAR(glm::dot(g.normal, expected), 1.0, 1e-12);
            EXPECT_NEAR(g.uv.x, x, 1e-6);
            EXPECT_NEAR(g.uv.y, z, 1e-6);
        }
}

TEST(HeightField, RayFromBelowAndObliqueRays) {
    auto shape = make_height_field_shape(grid_of(5, 5, ramp), false, 0.0);
    // From below the surface going up: the same plane.
    auto ts = sorted_crossings(*shape, DVec3(0.3, 0.0, 0.4), DVec3(0, 1, 0));
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(ts[0], ramp(0.3, 0.4), 1e-12);
    // Oblique: o + t d meets y = 0.25 + 0.5 x.
    const DVec3 o(-0.5, 1.0, 0.13), d(1.0, -0.6, 0.31);
    ts = sorted_crossings(*shape, o, d);
    ASSERT_EQ(ts.size(), 1u);
    const double t = (0.25 + 0.5 * o.x - o.y) / (d.y - 0.5 * d.x);
    EXPECT_NEAR(ts[0], t, 1e-12);
    // A ray passing above everything misses, one below too (open surface).
    EXPECT_TRUE(sorted_crossings(*shape, DVec3(-1, 0.9, 0.5), DVec3(1, 0, 0)).empty());
    EXPECT_TRUE(sorted_crossings(*shape, DVec3(-1, 0.1, 0.5), DVec3(1, 0, 0)).empty());
}

// A ridge along the diagonal: heights |x + z - 1| fall to 0 on the cell
// diagonals of a 2 x 2 grid's one cell, the surface is a V.
TEST(HeightField, TriangulationDiagonal) {
    // One cell: corners (0,0)=0 (1,0)=1 (0,1)=1 (1,1)=0. The diagonal
    // (1,0)-(0,1) is at height 1: a roof ridge, not a valley.
    HeightFieldGrid grid{2, 2, {0.f, 1.f, 1.f, 0.f}};
    auto shape = make_height_field_shape(grid, false, 0.0);
    // At the cell centre (on the diagonal) the height is 1 - 0 ... both triangles give 1.
    auto ts = sorted_crossings(*shape, DVec3(0.5, 2.0, 0.5), DVec3(0, -1, 0));
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(2.0 - ts[0], 1.0, 1e-12);
    // Near corner (0,0): the lower triangle y = x + z.
    ts = sorted_crossings(*shape, DVec3(0.2, 2.0, 0.1), DVec3(0, -1, 0));
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(2.0 - ts[0], 0.3, 1e-12);
    // Near corner (1,1): the upper triangle y = 2 - x - z.
    ts = sorted_crossings(*shape, DVec3(0.9, 2.0, 0.8), DVec3(0, -1, 0));
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(2.0 - ts[0], 0.3, 1e-12);
    // A ray along the diagonal at height 0.999 lies just under the ridge
    // line the whole way: it never crosses; at 1.001 above it neither.
    EXPECT_TRUE(sorted_crossings(*shape, DVec3(1.0, 1.001, 0.0) + DVec3(0.5, 0, -0.5), DVec3(-1, 0, 1)).empty());
    // A ray across the ridge at y = 0.5 crosses twice: in and out.
    ts = sorted_crossings(*shape, DVec3(-0.5, 0.5, -0.5), DVec3(1, 0, 1));
    ASSERT_EQ(ts.size(), 2u);
    EXPECT_NEAR(ts[0], 0.75, 1e-12);  // x = z = 0.25: y = 0.5
    EXPECT_NEAR(ts[1], 1.25, 1e-12);  // x = z = 0.75: y = 2 - 1.5
}

TEST(HeightField, RaysAlongGridLinesAndThroughCornersCountEachCrossingOnce) {
    // A bumpy 9 x 9 grid; rays along grid lines, through grid corners and
    // cell diagonals: the crossings alternate in and out (parity), each
    // at a point on the surface.
    auto bumps = [](double x, double z) { return 0.5 + 0.4 * std::sin(9.0 * x) * std::cos(7.0 * z); };
    HeightFieldGrid grid = grid_of(9, 9, bumps);
    auto shape = make_height_field_shape(grid, false, 0.0);
    std::vector<std::pair<DVec3, DVec3>> rays = {
        {DVec3(-0.2, 0.5, 0.5), DVec3(1, 0, 0)},       // along z = 0.5 (a grid line)
        {DVec3(0.25, 0.5, -0.2), DVec3(0, 0, 1)},      // along x = 0.25
        {DVec3(-0.25, 0.45, -0.25), DVec3(1, 0, 1)},   // through every corner (i, i)
        {DVec3(1.25, 0.55, -0.25), DVec3(-1, 0, 1)},   // along the cell diagonals
        {DVec3(-0.1, 0.9, 0.375), DVec3(1, -0.5, 0)},  // slanting through a grid line
    };
    for (auto [o, d] : rays) {
        const auto ts = sorted_crossings(*shape, o, d);
        ASSERT_FALSE(ts.empty());
        // Between consecutive crossings (and before the first, after the
        // last, inside the footprint) the inside state flips at each.
        for (std::size_t i = 0; i < ts.size(); ++i) {
            const double previous = i > 0 ? ts[i - 1] : ts[i] - 1e-4;
            const double next = i + 1 < ts.size() ? ts[i + 1] : ts[i] + 1e-4;
            const DVec3 before = o + 0.5 * (previous + ts[i]) * d, after = o + 0.5 * (ts[i] + next) * d;
            EXPECT_NE(shape->inside(before), shape->inside(after)) << "crossing " << i << " at " << ts[i];
            const DVec3 p = o + ts[i] * d;
            EXPECT_NEAR(shape->surface(p, -1).point.y, p.y, 1e-12);
            if (i + 1 < ts.size()) {
                EXPECT_GT(ts[i + 1] - ts[i], 1e-9);
            }
        }
    }
}

TEST(HeightField, RayThroughAGridVertexExactlyOnTheSurface) {
    // A flat field: a ray aimed exactly at a grid vertex finds one hit.
    HeightFieldGrid grid = grid_of(5, 5, [](double, double) { return 0.5; });
    auto shape = make_height_field_shape(grid, false, 0.0);
    const DVec3 target(0.5, 0.5, 0.75), o(0.1, 0.9, 0.35);
    const auto ts = sorted_crossings(*shape, o, target - o);
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(ts[0], 1.0, 1e-12);
}

TEST(HeightField, WaterLevelCutsTheSurfaceFlat) {
    auto shape = make_height_field_shape(grid_of(5, 5, ramp), false, 0.5);
    // y = 0.25 + 0.5 x is below 0.5 for x < 0.5: not drawn there.
    EXPECT_TRUE(sorted_crossings(*shape, DVec3(0.3, 2.0, 0.5), DVec3(0, -1, 0)).empty());
    const auto ts = sorted_crossings(*shape, DVec3(0.7, 2.0, 0.5), DVec3(0, -1, 0));
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(2.0 - ts[0], 0.6, 1e-12);
    // Below the water the solid is inside (POV), above the surface not.
    EXPECT_TRUE(shape->inside(DVec3(0.3, 0.45, 0.5)));
    EXPECT_TRUE(shape->inside(DVec3(0.3, -5.0, 0.5)));
    EXPECT_FALSE(shape->inside(DVec3(0.3, 0.51, 0.5)));
    DVec3 lower, upper;
    ASSERT_TRUE(shape->bounds(lower, upper));
    EXPECT_NEAR(lower.y, 0.5, 1e-6);
    EXPECT_NEAR(upper.y, 0.75, 1e-6);
}

TEST(HeightField, InsideIsBelowTheSurfaceWithinTheFootprint) {
    auto shape = make_height_field_shape(grid_of(5, 5, ramp), false, 0.0);
    EXPECT_TRUE(shape->inside(DVec3(0.5, 0.49, 0.5)));
    EXPECT_FALSE(shape->inside(DVec3(0.5, 0.51, 0.5)));
    EXPECT_TRUE(shape->inside(DVec3(0.5, -100.0, 0.5)));
    EXPECT_FALSE(shape->inside(DVec3(-0.01, 0.1, 0.5)));
    EXPECT_FALSE(shape->inside(DVec3(1.0, 0.1, 0.5)));  // the far edges are outside (POV: x < 1)
    EXPECT_FALSE(shape->inside(DVec3(0.5, 0.1, 1.0)));
}

TEST(HeightField, GrazingRaysAndRaysFromTheSurface) {
    auto shape = make_height_field_shape(grid_of(5, 5, ramp), false, 0.0);
    // A ray in the surface's own plane, just above it: no crossing.
    const DVec3 along = glm::normalize(DVec3(1.0, 0.5, 0.2));
    EXPECT_TRUE(sorted_crossings(*shape, DVec3(0.0, 0.25 + 1e-7, 0.1), along).empty());
    // Just below it, coming from outside the footprint: enters below, never crosses.
    EXPECT_TRUE(sorted_crossings(*shape, DVec3(-0.1, 0.2 - 1e-7, 0.1), along).empty());
    // Nearly grazing: the analytic crossing.
    const DVec3 o(-0.5, 1e-3, 0.5), d(1.0, 0.5 - 1e-3, 0.0);  // meets it at x = 0.5
    const auto ts = sorted_crossings(*shape, o, d);
    ASSERT_EQ(ts.size(), 1u);
    EXPECT_NEAR(ts[0], (0.25 + 0.5 * o.x - o.y) / (d.y - 0.5 * d.x), 1e-9);
    // Leaving the surface from a hit point (t_min tiny): no second hit.
    const DVec3 p(0.4, 0.45, 0.3);
    const SurfaceGeometry g = shape->surface(p, -1);
    EXPECT_NEAR(g.point.y, 0.45, 1e-15);
    const DVec3 reflected = glm::normalize(DVec3(0.3, 1.0, 0.1));
    EXPECT_TRUE(sorted_crossings(*shape, g.point + 1e-12 * g.normal, reflected, 1e-12).empty());
    // Through the surface from just above it: one hit right there.
    const auto down = sorted_crossings(*shape, g.point + 1e-10 * g.normal, DVec3(0, -1, 0), 1e-13);
    ASSERT_EQ(down.size(), 1u);
    EXPECT_LT(down[0], 1e-9);
}

TEST(HeightField, ScaledRaysFindTheSameHits) {
    auto bumps = [](double x, double z) { return 0.5 + 0.3 * std::sin(5.0 * x + 2.0 * z); };
    auto shape = make_height_field_shape(grid_of(17, 11, bumps), false, 0.0);
    const DVec3 o(-0.3, 1.2, 0.2), d(1.0, -0.9, 0.45);
    const auto reference = sorted_crossings(*shape, o, d);
    ASSERT_FALSE(reference.empty());
    for (double scale : {1e-4, 1e4}) {
        const auto ts = sorted_crossings(*shape, o, d * scale);
        ASSERT_EQ(ts.size(), reference.size());
        for (std::size_t i = 0; i < ts.size(); ++i) EXPECT_NEAR(ts[i] * scale, reference[i], 1e-12 * reference[i]);
    }
    // A far origin: the hit is still on the surface.
    const DVec3 far = o - 1e4 * d;
    const auto ts = sorted_crossings(*shape, far, d);
    ASSERT_EQ(ts.size(), reference.size());
    EXPECT_NEAR(ts[0] - 1e4, reference[0], 1e-9);
}

TEST(HeightField, SmoothNormalsOnAPlaneAreThePlaneNormal) {
    // On a plane every vertex normal is the plane's (up to POV's 16-bit
    // storage), so the interpolated normal is too.
    auto shape = make_height_field_shape(grid_of(5, 5, ramp), true, 0.0);
    ShapeCrossing hit;
    ASSERT_TRUE(shape->nearest(DVec3(0.37, 2.0, 0.61), DVec3(0, -1, 0), 0.0, 1e30, hit));
    const SurfaceGeometry g = shape->surface(DVec3(0.37, 2.0 - hit.t, 0.61), hit.face);
    // The grid's normal (-8192, 1, 0) per cell (heights at 65536 a unit)
    // is stored as shorts (-32766, 3, 0): y truncated from 3.9999.
    const DVec3 stored = glm::normalize(DVec3(-32766.0 * 4.0, 3.0 * 65536.0, 0.0));
    EXPECT_NEAR(glm::dot(g.shading_normal, stored), 1.0, 1e-12);
    EXPECT_NEAR(glm::length(g.shading_normal), 1.0, 1e-12);
    // The facet's own normal stays exact: rays leave across it.
    EXPECT_NEAR(glm::dot(g.normal, glm::normalize(DVec3(-0.5, 1.0, 0.0))), 1.0, 1e-12);
    // On a fine grid the storage costs little: within 1e-4 of the plane's.
    auto fine = make_height_field_shape(grid_of(257, 9, ramp), true, 0.0);
    ASSERT_TRUE(fine->nearest(DVec3(0.37, 2.0, 0.61), DVec3(0, -1, 0), 0.0, 1e30, hit));
    const SurfaceGeometry h = fine->surface(DVec3(0.37, 2.0 - hit.t, 0.61), hit.face);
    EXPECT_NEAR(glm::dot(h.shading_normal, glm::normalize(DVec3(-0.5, 1.0, 0.0))), 1.0, 1e-4);
}

TEST(HeightField, SmoothNormalsInterpolateAcrossARidge) {
    // A roof ridge along x = 0.5: flat normals jump across it, smooth ones
    // vary continuously and are vertical on the ridge line (the normal
    // shading reads; the facets' stay flat).
    auto roof = [](double x, double) { return 0.5 - 0.25 * std::fabs(x - 0.5) * 2.0; };
    auto flat = make_height_field_shape(grid_of(5, 5, roof), false, 0.0);
    auto smooth = make_height_field_shape(grid_of(5, 5, roof), true, 0.0);
    auto normal_at = [](const Shape& s, double x, double z) {
        ShapeCrossing hit;
        EXPECT_TRUE(s.nearest(DVec3(x, 2.0, z), DVec3(0, -1, 0), 0.0, 1e30, hit));
        const SurfaceGeometry g = s.surface(DVec3(x, 2.0 - hit.t, z), hit.face);
        return g.shading_normal == DVec3(0.0) ? g.normal : g.shading_normal;
    };
    EXPECT_NEAR(normal_at(*flat, 0.49, 0.4).x, -normal_at(*flat, 0.51, 0.4).x, 1e-12);
    EXPECT_LT(normal_at(*flat, 0.49, 0.4).x, -0.3);
    EXPECT_NEAR(normal_at(*smooth, 0.5 - 1e-9, 0.4).x, 0.0, 1e-6);
    EXPECT_NEAR(normal_at(*smooth, 0.49, 0.4).x, normal_at(*smooth, 0.51, 0.4).x, 0.05);
    // Halfway along a cell the blend is between the vertex normals.
    const DVec3 mid = normal_at(*smooth, 0.375, 0.4);
    EXPECT_GT(mid.x, -0.3);
    EXPECT_LT(mid.x, 0.0);
}

// A map of 16 million points builds (the min/max pyramid) and traces;
// its speed belongs to bench/, not here.
TEST(HeightField, LargeGridBuildsAndTraces) {
    const int n = 4096;
    HeightFieldGrid grid;
    grid.columns = grid.rows = n;
    grid.heights.resize(std::size_t(n) * n);
    for (int r = 0; r < n; ++r)
        for (int c = 0; c < n; ++c)
            grid.heights[std::size_t(r) * n + c] = float(0.5 + 0.25 * std::sin(c * 0.01) * std::cos(r * 0.013));
    auto shape = make_height_field_shape(std::move(grid), true, 0.0);
    ASSERT_TRUE(shape);
    int hits = 0;
    for (int i = 0; i < 20000; ++i) {
        const double u = (i % 141) / 141.0, v = (i / 141) / 141.0;
        ShapeCrossing hit;
        if (shape->nearest(DVec3(-0.2, 1.5, -0.2), DVec3(u + 0.2, -1.2, v + 0.2), 0.0, 1e30, hit)) ++hits;
    }
    EXPECT_GT(hits, 15000);
}

// ---- The image reader ----

std::string write_png(const std::string& name, int width, int height, OIIO::TypeDesc type, int channels,
                      const std::vector<float>& pixels) {
    const std::string path = "/tmp/lancer_hf_test_" + name + ".png";
    auto out = OIIO::ImageOutput::create(path);
    OIIO::ImageSpec spec(width, height, channels, type);
    EXPECT_TRUE(out->open(path, spec));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
    out->close();
    return path;
}

TEST(HeightFieldImage, SixteenBitGreyGivesValueOver65536AndTurnsTheImageOver) {
    // 3 x 2 pixels: top row 0, 1000, 65535; bottom row 2, 30000, 40000.
    const std::vector<int> codes = {0, 1000, 65535, 2, 30000, 40000};
    std::vector<float> pixels;
    for (int c : codes) pixels.push_back(float(c) / 65535.0f);
    const std::string path = write_png("grey16", 3, 2, OIIO::TypeDesc::UINT16, 1, pixels);
    const HeightFieldGrid grid = read_height_field_image(path, NAN);
    ASSERT_EQ(grid.columns, 3);
    ASSERT_EQ(grid.rows, 2);
    // Row 0 (z = 0) is the image's bottom row.
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(grid.heights[i] * 65536.0, codes[3 + i], 1.0);
        EXPECT_NEAR(grid.heights[3 + i] * 65536.0, codes[i], 1.0);
    }
    EXPECT_FLOAT_EQ(grid.heights[5], 65535.0f / 65536.0f);
}

TEST(HeightFieldImage, EightBitGreyIsScaledTo16Bits) {
    const std::vector<int> codes = {0, 1, 128, 255};
    std::vector<float> pixels;
    for (int c : codes) pixels.push_back(float(c) / 255.0f);
    const std::string path = write_png("grey8", 2, 2, OIIO::TypeDesc::UINT8, 1, pixels);
    const HeightFieldGrid grid = read_height_field_image(path, NAN);
    // Image rows: top {0, 1}, bottom {128, 255}; about 257 per step.
    EXPECT_NEAR(grid.heights[0] * 65536.0, 128 * 257, 300);
    EXPECT_NEAR(grid.heights[1] * 65536.0, 255 * 257, 300);
    EXPECT_EQ(grid.heights[2], 0.0f);
    EXPECT_NEAR(grid.heights[3] * 65536.0, 257, 300);
    // A gamma decodes before scaling: 128/255 squared.
    const HeightFieldGrid decoded = read_height_field_image(path, 2.0);
    EXPECT_NEAR(decoded.heights[0], std::pow(128.0 / 255.0, 2.0) * 65535.0 / 65536.0, 2e-3);
}

TEST(HeightFieldImage, EightBitColourIsRedHighGreenLow) {
    const std::vector<float> pixels = {10 / 255.f, 200 / 255.f, 0.f, 0.f, 0.f, 1.f, 1.f, 1.f, 1.f, 0.f, 1.f, 0.f};
    const std::string path = write_png("rgb8", 2, 2, OIIO::TypeDesc::UINT8, 3, pixels);
    const HeightFieldGrid grid = read_height_field_image(path, NAN);
    // Bottom row first: (255,255,255) then (0,255,0).
    EXPECT_NEAR(grid.heights[0] * 65536.0, 255 * 256 + 255, 1.0);
    EXPECT_NEAR(grid.heights[1] * 65536.0, 255, 1.0);
    EXPECT_NEAR(grid.heights[2] * 65536.0, 10 * 256 + 200, 1.0);
    EXPECT_NEAR(grid.heights[3] * 65536.0, 0, 1.0);
}

// A palette PNG's heights are its indices * 256, also where two entries
// share a colour (POV keeps the file's indices).
TEST(HeightFieldImage, PalettePngIsItsIndicesEvenWhereColoursRepeat) {
    const std::string path = "/tmp/lancer_hf_test_palette.png";
    // Entries 0, 2 and 3 alike; indices 2, 1 on the top row, 0, 3 below.
    testing::write_palette_png(path, 2, 2, {9, 9, 9, 200, 0, 0, 9, 9, 9, 9, 9, 9}, {2, 1, 0, 3});
    const HeightFieldGrid grid = read_height_field_image(path, NAN);
    ASSERT_EQ(grid.columns, 2);
    EXPECT_FLOAT_EQ(grid.heights[0] * 65536.0f, 0.0f);
    EXPECT_FLOAT_EQ(grid.heights[1] * 65536.0f, 3 * 256.0f);
    EXPECT_FLOAT_EQ(grid.heights[2] * 65536.0f, 2 * 256.0f);
    EXPECT_FLOAT_EQ(grid.heights[3] * 65536.0f, 256.0f);
    std::remove(path.c_str());
}

TEST(HeightFieldImage, BadFilesThrowOneLineErrors) {
    EXPECT_THROW(read_height_field_image("/tmp/lancer_hf_test_missing.png", NAN), std::runtime_error);
    {
        std::FILE* f = std::fopen("/tmp/lancer_hf_test_garbage.png", "wb");
        std::fputs("not an image at all", f);
        std::fclose(f);
    }
    try {
        read_height_field_image("/tmp/lancer_hf_test_garbage.png", NAN);
        ADD_FAILURE() << "no throw";
    } catch (const std::runtime_error& e) {
        const std::string what = e.what();
        EXPECT_NE(what.find("lancer_hf_test_garbage.png"), std::string::npos);
        EXPECT_EQ(what.find('\n'), std::string::npos);
    }
    // Truncated: a valid PNG cut in half.
    std::vector<float> pixels(64 * 64);
    for (std::size_t i = 0; i < pixels.size(); ++i) pixels[i] = float((i * 7919) % 251) / 255.0f;
    const std::string path = write_png("cut", 64, 64, OIIO::TypeDesc::UINT8, 1, pixels);
    std::FILE* f = std::fopen(path.c_str(), "rb");
    std::vector<char> bytes(100000);
    const std::size_t size = std::fread(bytes.data(), 1, bytes.size(), f);
    std::fclose(f);
    f = std::fopen(path.c_str(), "wb");
    std::fwrite(bytes.data(), 1, size / 2, f);
    std::fclose(f);
    EXPECT_THROW(read_height_field_image(path, NAN), std::runtime_error);
    // One pixel wide: no cells.
    const std::string thin = write_png("thin", 1, 4, OIIO::TypeDesc::UINT8, 1, std::vector<float>(4, 0.5f));
    EXPECT_THROW(read_height_field_image(thin, NAN), std::runtime_error);
}

TEST(HeightFieldImage, HugeClaimedSizeIsRefusedBeforeDecoding) {
    // A PNG header claiming 100000 x 100000 with no data.
    const unsigned char header[] = {0x89, 'P',  'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a, 0,    0,    0,
                                    13,   'I',  'H', 'D', 'R',  0,    1,    0x86, 0xa0, 0,    1,
                                    0x86, 0xa0, 8,   0,   0,    0,    0,    0x00, 0x00, 0x00, 0x00};
    std::FILE* f = std::fopen("/tmp/lancer_hf_test_huge.png", "wb");
    std::fwrite(header, 1, sizeof header, f);
    std::fclose(f);
    EXPECT_THROW(read_height_field_image("/tmp/lancer_hf_test_huge.png", NAN), std::runtime_error);
}

}  // namespace
}  // namespace lancer
