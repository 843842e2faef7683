// Light units and sampling: inverse-square point lights, POV fade, pdfs
// that integrate to one and agree with sample(), area lights matching a
// point light of the same colour far away, degenerate lights.
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "lancer/host/scene_compiler.h"
#include "lancer/render_scene.h"
#include "scene_test_helpers.h"

namespace lancer {
namespace {

using namespace lancer::testing;

sg::Light point_light(const glm::dvec3& position, const glm::dvec3& color) {
    sg::Light l;
    l.kind = sg::Light::Kind::Point;
    l.position = position;
    l.color = color;
    return l;
}

std::unique_ptr<RenderScene> compile_lights(std::vector<sg::Light> lights, std::vector<sg::Object> objects = {}) {
    sg::SceneGraph graph;
    graph.lights = std::move(lights);
    graph.objects = std::move(objects);
    return compile_scene(graph);
}

// POV-Ray's point light (reference/pov-3.7-semantics.md section 5): no
// falloff with distance; colour C reaches a surface as radiance pi*C, so
// a white matte surface facing it shows C.
TEST(Lights, PovPointLightHasNoFalloffAndIntensityPiC) {
    auto scene = compile_lights({point_light({0, 10, 0}, {1, 0.5, 0.25})});
    ASSERT_EQ(scene->lights().size(), 1u);
    const Light& light = *scene->lights()[0];
    EXPECT_TRUE(light.is_delta());
    const LightSample at1 = light.sample(Vec3(0, 9, 0), Vec2(0.5f));
    const LightSample at4 = light.sample(Vec3(0, 6, 0), Vec2(0.5f));
    const LightSample far = light.sample(Vec3(0, -1e6f, 0), Vec2(0.5f));
    EXPECT_NEAR(at1.radiance.r, kPi, 1e-5f);
    EXPECT_NEAR(at1.radiance.g, 0.5f * kPi, 1e-5f);
    EXPECT_EQ(at4.radiance, at1.radiance);
    EXPECT_EQ(far.radiance, at1.radiance);
    EXPECT_EQ(at1.wi, Vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(at4.distance, 4.0f);
    EXPECT_EQ(at1.pdf, 1.0f);
    EXPECT_TRUE(std::isfinite(light.power().r));
    EXPECT_GT(light.power().r, 0.0f);
    // At the light's position: no sample, no NaN.
    const LightSample at0 = light.sample(Vec3(0, 10, 0), Vec2(0.5f));
    EXPECT_EQ(at0.pdf, 0.0f);
}

// The physical point a lamp's proxy is: inverse-square, intensity pi*C
// (the assertions POV's point light had before it took POV's meaning).
TEST(Lights, PhysicalLampProxyIsInverseSquareWithIntensityPiC) {
    sg::Light lamp;
    lamp.kind = sg::Light::Kind::AreaSphere;
    lamp.position = {0, 10, 0};
    lamp.radius = 1e-3;
    lamp.color = {1, 0.5, 0.25};
    auto scene = compile_lights({lamp});
    ASSERT_EQ(scene->local_lights().size(), 1u);
    const Light& light = *scene->local_lights()[0];
    EXPECT_TRUE(light.is_delta());
    const LightSample at1 = light.sample(Vec3(0, 9, 0), Vec2(0.5f));
    const LightSample at4 = light.sample(Vec3(0, 6, 0), Vec2(0.5f));
    EXPECT_NEAR(at1.radiance.r, kPi, 1e-5f);
    EXPECT_NEAR(at1.radiance.g, 0.5f * kPi, 1e-5f);
    EXPECT_NEAR(at4.radiance.r / at1.radiance.r, 1.0f / 16.0f, 1e-6f);
    EXPECT_EQ(at1.wi, Vec3(0, 1, 0));
    EXPECT_FLOAT_EQ(at4.distance, 4.0f);
    EXPECT_EQ(at1.pdf, 1.0f);
    EXPECT_NEAR(light.power().r, 4.0f * kPi * kPi, 1e-4f);
    const LightSample at0 = light.sample(Vec3(0, 10, 0), Vec2(0.5f));
    EXPECT_EQ(at0.pdf, 0.0f);
}

TEST(Lights, PovFadeReplacesInverseSquare) {
    sg::Light l = point_light({0, 0, 0}, {1, 1, 1});
    l.fade_distance = 2.0;
    l.fade_power = 2.0;
    auto scene = compile_lights({l});
    const LightSample s = scene->lights()[0]->sample(Vec3(4, 0, 0), Vec2(0.5f));
    EXPECT_NEAR(s.radiance.r, kPi * 2.0f / (1.0f + 4.0f), 1e-5f);
}

TEST(Lights, DirectionalLightTravelsFromPositionToPointAt) {
    sg::Light l;
    l.kind = sg::Light::Kind::Directional;
    l.position = {0, 10, 0};
    l.point_at = {0, 0, 0};
    auto scene = compile_lights({l}, {sphere_object({0, 0, 0}, 1.0)});
    const LightSample s = scene->lights()[0]->sample(Vec3(0, 1, 0), Vec2(0.5f));
    EXPECT_EQ(s.wi, Vec3(0, 1, 0));
    EXPECT_NEAR(s.radiance.r, kPi, 1e-6f);
    EXPECT_TRUE(std::isinf(s.distance));
    // POV's parallel shadow ray ends at the light's plane (y = 10 here); a
    // point past the plane has nothing between it and the light.
    EXPECT_EQ(s.point, Vec3(0, 10, 0));
    EXPECT_EQ(scene->lights()[0]->sample(Vec3(3, 2, 1), Vec2(0.5f)).point, Vec3(3, 10, 1));
    EXPECT_EQ(scene->lights()[0]->sample(Vec3(3, 12, 1), Vec2(0.5f)).point, Vec3(3, 12, 1));
}

// POV's projected_through: the light reaches a point only along a segment
// that meets the projector (a unit sphere halfway up, here).
TEST(Lights, ProjectedThroughPassesOnlyThroughTheProjector) {
    sg::Light l;
    l.position = {0, 10, 0};
    auto projector = std::make_shared<sg::Object>(sphere_object({0, 5, 0}, 1.0));
    l.projected_through = projector;
    auto scene = compile_lights({l}, {sphere_object({0, -5, 0}, 1.0)});
    const Light& light = *scene->lights()[0];
    EXPECT_NEAR(light.sample(Vec3(0.5f, 0, 0), Vec2(0.5f)).radiance.r, kPi, 1e-5f);  // through the sphere
    EXPECT_EQ(light.sample(Vec3(4, 0, 0), Vec2(0.5f)).radiance.r, 0.0f);             // past it
    EXPECT_EQ(light.parameters<PointLightParameters>(), nullptr);                    // evaluated through sample() only
}

// POV's Attenuate_Light for a cylinder source (radius 1, falloff 2,
// tightness 2): (1 - r/2)^2 inside the radius, times a smooth step from 0
// at the falloff to 1 at the radius; nothing behind the light.
TEST(Lights, CylinderLightBeamFollowsPovRay) {
    sg::Light l;
    l.kind = sg::Light::Kind::Directional;
    l.cylinder = l.parallel = true;
    l.position = {0, 10, 0};
    l.point_at = {0, 0, 0};
    l.spot_radius = 1.0;
    l.spot_falloff = 2.0;
    l.tightness = 2.0;
    auto scene = compile_lights({l}, {sphere_object({0, 0, 0}, 1.0)});
    const Light& light = *scene->lights()[0];
    EXPECT_NEAR(light.sample(Vec3(0.5f, 0, 0), Vec2(0.5f)).radiance.r, kPi * 0.75f * 0.75f, 1e-5f);
    EXPECT_NEAR(light.sample(Vec3(0, -3, 1.5f), Vec2(0.5f)).radiance.r, kPi * 0.25f * 0.25f * 0.5f, 1e-5f);
    EXPECT_EQ(light.sample(Vec3(2.5f, 0, 0), Vec2(0.5f)).radiance.r, 0.0f);
    EXPECT_EQ(light.sample(Vec3(0, 11, 0), Vec2(0.5f)).radiance.r, 0.0f);
    EXPECT_EQ(light.sample(Vec3(0.5f, 0, 0), Vec2(0.5f)).wi, Vec3(0, 1, 0));  // parallel beams
}

// Monte Carlo estimate of the integral of pdf() over all directions from p
// (uniform directions, each traced to the light): should be 1.
double integrate_pdf(const RenderScene& scene, const Light& light, const Vec3& p) {
    std::mt19937 rng(5);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const int n = 400000;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const float z = 1.0f - 2.0f * u(rng);
        const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
        const float phi = 2.0f * kPi * u(rng);
        const Vec3 wi(r * std::cos(phi), z, r * std::sin(phi));
        Hit hit;
        if (!scene.intersect(make_ray(p, wi), hit) || hit.emitter != &light) continue;
        sum += light.pdf(p, wi, hit);
    }
    return sum * 4.0 * kPi / n;
}

// sample() reports the same density pdf() gives for the point it returns
// (when that point is visible from p: area sampling of a closed shape also
// picks points on its far side).
void expect_consistent_samples(const RenderScene& scene, const Light& light, const Vec3& p, int minimum_visible = 150) {
    std::mt19937 rng(11);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    int checked = 0, mismatched = 0;
    for (int i = 0; i < 200; ++i) {
        const LightSample s = light.sample(p, Vec2(u(rng), u(rng)));
        if (!(s.pdf > 0.0f)) continue;
        Hit hit;
        ASSERT_TRUE(scene.intersect(make_ray(p, s.wi), hit));
        if (hit.emitter != &light || std::fabs(hit.t - s.distance) > 1e-4f * s.distance) continue;
        // A ray aimed at a box edge may find the neighbouring face.
        if (std::fabs(light.pdf(p, s.wi, hit) / s.pdf - 1.0f) > 2e-3f) ++mismatched;
        ++checked;
    }
    EXPECT_GT(checked, minimum_visible);
    EXPECT_LE(mismatched, checked / 50);
}

// Fraction of samples whose point is visible from p: for area-sampled
// closed shapes it must equal the integral of pdf() over visible directions.
double visible_fraction(const RenderScene& scene, const Light& light, const Vec3& p) {
    std::mt19937 rng(17);
    std::uniform_real_distribution<float> u(0.0f, 1.0f);
    const int n = 100000;
    int visible = 0;
    Hit origin;
    origin.position = p;
    for (int i = 0; i < n; ++i) {
        const LightSample s = light.sample(p, Vec2(u(rng), u(rng)));
        if (s.pdf > 0.0f && !scene.occluded(origin.spawn_ray_to(s.point))) ++visible;
    }
    return double(visible) / n;
}

TEST(Lights, RectangleLightPdfIntegratesToOne) {
    sg::Light l;
    l.kind = sg::Light::Kind::AreaRectangle;
    l.position = {0, 2, 0};
    l.axis1 = {2, 0, 0};
    l.axis2 = {0, 0.5, 1};
    auto scene = compile_lights({l});
    const Light& light = *scene->lights()[0];
    EXPECT_NEAR(integrate_pdf(*scene, light, Vec3(0.3f, 0, 0.2f)), 1.0, 0.02);
    expect_consistent_samples(*scene, light, Vec3(0.3f, 0, 0.2f));
}

TEST(Lights, SphereLightPdfIntegratesToOne) {
    sg::Light l;
    l.kind = sg::Light::Kind::AreaSphere;
    l.position = {0, 3, 0};
    l.radius = 1.5;
    auto scene = compile_lights({l});
    const Light& light = *scene->lights()[0];
    EXPECT_NEAR(integrate_pdf(*scene, light, Vec3(0, 0, 0)), 1.0, 0.02);
    expect_consistent_samples(*scene, light, Vec3(0, 0, 0));
}

TEST(Lights, EmissiveBoxAndEllipsoidPdfIntegrateToOne) {
    auto glow = solid_material({1, 1, 1}, 0.0, {1, 1, 1});
    sg::Object ellipsoid = sphere_object({0, 0, 0}, 1.0, glow);
    ellipsoid.parent_from_object =
        glm::translate(glm::dmat4(1.0), glm::dvec3(0, 3, 0)) * glm::scale(glm::dmat4(1.0), glm::dvec3(2, 0.5, 1));
    sg::Object box = box_object({-1, -1, 2}, {1, 0.5, 3}, glow);
    auto scene = compile_lights({}, {ellipsoid, box});
    ASSERT_EQ(scene->lights().size(), 2u);
    for (const Light* light : scene->lights()) {
        const double visible = visible_fraction(*scene, *light, Vec3(0, 0, 0));
        EXPECT_GT(visible, 0.2);
        EXPECT_NEAR(integrate_pdf(*scene, *light, Vec3(0, 0, 0)), visible, 0.02);
        expect_consistent_samples(*scene, *light, Vec3(0, 0, 0), 40);
    }
    // Seen from outside, a sphere under a similarity is sampled by its cone:
    // every sample visible, pdf integrating to one.
    sg::Object ball = sphere_object({0, 3, 0}, 1.5, glow);
    auto round = compile_lights({}, {ball});
    EXPECT_NEAR(integrate_pdf(*round, *round->lights()[0], Vec3(0, 0, 0)), 1.0, 0.02);
    EXPECT_NEAR(visible_fraction(*round, *round->lights()[0], Vec3(0, 0, 0)), 1.0, 1e-9);
}

// Far along its axis (on its emitting side) a rectangle light of colour C
// gives the irradiance of a point light of colour C; a sphere light does so
// in every direction.
TEST(Lights, AreaLightsMatchPointLightFarAway) {
    sg::Light rectangle;
    rectangle.kind = sg::Light::Kind::AreaRectangle;
    rectangle.position = {0, 0, 0};
    rectangle.axis1 = {0.2, 0, 0};
    rectangle.axis2 = {0, 0, 0.2};
    sg::Light sphere;
    sphere.kind = sg::Light::Kind::AreaSphere;
    sphere.position = {0, 0, 0};
    sphere.radius = 0.1;
    for (const sg::Light& l : {rectangle, sphere}) {
        auto scene = compile_lights({l});
        const Light& light = *scene->lights()[0];
        const Vec3 p(0, -20, 0);  // axis1 x axis2 = x cross z points down
        // Irradiance on a surface facing the light, by Monte Carlo.
        std::mt19937 rng(3);
        std::uniform_real_distribution<float> u(0.0f, 1.0f);
        double irradiance = 0.0;
        const int n = 20000;
        for (int i = 0; i < n; ++i) {
            const LightSample s = light.sample(p, Vec2(u(rng), u(rng)));
            if (s.pdf > 0.0f) irradiance += s.radiance.r * std::fabs(s.wi.y) / s.pdf;
        }
        irradiance /= n;
        EXPECT_NEAR(irradiance, kPi / 400.0, 0.01 * kPi / 400.0);
        // The proxy is a point light with the same on-axis intensity.
        const LightSample proxy = light.proxy().sample(p, Vec2(0.5f));
        EXPECT_NEAR(proxy.radiance.r, kPi / 400.0f, 1e-6f);
        EXPECT_TRUE(light.proxy().is_delta());
    }
}

// A rectangle light emits on the side of axis1 x axis2 only: behind it
// neither the light, its proxy nor a camera ray sees any emission.
TEST(Lights, RectangleLightIsOneSided) {
    sg::Light l;
    l.kind = sg::Light::Kind::AreaRectangle;
    l.position = {0, 2, 0};
    l.axis1 = {1, 0, 0};
    l.axis2 = {0, 0, 1};
    l.color = {1, 1, 1};
    auto scene = compile_lights({l});
    const Light& light = *scene->lights()[0];
    const Vec3 above(0.1f, 5.0f, 0.2f), below(0.1f, -1.0f, 0.2f);
    EXPECT_EQ(light.sample(above, Vec2(0.3f, 0.6f)).pdf, 0.0f);
    EXPECT_GT(light.sample(below, Vec2(0.3f, 0.6f)).pdf, 0.0f);
    EXPECT_EQ(light.proxy().sample(above, Vec2(0.5f)).radiance.r, 0.0f);
    EXPECT_NEAR(light.proxy().sample(Vec3(0, -1, 0), Vec2(0.5f)).radiance.r, kPi / 9.0f, 1e-5f);
    // Power: pi * area * Le over the one emitting side, = pi^2 * C.
    EXPECT_NEAR(light.power().r, kPi * kPi, 1e-4f);
    EXPECT_NEAR(light.proxy().power().r, kPi * kPi, 1e-4f);
    Hit from_below, from_above;
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0, 0, 0), Vec3(0, 1, 0)), from_below));
    ASSERT_TRUE(scene->intersect(make_ray(Vec3(0, 4, 0), Vec3(0, -1, 0)), from_above));
    ASSERT_NE(from_below.emitter, nullptr);
    EXPECT_GT(from_below.emitter->emitted(from_below, Vec3(0, -1, 0)).r, 0.0f);
    EXPECT_EQ(from_above.emitter->emitted(from_above, Vec3(0, 1, 0)).r, 0.0f);
}

