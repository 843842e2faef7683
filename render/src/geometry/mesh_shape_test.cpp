// Checks of the triangle mesh shape (mesh_shape.h) against closed forms: a
// cube and an icosphere whose insides are known half-space tests, lines
// exactly through shared edges and vertices, crossings against a brute
// force loop over all triangles, open and degenerate meshes, and scales
// 1e-4 .. 1e4.
#include "geometry/mesh_shape.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <map>
#include <random>

#include "geometry/shape_test_support.h"

namespace lancer {
namespace {

using test::sorted_crossings;
using Face = MeshShapeParameters::Face;

Face face_of(int a, int b, int c) {
    Face f;
    f.position[0] = a;
    f.position[1] = b;
    f.position[2] = c;
    return f;
}

// The cube [-h, h]^3, two triangles a side, counter-clockwise seen from
// outside (so lancer's cross(p1 - p0, p2 - p0) points out).
MeshShapeParameters cube_mesh(double h, std::optional<DVec3> inside_vector) {
    MeshShapeParameters mesh;
    for (int i = 0; i < 8; ++i) mesh.positions.push_back(h * DVec3(i & 1 ? 1 : -1, i & 2 ? 1 : -1, i & 4 ? 1 : -1));
    // Corner index bits: x = 1, y = 2, z = 4. Each quad counter-clockwise from outside.
    const int quads[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
    for (const auto& q : quads) {
        mesh.faces.push_back(face_of(q[0], q[1], q[2]));
        mesh.faces.push_back(face_of(q[0], q[2], q[3]));
    }
    mesh.inside_vector = inside_vector;
    return mesh;
}

// An icosahedron subdivided `levels` times, corners on the sphere of
// `radius`, outward winding.
MeshShapeParameters icosphere_mesh(int levels, double radius, std::optional<DVec3> inside_vector) {
    MeshShapeParameters mesh;
    const double g = (1.0 + std::sqrt(5.0)) / 2.0;
    const DVec3 base[12] = {{-1, g, 0},  {1, g, 0},  {-1, -g, 0}, {1, -g, 0}, {0, -1, g},  {0, 1, g},
                            {0, -1, -g}, {0, 1, -g}, {g, 0, -1},  {g, 0, 1},  {-g, 0, -1}, {-g, 0, 1}};
    for (const DVec3& p : base) mesh.positions.push_back(glm::normalize(p));
    std::vector<std::array<int, 3>> faces = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11},
                                             {1, 5, 9},  {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                                             {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},
                                             {4, 9, 5},  {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
    for (int level = 0; level < levels; ++level) {
        std::map<std::pair<int, int>, int> midpoints;
        auto midpoint = [&](int a, int b) {
            const auto key = std::minmax(a, b);
            auto found = midpoints.find(key);
            if (found != midpoints.end()) return found->second;
            mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
            const int index = int(mesh.positions.size()) - 1;
            midpoints.emplace(key, index);
            return index;
        };
        std::vector<std::array<int, 3>> finer;
        for (const auto& f : faces) {
            const int ab = midpoint(f[0], f[1]), bc = midpoint(f[1], f[2]), ca = midpoint(f[2], f[0]);
            finer.push_back({f[0], ab, ca});
            finer.push_back({f[1], bc, ab});
            finer.push_back({f[2], ca, bc});
            finer.push_back({ab, bc, ca});
        }
        faces = std::move(finer);
    }
    for (DVec3& p : mesh.positions) p *= radius;
    for (const auto& f : faces) mesh.faces.push_back(face_of(f[0], f[1], f[2]));
    mesh.inside_vector = inside_vector;
    return mesh;
}

// Signed distance of p to the convex mesh's solid (negative inside): the
// largest distance past any face plane.
double convex_signed_distance(const MeshShapeParameters& mesh, const DVec3& p) {
    double largest = -INFINITY;
    for (const Face& f : mesh.faces) {
        const DVec3 &a = mesh.positions[f.position[0]], &b = mesh.positions[f.position[1]],
                    &c = mesh.positions[f.position[2]];
        const DVec3 n = glm::normalize(glm::cross(b - a, c - a));
        largest = std::max(largest, glm::dot(p - a, n));
    }
    return largest;
}

// Moller-Trumbore over every triangle: an independent answer for lines in
// general position.
std::vector<double> brute_force_crossings(const MeshShapeParameters& mesh, const DVec3& o, const DVec3& d, double t_min,
                                          double t_max) {
    std::vector<double> result;
    for (const Face& f : mesh.faces) {
        const DVec3 &a = mesh.positions[f.position[0]], &b = mesh.positions[f.position[1]],
                    &c = mesh.positions[f.position[2]];
        const DVec3 e1 = b - a, e2 = c - a, pv = glm::cross(d, e2);
        const double det = glm::dot(e1, pv);
        if (det == 0.0) continue;
        const DVec3 tv = o - a;
        const double u = glm::dot(tv, pv) / det;
        const DVec3 qv = glm::cross(tv, e1);
        const double v = glm::dot(d, qv) / det;
        const double t = glm::dot(e2, qv) / det;
        if (u >= 0 && v >= 0 && u + v <= 1 && t > t_min && t < t_max) result.push_back(t);
    }
    std::sort(result.begin(), result.end());
    return result;
}

DVec3 random_unit(std::mt19937& rng) {
    std::normal_distribution<double> normal;
    for (;;) {
        const DVec3 v(normal(rng), normal(rng), normal(rng));
        if (glm::length(v) > 1e-3) return glm::normalize(v);
    }
}

// Inside vectors along the cube's axes, face diagonals and body diagonals:
// from grid points their rays run exactly through the cube's edges, the
// triangles' diagonals and its corners.
const std::vector<DVec3> kLatticeDirections = {{1, 0, 0},   {0, -1, 0}, {0, 0, 1}, {0, 1, 1},  {0, 1, -1},
                                               {1, 1, 0},   {-1, 0, 1}, {1, 1, 1}, {1, -1, 1}, {-1, -1, 1},
                                               {-1, 1, -1}, {2, 1, 0},  {1, 2, 2}};

TEST(MeshShape, CubeInsideAtRandomPoints) {
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> coordinate(-2.0, 2.0);
    for (const DVec3& direction : {DVec3(0.3, 0.5, 0.7), DVec3(1, 0, 0), DVec3(0, 1, 1), DVec3(1, 1, 1)}) {
        const auto cube = make_mesh_shape(cube_mesh(1.0, direction));
        ASSERT_TRUE(cube);
        for (int i = 0; i < 2000; ++i) {
            const DVec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
            const double m = std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z)));
            if (std::fabs(m - 1.0) < 1e-9) continue;
            EXPECT_EQ(cube->inside(p), m < 1.0) << p.x << " " << p.y << " " << p.z;
        }
    }
}

TEST(MeshShape, CubeInsideOnLatticeRaysThroughEdgesAndCorners) {
    // Every grid point not on the surface, every lattice direction: the
    // rays pass exactly through shared edges and corners and run along
    // faces; the parity must still be the point's.
    const double steps[] = {-1.5, -1.0, -0.5, 0.0, 0.5, 1.0, 1.5};
    int checked = 0;
    for (const DVec3& direction : kLatticeDirections) {
        const auto cube = make_mesh_shape(cube_mesh(1.0, direction));
        for (double x : steps)
            for (double y : steps)
                for (double z : steps) {
                    const DVec3 p(x, y, z);
                    const double m = std::max(std::fabs(x), std::max(std::fabs(y), std::fabs(z)));
                    const bool on_surface = m == 1.0;
                    const bool inside = cube->inside(p);  // on the surface: any answer, no crash
                    if (on_surface) continue;
                    EXPECT_EQ(inside, m < 1.0) << "p " << x << " " << y << " " << z << " v " << direction.x << " "
                                               << direction.y << " " << direction.z;
                    ++checked;
                }
    }
    EXPECT_GT(checked, 2000);
}

TEST(MeshShape, IcosphereInsideAtRandomPoints) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<double> coordinate(-1.3, 1.3);
    const MeshShapeParameters parameters = icosphere_mesh(2, 1.0, std::nullopt);
    for (int trial = 0; trial < 4; ++trial) {
        MeshShapeParameters mesh = parameters;
        mesh.inside_vector = random_unit(rng);
        const auto sphere = make_mesh_shape(mesh);
        ASSERT_TRUE(sphere);
        for (int i = 0; i < 1500; ++i) {
            const DVec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
            const double distance = convex_signed_distance(parameters, p);
            if (std::fabs(distance) < 1e-9) continue;
            EXPECT_EQ(sphere->inside(p), distance < 0.0);
        }
    }
}

