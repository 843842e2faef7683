// Closed-form checks of POV-Ray 3.7's ovus (ovus.h): its layout as POV's
// parser computes it, hits, normals, (u, v), the inside test, the joins
// between its pieces, grazing rays, rays from on the surface, scales, and
// the parameters POV refuses or replaces.
#include "geometry/ovus.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace lancer {
namespace {

// POV 3.7's Parse_Ovus layout, written out as POV writes it (unfactored),
// to check the shape against.
struct Layout {
    double bottom, top, connecting, vertical, horizontal, low, high;
};
Layout pov_layout(double b, double a) {
    Layout l{b, a, 0, 0, 0, 0, 0};
    if (b > a) {
        l.connecting = 2 * b;
        l.vertical = 2 * a - b - a * a / (2 * b);
        l.horizontal = std::sqrt(b * b - l.vertical * l.vertical);
        l.low = -l.vertical;
        l.high = (b - l.vertical) * a / (l.connecting - a) + b;
    } else {
        l.connecting = 2 * a;
        l.vertical = -2 * a + b + 1.5 * a * a / b;
        l.horizontal = std::sqrt(a * a - (l.vertical - b) * (l.vertical - b));
        l.high = 2 * b - l.vertical;
        l.low = -l.vertical * b / (l.connecting - b);
    }
    return l;
}

// The ovus's radius about the y axis at height y (its meridian).
double profile(const Layout& l, double y) {
    if (y <= l.low) return std::sqrt(std::max(0.0, l.bottom * l.bottom - y * y));
    if (y >= l.high) return std::sqrt(std::max(0.0, l.top * l.top - (y - l.bottom) * (y - l.bottom)));
    const double dy = y - l.vertical;
    return std::sqrt(l.connecting * l.connecting - dy * dy) - l.horizontal;
}

std::vector<ShapeCrossing> sorted_crossings(const Shape& shape, const DVec3& o, const DVec3& d, double t_min = -1e300,
                                            double t_max = 1e300) {
    ShapeCrossings all;
    shape.crossings(o, d, t_min, t_max, all);
    std::vector<ShapeCrossing> hits(all.items, all.items + all.count);
    std::sort(hits.begin(), hits.end(), [](const ShapeCrossing& a, const ShapeCrossing& b) { return a.t < b.t; });
    return hits;
}

// Signed distance-like miss of a point from the surface, via the profile.
double surface_miss(const Layout& l, const DVec3& p) {
    return std::hypot(p.x, p.z) - profile(l, p.y);
}

TEST(Ovus, TangentCirclesLieOnBothPieces) {
    for (const double top : {1e-6, 0.1, 0.5, 0.99, 1.0, 1.3, 1.9}) {
        const Layout l = pov_layout(1.0, top);
        // At y_low the bottom sphere and the connection share their radius,
        // and at y_high the top sphere and the connection do.
        const double low_sphere = std::sqrt(1.0 - l.low * l.low);
        const double low_lemon =
            std::sqrt(4 * std::max(1.0, top) * std::max(1.0, top) - (l.low - l.vertical) * (l.low - l.vertical)) -
            l.horizontal;
        EXPECT_NEAR(low_sphere, low_lemon, 1e-9) << top;
        const double dy = l.high - 1.0;
        const double high_sphere = std::sqrt(std::max(0.0, top * top - dy * dy));
        const double high_lemon =
            std::sqrt(l.connecting * l.connecting - (l.high - l.vertical) * (l.high - l.vertical)) - l.horizontal;
        EXPECT_NEAR(high_sphere, high_lemon, 1e-9) << top;
        EXPECT_LT(l.low, l.high);
    }
}

TEST(Ovus, AxisRayHitsBothPoles) {
    const auto ovus = make_ovus_shape(1.0, 0.5);
    ASSERT_TRUE(ovus);
    const auto hits = sorted_crossings(*ovus, {0, -5, 0}, {0, 1, 0});
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 4.0, 1e-12);  // y = -1, bottom pole
    EXPECT_EQ(hits[0].face, kOvusBottomSphere);
    EXPECT_NEAR(hits[1].t, 6.5, 1e-12);  // y = 1.5, top pole
    EXPECT_EQ(hits[1].face, kOvusTopSphere);
    const SurfaceGeometry bottom = ovus->surface({0, -1, 0}, hits[0].face);
    EXPECT_NEAR(bottom.normal.y, -1.0, 1e-12);
    const SurfaceGeometry top = ovus->surface({0, 1.5, 0}, hits[1].face);
    EXPECT_NEAR(top.normal.y, 1.0, 1e-12);
}

