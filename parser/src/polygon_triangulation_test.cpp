// The OBJ face triangulator: every simple polygon becomes n - 2 triangles
// that cover it exactly once, wound as the polygon; convex faces, concave
// ones (stars, combs, spirals, skylines full of equal heights), corners that
// repeat, faces that are not planar, and faces that cross themselves.
#include "polygon_triangulation.h"

#include <chrono>
#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace lancer::parse {
namespace {

using Kind = PolygonTriangulation::Kind;
constexpr double kPi = 3.14159265358979323846;

std::vector<sg::Vec3> in_xy(const std::vector<glm::dvec2>& corners) {
    std::vector<sg::Vec3> points;
    for (const auto& c : corners) points.emplace_back(c.x, c.y, 0.0);
    return points;
}

// The polygon's vector area (Newell), and the sum of its triangles' areas.
sg::Vec3 vector_area(const std::vector<sg::Vec3>& p) {
    sg::Vec3 sum(0.0);
    for (size_t i = 0; i < p.size(); ++i) sum += glm::cross(p[i] - p[0], p[(i + 1) % p.size()] - p[0]);
    return 0.5 * sum;
}

// Even-odd point in polygon (the xy projection), for small polygons.
bool inside_xy(const std::vector<sg::Vec3>& p, double x, double y) {
    bool in = false;
    for (size_t i = 0, j = p.size() - 1; i < p.size(); j = i++) {
        if ((p[i].y > y) != (p[j].y > y) && x < (p[j].x - p[i].x) * (y - p[i].y) / (p[j].y - p[i].y) + p[i].x) in = !in;
    }
    return in;
}

// A valid triangulation of a simple planar polygon: n - 2 triangles (n
// distinct corners), each wound as the polygon (its normal on the side of
// the polygon's), whose areas add up to the polygon's; for small polygons in
// the xy plane each triangle's centroid also lies inside.
void expect_covers(const std::vector<sg::Vec3>& p, const PolygonTriangulation& t, size_t corners) {
    ASSERT_EQ(t.triangles.size(), corners - 2);
    const sg::Vec3 area = vector_area(p);
    const sg::Vec3 side = glm::normalize(area);
    double sum = 0.0;
    for (const auto& tri : t.triangles) {
        for (auto index : tri) ASSERT_LT(index, p.size());
        const sg::Vec3 n = 0.5 * glm::cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]);
        EXPECT_GE(glm::dot(n, side), -1e-12 * glm::length(area)) << "a triangle wound against the polygon";
        sum += glm::length(n);
        if (p.size() <= 200 && p[0].z == 0.0 && glm::length(n) > 1e-9 * glm::length(area)) {
            const sg::Vec3 c = (p[tri[0]] + p[tri[1]] + p[tri[2]]) / 3.0;
            EXPECT_TRUE(inside_xy(p, c.x, c.y)) << "triangle outside the polygon at " << c.x << "," << c.y;
        }
    }
    EXPECT_NEAR(sum, glm::length(area), 1e-9 * glm::length(area));
}

