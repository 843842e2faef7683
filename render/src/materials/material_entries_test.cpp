// texture_map and block lists of textures lit entry by entry: the scene
// hands each hit the materials of the entries that hold there and their
// blend (materials/material_entries.h).
#include <gtest/gtest.h>

#include "lancer/host/scene_compiler.h"
#include "lancer/material.h"
#include "lancer/render_scene.h"
#include "lancer/shading/material_blend.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;

sg::MaterialRef texture_with_diffuse(double diffuse) {
    auto m = std::make_shared<sg::Material>();
    m->pigment.color.rgb = {1.0, 1.0, 1.0};
    m->finish.diffuse = diffuse;
    return m;
}

// gradient x through [0 A] [1 B] on the plane y = 0.
sg::MaterialRef gradient_map(const sg::MaterialRef& a, const sg::MaterialRef& b) {
    auto m = std::make_shared<sg::Material>();
    m->pattern = sg::Pattern{};
    m->pattern->kind = sg::Pattern::Kind::Gradient;
    m->texture_map.push_back({0.0, a});
    m->texture_map.push_back({1.0, b});
    return m;
}

Hit hit_from_above(const RenderScene& scene, float x, float z = 0.5f) {
    Hit hit;
    EXPECT_TRUE(scene.intersect(make_ray(Vec3(x, 1.0f, z), Vec3(0.0f, -1.0f, 0.0f)), hit));
    return hit;
}

float diffuse_of(const Material* material) {
    return material ? material->parameters().diffuse : -1.0f;
}

TEST(MaterialEntries, MapBlendsTheTwoEntriesAroundTheValueHeavierFirst) {
    sg::SceneGraph graph;
    graph.objects.push_back(
        plane_object({0, 1, 0}, 0.0, gradient_map(texture_with_diffuse(0.2), texture_with_diffuse(0.8))));
    const auto scene = compile_scene(graph);

    const Hit quarter = hit_from_above(*scene, 0.25f);
    EXPECT_FLOAT_EQ(diffuse_of(quarter.material), 0.2f);
    EXPECT_FLOAT_EQ(diffuse_of(quarter.blend_material), 0.8f);
    EXPECT_NEAR(quarter.blend_weight, 0.25f, 1e-6f);

    const Hit most = hit_from_above(*scene, 0.875f);
    EXPECT_FLOAT_EQ(diffuse_of(most.material), 0.8f);
    EXPECT_FLOAT_EQ(diffuse_of(most.blend_material), 0.2f);
    EXPECT_NEAR(most.blend_weight, 0.125f, 1e-6f);
    // Without bumps the second entry keeps the surface's own normal.
    EXPECT_EQ(second_entry(most).shading_normal, most.shading_normal);
    EXPECT_FLOAT_EQ(diffuse_of(second_entry(most).material), 0.2f);
}

TEST(MaterialEntries, BlockListPicksOneEntryPerBlock) {
    auto checker = std::make_shared<sg::Material>();
    checker->pattern = sg::Pattern{};
    checker->pattern->kind = sg::Pattern::Kind::Checker;
    checker->block_textures = {texture_with_diffuse(0.3), texture_with_diffuse(0.7)};
    sg::SceneGraph graph;
    graph.objects.push_back(plane_object({0, 1, 0}, 0.0, checker));
    const auto scene = compile_scene(graph);

    const Hit first = hit_from_above(*scene, 0.5f);
    EXPECT_FLOAT_EQ(diffuse_of(first.material), 0.3f);
    EXPECT_EQ(first.blend_material, nullptr);
    const Hit second = hit_from_above(*scene, 1.5f);
    EXPECT_FLOAT_EQ(diffuse_of(second.material), 0.7f);
    EXPECT_EQ(second.blend_material, nullptr);
}

TEST(MaterialEntries, NestedMapsReachTheInnerEntriesThroughTheOuterPattern) {
    // The outer map is scaled by 4 along x: its value is x / 4, and the
    // inner map's entries are read at the outer pattern's point (x / 4), so
    // the inner gradient runs over x in [0, 4) too.
    const sg::MaterialRef inner = gradient_map(texture_with_diffuse(0.1), texture_with_diffuse(0.5));
    auto outer = std::make_shared<sg::Material>();
    outer->pattern = sg::Pattern{};
    outer->pattern->kind = sg::Pattern::Kind::Gradient;
    outer->pattern->pattern_from_object = glm::scale(glm::dmat4(1.0), glm::dvec3(0.25, 1.0, 1.0));
    outer->texture_map.push_back({0.5, inner});
    outer->texture_map.push_back({0.5, texture_with_diffuse(0.9)});
    sg::SceneGraph graph;
    graph.objects.push_back(plane_object({0, 1, 0}, 0.0, outer));
    const auto scene = compile_scene(graph);

    // x = 1: the outer value 0.25 holds the inner map, whose value is 0.25.
    const Hit low = hit_from_above(*scene, 1.0f);
    EXPECT_FLOAT_EQ(diffuse_of(low.material), 0.1f);
    EXPECT_FLOAT_EQ(diffuse_of(low.blend_material), 0.5f);
    EXPECT_NEAR(low.blend_weight, 0.25f, 1e-6f);
    // x = 3: the outer value 0.75, past the step, is the last entry alone.
    const Hit high = hit_from_above(*scene, 3.0f);
    EXPECT_FLOAT_EQ(diffuse_of(high.material), 0.9f);
    EXPECT_EQ(high.blend_material, nullptr);
}

TEST(MaterialEntries, AverageAndPlainMaterialsAreNotSplit) {
    auto average = std::make_shared<sg::Material>(*gradient_map(texture_with_diffuse(0.2), texture_with_diffuse(0.8)));
    average->average = true;
    sg::SceneGraph graph;
    graph.objects.push_back(plane_object({0, 1, 0}, 0.0, average));
    graph.objects.push_back(sphere_object({0, 5, 0}, 1.0, texture_with_diffuse(0.4)));
    const auto scene = compile_scene(graph);
    EXPECT_EQ(hit_from_above(*scene, 0.25f).blend_material, nullptr);
    Hit sphere;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0.0f, 10.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f)), sphere));
    EXPECT_FLOAT_EQ(diffuse_of(sphere.material), 0.4f);
    EXPECT_EQ(sphere.blend_material, nullptr);
}

}  // namespace
}  // namespace lancer
