// path — the unbiased reference path tracer every other integrator is
// measured against.
//
// Monte Carlo path tracing of the shared material model (material.h) with
// next-event estimation on the scene's lights (point, directional, rectangle
// and sphere area lights, emissive objects), BSDF importance sampling
// (bsdf_sampling.h), and multiple importance sampling of the two with the
// power heuristic, so small bright lights and glossy reflections of large
// ones both converge quickly. Paths are cut by Russian roulette after
// `rr_depth` bounces (unbiased; see survival_probability) and by
// `max_depth` (a truncation: light
// that needs more bounces is left out). Converges to the exact solution of
// the scene model, with these deliberate differences from POV-Ray:
//   - POV's ambient term is ignored: indirect light is computed, not faked;
//   - area lights and emissive objects are visible and emit by radiance;
//   - transparent surfaces with an ior are smooth dielectrics (Fresnel
//     reflection and refraction inside the transmitted share), with
//     radiance scaled by (eta_from/eta_to)^2 across the interface;
//   - as in POV-Ray and the seed, a finish is a sum: the mirror adds to the
//     diffuse lobe (additive_reflection=false takes the mirror's share
//     from the diffuse instead). A finish that reflects more than it
//     receives stays finite: max_depth bounds every path.
// Camera rays that hit a light see its emission; rays that escape see the
// background. A sky_sphere is also a light for NEE, importance-sampled by
// its brightness (lancer/shading/environment_light.h) and MIS-weighted
// against BSDF sampling as every other light.
//
// Parameters: documented by `lancer plugins` / docs/integrators.md (from kParameters below).
//
// `strategy` exists to test the estimator: the three converge to the same
// image (delta lights are always sampled by NEE, the only way to reach them).
//
// Example:
//     lancer render scenes/cornell_box.pov -i path --spp 256 -p sampler=sobol -o cornell.exr
// or in the scene:
//     render_settings { integrator "path" { max_depth 8 sampler "sobol" } }
#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>

#include <lancer/integrator.h>
#include <lancer/light_tree.h>
#include <lancer/shading/bsdf_sampling.h>
#include <lancer/shading/environment_light.h>
#include <lancer/shading/material_blend.h>
#include <lancer/shading/volume_tracking.h>

namespace {

using namespace lancer;

enum class SamplerKind { Independent, Sobol };
enum class LightSelection { Power, Uniform, All, Tree };
enum class Strategy { Mis, Nee, Bsdf };

// Bounce cap standing in for "unlimited": Russian roulette ends paths long
// before it unless every surface reflects everything.
constexpr int kUnlimitedDepth = 1 << 16;

// Russian roulette's chance that a path goes on: the square root of its
// throughput's largest channel (without the interface scaling, so paths
// inside glass are not killed for it), capped at 1. Any probability keeps
// the estimate unbiased; this one is Cycles'. Killing paths in proportion
// to their throughput, the textbook rule, cut them too early in rooms of
// bright walls, where later bounces still carry much of the light: on
// bench/cycles/cornell_cycles.pov (64 spp) it took 0.91 of the time for
// 1.28 times the variance (bench/README.md).
float survival_probability(const Color& throughput, float radiance_scale) {
    return std::min(1.0f, std::sqrt(max_component(throughput) / radiance_scale));
}

struct PathSettings {
    int max_depth = 16;
    int rr_depth = 3;
    float clamp = 0.0f;
    SamplerKind sampler = SamplerKind::Independent;
    LightSelection light_selection = LightSelection::Power;
    Strategy strategy = Strategy::Mis;
    bool additive_reflection = true;
};

class PathIntegrator final : public Integrator {
  public:
    explicit PathIntegrator(const PathSettings& settings) : m_settings(settings) {}