TEST(Lights, ZeroSizeAreaLightsDegradeToPointLights) {
    sg::Light rectangle;
    rectangle.kind = sg::Light::Kind::AreaRectangle;
    rectangle.position = {0, 1, 0};
    sg::Light sphere;
    sphere.kind = sg::Light::Kind::AreaSphere;
    sphere.position = {0, 1, 0};
    sphere.radius = 0.0;
    auto scene = compile_lights({rectangle, sphere});
    ASSERT_EQ(scene->lights().size(), 2u);
    for (const Light* light : scene->lights()) {
        EXPECT_EQ(light->kind(), Light::Kind::Point);
        const LightSample s = light->sample(Vec3(0, 0, 0), Vec2(0.3f, 0.7f));
        EXPECT_TRUE(std::isfinite(s.radiance.r));
        EXPECT_NEAR(s.radiance.r, kPi, 1e-5f);
    }
}

TEST(Lights, FlatEmitterProxyHasCosinePattern) {
    auto glow = solid_material({1, 1, 1}, 0.0, {2, 2, 2});
    auto scene = compile_lights({}, {mesh_object(triangle_mesh({0, 0, 0}, {2, 0, 0}, {0, 0, 2}), glow)});
    ASSERT_EQ(scene->local_lights().size(), 1u);
    const Light& proxy = *scene->local_lights()[0];
    const Vec3 centre(2.0f / 3.0f, 0.0f, 2.0f / 3.0f);
    // Intensity along the normal: Le * area = 2 * 2.
    EXPECT_NEAR(proxy.sample(centre + Vec3(0, 10, 0), Vec2(0.5f)).radiance.r, 4.0f / 100.0f, 1e-5f);
    EXPECT_NEAR(proxy.sample(centre + Vec3(10, 0, 0), Vec2(0.5f)).radiance.r, 0.0f, 1e-6f);
    EXPECT_NEAR(scene->lights()[0]->power().r, proxy.power().r, 1e-3f * proxy.power().r);
}