TEST(MeshShape, IcosphereInsideAlongVertexAndEdgeDirections) {
    // From the centre towards every corner and every edge midpoint: the
    // ray meets the surface at (or within rounding of) a shared vertex or
    // edge, and once.
    const MeshShapeParameters parameters = icosphere_mesh(1, 2.0, std::nullopt);
    std::vector<DVec3> directions = parameters.positions;
    for (const Face& f : parameters.faces)
        for (int k = 0; k < 3; ++k)
            directions.push_back(parameters.positions[f.position[k]] + parameters.positions[f.position[(k + 1) % 3]]);
    for (const DVec3& direction : directions) {
        MeshShapeParameters mesh = parameters;
        mesh.inside_vector = direction;
        const auto sphere = make_mesh_shape(mesh);
        EXPECT_TRUE(sphere->inside(DVec3(0.0)));
        EXPECT_TRUE(sphere->inside(DVec3(0.25, -0.5, 0.125)));
        const DVec3 unit = glm::normalize(direction);
        EXPECT_FALSE(sphere->inside(-5.0 * unit));  // outside, looking through the sphere: two crossings
        EXPECT_FALSE(sphere->inside(5.0 * unit));
        EXPECT_EQ(sorted_crossings(*sphere, DVec3(0.0), direction).size(), 1u);
    }
}

