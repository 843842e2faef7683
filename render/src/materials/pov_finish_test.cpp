// The finish's highlights at POV-Ray's peak values (pov-3.7-semantics.md
// §3.3, §3.4): under a light of colour C, brdf * cos * pi*C is exactly
// POV's phong * c^phong_size * C and specular * c^(1/roughness) * C.
#include <cmath>

#include <gtest/gtest.h>

#include "lancer/material.h"
#include "lancer/shading/local_shading.h"

namespace lancer {
namespace {

// Light reflected towards wo from light of colour 1 along wi, by the glossy
// lobes: what POV adds as its highlight term.
float highlight(const MaterialParameters& p, const Vec3& wo, const Vec3& wi) {
    const Material material(p);
    const SurfaceSample white{Color(1.0f), 0.0f, 0.0f};
    const Vec3 n(0.0f, 0.0f, 1.0f);
    return material.glossy_brdf(white, n, wo, wi).g * glm::dot(n, wi) * kPi;
}

TEST(PovFinish, PhongIsPovsPeakTimesCosineToTheMirrorDirection) {
    MaterialParameters p;
    p.phong = 0.7f;
    p.phong_size = 12.0f;
    const Vec3 wo = glm::normalize(Vec3(0.3f, 0.0f, 1.0f));
    const Vec3 mirror(-wo.x, -wo.y, wo.z);
    EXPECT_NEAR(highlight(p, wo, mirror), 0.7f, 1e-5f);  // the peak, at the mirror direction
    const Vec3 wi = glm::normalize(Vec3(-0.6f, 0.2f, 0.8f));
    EXPECT_NEAR(highlight(p, wo, wi), 0.7f * std::pow(glm::dot(mirror, wi), 12.0f), 1e-5f);
    // Grazing light keeps the same law: no 1/cos blow-up, no cut.
    const Vec3 grazing = glm::normalize(Vec3(-1.0f, 0.0f, 1e-4f));
    EXPECT_NEAR(highlight(p, wo, grazing), 0.7f * std::pow(glm::dot(mirror, grazing), 12.0f), 1e-5f);
}

TEST(PovFinish, SpecularIsPovsPeakTimesPowerOfTheHalfVector) {
    MaterialParameters p;
    p.specular = 0.5f;
    p.roughness = 0.05f;  // POV's exponent 20
    const Vec3 wo = glm::normalize(Vec3(0.2f, -0.1f, 1.0f));
    const Vec3 wi = glm::normalize(Vec3(-0.4f, 0.3f, 0.9f));
    const float c = glm::normalize(wo + wi).z;
    EXPECT_NEAR(highlight(p, wo, wi), 0.5f * std::pow(c, 20.0f), 1e-5f);
    const Vec3 mirror(-wo.x, -wo.y, wo.z);
    EXPECT_NEAR(highlight(p, wo, mirror), 0.5f, 1e-5f);
}

// POV-Ray's `albedo` rescaling (Parse_Finish) is the inverse of the share
// the peak reflects.
TEST(PovFinish, AlbedoShares) {
    EXPECT_FLOAT_EQ(phong_albedo(40.0f), 2.0f / 41.0f);
    const float k = 20.0f;
    EXPECT_NEAR(1.0f / specular_albedo(k), (k + 2.0f) / (4.0f * (2.0f - std::pow(2.0f, -k / 2.0f))), 1e-5f);
}

// What one point light of colour C along wi gives a white surface facing
// +z seen from +z, through the classic integrators' local shading.
LobeRadiance lit(const MaterialParameters& p, const Vec3& position, const Vec3& wi) {
    const Material material(p);
    Hit hit;
    hit.position = position;
    hit.geometric_normal = hit.shading_normal = Vec3(0.0f, 0.0f, 1.0f);
    ShadingContext at{
        hit, material, SurfaceSample{Color(1.0f), 0.0f, 0.0f}, Vec3(0.0f, 0.0f, 1.0f), Vec3(0.0f, 0.0f, 1.0f), true};
    if (material.has_iridescence()) at.film_thickness = material.film_thickness(position);
    LightSample sample;
    sample.radiance = Color(kPi);  // POV's light colour 1
    sample.wi = wi;
    sample.pdf = 1.0f;
    sample.is_delta = true;
    return reflect_light_sample(at, sample);
}

TEST(PovFinish, DiffuseBacksideLightsFromBehindWithTheSecondValue) {
    MaterialParameters p;
    p.diffuse = 0.6f;
    const Vec3 behind = glm::normalize(Vec3(0.3f, 0.0f, -1.0f));
    EXPECT_FLOAT_EQ(lit(p, Vec3(0.0f), behind).diffuse.g, 0.0f);  // none without it
    p.diffuse_back = 0.4f;
    EXPECT_NEAR(lit(p, Vec3(0.0f), behind).diffuse.g, 0.4f * -behind.z, 1e-5f);
    p.phong = 1.0f;  // no highlight from behind
    EXPECT_FLOAT_EQ(lit(p, Vec3(0.0f), behind).glossy.g, 0.0f);
}

TEST(PovFinish, IridTintsEachChannelByThinFilmInterference) {
    MaterialParameters p;
    p.diffuse = 1.0f;
    p.irid = 0.5f;
    p.irid_thickness = 0.3f;
    const Vec3 wi = glm::normalize(Vec3(0.0f, 0.6f, 0.8f));
    const LobeRadiance r = lit(p, Vec3(0.0f), wi);
    const float phase = 2.0f * kPi * 0.3f * (0.8f + 1.0f);
    EXPECT_NEAR(r.diffuse.r, 0.8f * (1.0f + 0.5f * std::cos(phase / 0.70f)), 1e-4f);
    EXPECT_NEAR(r.diffuse.g, 0.8f * (1.0f + 0.5f * std::cos(phase / 0.52f)), 1e-4f);
    EXPECT_NEAR(r.diffuse.b, 0.8f * (1.0f + 0.5f * std::cos(phase / 0.48f)), 1e-4f);
}

TEST(PovFinish, CrandTakesAGrainOfHalfItsValueOnAverage) {
    MaterialParameters p;
    p.diffuse = 1.0f;
    p.crand = 0.4f;
    const Vec3 wi(0.0f, 0.0f, 1.0f);
    double sum = 0.0, lowest = 1.0, highest = 0.0;
    constexpr int kPoints = 4000;
    for (int i = 0; i < kPoints; ++i) {
        const double value = lit(p, Vec3(0.01f * float(i), 0.37f, 0.0f), wi).diffuse.g;
        sum += value;
        lowest = std::min(lowest, value);
        highest = std::max(highest, value);
    }
    // 1 - 0.4 u, u uniform in [0, 1): mean 0.8 (standard error ~0.002).
    EXPECT_NEAR(sum / kPoints, 0.8, 0.01);
    EXPECT_GE(lowest, 0.6 - 1e-6);
    EXPECT_LE(highest, 1.0 + 1e-6);
    EXPECT_LT(lowest, 0.62);  // the grain spans its range
    EXPECT_GT(highest, 0.98);
    // The same point gives the same grain: a render repeats.
    EXPECT_EQ(lit(p, Vec3(0.5f), wi).diffuse.g, lit(p, Vec3(0.5f), wi).diffuse.g);
}

}  // namespace
}  // namespace lancer
