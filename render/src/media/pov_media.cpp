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
#include <array>
#include <cmath>
#include <vector>

#include "lancer/shading/local_shading.h"
#include "lancer/shading/shadow_rays.h"

namespace lancer {

InteriorMedia interior_media(const InteriorStack& inside) {
    InteriorMedia media;
    for (int i = 0; i < inside.size; ++i) {
        const InteriorStack::Entry& entry = inside.entries[std::size_t(i)];
        const MaterialParameters& p = entry.material->parameters();
        if (!p.hollow) return InteriorMedia{};
        if (p.medium) media.add(MediumRegion{p.medium, entry.object_id});
    }
    return media;
}

SegmentMedia media_along(const RenderScene& scene, const InteriorStack& inside) {
    SegmentMedia media;
    // POV: no media at all in a ray inside a solid object.
    for (int i = 0; i < inside.size; ++i)
        if (!inside.entries[std::size_t(i)].material->parameters().hollow) return SegmentMedia{};
    media.interiors = interior_media(inside);
    media.open = scene.atmosphere();
    media.in_open = true;
    return media;
}

SegmentMedia media_before_judged_by_face(const RenderScene& scene, const Ray& ray, const Hit* hit) {
    if (hit == nullptr || hit->is_front_face(-ray.direction)) return media_along(scene, {});
    // The segment ends on a back face: it ran inside that object.
    SegmentMedia media;
    const MaterialParameters& container = hit->material->parameters();
    if (!container.hollow) return media;  // a solid object: no media, not even the atmosphere
    if (container.medium) media.interiors.add(MediumRegion{container.medium, hit->object_id});
    media.open = scene.atmosphere();
    media.in_open = true;
    return media;
}

namespace {

float colour_distance(const Color& a, const Color& b) {
    const Color d = glm::abs(a - b);
    return d.r + d.g + d.b;
}

// Where along the segment a light can reach: all of it for a point light,
// the part inside a spotlight's falloff cone (POV's
// ComputeSpotLightInterval), none when the cone misses it.
struct LightRange {
    const Light* light = nullptr;
    float s0 = 0.0f;
    float s1 = 0.0f;
};

bool inside_cone(const PointLightParameters& spot, const Vec3& p) {
    const Vec3 v = p - spot.position;
    const float along = glm::dot(v, spot.spot_axis);
    return along > 0.0f && along >= spot.spot_cos_falloff * glm::length(v);
}

// The range of [0, length] inside a spotlight's cone: the cone (narrower
// than a half space) is convex, so the range is one interval, found
// between the roots of the cone's quadratic along the ray.
bool spot_range(const PointLightParameters& spot, const Vec3& origin, const Vec3& direction, float length, float& s0,
                float& s1) {
    const Vec3 w = origin - spot.position;
    const float c2 = spot.spot_cos_falloff * spot.spot_cos_falloff;
    const float da = glm::dot(direction, spot.spot_axis), wa = glm::dot(w, spot.spot_axis);
    const float a = da * da - c2 * glm::dot(direction, direction);
    const float b = 2.0f * (da * wa - c2 * glm::dot(direction, w));
    const float c = wa * wa - c2 * glm::dot(w, w);
    float cuts[4] = {0.0f, length, 0.0f, 0.0f};
    int count = 2;
    const float disc = b * b - 4.0f * a * c;
    if (std::fabs(a) > 1e-12f && disc >= 0.0f) {
        const float root = std::sqrt(disc);
        for (const float t : {(-b - root) / (2.0f * a), (-b + root) / (2.0f * a)})
            if (t > 0.0f && t < length) cuts[count++] = t;
    } else if (std::fabs(a) <= 1e-12f && std::fabs(b) > 1e-12f) {
        const float t = -c / b;
        if (t > 0.0f && t < length) cuts[count++] = t;
    }
    std::sort(cuts, cuts + count);
    bool found = false;
    for (int i = 0; i + 1 < count; ++i) {
        if (!(cuts[i + 1] > cuts[i])) continue;
        if (!inside_cone(spot, origin + (0.5f * (cuts[i] + cuts[i + 1])) * direction)) continue;
        if (!found) s0 = cuts[i];
        s1 = cuts[i + 1];
        found = true;
    }
    return found;
}

// The range of [0, length] a cylinder light's beam lights, as POV-Ray 3.7
// finds it (ComputeCylinderLightInterval), its rules kept because they
// decide where POV places the samples: the stretch between the ray's
// crossings of the infinite cylinder of radius `falloff` about the axis;
// none for a ray parallel to the axis or grazing the cylinder, or when
// both crossings lie behind the light's plane; a first crossing behind the
// plane starts the range at the ray's origin; a second one behind it (a
// ray leaving the beam through the plane) leaves the light out of the
// segment, as in POV-Ray.
bool cylinder_range(const DirectionalLightParameters& beam, const Vec3& origin, const Vec3& direction, float length,
                    float& s0, float& s1) {
    constexpr double kPovEpsilon = 1e-10, kPovSmallTolerance = 1e-3, kPovMaxDistance = 1e7;
    const glm::dvec3 axis = -glm::dvec3(beam.to_light), dir(direction);
    const glm::dvec3 v = glm::dvec3(origin) - glm::dvec3(beam.position);
    const double k1 = glm::dot(dir, axis), k2 = glm::dot(v, axis);
    if (k1 <= 0.0 && k2 < 0.0) return false;
    const double a = 1.0 - k1 * k1;
    if (a == 0.0) return false;
    const double b = glm::dot(v, dir) - k1 * k2;
    const double c = glm::dot(v, v) - k2 * k2 - double(beam.beam_falloff) * double(beam.beam_falloff);
    const double d = b * b - a * c;
    if (!(d > kPovEpsilon)) return false;
    const double root = std::sqrt(d);
    double t1 = (-b - root) / a, t2 = (-b + root) / a;
    if (t1 > t2) std::swap(t1, t2);
    const double l1 = k2 + t1 * k1, l2 = k2 + t2 * k1;
    if (l1 <= 0.0 && l2 <= 0.0) return false;
    if (l1 <= 0.0)
        t1 = 0.0;
    else if (l2 <= 0.0)
        t2 = (kPovMaxDistance - k2) / k1;
    if (!(t1 < double(length) && t2 > kPovSmallTolerance)) return false;
    s0 = float(std::max(t1, 0.0));
    s1 = float(std::min(t2, double(length)));
    return true;
}

// One sample's values: what it adds (already times the interval length)
// and its optical depth over the interval.
struct MediaSample {
    Color radiance{0.0f};
    Color depth{0.0f};
};

// POV's settings for media sampled together (MediaFunction::ComputeMedia):
// the first medium's with the most intervals, the smallest aa_threshold.
MediumSampling combined_sampling(const MediumRegion* regions, int count) {
    MediumSampling settings = regions[0].medium->sampling();
    for (int i = 1; i < count; ++i) {
        const MediumSampling& s = regions[i].medium->sampling();
        const float aa_threshold = std::min(settings.aa_threshold, s.aa_threshold);
        if (s.intervals > settings.intervals) settings = s;
        settings.aa_threshold = aa_threshold;
    }
    return settings;
}

class SegmentSampler {
  public:
    SegmentSampler(const RenderScene* scene, const MediumRegion* regions, int count, const MediumSampling& settings,
                   const Vec3& origin, const Vec3& direction, const MediaLighting& lighting,
                   std::vector<LightRange> lights = {}, const InteriorStack* inside = nullptr)
        : m_scene(scene),
          m_inside(inside),
          m_regions(regions),
          m_count(std::min(count, InteriorStack::kDepth)),
          m_origin(origin),
          m_direction(direction),
          m_sampler(lighting.jitter),
          m_shadows(lighting.shadows),
          m_lights(std::move(lights)) {
        m_jitter = settings.jitter;
        m_aa_threshold = settings.aa_threshold;
        m_aa_level = settings.aa_level;
    }

