// Tracing a few shapes without a BVH (see shape_list.h).
#include "geometry/shape_list.h"

#include <algorithm>
#include <cfloat>
#include <stdexcept>
#include <utility>

#include "geometry/embree_scene.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace lancer::embree {
namespace {

// The slab test's far distances are widened by the rounding of their own
// computation (pbrt's 1 + 2 gamma(3)), so no box that the exact ray meets
// is rejected.
constexpr float kWiden = 1.0f + 2.0f * (3.0f * FLT_EPSILON * 0.5f) / (1.0f - 3.0f * FLT_EPSILON * 0.5f);

}  // namespace

ShapeList::Boxes ShapeList::empty_boxes() {
    Boxes boxes;
    for (int axis = 0; axis < 3; ++axis)
        for (int lane = 0; lane < kLanes; ++lane) {
            boxes.lower[axis][lane] = FLT_MAX;
            boxes.upper[axis][lane] = -FLT_MAX;
        }
    return boxes;
}

void ShapeList::add(const Instance& instance, std::uint32_t index, unsigned geometry, unsigned primitive) {
    if (m_shapes.size() >= std::size_t(kLanes)) throw std::logic_error("ShapeList: more shapes than it traces");
    const std::size_t lane = m_shapes.size();
    m_shapes.push_back(Entry{index, geometry, primitive, instance.casts_shadow, instance.blocks_all_light,
                             instance.gathers_crossings});
    for (int axis = 0; axis < 3; ++axis) {
        m_boxes.lower[axis][lane] = instance.bounds_lower[axis];
        m_boxes.upper[axis][lane] = instance.bounds_upper[axis];
    }
}

// The slab test on every lane at once. Each select is written as the
// SIMD min/max whose rule it is (min(a, b) = a < b ? a : b), which the
// compiler does not find in the scalar loop by itself. A direction
// component of zero gives infinite slab distances, or NaN for an origin
// on the slab's plane, which the comparisons then leave out, lane by lane
// as the scalar test did.
unsigned ShapeList::boxes_met(const Ray& ray, float t_near, float t_far, float* entry) const {
    const Vec3 inverse_direction = 1.0f / ray.direction;
    unsigned met = 0;
#if defined(__SSE2__)
    for (int group = 0; group < int(m_shapes.size()); group += 4) {
        __m128 nearest = _mm_set1_ps(t_near), farthest = _mm_set1_ps(t_far);
        for (int axis = 0; axis < 3; ++axis) {
            const __m128 origin = _mm_set1_ps(ray.origin[axis]), inverse = _mm_set1_ps(inverse_direction[axis]);
            const __m128 a = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(&m_boxes.lower[axis][group]), origin), inverse);
            const __m128 b = _mm_mul_ps(_mm_sub_ps(_mm_loadu_ps(&m_boxes.upper[axis][group]), origin), inverse);
            const __m128 in = _mm_min_ps(b, a);                                    // a > b ? b : a
            const __m128 out = _mm_mul_ps(_mm_max_ps(a, b), _mm_set1_ps(kWiden));  // a > b ? a : b
            nearest = _mm_max_ps(in, nearest);                                     // in > nearest ? in : nearest
            farthest = _mm_min_ps(out, farthest);                                  // out < farthest ? out : farthest
        }
        met |= unsigned(_mm_movemask_ps(_mm_cmple_ps(nearest, farthest))) << group;
        _mm_storeu_ps(entry + group, nearest);
    }
#else
    for (int lane = 0; lane < int(m_shapes.size()); ++lane) {
        float nearest = t_near, farthest = t_far;
        for (int axis = 0; axis < 3; ++axis) {
            const float a = (m_boxes.lower[axis][lane] - ray.origin[axis]) * inverse_direction[axis];
            const float b = (m_boxes.upper[axis][lane] - ray.origin[axis]) * inverse_direction[axis];
            const float in = a > b ? b : a;
            const float out = (a > b ? a : b) * kWiden;
            nearest = in > nearest ? in : nearest;
            farthest = out < farthest ? out : farthest;
        }
        met |= unsigned(nearest <= farthest) << lane;
        entry[lane] = nearest;
    }
#endif
    return met & ((1u << m_shapes.size()) - 1u);
}

// The nearest crossing of one listed shape over [t_near, t_far], as
// Embree's user-geometry callbacks compute it.
void ShapeList::to_object(const SceneData& data, const Entry& shape, const Ray& ray, DVec3& o, DVec3& d) {
    const float org[3] = {ray.origin.x, ray.origin.y, ray.origin.z};
    const float dir[3] = {ray.direction.x, ray.direction.y, ray.direction.z};
    ray_to_object(data.instances[shape.instance], org, dir, o, d);
}

bool ShapeList::crosses(const SceneData& data, const Entry& shape, const Ray& ray, float t_near, float t_far, double& t,
                        int& face, std::uint32_t& leaf) {
    DVec3 o, d;
    to_object(data, shape, ray, o, d);
    return intersect_analytic(data, shape.instance, o, d, t_near, t_far, t, face, leaf);
}

