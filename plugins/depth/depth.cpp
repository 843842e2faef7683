// depth — an AOV: the distance from the camera to the nearest hit.
//
// The distance is measured along the ray in scene units (not the z-buffer
// depth). With `max_distance` > 0 it is normalised to [0, 1]: distance /
// max_distance, clamped, and a ray that hits nothing is 1 (as far as it
// gets). With `max_distance` = 0 the raw distance is written in all three
// channels (use EXR or HDR to keep it), and a ray that hits nothing is 0,
// which no hit can be.
//
// Parameters: documented by `lancer plugins` / docs/integrators.md (from kParameters below).
//
// Example:
//     lancer render scenes/demo.pov -i depth -p max_distance=20 -o demo_depth.png
//     lancer render scenes/demo.pov -i depth -o demo_depth.exr
#include <algorithm>

#include <iterator>
#include <stdexcept>
#include <string>

#include <lancer/integrator.h>

namespace {

using namespace lancer;

class DepthIntegrator final : public Integrator {
  public:
    explicit DepthIntegrator(float max_distance) : m_max_distance(max_distance) {}

    Color shade_camera_hit(const Ray& ray, const Hit* hit, const RenderScene&, Sampler&) const override {
        const bool normalised = m_max_distance > 0.0f;
        if (!hit) return Color(normalised ? 1.0f : 0.0f);
        // t is in units of the direction's length, which need not be 1.
        const float distance = hit->t * glm::length(ray.direction);
        return Color(normalised ? std::min(distance / m_max_distance, 1.0f) : distance);
    }

    bool is_deterministic() const override { return true; }

  private:
    float m_max_distance;
};

const ParameterDecl kParameters[] = {
    {"max_distance", ParameterType::Float, "0", "distance shown as white; 0 writes the raw distance (use EXR)"},
};

std::unique_ptr<Integrator> create(const ParameterSet& parameters) {
    const double max_distance = parameters.get_float("max_distance", 0.0);
    if (!(max_distance >= 0.0)) {
        throw std::invalid_argument("depth: max_distance must be 0 (raw) or positive, got " +
                                    std::to_string(max_distance));
    }
    return std::make_unique<DepthIntegrator>(float(max_distance));
}

const IntegratorDescriptor kDescriptor = {
    kPluginAbiVersion,      "depth", "AOV: distance to the nearest hit, raw or normalised", kParameters,
    std::size(kParameters), &create,
};

}  // namespace

LANCER_EXPORT_INTEGRATOR(kDescriptor)