    // Whether the interval being sampled is lit (POV skips lights elsewhere).
    void set_lit(bool lit) { m_lit = lit; }

    // The sample at fraction f of the interval [s0, s0 + ds].
    MediaSample sample(float s0, float ds, float f) const {
        const float s = s0 + f * ds;
        const Vec3 p = m_origin + s * m_direction;
        // Every medium's coefficients at the point, summed (each scatters
        // with its own phase function).
        std::array<Color, InteriorStack::kDepth> scattering;
        bool scatters = false;
        Color extinction(0.0f), emission(0.0f);
        for (int i = 0; i < m_count; ++i) {
            const MediumPoint c = m_regions[i].medium->at(p, m_regions[i].space);
            extinction += c.extinction;
            emission += c.emission;
            scattering[std::size_t(i)] = c.scattering;
            scatters = scatters || !is_black(c.scattering);
        }
        MediaSample result;
        result.depth = extinction * ds;
        if (m_scene == nullptr) return result;  // a shadow ray: extinction only
        Color added = emission;
        if (scatters && m_lit) added += light_at(p, s, scattering);
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
    Color light_at(const Vec3& p, float s, const std::array<Color, InteriorStack::kDepth>& scattering) const {
        Hit at;
        at.position = p;
        Color sum(0.0f);
        for (const LightRange& range : m_lights) {
            if (s < range.s0 || s > range.s1) continue;
            const Light* light = range.light;
            const Light& stand_in = simple_model_light(*light);
            const LightSample incident = stand_in.sample(p, Vec2(0.5f));
            if (!(incident.pdf > 0.0f) || is_black(incident.radiance)) continue;
            Color colour = incident.radiance * (1.0f / (kPi * incident.pdf));
            if (m_shadows && light->casts_shadows())
                colour *= transmittance_to(*m_scene, at, incident.point, light, m_inside);
            if (is_black(colour)) continue;
            const float cos_theta = glm::dot(incident.wi, m_direction);
            for (int i = 0; i < m_count; ++i)
                if (!is_black(scattering[std::size_t(i)]))
                    sum += scattering[std::size_t(i)] * m_regions[i].medium->pov_phase(cos_theta) * colour;
        }
        return sum;
    }

    const RenderScene* m_scene;
    const InteriorStack* m_inside;
    const MediumRegion* m_regions;
    int m_count;
    Vec3 m_origin;
    Vec3 m_direction;
    Sampler* m_sampler;
    bool m_shadows;
    std::vector<LightRange> m_lights;
    bool m_lit = false;
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

// A stretch of the segment, lit by some light or by none.
struct LitInterval {
    float s0, s1;
    bool lit;
};

// POV's lit intervals (ComputeMediaLightInterval): the lights' ranges,
// their starts and ends sorted apart, merged where they overlap, with the
// unlit gaps between.
std::vector<LitInterval> lit_intervals(const std::vector<LightRange>& lights, float length) {
    if (lights.empty()) return {LitInterval{0.0f, length, false}};
    std::vector<float> starts, ends;
    for (const LightRange& r : lights) {
        starts.push_back(r.s0);
        ends.push_back(r.s1);
    }
    std::sort(starts.begin(), starts.end());
    std::sort(ends.begin(), ends.end());
    std::vector<LitInterval> list;
    if (starts[0] > 0.0f) list.push_back({0.0f, starts[0], false});
    list.push_back({starts[0], ends[0], true});
    for (std::size_t i = 1; i < lights.size(); ++i) {
        if (starts[i] > list.back().s1) {
            list.push_back({list.back().s1, starts[i], false});
            list.push_back({starts[i], ends[i], true});
        } else if (ends[i] > list.back().s1) {
            list.back().s1 = ends[i];
        }
    }
    if (list.back().s1 < length) list.push_back({list.back().s1, length, false});
    return list;
}

// POV's sampling intervals (ComputeMediaSampleInterval): one when nothing
// lights a homogeneous medium; else `intervals` spread evenly over one
// lit interval, or shared among several by `ratio` (lit ones ratio, unlit
// ones 1 - ratio), each at least one.
std::vector<LitInterval> sampling_intervals(const std::vector<LitInterval>& lit, const MediumSampling& settings,
                                            bool homogeneous) {
    std::vector<LitInterval> out;
    const std::size_t intervals = std::max<std::size_t>(std::size_t(std::max(1, settings.intervals)), lit.size());
    if (lit.size() == 1) {
        const std::size_t n = (!lit[0].lit && homogeneous) ? 1 : intervals;
        const float delta = (lit[0].s1 - lit[0].s0) / float(n);
        for (std::size_t i = 0; i < n; ++i)
            out.push_back({lit[0].s0 + delta * float(i), lit[0].s0 + delta * float(i + 1), lit[0].lit});
        return out;
    }
    double sum = 0.0;
    for (const LitInterval& l : lit) sum += l.lit ? settings.ratio : 1.0 - settings.ratio;
    std::size_t remaining = intervals;
    for (std::size_t i = 0; i < lit.size(); ++i) {
        const double weight = lit[i].lit ? settings.ratio : 1.0 - settings.ratio;
        std::size_t n = std::size_t(weight / sum * double(intervals)) + 1;
        const std::size_t most = remaining - lit.size() + i + 1;
        if (n > most) n = most;
        const float delta = (lit[i].s1 - lit[i].s0) / float(n);
        for (std::size_t j = 0; j < n; ++j)
            out.push_back({lit[i].s0 + delta * float(j), lit[i].s0 + delta * float(j + 1), lit[i].lit});
        remaining -= n;
    }
    return out;
}

SegmentResult sample_segment(SegmentSampler& sampler, const MediumSampling& settings,
                             const std::vector<LightRange>& lights, bool homogeneous, float length) {
    const std::vector<LitInterval> intervals = sampling_intervals(lit_intervals(lights, length), settings, homogeneous);
    const int count = std::max(2, settings.samples_min / 2 + 1);
    const float step = 1.0f / float(count + 1);  // POV's spacing (see the file comment)
    SegmentResult total;
    for (const LitInterval& interval : intervals) {
        const float s0 = interval.s0;
        const float ds = interval.s1 - interval.s0;
        if (!(ds > 0.0f)) continue;
        sampler.set_lit(interval.lit);
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

Color pov_media_radiance(const RenderScene& scene, const MediumRegion* regions, int count, const Vec3& origin,
                         const Vec3& direction, float length, const Color& behind, const MediaLighting& lighting,
                         const InteriorStack* inside) {
    if (count <= 0 || !(length > 0.0f)) return behind;
    // Where each light that lights media reaches along the segment.
    std::vector<LightRange> lights;
    for (const Light* light : scene.lights()) {
        // A light_group's lights are not the scene's in POV-Ray: they light
        // their group's objects and no medium. Nor does a shadowless light
        // (POV's fill light, which ComputeOneMediaLightInterval skips).
        if (!light->lights_media() || light->light_group() >= 0 || !light->casts_shadows()) continue;
        LightRange range{light, 0.0f, length};
        const Light& stand_in = simple_model_light(*light);
        const PointLightParameters* point = stand_in.parameters<PointLightParameters>();
        if (point && point->spot_axis != Vec3(0.0f) &&
            !spot_range(*point, origin, direction, length, range.s0, range.s1))
            continue;
        const DirectionalLightParameters* beam = stand_in.parameters<DirectionalLightParameters>();
        if (beam && beam->beam_falloff > 0.0f && !cylinder_range(*beam, origin, direction, length, range.s0, range.s1))
            continue;
        lights.push_back(range);
    }
    const MediumSampling settings = combined_sampling(regions, count);
    bool homogeneous = true;
    for (int i = 0; i < count; ++i) homogeneous = homogeneous && regions[i].medium->homogeneous();
    SegmentSampler segment(&scene, regions, count, settings, origin, direction, lighting, lights, inside);
    const SegmentResult result = sample_segment(segment, settings, lights, homogeneous, length);
    return behind * glm::exp(-result.depth) + result.added;
}

Color pov_media_optical_depth(const MediumRegion* regions, int count, const Vec3& origin, const Vec3& direction,
                              float length) {
    if (count <= 0 || !(length > 0.0f)) return Color(0.0f);
    bool attenuates = false, homogeneous = true;
    Color constant(0.0f);
    for (int i = 0; i < count; ++i) {
        const Medium& medium = *regions[i].medium;
        attenuates = attenuates || medium.attenuates();
        homogeneous = homogeneous && medium.homogeneous();
        if (medium.homogeneous()) constant += medium.constant().extinction;
    }
    if (!attenuates) return Color(0.0f);
    // POV samples constant media on a shadow ray the regular way: exact.
    if (homogeneous) return constant * length;
    const MediumSampling settings = combined_sampling(regions, count);
    SegmentSampler segment(nullptr, regions, count, settings, origin, direction, MediaLighting{});
    return sample_segment(segment, settings, {}, false, length).depth;
}

}  // namespace lancer
