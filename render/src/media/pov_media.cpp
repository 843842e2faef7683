// POV-Ray 3.7's media sampling along a segment (lancer/shading/pov_media.h).
//
// Facts from POV's media.cpp (read, not copied): a segment is cut into
// `intervals` equal intervals (one when nothing lights it and the medium is
// homogeneous); method 3 takes max(2, samples_min / 2 + 1) sub-intervals in
// each, at fractions j / (count + 1) of the interval (so the last 1 / (count
// + 1) of each interval is never sampled, as in POV), and refines each
// sub-interval by recursive midpoints while two neighbouring samples differ
// by more than aa_threshold (sum over channels), at most aa_level - 1
// times, weighing the samples of a sub-interval 1:1:1 at the last level and
// 2:1 / 1:2 halves above it, as POV does. Each sample is (emission +
// scattering * light) * interval length and extinction * interval length;
// sub-interval results are attenuated by the optical depth before them.
#include "lancer/shading/pov_media.h"

#include <algorithm>
#include <cmath>

#include "lancer/shading/local_shading.h"
#include "lancer/shading/shadow_rays.h"

namespace lancer {

SegmentMedia media_before(const RenderScene& scene, const Ray& ray, const Hit* hit, const InteriorStack& inside) {
    SegmentMedia media;
    const MediumRegion atmosphere = scene.atmosphere();
    if (inside.size > 0) {
        bool all_hollow = true;
        for (int i = inside.size - 1; i >= 0; --i) {
            const InteriorStack::Entry& entry = inside.entries[std::size_t(i)];
            const MaterialParameters& p = entry.material->parameters();
            all_hollow = all_hollow && p.hollow;
            if (!p.medium) continue;
            const MediumRegion region{p.medium, entry.object_id};
            if (!media.interior)
                media.interior = region;
            else if (!media.outer_interior)
                media.outer_interior = region;
        }
        // POV: no media at all in a ray inside a solid object.
        if (!all_hollow) return SegmentMedia{};
        media.open = atmosphere;
        return media;
    }
    if (hit == nullptr || hit->is_front_face(-ray.direction)) {
        media.open = atmosphere;
        return media;
    }
    // The segment ends on a back face: it ran inside that object.
    const MaterialParameters& container = hit->material->parameters();
    if (!container.hollow) return media;  // a solid object: no media, not even the atmosphere
    if (container.medium) media.interior = MediumRegion{container.medium, hit->object_id};
    media.open = atmosphere;
    return media;
}

namespace {

float colour_distance(const Color& a, const Color& b) {
    const Color d = glm::abs(a - b);
    return d.r + d.g + d.b;
}

// One sample's values: what it adds (already times the interval length)
// and its optical depth over the interval.
struct MediaSample {
    Color radiance{0.0f};
    Color depth{0.0f};
};

class SegmentSampler {
  public:
    SegmentSampler(const RenderScene* scene, const MediumRegion& region, const Vec3& origin, const Vec3& direction,
                   Sampler* sampler)
        : m_scene(scene), m_region(region), m_origin(origin), m_direction(direction), m_sampler(sampler) {
        const MediumSampling& s = region.medium->sampling();
        m_jitter = s.jitter;
        m_aa_threshold = s.aa_threshold;
        m_aa_level = s.aa_level;
    }

    // The sample at fraction f of the interval [s0, s0 + ds].
    MediaSample sample(float s0, float ds, float f) const {
        const Vec3 p = m_origin + (s0 + f * ds) * m_direction;
        const MediumPoint c = m_region.medium->at(p, m_region.space);
        MediaSample result;
        result.depth = c.extinction * ds;
        if (m_scene == nullptr) return result;  // a shadow ray: extinction only
        Color added = c.emission;
        if (!is_black(c.scattering)) added += c.scattering * light_at(p);
        result.radiance = added * ds;
        return result;
    }

    // POV's recursive refinement of the sub-interval between fractions f1
    // and f3 whose end samples are a and c: the sub-interval's mean sample.
    MediaSample refine(float s0, float ds, float f1, float f3, const MediaSample& a, const MediaSample& c,
                       int level) const {
        const float f2 = 0.5f * (f1 + f3);
        const MediaSample b = sample(s0, ds, f2 + jitter() * (f3 - f1));
        MediaSample mean;
        if (level <= 0) {
            mean.radiance = (a.radiance + b.radiance + c.radiance) / 3.0f;
            mean.depth = (a.depth + b.depth + c.depth) / 3.0f;
            return mean;
        }
        if (colour_distance(a.radiance, b.radiance) > m_aa_threshold) {
            const MediaSample half = refine(s0, ds, f1, f2, a, b, level - 1);
            mean.radiance = half.radiance / 2.0f;
            mean.depth = half.depth / 2.0f;
        } else {
            mean.radiance = a.radiance / 3.0f + b.radiance / 6.0f;
            mean.depth = a.depth / 3.0f + b.depth / 6.0f;
        }
        if (colour_distance(b.radiance, c.radiance) > m_aa_threshold) {
            const MediaSample half = refine(s0, ds, f2, f3, b, c, level - 1);
            mean.radiance += half.radiance / 2.0f;
            mean.depth += half.depth / 2.0f;
        } else {
            mean.radiance += b.radiance / 6.0f + c.radiance / 3.0f;
            mean.depth += b.depth / 6.0f + c.depth / 3.0f;
        }
        return mean;
    }