TEST(Ovus, HorizontalRaysFollowTheProfile) {
    for (const double top : {0.2, 0.5, 1.0, 1.5, 1.9}) {
        const auto ovus = make_ovus_shape(1.0, top);
        ASSERT_TRUE(ovus);
        const Layout l = pov_layout(1.0, top);
        for (int i = 1; i < 200; ++i) {
            const double y = -1.0 + (2.0 + top) * i / 200.0;
            const auto hits = sorted_crossings(*ovus, {-10, y, 0.0}, {1, 0, 0});
            const double r = profile(l, y);
            ASSERT_EQ(hits.size(), 2u) << "top " << top << " y " << y;
            EXPECT_NEAR(hits[0].t, 10.0 - r, 1e-9) << "top " << top << " y " << y;
            EXPECT_NEAR(hits[1].t, 10.0 + r, 1e-9) << "top " << top << " y " << y;
            const int expected = y < l.low ? kOvusBottomSphere : y > l.high ? kOvusTopSphere : kOvusConnection;
            // Within rounding of a join either neighbour may be named.
            if (std::fabs(y - l.low) > 1e-6 && std::fabs(y - l.high) > 1e-6) {
                EXPECT_EQ(hits[0].face, expected);
            }
        }
    }
}

TEST(Ovus, NoCrackAtTheJoins) {
    // Rays straddling the tangent circles by tiny amounts: always two hits,
    // on the profile.
    const auto ovus = make_ovus_shape(1.0, 0.6);
    const Layout l = pov_layout(1.0, 0.6);
    for (const double join : {l.low, l.high})
        for (int k = -20; k <= 20; ++k) {
            const double y = join + k * 1e-10;
            const auto hits = sorted_crossings(*ovus, {0.3, y, -7.0}, {0, 0, 2});
            ASSERT_EQ(hits.size(), 2u) << y;
            const double r = profile(l, y);
            const double half = std::sqrt(r * r - 0.09);
            EXPECT_NEAR(hits[0].t, (7.0 - half) / 2.0, 1e-9);
            EXPECT_NEAR(hits[1].t, (7.0 + half) / 2.0, 1e-9);
        }
}

TEST(Ovus, ConnectionNormalsPointAwayFromTheMeridianCentre) {
    const auto ovus = make_ovus_shape(1.0, 1.0);  // V = 0.5, H = sqrt(0.75), R = 2
    const Layout l = pov_layout(1.0, 1.0);
    EXPECT_NEAR(l.vertical, 0.5, 1e-15);
    const double r = 2.0 - std::sqrt(0.75);  // widest, at y = V
    const auto hits = sorted_crossings(*ovus, {0, 0.5, -5}, {0, 0, 1});
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 5.0 - r, 1e-12);
    EXPECT_EQ(hits[0].face, kOvusConnection);
    const SurfaceGeometry g = ovus->surface({0, 0.5, -r}, hits[0].face);
    EXPECT_NEAR(g.normal.z, -1.0, 1e-12);
    // Off the equator: normal along (h + H, y - V) in the meridian plane.
    const double y = 1.2, h = profile(l, y);
    const DVec3 p(h * std::cos(0.7), y, h * std::sin(0.7));
    const SurfaceGeometry off = ovus->surface(p, kOvusConnection);
    const double radial = h + l.horizontal, dy = y - l.vertical, length = std::hypot(radial, dy);
    EXPECT_NEAR(off.normal.x, radial / length * std::cos(0.7), 1e-12);
    EXPECT_NEAR(off.normal.y, dy / length, 1e-12);
    EXPECT_NEAR(off.normal.z, radial / length * std::sin(0.7), 1e-12);
    EXPECT_NEAR(glm::length(off.point - p), 0.0, 1e-12);
}

TEST(Ovus, SurfaceProjectsOntoThePiece) {
    const auto ovus = make_ovus_shape(1.0, 0.5);
    const Layout l = pov_layout(1.0, 0.5);
    const double y = 0.8, h = profile(l, y);
    const SurfaceGeometry g = ovus->surface({h + 1e-7, y, 0}, kOvusConnection);
    EXPECT_NEAR(surface_miss(l, g.point), 0.0, 1e-13);
    const SurfaceGeometry s = ovus->surface({0.3, -0.9, 0.1}, kOvusBottomSphere);
    EXPECT_NEAR(glm::length(s.point), 1.0, 1e-15);
}

