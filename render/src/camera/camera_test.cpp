#include <gtest/gtest.h>

#include <cmath>

#include "lancer/camera.h"

namespace lancer {
namespace {

Ray ray_at(const Camera& camera, float x, float y, int width, int height) {
    Ray ray;
    EXPECT_TRUE(camera.generate_ray(x, y, width, height, ray));
    return ray;
}

// POV's camera with `angle A`: |direction| = |right| / tan(A/2) / 2.
Camera camera_with_angle(float degrees, float right_length) {
    const float direction_length = right_length / std::tan(glm::radians(degrees) / 2.0f) / 2.0f;
    return Camera(Camera::Projection::Perspective, Vec3(0.0f), Vec3(0, 0, direction_length), Vec3(right_length, 0, 0),
                  Vec3(0, 1, 0));
}

TEST(Camera, CentreOfImageLooksAlongDirection) {
    const Camera camera = camera_with_angle(60.0f, 1.33f);
    const Ray ray = ray_at(camera, 320.0f, 240.0f, 640, 480);
    EXPECT_NEAR(ray.direction.x, 0.0f, 1e-6f);
    EXPECT_NEAR(ray.direction.y, 0.0f, 1e-6f);
    EXPECT_NEAR(ray.direction.z, 1.0f, 1e-6f);
    EXPECT_FLOAT_EQ(glm::length(ray.direction), 1.0f);
}

TEST(Camera, LeftHandedPlusXIsRightAndPlusYIsUp) {
    const Camera camera = camera_with_angle(60.0f, 1.33f);
    EXPECT_GT(ray_at(camera, 600.0f, 240.0f, 640, 480).direction.x, 0.0f);  // right of centre
    EXPECT_LT(ray_at(camera, 40.0f, 240.0f, 640, 480).direction.x, 0.0f);
    EXPECT_GT(ray_at(camera, 320.0f, 10.0f, 640, 480).direction.y, 0.0f);  // top row looks up
    EXPECT_LT(ray_at(camera, 320.0f, 470.0f, 640, 480).direction.y, 0.0f);
}

TEST(Camera, AngleIsTheHorizontalFieldOfView) {
    const Camera camera = camera_with_angle(90.0f, 1.33f);
    const Ray left = ray_at(camera, 0.0f, 240.0f, 640, 480);
    const Ray right = ray_at(camera, 640.0f, 240.0f, 640, 480);
    const float full = std::acos(glm::dot(left.direction, right.direction));
    EXPECT_NEAR(glm::degrees(full), 90.0f, 1e-3f);
}

TEST(Camera, PixelCentresAreAtHalfIntegers) {
    // POV: x0 = (i + 0.5)/W - 0.5 for pixel i; pixel 0's centre of a 2-wide
    // image is at x0 = -0.25.
    const Camera camera(Camera::Projection::Perspective, Vec3(0.0f), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0));
    const Ray ray = ray_at(camera, 0.5f, 0.5f, 2, 2);
    const Vec3 expected = glm::normalize(Vec3(-0.25f, 0.25f, 1.0f));
    EXPECT_NEAR(ray.direction.x, expected.x, 1e-6f);
    EXPECT_NEAR(ray.direction.y, expected.y, 1e-6f);
}

TEST(Camera, OrthographicRaysAreParallelFromTheImagePlane) {
    const Camera camera(Camera::Projection::Orthographic, Vec3(0, 0, -5), Vec3(0, 0, 1), Vec3(4, 0, 0), Vec3(0, 3, 0));
    const Ray a = ray_at(camera, 0.0f, 0.0f, 4, 3);
    const Ray b = ray_at(camera, 4.0f, 3.0f, 4, 3);
    EXPECT_EQ(a.direction, Vec3(0, 0, 1));
    EXPECT_EQ(b.direction, Vec3(0, 0, 1));
    EXPECT_NEAR(a.origin.x, -2.0f, 1e-6f);
    EXPECT_NEAR(a.origin.y, 1.5f, 1e-6f);
    EXPECT_NEAR(b.origin.x, 2.0f, 1e-6f);
    EXPECT_NEAR(b.origin.y, -1.5f, 1e-6f);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

// A unit frame: direction z, right x, up y, all of length 1.
Camera unit_camera(Camera::Projection projection, double angle = 90.0) {
    Camera camera(projection, Vec3(0.0f), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0));
    camera.set_angles(angle, 360.0, 180.0);
    return camera;
}

void expect_direction(const Camera& camera, float x, float y, const Vec3& expected) {
    Ray ray;
    ASSERT_TRUE(camera.generate_ray(x, y, 100, 100, ray)) << "at " << x << ", " << y;
    EXPECT_NEAR(ray.direction.x, expected.x, 1e-5f) << "at " << x << ", " << y;
    EXPECT_NEAR(ray.direction.y, expected.y, 1e-5f) << "at " << x << ", " << y;
    EXPECT_NEAR(ray.direction.z, expected.z, 1e-5f) << "at " << x << ", " << y;
}

TEST(CameraProjections, FisheyeSeesItsAngleAcrossTheInscribedCircle) {
    const Camera camera = unit_camera(Camera::Projection::Fisheye, 180.0);
    expect_direction(camera, 50.0f, 50.0f, Vec3(0, 0, 1));
    // The circle's rim is half the angle off the axis: 90 degrees.
    expect_direction(camera, 100.0f, 50.0f, Vec3(1, 0, 0));
    expect_direction(camera, 50.0f, 0.0f, Vec3(0, 1, 0));
    // Half way out, 45 degrees.
    expect_direction(camera, 75.0f, 50.0f, glm::normalize(Vec3(1, 0, 1)));
    // The corners lie outside the circle: no ray, so the pixel is black.
    Ray ray;
    EXPECT_FALSE(camera.generate_ray(1.0f, 1.0f, 100, 100, ray));
    EXPECT_FALSE(camera.generate_ray(99.0f, 99.0f, 100, 100, ray));
}

TEST(CameraProjections, FisheyeOf360LooksBackwardsAtItsRim) {
    expect_direction(unit_camera(Camera::Projection::Fisheye, 360.0), 0.0f, 50.0f, Vec3(0, 0, -1));
}

TEST(CameraProjections, UltraWideAngleSpansItsAngleAcrossTheImage) {
    const Camera camera = unit_camera(Camera::Projection::UltraWideAngle, 180.0);
    expect_direction(camera, 50.0f, 50.0f, Vec3(0, 0, 1));
    expect_direction(camera, 100.0f, 50.0f, Vec3(1, 0, 0));
    expect_direction(camera, 0.0f, 50.0f, Vec3(-1, 0, 0));
    // Up spans angle * |up| / |right|; the corners still see (no circle).
    expect_direction(camera, 50.0f, 0.0f, Vec3(0, 1, 0));
    Ray ray;
    EXPECT_TRUE(camera.generate_ray(0.0f, 0.0f, 100, 100, ray));
}

TEST(CameraProjections, OmnimaxSeesNothingOutsideItsCircleNorFarBelowItsAxis) {
    const Camera camera = unit_camera(Camera::Projection::Omnimax);
    expect_direction(camera, 50.0f, 50.0f, Vec3(0, 0, 1));
    Ray ray;
    EXPECT_FALSE(camera.generate_ray(1.0f, 1.0f, 100, 100, ray));
    // Straight down the circle, the dome stops 45 degrees under its axis.
    EXPECT_FALSE(camera.generate_ray(50.0f, 99.0f, 100, 100, ray));
    EXPECT_TRUE(camera.generate_ray(50.0f, 1.0f, 100, 100, ray));
}

TEST(CameraProjections, PanoramicSweepsHalfATurnAndLooksStraightUpAtTheTop) {
    const Camera camera = unit_camera(Camera::Projection::Panoramic);
    expect_direction(camera, 0.0f, 50.0f, Vec3(-1, 0, 0));
    expect_direction(camera, 50.0f, 50.0f, Vec3(0, 0, 1));
    expect_direction(camera, 100.0f, 50.0f, Vec3(1, 0, 0));
    // The top edge is 90 degrees up: POV bounds tan() there, never NaN.
    expect_direction(camera, 50.0f, 0.0f, Vec3(0, 1, 0));
    expect_direction(camera, 50.0f, 100.0f, Vec3(0, -1, 0));
}

TEST(CameraProjections, SphericalCornersAndEdgesAreThePoles) {
    const Camera camera = unit_camera(Camera::Projection::Spherical);
    expect_direction(camera, 50.0f, 50.0f, Vec3(0, 0, 1));
    // Longitude spans 360 degrees: both side edges look backwards.
    expect_direction(camera, 0.0f, 50.0f, Vec3(0, 0, -1));
    expect_direction(camera, 100.0f, 50.0f, Vec3(0, 0, -1));
    expect_direction(camera, 25.0f, 50.0f, Vec3(-1, 0, 0));
    // Latitude spans 180: the top row is the zenith, whatever the column.
    expect_direction(camera, 0.0f, 0.0f, Vec3(0, 1, 0));
    expect_direction(camera, 80.0f, 0.0f, Vec3(0, 1, 0));
    expect_direction(camera, 30.0f, 100.0f, Vec3(0, -1, 0));
}

TEST(CameraProjections, CylindersTurnAboutOneAxisAndSlideAlongTheOther) {
    // cylinder 1: around up from the location, |up| high.
    const Camera one = unit_camera(Camera::Projection::Cylinder1, 180.0);
    expect_direction(one, 100.0f, 50.0f, Vec3(1, 0, 0));
    expect_direction(one, 50.0f, 0.0f, glm::normalize(Vec3(0, 0.5f, 1)));
    // cylinder 2: around right, |right| across.
    const Camera two = unit_camera(Camera::Projection::Cylinder2, 180.0);
    expect_direction(two, 50.0f, 0.0f, Vec3(0, 1, 0));
    expect_direction(two, 100.0f, 50.0f, glm::normalize(Vec3(0.5f, 0, 1)));
    // cylinder 3 and 4: parallel rays from a line through the location.
    Ray ray;
    const Camera three = unit_camera(Camera::Projection::Cylinder3, 180.0);
    ASSERT_TRUE(three.generate_ray(50.0f, 0.0f, 100, 100, ray));
    EXPECT_NEAR(ray.origin.y, 0.5f, 1e-6f);
    EXPECT_NEAR(ray.direction.z, 1.0f, 1e-6f);
    const Camera four = unit_camera(Camera::Projection::Cylinder4, 180.0);
    ASSERT_TRUE(four.generate_ray(0.0f, 50.0f, 100, 100, ray));
    EXPECT_NEAR(ray.origin.x, -0.5f, 1e-6f);
    EXPECT_NEAR(ray.direction.z, 1.0f, 1e-6f);
}

// Thin lens: every ray through one film point, wherever it leaves the
// aperture, meets the pinhole ray at the focal distance (measured along
// direction in units of |direction|).
TEST(CameraFocalBlur, PointsOnTheFocalPlaneStaySharp) {
    Camera camera(Camera::Projection::Perspective, Vec3(1, 2, 3), Vec3(0, 0, 2), Vec3(1.33f, 0, 0), Vec3(0, 1, 0));
    Camera::FocalBlur blur;
    blur.aperture = 0.8f;
    blur.samples = 16;
    blur.focal_distance = 6.0f;
    camera.set_focal_blur(blur);
    const Vec3 pinhole_direction = Vec3(0, 0, 2) + (0.3f - 0.5f) * Vec3(1.33f, 0, 0) + (0.5f - 0.6f) * Vec3(0, 1, 0);
    const Vec3 sharp_point = Vec3(1, 2, 3) + pinhole_direction * (6.0f / 2.0f);
    float largest_offset = 0.0f;
    for (const Vec2 lens : {Vec2(0.0f), Vec2(0.4f, 0.0f), Vec2(-0.2f, 0.3f), Vec2(0.1f, -0.45f)}) {
        Ray ray;
        ASSERT_TRUE(camera.generate_ray(30.0f, 60.0f, 100, 100, ray, lens));
        largest_offset = std::max(largest_offset, glm::length(ray.origin - Vec3(1, 2, 3)));
        // The point of the ray nearest the sharp point is the sharp point.
        const float t = glm::dot(sharp_point - ray.origin, ray.direction);
        EXPECT_LT(glm::length(ray.origin + t * ray.direction - sharp_point), 1e-4f);
    }
    // The lens point 0.45 off the centre moves the origin by aperture/2 * 0.45.
    EXPECT_NEAR(largest_offset, 0.4f * std::sqrt(0.1f * 0.1f + 0.45f * 0.45f), 1e-5f);
}

TEST(CameraFocalBlur, WithoutBlurSamplesTheLensIsIgnored) {
    Camera camera(Camera::Projection::Perspective, Vec3(0.0f), Vec3(0, 0, 1), Vec3(1, 0, 0), Vec3(0, 1, 0));
    Camera::FocalBlur blur;
    blur.aperture = 2.0f;  // POV-Ray: aperture alone does nothing
    camera.set_focal_blur(blur);
    EXPECT_FALSE(camera.has_focal_blur());
    Ray ray;
    ASSERT_TRUE(camera.generate_ray(50.0f, 50.0f, 100, 100, ray, Vec2(0.4f, 0.0f)));
    EXPECT_EQ(ray.origin, Vec3(0.0f));
}

// The general path agrees with the lane-parallel pinhole to float precision.
TEST(CameraProjections, PerspectiveThroughTheGeneralPathMatchesThePinhole) {
    Camera pinhole(Camera::Projection::Perspective, Vec3(0.0f), Vec3(0.2f, 0.1f, 1.5f), Vec3(1.33f, 0, 0),
                   Vec3(0, 1, 0));
    Camera blurred = pinhole;
    Camera::FocalBlur blur;
    blur.aperture = 1.0f;
    blur.samples = 1;
    blurred.set_focal_blur(blur);
    for (float x : {3.0f, 50.0f, 97.0f}) {
        Ray a, b;
        ASSERT_TRUE(pinhole.generate_ray(x, 20.0f, 100, 100, a));
        ASSERT_TRUE(blurred.generate_ray(x, 20.0f, 100, 100, b, Vec2(0.0f)));
        EXPECT_LT(glm::length(a.direction - b.direction), 1e-6f);
    }
}

}  // namespace
}  // namespace lancer
