// Shadow rays of the simple model: how much of a light reaches a surface
// hit, through transparent blockers, and POV-Ray's grid of shadow rays for
// its area_light (TraceAreaLightShadowRay; pov-3.7-semantics.md §6).
// Header-only, as local_shading.h.
#pragma once

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <vector>

#include "lancer/area_light_grid.h"
#include "lancer/render_scene.h"
#include "lancer/shading/material_blend.h"
#include "lancer/shading/point_hash.h"
#include "lancer/shading/pov_media.h"

namespace lancer {

// exp(-optical depth) of the interior media along `ray` up to `blocker`
// when the segment ran inside a hollow object with media; else 1.
inline Color interior_media_transmittance(const Ray& ray, const Hit& blocker) {
    if (blocker.is_front_face(-ray.direction)) return Color(1.0f);
    const MaterialParameters& inside = blocker.material->parameters();
    if (!inside.hollow || inside.medium == nullptr) return Color(1.0f);
    const float scale = glm::length(ray.direction);
    const MediumRegion region{inside.medium, blocker.object_id};
    return glm::exp(-pov_media_optical_depth(region, ray.origin, ray.direction / scale, blocker.t * scale));
}

// exp(-optical depth) of the interiors' media along `ray` up to `blocker`,
// as POV-Ray's shadow rays see them (ComputeShadowColour): every object on
// the ray's list, sampled as one, unless one of them is solid.
inline Color listed_media_transmittance(const Ray& ray, const Hit& blocker, const InteriorStack& inside) {
    const InteriorMedia media = interior_media(inside);
    if (!media) return Color(1.0f);
    const float scale = glm::length(ray.direction);
    return glm::exp(-pov_media_optical_depth(media.regions.data(), media.count, ray.origin, ray.direction / scale,
                                             blocker.t * scale));
}

// exp(-optical depth) of the atmosphere over the whole of a shadow ray.
inline Color atmosphere_transmittance(const RenderScene& scene, const Ray& ray) {
    const MediumRegion atmosphere = scene.atmosphere();
    if (!atmosphere) return Color(1.0f);
    const float scale = glm::length(ray.direction);
    const float length = std::isfinite(ray.t_max) ? ray.t_max * scale : kMediaEscapeDistance;
    return glm::exp(-pov_media_optical_depth(atmosphere, ray.origin, ray.direction / scale, length));
}

// Whether the atmosphere or fog dims `light` on its way to a surface
// (POV's media_attenuation; fog too).
inline bool dimmed_on_its_way(const RenderScene& scene, const Light* light) {
    return light != nullptr && light->dimmed_by_atmosphere() && (scene.has_media() || scene.fog() != nullptr);
}

// What the light loses along a shadow ray that nothing blocks: POV's
// media_attenuation (the atmosphere dims it on its way) and fog, which dims
// without adding its colour (POV's shadow rays).
inline Color dimming_on_the_way(const RenderScene& scene, const Ray& ray, const Light* own_light) {
    Color dimmed(1.0f);
    if (!dimmed_on_its_way(scene, own_light)) return dimmed;
    if (scene.has_media()) dimmed = atmosphere_transmittance(scene, ray);
    if (const SceneFog* fog = scene.fog()) {
        const float scale = glm::length(ray.direction);
        const float length = std::isfinite(ray.t_max) ? ray.t_max * scale : kFogEscapeDistance;
        dimmed *= fog->transmittance(ray.origin, ray.direction / scale, length);
    }
    return dimmed;
}

// What one surface on a shadow ray travelling along `direction` lets
// through: its filter and transmit (each layer's, each texture_map
// entry's blended), as POV-Ray's ComputeShadowTexture. A surface that casts
// no shadow, or is `own_light`'s, lets everything through.
inline Color surface_passes(const Hit& blocker, const Vec3& direction, const Light* own_light) {
    if (!blocker.casts_shadow || (own_light != nullptr && blocker.emitter == own_light)) return Color(1.0f);
    // Between two texture_map entries, what each lets through, blended.
    const auto passes = [&direction](const Hit& surface_hit) {
        const Material& material = *surface_hit.material;
        if (material.parameters().pigment_opaque) return Color(0.0f);
        const SurfaceSample surface = material.sample_surface(surface_hit);
        // POV's opaque test: neither filter nor transmit (a negative
        // transmit lets through negative light).
        if (surface.filter == 0.0f && surface.transmit == 0.0f) return Color(0.0f);
        Color passed = material.pov_transmitted(surface);
        if (const float caustics = material.parameters().caustics; caustics != 0.0f) {
            const float cosine = glm::dot(surface_hit.shading_normal, direction) / glm::length(direction);
            passed *= 1.0f + std::pow(std::fabs(cosine), caustics);
        }
        return passed;
    };
    // A layered texture: every layer dims it (POV's ComputeShadowTexture).
    const auto layers_pass = [&](const Hit& surface_hit) {
        const MaterialLayers* layers = layers_to_light(surface_hit);
        if (layers == nullptr) return passes(surface_hit);
        Color passed(1.0f);
        for (const Material* layer : layers->top_first) {
            passed *= passes(entry_hit(surface_hit, layer));
            if (lancer::is_black(passed)) break;
        }
        return passed;
    };
    return shade_blended(blocker, layers_pass);
}

// The interior fade over a stretch of `length` that ended leaving an
// object at `blocker` (POV's ComputeShadowTexture, which fades only with a
// fade_power); 1 elsewhere.
inline Color fade_before(const Hit& blocker, const Vec3& direction, float length) {
    if (blocker.is_front_face(-direction) || !(blocker.material->parameters().fade_power > 0.0f)) return Color(1.0f);
    return blocker.material->interior_attenuation(length);
}

// What the surfaces on `ray` up to `target` let through, found by walking
// them nearest first (surfaces_transmittance asks the scene first whether
// it needs to).
inline Color walked_transmittance(const RenderScene& scene, Ray ray, const Vec3& target, const Light* own_light,
                                  const InteriorStack* inside = nullptr) {
    InteriorStack listed = inside ? *inside : InteriorStack{};

    // Walk the surfaces in between, nearest first. The bound only guards
    // against pathological stacks of coplanar transparent faces.
    constexpr int kMaxSurfacesCrossed = 64;
    Color throughput(1.0f);
    // The length run since the last surface that casts shadows: a no_shadow
    // object is not on the way at all, so it neither fades nor ends a fade.
    float stretch = 0.0f;
    for (int crossed = 0; crossed < kMaxSurfacesCrossed; ++crossed) {
        Hit blocker;
        if (!scene.intersect(ray, blocker)) return throughput;
        throughput *= surface_passes(blocker, ray.direction, own_light);
        if (lancer::is_black(throughput)) return throughput;
        // The stretch just crossed ran inside the objects on the ray's list
        // (without one, inside this object if the ray leaves it here): their
        // media dim the light, as POV's shadow rays see interior media (not
        // the atmosphere: POV's media_attenuation is off by default). A
        // no_shadow object is not on the way at all.
        if (scene.has_media()) {
            if (inside) {
                throughput *= listed_media_transmittance(ray, blocker, listed);
                if (blocker.casts_shadow) listed = listed.crossed(blocker);
            } else {
                throughput *= interior_media_transmittance(ray, blocker);
            }
        }
        stretch += blocker.t * glm::length(ray.direction);
        if (blocker.casts_shadow) {
            throughput *= fade_before(blocker, ray.direction, stretch);
            stretch = 0.0f;
        }
        if (lancer::is_black(throughput)) return throughput;
        ray = blocker.spawn_ray_to(target);
    }
    return Color(0.0f);
}

// walked_transmittance over surfaces the scene gathered in one query
// (RenderScene::shadow_crossings), in a scene without media.
inline Color crossed_transmittance(const Ray& ray, const SeeThroughHits& crossed, const Light* own_light) {
    Color throughput(1.0f);
    const float scale = glm::length(ray.direction);
    float previous_t = 0.0f;
    for (int k = 0; k < crossed.count; ++k) {
        const Hit& blocker = crossed[k];
        throughput *= surface_passes(blocker, ray.direction, own_light);
        throughput *= fade_before(blocker, ray.direction, (blocker.t - previous_t) * scale);
        if (lancer::is_black(throughput)) return throughput;
        previous_t = blocker.t;
    }
    return throughput;
}

// What the surfaces between the hit and `target` let through (see
// transmittance_to), without the atmosphere's and fog's dimming.
inline Color surfaces_transmittance(const RenderScene& scene, const Ray& ray, const Vec3& target,
                                    const Light* own_light, const InteriorStack* inside = nullptr) {
    // Without media the surfaces may come gathered with the answer.
    SeeThroughHits crossed;
    const ShadowBlockers blockers =
        scene.has_media() ? scene.shadow_blockers(ray) : scene.shadow_crossings(ray, crossed);
    if (blockers == ShadowBlockers::None) return Color(1.0f);  // the common case: one cheap query
    // An opaque blocker lets nothing through, unless it is this light's own
    // surface (which never blocks it): a delta light has none.
    if (blockers == ShadowBlockers::Opaque && (own_light == nullptr || own_light->is_delta())) return Color(0.0f);
    if (blockers == ShadowBlockers::SeeThrough && crossed.count >= 0)
        return crossed_transmittance(ray, crossed, own_light);
    return walked_transmittance(scene, ray, target, own_light, inside);
}

// How much light leaving `target` reaches the hit: 1 when nothing lies
// between, 0 behind an opaque shadow caster. Transparent surfaces on the way
// filter it by transparency * transmission tint without bending it
// (POV-Ray's filtered shadows), so a fully transmitting object casts no
// shadow. `own_light`'s surface is skipped: the proxy of a sphere light sits
// at its centre, inside the light's own geometry.
// `inside`: the objects the shadow ray starts in (those of the ray that
// found `from`, as POV's light rays copy its list); null judges each
// interior by the face the shadow ray leaves it through.
inline Color transmittance_to(const RenderScene& scene, const Hit& from, const Vec3& target,
                              const Light* own_light = nullptr, const InteriorStack* inside = nullptr) {
    const Ray ray = from.spawn_ray_to(target);
    return dimming_on_the_way(scene, ray, own_light) * surfaces_transmittance(scene, ray, target, own_light, inside);
}

// POV's area-light visibility from `from`: the light's colour (in POV's
// units, for the adaptive threshold) times the transmittance to each grid
// point, averaged as POV does: the four corners of a region, split into
// four (sharing the midlines when sizes are odd) while the level is below
// `adaptive` or two neighbouring corners differ by more than 0.1 (sum over
// channels), then the mean of the four sub-results. Not the mean of all
// grid points: the hierarchy weights them unevenly, and matching POV's
// pixels needs this. Each grid point is traced at most once per call.
// Returns the visibility as a transmittance (1: all of the light arrives).
class PovAreaShadow {
  public:
    PovAreaShadow(const RenderScene& scene, const Hit& from, const Light& light, const PovAreaLightParameters& area,
                  const Vec3& to_light, const Color& light_colour, const InteriorStack* inside = nullptr)
        : m_scene(scene),
          m_from(from),
          m_inside(inside),
          m_light(light),
          m_area(area),
          m_axes(area_grid_axes(area, glm::dvec3(to_light))),
          m_colour(light_colour),
          m_state(state_of_thread()),
          m_clear(grid_is_clear()),
          m_dimmed(dimmed_on_its_way(scene, &light)) {
        State& state = m_state;
        const std::size_t cells = std::size_t(area.size1) * std::size_t(area.size2);
        if (state.stamp.size() < cells) state.stamp.resize(cells, 0);
        if (state.value.size() < cells) state.value.resize(cells);
        if (++state.generation == 0) {  // wrapped: forget every stamp
            std::fill(state.stamp.begin(), state.stamp.end(), 0u);
            state.generation = 1;
        }
    }

