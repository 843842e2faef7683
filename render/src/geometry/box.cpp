// Boxes: slab intersection, face surfaces, and sampling by world area
// (six parallelograms) for emissive boxes.
#include "geometry/shapes.h"

#include <algorithm>
#include <cfloat>
#include <cmath>

#include "geometry/polygon_sampler.h"

namespace lancer {

bool intersect_box(const AnalyticBox& b, const DVec3& o, const DVec3& d, double t_min, double t_max, double& t,
                   int& face) {
    double t_enter = -INFINITY, t_exit = INFINITY;
    int face_enter = -1, face_exit = -1;
    for (int axis = 0; axis < 3; ++axis) {
        if (d[axis] == 0.0) {
            if (o[axis] < b.lower[axis] || o[axis] > b.upper[axis]) return false;
            continue;
        }
        const double inverse = 1.0 / d[axis];
        double t_lower = (b.lower[axis] - o[axis]) * inverse;
        double t_upper = (b.upper[axis] - o[axis]) * inverse;
        int f_lower = 2 * axis, f_upper = 2 * axis + 1;
        // By direction, not by comparing t: a box flat along this axis has
        // t_lower == t_upper, and the face the ray enters is the one facing it.
        if (d[axis] < 0.0) {
            std::swap(t_lower, t_upper);
            std::swap(f_lower, f_upper);
        }
        if (t_lower > t_enter) {
            t_enter = t_lower;
            face_enter = f_lower;
        }
        if (t_upper < t_exit) {
            t_exit = t_upper;
            face_exit = f_upper;
        }
        if (t_enter > t_exit) return false;
    }
    if (t_enter > t_min && t_enter < t_max && face_enter >= 0) {
        t = t_enter;
        face = face_enter;
        return true;
    }
    if (t_exit > t_min && t_exit < t_max && face_exit >= 0) {
        t = t_exit;
        face = face_exit;
        return true;
    }
    return false;
}

namespace {

// POV's box (u,v): the six faces laid out as an unfolded cube, four side
// faces across (-x, +z, +x, -z, a quarter of u each) and the bottom and
// top below and above +z (a third of v each), none mirrored from outside.
Vec2 box_uv(const AnalyticBox& b, int face, const DVec3& point) {
    // Only the two axes across the face: the divisions are most of the cost.
    const int across = face / 2;
    DVec3 q(0.0);
    for (int a = 0; a < 3; ++a) {
        const double extent = b.upper[a] - b.lower[a];
        if (a != across && extent > 0.0) q[a] = (point[a] - b.lower[a]) / extent;
    }
    double u = 0.0, v = 0.0;
    switch (face) {
    case 0: u = q.z / 4.0, v = (1.0 + q.y) / 3.0; break;          // -x
    case 1: u = 0.75 - q.z / 4.0, v = (1.0 + q.y) / 3.0; break;   // +x
    case 2: u = 0.25 + q.x / 4.0, v = q.z / 3.0; break;           // -y
    case 3: u = 0.25 + q.x / 4.0, v = 1.0 - q.z / 3.0; break;     // +y
    case 4: u = 1.0 - q.x / 4.0, v = (1.0 + q.y) / 3.0; break;    // -z
    default: u = 0.25 + q.x / 4.0, v = (1.0 + q.y) / 3.0; break;  // +z
    }
    return Vec2(float(u), float(v));
}

}  // namespace

SurfaceGeometry box_surface(const AnalyticBox& b, const DVec3& p, int face, bool with_uv) {
    SurfaceGeometry g;
    const int axis = face / 2;
    const bool upper = face % 2 == 1;
    g.point = glm::clamp(p, b.lower, b.upper);
    g.point[axis] = upper ? b.upper[axis] : b.lower[axis];
    g.normal = DVec3(0.0);
    g.normal[axis] = upper ? 1.0 : -1.0;
    g.uv = with_uv ? box_uv(b, face, g.point) : Vec2(0.0f);
    return g;
}

std::unique_ptr<SurfaceSampler> make_box_sampler(const AnalyticBox& b, const Placement& placement,
                                                 const Material* material) {
    std::vector<PolygonSampler::Polygon> faces;
    for (int face = 0; face < 6; ++face) {
        const int axis = face / 2;
        const int u_axis = axis == 0 ? 2 : 0;
        const int v_axis = axis == 1 ? 2 : 1;
        DVec3 corner = b.lower;
        corner[axis] = face % 2 == 1 ? b.upper[axis] : b.lower[axis];
        DVec3 along_u(0.0), along_v(0.0);
        along_u[u_axis] = b.upper[u_axis] - b.lower[u_axis];
        along_v[v_axis] = b.upper[v_axis] - b.lower[v_axis];
        PolygonSampler::Polygon p;
        p.origin = placement.point_to_world(corner);
        p.edge1 = placement.point_to_world(corner + along_u) - p.origin;
        p.edge2 = placement.point_to_world(corner + along_v) - p.origin;
        // (u,v) is affine over a face: its corners' values interpolate it.
        p.uv0 = box_uv(b, face, corner);
        p.uv1 = box_uv(b, face, corner + along_u);
        p.uv2 = box_uv(b, face, corner + along_v);
        p.parallelogram = true;
        p.material = material;
        faces.push_back(p);
    }
    return std::make_unique<PolygonSampler>(std::move(faces), true);
}

}  // namespace lancer
