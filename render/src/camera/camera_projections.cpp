// POV-Ray 3.7's camera projections other than the pinhole perspective, its
// focal blur lens and its camera normal, as CreateCameraRay and
// JitterCameraRay compute them (tracepixel.cpp in POV-Ray 3.7, read for
// the formulas; docs/scene-language.md describes each projection). In
// double precision: the wide projections go through trigonometry, and a
// camera far from the origin or with a tiny field of view needs the digits.
#include <cmath>

#include "lancer/camera.h"
#include "lancer/hit.h"
#include "lancer/material.h"

#include "camera/mesh_camera.h"

namespace lancer {
namespace {

using DVec3 = glm::dvec3;
constexpr double kPiDouble = 3.14159265358979323846;

// POV's bound on tan() where the panoramic camera looks straight up or
// down (BOUND_HUGE), and its EPSILON.
constexpr double kBoundHuge = 2.0e10;
constexpr double kPovEpsilon = 1.0e-10;

DVec3 unit(const DVec3& v) {
    const double length = glm::length(v);
    return length > 0.0 ? v / length : v;
}

// v turned by `angle` radians about the unit axis k (Rodrigues' formula;
// POV's Compute_Axis_Rotation_Transform applied to a point).
DVec3 rotate_about(const DVec3& v, const DVec3& k, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    return v * c + glm::cross(k, v) * s + k * (glm::dot(k, v) * (1.0 - c));
}

// Polar angle of (x0, y0) as POV's fisheye and omnimax measure it.
double polar_angle(double x0, double y0, double radius) {
    if (radius == 0.0) return 0.0;
    return x0 < 0.0 ? kPiDouble - std::asin(y0 / radius) : std::asin(y0 / radius);
}

// One projected ray before the lens: its origin, its direction (not
// normalised: focal blur scales it, as POV does), and the image point
// (x0, y0) a camera normal's pattern is read at.
struct Projected {
    DVec3 origin{0.0};
    DVec3 direction{0.0, 0.0, 1.0};
    double x0 = 0.0, y0 = 0.0;
};

}  // namespace

bool Camera::generate_general_ray(float x, float y, int width, int height, const Vec2& lens, int ray_number,
                                  Ray& ray) const {
    // u runs 0..1 left to right, v 0..1 bottom to top.
    const double u = double(x) / double(width);
    const double v = 1.0 - double(y) / double(height);
    const DVec3 location(m_location), direction(m_direction), right(m_right), up(m_up);
    // POV normalises the frame of the projections that read angles off it.
    const DVec3 unit_right = unit(right), unit_up = unit(up), unit_direction = unit(direction);
    const double right_length = glm::length(right), up_length = glm::length(up);
    const double degrees = kPiDouble / 180.0;

    Projected p;
    p.origin = location;
    switch (m_projection) {
    case Projection::Perspective:
        p.x0 = u - 0.5;
        p.y0 = v - 0.5;
        p.direction = direction + p.x0 * right + p.y0 * up;
        break;
    case Projection::Orthographic:
        p.x0 = u - 0.5;
        p.y0 = v - 0.5;
        p.direction = direction;
        p.origin = location + p.x0 * right + p.y0 * up;
        break;
    case Projection::Fisheye: {
        // The image's inscribed ellipse (scaled by right and up) sees a
        // cone of `angle` degrees; outside it, nothing.
        const double x0 = (2.0 * u - 1.0) * right_length, y0 = (2.0 * v - 1.0) * up_length;
        const double radius = std::sqrt(x0 * x0 + y0 * y0);
        if (radius > 1.0) return false;
        p.x0 = polar_angle(x0, y0, radius);
        p.y0 = radius * m_angle * degrees * 0.5;
        const double sy = std::sin(p.y0);
        p.direction =
            std::cos(p.x0) * sy * unit_right + std::sin(p.x0) * sy * unit_up + std::cos(p.y0) * unit_direction;
        break;
    }
    case Projection::Omnimax: {
        // A dome projection: the circle fills the image's width, its centre
        // shifted down; the polynomial maps radius to the angle from the
        // axis. POV's constants.
        constexpr double kOmnimaxAspect = 1.283458;
        double x0 = 2.0 * u - 1.0, y0 = 2.0 * v - 1.0;
        const double aspect = right_length / up_length;
        if (aspect > 1.0) {
            if (aspect > kOmnimaxAspect) {
                x0 *= aspect / kOmnimaxAspect;
                y0 = (y0 - 1.0) / kOmnimaxAspect + 1.0;
            } else {
                y0 = (y0 - 1.0) / aspect + 1.0;
            }
        } else {
            y0 /= aspect;
        }
        const double radius = std::sqrt(x0 * x0 + y0 * y0);
        if (radius > 1.0) return false;
        p.x0 = polar_angle(x0, y0, radius);
        const double r3 = radius * radius * radius;
        p.y0 = 1.411269 * radius - 0.09439 * r3 + 0.25674 * r3 * radius * radius;
        const double cx = std::cos(p.x0), sx = std::sin(p.x0), cy = std::cos(p.y0), sy = std::sin(p.y0);
        // The dome does not reach below 45 degrees under its axis.
        if (sx * sy < std::tan(135.0 * degrees) * cy) return false;
        p.direction = cx * sy * unit_right + sx * sy * unit_up + cy * unit_direction;
        break;
    }
    case Projection::Panoramic: {
        // Graphics Gems III: 180 degrees around the up axis, latitude by
        // the tangent (POV's frame as given, not normalised).
        p.x0 = (1.0 - u) * kPiDouble;
        p.y0 = 0.5 * kPiDouble * (2.0 * v - 1.0);
        double ty;
        if (std::fabs(0.5 * kPiDouble - std::fabs(p.y0)) < kPovEpsilon)
            ty = p.y0 > 0.0 ? kBoundHuge : -kBoundHuge;
        else
            ty = std::tan(p.y0);
        p.direction = std::cos(p.x0) * right + ty * up + std::sin(p.x0) * direction;
        break;
    }
    case Projection::UltraWideAngle: {
        p.x0 = (u - 0.5) * m_angle * degrees;
        p.y0 = (v - 0.5) * m_angle * (up_length / right_length) * degrees;
        p.direction =
            std::sin(p.x0) * unit_right + std::sin(p.y0) * unit_up + std::cos(p.x0) * std::cos(p.y0) * unit_direction;
        break;
    }
    case Projection::Cylinder1:
    case Projection::Cylinder3: {
        // Around the up axis: `angle` degrees across, |up| high.
        p.x0 = (u - 0.5) * m_angle * degrees;
        p.y0 = (v - 0.5) * up_length;
        if (m_projection == Projection::Cylinder1) {
            p.direction = std::sin(p.x0) * unit_right + p.y0 * unit_up + std::cos(p.x0) * unit_direction;
        } else {
            p.direction = std::sin(p.x0) * unit_right + std::cos(p.x0) * unit_direction;
            p.origin = location + p.y0 * unit_up;
        }
        break;
    }
    case Projection::Cylinder2:
    case Projection::Cylinder4: {
        // Around the right axis: `angle` degrees high, |right| across.
        p.x0 = (u - 0.5) * right_length;
        p.y0 = (v - 0.5) * m_angle * degrees;
        if (m_projection == Projection::Cylinder2) {
            p.direction = p.x0 * unit_right + std::sin(p.y0) * unit_up + std::cos(p.y0) * unit_direction;
        } else {
            p.direction = std::sin(p.y0) * unit_up + std::cos(p.y0) * unit_direction;
            p.origin = location + p.x0 * unit_right;
        }
        break;
    }
    case Projection::Spherical: {
        // Latitude: direction turned about right; longitude: then about up.
        p.x0 = (u - 0.5) * m_horizontal_angle * degrees;
        p.y0 = (v - 0.5) * m_vertical_angle * degrees;
        const DVec3 latitude = rotate_about(direction, unit_right, -p.y0);
        p.direction = rotate_about(latitude, unit_up, p.x0);
        break;
    }
    case Projection::Mesh:
        // A camera normal's pattern is read at the image point (0, 0) for
        // every mesh ray, as POV leaves it.
        if (!m_mesh || !m_mesh->generate(x, y, width, height, ray_number, p.origin, p.direction)) return false;
        break;
    }

    // POV puts no lens in front of a mesh camera.
    if (has_focal_blur() && m_projection != Projection::Mesh) {
        // POV's thin lens: the origin moves across the aperture, in the
        // plane of up x direction and direction x that, to the camera's
        // location (POV moves every projection's origin there, the
        // orthographic camera's too); the direction turns back so that
        // points at focal_distance stay where the pinhole sees them.
        const DVec3 x_perp = unit(glm::cross(up, direction));
        const DVec3 y_perp = unit(glm::cross(direction, x_perp));
        const double half_aperture = 0.5 * double(m_blur.aperture);
        const DVec3 deflection = half_aperture * (double(lens.x) * x_perp - double(lens.y) * y_perp);
        p.origin = location + deflection;
        p.direction = p.direction * (double(m_blur.focal_distance) / glm::length(direction)) - deflection;
    }
    DVec3 d = unit(p.direction);
    if (m_normal) {
        // POV bends the ray as a surface normal, the pattern read at (x0, y0, 0).
        Hit at_image_point;
        at_image_point.position = Vec3(float(p.x0), float(p.y0), 0.0f);
        at_image_point.object_id = ~std::uint32_t(0);  // no object: the pattern's own space
        at_image_point.shading_normal = at_image_point.geometric_normal = Vec3(d);
        d = unit(DVec3(m_normal->perturb(at_image_point, Vec3(d))));
    }
    if (!(std::isfinite(d.x) && std::isfinite(d.y) && std::isfinite(d.z)) || d == DVec3(0.0)) return false;
    ray.origin = Vec3(p.origin);
    ray.direction = Vec3(d);
    ray.t_min = 0.0f;
    ray.t_max = kInfinity;
    // A mesh camera's optional reach (POV's max ray distance, from 1e-10).
    if (m_projection == Projection::Mesh && m_mesh->settings().max_distance >= 1e-10)
        ray.t_max = float(m_mesh->settings().max_distance);
    return true;
}

}  // namespace lancer
