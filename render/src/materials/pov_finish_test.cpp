// The finish's highlights at POV-Ray's peak values (pov-3.7-semantics.md
// §3.3, §3.4): under a light of colour C, brdf * cos * pi*C is exactly
// POV's phong * c^phong_size * C and specular * c^(1/roughness) * C.
#include <cmath>

#include <gtest/gtest.h>

#include "lancer/material.h"

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

}  // namespace
}  // namespace lancer