// Integrators that evaluate a kind of light themselves read its parameters
// through Light::parameters<T>(): the struct of its own kind, null for any
// other, and the values the scene gave (in lancer's units).
TEST(Lights, ParametersAreTypedByKind) {
    sg::Light faded = point_light({1, 2, 3}, {1, 0.5, 0.25});
    faded.fade_distance = 2.0;
    faded.fade_power = 1.0;
    sg::Light rectangle;
    rectangle.kind = sg::Light::Kind::AreaRectangle;
    rectangle.position = {0, 4, 0};
    rectangle.axis1 = {2, 0, 0};
    rectangle.axis2 = {0, 0, 1};
    rectangle.color = {1, 1, 1};
    sg::Light sphere;
    sphere.kind = sg::Light::Kind::AreaSphere;
    sphere.position = {0, 6, 0};
    sphere.radius = 0.5;
    sphere.color = {1, 1, 1};
    auto scene = compile_lights({point_light({0, 10, 0}, {1, 1, 1}), faded, rectangle, sphere});
    ASSERT_EQ(scene->lights().size(), 4u);
    // Area lights come first in lights() (their surfaces are built first).
    const Light* by_kind[2][2] = {};  // [point][plain or faded], [area][rectangle or sphere]
    for (const Light* light : scene->lights()) {
        if (light->kind() == Light::Kind::Point) by_kind[0][by_kind[0][0] ? 1 : 0] = light;
        if (light->kind() == Light::Kind::Rectangle) by_kind[1][0] = light;
        if (light->kind() == Light::Kind::Sphere) by_kind[1][1] = light;
    }
    ASSERT_TRUE(by_kind[0][0] && by_kind[0][1] && by_kind[1][0] && by_kind[1][1]);
    const Light& plain = *by_kind[0][0];
    const Light& fading = *by_kind[0][1];
    const Light& panel = *by_kind[1][0];
    const Light& ball = *by_kind[1][1];

    const auto* point = plain.parameters<PointLightParameters>();
    ASSERT_NE(point, nullptr);
    EXPECT_EQ(point->position, Vec3(0, 10, 0));
    EXPECT_NEAR(point->intensity.r, kPi, 1e-6f);
    EXPECT_TRUE(point->is_plain());
    EXPECT_EQ(point->falloff, PointFalloff::None);  // POV-Ray's point light
    EXPECT_EQ(plain.parameters<RectangleLightParameters>(), nullptr);
    EXPECT_EQ(plain.parameters<DirectionalLightParameters>(), nullptr);

    const auto* fade = fading.parameters<PointLightParameters>();
    ASSERT_NE(fade, nullptr);
    EXPECT_FLOAT_EQ(fade->fade_distance, 2.0f);
    EXPECT_FALSE(fade->is_plain());

    const auto* rect = panel.parameters<RectangleLightParameters>();
    ASSERT_NE(rect, nullptr);
    EXPECT_EQ(rect->center, Vec3(0, 4, 0));
    EXPECT_EQ(rect->axis1, Vec3(2, 0, 0));
    EXPECT_NEAR(rect->radiance.r, kPi / 2.0f, 1e-5f);  // pi C / area
    EXPECT_EQ(panel.parameters<PointLightParameters>(), nullptr);
    // Its proxy is a point light with a one-sided cosine pattern.
    const auto* proxy = panel.proxy().parameters<PointLightParameters>();
    ASSERT_NE(proxy, nullptr);
    EXPECT_TRUE(proxy->one_sided);
    EXPECT_FALSE(proxy->is_plain());
    EXPECT_EQ(proxy->falloff, PointFalloff::InverseSquare);  // the proxy of a physical lamp

    const auto* round = ball.parameters<SphereLightParameters>();
    ASSERT_NE(round, nullptr);
    EXPECT_FLOAT_EQ(round->radius, 0.5f);
    EXPECT_EQ(round->center, Vec3(0, 6, 0));
    EXPECT_EQ(ball.parameters<RectangleLightParameters>(), nullptr);
}

