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

// exp(-optical depth) of the atmosphere over the whole of a shadow ray.
inline Color atmosphere_transmittance(const RenderScene& scene, const Ray& ray) {
    const MediumRegion atmosphere = scene.atmosphere();
    if (!atmosphere) return Color(1.0f);
    const float scale = glm::length(ray.direction);
    const float length = std::isfinite(ray.t_max) ? ray.t_max * scale : kMediaEscapeDistance;
    return glm::exp(-pov_media_optical_depth(atmosphere, ray.origin, ray.direction / scale, length));
}

// How much light leaving `target` reaches the hit: 1 when nothing lies
// between, 0 behind an opaque shadow caster. Transparent surfaces on the way
// filter it by transparency * transmission tint without bending it
// (POV-Ray's filtered shadows), so a fully transmitting object casts no
// shadow. `own_light`'s surface is skipped: the proxy of a sphere light sits
// at its centre, inside the light's own geometry.
inline Color transmittance_to(const RenderScene& scene, const Hit& from, const Vec3& target,
                              const Light* own_light = nullptr) {
    Ray ray = from.spawn_ray_to(target);
    // POV's media_attenuation: the atmosphere dims the light on its way.
    Color dimmed(1.0f);
    if (own_light != nullptr && own_light->dimmed_by_atmosphere()) {
        if (scene.has_media()) dimmed = atmosphere_transmittance(scene, ray);
        // And fog, which dims without adding its colour (POV's shadow rays).
        if (const SceneFog* fog = scene.fog()) {
            const float scale = glm::length(ray.direction);
            const float length = std::isfinite(ray.t_max) ? ray.t_max * scale : kFogEscapeDistance;
            dimmed *= fog->transmittance(ray.origin, ray.direction / scale, length);
        }
    }
    if (!scene.occluded(ray)) return dimmed;  // the common case: one cheap query

    // Walk the surfaces in between, nearest first. The bound only guards
    // against pathological stacks of coplanar transparent faces.
    constexpr int kMaxSurfacesCrossed = 64;
    Color throughput = dimmed;
    for (int crossed = 0; crossed < kMaxSurfacesCrossed; ++crossed) {
        Hit blocker;
        if (!scene.intersect(ray, blocker)) return throughput;
        const bool filters = blocker.casts_shadow && (own_light == nullptr || blocker.emitter != own_light);
        if (filters) {
            // Between two texture_map entries, what each lets through, blended.
            const auto passes = [&ray](const Hit& surface_hit) {
                const Material& material = *surface_hit.material;
                const SurfaceSample surface = material.sample_surface(surface_hit);
                if (!(material.transparency(surface) > 0.0f)) return Color(0.0f);
                Color passed = material.pov_transmitted(surface);
                if (const float caustics = material.parameters().caustics; caustics != 0.0f) {
                    const float cosine =
                        glm::dot(surface_hit.shading_normal, ray.direction) / glm::length(ray.direction);
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
            throughput *= shade_blended(blocker, layers_pass);
            if (lancer::is_black(throughput)) return throughput;
        }
        // The stretch just crossed ran inside this object: its media dim the
        // light, as POV's shadow rays see interior media (not the
        // atmosphere: POV's media_attenuation is off by default).
        if (scene.has_media()) throughput *= interior_media_transmittance(ray, blocker);
        // And its interior fade, by the length of that stretch (POV's
        // ComputeShadowTexture, which fades only with a fade_power).
        if (!blocker.is_front_face(-ray.direction) && blocker.material->parameters().fade_power > 0.0f)
            throughput *= blocker.material->interior_attenuation(blocker.t * glm::length(ray.direction));
        if (lancer::is_black(throughput)) return throughput;
        ray = blocker.spawn_ray_to(target);
    }
    return Color(0.0f);
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
                  const Vec3& to_light, const Color& light_colour)
        : m_scene(scene),
          m_from(from),
          m_light(light),
          m_area(area),
          m_axes(area_grid_axes(area, glm::dvec3(to_light))),
          m_colour(light_colour),
          m_state(state_of_thread()) {
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
        if (m_area.size1 == 1 && m_area.size2 == 1) return corner(0, 0);
        return subset(0, 0, m_area.size1 - 1, m_area.size2 - 1, 0);
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
            c[0] = subset(u1, v1, low_u, low_v, level + 1);
            c[1] = subset(high_u, v1, u2, low_v, level + 1);
            c[2] = subset(u1, high_v, low_u, v2, level + 1);
            c[3] = subset(high_u, high_v, u2, v2, level + 1);
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
        const Color seen = transmittance_to(m_scene, m_from, Vec3(point), &m_light);
        state.stamp[index] = state.generation;
        state.value[index] = seen;
        return seen;
    }

    // POV jitters at random from render to render; lancer's jitter is a
    // hash of the shading point and the grid point, so a render repeats.
    double jitter(std::size_t index, int axis) const {
        return point_hash(m_from.position, std::uint64_t(index) << 1 | std::uint64_t(axis));
    }

    const RenderScene& m_scene;
    const Hit& m_from;
    const Light& m_light;
    const PovAreaLightParameters& m_area;
    AreaGridAxes m_axes;
    Color m_colour;
    State& m_state;
};

}  // namespace lancer