TEST(PolygonTriangulation, ConvexQuadSplitsAlongItsShorterDiagonalAsTinyobjloader) {
    // 0-2 is the shorter diagonal.
    auto t = triangulate_polygon(in_xy({{0, 0}, {3, 0}, {3, 1}, {0, 3}}));
    EXPECT_EQ(t.kind, Kind::Convex);
    ASSERT_EQ(t.triangles.size(), 2u);
    EXPECT_EQ(t.triangles[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
    EXPECT_EQ(t.triangles[1], (std::array<std::uint32_t, 3>{0, 2, 3}));
}

// tinyobjloader split every quad along its shorter diagonal, which for this
// dart lies outside the face.
TEST(PolygonTriangulation, ConcaveQuadSplitsAtItsReflexCorner) {
    const auto p = in_xy({{0, 0}, {10, 1}, {0, 2}, {1, 1}});
    auto t = triangulate_polygon(p);
    EXPECT_EQ(t.kind, Kind::General);
    expect_covers(p, t, 4);
}

TEST(PolygonTriangulation, LargeConvexFaceIsAFan) {
    constexpr int kCorners = 200000;
    std::vector<glm::dvec2> c;
    for (int i = 0; i < kCorners; ++i)
        c.emplace_back(std::cos(2 * kPi * i / kCorners), std::sin(2 * kPi * i / kCorners));
    const auto p = in_xy(c);
    const auto start = std::chrono::steady_clock::now();
    auto t = triangulate_polygon(p);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(t.kind, Kind::Convex);
    expect_covers(p, t, kCorners);
    EXPECT_NEAR(vector_area(p).z, kPi, 1e-6);
    std::printf("convex face of %d corners: %.3f s\n", kCorners, seconds);
}

// Stars, combs and spirals: concave everywhere, each needs the sweep.
std::vector<glm::dvec2> star(int corners) {
    std::vector<glm::dvec2> c;
    for (int i = 0; i < corners; ++i) {
        const double r = i % 2 ? 0.5 : 1.0, a = 2 * kPi * i / corners;
        c.emplace_back(r * std::cos(a), r * std::sin(a));
    }
    return c;
}

// Teeth 1 wide and 2 tall on a bar 1 high: many corners at equal heights,
// horizontal edges everywhere. Area 4 * teeth - 1, 4 * teeth corners.
std::vector<glm::dvec2> comb(int teeth) {
    std::vector<glm::dvec2> c{{0, 0}, {2 * teeth - 1, 0}};
    for (int i = teeth - 1; i >= 0; --i) {
        c.emplace_back(2 * i + 1, 3);
        c.emplace_back(2 * i, 3);
        if (i > 0) {
            c.emplace_back(2 * i, 1);
            c.emplace_back(2 * i - 1, 1);
        }
    }
    return c;
}

std::vector<glm::dvec2> spiral(int corners) {
    // Out along one arm and back along a parallel one: a thick spiral.
    std::vector<glm::dvec2> outer, inner;
    const int half = corners / 2;
    for (int i = 0; i < half; ++i) {
        const double a = 0.05 * i, r = 1.0 + 0.3 * a;
        outer.emplace_back(r * std::cos(a), r * std::sin(a));
        inner.emplace_back((r - 0.1) * std::cos(a), (r - 0.1) * std::sin(a));
    }
    std::vector<glm::dvec2> c(outer.begin(), outer.end());
    c.insert(c.end(), inner.rbegin(), inner.rend());
    return c;
}

TEST(PolygonTriangulation, LargeStarNeedsTheSweep) {
    constexpr int kCorners = 100000;
    const auto p = in_xy(star(kCorners));
    const auto start = std::chrono::steady_clock::now();
    auto t = triangulate_polygon(p);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_EQ(t.kind, Kind::General);
    expect_covers(p, t, kCorners);
    std::printf("star face of %d corners: %.3f s\n", kCorners, seconds);
}

TEST(PolygonTriangulation, LargeCombWithEqualHeights) {
    const auto p = in_xy(comb(25000));
    auto t = triangulate_polygon(p);
    EXPECT_EQ(t.kind, Kind::General);
    expect_covers(p, t, p.size());
    EXPECT_EQ(p.size(), 100000u);
    EXPECT_NEAR(vector_area(p).z, 4.0 * 25000 - 1, 1e-6);
}

TEST(PolygonTriangulation, SmallStarsCombsAndSpirals) {
    for (int corners : {6, 10, 16, 50}) {
        const auto p = in_xy(star(corners));
        auto t = triangulate_polygon(p);
        EXPECT_EQ(t.kind, Kind::General) << corners;
        expect_covers(p, t, corners);
    }
    for (int teeth : {1, 2, 5, 30}) {
        const auto p = in_xy(comb(teeth));
        expect_covers(p, triangulate_polygon(p), p.size());
    }
    for (int corners : {20, 100, 200}) {
        const auto p = in_xy(spiral(corners));
        auto t = triangulate_polygon(p);
        EXPECT_EQ(t.kind, Kind::General) << corners;
        expect_covers(p, t, p.size());
    }
}

// Whether two non-adjacent edges of the polygon cross (2), only touch (1),
// or neither (0), by brute force.
int crosses_itself(const std::vector<glm::dvec2>& c) {
    auto orient = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
        const double d = (b.x - a.x) * (p.y - a.y) - (b.y - a.y) * (p.x - a.x);
        return (d > 0) - (d < 0);
    };
    auto on = [](glm::dvec2 a, glm::dvec2 b, glm::dvec2 p) {
        return std::min(a.x, b.x) <= p.x && p.x <= std::max(a.x, b.x) && std::min(a.y, b.y) <= p.y &&
               p.y <= std::max(a.y, b.y);
    };
    const size_t n = c.size();
    int found = 0;
    for (size_t i = 0; i < n; ++i) {
        for (size_t j = i + 1; j < n; ++j) {
            if (j == i + 1 || (i == 0 && j == n - 1)) continue;
            const glm::dvec2 a = c[i], b = c[(i + 1) % n], p = c[j], q = c[(j + 1) % n];
            const int o1 = orient(a, b, p), o2 = orient(a, b, q), o3 = orient(p, q, a), o4 = orient(p, q, b);
            if (o1 * o2 < 0 && o3 * o4 < 0) return 2;
            if ((o1 == 0 && on(a, b, p)) || (o2 == 0 && on(a, b, q)) || (o3 == 0 && on(p, q, a)) ||
                (o4 == 0 && on(p, q, b)))
                found = 1;
        }
    }
    return found;
}

// Random star-shaped polygons (simple by construction), some on an integer
// grid so that heights and x coordinates repeat, in both windings.
TEST(PolygonTriangulation, RandomSimplePolygons) {
    std::mt19937 rng(22);
    int simple = 0, crossing = 0;
    for (int round = 0; round < 4000; ++round) {
        const int corners = 3 + static_cast<int>(rng() % 60);
        const bool grid = round % 2;
        std::vector<double> angles;
        for (int i = 0; i < corners; ++i) angles.push_back(std::uniform_real_distribution<double>(0, 2 * kPi)(rng));
        std::sort(angles.begin(), angles.end());
        std::vector<glm::dvec2> c;
        for (double a : angles) {
            const double r = std::uniform_real_distribution<double>(0.1, 10.0)(rng);
            glm::dvec2 q(r * std::cos(a), r * std::sin(a));
            if (grid) q = glm::round(q);
            if (!c.empty() && c.back() == q) continue;
            c.push_back(q);
        }
        if (round % 4 >= 2) std::reverse(c.begin(), c.end());
        auto p = in_xy(c);
        // With an angular gap wider than half a turn the polygon may cross
        // itself: those must be found.
        const double area = std::abs(vector_area(p).z);
        if (c.size() < 3 || area < 1e-9) continue;
        if (c.front() == c.back()) c.pop_back();
        auto t = triangulate_polygon(p);
        const int crossed = crosses_itself(c);
        if (crossed == 2) {
            ++crossing;
            EXPECT_EQ(t.kind, Kind::NotSimple) << "round " << round;
            EXPECT_EQ(t.triangles.size(), c.size() - 2);
        } else if (crossed == 1) {  // touching itself: a triangulation, or the fan
            if (t.kind != Kind::NotSimple) expect_covers(p, t, c.size());
        } else {
            ++simple;
            EXPECT_NE(t.kind, Kind::NotSimple) << "round " << round;
            expect_covers(p, t, c.size());
        }
        if (HasFailure()) {
            for (const auto& q : c) std::printf("{%.17g, %.17g}, ", q.x, q.y);
            std::printf("\n");
            return;
        }
    }
    EXPECT_GT(simple, 1000);
    EXPECT_GT(crossing, 500);
}

// Skylines: bars of random whole heights, so many corners share a height.
TEST(PolygonTriangulation, SkylinesOfEqualHeights) {
    std::mt19937 rng(7);
    for (int round = 0; round < 500; ++round) {
        const int bars = 1 + static_cast<int>(rng() % 30);
        std::vector<glm::dvec2> c{{0, 0}, {static_cast<double>(bars), 0}};
        int height = 0;
        for (int i = bars; i > 0; --i) {
            int h;
            do h = 1 + static_cast<int>(rng() % 4);
            while (h == height);
            height = h;
            c.emplace_back(i, h);
            c.emplace_back(i - 1, h);
        }
        // Bars of equal height meet in a straight line; skip the middle corners.
        std::vector<glm::dvec2> cleaned;
        for (const auto& q : c) cleaned.push_back(q);
        const auto p = in_xy(cleaned);
        auto t = triangulate_polygon(p);
        ASSERT_NE(t.kind, Kind::NotSimple) << "round " << round;
        expect_covers(p, t, p.size());
        if (HasFailure()) return;
    }
}

TEST(PolygonTriangulation, RepeatedCornersAreSkipped) {
    const auto p = in_xy({{0, 0}, {0, 0}, {2, 0}, {2, 2}, {1, 1}, {1, 1}, {0, 2}, {0, 0}});
    auto t = triangulate_polygon(p);
    ASSERT_EQ(t.triangles.size(), 3u);  // five distinct corners
    for (const auto& tri : t.triangles)
        EXPECT_GT(glm::length(glm::cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]])), 0.0);
}