    Color visibility() const {
        if (m_clear && !m_dimmed) return Color(1.0f);  // what every grid point would give
        const Color seen =
            m_area.size1 == 1 && m_area.size2 == 1 ? corner(0, 0) : subset(0, 0, m_area.size1 - 1, m_area.size2 - 1, 0);
        if (!m_dimmed || is_black(seen)) return seen;
        // POV-Ray dims the grid's average once, along the last light ray
        // its sampling computed (TraceShadowRay after
        // TraceAreaLightSubsetShadowRay): towards the centre, or, once the
        // grid was split, towards twice the centre's position (it passes
        // the centre as an offset from the centre), over the length of
        // whichever ray it computed last.
        const glm::dvec3 centre(m_area.center.position);
        Ray ray = m_from.spawn_ray_to(Vec3(m_split ? 2.0 * centre : centre));
        ray.t_max = float(m_last_length);
        return seen * dimming_on_the_way(m_scene, ray, &m_light);
    }

  private:
    struct State {
        std::vector<std::uint32_t> stamp;  // == generation: value holds this call's result
        std::vector<Color> value;
        std::uint32_t generation = 0;
    };
    static State& state_of_thread() {
        thread_local State state;
        return state;
    }

    float distance(const Color& a, const Color& b) const {
        const Color d = glm::abs(a - b) * m_colour;
        return d.r + d.g + d.b;
    }