    void prepare(const RenderScene& scene) override {
        // The lights NEE draws from: the scene's, and a sky that varies.
        m_environment.reset();
        if (scene.background_varies()) m_environment = std::make_unique<EnvironmentLight>(scene);
        m_lights = scene.lights();
        if (m_environment) m_lights.push_back(m_environment.get());
        // With the tree, the lights a tree can bound are chosen through it:
        // one tree for lights that fall off with distance, one for POV's
        // point lights without fade. Each stands in the list below as one
        // entry (null) of their summed power; the others (parallel lights,
        // the sky) stay as they are.
        m_trees.clear();
        std::vector<double> tree_power;  // per tree: its lights' summed power
        if (m_settings.light_selection == LightSelection::Tree) {
            std::vector<const Light*> falling, steady, others;
            for (const Light* light : m_lights) {
                if (light != m_environment.get() && LightTree::can_bound(*light, LightTree::Falloff::InverseSquare))
                    falling.push_back(light);
                else if (light != m_environment.get() && LightTree::can_bound(*light, LightTree::Falloff::None))
                    steady.push_back(light);
                else
                    others.push_back(light);
            }
            auto add_tree = [&](const std::vector<const Light*>& members, LightTree::Falloff falloff) {
                if (members.empty()) return;
                m_trees.push_back(std::make_unique<LightTree>(members, falloff));
                double power = 0.0;
                for (const Light* light : members) power += std::fabs(double(luminance(light->power())));
                tree_power.push_back(power);
                others.insert(others.end() - (m_environment ? 1 : 0), nullptr);
            };
            add_tree(falling, LightTree::Falloff::InverseSquare);
            add_tree(steady, LightTree::Falloff::None);
            m_lights = std::move(others);
        }
        // Entry i's tree (null for a light): the k-th null entry is tree k.
        m_entry_tree.assign(m_lights.size(), nullptr);
        std::vector<double> entry_tree_power(m_lights.size(), 0.0);
        for (std::size_t i = 0, k = 0; i < m_lights.size(); ++i)
            if (m_lights[i] == nullptr) {
                m_entry_tree[i] = m_trees[k].get();
                entry_tree_power[i] = tree_power[k++];
            }
        const std::vector<const Light*>& lights = m_lights;
        m_prepared_for = &scene;
        m_light_probability.assign(lights.size(), 0.0f);
        m_light_cdf.clear();
        m_light_index.clear();
        if (lights.empty()) return;
        const std::size_t others = lights.size() - (m_environment ? 1 : 0);
        const float environment_share = !m_environment ? 0.0f : others == 0 ? 1.0f : 0.5f;
        const float uniform = 1.0f / float(lights.size());
        std::vector<double> power(lights.size(), 0.0);
        double total = 0.0;
        bool finite = true;
        for (std::size_t i = 0; i < others; ++i) {
            // A negative light (valid POV) darkens as much as a positive
            // one lights: its magnitude sets how often it is sampled.
            power[i] = lights[i] == nullptr ? entry_tree_power[i] : std::fabs(double(luminance(lights[i]->power())));
            finite = finite && std::isfinite(power[i]);
            total += power[i];
        }
        if (m_settings.light_selection == LightSelection::Uniform ||
            m_settings.light_selection == LightSelection::All) {
            m_light_probability.assign(lights.size(), uniform);
        } else {
            const float others_uniform = others > 0 ? 1.0f / float(others) : 0.0f;
            for (std::size_t i = 0; i < others; ++i) {
                const float share =
                    !finite || !(total > 0.0) ? others_uniform : float(0.9 * power[i] / total + 0.1 * others_uniform);
                m_light_probability[i] = (1.0f - environment_share) * share;
            }
            if (m_environment) m_light_probability.back() = environment_share;
        }
        m_light_index.clear();
        for (std::size_t i = 0; i < lights.size(); ++i)
            if (lights[i] != nullptr) m_light_index[lights[i]] = i;

        m_light_cdf.assign(lights.size(), 0.0f);
        float running = 0.0f;
        for (std::size_t i = 0; i < lights.size(); ++i) m_light_cdf[i] = running += m_light_probability[i];
    }

    std::unique_ptr<Sampler> make_sampler(std::uint64_t seed) const override {
        return m_settings.sampler == SamplerKind::Sobol ? make_sobol_sampler(seed) : make_independent_sampler(seed);
    }

