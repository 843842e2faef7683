// What POV-Ray's functions ask of the renderer (noise, patterns, pigments),
// built once for a function and everything it calls, so evaluating it is
// read-only and safe from every render thread (internal to liblancer).
#pragma once

#include <map>
#include <memory>

#include "lancer/function.h"
#include "materials/point_pigment.h"

namespace lancer {

class RenderFunctionNatives final : public sg::FunctionNatives {
  public:
    // Compiles every pattern and pigment `root` and its callees use.
    RenderFunctionNatives(const sg::Function& root, const MaterialBuild& build);
    ~RenderFunctionNatives() override;

    double noise(const glm::dvec3& p, int generator) const override;
    double pattern(const sg::Pattern& pattern, const glm::dvec3& p) const override;
    std::array<double, 5> pigment(const sg::Pigment& pigment, const glm::dvec3& p) const override;

  private:
    void gather(const sg::Function& f, const MaterialBuild& build);

    NoiseGenerator m_generator;
    std::map<const sg::Pattern*, std::unique_ptr<CompiledPattern>> m_patterns;
    std::map<const sg::Pigment*, std::unique_ptr<PointPigment>> m_pigments;
};

}  // namespace lancer