    Color subset(int u1, int v1, int u2, int v2, int level) const {
        Color c[4] = {corner(u1, v1), corner(u2, v1), corner(u1, v2), corner(u2, v2)};
        if ((u2 - u1 > 1 || v2 - v1 > 1) &&
            (level < m_area.adaptive || distance(c[0], c[1]) > 0.1f || distance(c[1], c[3]) > 0.1f ||
             distance(c[3], c[2]) > 0.1f || distance(c[2], c[0]) > 0.1f)) {
            const int low_u = (u1 + u2) / 2, high_u = (u1 + u2 + 1) / 2;  // floor and ceil of the midpoint
            const int low_v = (v1 + v2) / 2, high_v = (v1 + v2 + 1) / 2;
            const int quarters[4][4] = {
                {u1, v1, low_u, low_v}, {high_u, v1, u2, low_v}, {u1, high_v, low_u, v2}, {high_u, high_v, u2, v2}};
            for (int i = 0; i < 4; ++i) {
                if (m_dimmed) aim_at_twice_the_centre();  // POV aims its light ray before each quarter
                const int* q = quarters[i];
                c[i] = subset(q[0], q[1], q[2], q[3], level + 1);
            }
        }
        return (c[0] + c[1] + c[2] + c[3]) * 0.25f;
    }