TEST(MeshShape, LinesAimedAtCornersAndEdgesFromAnywhere) {
    // From random points at the mesh's corners and edge midpoints: after
    // rounding the lines pass within an ulp of them, where the edge signs
    // need the exact fallback to stay consistent around a corner.
    const MeshShapeParameters parameters = icosphere_mesh(2, 1.0, std::nullopt);
    std::vector<DVec3> targets = parameters.positions;
    for (const Face& f : parameters.faces)
        targets.push_back(0.5 * (parameters.positions[f.position[0]] + parameters.positions[f.position[1]]));
    std::mt19937 rng(23);
    std::uniform_real_distribution<double> coordinate(-1.2, 1.2);
    MeshShapeParameters mesh = parameters;
    mesh.inside_vector = DVec3(1, 0, 0);
    const auto sphere = make_mesh_shape(mesh);
    int wrong_parity = 0, wrong_inside = 0;
    for (int i = 0; i < 20000; ++i) {
        const DVec3 o(coordinate(rng), coordinate(rng), coordinate(rng));
        const DVec3& target = targets[std::size_t(i) % targets.size()];
        const DVec3 d = target - o;
        if (sorted_crossings(*sphere, o, d, -INFINITY, INFINITY).size() % 2 != 0) ++wrong_parity;
        const double distance = convex_signed_distance(parameters, o);
        if (std::fabs(distance) < 1e-9) continue;
        MeshShapeParameters aimed = parameters;
        if (i % 50 == 0) {
            // Inside along the aimed direction (a rebuild per point: only some).
            aimed.inside_vector = d;
            if (make_mesh_shape(aimed)->inside(o) != (distance < 0.0)) ++wrong_inside;
        }
    }
    EXPECT_EQ(wrong_parity, 0);
    EXPECT_EQ(wrong_inside, 0);
}

TEST(MeshShape, EdgeSignsAreExact) {
    // The line x = y = 0 passes eps^2 to the right of the edge P -> Q
    // (eps = 2^-52), where the rounded edge function is exactly 0: the
    // exact sign puts the crossing on the right-hand triangle.
    const double eps = std::ldexp(1.0, -52);
    MeshShapeParameters mesh;
    mesh.positions = {{1 + eps, 1, 0}, {-(1 + 2 * eps), -(1 + eps), 0}, {1, -1, 1}, {-1, 1, -1}};
    mesh.faces = {face_of(0, 1, 2), face_of(1, 0, 3)};  // left of P -> Q, right of it
    const auto sheet = make_mesh_shape(mesh);
    ShapeCrossings all;
    sheet->crossings(DVec3(0, 0, -5), DVec3(0, 0, 1), 0.0, INFINITY, all);
    ASSERT_EQ(all.count, 1);
    EXPECT_EQ(all.items[0].face, 1);
    EXPECT_NEAR(all.items[0].t, 5.0, 1e-14);
}

