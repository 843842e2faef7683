// What a hit needs beyond Embree's answer: the point and its error bound,
// normals, (u,v), material and emitter, for triangles (lane by lane for a
// packet's plain world-mesh hits) and for analytic shapes.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "geometry/embree_scene.h"
#include "geometry/float_steps.h"

namespace lancer::embree {
namespace {

// Triangle hits from the float vertices Embree intersected: each point an
// affine combination of the corners (on the triangle's plane up to
// rounding, which the error bounds: pbrt-v4's gamma(7) bound for this sum,
// made generous for Embree's own arithmetic) and the unit geometric normal.
// Lane by lane (structure of arrays), so the compiler computes several
// lanes per instruction: a packet's square roots and divisions then cost
// little more than one ray's.
struct TriangleSurfaces {
    float px[kMaxLanes], py[kMaxLanes], pz[kMaxLanes];
    float nx[kMaxLanes], ny[kMaxLanes], nz[kMaxLanes];
    float largest[kMaxLanes];  // of the corners' coordinates, in magnitude
};

// The point's error bound per axis, in the space of the corners.
inline float triangle_point_error(float largest_coordinate) {
    return 16.0f * FLT_EPSILON * largest_coordinate;
}

// Lane k: the triangle whose corner indices start at corners[k], into the
// xyz array positions[k], at barycentrics (b1[k], b2[k]); count at most
// kMaxLanes.
void triangle_surfaces(const float* const* positions, const std::uint32_t* const* corners, const float* b1,
                       const float* b2, int count, TriangleSurfaces& out) {
    float corner_x[3][kMaxLanes], corner_y[3][kMaxLanes], corner_z[3][kMaxLanes];
    for (int k = 0; k < count; ++k)
        for (int c = 0; c < 3; ++c) {
            const float* xyz = &positions[k][3 * std::size_t(corners[k][c])];
            corner_x[c][k] = xyz[0];
            corner_y[c][k] = xyz[1];
            corner_z[c][k] = xyz[2];
        }
    for (int k = 0; k < count; ++k) {
        const float b0 = 1.0f - b1[k] - b2[k];
        out.px[k] = b0 * corner_x[0][k] + b1[k] * corner_x[1][k] + b2[k] * corner_x[2][k];
        out.py[k] = b0 * corner_y[0][k] + b1[k] * corner_y[1][k] + b2[k] * corner_y[2][k];
        out.pz[k] = b0 * corner_z[0][k] + b1[k] * corner_z[1][k] + b2[k] * corner_z[2][k];
        const float e1x = corner_x[1][k] - corner_x[0][k], e1y = corner_y[1][k] - corner_y[0][k],
                    e1z = corner_z[1][k] - corner_z[0][k];
        const float e2x = corner_x[2][k] - corner_x[0][k], e2y = corner_y[2][k] - corner_y[0][k],
                    e2z = corner_z[2][k] - corner_z[0][k];
        const float cx = e1y * e2z - e2y * e1z, cy = e1z * e2x - e2z * e1x, cz = e1x * e2y - e2x * e1y;
        const float length = std::sqrt(cx * cx + cy * cy + cz * cz);
        // A degenerate (zero-area) or overflowing triangle gets +y.
        const bool usable = length > 0.0f && length <= FLT_MAX;
        const float inverse = 1.0f / length;
        out.nx[k] = usable ? cx * inverse : 0.0f;
        out.ny[k] = usable ? cy * inverse : 1.0f;
        out.nz[k] = usable ? cz * inverse : 0.0f;
        float m = 0.0f;
        for (int c = 0; c < 3; ++c)
            m = std::max(
                m, std::max(std::fabs(corner_x[c][k]), std::max(std::fabs(corner_y[c][k]), std::fabs(corner_z[c][k]))));
        out.largest[k] = m;
    }
}

// One triangle's hit point, unit normal and the point's error bound.
struct TriangleSurface {
    Vec3 point, normal, error;
    float largest_coordinate;
};

TriangleSurface triangle_surface(const float* positions, const std::uint32_t* corners, float b1, float b2) {
    TriangleSurfaces lane;
    triangle_surfaces(&positions, &corners, &b1, &b2, 1, lane);
    return TriangleSurface{Vec3(lane.px[0], lane.py[0], lane.pz[0]), Vec3(lane.nx[0], lane.ny[0], lane.nz[0]),
                           Vec3(triangle_point_error(lane.largest[0])), lane.largest[0]};
}

}  // namespace

// Completes `count` (at most kMaxLanes) hits on plain world meshes: lane k
// found triangle primitive[k] of *meshes[k] at distance t[k] and
// barycentrics (u[k], v[k]); written to hits[k].
void complete_plain_triangle_hits(const PlainTriangles* const* meshes, const float* t, const unsigned* primitive,
                                  const float* u, const float* v, int count, Hit* hits) {
    const float* positions[kMaxLanes];
    const std::uint32_t* corners[kMaxLanes];
    for (int k = 0; k < count; ++k) {
        positions[k] = meshes[k]->positions;
        corners[k] = &meshes[k]->indices[3 * std::size_t(primitive[k])];
    }
    TriangleSurfaces surfaces;
    triangle_surfaces(positions, corners, u, v, count, surfaces);
    // World-space error: the corners' bound and the rounding of the point.
    float ex[kMaxLanes], ey[kMaxLanes], ez[kMaxLanes];
    for (int k = 0; k < count; ++k) {
        const float corner_error = triangle_point_error(surfaces.largest[k]);
        ex[k] = corner_error + 2.0f * FLT_EPSILON * std::fabs(surfaces.px[k]);
        ey[k] = corner_error + 2.0f * FLT_EPSILON * std::fabs(surfaces.py[k]);
        ez[k] = corner_error + 2.0f * FLT_EPSILON * std::fabs(surfaces.pz[k]);
    }
    for (int k = 0; k < count; ++k) {
        const PlainTriangles& mesh = *meshes[k];
        Hit& hit = hits[k];
        hit.t = t[k];
        hit.position = Vec3(surfaces.px[k], surfaces.py[k], surfaces.pz[k]);
        hit.position_error = Vec3(ex[k], ey[k], ez[k]);
        hit.geometric_normal = hit.shading_normal = Vec3(surfaces.nx[k], surfaces.ny[k], surfaces.nz[k]);
        hit.uv = Vec2(u[k], v[k]);
        hit.material = mesh.material;
        hit.mix = nullptr;
        hit.unbumped_normal = Vec3(0.0f);
        hit.emitter = mesh.emitter;
        hit.object_id = mesh.object_id;
        hit.interior_id = mesh.interior_id;
        hit.primitive_id = primitive[k];
        hit.casts_shadow = mesh.casts_shadow;
        hit.light_group = mesh.light_group;
        hit.lit_by_global_lights = mesh.lit_by_global_lights;
        hit.double_illuminate = mesh.double_illuminate;
    }
}

// POV-Ray shows an object's interior_texture where the ray runs along the
// surface's normal (POV's, smooth and unbent): it meets the surface from
// inside.
static void show_interior_texture(const Instance& instance, const Vec3& pov_normal, const Vec3& ray_direction,
                                  Hit& hit) {
    if (instance.interior_material && glm::dot(pov_normal, ray_direction) > 0.0f)
        hit.material = instance.interior_material;
}

void EmbreeScene::complete_analytic_hit(const Instance& instance, const Ray& ray, float t, int face, Hit& hit) const {
    DVec3 o, d;
    const float org[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const float dir[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    ray_to_object(instance, org, dir, o, d);
    const DVec3 p = o + double(t) * d;
    SurfaceGeometry g;
    const bool wants_uv = m_data->reads_surface_uv;
    switch (instance.kind) {
    case ShapeKind::Sphere: g = sphere_surface(instance.sphere, p, wants_uv); break;
    case ShapeKind::Box: g = box_surface(instance.box, p, face, wants_uv); break;
    case ShapeKind::Plane: g = plane_surface(instance.plane, p); break;
    case ShapeKind::Analytic:
        // A shape whose (u, v) POV-Ray leaves undefined reads the world's x
        // and y instead (below): its own would be computed for nothing.
        g = wants_uv && !instance.uv_from_world ? instance.shape->surface(p, face)
                                                : instance.shape->surface_without_uv(p, face);
        break;
    default: g = rectangle_surface(instance.rectangle, p); break;
    }
    if (instance.flip_normal) {
        g.normal = -g.normal;
        g.shading_normal = -g.shading_normal;
    }
    const DVec3 world = instance.placement.point_to_world(g.point);
    hit.position = Vec3(world);
    hit.position_error = instance.placement.world_point_error(g.point, world);
    // A sphere's, a box's and a plane's normals are unit already: in world
    // coordinates they need no second normalisation (two double divisions
    // and a square root a hit).
    const bool unit_in_world =
        instance.placement.identity &&
        (instance.kind == ShapeKind::Sphere || instance.kind == ShapeKind::Box || instance.kind == ShapeKind::Plane);
    hit.geometric_normal = Vec3(unit_in_world ? g.normal : instance.placement.normal_to_world_unit(g.normal));
    if (g.shading_normal != DVec3(0.0)) {
        // A mesh's written normals may disagree with its winding: the
        // facet's normal is turned to the shading side, as for meshes out
        // of CSG (the side a spawned ray is offset to follows its direction).
        hit.shading_normal = Vec3(instance.placement.normal_to_world_unit(g.shading_normal));
        if (glm::dot(hit.shading_normal, hit.geometric_normal) < 0.0f) hit.geometric_normal = -hit.geometric_normal;
    } else {
        hit.shading_normal = hit.geometric_normal;
    }
    hit.uv = !wants_uv ? Vec2(0.0f) : instance.uv_from_world ? Vec2(float(world.x), float(world.y)) : g.uv;
    // A mesh in CSG keeps its per-triangle textures.
    const std::size_t face_index = std::size_t(face);
    hit.material = face >= 0 && face_index < instance.face_materials.size() && instance.face_materials[face_index]
                       ? instance.face_materials[face_index]
                       : instance.material;
    hit.primitive_id = std::uint32_t(face);
}

void EmbreeScene::complete_mesh_hit(const Instance& instance, std::uint32_t primitive, float u, float v,
                                    const Vec3& ray_direction, Hit& hit) const {
    const MeshData& mesh = *instance.mesh;
    const std::uint32_t face_index = primitive;  // triangle i is face i (MeshData::indices)
    const std::vector<float>& positions = traced_positions(instance);
    const float* vertices = positions.data();
    const std::uint32_t* corners = &mesh.indices[3 * primitive];
    const TriangleSurface surface = triangle_surface(vertices, corners, u, v);
    const float b1 = u, b2 = v, b0 = 1.0f - b1 - b2;
    const Vec3& p = surface.point;
    const Vec3& normal = surface.normal;
    const Vec3& object_error = surface.error;
    const float largest = surface.largest_coordinate;
    Vec3 world, world_normal, error;
    if (instance.mesh_in_world) {
        world = p;
        world_normal = normal;
        error = object_error + 2.0f * FLT_EPSILON * glm::abs(p);
    } else {
        const DVec3 world_point = instance.placement.point_to_world(DVec3(p));
        world = Vec3(world_point);
        world_normal = Vec3(instance.placement.normal_to_world_unit(DVec3(normal)));
        const DMat3 a(instance.placement.world_from_object);
        DVec3 spread(0.0);
        for (int row = 0; row < 3; ++row)
            for (int col = 0; col < 3; ++col) spread[row] += std::fabs(a[col][row]) * double(object_error[col]);
        // Embree maps the ray to object space in float: an error of a few
        // ULPs of the world coordinates and the translation too.
        error = Vec3(spread) + 8.0f * instance.placement.world_point_error(DVec3(largest), world_point);
    }
    hit.position = world;
    hit.position_error = error;
    hit.geometric_normal = world_normal;
    hit.shading_normal = world_normal;  // not read back from hit: that stalls on the store just made
    // The source face (40 bytes a triangle, cold in cache: Embree traces its
    // own copies of the vertices) is read only when the mesh has per-vertex
    // normals or texture coordinates to interpolate.
    const bool has_normals = !mesh.normals.empty(), has_uvs = !mesh.uvs.empty();
    const sg::TriangleMesh::Face* face = has_normals || has_uvs ? &mesh.faces[face_index] : nullptr;
    // POV's normal of a flat triangle is the opposite of lancer's (see
    // mesh_shape.cpp); a smooth one's is the corners' blend in both.
    Vec3 pov_normal = -world_normal;
    if (has_normals && face->normal[0] >= 0) {
        DVec3 interpolated(0.0);
        const double weight[3] = {b0, b1, b2};
        for (int k = 0; k < 3; ++k) {
            const int n = face->normal[k];
            if (n >= 0 && std::size_t(n) < mesh.normals.size()) interpolated += weight[k] * mesh.normals[n];
        }
        if (glm::length(interpolated) > 0.0) {
            const Vec3 shading(instance.placement.normal_to_world_unit(interpolated));
            hit.shading_normal = shading;
            pov_normal = shading;
            // Keep both normals on the side the mesh author's normals give.
            if (glm::dot(shading, hit.geometric_normal) < 0.0f) hit.geometric_normal = -hit.geometric_normal;
        }
    }
    if (has_uvs && face->uv[0] >= 0) {
        glm::dvec2 uv(0.0);
        const double weight[3] = {b0, b1, b2};
        for (int k = 0; k < 3; ++k) {
            const int index = face->uv[k];
            if (index >= 0 && std::size_t(index) < mesh.uvs.size()) uv += weight[k] * mesh.uvs[index];
        }
        hit.uv = Vec2(uv);
    } else {
        hit.uv = Vec2(u, v);
    }
    const Material* face_material =
        face_index < instance.face_materials.size() ? instance.face_materials[face_index] : nullptr;
    hit.material = face_material ? face_material : instance.material;
    show_interior_texture(instance, pov_normal, ray_direction, hit);
    hit.primitive_id = face_index;
}

void EmbreeScene::complete_packet(const Ray* rays, const PacketAnswers& answers, int lanes, Hit* hits,
                                  bool* found) const {
    // The common case, every lane on a plain world mesh (and no planes,
    // outside the BVH, that may lie nearer), is completed lane-parallel;
    // any other packet lane by lane.
    const PlainTriangles* plain_mesh[kPacketLanes] = {};  // lanes past `lanes` stay null
    bool all_plain = m_unbounded.empty();
    for (int k = 0; k < lanes; ++k) {
        plain_mesh[k] = plain_triangles_of(answers.geometry[k], answers.instance[k]);
        all_plain = all_plain && plain_mesh[k] != nullptr;
    }
    if (all_plain) {
        complete_plain_triangle_hits(plain_mesh, answers.tfar, answers.primitive, answers.u, answers.v, lanes, hits);
        for (int k = 0; k < lanes; ++k) found[k] = true;
    } else {
        for (int k = 0; k < lanes; ++k) found[k] = complete_hit(rays[k], answers.lane(k), hits[k]);
    }
    for (int k = 0; k < lanes; ++k)
        if (found[k]) hits[k].ray_direction = rays[k].direction;
}

const Instance* EmbreeScene::mesh_instance_of(const EmbreeHit& found) const {
    if (found.geometry == kInvalidId) return nullptr;
    const GeometryEntry& entry = m_geometries[found.instance != kInvalidId ? found.instance : found.geometry];
    return entry.group ? nullptr : &m_data->instances[entry.instance];
}

void EmbreeScene::complete_instance_hit(std::uint32_t index, std::uint32_t leaf, const Ray& ray, float t, int face,
                                        Hit& hit) const {
    const Instance& instance = m_data->instances[index];
    const Instance& surface = m_data->instances[leaf];
    hit = Hit{};
    hit.t = t;
    complete_analytic_hit(surface, ray, t, face, hit);
    hit.object_id = leaf;
    hit.interior_id = surface.interior_id;
    hit.casts_shadow = instance.casts_shadow;
    hit.light_group = instance.light_group;
    hit.lit_by_global_lights = instance.lit_by_global_lights;
    hit.double_illuminate = surface.double_illuminate;
    show_interior_texture(surface, hit.shading_normal, ray.direction, hit);
    hit.emitter = emitter_of(surface, hit.material);
}

bool EmbreeScene::complete_hit(const Ray& ray, const EmbreeHit& found, Hit& hit, bool with_unbounded) const {
    if (!with_unbounded) return found.geometry != kInvalidId && complete_bvh_hit(ray, found, hit);
    // Unbounded shapes are outside the BVH: test them against the nearest so far.
    std::uint32_t unbounded_hit = kInvalidId, unbounded_leaf = 0;
    int unbounded_face = 0;
    // Embree reports its hit's distance in float; an unbounded shape at the
    // same float distance wins the tie. A transparent box resting on a
    // plane meets the plane exactly where its bottom is: without this the
    // ray inside it found the floor or the bottom face at random, by the
    // rounding of the box's distance, and half the floor under the box
    // showed what lies below (POV-Ray shows the floor).
    double unbounded_t =
        found.geometry == kInvalidId || m_unbounded.empty() ? double(found.tfar) : double(next_float_up(found.tfar));
    m_unbounded.nearest(*m_data, ray, found.tnear, unbounded_t, unbounded_hit, unbounded_leaf, unbounded_face);
    if (unbounded_hit != kInvalidId) {
        complete_instance_hit(unbounded_hit, unbounded_leaf, ray, float(unbounded_t), unbounded_face, hit);
        return true;
    }
    if (found.geometry == kInvalidId) return false;
    return complete_bvh_hit(ray, found, hit);
}

bool EmbreeScene::complete_bvh_hit(const Ray& ray, const EmbreeHit& found, Hit& hit) const {
    if (const PlainTriangles* mesh = plain_triangles_of(found.geometry, found.instance)) {
        complete_plain_triangle_hits(&mesh, &found.tfar, &found.primitive, &found.u, &found.v, 1, &hit);
        return true;
    }

    const unsigned top = found.instance != kInvalidId ? found.instance : found.geometry;
    const GeometryEntry& entry = m_geometries[top];
    if (entry.group) {
        const std::uint32_t index = entry.group->instances[found.primitive];
        complete_instance_hit(index, index - std::uint32_t(found.v), ray, found.tfar, int(found.u), hit);
        return true;
    }
    hit = Hit{};
    hit.t = found.tfar;
    const std::uint32_t index = entry.instance;
    complete_mesh_hit(m_data->instances[index], found.primitive, found.u, found.v, ray.direction, hit);
    const Instance& instance = m_data->instances[index];
    hit.object_id = index;
    hit.interior_id = instance.interior_id;
    hit.casts_shadow = instance.casts_shadow;
    hit.light_group = instance.light_group;
    hit.lit_by_global_lights = instance.lit_by_global_lights;
    hit.double_illuminate = instance.double_illuminate;
    hit.emitter = emitter_of(instance, hit.material);
    return true;
}

}  // namespace lancer::embree
