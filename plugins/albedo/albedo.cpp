// albedo — an AOV: the diffuse reflectance at the nearest hit.
//
// The colour is the pigment at the hit times the finish's `diffuse`, i.e. the
// fraction of light a matte surface would scatter, without any lighting. A
// ray that hits nothing is black. Denoisers take it as their albedo guide;
// it also shows texture lookups and (u,v) mapping without shading.
//
// No parameters.
//
// Example:
//     lancer render scenes/demo.pov -i albedo -o demo_albedo.exr
#include <lancer/integrator.h>

namespace {

using namespace lancer;

class AlbedoIntegrator final : public Integrator {
  public:
    Color shade_camera_hit(const Ray&, const Hit* hit, const RenderScene&, Sampler&) const override {
        if (!hit) return Color(0.0f);
        const Material& material = *hit->material;
        return material.sample_surface(*hit).pigment * material.parameters().diffuse;
    }

    bool is_deterministic() const override { return true; }
};

std::unique_ptr<Integrator> create(const ParameterSet&) {
    return std::make_unique<AlbedoIntegrator>();
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion, "albedo", "AOV: pigment x diffuse at the nearest hit, unlit", nullptr, 0, &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
