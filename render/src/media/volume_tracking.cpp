// Null-collision tracking of media for `path` (lancer/shading/volume_tracking.h).
//
// With a majorant m >= extinction everywhere on the segment (the sum of the
// regions' bounds), the radiance arriving at the origin is
//   L = int_0^d m e^{-m s} [ (emission + scattering * Ls + (m - extinction) * L(s)) / m ] ds + e^{-m d} L(d)
// (Galtier et al. 2013; Novák et al. 2014). Distances are drawn from
// m e^{-m s}; at each tentative collision the emission is scored, then the
// path either scatters or goes on (a null collision), each chosen with a
// probability proportional to its weight's mean over the channels and
// weighted by weight / probability; absorption is what neither keeps. In a
// grey homogeneous medium m equals the extinction: no null collisions, the
// free flight is sampled exactly and scattering weighs the albedo. The
// emission of a homogeneous medium is integrated in closed form instead.
#include "lancer/shading/volume_tracking.h"

#include <algorithm>
#include <array>
#include <cmath>

#include "lancer/shading/material_blend.h"

namespace lancer {

namespace {

float mean(const Color& c) {
    return (c.r + c.g + c.b) / 3.0f;
}

// The regions of a segment as a small list.
struct Regions {
    std::array<MediumRegion, InteriorStack::kDepth + 1> list;
    int count = 0;
    explicit Regions(const SegmentMedia& media) {
        for (int i = 0; i < media.interiors.count; ++i)
            list[std::size_t(count++)] = media.interiors.regions[std::size_t(i)];
        if (media.open) list[std::size_t(count++)] = media.open;
    }
    bool homogeneous() const {
        for (int i = 0; i < count; ++i)
            if (!list[std::size_t(i)].medium->homogeneous()) return false;
        return true;
    }
    float majorant() const {
        float sum = 0.0f;
        for (int i = 0; i < count; ++i) sum += max_component(list[std::size_t(i)].medium->extinction_bound());
        return sum;
    }
    bool emits() const {
        for (int i = 0; i < count; ++i)
            if (list[std::size_t(i)].medium->emits()) return true;
        return false;
    }
};

// exp(-sigma d) and its integral over [0, d], per channel (sigma may be 0).
Color integrated_transmittance(const Color& sigma, float d) {
    Color out;
    for (int k = 0; k < 3; ++k) {
        const float x = sigma[k] * d;
        out[k] = x < 1e-4f ? d * (1.0f - 0.5f * x) : -std::expm1(-x) / sigma[k];
    }
    return out;
}

}  // namespace

MediumInteraction track_segment(const SegmentMedia& media, const Vec3& origin, const Vec3& direction, float length,
                                Sampler& sampler) {
    MediumInteraction result;
    const Regions regions(media);
    if (regions.count == 0 || !(length > 0.0f)) return result;
    const bool homogeneous = regions.homogeneous();
    // A homogeneous medium's emission, in closed form.
    Color total_extinction(0.0f);
    if (homogeneous) {
        Color emission(0.0f);
        for (int i = 0; i < regions.count; ++i) {
            emission += regions.list[std::size_t(i)].medium->constant().emission;
            total_extinction += regions.list[std::size_t(i)].medium->constant().extinction;
        }
        if (!is_black(emission)) result.emitted = emission * integrated_transmittance(total_extinction, length);
    }
    float majorant = regions.majorant();
    // An emitting medium that does not attenuate still needs collisions to
    // score its varying emission: a few per segment.
    if (!homogeneous && regions.emits()) majorant = std::max(majorant, 4.0f / std::min(length, 1e6f));
    if (!(majorant > 0.0f)) return result;  // nothing to meet: the ray crosses unchanged

    float s = 0.0f;
    for (;;) {
        s -= std::log1p(-std::min(sampler.next_1d(), 0.99999994f)) / majorant;
        if (s >= length) return result;  // reached the surface (or escaped) with `weight`
        const Vec3 p = origin + s * direction;
        MediumPoint sum;
        std::array<Color, 3> scattering{};
        for (int i = 0; i < regions.count; ++i) {
            const MediumRegion& r = regions.list[std::size_t(i)];
            const MediumPoint c = r.medium->at(p, r.space);
            sum.emission += c.emission;
            sum.extinction += c.extinction;
            sum.scattering += c.scattering;
            scattering[std::size_t(i)] = c.scattering;
        }
        if (!homogeneous) result.emitted += result.weight * sum.emission / majorant;
        const Color null_share = glm::max(Color(majorant) - sum.extinction, Color(0.0f));
        const float p_scatter_raw = std::max(0.0f, mean(sum.scattering));
        const float p_null_raw = mean(null_share);
        const float total = p_scatter_raw + p_null_raw;
        if (!(total > 0.0f)) {  // pure absorption at the majorant: the path ends
            result.weight = Color(0.0f);
            return result;
        }
        const float u = sampler.next_1d();
        if (u * total < p_scatter_raw) {
            result.scattered = true;
            result.point = p;
            result.weight *= sum.scattering / (majorant * (p_scatter_raw / total));
            // The medium whose phase scatters: by share of the scattering.
            result.medium = regions.list[0].medium;
            if (regions.count > 1) {
                float pick = sampler.next_1d() * p_scatter_raw * 3.0f;
                for (int i = 0; i < regions.count; ++i) {
                    result.medium = regions.list[std::size_t(i)].medium;
                    pick -= mean(scattering[std::size_t(i)]) * 3.0f;
                    if (pick < 0.0f) break;
                }
            }
            return result;
        }
        result.weight *= null_share / (majorant * (p_null_raw / total));
        if (is_black(result.weight)) return result;
    }
}

Color segment_transmittance(const SegmentMedia& media, const Vec3& origin, const Vec3& direction, float length,
                            Sampler& sampler) {
    const Regions regions(media);
    if (regions.count == 0 || !(length > 0.0f)) return Color(1.0f);
    if (regions.homogeneous()) {
        Color extinction(0.0f);
        for (int i = 0; i < regions.count; ++i)
            extinction += regions.list[std::size_t(i)].medium->constant().extinction;
        return glm::exp(-extinction * length);
    }
    // Ratio tracking: the product of the null-collision shares.
    const float majorant = regions.majorant();
    if (!(majorant > 0.0f)) return Color(1.0f);
    Color transmittance(1.0f);
    float s = 0.0f;
    for (;;) {
        s -= std::log1p(-std::min(sampler.next_1d(), 0.99999994f)) / majorant;
        if (s >= length) return transmittance;
        const Vec3 p = origin + s * direction;
        Color extinction(0.0f);
        for (int i = 0; i < regions.count; ++i) {
            const MediumRegion& r = regions.list[std::size_t(i)];
            extinction += r.medium->at(p, r.space).extinction;
        }
        transmittance *= glm::max(Color(1.0f) - extinction / majorant, Color(0.0f));
        // Russian roulette once little is left (unbiased).
        const float left = max_component(transmittance);
        if (left < 0.1f) {
            if (sampler.next_1d() >= left) return Color(0.0f);
            transmittance /= left;
        }
    }
}

namespace {

Color entry_pass_through_weight(const Hit& hit) {
    const Material& material = *hit.material;
    const MaterialParameters& p = material.parameters();
    if (std::abs(p.ior - 1.0f) >= 1e-6f && p.ior > 0.0f) return Color(0.0f);
    const SurfaceSample surface = material.sample_surface(hit);
    const float transparency = material.transparency(surface);
    if (!(transparency > 0.0f)) return Color(0.0f);
    Color weight = transparency * material.transmission_tint(surface);
    if (p.conserve_energy) {
        const float cos_i = std::abs(glm::dot(hit.shading_normal, hit.geometric_normal));
        weight *=
            glm::clamp(Color(1.0f) - material.mirror_reflectance(surface, cos_i, p.ior), Color(0.0f), Color(1.0f));
    }
    return weight;
}

}  // namespace

Color pass_through_weight(const Hit& hit) {
    return shade_blended(hit, entry_pass_through_weight);
}

Color shadow_transmittance(const RenderScene& scene, const Ray& shadow_ray, const Light* own_light, Sampler& sampler) {
    // The bound guards against stacks of coplanar transparent faces.
    constexpr int kMaxSurfacesCrossed = 64;
    Color throughput(1.0f);
    Ray ray = shadow_ray;
    const Vec3 end = shadow_ray.at(shadow_ray.t_max);
    for (int crossed = 0; crossed < kMaxSurfacesCrossed; ++crossed) {
        const float scale = glm::length(ray.direction);
        // The surface after the end too: it tells which medium the last
        // stretch runs in (a back face: inside that object).
        Ray probe = ray;
        probe.t_max = kInfinity;
        Hit next;
        const bool found = scene.intersect(probe, next);
        const bool before_end = found && next.t <= ray.t_max;
        const float stretch = (before_end ? next.t : ray.t_max) * scale;
        const SegmentMedia media = media_before_judged_by_face(scene, probe, found ? &next : nullptr);
        throughput *= segment_transmittance(media, ray.origin, ray.direction / scale, stretch, sampler);
        if (!before_end || is_black(throughput)) return throughput;
        // A blocker passes light only straight through (no_shadow ones and
        // the light's own surface always).
        if (next.casts_shadow && (own_light == nullptr || next.emitter != own_light)) {
            throughput *= pass_through_weight(next);
            if (is_black(throughput)) return throughput;
        }
        ray = next.spawn_ray_to(end);
    }
    return Color(0.0f);
}

}  // namespace lancer
