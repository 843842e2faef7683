// Hit::offset_origin's last step, the float one further from the surface on
// each axis, against std::nextafter: zeros, denormals, signs, the largest
// floats and infinities.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "lancer/hit.h"

namespace lancer {
namespace {

// The origin offset_origin should give: position moved along the normal by
// the error box, then one float further on each axis the offset moves.
Vec3 expected_origin(const Hit& hit, const Vec3& direction) {
    const float distance = glm::dot(glm::abs(hit.geometric_normal), hit.position_error);
    Vec3 offset = distance * hit.geometric_normal;
    if (glm::dot(direction, hit.geometric_normal) < 0.0f) offset = -offset;
    Vec3 origin = hit.position + offset;
    for (int axis = 0; axis < 3; ++axis) {
        if (offset[axis] > 0.0f) origin[axis] = std::nextafter(origin[axis], kInfinity);
        if (offset[axis] < 0.0f) origin[axis] = std::nextafter(origin[axis], -kInfinity);
    }
    return origin;
}

TEST(HitOffsetOrigin, StepsOneFloatAwayAsNextafterDoes) {
    const float big = std::numeric_limits<float>::max();
    const float tiny = std::numeric_limits<float>::denorm_min();
    const float values[] = {0.0f, -0.0f, tiny, -tiny, 1e-30f, -1e-30f, 0.5f, -0.5f, 1.0f, -3.0e7f, big, -big};
    const Vec3 normals[] = {glm::normalize(Vec3(1, 2, -3)), Vec3(0, 0, 1), glm::normalize(Vec3(-1, -1, 1))};
    for (const float value : values)
        for (const Vec3& normal : normals)
            for (const float sign : {1.0f, -1.0f}) {
                Hit hit;
                hit.position = Vec3(value, -value, 0.25f * value);
                hit.position_error = Vec3(std::fabs(value) * 1e-6f);
                hit.geometric_normal = normal;
                const Vec3 direction = sign * normal;
                const Vec3 got = hit.offset_origin(direction), want = expected_origin(hit, direction);
                for (int axis = 0; axis < 3; ++axis) {
                    // The same float, sign of zero included.
                    EXPECT_EQ(std::signbit(got[axis]), std::signbit(want[axis])) << value;
                    EXPECT_TRUE(got[axis] == want[axis] || (std::isnan(got[axis]) && std::isnan(want[axis])))
                        << "value " << value << " axis " << axis << ": " << got[axis] << " != " << want[axis];
                }
            }
}

TEST(HitOffsetOrigin, RandomHitsStepAsNextafterDoes) {
    // Positions of every scale and sign, errors and normals at random, some
    // axes of the normal exactly zero (no step there).
    std::mt19937 random(7);
    std::uniform_real_distribution<float> unit(-1.0f, 1.0f), exponent(-40.0f, 38.0f);
    auto coordinate = [&] { return unit(random) * std::pow(10.0f, exponent(random)); };
    for (int i = 0; i < 100000; ++i) {
        Hit hit;
        hit.position = Vec3(coordinate(), coordinate(), coordinate());
        Vec3 normal(unit(random), unit(random), unit(random));
        if (i % 3 == 0) normal[i % 7 % 3] = 0.0f;
        if (!(glm::length(normal) > 0.0f)) continue;
        hit.geometric_normal = glm::normalize(normal);
        hit.position_error = glm::abs(hit.position) * (1e-7f * std::fabs(unit(random)));
        const Vec3 direction(unit(random), unit(random), unit(random));
        const Vec3 got = hit.offset_origin(direction), want = expected_origin(hit, direction);
        for (int axis = 0; axis < 3; ++axis) {
            ASSERT_EQ(std::signbit(got[axis]), std::signbit(want[axis])) << i;
            ASSERT_TRUE(got[axis] == want[axis] || (std::isnan(got[axis]) && std::isnan(want[axis])))
                << "hit " << i << " axis " << axis << ": " << got[axis] << " != " << want[axis];
        }
    }
}

TEST(HitOffsetOrigin, AnOriginLandingOnZeroStepsToTheSmallestFloat) {
    // The offset cancels the position exactly: the step leaves zero for the
    // smallest denormal on the offset's side, as std::nextafter does.
    Hit hit;
    hit.geometric_normal = Vec3(0, 0, 1);
    hit.position_error = Vec3(0, 0, 1e-30f);
    hit.position = Vec3(0, 0, -1e-30f);
    EXPECT_EQ(hit.offset_origin(Vec3(0, 0, 1)).z, std::numeric_limits<float>::denorm_min());
    hit.position = Vec3(0, 0, 1e-30f);
    EXPECT_EQ(hit.offset_origin(Vec3(0, 0, -1)).z, -std::numeric_limits<float>::denorm_min());
}

}  // namespace
}  // namespace lancer
