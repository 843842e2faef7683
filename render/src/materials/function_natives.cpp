#include "materials/function_natives.h"

#include "materials/noise.h"

namespace lancer {

RenderFunctionNatives::RenderFunctionNatives(const sg::Function& root, const MaterialBuild& build)
    : m_generator(build.generator) {
    gather(root, build);
}

RenderFunctionNatives::~RenderFunctionNatives() = default;

void RenderFunctionNatives::gather(const sg::Function& f, const MaterialBuild& build) {
    // Refused here, before any thread runs it.
    if (f.internal >= 0 && !sg::internal_function_supported(f.internal))
        throw sg::FunctionError("POV-Ray 3.7 has no internal function " + std::to_string(f.internal) +
                                (f.name.empty() ? std::string() : " (" + f.name + ")"));
    if (f.pattern && !m_patterns.count(f.pattern.get()))
        m_patterns.emplace(f.pattern.get(), std::make_unique<CompiledPattern>(compile_pattern(*f.pattern, build)));
    if (f.pigment && !m_pigments.count(f.pigment.get()))
        m_pigments.emplace(f.pigment.get(), make_point_pigment(*f.pigment, build));
    for (const auto& callee : f.callees) gather(*callee, build);
}

double RenderFunctionNatives::noise(const glm::dvec3& p, int generator) const {
    // 0: the scene's generator (f_noise3d).
    const NoiseGenerator chosen = generator >= 1 && generator <= 3 ? NoiseGenerator(generator) : m_generator;
    return pov_noise(p, chosen);
}

double RenderFunctionNatives::pattern(const sg::Pattern& pattern, const glm::dvec3& p) const {
    const auto found = m_patterns.find(&pattern);
    if (found == m_patterns.end()) return 0.0;
    return found->second->value(p);
}

std::array<double, 5> RenderFunctionNatives::pigment(const sg::Pigment& pigment, const glm::dvec3& p) const {
    const auto found = m_pigments.find(&pigment);
    if (found == m_pigments.end()) return {0.0, 0.0, 0.0, 0.0, 0.0};
    const TextureSample c = found->second->at(p, PatternContext{});
    return {c.rgb.r, c.rgb.g, c.rgb.b, c.filter, c.transmit};
}

namespace {

// For functions called while parsing: each pattern and pigment is compiled
// when asked for, as the scene graph may free and reuse them between calls,
// with the noise generator the scene has set so far. The natives for each
// generator are made at once, so one object may answer several threads.
class ParseTimeNatives final : public sg::FunctionNatives {
  public:
    ParseTimeNatives() : m_generator(NoiseGenerator::RangeCorrected) {
        m_original = std::unique_ptr<ParseTimeNatives>(new ParseTimeNatives(NoiseGenerator::Original, this));
        m_perlin = std::unique_ptr<ParseTimeNatives>(new ParseTimeNatives(NoiseGenerator::Perlin, this));
    }

    double noise(const glm::dvec3& p, int generator) const override {
        return pov_noise(p, generator >= 1 && generator <= 3 ? NoiseGenerator(generator) : m_generator);
    }
    double pattern(const sg::Pattern& pattern, const glm::dvec3& p) const override {
        try {
            return compile_pattern(pattern, MaterialBuild(m_generator)).value(p);
        } catch (const std::exception& e) {
            throw sg::FunctionError(e.what());
        }
    }
    std::array<double, 5> pigment(const sg::Pigment& pigment, const glm::dvec3& p) const override {
        try {
            const TextureSample c = make_point_pigment(pigment, MaterialBuild(m_generator))->at(p, PatternContext{});
            return {c.rgb.r, c.rgb.g, c.rgb.b, c.filter, c.transmit};
        } catch (const std::exception& e) {
            throw sg::FunctionError(e.what());
        }
    }
    glm::dvec3 turbulence_vector(const glm::dvec3& p, double omega, double lambda, int octaves) const override {
        return pov_dturbulence(p, omega, lambda, octaves, NoiseGenerator::RangeCorrected);
    }
    const sg::FunctionNatives& with_noise_generator(int generator) const override {
        const ParseTimeNatives& root = m_root ? *m_root : *this;
        if (generator == int(NoiseGenerator::Original)) return *root.m_original;
        if (generator == int(NoiseGenerator::Perlin)) return *root.m_perlin;
        return root;
    }

  private:
    ParseTimeNatives(NoiseGenerator generator, const ParseTimeNatives* root) : m_generator(generator), m_root(root) {}

    NoiseGenerator m_generator;
    const ParseTimeNatives* m_root = nullptr;  // null: this is the root, generator 2
    std::unique_ptr<ParseTimeNatives> m_original, m_perlin;
};

}  // namespace

std::unique_ptr<sg::FunctionNatives> make_parse_time_function_natives() {
    return std::make_unique<ParseTimeNatives>();
}

}  // namespace lancer
