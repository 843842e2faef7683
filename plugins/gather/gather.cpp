// gather — the seed's fourth integrator ("Ajout du pathtracing"): the
// diffuse term gathered from n directions spread evenly over the sphere.
//
// Once per render, n points s are spread evenly on the unit sphere (a
// spherical Fibonacci lattice, plugins/gather/sphere_lattice.h). At a hit
// with unit normal N, the diffuse term is the mean over the points of the
// radiance seen along v = s + N:
//     C_diffuse = (1/n) Σ_s π·f_d(v) · L(v)     (= ρd · mean L for a Lambertian surface)
// where L(v) is the colour of the nearest surface along v by the simple
// local model: its emission (a ray that hits a lamp adds the lamp's
// brightness) plus the direct light of every light of the simple model
// (point and directional lights, the proxies of area lights), without
// shadow rays; the background if v escapes. Why a plain mean: s + N lies on
// the unit sphere centred at N, which passes through the hit point, and the
// direction of a uniform point of that sphere has density cos θ / π about N.
// The mean therefore carries the cos θ of the diffuse integral by itself:
// bigger and closer lamps catch more of the n rays and light more. Shadows
// from lamps need no shadow rays: a gathered ray that a blocker stops never
// reaches the lamp (the seed: this replaces the occlusion computation).
//
// Jitter: each hit moves every point within its band of the lattice and
// turns the lattice about +y by random amounts drawn from the pixel's
// sampler (`jitter` 1: the full band and a full turn). At 1 the n
// directions are exactly cosine-distributed and stratified, so the lattice's
// fixed pattern gives way to fine noise that averages out over pixel
// samples; smaller values keep more of the fixed pattern (at 0, the seed's
// fixed lattice: the same n directions at every hit, visible as banded,
// blotchy lighting, and deterministic).
//
// Specular terms are whitted's (see whitted.cpp): highlights from the
// simple model's lights behind shadow rays, mirror reflection and refraction
// followed recursively (every hit reached that way gathers again), the
// reflection added to the diffuse (as whitted). Point and directional lights
// have no surface for a gathered ray to find, so their direct diffuse light
// is added as in whitted, behind a shadow ray. There is no ambient term: the
// gathered light stands in for it (as POV-Ray drops ambient under radiosity).
//
// Gather is biased: as n and the samples per pixel grow it converges to one
// bounce of the simple model, not to the true image (docs/integrators.md
// lists where it shows: light leaking through walls onto secondary hits,
// missing multiple bounces in closed rooms, hot spots near lamp proxies,
// no caustics).
//
// Parameters: documented by `lancer plugins` / docs/integrators.md (from kParameters below).
//
// Example:
//     lancer render scenes/cornell_box.pov -i gather -p n=100 --spp 16 -o cornell_gather.png
// or in the scene:
//     render_settings { integrator "gather" { n 100 jitter 1 } samples 16 }
#include <algorithm>
#include <iterator>
#include <stdexcept>
#include <string>

#include <lancer/integrator.h>
#include <lancer/shading/specular_tracing.h>

#include "sphere_lattice.h"

namespace {

using namespace lancer;

// POV-Ray's own limit on max_trace_level; also bounds the recursion's stack.
constexpr std::int64_t kMaxDepth = 256;

class GatherIntegrator final : public Integrator {
  public:
    GatherIntegrator(int point_count, float jitter, int max_depth, bool fresnel, bool additive_reflection)
        : m_point_count(point_count), m_jitter(jitter), m_requested_depth(max_depth), m_lattice(0) {
        m_options.fresnel = fresnel;
        m_options.additive_reflection = additive_reflection;
    }

    void prepare(const RenderScene& scene) override {
        m_lattice = SphereLattice(m_point_count);
        const int depth = m_requested_depth > 0 ? m_requested_depth : scene.options().max_trace_level;
        m_options.max_depth = int(std::clamp<std::int64_t>(depth, 1, kMaxDepth));
        m_options.min_weight = scene.options().adc_bailout;
    }

    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene, Sampler& sampler) const override {
        const auto gathered_local_term = [this, &scene](const ShadingContext& at, const Color& diffuse_scale,
                                                        Sampler& hit_sampler) {
            LobeRadiance local = direct_light(scene, at);
            if (!is_black(diffuse_scale)) local.diffuse += gathered_diffuse(scene, at, hit_sampler);
            return local;
        };
        return shade_specular(ray, hit, scene, sampler, m_options, gathered_local_term, 1, 1.0f,
                              scene.camera_interiors());
    }

    bool is_deterministic() const override { return m_jitter == 0.0f; }

