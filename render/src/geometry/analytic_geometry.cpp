// Analytic shapes (spheres, boxes, rectangle lights, planes, every Shape
// and CSG trees) as Embree user geometry: bounds, intersection of single rays and packets, shadow
// queries, and the filter that lets shadow rays pass no_shadow meshes.
#include <cmath>

#include "geometry/embree_scene.h"

namespace lancer::embree {

// Ray in an object's space, in double.
void ray_to_object(const Instance& instance, const float org[3], const float dir[3], DVec3& o, DVec3& d) {
    o = instance.placement.point_to_object(DVec3(org[0], org[1], org[2]));
    d = instance.placement.vector_to_object(DVec3(dir[0], dir[1], dir[2]));
}

// Lane i of a packet of n rays in an object's space (a single ray is n = 1).
static void ray_lane_to_object(const Instance& instance, RTCRayN* rays, unsigned n, unsigned i, DVec3& o, DVec3& d) {
    const float org[3] = {RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i)};
    const float dir[3] = {RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i)};
    ray_to_object(instance, org, dir, o, d);
}

bool intersect_analytic(const SceneData& data, std::uint32_t self, const DVec3& o, const DVec3& d, double t_min,
                        double t_max, double& t, int& face, std::uint32_t& leaf) {
    const Instance& instance = data.instances[self];
    face = 0;
    leaf = self;
    switch (instance.kind) {
    case ShapeKind::Sphere: return intersect_sphere(instance.sphere, o, d, t_min, t_max, t);
    case ShapeKind::Box: return intersect_box(instance.box, o, d, t_min, t_max, t, face);
    case ShapeKind::Rectangle: return intersect_rectangle(instance.rectangle, o, d, t_min, t_max, t);
    case ShapeKind::Plane: return intersect_plane(instance.plane, o, d, t_min, t_max, t);
    case ShapeKind::Analytic: {
        ShapeCrossing crossing;
        if (!instance.shape->nearest(o, d, t_min, t_max, crossing)) return false;
        t = crossing.t;
        face = crossing.face;
        return true;
    }
    case ShapeKind::Csg: {
        // A tree's leaves carry world placements: the root's is the identity.
        CsgCrossing crossing;
        if (!instance.csg->nearest(data.instances, o, d, t_min, t_max, crossing)) return false;
        t = crossing.t;
        face = crossing.face;
        leaf = crossing.instance;
        return true;
    }
    default: return false;
    }
}

void analytic_bounds(const RTCBoundsFunctionArguments* args) {
    const auto* group = static_cast<const AnalyticGroup*>(args->geometryUserPtr);
    const Instance& instance = group->data->instances[group->instances[args->primID]];
    *args->bounds_o = RTCBounds{instance.bounds_lower.x, instance.bounds_lower.y, instance.bounds_lower.z, 0.0f,
                                instance.bounds_upper.x, instance.bounds_upper.y, instance.bounds_upper.z, 0.0f};
}

// Embree calls these with one ray, or with a packet of N when rays are
// traced together (intersect_batch); valid[i] says which lanes are live.
void analytic_intersect(const RTCIntersectFunctionNArguments* args) {
    const auto* group = static_cast<const AnalyticGroup*>(args->geometryUserPtr);
    const std::uint32_t index = group->instances[args->primID];
    const Instance& instance = group->data->instances[index];
    const unsigned n = args->N;
    RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, n);
    RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, n);
    for (unsigned i = 0; i < n; ++i) {
        if (!args->valid[i]) continue;
        float& tfar = RTCRayN_tfar(rays, n, i);
        DVec3 o, d;
        ray_lane_to_object(instance, rays, n, i, o, d);
        double t;
        int face;
        std::uint32_t leaf;
        if (!intersect_analytic(*group->data, index, o, d, RTCRayN_tnear(rays, n, i), tfar, t, face, leaf)) continue;
        const float t_float = float(t);
        if (!(t_float < tfar)) continue;
        tfar = t_float;
        // u: the face; v: how far before its root the CSG leaf was listed
        // (0 for other shapes; exact in a float for trees below 2^24 leaves).
        RTCHitN_u(hits, n, i) = float(face);
        RTCHitN_v(hits, n, i) = float(index - leaf);
        RTCHitN_Ng_x(hits, n, i) = 0.0f;
        RTCHitN_Ng_y(hits, n, i) = 1.0f;
        RTCHitN_Ng_z(hits, n, i) = 0.0f;
        RTCHitN_primID(hits, n, i) = args->primID;
        RTCHitN_geomID(hits, n, i) = args->geomID;
        RTCHitN_instID(hits, n, i, 0) = args->context->instID[0];
    }
}