TEST(MeshShape, CrossingsThroughSharedEdgesAndCornersCountOnce) {
    const auto cube = make_mesh_shape(cube_mesh(1.0, std::nullopt));
    // Through both x faces' centres, on their diagonals.
    auto t = sorted_crossings(*cube, DVec3(-3, 0, 0), DVec3(1, 0, 0));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_DOUBLE_EQ(t[0], 2.0);
    EXPECT_DOUBLE_EQ(t[1], 4.0);
    // Corner to corner.
    t = sorted_crossings(*cube, DVec3(-3, -3, -3), DVec3(1, 1, 1));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 2.0, 1e-15);
    EXPECT_NEAR(t[1], 4.0, 1e-15);
    // Through the middle of the edge between the +y and +z faces.
    t = sorted_crossings(*cube, DVec3(0.25, -2, -2), DVec3(0, 1, 1));
    ASSERT_EQ(t.size(), 2u);
    EXPECT_NEAR(t[0], 1.0, 1e-15);
    EXPECT_NEAR(t[1], 3.0, 1e-15);
    // Every lattice line through the cube: an even count (a closed surface).
    const double steps[] = {-1.0, -0.5, 0.0, 0.5, 1.0};
    for (const DVec3& direction : kLatticeDirections)
        for (double x : steps)
            for (double y : steps)
                for (double z : steps) {
                    const DVec3 o = DVec3(x, y, z) - 5.0 * direction;
                    const auto all = sorted_crossings(*cube, o, direction, -INFINITY, INFINITY);
                    EXPECT_EQ(all.size() % 2, 0u) << x << " " << y << " " << z;
                }
}

TEST(MeshShape, CrossingsMatchBruteForce) {
    std::mt19937 rng(3);
    std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
    // An icosphere and a soup of random, overlapping triangles.
    std::vector<MeshShapeParameters> meshes = {icosphere_mesh(3, 1.0, DVec3(0, 0, 1))};
    MeshShapeParameters soup;
    for (int i = 0; i < 300; ++i) {
        const DVec3 centre(coordinate(rng), coordinate(rng), coordinate(rng));
        for (int k = 0; k < 3; ++k) soup.positions.push_back(centre + 0.6 * random_unit(rng));
        soup.faces.push_back(face_of(3 * i, 3 * i + 1, 3 * i + 2));
    }
    meshes.push_back(soup);
    for (const MeshShapeParameters& mesh : meshes) {
        const auto shape = make_mesh_shape(mesh);
        ASSERT_TRUE(shape);
        for (int i = 0; i < 500; ++i) {
            const DVec3 o(2.0 * coordinate(rng), 2.0 * coordinate(rng), 2.0 * coordinate(rng));
            const DVec3 d = random_unit(rng) * std::exp(coordinate(rng));  // not unit
            const double t_min = i % 2 ? 0.0 : 0.5, t_max = i % 3 ? INFINITY : 3.0;
            const auto expected = brute_force_crossings(mesh, o, d, t_min, t_max);
            const auto found = sorted_crossings(*shape, o, d, t_min, t_max);
            const std::size_t kept = std::min<std::size_t>(expected.size(), ShapeCrossings::kCapacity);
            ASSERT_EQ(found.size(), kept);
            for (std::size_t k = 0; k < kept; ++k) EXPECT_NEAR(found[k], expected[k], 1e-12 * (1.0 + expected[k]));
        }
    }
}