    Color shade_camera_hit(const Ray& camera_ray, const Hit* camera_hit, const RenderScene& scene,
                           Sampler& sampler) const override {
        const int max_depth = m_settings.max_depth < 0 ? kUnlimitedDepth : m_settings.max_depth;
        Ray ray = camera_ray;
        ray.direction = glm::normalize(ray.direction);

        Color radiance(0.0f);
        Color throughput(1.0f);
        // Product of the (eta_from/eta_to)^2 factors in `throughput`, divided
        // out for Russian roulette so it does not kill paths inside glass.
        float radiance_scale = 1.0f;
        bool delta_bounce = true;   // the camera counts as a delta event
        float previous_pdf = 0.0f;  // solid-angle density of the last BSDF sample
        Vec3 previous_point(0.0f);
        Vec3 previous_normal(0.0f);                       // the normal NEE weighed lights with there (0 in a medium)
        InteriorStack inside = scene.camera_interiors();  // objects the path is in (media, refraction)

        for (int depth = 0;; ++depth) {
            Hit hit;
            // The host traced the camera ray; the path traces the rest.
            const bool found = depth == 0 ? camera_hit != nullptr : scene.intersect(ray, hit);
            if (depth == 0 && found) hit = *camera_hit;
            // Participating media on the stretch to the hit (a scene
            // without media skips this): emission, attenuation, and
            // perhaps a scattering that continues the path from inside.
            if (scene.has_media()) {
                const SegmentMedia media = media_along(scene, inside);
                if (!media.empty()) {
                    const float length = found ? hit.t : kMediaEscapeDistance;
                    const MediumInteraction event = track_segment(media, ray.origin, ray.direction, length, sampler);
                    radiance += throughput * event.emitted;
                    throughput *= event.weight;
                    if (is_black(throughput)) break;
                    if (event.scattered) {
                        if (depth >= max_depth) break;
                        const float u_light = sampler.next_1d();
                        const Vec2 u_light_point = sampler.next_2d();
                        radiance += throughput *
                                    medium_direct_light(scene, event, ray.direction, u_light, u_light_point, sampler);
                        const float u_choice = sampler.next_1d();
                        const Vec2 u_direction = sampler.next_2d();
                        const float u_roulette = sampler.next_1d();
                        // The phase is sampled exactly: its weight is 1.
                        const Vec3 wi = event.medium->sample_phase(ray.direction, u_choice, u_direction);
                        delta_bounce = false;
                        previous_pdf = event.medium->phase_pdf(glm::dot(ray.direction, wi));
                        previous_point = event.point;
                        previous_normal = Vec3(0.0f);
                        ray = Ray{event.point, wi};
                        if (depth + 1 >= m_settings.rr_depth) {
                            const float survive = survival_probability(throughput, radiance_scale);
                            if (!(survive > 0.0f) || u_roulette >= survive) break;
                            throughput /= survive;
                        }
                        continue;
                    }
                }
            }
            if (!found) {
                // MIS-weighted against NEE when NEE could have drawn this
                // direction from the sky.
                float weight = 1.0f;
                if (m_environment && !delta_bounce && &scene == m_prepared_for) {
                    const float light_pdf =
                        selection_probability(scene, m_environment.get(), previous_point, previous_normal) *
                        m_environment->pdf(ray.direction);
                    if (m_settings.strategy == Strategy::Nee && light_pdf > 0.0f) weight = 0.0f;
                    if (m_settings.strategy == Strategy::Mis) weight = power_heuristic(previous_pdf, light_pdf);
                }
                radiance += throughput * weight * scene.background(ray);
                break;
            }
            // Next-event estimation's first number, drawn here: between two
            // texture_map entries it first picks one with its weight's
            // probability (the mean of the two, as POV-Ray blends them) and
            // is rescaled for NEE, so every bounce still draws the same
            // dimensions.
            float u_light = sampler.next_1d();
            if (hit.mix != nullptr) hit = chosen_entry(hit, u_light);
            const Vec3 wo = -ray.direction;
            const Material& material = *hit.material;
            // POV's interior fade on the stretch just travelled inside an
            // object (a back face ends it): for fade_power >= 1000 this is
            // Beer-Lambert absorption.
            if (!hit.is_front_face(wo)) throughput *= material.interior_attenuation(hit.t);
            const SurfaceSample surface = material.sample_surface(hit);

            // Emission seen along the path, MIS-weighted against NEE when
            // NEE could have produced the same path.
            if (hit.emitter != nullptr) {
                const Color emitted = hit.emitter->emitted(hit, wo);
                if (!is_black(emitted)) {
                    float weight = 1.0f;
                    if (!delta_bounce && m_settings.strategy == Strategy::Nee &&
                        selection_probability(scene, hit.emitter, previous_point, previous_normal) > 0.0f)
                        weight = 0.0f;
                    if (!delta_bounce && m_settings.strategy == Strategy::Mis) {
                        const float light_pdf =
                            selection_probability(scene, hit.emitter, previous_point, previous_normal) *
                            hit.emitter->pdf(previous_point, ray.direction, hit);
                        weight = power_heuristic(previous_pdf, light_pdf);
                    }
                    radiance += throughput * weight * emitted;
                }
            } else if (material.is_emissive()) {
                // An emitter the scene gives no light for: only BSDF sampling
                // reaches it, so it takes full weight.
                radiance += throughput * material.emitted(surface);
            }
            if (depth >= max_depth) break;

            // The indices across the surface from the objects the path is
            // in, as POV-Ray reads them: an air bubble in glass bends as
            // glass to air, water in a glass as glass to water.
            const float ior = glm::max(material.parameters().ior, 1e-6f);
            const Bsdf bsdf(material, surface, hit, wo, m_settings.additive_reflection,
                            inside.refraction_eta(hit, ior));
            if (bsdf.is_black()) break;

            // Next-event estimation. The dimensions are drawn even when
            // unused so every bounce consumes the same ones (keeps Sobol
            // dimensions aligned across samples).
            const Vec2 u_light_point = sampler.next_2d();
            if (bsdf.has_smooth())
                radiance += throughput * direct_light(scene, hit, bsdf, u_light, u_light_point, sampler);

            // Continue the path by sampling the BSDF.
            const float u_choice = sampler.next_1d();
            const Vec2 u_direction = sampler.next_2d();
            const float u_roulette = sampler.next_1d();
            const BsdfSample scattered = bsdf.sample(u_choice, u_direction);
            if (!scattered.valid()) break;
            throughput *= scattered.weight;
            if (scattered.is_transmission) radiance_scale *= bsdf.eta() * bsdf.eta();
            // With media, light is connected through index-matched surfaces
            // (shadow_transmittance): a ray passing one straight keeps the
            // sampling record of the vertex before it, for MIS.
            const bool passes_straight = scene.has_media() && scattered.is_transmission && scattered.is_delta &&
                                         std::abs(material.parameters().ior - 1.0f) < 1e-6f;
            if (scattered.is_transmission) inside = inside.crossed(hit);
            if (!passes_straight) {
                delta_bounce = scattered.is_delta;
                previous_pdf = scattered.pdf;
                previous_point = hit.position;
                previous_normal = hit.shading_normal;
            }
            ray = hit.spawn_ray(scattered.wi);

            if (depth + 1 >= m_settings.rr_depth) {
                const float survive = survival_probability(throughput, radiance_scale);
                if (!(survive > 0.0f) || u_roulette >= survive) break;
                throughput /= survive;
            }
        }

        if (m_settings.clamp > 0.0f) {
            const float peak = max_component(radiance);
            if (peak > m_settings.clamp) radiance *= m_settings.clamp / peak;
        }
        return radiance;
    }

