// Watertightness of triangle meshes (why embree_scene.cpp keeps
// RTC_SCENE_FLAG_ROBUST): rays from inside a closed mesh aimed exactly at
// points of its shared edges must always hit it, whatever the scale and the
// distance from the origin, for a mesh in world space and an instanced one.
//
// Measured with bare Embree 3.13 on this very mesh (bench/README.md): without
// the flag 3-7% of edge-aimed rays and ~10-20% of vertex-aimed rays leak;
// with it, no edge-aimed ray leaks. Embree's robust (Pluecker) test is not
// watertight exactly at vertices: ~0.1-0.2% of rays aimed at a vertex in
// float precision still escape, which this test bounds rather than hides.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <random>
#include <tuple>

#include "lancer/host/scene_compiler.h"
#include "lancer/render_scene.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;

// A subdivided octahedron pushed onto a bumpy sphere: closed, consistently
// wound, every edge shared by two triangles, irregular float coordinates.
sg::MeshRef closed_mesh(double scale, const glm::dvec3& centre) {
    auto mesh = std::make_shared<sg::TriangleMesh>();
    std::map<std::tuple<int, int, int>, int> ids;
    const int n = 16;
    auto vertex = [&](int a, int b, int c, int sx, int sy, int sz) {
        const auto key = std::make_tuple(sx * a, sy * b, sz * c);
        const auto found = ids.find(key);
        if (found != ids.end()) return found->second;
        const glm::dvec3 p(sx * double(a) / n, sy * double(b) / n, sz * double(c) / n);
        const double r = 1.0 + 0.01 * std::sin(13.0 * p.x + 7.0 * p.y + 3.0 * p.z);
        mesh->positions.push_back(centre + scale * r * glm::normalize(p));
        ids[key] = int(mesh->positions.size()) - 1;
        return ids[key];
    };
    auto add = [&](int a, int b, int c) {
        sg::TriangleMesh::Face face;
        face.position[0] = a, face.position[1] = b, face.position[2] = c;
        mesh->faces.push_back(face);
    };
    for (int sx : {-1, 1})
        for (int sy : {-1, 1})
            for (int sz : {-1, 1}) {
                const bool flip = sx * sy * sz < 0;
                auto at = [&](int i, int j) { return vertex(i, j, n - i - j, sx, sy, sz); };
                for (int i = 0; i < n; ++i)
                    for (int j = 0; i + j < n; ++j) {
                        int a = at(i, j), b = at(i + 1, j), c = at(i, j + 1);
                        if (flip) std::swap(b, c);
                        add(a, b, c);
                        if (i + j + 1 < n) {
                            int d = at(i + 1, j + 1), e = at(i + 1, j), f = at(i, j + 1);
                            if (flip) std::swap(e, f);
                            add(e, d, f);
                        }
                    }
            }
    return mesh;
}

struct Leaks {
    int edge_rays = 0, edge_leaks = 0, vertex_rays = 0, vertex_leaks = 0;
};

// Rays from random interior points towards float points of edges and
// vertices, as Embree sees them (world-space floats).
Leaks shoot(const RenderScene& scene, const sg::TriangleMesh& mesh, const glm::dmat4& world_from_object,
            const glm::dvec3& centre, double scale) {
    std::mt19937 rng(99);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    auto world = [&](int index) {
        return Vec3(glm::dvec3(world_from_object * glm::dvec4(mesh.positions[index], 1.0)));
    };
    Leaks leaks;
    for (int k = 0; k < 20000; ++k) {
        const glm::dvec3 jitter(unit(rng) - 0.5, unit(rng) - 0.5, unit(rng) - 0.5);
        const Vec3 origin = Vec3(glm::dvec3(world_from_object * glm::dvec4(centre + 0.5 * scale * jitter, 1.0)));
        const auto& face = mesh.faces[std::size_t(unit(rng) * double(mesh.faces.size()))];
        const int e = int(unit(rng) * 3.0) % 3;
        const Vec3 a = world(face.position[e]), b = world(face.position[(e + 1) % 3]);
        const bool at_vertex = k % 4 == 0;
        const Vec3 target = at_vertex ? a : a + float(unit(rng)) * (b - a);
        Ray ray;
        ray.origin = origin;
        ray.direction = target - origin;  // not normalised: the target is at t = 1 exactly
        Hit hit;
        const bool found = scene.intersect(ray, hit);
        (at_vertex ? leaks.vertex_rays : leaks.edge_rays)++;
        if (!found) (at_vertex ? leaks.vertex_leaks : leaks.edge_leaks)++;
    }
    return leaks;
}

class Watertight : public ::testing::TestWithParam<std::tuple<double, double, bool>> {};

TEST_P(Watertight, RaysAtSharedEdgesNeverLeaveAClosedMesh) {
    const auto [scale, offset, instanced] = GetParam();
    const glm::dvec3 centre(offset, 0.5 * offset, -offset);
    const sg::MeshRef mesh = closed_mesh(scale, instanced ? glm::dvec3(0.0) : centre);
    sg::SceneGraph graph;
    const glm::dmat4 placement = instanced ? glm::translate(glm::dmat4(1.0), centre) *
                                                 glm::rotate(glm::dmat4(1.0), 0.7, glm::dvec3(0.3, 1.0, 0.2))
                                           : glm::dmat4(1.0);
    graph.objects.push_back(mesh_object(mesh, solid_material(glm::dvec3(0.5)), placement));
    // Used twice, the mesh is built once and instanced; the copy sits far off.
    if (instanced)
        graph.objects.push_back(mesh_object(mesh, solid_material(glm::dvec3(0.5)),
                                            glm::translate(glm::dmat4(1.0), centre + glm::dvec3(100.0 * scale))));
    const auto scene = compile_scene(graph);
    const Leaks leaks = shoot(*scene, *mesh, placement, instanced ? glm::dvec3(0.0) : centre, scale);
    EXPECT_EQ(leaks.edge_leaks, 0) << "of " << leaks.edge_rays << " rays aimed at shared edges";
    // Exactly at a vertex Embree's robust test can still let a ray through:
    // bounded, not zero (see the file comment).
    EXPECT_LE(leaks.vertex_leaks, leaks.vertex_rays / 100) << "of " << leaks.vertex_rays << " rays at vertices";
}

INSTANTIATE_TEST_SUITE_P(ScalesAndOffsets, Watertight,
                         ::testing::Combine(::testing::Values(1e-3, 1.0, 1e3), ::testing::Values(0.0, 1e3),
                                            ::testing::Bool()));

}  // namespace
}  // namespace lancer