// `layers` unit squares stacked along y at y = 0, 1, 2, ...
MeshShapeParameters stacked_squares(int layers, std::optional<DVec3> inside_vector) {
    MeshShapeParameters mesh;
    for (int layer = 0; layer < layers; ++layer) {
        const int base = int(mesh.positions.size());
        for (int corner = 0; corner < 4; ++corner)
            mesh.positions.push_back(DVec3(corner & 1 ? 1 : -1, layer, corner & 2 ? 1 : -1));
        mesh.faces.push_back(face_of(base, base + 2, base + 3));
        mesh.faces.push_back(face_of(base, base + 3, base + 1));
    }
    mesh.inside_vector = inside_vector;
    return mesh;
}

TEST(MeshShape, MoreThanSixteenCrossingsKeepTheNearest) {
    const auto stack = make_mesh_shape(stacked_squares(40, std::nullopt));
    const auto up = sorted_crossings(*stack, DVec3(0.1, -0.5, 0.2), DVec3(0, 1, 0));
    ASSERT_EQ(up.size(), std::size_t(ShapeCrossings::kCapacity));
    for (int k = 0; k < ShapeCrossings::kCapacity; ++k) EXPECT_DOUBLE_EQ(up[k], k + 0.5);
    const auto down = sorted_crossings(*stack, DVec3(0.1, 39.5, 0.2), DVec3(0, -2, 0), 1.0, INFINITY);
    ASSERT_EQ(down.size(), std::size_t(ShapeCrossings::kCapacity));
    for (int k = 0; k < ShapeCrossings::kCapacity; ++k) EXPECT_DOUBLE_EQ(down[k], 0.5 * (k + 2) + 0.25);
    // A partly filled list only gets the room left.
    ShapeCrossings partial;
    for (int k = 0; k < 10; ++k) partial.add(100.0 + k, -1);
    stack->crossings(DVec3(0.1, -0.5, 0.2), DVec3(0, 1, 0), 0.0, INFINITY, partial);
    ASSERT_EQ(partial.count, ShapeCrossings::kCapacity);
    EXPECT_DOUBLE_EQ(partial.items[10].t, 0.5);
    EXPECT_DOUBLE_EQ(partial.items[15].t, 5.5);
}

TEST(MeshShape, InsideCountsEveryCrossingPastTheCap) {
    // 41 layers above the point: odd, inside; 40: even, outside.
    EXPECT_TRUE(make_mesh_shape(stacked_squares(41, DVec3(0, 1, 0)))->inside(DVec3(0.3, -1, 0.1)));
    EXPECT_FALSE(make_mesh_shape(stacked_squares(40, DVec3(0, 1, 0)))->inside(DVec3(0.3, -1, 0.1)));
    EXPECT_TRUE(make_mesh_shape(stacked_squares(40, DVec3(0, 1, 0)))->inside(DVec3(0.3, 0.5, 0.1)));
}

TEST(MeshShape, NoInsideWithoutInsideVector) {
    const auto cube = make_mesh_shape(cube_mesh(1.0, std::nullopt));
    EXPECT_FALSE(cube->inside(DVec3(0.0)));
    EXPECT_FALSE(cube->inside(DVec3(0.5, -0.2, 0.1)));
    const auto zero = make_mesh_shape(cube_mesh(1.0, DVec3(0.0)));
    EXPECT_FALSE(zero->inside(DVec3(0.0)));
    const auto not_finite = make_mesh_shape(cube_mesh(1.0, DVec3(NAN, 0, 1)));
    EXPECT_FALSE(not_finite->inside(DVec3(0.0)));
    // A lone triangle (POV's triangle) has no inside either, but crossings.
    MeshShapeParameters triangle;
    triangle.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    triangle.faces = {face_of(0, 1, 2)};
    const auto lone = make_mesh_shape(triangle);
    EXPECT_FALSE(lone->inside(DVec3(0.2, 0.2, -1)));
    const auto t = sorted_crossings(*lone, DVec3(0.2, 0.2, -1), DVec3(0, 0, 1));
    ASSERT_EQ(t.size(), 1u);
    EXPECT_DOUBLE_EQ(t[0], 1.0);
}

