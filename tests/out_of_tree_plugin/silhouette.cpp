// silhouette — a sample integrator written outside lancer's source tree.
//
// Every surface a camera ray hits shows one flat grey level; rays that miss
// show the scene's background. Built with find_package(lancer) and loaded
// through LANCER_PLUGIN_PATH by tests/out_of_tree_plugin_test.cpp.
//
// Parameters: documented by `lancer plugins` (generated from kParameters below).
//
// Example:
//     LANCER_PLUGIN_PATH=build lancer render scene.pov -i silhouette -p level=0.5
#include <iterator>

#include <lancer/integrator.h>

namespace {

class Silhouette final : public lancer::Integrator {
  public:
    explicit Silhouette(float level) : m_level(level) {}

    lancer::Color shade_camera_hit(const lancer::Ray& ray, const lancer::Hit* hit, const lancer::RenderScene& scene,
                                   lancer::Sampler&) const override {
        return hit != nullptr ? lancer::Color(m_level) : scene.background(ray);
    }

    bool is_deterministic() const override { return true; }

  private:
    float m_level;
};

const lancer::ParameterDecl kParameters[] = {
    {"level", lancer::ParameterType::Float, "1", "grey level of every hit surface"},
};

std::unique_ptr<lancer::Integrator> create(const lancer::ParameterSet& parameters) {
    return std::make_unique<Silhouette>(float(parameters.get_float("level", 1.0)));
}

const lancer::IntegratorDescriptor kDescriptor = {
    lancer::kPluginAbiVersion, "silhouette", "flat grey where a surface is hit (out-of-tree sample)", kParameters,
    std::size(kParameters),    &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