  private:
    // The (eta_from/eta_to)^2 radiance factor a dielectric refraction put
    // into the weight (1 for anything else).
    // Probability that NEE at point p with normal n (0 in a medium) picks
    // `light` (1 when every light is sampled).
    float selection_probability(const RenderScene& scene, const Light* light, const Vec3& p, const Vec3& n) const {
        if (m_settings.light_selection == LightSelection::All) return 1.0f;
        if (&scene != m_prepared_for) return scene.lights().empty() ? 0.0f : 1.0f / float(scene.lights().size());
        const auto found = m_light_index.find(light);
        if (found != m_light_index.end()) return m_light_probability[found->second];
        // In a tree (probability 0 in the others), or not a light NEE knows:
        // then BSDF sampling takes full weight.
        float probability = 0.0f;
        for (std::size_t i = 0; i < m_entry_tree.size(); ++i)
            if (m_entry_tree[i] != nullptr)
                probability += m_light_probability[i] * m_entry_tree[i]->probability(p, n, light);
        return probability;
    }

    // Light reaching `hit` straight from the lights, through the smooth
    // lobes of `bsdf`, MIS-weighted against BSDF sampling.
    Color direct_light(const RenderScene& scene, const Hit& hit, const Bsdf& bsdf, float u_light, const Vec2& u_point,
                       Sampler& sampler) const {
        return for_chosen_lights(scene, u_light, u_point, hit.position, hit.shading_normal, sampler,
                                 [&](const Light& light, float selection, const Vec2& u) {
                                     return light_contribution(scene, hit, bsdf, light, selection, u, sampler);
                                 });
    }

