// normal — an AOV: the surface normal at the nearest hit, as a colour.
//
// Each component of the unit normal n, turned to face the camera, is mapped
// to [0, 1] as 0.5 + 0.5 n (so +x is red, +y green, +z blue; a surface facing
// the camera along -z is bluish-dark). A ray that hits nothing is black.
// Useful to debug geometry and normals. A denoiser wants the normal
// unencoded, in [-1, 1]: `lancer render --aov normal` writes it so, as the
// N layer beside the beauty.
//
// Parameters: documented by `lancer plugins` / docs/integrators.md (from kParameters below).
//
// Example:
//     lancer render scenes/demo.pov -i normal -o demo_normal.png
#include <cmath>
#include <iterator>

#include <lancer/integrator.h>
#include <lancer/shading/denoiser_guides.h>

namespace {

using namespace lancer;

class NormalIntegrator final : public Integrator {
  public:
    explicit NormalIntegrator(bool shading) : m_shading(shading) {}

    Color shade_camera_hit(const Ray& ray, const Hit* found, const RenderScene&, Sampler&) const override {
        if (!found) return Color(0.0f);
        return Color(0.5f) + 0.5f * camera_facing_normal(ray, *found, m_shading);
    }

    bool is_deterministic() const override { return true; }

  private:
    bool m_shading;
};

const ParameterDecl kParameters[] = {
    {"shading", ParameterType::Bool, "true", "the interpolated shading normal; false: the geometric normal"},
};

std::unique_ptr<Integrator> create(const ParameterSet& parameters) {
    return std::make_unique<NormalIntegrator>(parameters.get_bool("shading", true));
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion,      "normal", "AOV: camera-facing surface normal as colour 0.5 + 0.5 n", kParameters,
    std::size(kParameters), &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
