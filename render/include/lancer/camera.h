// The camera, resolved from the scene graph as POV-Ray 3.7 frames it
// (pov-3.7-semantics.md §1): every POV projection, focal blur's thin lens
// and a camera normal. The pinhole perspective camera, nearly every scene's,
// is inline and lane-parallel; the others are in render/src/camera/, POV's
// mesh_camera among them (its faces are the camera's MeshCameraRays).
#pragma once

#include <cmath>

#include "lancer/ray.h"

namespace lancer {

class NormalPerturbation;
class MeshCameraRays;
class ApertureShape;

class Camera {
  public:
    enum class Projection {
        Perspective,
        Orthographic,
        Fisheye,
        UltraWideAngle,
        Omnimax,
        Panoramic,
        Cylinder1,
        Cylinder2,
        Cylinder3,
        Cylinder4,
        Spherical,
        Mesh,  // POV's mesh_camera: rays leave mesh faces (set_mesh)
    };

    // POV-Ray's focal blur: rays leave a lens across the aperture and meet
    // again at focal_distance along the direction (in units of
    // |direction|, as POV measures it).
    struct FocalBlur {
        float aperture = 0.0f;  // 0: a pinhole
        float focal_distance = 1.0f;
        int samples = 0;      // POV's blur_samples (its most per pixel)
        int samples_min = 0;  // the least before POV's confidence test
        float confidence = 0.9f;
        float variance = 1.0f / 10000.0f;
    };

    Camera() = default;
    Camera(Projection projection, const Vec3& location, const Vec3& direction, const Vec3& right, const Vec3& up)
        : m_projection(projection), m_location(location), m_direction(direction), m_right(right), m_up(up) {}

    // POV's `angle` for the non-planar projections (degrees; default 90)
    // and the spherical camera's two spans.
    void set_angles(double angle, double horizontal, double vertical) {
        m_angle = angle;
        m_horizontal_angle = horizontal;
        m_vertical_angle = vertical;
    }
    void set_focal_blur(const FocalBlur& blur) { m_blur = blur; }
    // POV's bokeh: the lens' shape and transmission, which the host draws
    // lens points from (null: the round lens); must outlive the camera.
    void set_bokeh(const ApertureShape* bokeh) { m_bokeh = bokeh; }
    const ApertureShape* bokeh() const { return m_bokeh; }
    // Bends every ray's direction as a surface normal (POV's camera
    // normal { }); the perturbation must outlive the camera.
    void set_normal(const NormalPerturbation* normal) { m_normal = normal; }
    // The faces a Mesh projection's rays leave from, and how many rays a
    // pixel averages (POV's rays_per_pixel); the faces must outlive the
    // camera.
    void set_mesh(const MeshCameraRays* mesh, int rays_per_pixel) {
        m_mesh = mesh;
        m_rays_per_pixel = rays_per_pixel;
    }

    // The ray through the film point (x, y) in pixels, (0,0) the top-left
    // corner of the image and (width, height) the bottom-right; pixel
    // centres are at half-integers, as POV-Ray's. `lens` is the point of
    // the aperture the ray leaves from, in POV's sample-grid units (the
    // disc of radius 0.5; ignored without focal blur). Returns false where
    // the projection sees nothing (a fisheye's corners, outside omnimax's
    // circle, a mesh camera's pixel past its faces): POV traces no ray
    // there. `ray_number` (0 to rays_per_pixel() - 1) picks which of a
    // mesh camera's rays of the pixel this is; other cameras ignore it.
    bool generate_ray(float x, float y, int width, int height, Ray& ray, const Vec2& lens = Vec2(0.0f),
                      int ray_number = 0) const {
        if (!is_pinhole_perspective()) return generate_general_ray(x, y, width, height, lens, ray_number, ray);
        // Normalised image coordinates: x0 in [-0.5, 0.5] left to right, y0
        // in [-0.5, 0.5] bottom to top.
        const float x0 = x / float(width) - 0.5f;
        const float y0 = 0.5f - y / float(height);
        ray.origin = m_location;
        ray.direction = glm::normalize(m_direction + x0 * m_right + y0 * m_up);
        ray.t_min = 0.0f;
        ray.t_max = kInfinity;
        return true;
    }