TEST(PolygonTriangulation, ClockwiseFacesKeepTheirWinding) {
    auto c = star(12);
    std::reverse(c.begin(), c.end());
    const auto p = in_xy(c);
    auto t = triangulate_polygon(p);
    EXPECT_EQ(t.kind, Kind::General);
    expect_covers(p, t, 12);  // each triangle's normal points to -z, as the face's
}

// A face that is not planar is triangulated in the plane it is closest to:
// an L shape bent along its corner, far from the origin.
TEST(PolygonTriangulation, FacesThatAreNotPlanar) {
    std::vector<sg::Vec3> p;
    for (const auto& c : std::vector<glm::dvec2>{{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})
        p.emplace_back(1e6 + c.x, 2e6 + c.y, 3e6 + 0.05 * c.x * c.y);
    auto t = triangulate_polygon(p);
    EXPECT_EQ(t.kind, Kind::General);
    ASSERT_EQ(t.triangles.size(), 4u);
    for (const auto& tri : t.triangles) EXPECT_GT(glm::cross(p[tri[1]] - p[tri[0]], p[tri[2]] - p[tri[0]]).z, 0.0);
}

TEST(PolygonTriangulation, FacesThatCrossThemselvesBecomeAFan) {
    // A bow tie, and a star polygon drawn in one stroke (a pentagram).
    auto bow_tie = triangulate_polygon(in_xy({{0, 0}, {2, 2}, {2, 0}, {0, 2}, {-1, 1}}));
    EXPECT_EQ(bow_tie.kind, Kind::NotSimple);
    EXPECT_EQ(bow_tie.triangles.size(), 3u);
    std::vector<glm::dvec2> pentagram;
    for (int i = 0; i < 5; ++i) pentagram.emplace_back(std::cos(4 * kPi * i / 5), std::sin(4 * kPi * i / 5));
    auto t = triangulate_polygon(in_xy(pentagram));
    EXPECT_EQ(t.kind, Kind::NotSimple);
    EXPECT_EQ(t.triangles.size(), 3u);
}

TEST(PolygonTriangulation, FacesWithoutAreaGiveNoTriangles) {
    EXPECT_EQ(triangulate_polygon(in_xy({{0, 0}, {1, 1}, {2, 2}, {3, 3}})).kind, Kind::NoArea);
    EXPECT_TRUE(triangulate_polygon(in_xy({{0, 0}, {1, 1}, {2, 2}, {3, 3}})).triangles.empty());
    EXPECT_EQ(triangulate_polygon(in_xy({{1, 1}, {1, 1}, {1, 1}, {2, 2}})).kind, Kind::NoArea);
    // A figure eight of two equal loops encloses no net area.
    EXPECT_EQ(triangulate_polygon(in_xy({{0, 0}, {1, 1}, {2, 0}, {2, 1}, {1, 0}, {0, 1}})).kind, Kind::NoArea);
}

}  // namespace
}  // namespace lancer::parse