    Color corner(int u, int v) const {
        State& state = m_state;  // looked up once: a plugin's thread_local costs a call per access
        const std::size_t index = std::size_t(u) * std::size_t(m_area.size2) + std::size_t(v);
        if (state.stamp[index] == state.generation) return state.value[index];
        double ju = u, jv = v;
        if (m_area.jitter) {
            ju += jitter(index, 0) - 0.5;
            jv += jitter(index, 1) - 0.5;
        }
        const glm::dvec3 point = glm::dvec3(m_area.center.position) + area_grid_offset(m_area, m_axes, ju, jv);
        if (m_dimmed) m_last_length = glm::distance(point, glm::dvec3(m_from.position));
        // Undimmed: the atmosphere and fog dim the average (visibility()).
        const Color seen = m_clear ? Color(1.0f)
                                   : surfaces_transmittance(m_scene, m_from.spawn_ray_to(Vec3(point)), Vec3(point),
                                                            &m_light, m_inside);
        state.stamp[index] = state.generation;
        state.value[index] = seen;
        return seen;
    }

    void aim_at_twice_the_centre() const {
        m_split = true;
        m_last_length = glm::distance(2.0 * glm::dvec3(m_area.center.position), glm::dvec3(m_from.position));
    }

    // Whether nothing can stand between the hit and any grid point, jitter
    // included (RenderScene::may_block_towards): then no shadow ray is
    // traced. The grid's points lie in the parallelogram the oriented axes
    // span around the centre, out to half a cell past its edges when
    // jittered (POV's circular nudge of 0.001 is covered too). One ray
    // origin must serve them all, so they must lie clearly on one side of
    // the surface.
    bool grid_is_clear() const {
        if (m_area.circular && (m_area.size1 == 1 || m_area.size2 == 1)) return false;
        const auto half_extent = [&](int size) {
            return size <= 1 ? 0.0 : 0.502 + (m_area.jitter ? 0.5 / double(size - 1) : 0.0);
        };
        const double h1 = half_extent(m_area.size1), h2 = half_extent(m_area.size2);
        const glm::dvec3 corner = glm::dvec3(m_area.center.position) - h1 * m_axes.axis1 - h2 * m_axes.axis2;
        const glm::dvec3 edge1 = 2.0 * h1 * m_axes.axis1, edge2 = 2.0 * h2 * m_axes.axis2;
        const glm::dvec3 position(m_from.position), normal(m_from.geometric_normal);
        int above = 0, below = 0;
        for (const glm::dvec3& point : {corner, corner + edge1, corner + edge1 + edge2, corner + edge2}) {
            const double side = glm::dot(point - position, normal);
            const double clearance = 1e-4 * glm::length(point - position);
            above += side > clearance;
            below += side < -clearance;
        }
        if (above != 4 && below != 4) return false;
        const Vec3 origin = m_from.offset_origin(Vec3(corner - position));
        return !m_scene.may_block_towards(origin, Vec3(corner), Vec3(edge1), Vec3(edge2));
    }

    // POV jitters at random from render to render; lancer's jitter is a
    // hash of the shading point and the grid point, so a render repeats.
    double jitter(std::size_t index, int axis) const {
        return point_hash(m_from.position, std::uint64_t(index) << 1 | std::uint64_t(axis));
    }

    const RenderScene& m_scene;
    const Hit& m_from;
    const InteriorStack* m_inside;
    const Light& m_light;
    const PovAreaLightParameters& m_area;
    AreaGridAxes m_axes;
    Color m_colour;
    State& m_state;
    bool m_clear;   // no grid point needs a shadow ray
    bool m_dimmed;  // the atmosphere or fog dims the light on its way
    // POV's last light ray (see visibility()): whether it was aimed at twice
    // the centre, and its length.
    mutable bool m_split = false;
    mutable double m_last_length = 0.0;
};

}  // namespace lancer
