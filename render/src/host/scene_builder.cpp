// Walking the scene graph into world-space tables.
#include "host/scene_builder.h"

#include <algorithm>
#include <cfloat>
#include <cmath>
#include <iostream>
#include <map>
#include <tuple>

#include "camera/mesh_camera_setup.h"
#include "geometry/bicubic_patch.h"
#include "geometry/height_field.h"
#include "geometry/julia_fractal.h"
#include "geometry/mesh_shape.h"
#include "geometry/ovus.h"
#include "geometry/parametric.h"
#include "geometry/sphere_sweep.h"
#include "host/shared_height_fields.h"
#include "lancer/host/scene_compiler.h"
#include "lancer/scene_error.h"
#include "materials/average_weights.h"
#include "materials/opaque_pigment.h"
#include "materials/point_pigment.h"

namespace lancer {
namespace {

MaterialParameters to_parameters(const sg::Material& m, const Texture* pigment, const NormalPerturbation* normal) {
    MaterialParameters p;
    p.pigment = pigment;
    p.normal = normal;
    p.ambient = Color(m.finish->ambient);
    p.emission = Color(m.finish->emission);
    p.diffuse = float(m.finish->diffuse);
    p.brilliance = float(m.finish->brilliance);
    p.specular = float(m.finish->specular);
    p.roughness = float(m.finish->roughness);
    p.phong = float(m.finish->phong);
    p.phong_size = float(m.finish->phong_size);
    p.metallic = float(m.finish->metallic);
    p.reflection_min = Color(m.finish->reflection.min);
    p.reflection_max = Color(m.finish->reflection.max);
    p.reflection_falloff = float(m.finish->reflection.falloff);
    p.reflection_fresnel = m.finish->reflection.fresnel;
    p.reflection_metallic = float(m.finish->reflection.metallic);
    // POV raises the reflected colour to 1 / exponent (its Reflect_Exp).
    p.reflection_exponent = float(1.0 / m.finish->reflection.exponent);
    p.conserve_energy = m.finish->conserve_energy;
    p.diffuse_back = float(m.finish->diffuse_back);
    p.crand = float(m.finish->crand);
    p.irid = float(m.finish->irid);
    p.irid_thickness = float(m.finish->irid_thickness);
    p.irid_turbulence = float(m.finish->irid_turbulence);
    p.ior = float(m.interior->ior);
    p.caustics = float(45.0 * m.interior->caustics);  // POV-Ray's scale (Parse_Interior)
    p.fade_distance = float(m.interior->fade_distance);
    p.fade_power = float(m.interior->fade_power);
    p.fade_color = Color(m.interior->fade_color);
    return p;
}

// Per channel, the largest value a density pigment takes: a colour map
// clamps its index, so its entries bound it; 1 for an image (and anything
// whose values lancer cannot bound: `path` then clamps, docs/integrators.md).
Color density_bound(const sg::Pigment& p) {
    Color bound(0.0f);
    switch (p.kind) {
    case sg::Pigment::Kind::Solid: return glm::max(Color(p.color.rgb), Color(0.0f));
    case sg::Pigment::Kind::Image: return Color(1.0f);
    case sg::Pigment::Kind::Patterned:
    case sg::Pigment::Kind::Average:
        if (p.color_map)
            for (const auto& entry : *p.color_map) bound = glm::max(bound, Color(entry.color.rgb));
        for (const auto& entry : p.pigment_map)
            if (entry.pigment) bound = glm::max(bound, density_bound(*entry.pigment));
        for (const auto& block : p.block_pigments)
            if (block) bound = glm::max(bound, density_bound(*block));
        return bound;
    }
    return Color(1.0f);
}

void expand(Bounds& b, const Vec3& lower, const Vec3& upper) {
    b.lower = glm::min(b.lower, lower);
    b.upper = glm::max(b.upper, upper);
}

// The shapes whose (u, v) POV-Ray 3.7 defines (their UVCoord); every other
// shape's is the hit's world x and y (ObjectBase::UVCoord).
bool pov_defines_uv(const decltype(sg::Object::shape)& shape) {
    return std::holds_alternative<sg::Sphere>(shape) || std::holds_alternative<sg::Box>(shape) ||
           std::holds_alternative<sg::Torus>(shape) || std::holds_alternative<sg::Lathe>(shape) ||
           std::holds_alternative<sg::Sor>(shape) || std::holds_alternative<sg::Ovus>(shape) ||
           std::holds_alternative<sg::BicubicPatch>(shape) || std::holds_alternative<sg::Parametric>(shape) ||
           std::holds_alternative<sg::MeshRef>(shape);
}

// World AABB of an object-space box under a placement, widened by a few
// ULPs so float bounds contain the double-precision surface.
void world_bounds(const Placement& placement, const DVec3& lower, const DVec3& upper, Vec3& out_lower,
                  Vec3& out_upper) {
    DVec3 lo(INFINITY), hi(-INFINITY);
    for (int corner = 0; corner < 8; ++corner) {
        const DVec3 p((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
                      (corner & 4) ? upper.z : lower.z);
        const DVec3 w = placement.point_to_world(p);
        lo = glm::min(lo, w);
        hi = glm::max(hi, w);
    }
    const DVec3 slack = 8.0 * double(FLT_EPSILON) * glm::max(glm::abs(lo), glm::abs(hi));
    out_lower = Vec3(lo - slack);
    out_upper = Vec3(hi + slack);
}

// The box of a sphere placed in the world. Moved, turned or scaled alike
// it stays a sphere, whose box is exact, as in POV-Ray (a rotated sphere's
// box is not its own box's rotated corners). Stretched, POV-Ray keeps
// the transform and turns the sphere's box's corners (min_extent shows
// it), as lancer does then.
void sphere_world_bounds(const Placement& placement, const AnalyticSphere& sphere, Vec3& out_lower, Vec3& out_upper) {
    const DVec3 r(sphere.radius);
    if (!placement.identity && !placement.is_similarity()) {
        world_bounds(placement, sphere.center - r, sphere.center + r, out_lower, out_upper);
        return;
    }
    const DVec3 center = placement.point_to_world(sphere.center);
    const DVec3 half = placement.identity ? r : r * placement.uniform_scale();
    const DVec3 lo = center - half, hi = center + half;
    const DVec3 slack = 8.0 * double(FLT_EPSILON) * glm::max(glm::abs(lo), glm::abs(hi));
    out_lower = Vec3(lo - slack);
    out_upper = Vec3(hi + slack);
}

// A setting of the objects being added, changed while one object and its
// children are added and restored after them.
template <class Setting>
class SettingScope {
  public:
    SettingScope(Setting& current, const Setting& inside) : m_current(current), m_saved(current) { current = inside; }
    ~SettingScope() { m_current = m_saved; }
    SettingScope(const SettingScope&) = delete;
    SettingScope& operator=(const SettingScope&) = delete;

  private:
    Setting& m_current;
    Setting m_saved;
};

// The light_group the objects being added are in: an object's own group
// while its children are added, the enclosing one otherwise.
struct LightGroupScope : SettingScope<int> {
    LightGroupScope(int& current, int own) : SettingScope(current, own >= 0 ? own : current) {}
};

// POV's double_illuminate on a group reaches everything inside it,
// overriding what the objects inside said: the outermost setting wins.
struct DoubleIlluminateScope : SettingScope<std::optional<bool>> {
    DoubleIlluminateScope(std::optional<bool>& current, const std::optional<bool>& own)
        : SettingScope(current, current ? current : own) {}
};

// POV's no_image and no_reflection on a group reach everything inside it
// (POV's Post_Process sets them on the children; it never clears them).
struct HiddenFrom {
    bool image = false;
    bool reflection = false;
};
struct HiddenFromScope : SettingScope<HiddenFrom> {
    HiddenFromScope(HiddenFrom& current, const sg::Object& object)
        : SettingScope(current,
                       HiddenFrom{current.image || object.no_image, current.reflection || object.no_reflection}) {}
};

// Whose interior the objects being added share: POV-Ray's Post_Process
// gives a group's Interior (one object, written or made for it) to every
// part without an interior written for it, so overlapping parts of a union
// are one object to a ray's list of interiors, while a part with its own
// interior is an object of its own, inside a merge too.
struct InteriorOwnerScope : SettingScope<const sg::Object*> {
    InteriorOwnerScope(const sg::Object*& current, const sg::Object& object)
        : SettingScope(current, current == nullptr || writes_interior(object) ? &object : current) {}

    static bool writes_interior(const sg::Object& object) {
        return object.material && object.material->has_interior && !object.inherits_material;
    }
};

class Builder {
  public:
    explicit Builder(sg::SceneGraph& graph) : m_graph(graph), m_data(std::make_unique<SceneData>()) {
        m_data->texture_factory = std::make_unique<TextureFactory>(m_data->texture_spaces);
        m_data->texture_factory->set_noise_generator(m_graph.global.noise_generator);
        m_data->texture_factory->set_inside_tests([this](const sg::Object& object) { return inside_test(object); });
    }

    // With `inside_of_first`, also POV's inside test of the graph's first
    // object (for the parser's inside()).
    std::unique_ptr<SceneData> run(InsideTest* inside_of_first = nullptr) {
        build_camera();
        // POV-Ray takes a transparent background's transmit away from its
        // colour whether or not the image has an alpha channel (measured:
        // rgbt <1,0,0,0.5> shows as rgb <0.5,0,0>).
        // Without a background statement, POV's is black and transparent.
        const double background_transmit = std::clamp(m_graph.background_transmit.value_or(0.0), 0.0, 1.0);
        m_data->background = Color(m_graph.background * (1.0 - background_transmit));
        m_data->background_transparency =
            m_graph.sky_sphere ? 0.0f : float(m_graph.background_transmit ? background_transmit : 1.0);
        build_fog();
        build_rainbows();
        if (m_graph.sky_sphere)
            m_data->sky = std::make_unique<SkySphere>(*m_graph.sky_sphere, m_data->background,
                                                      m_graph.global.language_version, *m_data->texture_factory);
        m_data->options.max_trace_level = m_graph.global.max_trace_level;
        m_data->options.adc_bailout = float(m_graph.global.adc_bailout);
        m_data->options.ambient_light = Color(m_graph.global.ambient_light);
        count_mesh_uses(m_graph.objects);
        // Room for the instances at once: a large scene's tens of thousands
        // of 768-byte entries were moved whole at every growth (abyss, 48,000
        // objects: a tenth of its build).
        const std::size_t expected_instances = object_nodes(m_graph.objects) + m_graph.lights.size();
        m_data->instances.reserve(expected_instances);
        m_data->texture_spaces.reserve(expected_instances);
        add_objects(m_graph.objects, DMat4(1.0), nullptr, DMat4(1.0), false);
        build_emitters();
        add_area_light_surfaces();
        compute_bounds();
        add_sg_lights();
        take_mesh_hit_data();
        build_atmosphere();
        if (inside_of_first && !m_graph.objects.empty()) *inside_of_first = inside_test(m_graph.objects.front());
        m_data->reads_surface_uv = m_data->texture_factory->reads_surface_uv();
        // The maker refers to this builder, which ends here.
        m_data->texture_factory->set_inside_tests(nullptr);
        return std::move(m_data);
    }

  private:
    void build_camera() {
        const sg::Camera camera = m_graph.camera.value_or(sg::Camera{});
        // The two enumerations list POV's projections in the same order.
        static_assert(int(Camera::Projection::Mesh) == int(sg::Camera::Projection::Mesh));
        const auto projection = static_cast<Camera::Projection>(static_cast<int>(camera.projection));
        m_data->camera =
            Camera(projection, Vec3(camera.location), Vec3(camera.direction), Vec3(camera.right), Vec3(camera.up));
        m_data->camera.set_angles(camera.angle, camera.horizontal_angle, camera.vertical_angle);
        Camera::FocalBlur blur;
        blur.aperture = float(camera.aperture);
        blur.focal_distance = float(camera.focal_distance);
        blur.samples = camera.blur_samples;
        blur.samples_min = camera.blur_samples_min;
        blur.confidence = float(camera.confidence);
        blur.variance = float(camera.variance);
        m_data->camera.set_focal_blur(blur);
        if (camera.bokeh && camera.focal_blur()) {
            const auto pigment = m_data->texture_factory->make_point_pigment(*camera.bokeh);
            m_data->bokeh = std::make_unique<ApertureShape>(*pigment, camera.bokeh->location);
            m_data->camera.set_bokeh(m_data->bokeh.get());
        }
        if (camera.normal) {
            m_data->normals.push_back(m_data->texture_factory->make_normal(*camera.normal));
            m_data->camera.set_normal(m_data->normals.back().get());
        }
        m_data->mesh_camera = make_mesh_camera_rays(camera);
        if (m_data->mesh_camera)
            m_data->camera.set_mesh(m_data->mesh_camera.get(), mesh_camera_rays_per_pixel(*camera.mesh));
    }

    // The objects in `objects`, with those inside groups, clips and bounds:
    // about the instances they make (one a leaf; CSG adds a root, and its
    // inner nodes make none).
    static std::size_t object_nodes(const std::vector<sg::Object>& objects) {
        std::size_t count = 0;
        for (const sg::Object& object : objects) {
            count += 1 + object_nodes(object.clipped_by) + object_nodes(object.bounded_by);
            if (const auto* group = std::get_if<sg::Group>(&object.shape)) count += object_nodes(group->children);
        }
        return count;
    }

    void count_mesh_uses(const std::vector<sg::Object>& objects) {
        for (const sg::Object& object : objects) {
            if (const auto* group = std::get_if<sg::Group>(&object.shape)) count_mesh_uses(group->children);
            if (const auto* mesh = std::get_if<sg::MeshRef>(&object.shape))
                if (*mesh) ++m_mesh_uses[mesh->get()];
        }
    }

    const Material* default_material() {
        if (!m_default_material) {
            sg::Material black;  // black pigment, default finish
            m_default_material = make_material(black);
        }
        return m_default_material;
    }

    // One material per written material and hollow flag: POV's `hollow` is
    // the object's, but what a ray inside sees (media) depends on it.
    // No material written: POV's default texture (keyed by a null pointer).
    const Material* material_for(const sg::MaterialRef& ref, bool hollow = false) {
        if (!ref && !hollow) return default_material();
        auto found = m_materials.find({ref.get(), hollow});
        if (found != m_materials.end()) return found->second;
        const Material* material = make_material(ref ? *ref : sg::Material{}, hollow);
        m_materials[{ref.get(), hollow}] = material;
        return material;
    }

    // POV's interior_texture of `ref`, with the object's interior (what
    // the rays inside see is the object's, whichever side they meet); null
    // when it has none.
    const Material* interior_material_for(const sg::MaterialRef& ref, bool hollow) {
        if (!ref || !ref->interior_texture) return nullptr;
        auto found = m_interior_materials.find({ref.get(), hollow});
        if (found != m_interior_materials.end()) return found->second;
        sg::Material inside = *ref->interior_texture;
        inside.interior = ref->interior;
        const Material* material = make_material(inside, hollow);
        m_interior_materials[{ref.get(), hollow}] = material;
        return material;
    }

    const Material* make_material(const sg::Material& written, bool hollow = false) {
        return build_material(written, hollow, material_entries(written, *written.interior, hollow, {}));
    }

    const Material* build_material(const sg::Material& written, bool hollow, const MaterialEntries* entries) {
        sg::Material source = flatten_patterned_texture(written);
        sg::NormalRef surface_normal = source.normal;
        const bool pigment_opaque = pigment_is_opaque(source.pigment);
        if (!pigment_opaque) m_data->opaque_surfaces = false;
        if (written.layers_above.empty()) {
            m_data->textures.push_back(m_data->texture_factory->make(source.pigment));
        } else {
            std::vector<std::unique_ptr<Texture>> layers;
            std::vector<TextureSample> averages;
            std::vector<sg::Finish> finishes{*source.finish};
            layers.push_back(m_data->texture_factory->make(source.pigment));
            averages.push_back(layers.back()->average());
            for (const auto& layer : written.layers_above) {
                const sg::Material flat = flatten_patterned_texture(*layer);
                if (!pigment_is_opaque(flat.pigment)) m_data->opaque_surfaces = false;
                layers.push_back(m_data->texture_factory->make(flat.pigment));
                averages.push_back(layers.back()->average());
                finishes.push_back(*flat.finish);
                if (flat.normal) surface_normal = flat.normal;  // the topmost bumps show
            }
            source.finish = blend_finishes(finishes, layer_visibility(averages));
            m_data->textures.push_back(make_layered_texture(std::move(layers)));
        }
        const NormalPerturbation* normal = nullptr;
        if (surface_normal) {
            m_data->normals.push_back(m_data->texture_factory->make_normal(*surface_normal));
            normal = m_data->normals.back().get();
            m_data->has_normal_perturbation = true;
        }
        MaterialParameters parameters = to_parameters(source, m_data->textures.back().get(), normal);
        parameters.irid_wavelengths = Color(m_graph.global.irid_wavelength);
        parameters.noise_generator = m_graph.global.noise_generator;
        // POV compares whole hundredths: 3.7 is 370.
        parameters.legacy_opacity = int(m_graph.global.language_version * 100.0 + 0.5) < 370;
        parameters.hollow = hollow;
        parameters.pigment_opaque = pigment_opaque && written.layers_above.empty();
        // POV shows an interior's media only inside a hollow object.
        if (hollow && !source.interior->media.empty()) parameters.medium = make_medium(source.interior->media);
        parameters.entries = entries;
        if (!written.layers_above.empty()) parameters.layers = material_layers(written, hollow);
        parameters.blocks_light = blocks_light(parameters, entries);
        if (parameters.ior != 1.0f) m_data->has_refraction = true;
        m_data->materials.push_back(std::make_unique<Material>(parameters));
        return m_data->materials.back().get();
    }

    // MaterialParameters::blocks_light, from what is known of the material
    // so far (its layers and entries are built before it).
    static bool blocks_light(const MaterialParameters& parameters, const MaterialEntries* entries) {
        if (parameters.layers) {
            const std::vector<const Material*>& layers = parameters.layers->top_first;
            return std::any_of(layers.begin(), layers.end(),
                               [](const Material* layer) { return layer->parameters().blocks_light; });
        }
        if (entries) return entries->every_entry_blocks_light();
        return parameters.pigment_opaque;
    }

    // A layered texture's layers, top first, each a material of its own with
    // the object's interior (lancer/shading/material_layers.h lights them).
    const MaterialLayers* material_layers(const sg::Material& written, bool hollow) {
        auto layers = std::make_unique<MaterialLayers>();
        for (auto layer = written.layers_above.rbegin(); layer != written.layers_above.rend(); ++layer) {
            sg::Material own = **layer;
            own.interior = written.interior;
            layers->top_first.push_back(make_material(own, hollow));
        }
        sg::Material bottom = written;
        bottom.layers_above.clear();
        layers->top_first.push_back(make_material(bottom, hollow));
        m_data->material_layers.push_back(std::move(layers));
        return m_data->material_layers.back().get();
    }

    // A texture_map's, a block list's or an average's entries, each a
    // material of its own (POV lights each with its own finish), with
    // pigment and normal read at the map's pattern point: `outer` holds the
    // patterns of the maps this one is an entry of, outermost first. Null
    // for other materials. Every entry takes the object's interior, as in
    // POV-Ray.
    const MaterialEntries* material_entries(const sg::Material& written, const sg::Interior& interior, bool hollow,
                                            std::vector<sg::Pattern> outer) {
        if (!written.pattern || !written.layers_above.empty()) return nullptr;
        const bool blocks = !written.block_textures.empty();
        const auto pick = written.average ? MaterialEntries::Pick::Average
                          : blocks        ? MaterialEntries::Pick::Blocks
                                          : MaterialEntries::Pick::Map;
        std::vector<sg::MaterialRef> entries;
        std::vector<float> values;
        for (const auto& entry : written.texture_map) {
            entries.push_back(entry.texture);
            values.push_back(float(entry.value));
        }
        for (const auto& block : written.block_textures) entries.push_back(block);
        if (entries.empty()) return nullptr;
        outer.push_back(*written.pattern);
        std::vector<const Material*> materials;
        for (const auto& entry : entries) materials.push_back(entry_material(*entry, interior, hollow, outer));
        if (pick == MaterialEntries::Pick::Average) {
            const std::vector<double> written_weights(values.begin(), values.end());
            const std::vector<double> shares = average_weights(written_weights);
            values.assign(shares.begin(), shares.end());
        }
        m_data->material_entries.push_back(m_data->texture_factory->make_material_entries(
            *written.pattern, int(pick), std::move(values), std::move(materials)));
        m_data->has_material_entries = true;
        return m_data->material_entries.back().get();
    }

    // One entry of a map whose patterns (outermost first) are `maps`: its
    // pigment and normal (and its layers') read where the innermost map
    // reads its entries.
    const Material* entry_material(const sg::Material& entry, const sg::Interior& interior, bool hollow,
                                   const std::vector<sg::Pattern>& maps) {
        sg::Material own = read_through_maps(flatten_patterned_texture(entry), maps);
        own.interior = interior;
        own.layers_above.clear();
        for (const auto& layer : entry.layers_above)
            own.layers_above.push_back(std::make_shared<sg::Material>(read_through_maps(*layer, maps)));
        return build_material(own, hollow, material_entries(entry, interior, hollow, maps));
    }

    // A plain texture whose pigment and normal are read at the point the
    // innermost of `maps` gives its entries (each map's transforms and warps,
    // outermost first, as POV's Warp_EPoint).
    static sg::Material read_through_maps(const sg::Material& texture, const std::vector<sg::Pattern>& maps) {
        sg::Material own;
        own.finish = texture.finish;
        own.name = texture.name;
        own.location = texture.location;
        own.pigment = texture.pigment;
        own.normal = texture.normal;
        for (auto pattern = maps.rbegin(); pattern != maps.rend(); ++pattern) {
            sg::Pigment pigment;
            pigment.kind = sg::Pigment::Kind::Average;
            pigment.pattern = *pattern;
            pigment.location = own.location;
            pigment.pigment_map.push_back({1.0, std::make_shared<sg::Pigment>(std::move(own.pigment))});
            own.pigment = std::move(pigment);
            if (own.normal) {
                auto normal = std::make_shared<sg::Normal>();
                normal->kind = sg::Normal::Kind::Average;
                normal->pattern = *pattern;
                normal->location = own.normal->location;
                normal->normal_map.push_back({1.0, own.normal});
                own.normal = normal;
            }
        }
        return own;
    }

    // Media (lancer/medium.h) from the scene graph's: densities become
    // textures, evaluated in the space the caller's region names.
    const Medium* make_medium(const std::vector<sg::Media>& written) {
        std::vector<MediumComponent> components;
        MediumSampling sampling;
        int most_intervals = 0;
        sampling.aa_threshold = kInfinity;
        for (const sg::Media& m : written) {
            MediumComponent c;
            c.emission = Color(m.emission);
            c.absorption = Color(m.absorption);
            c.scattering = Color(m.scattering);
            c.extinction = c.absorption + float(m.extinction) * c.scattering;
            c.phase = static_cast<PhaseType>(static_cast<int>(m.scattering_type));
            c.eccentricity = float(m.eccentricity);
            for (const auto& density : m.densities) {
                m_data->textures.push_back(m_data->texture_factory->make(*density));
                c.densities.push_back(m_data->textures.back().get());
                c.density_bound *= density_bound(*density);
            }
            components.push_back(c);
            // POV: the settings of the media with the most intervals, the
            // smallest aa_threshold of all.
            if (m.intervals > most_intervals) {
                most_intervals = m.intervals;
                sampling.method = m.method;
                sampling.intervals = m.intervals;
                sampling.samples_min = m.samples_min;
                sampling.samples_max = m.samples_max;
                sampling.aa_level = m.aa_level;
                sampling.jitter = float(m.jitter);
                sampling.ratio = float(m.ratio);
            }
            sampling.aa_threshold = std::min(sampling.aa_threshold, float(m.aa_threshold));
        }
        m_data->media.push_back(std::make_unique<Medium>(std::move(components), sampling));
        m_data->has_media = true;
        return m_data->media.back().get();
    }

    void build_fog() {
        std::vector<FogLayer> layers;
        for (const sg::Fog& fog : m_graph.fogs) {
            FogLayer layer;
            layer.ground = fog.type == sg::Fog::Type::Ground;
            layer.distance = float(fog.distance);
            layer.color = Color(fog.color.rgb);
            layer.filter = float(fog.color.filter);
            layer.transmit = float(fog.color.transmit);
            layer.offset = float(fog.offset);
            layer.alt = float(fog.alt);
            layer.up = Vec3(fog.up);
            layer.turbulent = fog.turbulent;
            layer.turbulence = Vec3(fog.turbulence);
            layer.turb_depth = float(fog.turb_depth);
            layer.octaves = fog.octaves;
            layer.omega = float(fog.omega);
            layer.lambda = float(fog.lambda);
            layers.push_back(layer);
        }
        if (!layers.empty())
            m_data->fog = std::make_unique<SceneFog>(std::move(layers), m_graph.global.noise_generator);
    }

    // POV's set-up (Parse_Rainbow): up squared to the antisolar direction,
    // the map starting half a width before `angle`.
    void build_rainbows() {
        std::vector<RainbowArc> arcs;
        std::vector<std::unique_ptr<PointPigment>> maps;
        for (const sg::Rainbow& rainbow : m_graph.rainbows) {
            if (!rainbow.color_map) continue;
            RainbowArc arc;
            const DVec3 antisolar = glm::normalize(rainbow.direction);
            const DVec3 right = glm::normalize(glm::cross(glm::normalize(rainbow.up), antisolar));
            arc.antisolar = Vec3(antisolar);
            arc.right = Vec3(right);
            arc.up = Vec3(glm::normalize(glm::cross(antisolar, right)));
            arc.start_angle = glm::radians(rainbow.angle - 0.5 * rainbow.width);
            arc.width = glm::radians(rainbow.width);
            arc.distance = rainbow.distance;
            arc.jitter = rainbow.jitter;
            arc.arc_angle = rainbow.arc_angle;
            arc.falloff_angle = rainbow.falloff_angle;
            sg::Pigment map;  // POV's gradient x through the map, read at (index, 0, 0)
            map.kind = sg::Pigment::Kind::Patterned;
            map.color_map = rainbow.color_map;
            map.location = rainbow.location;
            maps.push_back(m_data->texture_factory->make_point_pigment(map));
            arcs.push_back(arc);
        }
        if (!arcs.empty()) m_data->rainbows = std::make_unique<SceneRainbows>(std::move(arcs), std::move(maps));
    }

    // The scene's media, in world space: a texture space of their own, after every object's.
    void build_atmosphere() {
        if (m_graph.atmosphere.empty()) return;
        const auto space = std::uint32_t(m_data->texture_spaces.size());
        m_data->texture_spaces.push_back(DMat4(1.0));
        m_data->atmosphere = MediumRegion{make_medium(m_graph.atmosphere), space};
    }

    const MeshData* mesh_data(const sg::MeshRef& ref, const sg::SourceLocation& location) {
        auto found = m_meshes.find(ref.get());
        if (found != m_meshes.end()) return found->second;
        auto mesh = std::make_unique<MeshData>();
        mesh->source = ref;
        mesh->object_positions.reserve(3 * ref->positions.size() + 1);
        for (const sg::Vec3& p : ref->positions) {
            mesh->object_positions.push_back(float(p.x));
            mesh->object_positions.push_back(float(p.y));
            mesh->object_positions.push_back(float(p.z));
        }
        mesh->object_positions.push_back(0.0f);  // Embree reads 16 bytes per vertex
        mesh->inside_vector = ref->inside_vector;
        const int count = int(ref->positions.size());
        mesh->indices.reserve(3 * ref->faces.size());
        for (std::uint32_t f = 0; f < ref->faces.size(); ++f) {
            const auto& face = ref->faces[f];
            for (int k = 0; k < 3; ++k)
                if (face.position[k] < 0 || face.position[k] >= count)
                    throw SceneError(location, "mesh face " + std::to_string(f) + " uses vertex " +
                                                   std::to_string(face.position[k]) + " but the mesh has " +
                                                   std::to_string(count) + " vertices");
            for (int k = 0; k < 3; ++k) mesh->indices.push_back(std::uint32_t(face.position[k]));
        }
        const MeshData* result = mesh.get();
        m_data->meshes.push_back(std::move(mesh));
        m_meshes[ref.get()] = result;
        return result;
    }

    std::uint32_t push_instance(Instance instance, const DMat4& texture_owner_from_world) {
        // A group the graph does not list (a hand-built graph) is no group.
        const bool grouped = m_light_group >= 0 && std::size_t(m_light_group) < m_graph.light_groups.size() &&
                             m_light_group <= sg::kMaxLightGroups;
        instance.light_group = grouped ? std::int16_t(m_light_group) : std::int16_t(-1);
        instance.lit_by_global_lights = !grouped || m_graph.light_groups[std::size_t(m_light_group)].global_lights;
        instance.double_illuminate = m_double_illuminate.value_or(false);
        instance.no_image = m_hidden_from.image;
        instance.no_reflection = m_hidden_from.reflection;
        m_data->has_hidden_objects = m_data->has_hidden_objects || instance.no_image || instance.no_reflection;
        const auto next_interior_id = std::uint32_t(m_data->instances.size());
        instance.interior_id = m_interior_owner == nullptr
                                   ? next_interior_id
                                   : m_interior_ids.try_emplace(m_interior_owner, next_interior_id).first->second;
        m_data->instances.push_back(std::move(instance));
        m_data->texture_spaces.push_back(texture_owner_from_world);
        return std::uint32_t(m_data->instances.size() - 1);
    }

    void add_objects(const std::vector<sg::Object>& objects, const DMat4& world_from_parent,
                     const sg::MaterialRef& inherited, const DMat4& inherited_owner, bool no_shadow) {
        for (const sg::Object& object : objects)
            add_object(object, world_from_parent, inherited, inherited_owner, no_shadow);
    }

    // `union_bound`: the object's bounded_by holds a union's bound (see
    // add_bounded_union_parts).
    void add_object(const sg::Object& object, const DMat4& world_from_parent, const sg::MaterialRef& inherited,
                    const DMat4& inherited_owner, bool no_shadow, bool union_bound = false) {
        const LightGroupScope group(m_light_group, object.light_group);
        const DoubleIlluminateScope illuminated(m_double_illuminate, object.double_illuminate);
        const HiddenFromScope hidden(m_hidden_from, object);
        const InteriorOwnerScope interior(m_interior_owner, object);
        const DMat4 world_from_object = world_from_parent * object.parent_from_object;
        const sg::MaterialRef& material = object.material ? object.material : inherited;
        // POV: a texture follows the transforms applied after it, i.e. it
        // lives in the space of the object it was attached to.
        const DMat4 owner = object.material ? world_from_object : inherited_owner;
        const bool object_no_shadow = no_shadow || object.no_shadow;
        const bool plain_union = object.kind == sg::Object::Kind::Union && !object.inverse && object.clipped_by.empty();
        if (const auto* group = std::get_if<sg::Group>(&object.shape); group && plain_union) {
            if (object.bounded_by.empty())
                add_objects(group->children, world_from_object, material, owner, object_no_shadow);
            else
                add_bounded_union_parts(object, group->children, world_from_object, material, owner, object_no_shadow);
            return;
        }
        // CSG, or an object that an inversion, a clip or a bound makes one
        // (a union's bound always: see add_bounded_union_parts).
        if (std::holds_alternative<sg::Group>(object.shape) || object.inverse || !object.clipped_by.empty() ||
            bound_may_cut(object, material) || (union_bound && !object.bounded_by.empty())) {
            add_csg(object, world_from_parent, inherited, inherited_owner, no_shadow, union_bound);
            return;
        }
        Instance instance;
        if (!make_leaf(object, world_from_object, material_for(material, object.hollow), object_no_shadow, instance))
            return;
        instance.interior_material = interior_material_for(material, object.hollow);
        push_instance(std::move(instance), glm::inverse(owner));
    }

    // A union's parts under its bounded_by. POV-Ray tests a union's bound
    // before any of its parts, so it cuts them where rays miss it: a part
    // lancer cannot bound by itself (a plane, a quadric, a polynomial) or
    // one that is CSG already takes the bound as its own, which both culls
    // the rays that miss it (the sample pawns' unbounded quartics) and cuts
    // it as POV-Ray does. The other parts keep their own boxes and the BVH:
    // there the bound serves speed and rarely cuts.
    void add_bounded_union_parts(const sg::Object& group, const std::vector<sg::Object>& parts,
                                 const DMat4& world_from_group, const sg::MaterialRef& material, const DMat4& owner,
                                 bool no_shadow) {
        for (const sg::Object& part : parts) {
            const double determinant = glm::determinant(part.parent_from_object);
            if (!takes_union_bound(part) || !(determinant != 0.0) || !std::isfinite(determinant)) {
                add_object(part, world_from_group, material, owner, no_shadow);
                continue;
            }
            // The bound is written in the union's space; the part's own
            // bounded_by is in the part's.
            sg::Object own = part;
            const DMat4 part_from_group = glm::inverse(part.parent_from_object);
            for (sg::Object bound : group.bounded_by) {
                bound.parent_from_object = part_from_group * bound.parent_from_object;
                own.bounded_by.push_back(std::move(bound));
            }
            add_object(own, world_from_group, material, owner, no_shadow, /*union_bound=*/true);
        }
    }

    static bool takes_union_bound(const sg::Object& part) {
        using Kind = sg::Object::Kind;
        if (std::holds_alternative<sg::Group>(part.shape)) return true;
        switch (part.kind) {
        case Kind::Plane:
        case Kind::Quadric:
        case Kind::Poly:
        case Kind::Cubic:
        case Kind::Quartic: return true;
        default: return false;
        }
    }

    // POV's bounded_by cuts an object where rays miss the bound (csg.h):
    // traced as CSG for a shape (the quartics POV's samples bound), while
    // on a group or mesh, where it serves speed and rarely cuts, it is left
    // out so that they keep their BVH, and so it is on a glowing cheap shape,
    // which as a CSG leaf would not be a light `path` samples.
    static bool bound_may_cut(const sg::Object& object, const sg::MaterialRef& material) {
        if (object.bounded_by.empty() || std::holds_alternative<sg::Group>(object.shape) ||
            std::holds_alternative<sg::MeshRef>(object.shape))
            return false;
        const bool glows = material && material->finish->emission != sg::Vec3(0.0);
        return keeps_ray_bounds(object) || !glows;
    }

    // The objects outside CSG whose bounds POV keeps testing rays against
    // (Link_To_Frame drops the others': CSG, polynomials, text and quadrics
    // are costly to intersect).
    static bool keeps_ray_bounds(const sg::Object& object) {
        using Kind = sg::Object::Kind;
        switch (object.kind) {
        case Kind::Union:
        case Kind::Merge:
        case Kind::Intersection:
        case Kind::Difference:
        case Kind::Poly:
        case Kind::Cubic:
        case Kind::Quartic:
        case Kind::Text:
        case Kind::Quadric: return true;
        default: return false;
        }
    }

    // The Instance of a leaf object (no group); false for an empty mesh.
    bool make_leaf(const sg::Object& object, const DMat4& world_from_object, const Material* material, bool no_shadow,
                   Instance& instance) {
        instance.placement = Placement::from(world_from_object);
        instance.uv_from_world = !pov_defines_uv(object.shape);
        instance.material = material;
        instance.casts_shadow = !no_shadow;
        instance.location = object.location;
        if (const auto* sphere = std::get_if<sg::Sphere>(&object.shape)) {
            instance.kind = ShapeKind::Sphere;
            instance.sphere = {sphere->center, std::fabs(sphere->radius)};
            sphere_world_bounds(instance.placement, instance.sphere, instance.bounds_lower, instance.bounds_upper);
        } else if (const auto* box = std::get_if<sg::Box>(&object.shape)) {
            instance.kind = ShapeKind::Box;
            instance.box = {glm::min(box->corner1, box->corner2), glm::max(box->corner1, box->corner2)};
            world_bounds(instance.placement, instance.box.lower, instance.box.upper, instance.bounds_lower,
                         instance.bounds_upper);
        } else if (const auto* plane = std::get_if<sg::Plane>(&object.shape)) {
            instance.kind = ShapeKind::Plane;
            instance.bounded = false;
            const double length = glm::length(plane->normal);
            if (!(length > 0.0)) throw SceneError(object.location, "plane normal has zero length");
            instance.plane = AnalyticPlane(plane->normal / length, plane->distance);
        } else if (const auto* mesh_ref = std::get_if<sg::MeshRef>(&object.shape)) {
            if (!*mesh_ref) return false;
            instance.kind = ShapeKind::Mesh;
            const MeshData* mesh = mesh_data(*mesh_ref, object.location);
            instance.mesh = mesh;
            instance.mesh_in_world = m_mesh_uses[mesh_ref->get()] <= 1;
            add_mesh_details(instance, *mesh);
        } else {
            instance.kind = ShapeKind::Analytic;
            const auto* iso = std::get_if<sg::Isosurface>(&object.shape);
            const auto* field = std::get_if<sg::HeightField>(&object.shape);
            const auto* parametric = std::get_if<sg::Parametric>(&object.shape);
            if (iso)
                instance.shape = isosurface_shape(*iso, object.location);
            else if (parametric)
                instance.shape = parametric_shape(*parametric, object.location);
            else if (field && field->function)
                instance.shape = shared_function_height_field(*field, [&] { return function_height_field(*field); });
            else
                instance.shape = analytic_shape(object, world_from_object);
            DVec3 lower, upper;
            instance.bounded = instance.shape->bounds(lower, upper);
            if (instance.bounded)
                world_bounds(instance.placement, lower, upper, instance.bounds_lower, instance.bounds_upper);
        }
        return true;
    }

    // A mesh (or triangle) as a CSG leaf: traced through its tree's root as
    // an analytic shape, a solid only with POV's inside_vector.
    void make_mesh_leaf(const sg::Object& object, const sg::TriangleMesh& mesh, const DMat4& world_from_object,
                        const Material* material, bool no_shadow, Instance& instance) {
        instance.kind = ShapeKind::Analytic;
        instance.placement = Placement::from(world_from_object);
        instance.material = material;
        instance.casts_shadow = !no_shadow;
        instance.location = object.location;
        MeshShapeParameters parameters;
        parameters.positions.assign(mesh.positions.begin(), mesh.positions.end());
        parameters.normals.assign(mesh.normals.begin(), mesh.normals.end());
        parameters.uvs.assign(mesh.uvs.begin(), mesh.uvs.end());
        for (const sg::TriangleMesh::Face& face : mesh.faces) {
            MeshShapeParameters::Face f;
            for (int k = 0; k < 3; ++k) {
                f.position[k] = face.position[k];
                f.normal[k] = face.normal[k];
                f.uv[k] = face.uv[k];
            }
            parameters.faces.push_back(f);
        }
        // Per-triangle textures, by the face the shape reports.
        for (std::size_t f = 0; f < mesh.faces.size(); ++f) {
            const int m = mesh.faces[f].material;
            if (m < 0 || std::size_t(m) >= mesh.materials.size() || !mesh.materials[std::size_t(m)]) continue;
            instance.face_materials.resize(mesh.faces.size(), nullptr);
            instance.face_materials[f] = material_for(mesh.materials[std::size_t(m)]);
        }
        // POV-Ray reads inside_vector in world space (it never transforms it).
        if (mesh.inside_vector) parameters.inside_vector = instance.placement.vector_to_object(*mesh.inside_vector);
        instance.shape = make_mesh_shape(std::move(parameters));
        if (!instance.shape) throw SceneError(object.location, "the mesh has no triangle with an area");
        DVec3 lower, upper;
        instance.bounded = instance.shape->bounds(lower, upper);
        if (instance.bounded)
            world_bounds(instance.placement, lower, upper, instance.bounds_lower, instance.bounds_upper);
    }

    std::shared_ptr<const Shape> isosurface_shape(const sg::Isosurface& iso, const sg::SourceLocation& at) {
        IsosurfaceParameters parameters;
        parameters.function = iso.function;
        if (!iso.function) throw SceneError(at, "isosurface: it has no function");
        parameters.natives = m_data->texture_factory->function_natives(*iso.function);
        parameters.container = ContainedBy::from(iso);
        parameters.threshold = iso.threshold;
        parameters.accuracy = iso.accuracy;
        parameters.max_gradient = iso.max_gradient;
        parameters.evaluate = iso.evaluate;
        parameters.evaluate_parameters = iso.evaluate_parameters;
        parameters.open = iso.open;
        parameters.max_trace = iso.max_trace;
        // One record per isosurface written, however often it is reused
        // (copies share the function and the location).
        auto& records =
            m_isosurface_records[{iso.function.get(), iso.location.file.get(), iso.location.line, iso.location.column}];
        if (!records) {
            records = std::make_shared<IsosurfaceGradientRecord>();
            m_data->isosurfaces.push_back({parameters, records, iso.location.file ? iso.location : at});
        }
        auto shape = make_isosurface_shape(parameters, records);
        if (!shape) throw SceneError(at, "isosurface: its container or settings are not finite");
        return shape;
    }

    std::shared_ptr<const Shape> parametric_shape(const sg::Parametric& parametric, const sg::SourceLocation& at) {
        ParametricParameters parameters;
        for (std::size_t i = 0; i < 3; ++i) {
            if (!parametric.functions[i]) throw SceneError(at, "parametric: it lacks a function");
            parameters.functions[i] = parametric.functions[i];
            parameters.natives[i] = m_data->texture_factory->function_natives(*parametric.functions[i]);
        }
        parameters.uv_min = parametric.uv_min;
        parameters.uv_max = parametric.uv_max;
        parameters.container = ContainedBy::from(parametric);
        parameters.accuracy = parametric.accuracy;
        parameters.max_gradient = parametric.max_gradient;
        parameters.precompute_depth = parametric.precompute_depth;
        parameters.precompute_axes = parametric.precompute_axes;
        auto shape = make_parametric_shape(parameters);
        if (!shape) throw SceneError(at, "parametric: its container, range or settings are not finite");
        return shape;
    }

    // POV's `height_field { function W, H { … } }`: the function made into
    // a 16-bit image as POV makes it (each value clipped to 0..1 and
    // rounded; a pigment function's colour to 16-bit channels, then its
    // grey), then read as an image file would be.
    std::shared_ptr<const Shape> function_height_field(const sg::HeightField& field) {
        const int width = field.function_width, height = field.function_height;
        const auto natives = m_data->texture_factory->function_natives(*field.function, field.function_noise_generator);
        const auto encode = [](double v) {
            const float clipped = v == v ? std::clamp(float(v), 0.0f, 1.0f) : 0.0f;  // NaN: 0
            return std::uint16_t(std::floor(clipped * 65535.0f + 0.5f));
        };
        std::vector<std::uint16_t> values(std::size_t(width) * height);
        for (int row = 0; row < height; ++row) {
            for (int column = 0; column < width; ++column) {
                const double at[3] = {double(column) / (width - 1), double(row) / (height - 1), 0.0};
                std::uint16_t& value = values[std::size_t(row) * width + column];
                if (!field.function->pigment) {
                    value = encode(sg::evaluate_function(*field.function, at, 3, natives.get()));
                    continue;
                }
                // One look-up gives the three channels a call per channel
                // would (the pigment is its whole cost: agate's turbulence in
                // POV's advanced/landscape.pov).
                const std::array<double, 5> colour =
                    natives->pigment(*field.function->pigment, glm::dvec3(at[0], at[1], at[2]));
                double grey = 0.0;
                const double weights[3] = {0.297, 0.589, 0.114};
                for (int channel = 0; channel < 3; ++channel)
                    grey += weights[channel] * (encode(colour[std::size_t(channel)]) / 65535.0);
                const double scaled = grey * 65535.0;
                value = scaled >= 65535.0 ? 65535 : scaled > 0.0 ? std::uint16_t(scaled) : 0;
            }
        }
        if (auto shape =
                make_height_field_shape(grid_from_values(width, height, values), field.smooth, field.water_level))
            return shape;
        throw SceneError(field.location, "height_field: its function gives no height field");
    }

    static JuliaFractalParameters julia_parameters(const sg::JuliaFractal& julia) {
        using In = sg::JuliaFractal::Function;
        using Out = JuliaFractalParameters::Function;
        static const std::map<In, Out> functions = {
            {In::Sqr, Out::Sqr}, {In::Cube, Out::Cube}, {In::Exp, Out::Exp},   {In::Reciprocal, Out::Reciprocal},
            {In::Sin, Out::Sin}, {In::Asin, Out::Asin}, {In::Sinh, Out::Sinh}, {In::Asinh, Out::Asinh},
            {In::Cos, Out::Cos}, {In::Acos, Out::Acos}, {In::Cosh, Out::Cosh}, {In::Acosh, Out::Acosh},
            {In::Tan, Out::Tan}, {In::Atan, Out::Atan}, {In::Tanh, Out::Tanh}, {In::Atanh, Out::Atanh},
            {In::Ln, Out::Ln},   {In::Pwr, Out::Pwr}};
        JuliaFractalParameters parameters;
        parameters.julia_parameter = julia.julia;
        parameters.algebra = julia.algebra == sg::JuliaFractal::Algebra::Quaternion
                                 ? JuliaFractalParameters::Algebra::Quaternion
                                 : JuliaFractalParameters::Algebra::Hypercomplex;
        parameters.function = functions.at(julia.function);
        parameters.power = julia.power;
        parameters.max_iteration = julia.max_iteration;
        parameters.precision = julia.precision;
        parameters.slice_normal = julia.slice;
        parameters.slice_distance = julia.slice_distance;
        return parameters;
    }

    static std::shared_ptr<const Shape> analytic_shape(const sg::Object& object, const DMat4& world_from_object) {
        if (const auto* ovus = std::get_if<sg::Ovus>(&object.shape)) {
            if (auto shape = make_ovus_shape(ovus->bottom_radius, ovus->top_radius)) return shape;
            throw SceneError(object.location, "ovus: its radii must be positive");
        }
        if (const auto* sweep = std::get_if<sg::SphereSweep>(&object.shape)) {
            std::vector<glm::dvec4> spheres;
            for (const auto& sphere : sweep->spheres) spheres.emplace_back(sphere.center, sphere.radius);
            if (auto shape = make_sphere_sweep_shape(SphereSweepSpline(int(sweep->spline)), spheres, sweep->tolerance))
                return shape;
            throw SceneError(object.location, "sphere_sweep: too few spheres for its spline");
        }
        if (const auto* julia = std::get_if<sg::JuliaFractal>(&object.shape)) {
            if (auto shape = make_julia_fractal_shape(julia_parameters(*julia))) return shape;
            throw SceneError(object.location, "julia_fractal: its slice or function is not one POV-Ray accepts");
        }
        if (const auto* field = std::get_if<sg::HeightField>(&object.shape)) {
            return shared_image_height_field(*field, [field] {
                HeightFieldGrid grid;
                try {
                    grid = read_height_field_image(field->path, field->gamma > 0.0 ? field->gamma : std::nan(""));
                } catch (const std::exception& e) {
                    throw SceneError(field->location, std::string("height_field: ") + e.what());
                }
                if (auto shape = make_height_field_shape(std::move(grid), field->smooth, field->water_level))
                    return shape;
                throw SceneError(field->location, "height_field: the image '" + field->written +
                                                      "' gives no height field (it needs at least 2 x 2 pixels)");
            });
        }
        if (const auto* patch = std::get_if<sg::BicubicPatch>(&object.shape)) {
            BicubicPatchParameters parameters;
            parameters.type = patch->type;
            parameters.flatness = patch->flatness;
            parameters.u_steps = patch->u_steps;
            parameters.v_steps = patch->v_steps;
            for (int i = 0; i < 16; ++i) parameters.points[std::size_t(i)] = patch->points[i];
            for (int i = 0; i < 4; ++i) parameters.uv_corners[std::size_t(i)] = patch->uv_corners[i];
            parameters.world_from_object = world_from_object;
            if (auto shape = make_bicubic_patch_shape(parameters)) return shape;
            throw SceneError(object.location, "bicubic_patch: needs a type (0 or 1) and finite control points");
        }
        if (const auto* cone = std::get_if<sg::Cone>(&object.shape))
            return make_cone_shape(ConeParameters{cone->base, cone->cap, std::fabs(cone->base_radius),
                                                  std::fabs(cone->cap_radius), cone->open});
        if (const auto* torus = std::get_if<sg::Torus>(&object.shape))
            return make_torus_shape(std::fabs(torus->major_radius), std::fabs(torus->minor_radius));
        if (const auto* disc = std::get_if<sg::Disc>(&object.shape))
            return make_disc_shape(DiscParameters{disc->center, glm::normalize(disc->normal), std::fabs(disc->radius),
                                                  std::fabs(disc->hole_radius)});
        if (const auto* quadric = std::get_if<sg::Quadric>(&object.shape))
            return make_quadric_shape(QuadricParameters{quadric->square_terms, quadric->mixed_terms,
                                                        quadric->linear_terms, quadric->constant});
        if (const auto* blob = std::get_if<sg::Blob>(&object.shape)) {
            BlobParameters parameters;
            parameters.threshold = blob->threshold;
            for (const auto& c : blob->components) {
                BlobComponent component;
                component.kind = c.kind == sg::Blob::Component::Kind::Cylinder ? BlobComponent::Kind::Cylinder
                                                                               : BlobComponent::Kind::Sphere;
                component.center = c.center;
                component.apex = c.kind == sg::Blob::Component::Kind::Cylinder ? c.apex : c.center;
                component.radius = std::fabs(c.radius);
                component.strength = c.strength;
                component.blob_from_component = c.blob_from_component;
                if (component.radius > 0.0) parameters.components.push_back(component);
            }
            if (auto shape = make_blob_shape(std::move(parameters))) return shape;
            throw SceneError(object.location, "blob has no component with a positive radius");
        }
        if (const auto* prism = std::get_if<sg::Prism>(&object.shape)) {
            PrismParameters parameters;
            parameters.spline = SplineKind(int(prism->spline));
            for (const auto& p : prism->points) parameters.points.push_back(p);
            parameters.height1 = prism->height1;
            parameters.height2 = prism->height2;
            parameters.conic = prism->conic;
            parameters.open = prism->open;
            if (auto shape = make_prism_shape(parameters)) return shape;
            throw SceneError(object.location, "prism: too few points for its spline");
        }
        if (const auto* text = std::get_if<sg::Text>(&object.shape)) {
            std::vector<SplineSegment> segments;
            for (const auto& s : text->segments) {
                SplineSegment segment;
                if (s.line) {
                    segment.c = s.p[3] - s.p[0];
                    segment.d = s.p[0];
                } else {
                    segment.a = s.p[3] - 3.0 * s.p[2] + 3.0 * s.p[1] - s.p[0];
                    segment.b = 3.0 * s.p[2] - 6.0 * s.p[1] + 3.0 * s.p[0];
                    segment.c = 3.0 * s.p[1] - 3.0 * s.p[0];
                    segment.d = s.p[0];
                }
                segments.push_back(segment);
            }
            if (auto shape = make_text_shape(std::move(segments), text->thickness)) return shape;
            throw SceneError(object.location, "text has no glyph outlines to render (only spaces?)");
        }
        if (const auto* sor = std::get_if<sg::Sor>(&object.shape)) {
            std::vector<glm::dvec2> points(sor->points.begin(), sor->points.end());
            if (auto shape = make_sor_shape(points, sor->open)) return shape;
            throw SceneError(object.location,
                             "sor: a negative radius, or heights that do not rise (POV-Ray's \"incorrect "
                             "point in surface of revolution\")");
        }
        if (const auto* lathe = std::get_if<sg::Lathe>(&object.shape)) {
            std::vector<glm::dvec2> points(lathe->points.begin(), lathe->points.end());
            if (auto shape = make_lathe_shape(SplineKind(int(lathe->spline)), points)) return shape;
            throw SceneError(object.location, "lathe: too few points for its spline");
        }
        if (const auto* superellipsoid = std::get_if<sg::Superellipsoid>(&object.shape))
            return make_superellipsoid_shape(superellipsoid->east_west, superellipsoid->north_south);
        if (const auto* polygon = std::get_if<sg::Polygon>(&object.shape)) {
            if (auto shape = make_polygon_shape(polygon->points)) return shape;
            throw SceneError(object.location, "polygon: its points span no plane (they are all in a line)");
        }
        if (const auto* polynomial = std::get_if<sg::Polynomial>(&object.shape)) {
            if (auto shape = make_polynomial_shape(polynomial->order, polynomial->coefficients)) return shape;
            throw SceneError(object.location,
                             "poly: no renderable polynomial (every coefficient is 0, or the "
                             "order is above " +
                                 std::to_string(kMaxPolynomialShapeOrder) + ")");
        }
        throw SceneError(object.location, "lancer has no renderer for this kind of object");
    }

    // The object pattern's solid: a CSG tree of the object (in pattern
    // space) that is never traced, only asked what is inside it.
    InsideTest inside_test(const sg::Object& object) {
        auto tree = std::make_unique<CsgTree>();
        tree->root = add_csg_node(*tree, object, DMat4(1.0), nullptr, DMat4(1.0), true, false);
        tree->compute_bounds(m_data->instances);
        const CsgTree* solid = tree.get();
        m_data->csg_trees.push_back(std::move(tree));
        const SceneData* data = m_data.get();
        return [solid, data](const glm::dvec3& p) { return solid->inside(data->instances, solid->root, p); };
    }

    // A CSG object (or one an inversion or clip makes one): its leaves,
    // then the root Embree sees (csg.h).
    // `union_bound`: the object's bounded_by holds a union's bound
    // (add_bounded_union_parts), which POV keeps whatever the part's kind.
    void add_csg(const sg::Object& object, const DMat4& world_from_parent, const sg::MaterialRef& inherited,
                 const DMat4& inherited_owner, bool no_shadow, bool union_bound = false) {
        auto tree = std::make_unique<CsgTree>();
        tree->root = add_csg_node(*tree, object, world_from_parent, inherited, inherited_owner, no_shadow, false);
        // POV keeps testing rays against a part's bounds, but drops an
        // object's own for the cheap kinds (Link_To_Frame).
        tree->nodes[tree->root].rays_must_meet_bounds = union_bound || keeps_ray_bounds(object);
        tree->compute_bounds(m_data->instances);
        const CsgNode& root = tree->nodes[tree->root];
        Instance instance;
        instance.kind = ShapeKind::Csg;
        instance.csg = tree.get();
        instance.material = default_material();
        instance.casts_shadow = !(no_shadow || object.no_shadow);
        instance.location = object.location;
        instance.bounded = root.bounded;
        instance.pov_unbounded = root.bounded && !root.pov_bounded;
        if (root.bounded) {
            instance.bounds_lower = Vec3(root.lower);
            instance.bounds_upper = Vec3(root.upper);
        }
        m_data->csg_trees.push_back(std::move(tree));
        push_instance(std::move(instance), DMat4(1.0));
    }

    std::uint32_t add_csg_node(CsgTree& tree, const sg::Object& object, const DMat4& world_from_parent,
                               const sg::MaterialRef& inherited, const DMat4& inherited_owner, bool no_shadow,
                               bool inverted) {
        const DoubleIlluminateScope illuminated(m_double_illuminate, object.double_illuminate);
        const HiddenFromScope hidden(m_hidden_from, object);
        const InteriorOwnerScope interior(m_interior_owner, object);
        const DMat4 world_from_object = world_from_parent * object.parent_from_object;
        const sg::MaterialRef& material = object.material ? object.material : inherited;
        const DMat4 owner = object.material ? world_from_object : inherited_owner;
        const bool object_no_shadow = no_shadow || object.no_shadow;
        const bool inverse = inverted != object.inverse;
        CsgNode node;
        using Kind = sg::Object::Kind;
        if (const auto* group = std::get_if<sg::Group>(&object.shape)) {
            // Inversions go down to the leaves (De Morgan, as POV's Invert).
            switch (object.kind) {
            case Kind::Union:
                node.operation = inverse ? CsgNode::Operation::Intersection : CsgNode::Operation::Union;
                break;
            case Kind::Merge:
                node.operation = inverse ? CsgNode::Operation::Intersection : CsgNode::Operation::Merge;
                break;
            default: node.operation = inverse ? CsgNode::Operation::Merge : CsgNode::Operation::Intersection; break;
            }
            for (std::size_t k = 0; k < group->children.size(); ++k) {
                // A difference is its first child intersected with the inverse of the others.
                const bool subtracted = object.kind == Kind::Difference && k > 0;
                node.children.push_back(add_csg_node(tree, group->children[k], world_from_object, material, owner,
                                                     object_no_shadow, inverse != subtracted));
            }
        } else {
            Instance instance;
            if (const auto* mesh = std::get_if<sg::MeshRef>(&object.shape)) {
                if (!*mesh) throw SceneError(object.location, "a mesh in CSG has no triangles");
                make_mesh_leaf(object, **mesh, world_from_object, material_for(material, object.hollow),
                               object_no_shadow, instance);
            } else {
                make_leaf(object, world_from_object, material_for(material, object.hollow), object_no_shadow, instance);
            }
            instance.interior_material = interior_material_for(material, object.hollow);
            if (!instance.shape) {
                switch (instance.kind) {
                case ShapeKind::Sphere: instance.shape = make_sphere_shape(instance.sphere); break;
                case ShapeKind::Box: instance.shape = make_box_shape(instance.box); break;
                default: instance.shape = make_plane_shape(instance.plane); break;
                }
            }
            instance.csg_leaf = true;
            instance.flip_normal = inverse;
            node.operation = CsgNode::Operation::Leaf;
            node.inverted = inverse;
            node.instance = push_instance(std::move(instance), glm::inverse(owner));
        }
        for (const sg::Object& clip : object.clipped_by)
            node.clips.push_back(add_csg_node(tree, clip, world_from_object, material, owner, object_no_shadow, false));
        for (const sg::Object& bound : object.bounded_by)
            node.bounds.push_back(
                add_csg_node(tree, bound, world_from_object, material, owner, object_no_shadow, false));
        node.rays_must_meet_bounds = true;
        tree.nodes.push_back(std::move(node));
        return std::uint32_t(tree.nodes.size() - 1);
    }

    void add_mesh_details(Instance& instance, const MeshData& mesh) {
        const sg::TriangleMesh& source = *mesh.source;
        DVec3 lo(INFINITY), hi(-INFINITY);
        if (instance.mesh_in_world) instance.world_positions.reserve(3 * source.positions.size() + 1);
        for (const sg::Vec3& p : source.positions) {
            const DVec3 w = instance.placement.point_to_world(p);
            lo = glm::min(lo, w);
            hi = glm::max(hi, w);
            if (instance.mesh_in_world) {
                instance.world_positions.push_back(float(w.x));
                instance.world_positions.push_back(float(w.y));
                instance.world_positions.push_back(float(w.z));
            }
        }
        if (instance.mesh_in_world) instance.world_positions.push_back(0.0f);
        if (source.positions.empty()) lo = hi = DVec3(0.0);
        instance.bounds_lower = Vec3(lo);
        instance.bounds_upper = Vec3(hi);
        bool any_face_material = false;
        for (const auto& face : source.faces)
            any_face_material |= face.material >= 0 && std::size_t(face.material) < source.materials.size();
        if (any_face_material) {
            instance.face_materials.resize(source.faces.size(), nullptr);
            for (std::size_t f = 0; f < source.faces.size(); ++f) {
                const int m = source.faces[f].material;
                if (m >= 0 && std::size_t(m) < source.materials.size() && source.materials[m])
                    instance.face_materials[f] = material_for(source.materials[m]);
            }
        }
    }

    // Every object whose material (or a face's) emits becomes a light.
    void build_emitters() {
        const std::size_t count = m_data->instances.size();
        for (std::uint32_t index = 0; index < count; ++index) {
            Instance& instance = m_data->instances[index];
            if (instance.csg_leaf) continue;  // only part of its surface is there
            std::unique_ptr<SurfaceSampler> surface;
            const EmissiveShapeLight::SphereShape* sphere_shape = nullptr;
            EmissiveShapeLight::SphereShape shape;
            switch (instance.kind) {
            case ShapeKind::Sphere:
                if (!instance.material->is_emissive()) continue;
                if (!(instance.sphere.radius > 0.0)) continue;
                surface = make_sphere_sampler(instance.sphere, instance.placement, instance.material);
                if (instance.placement.is_similarity()) {
                    shape.object = instance.sphere;
                    shape.placement = instance.placement;
                    shape.world.center = instance.placement.point_to_world(instance.sphere.center);
                    shape.world.radius = instance.sphere.radius * instance.placement.uniform_scale();
                    sphere_shape = &shape;
                }
                break;
            case ShapeKind::Box:
                if (!instance.material->is_emissive()) continue;
                surface = make_box_sampler(instance.box, instance.placement, instance.material);
                break;
            case ShapeKind::Plane:
                if (instance.material->is_emissive())
                    std::cerr << "lancer: note: an emissive plane is infinite and cannot be sampled as a "
                                 "light; it still shows its emission to rays that hit it\n";
                continue;
            case ShapeKind::Mesh: {
                std::vector<WorldTriangle> triangles = emissive_triangles(instance);
                if (triangles.empty()) continue;
                surface = make_triangle_sampler(std::move(triangles));
                break;
            }
            default: continue;
            }
            if (!(surface->area() > 0.0) || !std::isfinite(surface->area())) continue;
            auto light =
                std::make_unique<EmissiveShapeLight>(std::move(surface), index, instance.material, sphere_shape);
            instance.emitter = light.get();
            m_data->lights.push_back(light.get());
            m_data->local_lights.push_back(&light->proxy());
            m_data->owned_lights.push_back(std::move(light));
        }
    }

    std::vector<WorldTriangle> emissive_triangles(const Instance& instance) {
        std::vector<WorldTriangle> triangles;
        const sg::TriangleMesh& source = *instance.mesh->source;
        for (std::size_t f = 0; f < source.faces.size(); ++f) {
            const Material* face_material = f < instance.face_materials.size() && instance.face_materials[f]
                                                ? instance.face_materials[f]
                                                : instance.material;
            if (!face_material->is_emissive()) continue;
            const auto& face = source.faces[f];
            WorldTriangle t;
            for (int k = 0; k < 3; ++k) {
                t.p[k] = instance.placement.point_to_world(source.positions[face.position[k]]);
                const int uv = face.uv[k];
                t.uv[k] = uv >= 0 && std::size_t(uv) < source.uvs.size() ? Vec2(source.uvs[uv]) : Vec2(k == 1, k == 2);
            }
            t.material = face_material;
            triangles.push_back(t);
        }
        return triangles;
    }

    // Area lights as black, non-reflecting emitting surfaces (after the
    // scene's objects so their ids do not shift).
    void add_area_light_surfaces() {
        for (const sg::Light& source : m_graph.lights) {
            if (source.kind == sg::Light::Kind::AreaRectangle) {
                const DVec3 cross = glm::cross(source.axis1, source.axis2);
                const double area = glm::length(cross);
                if (!(area > 0.0) || !std::isfinite(area)) continue;  // a point light, added later
                AnalyticRectangle rectangle{source.position, source.axis1, source.axis2};
                auto light = std::make_unique<RectangleLight>(rectangle, Color(source.color));
                Instance instance;
                instance.kind = ShapeKind::Rectangle;
                instance.rectangle = rectangle;
                instance.material = emitting_material(light->radiance());
                instance.light = light.get();
                instance.location = source.location;
                const DVec3 half = 0.5 * (glm::abs(source.axis1) + glm::abs(source.axis2));
                world_bounds(instance.placement, source.position - half, source.position + half, instance.bounds_lower,
                             instance.bounds_upper);
                push_instance(std::move(instance), DMat4(1.0));
                add_light(std::move(light));
            } else if (source.kind == sg::Light::Kind::AreaSphere) {
                if (!(source.radius > 0.0) || !std::isfinite(source.radius)) continue;
                auto light = std::make_unique<SphereLight>(source.position, source.radius, Color(source.color));
                Instance instance;
                instance.kind = ShapeKind::Sphere;
                instance.sphere = {source.position, source.radius};
                instance.material = emitting_material(light->radiance());
                instance.light = light.get();
                instance.location = source.location;
                const DVec3 r(source.radius);
                world_bounds(instance.placement, source.position - r, source.position + r, instance.bounds_lower,
                             instance.bounds_upper);
                push_instance(std::move(instance), DMat4(1.0));
                add_light(std::move(light));
            }
        }
    }

    const Material* emitting_material(const Color& radiance) {
        m_data->textures.push_back(TextureFactory::make_solid(Color(1.0f)));
        MaterialParameters p;
        p.pigment = m_data->textures.back().get();
        p.ambient = Color(0.0f);
        p.diffuse = 0.0f;
        p.emission = radiance;
        m_data->materials.push_back(std::make_unique<Material>(p));
        return m_data->materials.back().get();
    }

    void add_light(std::unique_ptr<Light> light, bool casts_shadows = true,
                   const std::shared_ptr<const sg::Object>& projected_through = nullptr,
                   const sg::Light* source = nullptr) {
        light->set_casts_shadows(casts_shadows);
        if (projected_through) {
            sg::SceneGraph projector;
            projector.objects.push_back(*projected_through);
            light = std::make_unique<ProjectedLight>(std::move(light), compile_scene(std::move(projector)));
        }
        if (source) {
            light->set_media_interaction(source->media_interaction, source->media_attenuation);
            light->set_light_group(source->light_group);
        }
        m_data->lights.push_back(light.get());
        m_data->local_lights.push_back(&light->proxy());
        m_data->owned_lights.push_back(std::move(light));
    }

    void compute_bounds() {
        for (const Instance& instance : m_data->instances)
            if (instance.bounded && !instance.csg_leaf && !instance.pov_unbounded)
                expand(m_data->bounds, instance.bounds_lower, instance.bounds_upper);
    }

    // POV's point, spot, area and parallel lights, and physical lamps too
    // small to have a surface (degraded to point lights of the same
    // intensity pi*C).
    void add_sg_lights() {
        const Bounds& b = m_data->bounds;
        const float radius = b.empty() ? 1.0f : glm::max(0.5f * glm::length(b.upper - b.lower), 1e-30f);
        for (const sg::Light& source : m_graph.lights) {
            const Color color(source.color);
            const bool directional = source.kind == sg::Light::Kind::Directional ||
                                     (source.kind == sg::Light::Kind::Point && source.parallel);
            if (directional) {
                DirectionalLightParameters light;
                light.to_light = Vec3(source.position - source.point_at);
                light.irradiance = float(kPiD) * color;
                light.position = Vec3(source.position);
                light.fade_distance = float(source.fade_distance);
                light.fade_power = float(source.fade_power);
                if (source.cylinder) {
                    light.beam_radius = float(source.spot_radius);
                    light.beam_falloff = float(source.spot_falloff);
                    light.tightness = float(source.tightness);
                }
                add_light(std::make_unique<DirectionalLight>(light, radius), !source.shadowless,
                          source.projected_through, &source);
                continue;
            }
            const bool degenerate_rectangle = source.kind == sg::Light::Kind::AreaRectangle &&
                                              !(glm::length(glm::cross(source.axis1, source.axis2)) > 0.0);
            const bool degenerate_sphere = source.kind == sg::Light::Kind::AreaSphere && !(source.radius > 0.0);
            if (source.kind == sg::Light::Kind::Point) {
                // POV-Ray's point light: no falloff unless it fades; an
                // area_light lights the same way from its centre.
                PointLightParameters light;
                light.position = Vec3(source.position);
                light.intensity = float(kPiD) * color;
                light.falloff = PointFalloff::None;
                light.fade_distance = float(source.fade_distance);
                light.fade_power = float(source.fade_power);
                if (source.spotlight) {
                    light.spot_axis = Vec3(glm::normalize(source.point_at - source.position));
                    light.spot_cos_radius = float(std::cos(glm::radians(source.spot_radius)));
                    light.spot_cos_falloff = float(std::cos(glm::radians(source.spot_falloff)));
                    light.tightness = float(source.tightness);
                }
                if (source.area_light) {
                    PovAreaLightParameters area;
                    area.center = light;
                    area.axis1 = Vec3(source.axis1);
                    area.axis2 = Vec3(source.axis2);
                    area.size1 = source.samples1;
                    area.size2 = source.samples2;
                    area.adaptive = source.adaptive;
                    area.jitter = source.jitter;
                    area.circular = source.circular;
                    area.orient = source.orient;
                    area.area_illumination = source.area_illumination;
                    add_light(std::make_unique<PovAreaLight>(area, radius), !source.shadowless,
                              source.projected_through, &source);
                } else {
                    add_light(std::make_unique<PointLight>(light, radius), !source.shadowless, source.projected_through,
                              &source);
                }
            } else if (degenerate_rectangle || degenerate_sphere) {
                // A physical lamp without size: the physical point it shrank to.
                add_light(std::make_unique<PointLight>(
                    PointLightParameters{.position = Vec3(source.position), .intensity = float(kPiD) * color}));
            }
        }
    }

    // Moves what hits read out of each mesh when the graph being consumed
    // holds every reference to it (always, for a parsed scene); a mesh the
    // caller shares elsewhere is copied, so the caller's copy stays whole.
    void take_mesh_hit_data() {
        for (const std::unique_ptr<MeshData>& mesh : m_data->meshes) {
            const long held_by_graph = m_mesh_uses[mesh->source.get()];
            const bool graph_alone = mesh->source.use_count() == held_by_graph + 1;  // + MeshData's own
            // The graph is ours to consume (build_scene_data's contract).
            auto& source = const_cast<sg::TriangleMesh&>(*mesh->source);
            if (graph_alone) {
                mesh->normals = std::move(source.normals);
                mesh->uvs = std::move(source.uvs);
                mesh->faces = std::move(source.faces);
            } else {
                mesh->normals = source.normals;
                mesh->uvs = source.uvs;
                mesh->faces = source.faces;
            }
            mesh->source.reset();
        }
    }

    sg::SceneGraph& m_graph;
    std::unique_ptr<SceneData> m_data;
    int m_light_group = -1;                        // the light_group of the objects being added (LightGroupScope)
    std::optional<bool> m_double_illuminate;       // of the objects being added (DoubleIlluminateScope)
    HiddenFrom m_hidden_from;                      // of the objects being added (HiddenFromScope)
    const sg::Object* m_interior_owner = nullptr;  // of the objects being added (InteriorOwnerScope)
    std::map<const sg::Object*, std::uint32_t> m_interior_ids;  // by owner; an instance with none gets its own
    std::map<const sg::TriangleMesh*, int> m_mesh_uses;
    std::map<std::tuple<const sg::Function*, const std::string*, int, int>, std::shared_ptr<IsosurfaceGradientRecord>>
        m_isosurface_records;
    std::map<const sg::TriangleMesh*, const MeshData*> m_meshes;
    std::map<std::pair<const sg::Material*, bool>, const Material*> m_materials;
    std::map<std::pair<const sg::Material*, bool>, const Material*> m_interior_materials;
    const Material* m_default_material = nullptr;
};

}  // namespace

std::unique_ptr<SceneData> build_scene_data(sg::SceneGraph& graph) {
    return Builder(graph).run();
}

std::unique_ptr<SceneData> build_object_scene_data(const sg::Object& object, const sg::GlobalSettings& settings,
                                                   InsideTest& inside) {
    sg::SceneGraph graph;
    graph.global = settings;
    graph.objects.push_back(object);
    Builder builder(graph);
    return builder.run(&inside);
}

}  // namespace lancer
