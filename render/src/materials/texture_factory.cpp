// Pigments from the scene graph, one pattern family per file.
#include "materials/pattern_space.h"

namespace lancer {

TextureFactory::TextureFactory(const TextureSpaces& spaces) : m_spaces(spaces) {}
TextureFactory::~TextureFactory() = default;

std::unique_ptr<Texture> TextureFactory::make(const sg::Pigment& pigment) {
    switch (pigment.kind) {
    case sg::Pigment::Kind::Checker: return make_checker_texture(pigment, m_spaces);
    case sg::Pigment::Kind::Image: return make_image_texture(pigment, m_spaces, m_images);
    case sg::Pigment::Kind::Solid:
    default: return make_solid_texture(to_sample(pigment.color));
    }
}

std::unique_ptr<Texture> TextureFactory::make_solid(const Color& rgb, float filter, float transmit) {
    return make_solid_texture(TextureSample{rgb, filter, transmit});
}

}  // namespace lancer
