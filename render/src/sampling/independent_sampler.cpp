// A counter-based sampler: every value is a hash of (seed, pixel, sample,
// dimension), so any sample can be regenerated independently of the order
// in which pixels, tiles or threads run.
#include "lancer/sampler.h"

namespace lancer {
namespace {

// SplitMix64's finaliser: a bijective 64-bit mixer with full avalanche.
std::uint64_t mix64(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

// Largest float below 1, so results stay in [0, 1).
constexpr float kOneMinusEpsilon = 0x1.fffffep-1f;

float to_unit_float(std::uint64_t bits) {
    // 24 high bits give every float in [0, 1) on a 2^-24 grid.
    return glm::min(float(bits >> 40) * 0x1.0p-24f, kOneMinusEpsilon);
}

class IndependentSampler final : public Sampler {
  public:
    explicit IndependentSampler(std::uint64_t seed) : m_seed(mix64(seed ^ 0x6a09e667f3bcc908ULL)) {}

    void start_sample(int pixel_x, int pixel_y, std::uint32_t sample_index) override {
        std::uint64_t key = mix64(m_seed ^ (std::uint64_t(std::uint32_t(pixel_x)) << 32 | std::uint32_t(pixel_y)));
        m_stream = mix64(key + 0x9e3779b97f4a7c15ULL * (std::uint64_t(sample_index) + 1));
        m_dimension = 0;
    }
    float next_1d() override { return to_unit_float(next_bits()); }
    Vec2 next_2d() override {
        const float u = next_1d();
        const float v = next_1d();
        return {u, v};
    }
    std::unique_ptr<Sampler> clone() const override { return std::make_unique<IndependentSampler>(*this); }

  private:
    std::uint64_t next_bits() { return mix64(m_stream + 0xd1b54a32d192ed03ULL * ++m_dimension); }

    std::uint64_t m_seed;
    std::uint64_t m_stream = 0;
    std::uint64_t m_dimension = 0;
};

}  // namespace

std::unique_ptr<Sampler> make_independent_sampler(std::uint64_t seed) {
    return std::make_unique<IndependentSampler>(seed);
}

}  // namespace lancer
