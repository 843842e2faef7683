// A plugin whose descriptor name differs from its file name: `-i misnamed`
// would otherwise load an integrator that calls itself something else.
#include <lancer/integrator.h>

namespace {

class Black final : public lancer::Integrator {
  public:
    lancer::Color shade_camera_hit(const lancer::Ray&, const lancer::Hit*, const lancer::RenderScene&,
                                   lancer::Sampler&) const override {
        return lancer::Color(0.0f);
    }
};

std::unique_ptr<lancer::Integrator> create(const lancer::ParameterSet&) {
    return std::make_unique<Black>();
}

const lancer::IntegratorDescriptor kDescriptor = {
    lancer::kPluginAbiVersion, "something_else", "name differs from file", nullptr, 0, &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
