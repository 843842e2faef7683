// A pigment of one colour.
#include "materials/pattern_space.h"

namespace lancer {
namespace {

class SolidTexture final : public Texture {
  public:
    explicit SolidTexture(const TextureSample& value) : m_value(value) {}
    TextureSample evaluate(const Hit&) const override { return m_value; }
    TextureSample average() const override { return m_value; }
    const TextureSample* constant() const override { return &m_value; }

  private:
    TextureSample m_value;
};

}  // namespace

std::unique_ptr<Texture> make_solid_texture(const TextureSample& value) {
    return std::make_unique<SolidTexture>(value);
}

}  // namespace lancer