TEST(MeshShape, OpenMeshInsideIsTheRayParity) {
    // One square at y = 0 with inside_vector +y: points under it are
    // "inside", as POV's count makes them.
    const auto square = make_mesh_shape(stacked_squares(1, DVec3(0, 1, 0)));
    EXPECT_TRUE(square->inside(DVec3(0.5, -3, -0.5)));
    EXPECT_FALSE(square->inside(DVec3(0.5, 3, -0.5)));
    EXPECT_FALSE(square->inside(DVec3(1.5, -3, -0.5)));
    // Under the shared diagonal: one crossing, not two.
    EXPECT_TRUE(square->inside(DVec3(0.5, -3, 0.5)));
    EXPECT_TRUE(square->inside(DVec3(-0.25, -3, -0.25)));
    // The cube without its top: a ray up through the hole is outside.
    MeshShapeParameters open_box = cube_mesh(1.0, DVec3(0, 1, 0));
    open_box.faces.erase(open_box.faces.begin() + 6, open_box.faces.begin() + 8);  // the +y quad
    const auto box = make_mesh_shape(open_box);
    EXPECT_FALSE(box->inside(DVec3(0.2, 0.0, 0.3)));
    EXPECT_TRUE(box->inside(DVec3(0.2, -2.0, 0.3)));  // the bottom only
}

TEST(MeshShape, DegenerateTrianglesAreIgnored) {
    MeshShapeParameters mesh = cube_mesh(1.0, DVec3(0.2, 0.3, 1.0));
    const int extra = int(mesh.positions.size());
    mesh.positions.push_back(DVec3(0.5, 0.5, 0.5));
    mesh.positions.push_back(DVec3(0.0, 0.0, 0.0));
    mesh.positions.push_back(DVec3(NAN, 0.0, 0.0));
    mesh.faces.push_back(face_of(0, 0, 1));          // repeated corner
    mesh.faces.push_back(face_of(0, 7, extra + 1));  // collinear (the diagonal through the origin)
    mesh.faces.push_back(face_of(0, 7, extra));      // collinear again
    mesh.faces.push_back(face_of(0, 1, 99));         // out of range
    mesh.faces.push_back(face_of(-1, 1, 2));         // negative
    mesh.faces.push_back(face_of(0, 1, extra + 2));  // not finite
    const auto cube = make_mesh_shape(mesh);
    ASSERT_TRUE(cube);
    EXPECT_TRUE(cube->inside(DVec3(0.0)));
    EXPECT_TRUE(cube->inside(DVec3(0.5, 0.5, 0.5)));
    EXPECT_FALSE(cube->inside(DVec3(1.5, 0.5, 0.5)));
    auto t = sorted_crossings(*cube, DVec3(-2, -2, -2), DVec3(1, 1, 1), -INFINITY, INFINITY);
    EXPECT_EQ(t.size(), 2u);
    DVec3 lower, upper;
    ASSERT_TRUE(cube->bounds(lower, upper));
    EXPECT_EQ(lower, DVec3(-1.0));
    EXPECT_EQ(upper, DVec3(1.0));
    // Nothing usable: no shape.
    MeshShapeParameters none;
    none.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}};
    none.faces = {face_of(0, 1, 2), face_of(0, 0, 0)};
    EXPECT_EQ(make_mesh_shape(none), nullptr);
    EXPECT_EQ(make_mesh_shape(MeshShapeParameters{}), nullptr);
}

