// normal — an AOV: the surface normal at the nearest hit, as a colour.
//
// Each component of the unit normal n, turned to face the camera, is mapped
// to [0, 1] as 0.5 + 0.5 n (so +x is red, +y green, +z blue; a surface facing
// the camera along -z is bluish-dark). A ray that hits nothing is black.
// Useful to debug geometry and normals, and as a denoiser's guide channel
// (write EXR to keep the values linear).
//
// Parameters: documented by `lancer plugins` / docs/integrators.md (from kParameters below).
//
// Example:
//     lancer render scenes/demo.pov -i normal -o demo_normal.png
#include <cmath>
#include <iterator>

#include <lancer/integrator.h>

namespace {

using namespace lancer;

class NormalIntegrator final : public Integrator {
  public:
    explicit NormalIntegrator(bool shading) : m_shading(shading) {}

    Color shade_camera_hit(const Ray& ray, const Hit* found, const RenderScene&, Sampler&) const override {
        if (!found) return Color(0.0f);
        const Hit& hit = *found;
        const Vec3 toward_camera = -ray.direction;
        Vec3 n = m_shading ? hit.facing_normal(toward_camera) : hit.geometric_normal;
        if (glm::dot(n, toward_camera) < 0.0f) n = -n;
        return Color(0.5f) + 0.5f * n;
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