  private:
    // Highlights from every light of the simple model, and the diffuse light
    // of point and directional lights (which gathered rays cannot find),
    // each behind a shadow ray. Area lights' diffuse light is gathered.
    static LobeRadiance direct_light(const RenderScene& scene, const ShadingContext& at) {
        LobeRadiance total;
        for (const Light* light : scene.lights())
            total += reflect_simple_light(scene, at, *light, Shadows::Hard,
                                          light->is_delta() ? Lobes::All : Lobes::GlossyOnly);
        return total;
    }

    // The seed's gathered diffuse: mean over the lattice of π·f_d·L along
    // normalize(s + N), which is cosine-distributed about N.
    Color gathered_diffuse(const RenderScene& scene, const ShadingContext& at, Sampler& sampler) const {
        if (!(at.material.parameters().diffuse > 0.0f) || !(at.material.transparency(at.surface) < 1.0f))
            return Color(0.0f);
        const SphereLattice::Turn turn = SphereLattice::turn(m_jitter, m_jitter > 0.0f ? sampler.next_1d() : 0.5f);
        Color sum(0.0f);
        for (int i = 0; i < m_lattice.size(); ++i) {
            const float u = m_jitter > 0.0f ? sampler.next_1d() : 0.5f;
            const Vec3 v = m_lattice.point(i, m_jitter, u, turn) + at.normal;
            const float length = glm::length(v);
            if (!(length > 1e-6f)) continue;  // s = -N: a grazing direction of measure zero
            const Vec3 wi = v / length;
            const Color f = at.material.diffuse_brdf(at.surface, at.normal, at.wo, wi);
            if (is_black(f)) continue;
            sum += f * seen_by_simple_model(scene, at.hit.spawn_ray(wi));
        }
        return sum * (kPi / float(m_lattice.size()));
    }

    // Colour of the nearest surface along a gathered ray: emission plus the
    // simple model without shadows; the background if the ray escapes.
    static Color seen_by_simple_model(const RenderScene& scene, const Ray& ray) {
        Hit hit;
        if (!scene.intersect(ray, hit)) return scene.background(ray);
        const auto own_light = [&](const ShadingContext& at) {
            return surface_emission(at) + simple_direct_light(scene, at, Shadows::None).total();
        };
        return shade_own_light(hit, ray, scene, own_light);
    }

    int m_point_count;
    float m_jitter;
    int m_requested_depth;
    SphereLattice m_lattice;
    SpecularOptions m_options;
};

constexpr std::int64_t kMaxPoints = 1 << 20;

const ParameterDecl kParameters[] = {
    {"n", ParameterType::Int, "64", "points on the sphere: gathered rays per diffuse hit"},
    {"jitter", ParameterType::Float, "1",
     "in [0,1]: how far each hit moves the points (1: exact cosine distribution, 0: fixed lattice)"},
    {"max_depth", ParameterType::Int, "0",
     "deepest mirror/refraction level (camera ray = 1), at most 256; 0: the scene's max_trace_level"},
    {"fresnel", ParameterType::Bool, "false", "Fresnel split of transparent surfaces, as whitted"},
    {"additive_reflection", ParameterType::Bool, "true",
     "POV-Ray's sum: reflection added to the diffuse term; false: a mirror takes its share from the diffuse"},
};

std::unique_ptr<Integrator> create(const ParameterSet& parameters) {
    const std::int64_t point_count = parameters.get_int("n", 64);
    if (point_count < 1 || point_count > kMaxPoints)
        throw std::invalid_argument("gather: n must lie in [1, " + std::to_string(kMaxPoints) + "], got " +
                                    std::to_string(point_count));
    const double jitter = parameters.get_float("jitter", 1.0);
    if (!(jitter >= 0.0 && jitter <= 1.0))
        throw std::invalid_argument("gather: jitter must lie in [0, 1], got " + std::to_string(jitter));
    const std::int64_t max_depth = parameters.get_int("max_depth", 0);
    if (max_depth < 0 || max_depth > kMaxDepth)
        throw std::invalid_argument("gather: max_depth must lie in [0, " + std::to_string(kMaxDepth) + "], got " +
                                    std::to_string(max_depth));
    return std::make_unique<GatherIntegrator>(static_cast<int>(point_count), static_cast<float>(jitter),
                                              static_cast<int>(max_depth), parameters.get_bool("fresnel", false),
                                              parameters.get_bool("additive_reflection", true));
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion,
    "gather",
    "the seed's path tracing: diffuse gathered from n points on the sphere, whitted's specular",
    kParameters,
    std::size(kParameters),
    &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