TEST(Ovus, UvIsPovsSphericalMapAboutHalfTheTopRadius) {
    const auto ovus = make_ovus_shape(1.0, 0.5);
    // Centre of the map: <0, 0.25, 0>.
    SurfaceGeometry g = ovus->surface({1, 0, 0}, kOvusBottomSphere);
    EXPECT_NEAR(g.uv.x, 0.0, 1e-7);
    EXPECT_NEAR(g.uv.y, 0.5 + std::asin(-0.25 / std::sqrt(1.0625)) / kPiD, 1e-6);
    g = ovus->surface({0, 0, -1}, kOvusBottomSphere);
    EXPECT_NEAR(g.uv.x, 0.75, 1e-6);
    g = ovus->surface({0, 0, 1}, kOvusBottomSphere);
    EXPECT_NEAR(g.uv.x, 0.25, 1e-6);
    g = ovus->surface({-1, 0, 0}, kOvusBottomSphere);
    EXPECT_NEAR(g.uv.x, 0.5, 1e-6);
    g = ovus->surface({0, 1.5, 0}, kOvusTopSphere);
    EXPECT_NEAR(g.uv.x, 0.0, 1e-7);
    EXPECT_NEAR(g.uv.y, 1.0, 1e-6);
    g = ovus->surface({0, -1, 0}, kOvusBottomSphere);
    EXPECT_NEAR(g.uv.y, 0.0, 1e-6);
}

TEST(Ovus, InsideIsPovsUnionOfPieces) {
    const auto ovus = make_ovus_shape(1.0, 0.5);
    const Layout l = pov_layout(1.0, 0.5);
    EXPECT_TRUE(ovus->inside({0, 0, 0}));
    EXPECT_TRUE(ovus->inside({0, 1.49, 0}));
    EXPECT_FALSE(ovus->inside({0, 1.51, 0}));
    EXPECT_FALSE(ovus->inside({0, -1.01, 0}));
    const double y = 0.6, r = profile(l, y);
    EXPECT_GT(r, std::sqrt(1 - y * y));  // wider than the bottom ball there
    EXPECT_TRUE(ovus->inside({0, y, r - 1e-6}));
    EXPECT_FALSE(ovus->inside({0, y, r + 1e-6}));
    EXPECT_TRUE(ovus->inside({(r - 1e-6) * std::sqrt(0.5), y, (r - 1e-6) * std::sqrt(0.5)}));
    // The lemon beyond the slab (towards its tips) is not the ovus.
    EXPECT_FALSE(ovus->inside({0, 1.53, 0}));
}

TEST(Ovus, BoundsArePovs) {
    const auto ovus = make_ovus_shape(1.0, 0.5);
    const Layout l = pov_layout(1.0, 0.5);
    DVec3 lower, upper;
    ASSERT_TRUE(ovus->bounds(lower, upper));
    EXPECT_DOUBLE_EQ(lower.y, -1.0);
    EXPECT_DOUBLE_EQ(upper.y, 1.5);
    EXPECT_NEAR(upper.x, l.connecting - l.horizontal, 1e-12);
    EXPECT_NEAR(lower.z, -(l.connecting - l.horizontal), 1e-12);
    for (int i = 0; i <= 100; ++i) EXPECT_LE(profile(l, -1.0 + 2.5 * i / 100.0), upper.x);
}

TEST(Ovus, RandomLinesCrossOnceInOnceOut) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const double scale : {1e-4, 1.0, 1e4})
        for (const double top : {0.05, 0.5, 1.0, 1.7}) {
            const auto ovus = make_ovus_shape(1.0, top);
            const auto scaled = make_ovus_shape(scale, scale * top);
            const Layout l = pov_layout(1.0, top);
            int hit_lines = 0;
            for (int i = 0; i < 3000; ++i) {
                const DVec3 o(3 * unit(rng), 3 * unit(rng), 3 * unit(rng));
                const DVec3 d(unit(rng), unit(rng), unit(rng));
                // The same line on the scaled ovus crosses at the same t.
                const auto reference = sorted_crossings(*ovus, o, d);
                const auto on_scaled = sorted_crossings(*scaled, scale * o, d * scale);
                ASSERT_EQ(reference.size(), on_scaled.size());
                for (size_t k = 0; k < reference.size(); ++k) EXPECT_NEAR(reference[k].t, on_scaled[k].t, 1e-9);
                if (scale != 1.0) continue;
                const auto hits = sorted_crossings(*ovus, o, d);
                ASSERT_TRUE(hits.size() == 0u || hits.size() == 2u);
                if (hits.empty()) {
                    // Then the line misses the solid: sample it.
                    for (int k = -50; k <= 50; ++k) EXPECT_FALSE(ovus->inside(o + (k * 0.1) * d)) << top;
                    continue;
                }
                ++hit_lines;
                for (const ShapeCrossing& h : hits) EXPECT_NEAR(surface_miss(l, o + h.t * d), 0.0, 1e-12);
                EXPECT_TRUE(ovus->inside(o + (0.5 * (hits[0].t + hits[1].t)) * d));
                const double span = hits[1].t - hits[0].t;
                EXPECT_FALSE(ovus->inside(o + (hits[0].t - 1e-6 * (1 + span)) * d));
                EXPECT_FALSE(ovus->inside(o + (hits[1].t + 1e-6 * (1 + span)) * d));
            }
            if (scale == 1.0) {
                EXPECT_GT(hit_lines, 300);
            }
        }
}

