// The camera block, resolved as POV-Ray 3.7's Parse_Camera does (parse.cpp
// in POV-Ray 3.7, read for its rules; pov-3.7-semantics.md section 1): the
// type first, then the vectors applied in a fixed order whatever order the
// block lists them in, focal blur's settings, and the block's transforms.
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {
namespace {

using Projection = sg::Camera::Projection;

bool is_planar(Projection p) {
    return p == Projection::Perspective || p == Projection::Orthographic;
}

const char* projection_name(Projection p) {
    switch (p) {
    case Projection::Perspective: return "perspective";
    case Projection::Orthographic: return "orthographic";
    case Projection::Fisheye: return "fisheye";
    case Projection::UltraWideAngle: return "ultra_wide_angle";
    case Projection::Omnimax: return "omnimax";
    case Projection::Panoramic: return "panoramic";
    case Projection::Cylinder1: return "cylinder 1";
    case Projection::Cylinder2: return "cylinder 2";
    case Projection::Cylinder3: return "cylinder 3";
    case Projection::Cylinder4: return "cylinder 4";
    case Projection::Spherical: return "spherical";
    case Projection::Mesh: return "mesh_camera";
    }
    return "camera";
}

}  // namespace

// POV's order: right, direction, angle, up, sky, location, look_at,
// focal_point; transforms come last.
sg::Camera resolve_camera(const CameraSpec& spec, bool* sky_along_view) {
    sg::Camera camera;
    camera.projection = spec.projection;
    camera.location_in_source = spec.location_in_source;
    sg::Vec3 right = spec.right.value_or(sg::Vec3(1.33, 0.0, 0.0));
    sg::Vec3 direction = spec.direction.value_or(sg::Vec3(0.0, 0.0, 1.0));
    sg::Vec3 up = spec.up.value_or(sg::Vec3(0.0, 1.0, 0.0));
    sg::Vec3 sky = spec.sky.value_or(sg::Vec3(0.0, 1.0, 0.0));
    sg::Vec3 location = spec.location.value_or(sg::Vec3(0.0));
    // Where an unfocused focal blur focuses: POV's Direction_Length, which
    // only angle and look_at set (a bare `direction` leaves it at 1).
    double direction_length = 1.0;
    if (spec.angle && spec.projection == Projection::Spherical) {
        camera.horizontal_angle = *spec.angle;
        camera.vertical_angle = spec.vertical_angle.value_or(*spec.angle * 0.5);
    } else if (spec.angle) {
        camera.angle = *spec.angle;
        if (is_planar(spec.projection) && *spec.angle > 0.0) {
            // angle is the horizontal field of view: |direction| = |right| / 2 / tan(angle / 2).
            direction_length = 0.5 * glm::length(right) / std::tan(glm::radians(*spec.angle) / 2.0);
            direction = glm::normalize(direction) * direction_length;
        }
    }
    if (spec.look_at) {
        sg::Vec3 target = *spec.look_at;
        if (glm::length(target - location) > 0.0) {
            direction_length = glm::length(direction);
            // POV keeps right's sense only when (up x direction) . right is positive: a
            // frame with up along direction has none, and its image comes out mirrored.
            double handedness = glm::dot(glm::cross(up, direction), right) > 0.0 ? 1.0 : -1.0;
            sg::Vec3 d = glm::normalize(target - location);
            sg::Vec3 new_right = glm::cross(sky, d);
            // Looking along the sky: POV keeps the right vector it had
            // (with a warning) and still turns up to face the view.
            if (glm::length(new_right) < 1e-10) {
                new_right = right;
                if (sky_along_view) *sky_along_view = true;
            }
            const double right_length = glm::length(right);
            right = glm::normalize(new_right) * right_length * handedness;
            up = glm::normalize(glm::cross(d, right)) * glm::length(up);
            // Keep up's sense when right was flipped (left-handed frame).
            if (handedness < 0.0) up = -up;
            direction = d * direction_length;
        }
    }
    if (spec.projection == Projection::Orthographic && ((!spec.up && !spec.right) || spec.angle)) {
        // POV-Ray's orthographic camera sees the area the perspective one
        // sees at the look_at distance (look_at defaulting to <0,0,1>):
        // right and up grow by |look_at - location| / |direction|.
        const double k1 = glm::length(spec.look_at.value_or(sg::Vec3(0.0, 0.0, 1.0)) - location);
        const double k2 = glm::length(direction);
        if (k1 > 1e-10 && k2 > 1e-10) {
            right *= k1 / k2;
            up *= k1 / k2;
        }
    }
    camera.focal_distance = spec.focal_point ? glm::length(*spec.focal_point - location) : direction_length;
    if (camera.focal_distance == 0.0) camera.focal_distance = 1.0;
    camera.aperture = spec.aperture;
    camera.blur_samples = spec.blur_samples;
    camera.blur_samples_min = spec.blur_samples_min;
    camera.confidence = spec.confidence;
    camera.variance = spec.variance;
    camera.normal = spec.normal;
    camera.bokeh = spec.bokeh;
    camera.mesh = spec.mesh;
    const sg::Mat4& m = spec.world_from_camera;
    camera.location = sg::Vec3(m * glm::dvec4(location, 1.0));
    camera.direction = sg::Vec3(m * glm::dvec4(direction, 0.0));
    camera.right = sg::Vec3(m * glm::dvec4(right, 0.0));
    camera.up = sg::Vec3(m * glm::dvec4(up, 0.0));
    return camera;
}

double Evaluator::camera_angle(const Value& v, const SourceRange& where) {
    const double angle = to_float(v, where, "a float angle in degrees");
    if (v.kind == Value::Kind::Float && angle < 0.0) {
        error(where.begin, "a camera angle must not be negative, got " + std::to_string(angle));
        return 0.0;
    }
    return angle;
}

Projection Evaluator::cylinder_camera(const Value& v, const SourceRange& where) {
    // POV truncates the number, as it does every integer it reads.
    const int type = saturated_int(to_float(v, where, "a cylinder camera type (1 to 4)"));
    switch (type) {
    case 1: return Projection::Cylinder1;
    case 2: return Projection::Cylinder2;
    case 3: return Projection::Cylinder3;
    case 4: return Projection::Cylinder4;
    default:
        if (v.kind == Value::Kind::Float)
            error(where.begin, "invalid cylinder camera type " + std::to_string(type) + ": the types are 1 to 4");
        return Projection::Cylinder1;
    }
}

// blur_samples N, or blur_samples MIN, MAX: POV traces at least MIN and at
// most MAX rays per pixel, stopping in between when its confidence test
// passes.
std::function<void(CameraSpec&)> Evaluator::blur_samples(const Value& first, const SourceRange& wf, const Value* second,
                                                         const SourceRange& ws) {
    int least = saturated_int(to_float(first, wf, "a number of focal blur samples"));
    int most = second ? saturated_int(to_float(*second, ws, "a number of focal blur samples")) : 0;
    if (least <= 0 && first.kind == Value::Kind::Float) {
        error(wf.begin, "blur_samples must be at least 1, got " + std::to_string(least));
        least = 1;
    }
    if (most == 0) {
        most = least;
        least = 0;
    } else if (least > most) {
        error(ws.begin, "the least number of focal blur samples must not be larger than the most");
        most = least;
    }
    constexpr int kMostBlurSamples = 1 << 16;
    if (most > kMostBlurSamples) {
        error((second ? ws : wf).begin, "blur_samples is at most " + std::to_string(kMostBlurSamples));
        most = kMostBlurSamples;
        least = std::min(least, most);
    }
    return [least, most](CameraSpec& c) {
        c.blur_samples = most;
        c.blur_samples_min = least;
        c.other_item_seen = true;
    };
}

std::function<void(CameraSpec&)> Evaluator::blur_confidence(const Value& v, const SourceRange& where) {
    const double value = to_float(v, where, "a float confidence");
    if (!(value > 0.0 && value < 1.0)) {
        warning(where.begin, "confidence must lie strictly between 0 and 1; the default 0.9 is used (as POV-Ray does)");
        return [](CameraSpec& c) { c.other_item_seen = true; };
    }
    return [value](CameraSpec& c) {
        c.confidence = value;
        c.other_item_seen = true;
    };
}

std::function<void(CameraSpec&)> Evaluator::blur_variance(const Value& v, const SourceRange& where) {
    const double value = to_float(v, where, "a float variance");
    if (!(value >= 0.0 && value <= 1.0)) {
        warning(where.begin, "variance must lie between 0 and 1; the default 1/10000 is used (as POV-Ray does)");
        return [](CameraSpec& c) { c.other_item_seen = true; };
    }
    return [value](CameraSpec& c) {
        c.variance = value;
        c.other_item_seen = true;
    };
}

void Evaluator::set_camera(const CameraSpec& spec) {
    if (m_saw_camera)
        warning(spec.location_in_source, "a second camera replaces the first (POV-Ray uses the last one)");
    m_saw_camera = true;
    if (spec.late_type_location) {
        error(*spec.late_type_location, std::string("the camera type (") + projection_name(spec.projection) +
                                            ") must come first in the camera block, before its other items (POV-Ray "
                                            "reads it there)");
        return;
    }
    if (spec.angle && spec.projection != Projection::Orthographic && !spec.angle_has_value) {
        error(spec.angle_location, "angle needs a value here (only an orthographic camera's angle may go without)");
        return;
    }
    if (spec.angle && spec.projection == Projection::Perspective && !(*spec.angle > 0.0 && *spec.angle < 180.0)) {
        error(spec.angle_location, "a perspective camera's angle must be between 0 and 180 degrees (exclusive), got " +
                                       std::to_string(*spec.angle));
        return;
    }
    if (spec.angle && spec.projection == Projection::Orthographic && *spec.angle >= 180.0) {
        error(spec.angle_location,
              "an orthographic camera's angle must be below 180 degrees, got " + std::to_string(*spec.angle));
        return;
    }
    if (spec.vertical_angle && spec.projection != Projection::Spherical) {
        error(spec.angle_location, "only the spherical camera takes two angles");
        return;
    }
    if (spec.angle && spec.projection == Projection::Mesh) {
        error(spec.angle_location, "a mesh_camera takes no angle (its meshes place and aim its rays)");
        return;
    }
    if (spec.look_at && glm::length(*spec.look_at - spec.location.value_or(sg::Vec3(0.0))) == 0.0) {
        error(spec.location_in_source, "camera location and look_at point must be different (as in POV-Ray)");
        return;
    }
    bool sky_along_view = false;
    m_scene.camera = resolve_camera(spec, &sky_along_view);
    // The three vectors must span space, or every ray is the same ray (or
    // none): POV-Ray renders such a camera as garbage or black.
    const sg::Camera& c = *m_scene.camera;
    const double volume = std::fabs(glm::dot(glm::cross(c.right, c.up), c.direction));
    const double scale = glm::length(c.right) * glm::length(c.up) * glm::length(c.direction);
    // A mesh camera reads only location.z and direction.z.
    if (!(volume > 1e-9 * scale) && c.projection != Projection::Mesh) {
        error(spec.location_in_source,
              "the camera's direction, up and right vectors lie in one plane (or one is zero): they must span "
              "space");
        return;
    }
    // lancer traces in single precision, and its ray tracer takes no ray
    // whose origin lies farther out than about 1.8e18 on an axis.
    constexpr double kFarthestCameraCoordinate = 1e18;
    if (c.projection != Projection::Mesh && !(std::fabs(c.location.x) <= kFarthestCameraCoordinate &&
                                              std::fabs(c.location.y) <= kFarthestCameraCoordinate &&
                                              std::fabs(c.location.z) <= kFarthestCameraCoordinate)) {
        error(spec.location_in_source,
              "the camera's location lies more than 1e18 from the origin along an axis: lancer traces no ray from "
              "that far (move the scene towards the origin)");
        return;
    }
    if (sky_along_view)
        warning(spec.location_in_source,
                "the camera looks along its sky direction: the right vector is kept as given (POV-Ray's rule); "
                "set sky to choose which way is up");
    if (c.projection == Projection::Mesh && c.focal_blur()) {
        warning(spec.location_in_source,
                "focal blur is ignored on a mesh_camera: POV-Ray puts no lens in front of its rays either");
        m_scene.camera->aperture = 0.0;
        return;
    }
    if (spec.aperture != 0.0 && spec.blur_samples == 0)
        warning(spec.location_in_source,
                "aperture without blur_samples: no focal blur (POV-Ray traces none either); add blur_samples N");
    const bool parallel_rays = spec.projection == Projection::Orthographic ||
                               spec.projection == Projection::Cylinder3 || spec.projection == Projection::Cylinder4;
    if (c.focal_blur() && parallel_rays)
        warning(spec.location_in_source,
                std::string("focal blur starts every ray at the camera's location (POV-Ray's rule, kept), so this ") +
                    projection_name(spec.projection) + " camera loses its parallel rays: the picture is a blur");
    if (spec.aperture == 0.0 && (spec.blur_samples > 0 || spec.focal_point))
        warning(spec.location_in_source, "blur_samples and focal_point do nothing without an aperture");
    if (spec.bokeh && !c.focal_blur())
        warning(spec.bokeh->location,
                "bokeh shapes the lens of focal blur: without aperture and blur_samples it does nothing");
}

}  // namespace lancer::parse
