// albedo — an AOV: the albedo a denoiser takes as its guide.
//
// Intel Open Image Denoise's albedo (lancer/shading/denoiser_guides.h): the
// pigment times the finish's `diffuse` times the surface's opacity, in
// [0, 1], unlit. A perfect mirror or clear glass shows the albedo of what it
// reflects or lets through, tinted by it; a ray that escapes shows the
// background, clamped. `lancer render --aov albedo` writes the same values
// as a layer beside the beauty.
//
// No parameters.
//
// Example:
//     lancer render scenes/demo.pov -i albedo -o demo_albedo.exr
#include <lancer/integrator.h>
#include <lancer/shading/denoiser_guides.h>

namespace {

using namespace lancer;

class AlbedoIntegrator final : public Integrator {
  public:
    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene& scene, Sampler&) const override {
        return denoiser_guides(ray, hit, scene).albedo;
    }

    bool is_deterministic() const override { return true; }
};

std::unique_ptr<Integrator> create(const ParameterSet&) {
    return std::make_unique<AlbedoIntegrator>();
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion, "albedo", "AOV: the denoiser albedo, pigment x diffuse, seen through mirrors and glass",
    nullptr,           0,        &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