TEST(Ovus, RaysFromTheSurfaceDoNotFindTheirStart) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    for (const double scale : {1e-4, 1.0, 1e4}) {
        const auto ovus = make_ovus_shape(scale, 0.7 * scale);
        const Layout l = pov_layout(scale, 0.7 * scale);
        for (int i = 0; i < 2000; ++i) {
            // A point on the surface from a crossing of a line through the inside.
            const DVec3 o = scale * DVec3(0.2 * unit(rng), 0.3 + 0.5 * unit(rng), 0.2 * unit(rng));
            const DVec3 d(unit(rng), unit(rng), unit(rng));
            const auto through = sorted_crossings(*ovus, o, d, 0.0, 1e300);
            ASSERT_EQ(through.size(), 1u);
            const DVec3 p = ovus->surface(o + through[0].t * d, through[0].face).point;
            EXPECT_NEAR(surface_miss(l, p) / scale, 0.0, 1e-12);
            const DVec3 n = ovus->surface(p, through[0].face).normal;
            DVec3 w(unit(rng), unit(rng), unit(rng));
            if (glm::dot(w, n) < 0) w = -w;
            // Leaving: nothing. Entering: the far side only, well away.
            const double direction_scale = 1e-3 + std::fabs(unit(rng)) * 1e3;
            const DVec3 out = w * direction_scale, in = -w * direction_scale;
            const double t_min = 1e-9 * scale / direction_scale;
            EXPECT_TRUE(sorted_crossings(*ovus, p, out, t_min, 1e300).empty()) << scale << " " << p.y / scale;
            const auto far = sorted_crossings(*ovus, p, in, t_min, 1e300);
            ASSERT_EQ(far.size(), 1u);
            EXPECT_GT(far[0].t * direction_scale, 1e-7 * scale);
        }
    }
}

TEST(Ovus, HitsScaleWithTheRayAndTheShape) {
    for (const double scale : {1e-4, 1e4})
        for (const double speed : {1e-3, 1e3}) {
            const auto ovus = make_ovus_shape(scale, 0.5 * scale);
            const Layout l = pov_layout(1.0, 0.5);
            const double y = 1.2, r = profile(l, y);
            const auto hits = sorted_crossings(*ovus, scale * DVec3(0, y, -3), DVec3(0, 0, speed));
            ASSERT_EQ(hits.size(), 2u);
            EXPECT_NEAR(hits[0].t * speed / scale, 3.0 - r, 1e-9);
            EXPECT_NEAR(hits[1].t * speed / scale, 3.0 + r, 1e-9);
        }
}

TEST(Ovus, FarOriginsKeepTheirDigits) {
    const auto ovus = make_ovus_shape(1.0, 0.5);
    const Layout l = pov_layout(1.0, 0.5);
    const double y = 0.9, r = profile(l, y);
    const auto hits = sorted_crossings(*ovus, {1e6, y, 0}, {-1, 0, 0});
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 1e6 - r, 1e-9 * 1e6);
    EXPECT_NEAR(1e6 - hits[1].t, -r, 1e-8);
}

TEST(Ovus, GrazingRaysGiveZeroOrTwoHits) {
    const auto ovus = make_ovus_shape(1.0, 0.5);
    const Layout l = pov_layout(1.0, 0.5);
    for (const double y : {-0.5, 0.7, 1.45}) {
        const double r = profile(l, y);
        for (int k = -30; k <= 30; ++k) {
            const double x = r * (1.0 + k * 1e-9);
            const auto hits = sorted_crossings(*ovus, {x, y, -4}, {0, 0, 1});
            if (k > 1) {
                EXPECT_TRUE(hits.empty()) << y << " " << k;
            }
            if (k < -1) {
                EXPECT_EQ(hits.size(), 2u) << y << " " << k;
            }
            EXPECT_TRUE(hits.size() == 0u || hits.size() == 2u);
        }
    }
}