    // Light scattered towards -direction at a medium point, MIS-weighted
    // against phase sampling; through media and index-matched surfaces.
    Color medium_direct_light(const RenderScene& scene, const MediumInteraction& at, const Vec3& direction,
                              float u_light, const Vec2& u_point, Sampler& sampler) const {
        return for_chosen_lights(scene, u_light, u_point, at.point, Vec3(0.0f), sampler,
                                 [&](const Light& light, float selection, const Vec2& u) {
                                     const bool delta = light.is_delta();
                                     if (!delta && m_settings.strategy == Strategy::Bsdf) return Color(0.0f);
                                     if (!light.lights_media()) return Color(0.0f);  // POV's media_interaction off
                                     if (delta && light.light_group() >= 0)
                                         return Color(0.0f);  // a light_group's: no medium
                                     const LightSample incident = light.sample(at.point, u);
                                     if (!(incident.pdf > 0.0f) || is_black(incident.radiance)) return Color(0.0f);
                                     const float phase = at.medium->phase_pdf(glm::dot(direction, incident.wi));
                                     if (!(phase > 0.0f)) return Color(0.0f);
                                     Color visible(1.0f);
                                     if (light.casts_shadows()) {
                                         Hit from;
                                         from.position = at.point;
                                         visible = shadow_transmittance(scene, from.spawn_ray_to(incident.point),
                                                                        &light, sampler);
                                         if (is_black(visible)) return Color(0.0f);
                                     }
                                     const float light_pdf = selection * incident.pdf;
                                     float weight = 1.0f;
                                     if (!incident.is_delta && m_settings.strategy == Strategy::Mis)
                                         weight = power_heuristic(light_pdf, phase);
                                     return phase * incident.radiance * visible * (weight / light_pdf);
                                 });
    }

    // Sums contribution(light, selection probability, u) over the lights
    // NEE picks at point p with normal n: one by the selection
    // distribution (through the tree when its entry is drawn), or every one.
    template <class Contribution>
    Color for_chosen_lights(const RenderScene& scene, float u_light, const Vec2& u_point, const Vec3& p, const Vec3& n,
                            Sampler& sampler, const Contribution& contribution) const {
        const std::vector<const Light*>& lights = &scene == m_prepared_for ? m_lights : scene.lights();
        if (lights.empty()) return Color(0.0f);
        if (m_settings.light_selection == LightSelection::All) {
            Color sum(0.0f);
            for (std::size_t i = 0; i < lights.size(); ++i)
                sum += contribution(*lights[i], 1.0f, i == 0 ? u_point : sampler.next_2d());
            return sum;
        }
        // One light, chosen by the selection distribution.
        std::size_t index = 0;
        float probability = 0.0f;
        if (&scene == m_prepared_for && m_light_cdf.size() == lights.size()) {
            const float target = u_light * m_light_cdf.back();
            index = std::size_t(std::upper_bound(m_light_cdf.begin(), m_light_cdf.end(), target) - m_light_cdf.begin());
            index = std::min(index, lights.size() - 1);
            probability = m_light_probability[index];
            if (lights[index] == nullptr) {
                // A tree's entry: u_light's place within it picks there.
                const float lower = index == 0 ? 0.0f : m_light_cdf[index - 1];
                const float width = m_light_cdf[index] - lower;
                const float u = width > 0.0f ? std::clamp((target - lower) / width, 0.0f, 0x1.fffffep-1f) : 0.5f;
                const LightTree::Choice choice = m_entry_tree[index]->sample(p, n, u);
                if (choice.light == nullptr || !(probability > 0.0f)) return Color(0.0f);
                return contribution(*choice.light, probability * choice.probability, u_point);
            }
        } else {
            index = std::min(std::size_t(u_light * float(lights.size())), lights.size() - 1);
            probability = 1.0f / float(lights.size());
        }
        if (!(probability > 0.0f)) return Color(0.0f);
        return contribution(*lights[index], probability, u_point);
    }

    Color light_contribution(const RenderScene& scene, const Hit& hit, const Bsdf& bsdf, const Light& light,
                             float selection, const Vec2& u, Sampler& sampler) const {
        const bool delta = light.is_delta();
        if (!delta && m_settings.strategy == Strategy::Bsdf) return Color(0.0f);
        // POV's light_group, for POV's lights (only NEE reaches them); light
        // from surfaces and the sky, which BSDF sampling finds too, reaches
        // every object.
        if (delta && !light_reaches(light, hit)) return Color(0.0f);
        const LightSample incident = light.sample(hit.position, u);
        if (!(incident.pdf > 0.0f) || is_black(incident.radiance)) return Color(0.0f);
        const Color f = bsdf.eval(incident.wi);
        if (is_black(f)) return Color(0.0f);
        Color visible(1.0f);
        if (light.casts_shadows()) {
            // With media, the light comes through them (and through
            // index-matched surfaces); without, any surface blocks it.
            const Ray shadow = hit.spawn_ray_to(incident.point);
            if (scene.has_media())
                visible = shadow_transmittance(scene, shadow, &light, sampler);
            else if (scene.occluded(shadow))
                return Color(0.0f);
            if (is_black(visible)) return Color(0.0f);
        }
        const float light_pdf = selection * incident.pdf;
        float weight = 1.0f;
        if (!incident.is_delta && m_settings.strategy == Strategy::Mis)
            weight = power_heuristic(light_pdf, bsdf.pdf(incident.wi));
        return f * incident.radiance * visible * (weight / light_pdf);
    }

