// The --aov layers: each rendered by the host's own pixel loop with a small
// integrator that returns the layer's values as a colour, then taken out of
// its film as the layer's channels.
#include "lancer/host/aov.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>

#include "lancer/shading/denoiser_guides.h"

namespace lancer {
namespace {

// What every layer's integrator shares: the beauty's sampler and its rule
// for where one sample looks.
class LayerIntegrator : public Integrator {
  public:
    explicit LayerIntegrator(const Integrator& beauty) : m_beauty(beauty) {}
    bool is_deterministic() const override { return m_beauty.is_deterministic(); }
    std::unique_ptr<Sampler> make_sampler(std::uint64_t seed) const override { return m_beauty.make_sampler(seed); }

  private:
    const Integrator& m_beauty;
};

class AlbedoLayer final : public LayerIntegrator {
  public:
    using LayerIntegrator::LayerIntegrator;
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene, Sampler&) const override {
        return denoiser_guides(ray, hit, scene).albedo;
    }
};

class NormalLayer final : public LayerIntegrator {
  public:
    using LayerIntegrator::LayerIntegrator;
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene, Sampler&) const override {
        return Color(denoiser_guides(ray, hit, scene).normal);
    }
};

// Distance in red, 1 in green for a hit: the mean over a pixel's samples
// divided by green is the mean distance of those that hit.
class DepthLayer final : public LayerIntegrator {
  public:
    using LayerIntegrator::LayerIntegrator;
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene&, Sampler&) const override {
        if (!hit) return Color(0.0f);
        return Color(hit->t * glm::length(ray.direction), 1.0f, 0.0f);
    }
};

class PositionLayer final : public LayerIntegrator {
  public:
    using LayerIntegrator::LayerIntegrator;
    Color shade_camera_hit(const Ray&, const Hit* hit, const RenderScene&, Sampler&) const override {
        return hit ? Color(hit->position) : Color(0.0f);
    }
};

class AlphaLayer final : public LayerIntegrator {
  public:
    using LayerIntegrator::LayerIntegrator;
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene, Sampler&) const override {
        return Color(camera_alpha(ray, hit, scene));
    }
};

Film render_layer(const RenderScene& scene, const Integrator& layer, const RenderOptions& options) {
    Film film(options.width, options.height, film_storage_for(scene, layer, options));
    render_image(scene, layer, options, film);
    return film;
}

ImageLayer layer_from_film(const Film& film, std::vector<std::string> channels) {
    ImageLayer layer{std::move(channels), {}};
    const std::size_t count = layer.channels.size();
    layer.values.reserve(std::size_t(film.width()) * film.height() * count);
    for (int y = 0; y < film.height(); ++y)
        for (int x = 0; x < film.width(); ++x) {
            const Color mean = film.mean(x, y);
            for (std::size_t c = 0; c < count; ++c) layer.values.push_back(mean[int(c)]);
        }
    return layer;
}

}  // namespace

const char* aov_name(Aov aov) {
    switch (aov) {
    case Aov::Albedo: return "albedo";
    case Aov::Normal: return "normal";
    case Aov::Depth: return "depth";
    case Aov::Position: return "position";
    case Aov::Alpha: return "alpha";
    }
    return "?";
}

const std::vector<Aov>& all_aovs() {
    static const std::vector<Aov> every{Aov::Albedo, Aov::Normal, Aov::Depth, Aov::Position, Aov::Alpha};
    return every;
}

std::vector<Aov> parse_aov_list(const std::string& text, std::string& problem) {
    std::vector<Aov> layers;
    std::stringstream items(text);
    std::string item;
    while (std::getline(items, item, ',')) {
        const auto known =
            std::find_if(all_aovs().begin(), all_aovs().end(), [&](Aov aov) { return item == aov_name(aov); });
        if (known == all_aovs().end()) {
            std::string names;
            for (Aov aov : all_aovs()) names += std::string(names.empty() ? "" : ", ") + aov_name(aov);
            problem = "unknown AOV '" + item + "' (known: " + names + ")";
            return {};
        }
        if (std::find(layers.begin(), layers.end(), *known) != layers.end()) {
            problem = "AOV '" + item + "' is named twice";
            return {};
        }
        layers.push_back(*known);
    }
    if (layers.empty()) problem = "no AOV named (known: albedo, normal, depth, position, alpha)";
    return layers;
}

int aov_samples_for(double beauty_mean_samples) {
    return std::clamp(int(std::lround(beauty_mean_samples)), 1, 16);
}

std::vector<ImageLayer> render_aovs(const RenderScene& scene, const Integrator& beauty, const std::vector<Aov>& layers,
                                    const RenderOptions& options, int samples) {
    RenderOptions pass = options;
    pass.samples_per_pixel = std::max(samples, 1);
    pass.max_samples_per_pixel = 0;
    pass.time_budget_seconds = 0.0;
    pass.noise_target = 0.0;
    pass.progress = ProgressMode::Quiet;
    pass.checkpoint_interval_seconds = 0.0;
    pass.on_checkpoint = nullptr;
    pass.on_pass = nullptr;
    pass.on_progress = nullptr;
    pass.cancel = nullptr;
    pass.ray_counter = nullptr;

    std::vector<ImageLayer> out;
    std::optional<Film> depth;  // shared by depth and position
    const auto hit_fraction = [&](std::size_t pixel) {
        if (!depth) depth = render_layer(scene, DepthLayer(beauty), pass);
        return depth->mean(int(pixel % std::size_t(pass.width)), int(pixel / std::size_t(pass.width))).g;
    };
    for (Aov aov : layers) {
        switch (aov) {
        case Aov::Albedo:
            out.push_back(
                layer_from_film(render_layer(scene, AlbedoLayer(beauty), pass), {"albedo.R", "albedo.G", "albedo.B"}));
            break;
        case Aov::Normal:
            out.push_back(layer_from_film(render_layer(scene, NormalLayer(beauty), pass), {"N.X", "N.Y", "N.Z"}));
            break;
        case Aov::Depth: {
            ImageLayer z{{"Z"}, {}};
            const std::size_t pixels = std::size_t(pass.width) * pass.height;
            z.values.resize(pixels);
            for (std::size_t i = 0; i < pixels; ++i) {
                const float hits = hit_fraction(i);
                const Color mean = depth->mean(int(i % std::size_t(pass.width)), int(i / std::size_t(pass.width)));
                z.values[i] = hits > 0.0f ? mean.r / hits : std::numeric_limits<float>::infinity();
            }
            out.push_back(std::move(z));
            break;
        }
        case Aov::Position: {
            ImageLayer p = layer_from_film(render_layer(scene, PositionLayer(beauty), pass), {"P.X", "P.Y", "P.Z"});
            for (std::size_t i = 0; i * 3 < p.values.size(); ++i) {
                const float hits = hit_fraction(i);
                for (int c = 0; c < 3; ++c) p.values[i * 3 + c] = hits > 0.0f ? p.values[i * 3 + c] / hits : 0.0f;
            }
            out.push_back(std::move(p));
            break;
        }
        case Aov::Alpha: out.push_back(layer_from_film(render_layer(scene, AlphaLayer(beauty), pass), {"A"})); break;
        }
    }
    return out;
}

}  // namespace lancer
