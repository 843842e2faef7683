// Building pigments from the scene graph (internal to liblancer).
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include <glm/glm.hpp>

#include "lancer/material.h"
#include "lancer/scene_graph.h"
#include "lancer/texture.h"
#include "materials/noise.h"

namespace lancer {

// For each object id, the map from world space to the space of the object
// the texture was attached to (POV: a texture moves with the transforms
// applied after it). Owned by the render scene; textures only read it.
using TextureSpaces = std::vector<glm::dmat4>;

// The scene's images, read once each; created only when a scene has an
// image_map.
class ImageCache;
class PointPigment;
class MaterialEntries;

// POV's Inside_Object for the object pattern: whether a point of pattern
// space lies in the object's solid. The scene builder makes them (this
// room does not know shapes).
using InsideTest = std::function<bool(const glm::dvec3& point)>;
using InsideTestMaker = std::function<InsideTest(const sg::Object& object)>;

// What building a pigment, pattern or normal needs beyond its scene-graph
// node: the scene's noise generator, the factory's image cache, opened on
// the first image (null: each image opens its own), and the maker of the
// object pattern's inside tests (null: the object pattern is refused).
struct MaterialBuild {
    MaterialBuild(NoiseGenerator noise = NoiseGenerator::RangeCorrected,
                  std::shared_ptr<ImageCache>* image_cache = nullptr, const InsideTestMaker* solids = nullptr)
        : generator(noise), images(image_cache), inside_tests(solids) {}
    NoiseGenerator generator;
    std::shared_ptr<ImageCache>* images;
    const InsideTestMaker* inside_tests;
};

class TextureFactory {
  public:
    explicit TextureFactory(const TextureSpaces& spaces);
    ~TextureFactory();
    TextureFactory(const TextureFactory&) = delete;
    TextureFactory& operator=(const TextureFactory&) = delete;

    // global_settings' noise_generator, for patterns that do not choose.
    void set_noise_generator(int generator) { m_noise_generator = NoiseGenerator(generator); }
    void set_inside_tests(InsideTestMaker maker) { m_inside_tests = std::move(maker); }

    // Throws lancer::SceneError at the image_map's location when the image
    // cannot be read, and at a pattern's when lancer cannot evaluate it.
    std::unique_ptr<Texture> make(const sg::Pigment& pigment);
    std::unique_ptr<NormalPerturbation> make_normal(const sg::Normal& normal);
    // A patterned texture's entries, picked by `pattern` at each hit: by
    // block, by the map's `values`, or all by their weights (`values`) for
    // an average (materials/material_entries.h).
    std::unique_ptr<MaterialEntries> make_material_entries(const sg::Pattern& pattern, int pick,
                                                           std::vector<float> values,
                                                           std::vector<const Material*> materials);
    // A pigment read at points of its own space, not at hits (the sky).
    std::unique_ptr<PointPigment> make_point_pigment(const sg::Pigment& pigment);
    // A constant colour (default black pigment, light materials).
    static std::unique_ptr<Texture> make_solid(const Color& rgb, float filter = 0.0f, float transmit = 0.0f);
    // What `function` and its callees ask of the renderer (noise, patterns,
    // pigments), for a shape that evaluates it (the isosurface).
    std::shared_ptr<const sg::FunctionNatives> function_natives(const sg::Function& function);
    // The same with patterns that do not choose taking `noise_generator`
    // (1-3) instead of global_settings' final one (a function height field
    // is made where it is written).
    std::shared_ptr<const sg::FunctionNatives> function_natives(const sg::Function& function, int noise_generator);
    // Whether something made so far reads a hit's (u,v) (uv_mapping, an
    // image mapped by (u,v)): without, the scene's hits need none.
    bool reads_surface_uv() const { return m_reads_surface_uv; }

  private:
    const TextureSpaces& m_spaces;
    bool m_reads_surface_uv = false;
    std::shared_ptr<ImageCache> m_images;
    NoiseGenerator m_noise_generator = NoiseGenerator::RangeCorrected;
    InsideTestMaker m_inside_tests;

    MaterialBuild build() {
        return MaterialBuild(m_noise_generator, &m_images, m_inside_tests ? &m_inside_tests : nullptr);
    }
};

// Whether a top-level pigment is read at the hit's (u, v) (uv_mapping, or
// an image mapped by (u, v)) rather than at its point.
bool pigment_reads_surface_uv(const sg::Pigment& pigment);

// One constructor per pattern family, each in a file of its own; the
// factory picks one by the pigment's kind. A new pattern adds a file and a
// line here and in TextureFactory::make.
std::unique_ptr<Texture> make_solid_texture(const TextureSample& value);
std::unique_ptr<Texture> make_checker_texture(const TextureSample& first, const TextureSample& second,
                                              const glm::dmat4& pattern_from_object, const TextureSpaces& spaces);
std::unique_ptr<Texture> make_pattern_texture(const sg::Pigment& pigment, const TextureSpaces& spaces,
                                              const MaterialBuild& build);
// A patterned texture (texture_map, a block list of textures) as one
// material: the map of its entries' pigments and normals, the first
// entry's finish (texture_layers.cpp says where it stands for the entries,
// each lit on its own). Others are returned as they are.
sg::Material flatten_patterned_texture(const sg::Material& texture);
// Layers' pigments composited as POV composites layered textures, bottom
// first.
std::unique_ptr<Texture> make_layered_texture(std::vector<std::unique_ptr<Texture>> layers);
// How much of each layer (bottom first) shows, from the layers' mean
// pigments; and finishes blended by such weights.
std::vector<double> layer_visibility(const std::vector<TextureSample>& averages);
sg::Finish blend_finishes(const std::vector<sg::Finish>& finishes, const std::vector<double>& weights);
std::unique_ptr<NormalPerturbation> make_surface_normal(const sg::Normal& normal, const TextureSpaces& spaces,
                                                        const MaterialBuild& build);

}  // namespace lancer
