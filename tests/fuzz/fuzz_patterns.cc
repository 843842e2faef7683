// libFuzzer target for patterns, maps and normals (issue 17): scene text
// as fuzz_scene takes it; when it parses, the scene is compiled and every
// material's pigment and normal evaluated where 8x6 camera rays (one per
// pixel centre) meet it, and at the same hits moved far off (patterns
// must stay finite at any point).
//
// Checked: compiling never throws anything but a located SceneError;
// every colour, filter and transmit is finite (the pigment at the hit, its
// average, and at the far points); every shading normal the scene returns
// (RenderScene::intersect applies normal { } to it) and every perturbed
// normal is finite and of unit length; nothing crashes, hangs or leaks.
// A map hides a pattern's NaN (search_blend_map puts it on the first
// entry), so every pattern of the scene (maps' nested ones too) is also
// compiled on its own (materials/pattern.h) and its value, block index and
// own normal checked at the same points.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string_view>

#include <stdexcept>
#include <vector>

#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"
#include "lancer/scene_error.h"
#include "materials/pattern.h"

namespace {

using lancer::Vec3;

char g_pattern[64] = "";  // the pattern under test, for the failure message

[[noreturn]] void fail(const char* what, const Vec3& position, double value) {
    std::fprintf(stderr, "fuzz_patterns: %s (%.9g) at %.9g %.9g %.9g %s\n", what, value, position.x, position.y,
                 position.z, g_pattern);
    std::abort();
}

bool finite(const Vec3& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

void check_colour(const lancer::Color& rgb, float filter, float transmit, const Vec3& where, const char* what) {
    if (!finite(rgb)) fail(what, where, rgb.x + rgb.y + rgb.z);
    if (!std::isfinite(filter)) fail(what, where, filter);
    if (!std::isfinite(transmit)) fail(what, where, transmit);
}

void check_unit(const Vec3& n, const Vec3& where, const char* what) {
    const float length = glm::length(n);
    if (!finite(n) || !(std::fabs(length - 1.0f) < 1e-3f)) fail(what, where, length);
}

// The material's pigment and normal at a hit (which may have been moved).
void evaluate(const lancer::Hit& hit, const Vec3& unperturbed_normal) {
    const lancer::Material& material = *hit.material;
    const lancer::SurfaceSample surface = material.sample_surface(hit);
    check_colour(surface.pigment, surface.filter, surface.transmit, hit.position, "non-finite pigment");
    if (const lancer::NormalPerturbation* normal = material.normal_perturbation())
        check_unit(normal->perturb(hit, unperturbed_normal), hit.position, "perturbed normal not of unit length");
}

// Every pattern in the scene graph: pigments, normals and textures, their
// maps and lists, layers, objects' children and clips.
class PatternCollector {
  public:
    static constexpr std::size_t kMaxPatterns = 64;  // bounds the time per input
    std::vector<const lancer::sg::Pattern*> patterns;

    void add(const lancer::sg::Pattern& pattern) {
        if (patterns.size() < kMaxPatterns) patterns.push_back(&pattern);
    }
    void pigment(const lancer::sg::Pigment& p) {
        using Kind = lancer::sg::Pigment::Kind;
        if (p.kind == Kind::Patterned || p.kind == Kind::Average) add(*p.pattern);
        for (const auto& entry : p.pigment_map)
            if (entry.pigment) pigment(*entry.pigment);
        for (const auto& block : p.block_pigments)
            if (block) pigment(*block);
    }
    void normal(const lancer::sg::Normal& n) {
        if (n.kind != lancer::sg::Normal::Kind::BumpMap) add(*n.pattern);
        for (const auto& entry : n.normal_map)
            if (entry.normal) normal(*entry.normal);
        for (const auto& block : n.block_normals)
            if (block) normal(*block);
    }
    void material(const lancer::sg::Material& m) {
        pigment(m.pigment);
        if (m.normal) normal(*m.normal);
        if (m.pattern) add(*m.pattern);
        for (const auto& entry : m.texture_map)
            if (entry.texture) material(*entry.texture);
        for (const auto& block : m.block_textures)
            if (block) material(*block);
        for (const auto& layer : m.layers_above)
            if (layer) material(*layer);
    }
    void object(const lancer::sg::Object& o) {
        if (o.material) material(*o.material);
        if (const auto* group = std::get_if<lancer::sg::Group>(&o.shape))
            for (const auto& child : group->children) object(child);
        for (const auto& clip : o.clipped_by) object(clip);
    }
};

// One pattern at one point: its value finite, its block index in range,
// its own normal finite and of unit length.
struct Checked {
    lancer::CompiledPattern pattern;
    int kind;  // sg::Pattern::Kind, for the message
};

void check_pattern(const Checked& checked, const glm::dvec3& point, const Vec3& where) {
    const lancer::CompiledPattern& pattern = checked.pattern;
    std::snprintf(g_pattern, sizeof g_pattern, "pattern kind %d", checked.kind);
    const double value = pattern.value(point);
    if (!std::isfinite(value)) fail("non-finite pattern value", where, value);
    if (pattern.is_block()) {
        const int index = pattern.block_index(point);
        if (index < 0 || index >= pattern.block_count()) fail("block index out of range", where, index);
    }
    if (pattern.has_own_normal()) {
        const glm::dvec3 n = pattern.perturb_normal(glm::dvec3(0.0, 0.6, -0.8), point, 0.5);
        const double length = glm::length(n);
        if (!std::isfinite(length) || std::fabs(length - 1.0) > 1e-6) fail("pattern normal not unit", where, length);
    }
    g_pattern[0] = 0;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    static const std::string root = std::filesystem::current_path().string();
    // fuzz_scene's limits (fuzz_scene.cc says why).
    lancer::ParseOptions options;
    options.max_loop_iterations = 2000;
    options.max_objects = 2000;
    options.max_macro_depth = 50;
    options.safe = true;
    options.safe_root = root;
    std::string_view text(reinterpret_cast<const char*>(data), size);
    lancer::ParseResult result = lancer::parse_scene_string(text, "<fuzz>", options);
    if (!result.ok()) return 0;
    // The graph's patterns, kept alive while the scene is compiled from a copy.
    const lancer::sg::SceneGraph graph = *result.scene;
    PatternCollector collector;
    for (const auto& object : graph.objects) collector.object(object);
    std::unique_ptr<lancer::RenderScene> scene;
    try {
        scene = lancer::compile_scene(std::move(*result.scene));
    } catch (const lancer::SceneError&) {
        return 0;  // a located error for bad input: the contract
    }
    std::vector<Checked> patterns;
    const auto generator = lancer::NoiseGenerator(graph.global.noise_generator);
    for (const auto* pattern : collector.patterns) {
        try {
            patterns.push_back({lancer::CompiledPattern(*pattern, generator), int(pattern->kind)});
        } catch (const std::runtime_error&) {
            // Refused (unsupported, or parameters POV refuses) where the
            // scene does not use it; where it does, compile_scene refused it.
        }
    }
    constexpr int kWidth = 8, kHeight = 6;
    for (int y = 0; y < kHeight; ++y) {
        for (int x = 0; x < kWidth; ++x) {
            lancer::Ray ray;
            // A pixel outside the camera's view, or a degenerate camera, is
            // not what this target tests.
            if (!scene->camera().generate_ray(float(x) + 0.5f, float(y) + 0.5f, kWidth, kHeight, ray)) continue;
            if (!finite(ray.origin) || !finite(ray.direction)) continue;
            lancer::Hit hit;
            if (!scene->intersect(ray, hit)) continue;
            if (hit.material == nullptr) fail("hit without a material", hit.position, 0.0);
            check_unit(hit.shading_normal, hit.position, "shading normal not of unit length");
            const lancer::MaterialParameters& parameters = hit.material->parameters();
            if (parameters.pigment != nullptr) {
                const lancer::TextureSample mean = parameters.pigment->average();
                check_colour(mean.rgb, mean.filter, mean.transmit, hit.position, "non-finite pigment average");
            }
            // The geometric normal stands in for the unperturbed one (the
            // scene has already bent hit.shading_normal).
            const Vec3 normal = glm::normalize(hit.geometric_normal);
            if (!finite(normal)) continue;
            evaluate(hit, normal);
            // The same surface far off and at large coordinates.
            for (const float offset : {0.0f, 1.0e3f, 1.0e7f, -3.0e12f}) {
                lancer::Hit moved = hit;
                moved.position = hit.position + Vec3(offset, 0.5f * offset, -0.25f * offset);
                if (offset != 0.0f) evaluate(moved, normal);
                for (const auto& pattern : patterns) check_pattern(pattern, glm::dvec3(moved.position), moved.position);
            }
        }
    }
    return 0;
}