    PathSettings m_settings;
    // Light selection, built in prepare() for one scene: its lights, then
    // the sky's when it varies.
    const RenderScene* m_prepared_for = nullptr;
    std::unique_ptr<EnvironmentLight> m_environment;
    std::vector<const Light*> m_lights;
    std::vector<float> m_light_probability;
    std::vector<float> m_light_cdf;
    std::unordered_map<const Light*, std::size_t> m_light_index;
    // light_sampling "tree": the trees, and for each entry of m_lights its
    // tree (null: the entry is a light).
    std::vector<std::unique_ptr<LightTree>> m_trees;
    std::vector<const LightTree*> m_entry_tree;
};

const ParameterDecl kParameters[] = {
    {"max_depth", ParameterType::Int, "16", "bounces: 0 emission only, 1 direct light only; negative: unlimited"},
    {"rr_depth", ParameterType::Int, "3", "bounces before Russian roulette starts"},
    {"clamp", ParameterType::Float, "0", "cap on each sample's largest component (biased firefly control); 0: off"},
    {"sampler", ParameterType::String, "independent",
     "\"independent\" or \"sobol\" (Owen-scrambled Sobol; best with 2^k samples)"},
    {"light_sampling", ParameterType::String, "power",
     "light chosen per NEE: \"power\", \"tree\" (by each light's bound on its contribution at the point, through a "
     "tree of their bounds), \"uniform\", or \"all\" (every light each time)"},
    {"strategy", ParameterType::String, "mis",
     "\"mis\" (default), \"nee\" (light sampling only) or \"bsdf\" (BSDF sampling only)"},
    {"additive_reflection", ParameterType::Bool, "true",
     "POV-Ray's sum: reflection added to the diffuse term; false: a mirror takes its share from the diffuse"},
};

std::unique_ptr<Integrator> create(const ParameterSet& parameters) {
    PathSettings settings;
    settings.max_depth = int(parameters.get_int("max_depth", 16));
    settings.rr_depth = int(std::max<std::int64_t>(0, parameters.get_int("rr_depth", 3)));
    settings.clamp = float(std::max(0.0, parameters.get_float("clamp", 0.0)));

    const std::string sampler = parameters.get_string("sampler", "independent");
    if (sampler == "independent")
        settings.sampler = SamplerKind::Independent;
    else if (sampler == "sobol")
        settings.sampler = SamplerKind::Sobol;
    else
        throw std::invalid_argument("path: sampler must be \"independent\" or \"sobol\", not \"" + sampler + "\"");

    const std::string selection = parameters.get_string("light_sampling", "power");
    if (selection == "power")
        settings.light_selection = LightSelection::Power;
    else if (selection == "uniform")
        settings.light_selection = LightSelection::Uniform;
    else if (selection == "all")
        settings.light_selection = LightSelection::All;
    else if (selection == "tree")
        settings.light_selection = LightSelection::Tree;
    else
        throw std::invalid_argument("path: light_sampling must be \"tree\", \"power\", \"uniform\" or \"all\", not \"" +
                                    selection + "\"");

    settings.additive_reflection = parameters.get_bool("additive_reflection", true);
    const std::string strategy = parameters.get_string("strategy", "mis");
    if (strategy == "mis")
        settings.strategy = Strategy::Mis;
    else if (strategy == "nee")
        settings.strategy = Strategy::Nee;
    else if (strategy == "bsdf")
        settings.strategy = Strategy::Bsdf;
    else
        throw std::invalid_argument("path: strategy must be \"mis\", \"nee\" or \"bsdf\", not \"" + strategy + "\"");
    return std::make_unique<PathIntegrator>(settings);
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion,
    "path",
    "unbiased path tracing: NEE + BSDF sampling with MIS, Russian roulette (the reference)",
    kParameters,
    std::size(kParameters),
    &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