TEST(MeshShape, SurfaceNormalsAndUv) {
    MeshShapeParameters mesh;
    mesh.positions = {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}};
    mesh.faces = {face_of(0, 1, 2), face_of(0, 2, 1)};
    mesh.normals = {{0, 0, 2}, {1, 0, 1}, {0, 1, 1}};
    mesh.uvs = {{0.0, 0.0}, {1.0, 0.0}, {0.0, 4.0}};
    mesh.faces[1].normal[0] = 0;
    mesh.faces[1].normal[1] = 2;
    mesh.faces[1].normal[2] = 1;
    mesh.faces[1].uv[0] = 0;
    mesh.faces[1].uv[1] = 2;
    mesh.faces[1].uv[2] = 1;
    const auto shape = make_mesh_shape(mesh);
    // Flat face 0: cross(p1 - p0, p2 - p0) = +z; (u, v) the barycentric weights of corners 1 and 2.
    SurfaceGeometry g = shape->surface(DVec3(0.5, 0.25, 1e-3), 0);
    EXPECT_EQ(g.point.z, 0.0);
    EXPECT_DOUBLE_EQ(g.point.x, 0.5);
    EXPECT_NEAR(g.normal.z, 1.0, 1e-15);
    EXPECT_NEAR(g.uv.x, 0.25f, 1e-6f);
    EXPECT_NEAR(g.uv.y, 0.125f, 1e-6f);
    // Smooth face 1 (corners 0, 2, 1): normals blended and normalised, uvs blended.
    g = shape->surface(DVec3(0.5, 0.25, 0.0), 1);
    const double b0 = 1.0 - 0.125 - 0.25, b_corner2 = 0.125, b_corner1 = 0.25;  // weights of positions 0, 2, 1
    const DVec3 blended = b0 * mesh.normals[0] + b_corner2 * mesh.normals[2] + b_corner1 * mesh.normals[1];
    EXPECT_NEAR(glm::length(g.shading_normal - glm::normalize(blended)), 0.0, 1e-12);
    EXPECT_NEAR(std::fabs(g.normal.z), 1.0, 1e-15);  // the facet's own, which rays leave across
    EXPECT_NEAR(g.uv.x, float(b_corner1 * 1.0), 1e-6f);
    EXPECT_NEAR(g.uv.y, float(b_corner2 * 4.0), 1e-6f);
    // A face index out of range gives finite output.
    g = shape->surface(DVec3(0.5, 0.25, 0.0), 7);
    EXPECT_TRUE(std::isfinite(g.normal.x + g.normal.y + g.normal.z));
}

TEST(MeshShape, FaceIndexIsTheInputFace) {
    MeshShapeParameters mesh = cube_mesh(1.0, std::nullopt);
    mesh.faces.insert(mesh.faces.begin(), face_of(0, 0, 0));  // dropped, yet numbered
    const auto cube = make_mesh_shape(mesh);
    ShapeCrossings all;
    cube->crossings(DVec3(0.3, 0.2, -5), DVec3(0, 0, 1), 0.0, INFINITY, all);
    ASSERT_EQ(all.count, 2);
    for (int k = 0; k < 2; ++k) {
        const int face = all.items[k].face;
        ASSERT_GE(face, 1);
        const SurfaceGeometry g = cube->surface(DVec3(0.3, 0.2, -5) + all.items[k].t * DVec3(0, 0, 1), face);
        // The -z face at t = 4 faces -z, the +z face at t = 6 faces +z.
        EXPECT_NEAR(g.normal.z, all.items[k].t < 5 ? -1.0 : 1.0, 1e-15);
    }
}

TEST(MeshShape, RaysFromTheSurfaceAndGrazing) {
    const auto sphere = make_mesh_shape(icosphere_mesh(2, 1.0, DVec3(0.1, 0.2, 1)));
    std::mt19937 rng(5);
    for (int i = 0; i < 300; ++i) {
        const DVec3 o = 3.0 * random_unit(rng);
        const DVec3 d = -o + 0.5 * random_unit(rng);
        ShapeCrossing hit;
        if (!sphere->nearest(o, d, 0.0, INFINITY, hit)) continue;
        const SurfaceGeometry g = sphere->surface(o + hit.t * d, hit.face);
        // Onwards from the hit: outwards nothing, inwards exactly one crossing.
        const double t_min = 1e-9;
        EXPECT_TRUE(sorted_crossings(*sphere, g.point, g.normal, t_min).empty());
        const DVec3 inwards = -g.normal + 0.3 * random_unit(rng);
        if (glm::dot(inwards, g.normal) < -0.1) {
            EXPECT_EQ(sorted_crossings(*sphere, g.point, inwards, t_min).size(), 1u);
        }
    }
    // In the plane of the cube's top face: tangent, an even count.
    const auto cube = make_mesh_shape(cube_mesh(1.0, std::nullopt));
    for (const DVec3& d : {DVec3(1, 0, 0), DVec3(1, 0, 1), DVec3(1, 0, 0.3)}) {
        const auto t = sorted_crossings(*cube, DVec3(-3, 1, 0.2) - 0.0 * d, d, -INFINITY, INFINITY);
        EXPECT_EQ(t.size() % 2, 0u);
    }
    // Rays from points on faces, edges and corners: finite answers.
    for (const DVec3& p : {DVec3(1, 0.3, 0.2), DVec3(1, 1, 0.2), DVec3(1, 1, 1), DVec3(0, 0, -1)})
        for (const DVec3& v : kLatticeDirections) {
            (void)cube->inside(p);
            for (double t : sorted_crossings(*cube, p, v, -INFINITY, INFINITY)) EXPECT_TRUE(std::isfinite(t));
        }
}