    // generate_ray for `count` film points (x[i], y[i]), lens points
    // lens[i] (null: the lens centre) and ray numbers ray_numbers[i] (null:
    // 0), bit for bit, into out[i] and sees[i]. The pinhole perspective
    // camera is computed lane by lane, so the compiler takes several rays
    // per instruction: the host generates a tile's camera rays at once.
    void generate_rays(const float* x, const float* y, const Vec2* lens, int count, int width, int height, Ray* out,
                       bool* sees, const int* ray_numbers = nullptr) const {
        if (!is_pinhole_perspective()) {
            for (int i = 0; i < count; ++i)
                sees[i] = generate_general_ray(x[i], y[i], width, height, lens ? lens[i] : Vec2(0.0f),
                                               ray_numbers ? ray_numbers[i] : 0, out[i]);
            return;
        }
        constexpr int kLanes = 16;
        for (int first = 0; first < count; first += kLanes) {
            const int lanes = count - first < kLanes ? count - first : kLanes;
            float dx[kLanes], dy[kLanes], dz[kLanes];
            for (int i = 0; i < lanes; ++i) {
                // generate_ray's arithmetic, component by component.
                const float x0 = x[first + i] / float(width) - 0.5f;
                const float y0 = 0.5f - y[first + i] / float(height);
                const float vx = (m_direction.x + x0 * m_right.x) + y0 * m_up.x;
                const float vy = (m_direction.y + x0 * m_right.y) + y0 * m_up.y;
                const float vz = (m_direction.z + x0 * m_right.z) + y0 * m_up.z;
                const float inverse_length = 1.0f / std::sqrt((vx * vx + vy * vy) + vz * vz);
                dx[i] = vx * inverse_length;
                dy[i] = vy * inverse_length;
                dz[i] = vz * inverse_length;
            }
            for (int i = 0; i < lanes; ++i) {
                Ray& ray = out[first + i];
                ray.origin = m_location;
                ray.direction = Vec3(dx[i], dy[i], dz[i]);
                ray.t_min = 0.0f;
                ray.t_max = kInfinity;
                sees[first + i] = true;
            }
        }
    }

    Projection projection() const { return m_projection; }
    const Vec3& location() const { return m_location; }
    const Vec3& direction() const { return m_direction; }
    const Vec3& right() const { return m_right; }
    const Vec3& up() const { return m_up; }
    double angle() const { return m_angle; }
    const FocalBlur& focal_blur() const { return m_blur; }
    bool has_focal_blur() const { return m_blur.aperture != 0.0f && m_blur.samples > 0; }
    const NormalPerturbation* normal() const { return m_normal; }
    // The rays a pixel averages over those the camera makes: POV's
    // rays_per_pixel for a mesh camera, 1 for every other.
    int rays_per_pixel() const { return m_rays_per_pixel; }

  private:
    bool is_pinhole_perspective() const {
        return m_projection == Projection::Perspective && !has_focal_blur() && m_normal == nullptr;
    }
    // Every other projection, focal blur and the camera normal, in double
    // precision (render/src/camera/camera_projections.cpp).
    bool generate_general_ray(float x, float y, int width, int height, const Vec2& lens, int ray_number,
                              Ray& ray) const;

    Projection m_projection = Projection::Perspective;
    Vec3 m_location{0.0f};
    Vec3 m_direction{0.0f, 0.0f, 1.0f};
    Vec3 m_right{1.33f, 0.0f, 0.0f};
    Vec3 m_up{0.0f, 1.0f, 0.0f};
    double m_angle = 90.0;
    double m_horizontal_angle = 360.0, m_vertical_angle = 180.0;
    FocalBlur m_blur;
    const NormalPerturbation* m_normal = nullptr;
    const ApertureShape* m_bokeh = nullptr;
    const MeshCameraRays* m_mesh = nullptr;
    int m_rays_per_pixel = 1;
};

}  // namespace lancer