    int aa_level() const { return m_aa_level; }
    float jitter() const {
        if (m_jitter == 0.0f || m_sampler == nullptr) return 0.0f;
        return m_jitter * (m_sampler->next_1d() - 0.5f);
    }

  private:
    // POV's light at a medium sample: each light's colour (POV's units)
    // behind its shadow ray, weighted by the media's k towards the ray.
    Color light_at(const Vec3& p) const {
        Hit at;
        at.position = p;
        Color sum(0.0f);
        for (const Light* light : m_scene->lights()) {
            if (!light->lights_media()) continue;
            const Light& stand_in = simple_model_light(*light);
            const LightSample incident = stand_in.sample(p, Vec2(0.5f));
            if (!(incident.pdf > 0.0f) || is_black(incident.radiance)) continue;
            Color colour = incident.radiance * (1.0f / (kPi * incident.pdf));
            if (light->casts_shadows()) colour *= transmittance_to(*m_scene, at, incident.point, light);
            if (is_black(colour)) continue;
            sum += m_region.medium->pov_phase(glm::dot(incident.wi, m_direction)) * colour;
        }
        return sum;
    }

    const RenderScene* m_scene;
    MediumRegion m_region;
    Vec3 m_origin;
    Vec3 m_direction;
    Sampler* m_sampler;
    float m_jitter = 0.0f;
    float m_aa_threshold = 0.1f;
    int m_aa_level = 3;
};

// POV's sum over intervals: the radiance added towards the origin and the
// whole optical depth.
struct SegmentResult {
    Color added{0.0f};
    Color depth{0.0f};
};

SegmentResult sample_segment(const SegmentSampler& sampler, const MediumSampling& settings, bool lit, bool homogeneous,
                             float length) {
    const int intervals = (!lit && homogeneous) ? 1 : std::max(1, settings.intervals);
    const float ds = length / float(intervals);
    const int count = std::max(2, settings.samples_min / 2 + 1);
    const float step = 1.0f / float(count + 1);  // POV's spacing (see the file comment)
    SegmentResult total;
    for (int i = 0; i < intervals; ++i) {
        const float s0 = float(i) * ds;
        Color interval_added(0.0f), interval_depth(0.0f);
        MediaSample previous = sampler.sample(s0, ds, step * sampler.jitter());
        float f = step;
        for (int j = 1; j <= count; ++j, f += step) {
            const MediaSample next = sampler.sample(s0, ds, f + step * sampler.jitter());
            const MediaSample mean = sampler.refine(s0, ds, f - step, f, previous, next, sampler.aa_level() - 1);
            interval_added += mean.radiance * glm::exp(-interval_depth / float(count));
            interval_depth += mean.depth;
            previous = next;
        }
        total.added += interval_added / float(count) * glm::exp(-total.depth);
        total.depth += interval_depth / float(count);
    }
    return total;
}

}  // namespace

Color pov_media_radiance(const RenderScene& scene, const MediumRegion& region, const Vec3& origin,
                         const Vec3& direction, float length, const Color& behind, Sampler& sampler) {
    if (!region || !(length > 0.0f)) return behind;
    const Medium& medium = *region.medium;
    const SegmentSampler segment(&scene, region, origin, direction, &sampler);
    const bool lit = std::any_of(scene.lights().begin(), scene.lights().end(),
                                 [](const Light* light) { return light->lights_media(); });
    const SegmentResult result = sample_segment(segment, medium.sampling(), lit, medium.homogeneous(), length);
    return behind * glm::exp(-result.depth) + result.added;
}

Color pov_media_optical_depth(const MediumRegion& region, const Vec3& origin, const Vec3& direction, float length) {
    if (!region || !(length > 0.0f) || !region.medium->attenuates()) return Color(0.0f);
    const Medium& medium = *region.medium;
    // POV samples constant media on a shadow ray the regular way: exact.
    if (medium.homogeneous()) return medium.constant().extinction * length;
    const SegmentSampler segment(nullptr, region, origin, direction, nullptr);
    return sample_segment(segment, medium.sampling(), false, false, length).depth;
}

}  // namespace lancer