TEST(MeshShape, Scales) {
    for (double scale : {1e-4, 1e-2, 1.0, 1e2, 1e4}) {
        const auto cube = make_mesh_shape(cube_mesh(scale, DVec3(0.1, 1, 0.3)));
        const auto sphere = make_mesh_shape(icosphere_mesh(2, scale, DVec3(1, 1, 1)));
        std::mt19937 rng(13);
        std::uniform_real_distribution<double> coordinate(-1.5, 1.5);
        for (int i = 0; i < 300; ++i) {
            const DVec3 p(coordinate(rng), coordinate(rng), coordinate(rng));
            const double m = std::max(std::fabs(p.x), std::max(std::fabs(p.y), std::fabs(p.z)));
            if (std::fabs(m - 1.0) > 1e-6) {
                EXPECT_EQ(cube->inside(scale * p), m < 1.0);
            }
        }
        for (double direction_scale : {1e-3, 1.0, 1e3}) {
            const DVec3 d = direction_scale * scale * DVec3(1, 0, 0);
            const auto t = sorted_crossings(*cube, scale * DVec3(-3, 0.3, -0.4), d);
            ASSERT_EQ(t.size(), 2u);
            EXPECT_NEAR(t[0], 2.0 / direction_scale, 1e-13 * t[0]);
            EXPECT_NEAR(t[1], 4.0 / direction_scale, 1e-13 * t[1]);
            // The icosphere against the brute force.
            const MeshShapeParameters parameters = icosphere_mesh(2, scale, std::nullopt);
            const DVec3 o = scale * DVec3(-3, 0.1, 0.05);
            const auto expected = brute_force_crossings(parameters, o, d, 0.0, INFINITY);
            const auto found = sorted_crossings(*sphere, o, d);
            ASSERT_EQ(found.size(), expected.size());
            for (std::size_t k = 0; k < found.size(); ++k) EXPECT_NEAR(found[k], expected[k], 1e-12 * expected[k]);
        }
        DVec3 lower, upper;
        ASSERT_TRUE(cube->bounds(lower, upper));
        EXPECT_EQ(upper, DVec3(scale));
    }
}

TEST(MeshShape, LargeMeshBuildsAndTracesFast) {
    const MeshShapeParameters mesh = icosphere_mesh(7, 1.0, DVec3(0.3, 0.2, 1));  // 327,680 triangles
    const auto start = std::chrono::steady_clock::now();
    const auto sphere = make_mesh_shape(mesh);
    const double build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    std::mt19937 rng(17);
    const int rays = 20000;
    int inside = 0, hits = 0;
    const auto trace_start = std::chrono::steady_clock::now();
    for (int i = 0; i < rays; ++i) {
        const DVec3 o = 2.0 * random_unit(rng), d = -o + random_unit(rng);
        ShapeCrossings all;
        sphere->crossings(o, d, 0.0, INFINITY, all);
        hits += all.count;
        inside += sphere->inside(0.9 * random_unit(rng)) ? 1 : 0;
    }
    const double per_ray = std::chrono::duration<double>(std::chrono::steady_clock::now() - trace_start).count() / rays;
    std::printf("build %.3f s for %zu triangles, %.2f us per crossings + inside\n", build_seconds, mesh.faces.size(),
                per_ray * 1e6);
    EXPECT_EQ(inside, rays);
    EXPECT_GT(hits, rays);
    EXPECT_LT(build_seconds, 5.0);
    EXPECT_LT(per_ray, 1e-4);
}

}  // namespace
}  // namespace lancer
