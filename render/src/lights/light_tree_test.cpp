// The light tree: sample() draws lights as often as probability() says, and
// no light that can light a point gets probability 0 there. The
// probabilities at a point sum to 1 or less: a walk that reaches a node
// whose lights none can reach the point (though its parent's looser bounds
// said they might) chooses no light, as in pbrt-v4; that costs a sample,
// never a bias.
#include "lancer/light_tree.h"

#include <cmath>
#include <memory>
#include <random>
#include <vector>

#include <gtest/gtest.h>
#include <glm/gtc/matrix_transform.hpp>

#include "geometry/shapes.h"
#include "lights/lights.h"

namespace lancer {
namespace {

// A field of lights of several kinds, in a 10 x 10 x 4 box.
struct Field {
    std::vector<std::unique_ptr<Light>> owned;
    std::vector<const Light*> lights;

    explicit Field(int count, std::uint32_t seed = 7) {
        std::mt19937 random(seed);
        std::uniform_real_distribution<float> unit(0.0f, 1.0f);
        for (int i = 0; i < count; ++i) {
            const Vec3 at(10.0f * unit(random) - 5.0f, 4.0f * unit(random), 10.0f * unit(random) - 5.0f);
            const Color colour(0.2f + unit(random), 0.2f + unit(random), 0.2f + unit(random));
            switch (i % 4) {
            case 0: {
                PointLightParameters p;
                p.position = at;
                p.intensity = colour;
                p.falloff = PointFalloff::InverseSquare;
                add(std::make_unique<PointLight>(p));
                break;
            }
            case 1: {
                PointLightParameters p;  // a POV spotlight with fade
                p.position = at;
                p.intensity = colour;
                p.falloff = PointFalloff::None;
                p.fade_distance = 1.0f;
                p.fade_power = 2.0f;
                p.spot_axis = glm::normalize(Vec3(unit(random) - 0.5f, -1.0f, unit(random) - 0.5f));
                p.spot_cos_radius = std::cos(0.3f);
                p.spot_cos_falloff = std::cos(0.5f);
                add(std::make_unique<PointLight>(p));
                break;
            }
            case 2: {
                AnalyticRectangle r;  // facing down or up
                r.center = DVec3(at);
                r.axis1 = DVec3(0.3 + unit(random), 0.0, 0.0);
                r.axis2 = DVec3(0.0, 0.0, (i % 8 == 2 ? 1.0 : -1.0) * (0.3 + unit(random)));
                add(std::make_unique<RectangleLight>(r, colour));
                break;
            }
            default: add(std::make_unique<SphereLight>(DVec3(at), 0.05 + 0.2 * unit(random), colour)); break;
            }
        }
    }
    void add(std::unique_ptr<Light> light) {
        lights.push_back(light.get());
        owned.push_back(std::move(light));
    }
};

TEST(LightTree, ProbabilitiesAtAPointSumToAtMostOneAndMatchWhatSampleReturns) {
    const Field field(37);
    const LightTree tree(field.lights);
    ASSERT_FALSE(tree.empty());
    std::mt19937 random(3);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    for (int trial = 0; trial < 50; ++trial) {
        const Vec3 p(12.0f * unit(random) - 6.0f, 5.0f * unit(random) - 0.5f, 12.0f * unit(random) - 6.0f);
        const Vec3 n =
            trial % 5 == 0 ? Vec3(0.0f) : glm::normalize(Vec3(unit(random) - 0.5f, unit(random), unit(random) - 0.5f));
        double sum = 0.0;
        for (const Light* light : field.lights) sum += tree.probability(p, n, light);
        EXPECT_LE(sum, 1.0 + 1e-5) << "trial " << trial;
        EXPECT_GT(sum, 0.5) << "trial " << trial;
        for (int k = 0; k < 20; ++k) {
            const LightTree::Choice choice = tree.sample(p, n, unit(random));
            if (choice.light == nullptr) continue;
            EXPECT_EQ(choice.probability, tree.probability(p, n, choice.light));
        }
    }
}

TEST(LightTree, SampleDrawsLightsAsOftenAsTheirProbability) {
    const Field field(9);
    const LightTree tree(field.lights);
    const Vec3 p(0.5f, 0.0f, -0.5f), n(0.0f, 1.0f, 0.0f);
    std::vector<int> drawn(field.lights.size(), 0);
    constexpr int kDraws = 200000;
    for (int i = 0; i < kDraws; ++i) {
        const LightTree::Choice choice = tree.sample(p, n, (float(i) + 0.5f) / float(kDraws));
        for (std::size_t k = 0; k < field.lights.size(); ++k)
            if (field.lights[k] == choice.light) ++drawn[k];
    }
    for (std::size_t k = 0; k < field.lights.size(); ++k)
        EXPECT_NEAR(double(drawn[k]) / kDraws, tree.probability(p, n, field.lights[k]), 2e-3) << "light " << k;
}

// Unbiasedness: wherever a light's sample brings light to a point (the
// surface there facing it), the tree gives that light a probability.
TEST(LightTree, EveryLightThatReachesAPointCanBeChosenThere) {
    const Field field(64, 11);
    const LightTree tree(field.lights);
    std::mt19937 random(5);
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    int reaching = 0;
    for (int trial = 0; trial < 400; ++trial) {
        const Vec3 p(12.0f * unit(random) - 6.0f, 5.0f * unit(random) - 0.5f, 12.0f * unit(random) - 6.0f);
        const Vec3 n = glm::normalize(Vec3(unit(random) - 0.5f, unit(random) - 0.5f, unit(random) - 0.5f));
        for (const Light* light : field.lights)
            for (int k = 0; k < 4; ++k) {
                const LightSample s = light->sample(p, Vec2(unit(random), unit(random)));
                if (!(s.pdf > 0.0f) || !(luminance(s.radiance) > 0.0f) || !(std::abs(glm::dot(s.wi, n)) > 0.0f))
                    continue;
                ++reaching;
                EXPECT_GT(tree.probability(p, n, light), 0.0f) << "trial " << trial;
            }
    }
    EXPECT_GT(reaching, 1000);
}

TEST(LightTree, EachTreeHoldsTheLightsOfItsFalloff) {
    using Falloff = LightTree::Falloff;
    PointLightParameters pov;  // POV-Ray's point light: the same at every distance
    pov.falloff = PointFalloff::None;
    pov.intensity = Color(1.0f);
    EXPECT_FALSE(LightTree::can_bound(PointLight(pov), Falloff::InverseSquare));
    EXPECT_TRUE(LightTree::can_bound(PointLight(pov), Falloff::None));
    pov.fade_distance = 2.0f;
    pov.fade_power = 1.0f;
    EXPECT_TRUE(LightTree::can_bound(PointLight(pov), Falloff::InverseSquare));
    EXPECT_FALSE(LightTree::can_bound(PointLight(pov), Falloff::None));
    DirectionalLightParameters parallel;
    parallel.irradiance = Color(1.0f);
    EXPECT_FALSE(LightTree::can_bound(DirectionalLight(parallel, 10.0f), Falloff::InverseSquare));
    EXPECT_FALSE(LightTree::can_bound(DirectionalLight(parallel, 10.0f), Falloff::None));
    EXPECT_TRUE(LightTree::can_bound(SphereLight(DVec3(0.0), 0.5, Color(1.0f)), Falloff::InverseSquare));
    EXPECT_FALSE(LightTree::can_bound(SphereLight(DVec3(0.0), 0.5, Color(1.0f)), Falloff::None));
    // A light it cannot hold has probability 0 in it.
    const PointLight outside(PointLightParameters{});
    const Field field(4);
    const LightTree tree(field.lights);
    EXPECT_EQ(tree.probability(Vec3(0.0f), Vec3(0.0f, 1.0f, 0.0f), &outside), 0.0f);
}

// Behind a one-sided panel, and outside a spotlight's cone, a light sends
// nothing: the tree does not choose it there.
TEST(LightTree, LightsThatCannotReachAPointAreNotChosen) {
    AnalyticRectangle panel;  // at y = 2, emitting downwards (axis1 x axis2)
    panel.center = DVec3(0.0, 2.0, 0.0);
    panel.axis1 = DVec3(1.0, 0.0, 0.0);
    panel.axis2 = DVec3(0.0, 0.0, 1.0);
    const RectangleLight down(panel, Color(1.0f));
    const LightSample below = down.sample(Vec3(0.0f), Vec2(0.5f));
    ASSERT_GT(below.pdf, 0.0f);
    PointLightParameters spot;
    spot.position = Vec3(10.0f, 2.0f, 0.0f);
    spot.intensity = Color(1.0f);
    spot.spot_axis = Vec3(0.0f, -1.0f, 0.0f);
    spot.spot_cos_radius = std::cos(0.2f);
    spot.spot_cos_falloff = std::cos(0.3f);
    const PointLight cone(spot);
    const LightTree tree({&down, &cone});
    const Vec3 up(0.0f, 1.0f, 0.0f);
    EXPECT_EQ(tree.probability(Vec3(0.0f, 3.0f, 0.0f), up, &down), 0.0f);  // above the panel
    EXPECT_EQ(tree.probability(Vec3(0.0f, 3.0f, 0.0f), up, &cone), 0.0f);  // above the spot, too
    EXPECT_EQ(tree.sample(Vec3(0.0f, 3.0f, 0.0f), up, 0.5f).light, nullptr);
    EXPECT_EQ(tree.probability(Vec3(0.0f, 0.0f, 0.0f), up, &cone), 0.0f);  // far outside the cone
    EXPECT_EQ(tree.probability(Vec3(0.0f, 0.0f, 0.0f), up, &down), 1.0f);
    EXPECT_GT(tree.probability(Vec3(10.0f, 0.0f, 0.0f), up, &cone), 0.0f);  // under the spot
}

// An emitting object's box (EmissiveShapeParameters) holds every point its
// light samples, for a sphere stretched and turned and for a box's faces.
TEST(LightTree, EmittingShapesBoundWhatTheySample) {
    const DMat4 turned =
        glm::rotate(glm::scale(glm::translate(DMat4(1.0), DVec3(1.0, 2.0, -3.0)), DVec3(2.0, 0.5, 1.0)), 0.7,
                    glm::normalize(DVec3(1.0, 1.0, 0.0)));
    const Placement placement = Placement::from(turned);
    AnalyticSphere ball;
    ball.center = DVec3(0.3, 0.0, 0.1);
    ball.radius = 0.8;
    AnalyticBox box;
    box.lower = DVec3(-1.0, -0.5, 0.0);
    box.upper = DVec3(0.5, 0.5, 2.0);
    std::vector<std::unique_ptr<SurfaceSampler>> surfaces;
    surfaces.push_back(make_sphere_sampler(ball, placement, nullptr));
    surfaces.push_back(make_box_sampler(box, placement, nullptr));
    for (const auto& surface : surfaces) {
        DVec3 lower, upper;
        surface->bounds(lower, upper);
        for (int i = 0; i < 64; ++i)
            for (int j = 0; j < 64; ++j) {
                const DVec3 point =
                    surface->sample(Vec2((float(i) + 0.5f) / 64.0f, (float(j) + 0.5f) / 64.0f)).position;
                for (int c = 0; c < 3; ++c) {
                    EXPECT_GE(point[c], lower[c] - 1e-9);
                    EXPECT_LE(point[c], upper[c] + 1e-9);
                }
            }
    }
}

// The same scene in another unit chooses the same lights.
TEST(LightTree, ScalingTheSceneChangesNoProbability) {
    for (const double scale : {1e-4, 1e-2, 1e2, 1e4}) {
        const SphereLight big(DVec3(0.0, 3.0, 0.0), 0.8, Color(1.0f)), small(DVec3(2.0, 1.0, 0.5), 0.1, Color(1.0f));
        const SphereLight big_scaled(DVec3(0.0, 3.0, 0.0) * scale, 0.8 * scale, Color(1.0f));
        const SphereLight small_scaled(DVec3(2.0, 1.0, 0.5) * scale, 0.1 * scale, Color(1.0f));
        const LightTree tree({&big, &small}), scaled({&big_scaled, &small_scaled});
        const Vec3 up(0.0f, 1.0f, 0.0f);
        for (const Vec3& p : {Vec3(0.0f), Vec3(2.0f, 0.0f, 0.5f), Vec3(1.0f, 2.9f, 0.0f)})
            EXPECT_NEAR(scaled.probability(p * float(scale), up, &big_scaled), tree.probability(p, up, &big), 1e-5)
                << "scale " << scale;
    }
}

// POV's point lights without fade: weighed by colour and cosines, not by
// distance. Two equal lights, one near and one 100 times as far: the far
// one keeps a share of the same order (by distance it would get 1/10000 of
// the near one's; the node bounds make the shares unequal); a spotlight
// turned away: none.
TEST(LightTree, LightsWithoutFalloffAreWeighedWithoutDistance) {
    PointLightParameters p;
    p.falloff = PointFalloff::None;
    p.intensity = Color(1.0f);
    p.position = Vec3(0.0f, 1.0f, 0.0f);
    const PointLight near(p);
    p.position = Vec3(0.0f, 100.0f, 0.0f);
    const PointLight far(p);
    p.position = Vec3(5.0f, 5.0f, 0.0f);
    p.spot_axis = Vec3(0.0f, 1.0f, 0.0f);  // pointing up, away from the floor
    p.spot_cos_radius = std::cos(0.2f);
    p.spot_cos_falloff = std::cos(0.3f);
    const PointLight away(p);
    const LightTree tree({&near, &far, &away}, LightTree::Falloff::None);
    const Vec3 floor(0.0f), up(0.0f, 1.0f, 0.0f);
    EXPECT_GT(tree.probability(floor, up, &near), 0.25f);
    EXPECT_GT(tree.probability(floor, up, &far), 0.25f);
    EXPECT_NEAR(tree.probability(floor, up, &near) + tree.probability(floor, up, &far), 1.0f, 1e-6f);
    EXPECT_EQ(tree.probability(floor, up, &away), 0.0f);
}

}  // namespace
}  // namespace lancer