// The float path of a plain point light is plain_point_incidence(): what
// lane-parallel shading computes is what sample() gives, bit for bit.
TEST(Lights, PlainPointSampleIsPlainPointIncidence) {
    auto scene = compile_lights({point_light({0.3, 10, -2}, {1, 0.5, 0.25})});
    const Light& light = *scene->lights()[0];
    const auto* point = light.parameters<PointLightParameters>();
    ASSERT_NE(point, nullptr);
    const Vec3 p(1.7f, -0.25f, 3.5f);
    const Vec3 to_light = point->position - p;
    const float distance_squared = glm::dot(to_light, to_light);
    ASSERT_TRUE(in_plain_point_range(distance_squared));
    const PointIncidence incidence = plain_point_incidence(distance_squared, point->falloff);
    const LightSample sample = light.sample(p, Vec2(0.5f));
    EXPECT_EQ(sample.radiance, point->intensity * incidence.falloff);
    EXPECT_EQ(sample.wi, to_light * incidence.inverse_distance);
    EXPECT_EQ(sample.distance, incidence.distance);
}

// POV-Ray's spotlight (its Attenuate_Light): full light within `radius` of
// the axis, none beyond `falloff`, a cubic smooth step between, times
// cos^tightness; nothing behind the light. No distance falloff.
TEST(Lights, SpotlightConeFollowsPovRay) {
    sg::Light spot = point_light({0, 10, 0}, {1, 1, 1});
    spot.spotlight = true;
    spot.point_at = {0, 0, 0};
    spot.spot_radius = 20.0;
    spot.spot_falloff = 40.0;
    auto scene = compile_lights({spot});
    const Light& light = *scene->lights()[0];
    ASSERT_NE(light.parameters<PointLightParameters>(), nullptr);
    EXPECT_FALSE(light.parameters<PointLightParameters>()->is_plain());
    // A point of the floor y = 0 at angle a from the axis.
    auto at_angle = [&](double degrees) {
        const double x = 10.0 * std::tan(glm::radians(degrees));
        return light.sample(Vec3(float(x), 0.0f, 0.0f), Vec2(0.5f)).radiance.r;
    };
    EXPECT_NEAR(at_angle(0.0), kPi, 1e-5f);
    EXPECT_NEAR(at_angle(15.0), kPi, 1e-5f);  // inside the radius
    EXPECT_EQ(at_angle(45.0), 0.0f);          // beyond the falloff
    // Halfway between the cosines of radius and falloff: the smooth step is 1/2.
    const double c20 = std::cos(glm::radians(20.0)), c40 = std::cos(glm::radians(40.0));
    const double halfway = glm::degrees(std::acos(0.5 * (c20 + c40)));
    EXPECT_NEAR(at_angle(halfway), 0.5f * kPi, 1e-4f);
    // A quarter of the way from the falloff: 3t^2 - 2t^3 at t = 1/4.
    const double quarter = glm::degrees(std::acos(c40 + 0.25 * (c20 - c40)));
    EXPECT_NEAR(at_angle(quarter), float((3.0 - 0.5) * 0.0625) * kPi, 1e-4f);
    // Behind the light: nothing.
    EXPECT_EQ(light.sample(Vec3(0, 20, 0), Vec2(0.5f)).radiance.r, 0.0f);
    // No falloff with distance along the axis.
    EXPECT_NEAR(light.sample(Vec3(0, -90, 0), Vec2(0.5f)).radiance.r, kPi, 1e-5f);

    // tightness multiplies by cos^tightness everywhere.
    spot.tightness = 10.0;
    auto tight = compile_lights({spot});
    const double x = 10.0 * std::tan(glm::radians(15.0));
    EXPECT_NEAR(tight->lights()[0]->sample(Vec3(float(x), 0.0f, 0.0f), Vec2(0.5f)).radiance.r,
                float(std::pow(std::cos(glm::radians(15.0)), 10.0)) * kPi, 1e-4f);
}

// POV's fade with fade_power but no fade_distance: 1 / d^fade_power.
TEST(Lights, FadePowerWithoutDistanceIsAPowerLaw) {
    sg::Light l = point_light({0, 0, 0}, {1, 1, 1});
    l.fade_power = 1.0;
    auto scene = compile_lights({l});
    EXPECT_NEAR(scene->lights()[0]->sample(Vec3(4, 0, 0), Vec2(0.5f)).radiance.r, kPi / 4.0f, 1e-5f);
}

}  // namespace
}  // namespace lancer
