// texture_map and block lists of textures lit entry by entry: the scene
// hands each hit the materials of the entries that hold there and their
// blend (materials/material_entries.h).
#include <gtest/gtest.h>

#include <utility>
#include <vector>

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
    m->finish->diffuse = diffuse;
    return m;
}

// gradient x through [0 A] [1 B] on the plane y = 0.
sg::MaterialRef gradient_map(const sg::MaterialRef& a, const sg::MaterialRef& b) {
    auto m = std::make_shared<sg::Material>();
    m->pattern.emplace().kind = sg::Pattern::Kind::Gradient;
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

// The mix's entries at a hit: (diffuse, share), heaviest first.
std::vector<std::pair<float, float>> mix_of(const Hit& hit) {
    std::vector<std::pair<float, float>> out;
    if (hit.mix == nullptr) return {{diffuse_of(hit.material), 1.0f}};
    MaterialMix::Part parts[MaterialMix::kMostParts];
    const int count = mix_parts(hit, parts);
    for (int i = 0; i < count; ++i) out.emplace_back(diffuse_of(parts[i].material), parts[i].weight);
    return out;
}

void expect_mix(const Hit& hit, const std::vector<std::pair<float, float>>& expected) {
    const auto seen = mix_of(hit);
    ASSERT_EQ(seen.size(), expected.size());
    for (std::size_t i = 0; i < seen.size(); ++i) {
        EXPECT_FLOAT_EQ(seen[i].first, expected[i].first) << "entry " << i;
        EXPECT_NEAR(seen[i].second, expected[i].second, 1e-6f) << "entry " << i;
    }
    // The hit's own material is the heaviest entry.
    EXPECT_FLOAT_EQ(diffuse_of(hit.material), expected.front().first);
}

TEST(MaterialEntries, MapBlendsTheTwoEntriesAroundTheValueHeavierFirst) {
    sg::SceneGraph graph;
    graph.objects.push_back(
        plane_object({0, 1, 0}, 0.0, gradient_map(texture_with_diffuse(0.2), texture_with_diffuse(0.8))));
    const auto scene = compile_scene(graph);

    expect_mix(hit_from_above(*scene, 0.25f), {{0.2f, 0.75f}, {0.8f, 0.25f}});
    const Hit most = hit_from_above(*scene, 0.875f);
    expect_mix(most, {{0.8f, 0.875f}, {0.2f, 0.125f}});
    // Without bumps each entry keeps the surface's own normal.
    MaterialMix::Part parts[MaterialMix::kMostParts];
    ASSERT_EQ(mix_parts(most, parts), 2);
    EXPECT_EQ(entry_hit(most, parts[1].material).shading_normal, most.shading_normal);
}

TEST(MaterialEntries, BlockListPicksOneEntryPerBlock) {
    auto checker = std::make_shared<sg::Material>();
    checker->pattern.emplace().kind = sg::Pattern::Kind::Checker;
    checker->block_textures = {texture_with_diffuse(0.3), texture_with_diffuse(0.7)};
    sg::SceneGraph graph;
    graph.objects.push_back(plane_object({0, 1, 0}, 0.0, checker));
    const auto scene = compile_scene(graph);

    const Hit first = hit_from_above(*scene, 0.5f);
    EXPECT_FLOAT_EQ(diffuse_of(first.material), 0.3f);
    EXPECT_EQ(first.mix, nullptr);
    const Hit second = hit_from_above(*scene, 1.5f);
    EXPECT_FLOAT_EQ(diffuse_of(second.material), 0.7f);
    EXPECT_EQ(second.mix, nullptr);
}

TEST(MaterialEntries, NestedMapsReachTheInnerEntriesThroughTheOuterPattern) {
    // The outer map is scaled by 4 along x: its value is x / 4, and the
    // inner map's entries are read at the outer pattern's point (x / 4), so
    // the inner gradient runs over x in [0, 4) too.
    const sg::MaterialRef inner = gradient_map(texture_with_diffuse(0.1), texture_with_diffuse(0.5));
    auto outer = std::make_shared<sg::Material>();
    outer->pattern.emplace().kind = sg::Pattern::Kind::Gradient;
    outer->pattern->pattern_from_object = glm::scale(glm::dmat4(1.0), glm::dvec3(0.25, 1.0, 1.0));
    outer->texture_map.push_back({0.4, inner});
    outer->texture_map.push_back({0.6, texture_with_diffuse(0.9)});
    sg::SceneGraph graph;
    graph.objects.push_back(plane_object({0, 1, 0}, 0.0, outer));
    const auto scene = compile_scene(graph);

    // x = 1: the outer value 0.25 holds the inner map, whose value is 0.25.
    expect_mix(hit_from_above(*scene, 1.0f), {{0.1f, 0.75f}, {0.5f, 0.25f}});
    // x = 2: the outer value 0.5 is halfway: half the inner map (itself at
    // 0.5, half and half) and half the last entry: three entries.
    expect_mix(hit_from_above(*scene, 2.0f), {{0.9f, 0.5f}, {0.1f, 0.25f}, {0.5f, 0.25f}});
    // x = 3: the outer value 0.75, past the last entry, is it alone.
    const Hit high = hit_from_above(*scene, 3.0f);
    EXPECT_FLOAT_EQ(diffuse_of(high.material), 0.9f);
    EXPECT_EQ(high.mix, nullptr);
}

TEST(MaterialEntries, AverageMixesEveryEntryByItsWeight) {
    auto average = std::make_shared<sg::Material>();
    average->pattern.emplace();
    average->average = true;
    average->texture_map = {
        {1.0, texture_with_diffuse(0.2)}, {1.0, texture_with_diffuse(0.4)}, {2.0, texture_with_diffuse(0.8)}};
    sg::SceneGraph graph;
    graph.objects.push_back(plane_object({0, 1, 0}, 0.0, average));
    graph.objects.push_back(sphere_object({0, 5, 0}, 1.0, texture_with_diffuse(0.4)));
    const auto scene = compile_scene(graph);
    const auto mix = mix_of(hit_from_above(*scene, 0.25f));
    ASSERT_EQ(mix.size(), 3u);
    EXPECT_FLOAT_EQ(mix[0].first, 0.8f);
    EXPECT_NEAR(mix[0].second, 0.5f, 1e-6f);
    EXPECT_NEAR(mix[1].second + mix[2].second, 0.5f, 1e-6f);

    Hit sphere;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0.0f, 10.0f, 0.0f), Vec3(0.0f, -1.0f, 0.0f)), sphere));
    EXPECT_FLOAT_EQ(diffuse_of(sphere.material), 0.4f);
    EXPECT_EQ(sphere.mix, nullptr);
}

}  // namespace
}  // namespace lancer