void ShapeList::nearest(const SceneData& data, const Ray& ray, EmbreeHit& found) const {
    float entry[kLanes];
    const unsigned met = boxes_met(ray, found.tnear, found.tfar, entry);
    for (std::size_t lane = 0; lane < m_shapes.size(); ++lane) {
        // A box entered beyond the nearest crossing so far is passed over,
        // as the slab test against that nearer end would.
        if (!(met & (1u << lane)) || entry[lane] > found.tfar) continue;
        const Entry& shape = m_shapes[lane];
        double t;
        int face;
        std::uint32_t leaf;
        if (!crosses(data, shape, ray, found.tnear, found.tfar, t, face, leaf)) continue;
        const float t_float = float(t);
        if (!(t_float < found.tfar)) continue;
        found.tfar = t_float;
        found.geometry = shape.geometry;
        found.primitive = shape.primitive;
        found.u = float(face);
        found.v = float(shape.instance - leaf);
    }
}

bool ShapeList::occluded(const SceneData& data, const Ray& ray, float t_near, float t_far) const {
    float entry[kLanes];
    const unsigned met = boxes_met(ray, t_near, t_far, entry);
    for (std::size_t lane = 0; lane < m_shapes.size(); ++lane) {
        const Entry& shape = m_shapes[lane];
        if (!shape.casts_shadow || !(met & (1u << lane))) continue;
        double t;
        int face;
        std::uint32_t leaf;
        if (crosses(data, shape, ray, t_near, t_far, t, face, leaf)) return true;
    }
    return false;
}

ShadowBlockers ShapeList::shadow_blockers(const SceneData& data, const Ray& ray, float t_near, float t_far,
                                          SeeThroughRecords* records) const {
    float entry[kLanes];
    const unsigned met = boxes_met(ray, t_near, t_far, entry);
    bool see_through = false;
    for (std::size_t lane = 0; lane < m_shapes.size(); ++lane) {
        const Entry& shape = m_shapes[lane];
        // Once one surface that may let light through is found, only an
        // opaque one changes the answer, unless each is being recorded.
        const bool recording = records && !records->overflowed;
        if (!shape.casts_shadow || !(met & (1u << lane)) || (see_through && !shape.blocks_all_light && !recording))
            continue;
        double t;
        int face;
        std::uint32_t leaf;
        if (!crosses(data, shape, ray, t_near, t_far, t, face, leaf)) continue;
        if (shape.blocks_all_light) return ShadowBlockers::Opaque;
        see_through = true;
        if (!recording) continue;
        if (!shape.gathers_crossings) {
            records->overflowed = true;  // its later crossings: the walk's to find
            continue;
        }
        // Every crossing on the way, each as nearest() reports it.
        DVec3 o, d;
        to_object(data, shape, ray, o, d);
        record_crossings(data, shape.instance, o, d, t_near, t_far, t, face, leaf,
                         EmbreeHit{0.0f, 0.0f, shape.geometry, shape.primitive, kInvalidId, 0.0f, 0.0f}, *records);
    }
    return see_through ? ShadowBlockers::SeeThrough : ShadowBlockers::None;
}

bool ShapeList::may_meet_hull(const DVec3* points, int point_count, const DVec3* axes, int axis_count,
                              double margin) const {
    DVec3 hull_lower(points[0]), hull_upper(points[0]);
    for (int i = 1; i < point_count; ++i) {
        hull_lower = glm::min(hull_lower, points[i]);
        hull_upper = glm::max(hull_upper, points[i]);
    }
    // The hull's extent along each axis, the same for every shape.
    constexpr int kMostAxes = 8;
    double hull_min[kMostAxes], hull_max[kMostAxes];
    axis_count = std::min(axis_count, kMostAxes);  // fewer axes: still conservative
    for (int a = 0; a < axis_count; ++a) {
        hull_min[a] = hull_max[a] = glm::dot(points[0], axes[a]);
        for (int i = 1; i < point_count; ++i) {
            const double x = glm::dot(points[i], axes[a]);
            hull_min[a] = std::min(hull_min[a], x);
            hull_max[a] = std::max(hull_max[a], x);
        }
    }
    for (std::size_t lane = 0; lane < m_shapes.size(); ++lane) {
        if (!m_shapes[lane].casts_shadow) continue;
        const DVec3 shape_lower(m_boxes.lower[0][lane], m_boxes.lower[1][lane], m_boxes.lower[2][lane]);
        const DVec3 shape_upper(m_boxes.upper[0][lane], m_boxes.upper[1][lane], m_boxes.upper[2][lane]);
        const DVec3 lower = shape_lower - margin, upper = shape_upper + margin;
        // The world axes: the two boxes.
        if (glm::any(glm::lessThan(hull_upper, lower)) || glm::any(glm::lessThan(upper, hull_lower))) continue;
        const DVec3 centre = 0.5 * (lower + upper), half = 0.5 * (upper - lower);
        bool separated = false;
        for (int a = 0; a < axis_count && !separated; ++a) {
            const double box_middle = glm::dot(centre, axes[a]);
            const double box_reach = glm::dot(half, glm::abs(axes[a]));
            separated = hull_max[a] < box_middle - box_reach || box_middle + box_reach < hull_min[a];
        }
        if (!separated) return true;
    }
    return false;
}

}  // namespace lancer::embree
