#include <gtest/gtest.h>

#include <cmath>

#include "lancer/camera.h"

namespace lancer {
namespace {

// POV's camera with `angle A`: |direction| = |right| / tan(A/2) / 2.
Camera camera_with_angle(float degrees, float right_length) {
    const float direction_length = right_length / std::tan(glm::radians(degrees) / 2.0f) / 2.0f;
    return Camera(Camera::Projection::Perspective, Vec3(0.0f), Vec3(0, 0, direction_length), Vec3(right_length, 0, 0),
                  Vec3(0, 1, 0));
}

TEST(Camera, CentreOfImageLooksAlongDirection) {
    const Camera camera = camera_with_angle(60.0f, 1.33f);
    const Ray ray = camera.generate_ray(320.0f, 240.0f, 640, 480);
    EXPECT_NEAR(ray.direction.x, 0.0f, 1e-6f);
    EXPECT_NEAR(ray.direction.y, 0.0f, 1e-6f);
    EXPECT_NEAR(ray.direction.z, 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(glm::length(ray.direction), 1.0f);
}

TEST(Camera, LeftHandedPlusXIsRightAndPlusYIsUp) {
    const Camera camera = camera_with_angle(60.0f, 1.33f);
    EXPECT_GT(camera.generate_ray(600.0f, 240.0f, 640, 480).direction.x, 0.0f);  // right of centre
    EXPECT_LT(camera.generate_ray(40.0f, 240.0f, 640, 480).direction.x, 0.0f);
    EXPECT_GT(camera.generate_ray(320.0f, 10.0f, 640, 480).direction.y, 0.0f);  // top row looks up
    EXPECT_LT(camera.generate_ray(320.0f, 470.0f, 640, 480).direction.y, 0.0f);
}

TEST(Camera, AngleIsTheHorizontalFieldOfView) {
    const Camera camera = camera_with_angle(90.0f, 1.33f);
    const Ray left = camera.generate_ray(0.0f, 240.0f, 640, 480);
    const Ray right = camera.generate_ray(640.0f, 240.0f, 640, 480);
    const float full = std::acos(glm::dot(left.direction, right.direction));
    EXPECT_NEAR(glm::degrees(full), 90.0f, 1e-3f);
}

TEST(Camera, PixelCentresAreAtHalfIntegers) {
    // POV: x0 = (i + 0.5)/W - 0.5 for pixel i; pixel 0's centre of a 2-wide
    // image is at x0 = -0.25.
    const Camera camera(Camera::Projection::Perspective, Vec3(0.0f), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0));
    const Ray ray = camera.generate_ray(0.5f, 0.5f, 2, 2);
    const Vec3 expected = glm::normalize(Vec3(-0.25f, 0.25f, 1.0f));
    EXPECT_NEAR(ray.direction.x, expected.x, 1e-6f);
    EXPECT_NEAR(ray.direction.y, expected.y, 1e-6f);
}

TEST(Camera, OrthographicRaysAreParallelFromTheImagePlane) {
    const Camera camera(Camera::Projection::Orthographic, Vec3(0, 0, -5), Vec3(0, 0, 1), Vec3(4, 0, 0), Vec3(0, 3, 0));
    const Ray a = camera.generate_ray(0.0f, 0.0f, 4, 3);
    const Ray b = camera.generate_ray(4.0f, 3.0f, 4, 3);
    EXPECT_EQ(a.direction, Vec3(0, 0, 1));
    EXPECT_EQ(b.direction, Vec3(0, 0, 1));
    EXPECT_NEAR(a.origin.x, -2.0f, 1e-6f);
    EXPECT_NEAR(a.origin.y, 1.5f, 1e-6f);
    EXPECT_NEAR(b.origin.x, 2.0f, 1e-6f);
    EXPECT_NEAR(b.origin.y, -1.5f, 1e-6f);
}

}  // namespace
}  // namespace lancer
