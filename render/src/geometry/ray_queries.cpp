// Ray queries on the Embree scene: one ray (intersect, occluded), and
// batches of coherent camera rays traced in packets through a pipeline that
// hides the memory latency of completing their hits.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "geometry/embree_scene.h"
#include "geometry/float_steps.h"
#include "lancer/shading/material_blend.h"

namespace lancer::embree {
namespace {

// Embree traces a ray only when its origin and direction are within its
// range and its t range is not NaN. Such a ray (a camera or a hit that far
// off) misses everything in the BVH; the shapes tested outside it, in double
// precision, may still hit it.
bool embree_can_trace(const Ray& ray) {
    return within_embree_range(ray.origin) && within_embree_range(ray.direction) && !std::isnan(ray.t_min) &&
           !std::isnan(ray.t_max);
}

// Embree's answer for a ray that meets nothing: its own range, no ids.
EmbreeHit no_hit(const Ray& ray) {
    const float t_near = glm::max(ray.t_min, 0.0f);
    return EmbreeHit{t_near, glm::max(ray.t_max, t_near), kInvalidId, kInvalidId, kInvalidId, 0.0f, 0.0f};
}

void fill_embree_ray(const Ray& ray, RTCRay& out) {
    out.org_x = ray.origin.x;
    out.org_y = ray.origin.y;
    out.org_z = ray.origin.z;
    out.dir_x = ray.direction.x;
    out.dir_y = ray.direction.y;
    out.dir_z = ray.direction.z;
    const EmbreeHit range = no_hit(ray);
    out.tnear = range.tnear;
    out.tfar = range.tfar;
    out.time = 0.0f;
    out.mask = 0xffffffffu;
    out.id = 0;
    out.flags = 0;
}

// A texture_map's entries at the hit (materials/material_entries.h; a
// light's surface keeps the one material its light was made from), then
// POV's normal { }: every integrator sees the bent normal.
inline void finish_surface(Hit& hit, const Vec3& ray_direction, const SceneData& data) {
    if (data.has_material_entries && hit.emitter == nullptr)
        if (const MaterialMix* entries = hit.material ? hit.material->entries() : nullptr) {
            MaterialMix::Part parts[MaterialMix::kMostParts];
            const int count = entries->parts(hit, parts);
            hit.material = parts[0].material;
            hit.mix = count > 1 ? entries : nullptr;
        }
    if (!data.has_normal_perturbation) return;
    hit.unbumped_normal = hit.shading_normal;
    hit.shading_normal = bent_normal(hit, hit.material, hit.shading_normal, ray_direction);
}

}  // namespace

bool EmbreeScene::intersect(const Ray& ray, Hit& hit) const {
    if (!nearest_hit(ray, hit)) return false;
    if (m_data->has_hidden_objects && hidden_from(ray, hit)) return nearest_visible_hit(ray, hit);
    return true;
}

bool EmbreeScene::hidden_from(const Ray& ray, const Hit& hit) const {
    if (ray.seen_as == RaySight::Other) return false;
    // A part of a group is hidden with the whole (the builder passes the
    // group's no_image and no_reflection down to its parts), or alone.
    const Instance& part = m_data->instances[hit.object_id];
    return ray.seen_as == RaySight::Image ? part.no_image : part.no_reflection;
}

bool EmbreeScene::nearest_visible_hit(const Ray& ray, Hit& hit) const {
    // Past each hidden surface in turn; the bound guards against stacks of
    // coplanar hidden faces.
    constexpr int kMostHiddenSurfaces = 64;
    Ray rest = ray;
    for (int passed = 0; passed < kMostHiddenSurfaces; ++passed) {
        rest.t_min = next_float_up(std::max(hit.t, rest.t_min));
        if (!(rest.t_min < rest.t_max) || !nearest_hit(rest, hit)) return false;
        if (!hidden_from(ray, hit)) return true;
    }
    return false;
}

bool EmbreeScene::nearest_hit(const Ray& ray, Hit& hit) const {
    // An untraceable ray meets only the shapes outside the BVH (complete_hit).
    EmbreeHit found = no_hit(ray);
    if (embree_can_trace(ray) && m_traces_list) {
        m_few_shapes.nearest(*m_data, ray, found);
    } else if (embree_can_trace(ray)) {
        RTCIntersectContext context;
        rtcInitIntersectContext(&context);
        RTCRayHit rayhit;
        fill_embree_ray(ray, rayhit.ray);
        rayhit.hit.geomID = kInvalidId;
        rayhit.hit.primID = kInvalidId;
        rayhit.hit.instID[0] = kInvalidId;
        rayhit.hit.u = rayhit.hit.v = 0.0f;
        rtcIntersect1(m_scene, &context, &rayhit);
        found = EmbreeHit{rayhit.ray.tnear,     rayhit.ray.tfar, rayhit.hit.geomID, rayhit.hit.primID,
                          rayhit.hit.instID[0], rayhit.hit.u,    rayhit.hit.v};
    }
    if (!complete_hit(ray, found, hit)) return false;
    hit.ray_direction = ray.direction;
    finish_surface(hit, ray.direction, *m_data);
    return true;
}

void EmbreeScene::trace_packet(const Ray* rays, int lanes, PacketAnswers& answers) const {
    if (m_traces_list) {
        for (int k = 0; k < lanes; ++k) {
            EmbreeHit found = no_hit(rays[k]);
            if (embree_can_trace(rays[k])) m_few_shapes.nearest(*m_data, rays[k], found);
            answers.tnear[k] = found.tnear;
            answers.tfar[k] = found.tfar;
            answers.geometry[k] = found.geometry;
            answers.primitive[k] = found.primitive;
            answers.instance[k] = found.instance;
            answers.u[k] = found.u;
            answers.v[k] = found.v;
        }
        return;
    }
    RTCIntersectContext context;
    rtcInitIntersectContext(&context);
    context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
    alignas(64) int valid[kPacketLanes];
    alignas(64) RTCRayHit16 packet;
    bool untraceable[kPacketLanes] = {};
    for (int k = 0; k < kPacketLanes; ++k) {
        // Idle lanes repeat a live ray so every lane holds finite data; an
        // untraceable lane, which Embree skips, holds a harmless one.
        static const Ray kHarmless;
        const Ray& source = rays[std::min(k, lanes - 1)];
        const bool traceable = embree_can_trace(source);
        untraceable[k] = k < lanes && !traceable;
        valid[k] = k < lanes && traceable ? -1 : 0;
        const Ray& ray = traceable ? source : kHarmless;
        packet.ray.org_x[k] = ray.origin.x;
        packet.ray.org_y[k] = ray.origin.y;
        packet.ray.org_z[k] = ray.origin.z;
        packet.ray.dir_x[k] = ray.direction.x;
        packet.ray.dir_y[k] = ray.direction.y;
        packet.ray.dir_z[k] = ray.direction.z;
        packet.ray.tnear[k] = glm::max(ray.t_min, 0.0f);  // as fill_embree_ray
        packet.ray.tfar[k] = glm::max(ray.t_max, packet.ray.tnear[k]);
        packet.ray.time[k] = 0.0f;
        packet.ray.mask[k] = 0xffffffffu;
        packet.ray.id[k] = 0;
        packet.ray.flags[k] = 0;
        packet.hit.geomID[k] = kInvalidId;
        packet.hit.primID[k] = kInvalidId;
        packet.hit.instID[0][k] = kInvalidId;
        packet.hit.u[k] = packet.hit.v[k] = 0.0f;
    }
    rtcIntersect16(valid, m_scene, &context, &packet);
    for (int k = 0; k < kPacketLanes; ++k) {
        // A miss over the ray's own range, as intersect() gives.
        if (untraceable[k]) {
            packet.ray.tnear[k] = glm::max(rays[k].t_min, 0.0f);
            packet.ray.tfar[k] = glm::max(rays[k].t_max, packet.ray.tnear[k]);
        }
        answers.tnear[k] = packet.ray.tnear[k];
        answers.tfar[k] = packet.ray.tfar[k];
        answers.geometry[k] = packet.hit.geomID[k];
        answers.primitive[k] = packet.hit.primID[k];
        answers.instance[k] = packet.hit.instID[0][k];
        answers.u[k] = packet.hit.u[k];
        answers.v[k] = packet.hit.v[k];
    }
}

void EmbreeScene::prefetch_corner_indices(const PacketAnswers& answers, int lanes) const {
    for (int k = 0; k < lanes; ++k) {
        if (const PlainTriangles* mesh = plain_triangles_of(answers.geometry[k], answers.instance[k]))
            __builtin_prefetch(&mesh->indices[3 * std::size_t(answers.primitive[k])]);
        else if (const Instance* instance = mesh_instance_of(answers.lane(k)))
            __builtin_prefetch(&instance->mesh->indices[3 * std::size_t(answers.primitive[k])]);
    }
}

void EmbreeScene::prefetch_corners(const PacketAnswers& answers, int lanes) const {
    for (int k = 0; k < lanes; ++k) {
        const float* positions;
        const std::uint32_t* corner;
        if (const PlainTriangles* mesh = plain_triangles_of(answers.geometry[k], answers.instance[k])) {
            positions = mesh->positions;
            corner = &mesh->indices[3 * std::size_t(answers.primitive[k])];
        } else if (const Instance* instance = mesh_instance_of(answers.lane(k))) {
            positions = traced_positions(*instance).data();
            corner = &instance->mesh->indices[3 * std::size_t(answers.primitive[k])];
        } else {
            continue;
        }
        for (int c = 0; c < 3; ++c) __builtin_prefetch(&positions[3 * std::size_t(corner[c])]);
    }
}

void EmbreeScene::intersect_batch(const Ray* rays, int count, Hit* hits, bool* found, RayCoherence coherence) const {
    // Incoherent rays share too few BVH nodes for packets to pay.
    if (coherence == RayCoherence::Incoherent) {
        for (int i = 0; i < count; ++i) found[i] = intersect(rays[i], hits[i]);
        return;
    }
    // A mesh hit needs its triangle's corner indices, then the corners: two
    // dependent loads, cold in cache (Embree traverses its own copy of the
    // vertices), which would stall completion for most of a memory latency
    // each. So the packets go through a pipeline: after packet i is traced,
    // its indices are requested, packet i-1's corners (indices now cached)
    // are requested, and packet i-2 is completed; each packet's tracing
    // hides the next stage's misses.
    constexpr int kDepth = 3;
    PacketAnswers answers[kDepth];
    const int packets = (count + kPacketLanes - 1) / kPacketLanes;
    auto lanes_of = [&](int packet) { return std::min(kPacketLanes, count - packet * kPacketLanes); };
    for (int step = 0; step < packets + 2; ++step) {
        if (step < packets) {
            PacketAnswers& traced = answers[step % kDepth];
            trace_packet(rays + step * kPacketLanes, lanes_of(step), traced);
            if (m_has_meshes) prefetch_corner_indices(traced, lanes_of(step));
        }
        if (const int previous = step - 1; m_has_meshes && previous >= 0 && previous < packets)
            prefetch_corners(answers[previous % kDepth], lanes_of(previous));
        if (const int ready = step - 2; ready >= 0)
            complete_packet(rays + ready * kPacketLanes, answers[ready % kDepth], lanes_of(ready),
                            hits + ready * kPacketLanes, found + ready * kPacketLanes);
    }
    if (m_data->has_normal_perturbation || m_data->has_material_entries)
        for (int i = 0; i < count; ++i)
            if (found[i]) finish_surface(hits[i], rays[i].direction, *m_data);
    if (m_data->has_hidden_objects)
        for (int i = 0; i < count; ++i)
            if (found[i] && hidden_from(rays[i], hits[i])) found[i] = nearest_visible_hit(rays[i], hits[i]);
}

// rtcOccluded1 on the BVH: whether a shadow caster ends the query. With
// `classify`, the casters that may let light through do not end it; they
// set *see_through instead.
bool EmbreeScene::bvh_occluded(RTCRay& shadow_ray, bool classify, bool* see_through, SeeThroughRecords* records) const {
    ShadowContext context;
    rtcInitIntersectContext(&context.base);
    context.geometries = &m_geometries;
    context.data = m_data.get();
    context.classify = classify;
    context.records = records;
    if (m_has_no_shadow_mesh || (classify && m_has_see_through_mesh)) context.base.filter = shadow_filter;
    rtcOccluded1(m_scene, &context.base, &shadow_ray);
    if (see_through) *see_through = context.see_through_met;
    return shadow_ray.tfar == -INFINITY;
}

bool EmbreeScene::occluded(const Ray& ray) const {
    RTCRay shadow_ray;
    fill_embree_ray(ray, shadow_ray);
    if (embree_can_trace(ray)) {
        if (m_traces_list ? m_few_shapes.occluded(*m_data, ray, shadow_ray.tnear, shadow_ray.tfar)
                          : bvh_occluded(shadow_ray, false, nullptr))
            return true;
    }
    return m_unbounded.occluded(*m_data, ray, glm::max(ray.t_min, 0.0f), ray.t_max);
}

ShadowBlockers EmbreeScene::shadow_blockers(const Ray& ray) const {
    if (!m_has_see_through_caster) return occluded(ray) ? ShadowBlockers::Opaque : ShadowBlockers::None;
    bool see_through = false;
    RTCRay shadow_ray;
    fill_embree_ray(ray, shadow_ray);
    if (embree_can_trace(ray)) {
        if (m_traces_list) {
            const ShadowBlockers listed = m_few_shapes.shadow_blockers(*m_data, ray, shadow_ray.tnear, shadow_ray.tfar);
            if (listed == ShadowBlockers::Opaque) return listed;
            see_through = listed == ShadowBlockers::SeeThrough;
        } else if (bvh_occluded(shadow_ray, true, &see_through)) {
            return ShadowBlockers::Opaque;
        }
    }
    const ShadowBlockers unbounded = m_unbounded.shadow_blockers(*m_data, ray, glm::max(ray.t_min, 0.0f), ray.t_max);
    if (unbounded != ShadowBlockers::None) return unbounded;
    return see_through ? ShadowBlockers::SeeThrough : ShadowBlockers::None;
}

ShadowBlockers EmbreeScene::shadow_crossings(const Ray& ray, SeeThroughHits& crossed) const {
    crossed.count = -1;
    if (!m_has_see_through_caster || !embree_can_trace(ray)) return shadow_blockers(ray);
    // The shapes outside the BVH first: the gathered surfaces must be all
    // there are. One that may let light through leaves the walk to do.
    const ShadowBlockers unbounded = m_unbounded.shadow_blockers(*m_data, ray, glm::max(ray.t_min, 0.0f), ray.t_max);
    if (unbounded == ShadowBlockers::Opaque) return unbounded;
    if (unbounded == ShadowBlockers::SeeThrough) return shadow_blockers(ray);
    RTCRay shadow_ray;
    fill_embree_ray(ray, shadow_ray);
    SeeThroughRecords records;
    bool see_through = false;
    if (m_traces_list) {
        const ShadowBlockers listed =
            m_few_shapes.shadow_blockers(*m_data, ray, shadow_ray.tnear, shadow_ray.tfar, &records);
        if (listed == ShadowBlockers::Opaque) return listed;
        see_through = listed == ShadowBlockers::SeeThrough;
    } else if (bvh_occluded(shadow_ray, true, &see_through, &records)) {
        return ShadowBlockers::Opaque;
    }
    if (!see_through) return ShadowBlockers::None;
    if (records.overflowed) return ShadowBlockers::SeeThrough;
    EmbreeHit* begin = records.found;
    EmbreeHit* end = begin + records.count;
    std::sort(begin, end, [](const EmbreeHit& a, const EmbreeHit& b) { return a.tfar < b.tfar; });
    // A triangle Embree reported twice (split between two BVH leaves).
    end = std::unique(begin, end, [](const EmbreeHit& a, const EmbreeHit& b) {
        return a.tfar == b.tfar && a.geometry == b.geometry && a.primitive == b.primitive && a.instance == b.instance;
    });
    const int count = int(end - begin);
    if (count > SeeThroughHits::kMost) return ShadowBlockers::SeeThrough;
    // Surfaces nearly at one place are left to the walk, which steps past
    // each hit by its rounding error, so that both give the same answer.
    const float length = glm::length(ray.direction);
    for (int k = 1; k < count; ++k) {
        const float gap = (begin[k].tfar - begin[k - 1].tfar) * length;
        const float reach = glm::length(ray.origin + begin[k].tfar * ray.direction);
        if (!(gap > 1e-4f * (1.0f + reach))) return ShadowBlockers::SeeThrough;
    }
    for (int k = 0; k < count; ++k) {
        Hit& hit = crossed.make(k);
        // The shapes outside the BVH let the ray through (above): none of
        // them, not even one that casts no shadow, stands for this surface.
        if (!complete_hit(ray, begin[k], hit, false)) return ShadowBlockers::SeeThrough;
        hit.ray_direction = ray.direction;
        finish_surface(hit, ray.direction, *m_data);
    }
    crossed.count = count;
    return ShadowBlockers::SeeThrough;
}

bool EmbreeScene::may_block_towards(const Vec3& origin, const Vec3& corner, const Vec3& edge1,
                                    const Vec3& edge2) const {
    if (!m_traces_list) return true;
    const DVec3 apex(origin), base(corner);
    const DVec3 points[5] = {apex, base, base + DVec3(edge1), base + DVec3(edge1) + DVec3(edge2), base + DVec3(edge2)};
    double reach = 0.0, largest = 0.0;  // the longest segment, the largest coordinate
    for (const DVec3& p : points) {
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) return true;
        reach = std::max(reach, glm::length(p - apex));
        largest = std::max({largest, std::fabs(p.x), std::fabs(p.y), std::fabs(p.z)});
    }
    // The shadow rays run between floats near these points, along rounded
    // directions: a thousand times their error keeps the answer safe.
    const double margin = 1e-4 * reach + 1e-6 * largest;
    for (std::size_t k = 0; k < m_unbounded.size(); ++k) {
        const Instance& instance = m_data->instances[m_unbounded.instance(k)];
        if (!instance.casts_shadow) continue;
        if (instance.kind != ShapeKind::Plane) return true;
        // A plane is crossed by no such segment when the apex and the whole
        // parallelogram lie on one side of it.
        double side[5];
        for (int i = 0; i < 5; ++i)
            side[i] = glm::dot(instance.plane.normal, instance.placement.point_to_object(points[i])) -
                      instance.plane.distance;
        // The world margin in the plane's space: at most the margin times
        // the transform's Frobenius norm.
        const DVec3 x = instance.placement.vector_to_object(DVec3(1.0, 0.0, 0.0));
        const DVec3 y = instance.placement.vector_to_object(DVec3(0.0, 1.0, 0.0));
        const DVec3 z = instance.placement.vector_to_object(DVec3(0.0, 0.0, 1.0));
        const double corner_margin = margin * std::sqrt(glm::dot(x, x) + glm::dot(y, y) + glm::dot(z, z));
        // The apex may lie on the plane (a hit on the plane itself): its
        // rays cross it at t = 0, which the plane's own test rejects (the
        // apex is a ray origin, already offset off the surface).
        const double sign = side[1] > 0.0 ? 1.0 : -1.0;
        if (sign * side[0] < 0.0) return true;
        for (int i = 1; i < 5; ++i)
            if (!(sign * side[i] > corner_margin)) return true;
    }
    const DVec3 e1(edge1), e2(edge2);
    const DVec3 faces[5] = {glm::cross(e1, e2), glm::cross(points[1] - apex, points[2] - apex),
                            glm::cross(points[2] - apex, points[3] - apex),
                            glm::cross(points[3] - apex, points[4] - apex),
                            glm::cross(points[4] - apex, points[1] - apex)};
    return m_few_shapes.may_meet_hull(points, 5, faces, 5, margin);
}

}  // namespace lancer::embree
