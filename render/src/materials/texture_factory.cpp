// Pigments from the scene graph, one pattern family per file.
#include <stdexcept>

#include "lancer/scene_error.h"
#include "materials/function_natives.h"
#include "materials/material_entries.h"
#include "materials/pattern_space.h"
#include "materials/point_pigment.h"

namespace lancer {

TextureFactory::TextureFactory(const TextureSpaces& spaces) : m_spaces(spaces) {}
TextureFactory::~TextureFactory() = default;

namespace {

// A checker of two colours needs no pattern machinery.
bool is_plain_checker(const sg::Pigment& pigment) {
    const sg::Pattern& p = *pigment.pattern;
    if (pigment.kind != sg::Pigment::Kind::Patterned || p.kind != sg::Pattern::Kind::Checker) return false;
    if (!p.warps.empty() || p.turbulence != sg::Vec3(0.0) || p.uv_mapping || pigment.block_pigments.size() != 2)
        return false;
    for (const auto& block : pigment.block_pigments)
        if (block->kind != sg::Pigment::Kind::Solid) return false;
    return true;
}

}  // namespace

std::unique_ptr<Texture> TextureFactory::make(const sg::Pigment& pigment) {
    switch (pigment.kind) {
    case sg::Pigment::Kind::Image:
    case sg::Pigment::Kind::Patterned:
    case sg::Pigment::Kind::Average:
        if (is_plain_checker(pigment))
            return make_checker_texture(to_sample(pigment.block_pigments[0]->color),
                                        to_sample(pigment.block_pigments[1]->color),
                                        pigment.pattern->pattern_from_object, m_spaces);
        m_reads_surface_uv = m_reads_surface_uv || pigment_reads_surface_uv(pigment);
        try {
            return make_pattern_texture(pigment, m_spaces, build());
        } catch (const SceneError&) {
            throw;
        } catch (const std::runtime_error& unsupported) {
            throw SceneError(pigment.location, std::string("pigment: ") + unsupported.what());
        }
    case sg::Pigment::Kind::Solid:
    default: return make_solid_texture(to_sample(pigment.color));
    }
}

std::unique_ptr<NormalPerturbation> TextureFactory::make_normal(const sg::Normal& normal) {
    m_reads_surface_uv = m_reads_surface_uv || (normal.pattern && normal.pattern->uv_mapping);
    return make_surface_normal(normal, m_spaces, build());
}

std::unique_ptr<MaterialEntries> TextureFactory::make_material_entries(const sg::Pattern& pattern, int pick,
                                                                       std::vector<float> values,
                                                                       std::vector<const Material*> materials) {
    const auto how = MaterialEntries::Pick(pick);
    m_reads_surface_uv = m_reads_surface_uv || pattern.uv_mapping;
    CompiledPattern compiled = how == MaterialEntries::Pick::Blocks ? compile_block_pattern(pattern, build())
                                                                    : compile_pattern(pattern, build());
    return std::make_unique<MaterialEntries>(std::move(compiled), how, std::move(values), std::move(materials),
                                             m_spaces, pattern.uv_mapping);
}

std::unique_ptr<PointPigment> TextureFactory::make_point_pigment(const sg::Pigment& pigment) {
    return lancer::make_point_pigment(pigment, build());
}

std::unique_ptr<Texture> TextureFactory::make_solid(const Color& rgb, float filter, float transmit) {
    return make_solid_texture(TextureSample{rgb, filter, transmit});
}

std::shared_ptr<const sg::FunctionNatives> TextureFactory::function_natives(const sg::Function& function) {
    return std::make_shared<const RenderFunctionNatives>(function, build());
}

std::shared_ptr<const sg::FunctionNatives> TextureFactory::function_natives(const sg::Function& function,
                                                                            int noise_generator) {
    MaterialBuild how = build();
    how.generator = NoiseGenerator(noise_generator);
    return std::make_shared<const RenderFunctionNatives>(function, how);
}

}  // namespace lancer