TEST(Ovus, RangeLimitsAreOpen) {
    const auto ovus = make_ovus_shape(1.0, 0.5);
    EXPECT_EQ(sorted_crossings(*ovus, {0, -5, 0}, {0, 1, 0}, 4.0, 6.5).size(), 0u);
    EXPECT_EQ(sorted_crossings(*ovus, {0, -5, 0}, {0, 1, 0}, 3.9, 6.6).size(), 2u);
    EXPECT_EQ(sorted_crossings(*ovus, {0, -5, 0}, {0, 1, 0}, 4.5, 6.6).size(), 1u);
}

TEST(Ovus, TinyTopRadius) {
    const double top = 1e-6;
    const auto ovus = make_ovus_shape(1.0, top);
    const auto hits = sorted_crossings(*ovus, {0, -5, 0}, {0, 1, 0});
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[1].t, 6.0 + top, 1e-12);
    EXPECT_FALSE(ovus->inside({0, 1.0 + 2 * top, 0}));
    EXPECT_TRUE(ovus->inside({0, 1.0 + 0.5 * top, 0}));
}

TEST(Ovus, ZeroTopRadiusIsTheBottomSphere) {
    const auto ovus = make_ovus_shape(2.0, 0.0);
    ASSERT_TRUE(ovus);
    auto hits = sorted_crossings(*ovus, {0, -5, 0}, {0, 1, 0});
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 3.0, 1e-12);
    EXPECT_NEAR(hits[1].t, 7.0, 1e-12);
    hits = sorted_crossings(*ovus, {-5, 1.5, 0}, {1, 0, 0});
    ASSERT_EQ(hits.size(), 2u);
    EXPECT_NEAR(hits[0].t, 5.0 - std::sqrt(4.0 - 2.25), 1e-12);
    EXPECT_FALSE(ovus->inside({0, 2.01, 0}));
}

TEST(Ovus, LargeTopRadiusBecomesTheTopSphere) {
    // POV: top >= 2 bottom gives sphere { <0, bottom, 0>, top }.
    for (const double bottom : {1.0, 0.0}) {
        const double top = bottom > 0 ? 2.0 * bottom : 1.5;
        const auto sphere = make_ovus_shape(bottom, top);
        ASSERT_TRUE(sphere);
        const auto hits = sorted_crossings(*sphere, {0, -10, 0}, {0, 1, 0});
        ASSERT_EQ(hits.size(), 2u);
        EXPECT_NEAR(hits[0].t, 10.0 + bottom - top, 1e-12);
        EXPECT_NEAR(hits[1].t, 10.0 + bottom + top, 1e-12);
        DVec3 lower, upper;
        ASSERT_TRUE(sphere->bounds(lower, upper));
        EXPECT_NEAR(lower.x, -top, 1e-12);
    }
}

TEST(Ovus, RefusedParameters) {
    EXPECT_FALSE(make_ovus_shape(-1.0, 0.5));
    EXPECT_FALSE(make_ovus_shape(1.0, -0.5));
    EXPECT_FALSE(make_ovus_shape(NAN, 0.5));
    EXPECT_FALSE(make_ovus_shape(1.0, INFINITY));
    EXPECT_TRUE(make_ovus_shape(0.0, 0.0));  // POV: a sphere of radius 0
}

TEST(Ovus, DegenerateRaysGiveNothingAndNoNan) {
    const auto ovus = make_ovus_shape(1.0, 1.5);
    ShapeCrossings out;
    ovus->crossings({0, 0, -5}, {0, 0, 0}, 0.0, INFINITY, out);
    EXPECT_EQ(out.count, 0);
    ovus->crossings({0, 0, -5}, {0, 0, 1e-300}, 0.0, INFINITY, out);
    for (int i = 0; i < out.count; ++i) EXPECT_TRUE(std::isfinite(out.items[i].t));
    const SurfaceGeometry g = ovus->surface({0, 0.75, 0}, kOvusConnection);  // on the axis, not the surface
    EXPECT_TRUE(std::isfinite(g.normal.x + g.normal.y + g.normal.z + g.point.x + g.point.y + g.point.z));
    EXPECT_TRUE(std::isfinite(g.uv.x + g.uv.y));
}

}  // namespace
}  // namespace lancer