void analytic_occluded(const RTCOccludedFunctionNArguments* args) {
    const auto* group = static_cast<const AnalyticGroup*>(args->geometryUserPtr);
    const std::uint32_t index = group->instances[args->primID];
    const Instance& instance = group->data->instances[index];
    if (!instance.casts_shadow) return;
    // Occlusion queries come only with a ShadowContext (ray_queries.cpp).
    auto* context = reinterpret_cast<ShadowContext*>(args->context);
    const bool passes_through = context->classify && !instance.blocks_all_light;
    // Nothing more to learn here, unless each crossing is being recorded
    // (and there is still room: past it the walk does the counting).
    const bool recording = context->records && !context->records->overflowed;
    if (passes_through && context->see_through_met && !recording) return;
    const unsigned n = args->N;
    RTCRayN* rays = args->ray;
    for (unsigned i = 0; i < n; ++i) {
        if (!args->valid[i]) continue;
        DVec3 o, d;
        ray_lane_to_object(instance, rays, n, i, o, d);
        double t;
        int face;
        std::uint32_t leaf;
        const float t_near = RTCRayN_tnear(rays, n, i), t_far = RTCRayN_tfar(rays, n, i);
        if (!intersect_analytic(*group->data, index, o, d, t_near, t_far, t, face, leaf)) continue;
        if (!passes_through) {
            RTCRayN_tfar(rays, n, i) = -INFINITY;
            continue;
        }
        context->see_through_met = true;
        if (!recording) continue;
        if (!instance.gathers_crossings) {
            context->records->overflowed = true;  // its later crossings: the walk's to find
            continue;
        }
        record_crossings(*group->data, index, o, d, t_near, t_far, t, face, leaf,
                         EmbreeHit{0.0f, 0.0f, args->geomID, args->primID, args->context->instID[0], 0.0f, 0.0f},
                         *context->records);
    }
}

void record_crossings(const SceneData& data, std::uint32_t self, const DVec3& o, const DVec3& d, float t_near,
                      float t_far, double t, int face, std::uint32_t leaf, const EmbreeHit& ids,
                      SeeThroughRecords& records) {
    for (int more = 0; more < SeeThroughRecords::kMost; ++more) {
        records.add(
            EmbreeHit{t_near, float(t), ids.geometry, ids.primitive, ids.instance, float(face), float(self - leaf)});
        if (records.overflowed) break;
        const float past = std::nextafter(float(t), INFINITY);
        if (!(past < t_far) || !intersect_analytic(data, self, o, d, past, t_far, t, face, leaf)) break;
    }
}

// During occluded(): rejects hits on meshes of no_shadow objects, and for
// shadow_blockers() those on meshes that may let light through (noting
// them), so that only an opaque one ends the query.
void shadow_filter(const RTCFilterFunctionNArguments* args) {
    auto* context = reinterpret_cast<ShadowContext*>(args->context);
    for (unsigned i = 0; i < args->N; ++i) {
        if (!args->valid[i]) continue;
        unsigned top = RTCHitN_instID(args->hit, args->N, i, 0);
        if (top == kInvalidId) top = RTCHitN_geomID(args->hit, args->N, i);
        if (top >= context->geometries->size()) continue;
        const GeometryEntry& entry = (*context->geometries)[top];
        if (entry.group) continue;
        const Instance& instance = context->data->instances[entry.instance];
        if (!instance.casts_shadow) {
            args->valid[i] = 0;
        } else if (context->classify && !instance.blocks_all_light) {
            context->see_through_met = true;
            args->valid[i] = 0;
            if (context->records)
                context->records->add(
                    EmbreeHit{RTCRayN_tnear(args->ray, args->N, i), RTCRayN_tfar(args->ray, args->N, i),
                              RTCHitN_geomID(args->hit, args->N, i), RTCHitN_primID(args->hit, args->N, i),
                              RTCHitN_instID(args->hit, args->N, i, 0), RTCHitN_u(args->hit, args->N, i),
                              RTCHitN_v(args->hit, args->N, i)});
        }
    }
}

}  // namespace lancer::embree
