// Objects and materials: primitives, unions, modifiers, textures.
//
// Transforms: every object keeps its geometry in its own space and
// parent_from_object maps it into its parent's (union's or world's) space.
// A transform modifier left-multiplies parent_from_object, so `scale 2
// translate x` scales first. A texture is attached in the space it was
// written in; its pattern transform is then re-expressed in object space
// (pattern_from_object = pattern_from_parent * parent_from_object) so the
// pattern follows later transforms of the object, as in POV-Ray.
#include <cmath>
#include <filesystem>

#include <glm/gtc/matrix_transform.hpp>

#include "evaluator.h"

namespace lancer::parse {

namespace {

using MaterialPtr = std::shared_ptr<const sg::Material>;

// Re-expresses a material given in the parent's space in a child's space.
MaterialPtr in_child_space(const MaterialPtr& material, const sg::Mat4& parent_from_child) {
    if (material->pigment.kind == sg::Pigment::Kind::Solid && !material->normal &&
        !has_media_densities(*material->interior) && !material->interior_texture)
        return material;  // nothing to move
    auto moved = std::make_shared<sg::Material>(*material);
    move_patterns(*moved, parent_from_child);
    return moved;
}

// POV-Ray promotes a group's interior_texture to every descendant without
// one, a texture of its own or not (Post_Process); `inside` is in the
// object's space.
void give_interior_texture(sg::Object& object, const MaterialPtr& inside) {
    if (object.material && object.material->interior_texture) return;
    if (object.material && !object.inherits_material) {
        auto with = std::make_shared<sg::Material>(*object.material);
        with->interior_texture = inside;
        object.material = with;
    }
    if (auto* group = std::get_if<sg::Group>(&object.shape))
        for (auto& child : group->children)
            give_interior_texture(child, in_child_space(inside, child.parent_from_object));
}

// POV-Ray promotes a group's interior to every descendant that has a
// texture, its own or a nested group's, but no interior written for it
// (Post_Process copies the interior to children without one); `outer`
// holds the interior, in the object's space.
void give_interior(sg::Object& object, const MaterialPtr& outer) {
    if (object.material && object.material->has_interior && !object.inherits_material) return;
    if (object.material) {
        auto with = std::make_shared<sg::Material>(*object.material);
        with->interior = outer->interior;
        object.material = with;
    }
    if (auto* group = std::get_if<sg::Group>(&object.shape))
        for (auto& child : group->children) give_interior(child, in_child_space(outer, child.parent_from_object));
}

// POV: a texture on a union reaches every descendant that has none of its
// own; a later pigment or finish on the union reaches them again.
void give_material(sg::Object& object, const MaterialPtr& material, bool inherited = false) {
    object.material = material;
    object.inherits_material = inherited;
    if (auto* group = std::get_if<sg::Group>(&object.shape)) {
        for (auto& child : group->children) {
            if (!child.material || child.inherits_material) {
                give_material(child, in_child_space(material, child.parent_from_object), true);
                continue;
            }
            if (material->has_interior) give_interior(child, in_child_space(material, child.parent_from_object));
            if (material->interior_texture)
                give_interior_texture(child, in_child_space(material->interior_texture, child.parent_from_object));
        }
    }
}

// An OBJ's MTL materials give way to a texture written on the object.
void drop_face_materials(sg::Object& object) {
    auto* mesh = std::get_if<sg::MeshRef>(&object.shape);
    if (object.kind != sg::Object::Kind::ObjMesh || !mesh || !*mesh || (*mesh)->materials.empty()) return;
    auto plain = std::make_shared<sg::TriangleMesh>(**mesh);
    plain->materials.clear();
    for (auto& face : plain->faces) face.material = -1;
    *mesh = plain;
}

// Attaches a material written in the space parent_from_object maps into.
// A texture's uv_mapping reaches its pigment, normal, image and pattern.
void map_by_uv(sg::Material& material) {
    if (material.interior_texture) {
        auto inside = std::make_shared<sg::Material>(*material.interior_texture);
        map_by_uv(*inside);
        material.interior_texture = inside;
    }
    material.uv_mapping = true;
    if (material.pattern) material.pattern->uv_mapping = true;
    pigment_pattern_of(material.pigment).uv_mapping = true;
    material.pigment.image->map_type = sg::MapType::UV;
    if (material.normal) {
        auto normal = std::make_shared<sg::Normal>(*material.normal);
        normal->pattern->uv_mapping = true;
        material.normal = normal;
    }
}

void attach_in_parent_space(ShapeValue& shape, const sg::Material& material) {
    auto in_object = std::make_shared<sg::Material>(material);
    if (shape.uv_mapping) map_by_uv(*in_object);
    move_patterns(*in_object, shape.object.parent_from_object);
    drop_face_materials(shape.object);
    give_material(shape.object, in_object);
}

// The material an object-level pigment/finish/interior modifies, expressed
// in the parent's space (POV starts from the default texture).
sg::Material current_in_parent_space(const ShapeValue& shape, const sg::Material& fallback) {
    if (!shape.object.material) return fallback;
    sg::Material material = *shape.object.material;
    move_patterns(material, glm::inverse(shape.object.parent_from_object));
    return material;
}

// A pigment, normal or finish written on an object without a texture makes
// its texture (POV's copy of the default texture), which a texture written
// after it then lies on top of; an interior alone makes none.
void written_at(sg::Material& material, const sg::SourceLocation& at) {
    if (material.location.line == 0) material.location = at;
}

void apply_default_material(sg::Object& object, const MaterialPtr& fallback) {
    if (!object.material) {
        give_material(object, fallback, true);
        return;
    }
    if (auto* group = std::get_if<sg::Group>(&object.shape)) {
        for (auto& child : group->children)
            apply_default_material(child, in_child_space(fallback, child.parent_from_object));
    }
}

}  // namespace

void transform_light(sg::Light& light, const sg::Mat4& m) {
    if (light.looks_like) {
        auto moved = std::make_shared<sg::Object>(*light.looks_like);
        moved->parent_from_object = m * moved->parent_from_object;
        light.looks_like = std::move(moved);
    }
    if (light.projected_through) {
        auto moved = std::make_shared<sg::Object>(*light.projected_through);
        moved->parent_from_object = m * moved->parent_from_object;
        light.projected_through = std::move(moved);
    }
    light.position = sg::Vec3(m * glm::dvec4(light.position, 1.0));
    light.point_at = sg::Vec3(m * glm::dvec4(light.point_at, 1.0));
    light.axis1 = sg::Vec3(m * glm::dvec4(light.axis1, 0.0));
    light.axis2 = sg::Vec3(m * glm::dvec4(light.axis2, 0.0));
    light.radius *= std::cbrt(std::fabs(glm::determinant(glm::dmat3(m))));
}

// ------------------------------------------------------------ primitives

ShapePtr Evaluator::make_sphere(const Value& c, const SourceRange& wc, const Value& r, const SourceRange& wr,
                                const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = sg::Object::Kind::Sphere;
    shape->object.location = at;
    sg::Sphere sphere;
    sphere.center = to_vec3(c, wc);
    sphere.radius = to_float(r, wr, "a float radius");
    if (!check_renderable(&sphere.radius, 1, wr, "the sphere radius")) sphere.radius = 1.0;
    if (sphere.radius <= 0.0 && r.kind == Value::Kind::Float)
        error(wr.begin, "sphere radius must be positive, got " + std::to_string(sphere.radius));
    shape->object.shape = sphere;
    return shape;
}

ShapePtr Evaluator::make_plane(const Value& n, const SourceRange& wn, const Value& d, const SourceRange& wd,
                               const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = sg::Object::Kind::Plane;
    shape->object.location = at;
    sg::Vec3 normal = nonzero_vec3(n, wn, "the plane normal");
    double length = glm::length(normal);
    // plane { N, D } is the set N.p = D; stored with a unit normal.
    shape->object.shape = sg::Plane{normal / length, to_float(d, wd, "a float distance") / length};
    return shape;
}

ShapePtr Evaluator::make_box(const Value& a, const SourceRange& wa, const Value& b, const SourceRange& wb,
                             const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = sg::Object::Kind::Box;
    shape->object.location = at;
    sg::Vec3 p = to_vec3(a, wa), q = to_vec3(b, wb);
    if (p.x == q.x || p.y == q.y || p.z == q.z) warning(at, "box has zero thickness along an axis");
    shape->object.shape = sg::Box{glm::min(p, q), glm::max(p, q)};
    return shape;
}

ShapePtr Evaluator::make_union(const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = sg::Object::Kind::Union;
    shape->object.location = at;
    shape->object.shape = sg::Group{};
    return shape;
}

// POV's light_group: a union whose lights light only its objects. Lights
// and objects of a light_group inside it keep their own group.
ShapePtr Evaluator::make_light_group(const Edits<ShapeValue>& edits, const sg::SourceLocation& at) {
    ShapePtr shape = make_union(at);
    apply(shape, edits);
    // Hits carry the group in 16 bits (lancer/hit.h).
    if (m_scene.light_groups.size() >= std::size_t(sg::kMaxLightGroups)) {
        error(at, "more than " + std::to_string(sg::kMaxLightGroups) + " light_groups in one scene");
        return shape;
    }
    const int group = int(m_scene.light_groups.size());
    m_scene.light_groups.push_back(sg::LightGroup{shape->global_lights});
    shape->object.light_group = group;
    for (sg::Light& light : shape->lights)
        if (light.light_group < 0) light.light_group = group;
    return shape;
}

void Evaluator::apply(ShapePtr& shape, const Edits<ShapeValue>& edits) {
    for (const auto& edit : edits) edit(*shape);
}

Value Evaluator::object_value(const ShapePtr& shape) {
    Value value;
    value.kind = Value::Kind::Object;
    value.payload = shape;
    return value;
}

// ------------------------------------------------------------- modifiers

std::function<void(ShapeValue&)> Evaluator::transform_edit(const sg::Mat4& transform) {
    return [transform](ShapeValue& s) { s.object.parent_from_object = transform * s.object.parent_from_object; };
}

std::function<void(ShapeValue&)> Evaluator::object_uv_mapping(const sg::SourceLocation& at) {
    return [this, at](ShapeValue& s) {
        if (s.object.material && !s.object.inherits_material) {
            error(at, "uv_mapping must come before the object's texture (POV-Ray requires it there)");
            return;
        }
        s.uv_mapping = true;
    };
}

std::function<void(ShapeValue&)> Evaluator::texture_edit(std::shared_ptr<sg::Material> texture) {
    return [this, texture](ShapeValue& s) {
        // A second texture on the same object lies on top of the first
        // (POV's layered texture).
        if (s.object.material && !s.object.inherits_material && s.object.material->location.line > 0) {
            auto below = std::make_shared<sg::Material>(current_in_parent_space(s, sg::Material{}));
            attach_in_parent_space(s, *layer_texture(below, std::make_shared<sg::Material>(*texture)));
            return;
        }
        sg::Material material = *texture;
        if (s.object.material) {
            material.interior = s.object.material->interior;  // a texture has no interior
            material.has_interior = s.object.material->has_interior;
            if (s.object.material->interior_texture)  // nor an interior_texture
                material.interior_texture = current_in_parent_space(s, sg::Material{}).interior_texture;
        }
        attach_in_parent_space(s, material);
    };
}

std::function<void(ShapeValue&)> Evaluator::interior_texture_edit(std::shared_ptr<sg::Material> texture) {
    return [texture, fallback = default_texture()](ShapeValue& s) {
        sg::Material material = current_in_parent_space(s, fallback);
        material.interior_texture = texture;
        attach_in_parent_space(s, material);
    };
}

std::function<void(ShapeValue&)> Evaluator::material_edit(std::shared_ptr<sg::Material> material) {
    return [material](ShapeValue& s) { attach_in_parent_space(s, *material); };
}

// POV-Ray lays a pigment, normal or finish written on an object with a
// texture over that texture as a layer of its own, which a patterned
// texture does not take.
bool Evaluator::refuse_layer_over_pattern(const ShapeValue& s, const sg::SourceLocation& at) {
    if (!s.object.material || s.object.inherits_material || !top_layer_is_patterned(*s.object.material)) return false;
    error(at,
          "cannot layer over a patterned texture (POV-Ray refuses it too): a pigment, normal or finish on an "
          "object whose texture is patterned; put it in the texture's entries");
    return true;
}

std::function<void(ShapeValue&)> Evaluator::pigment_edit(const Edits<sg::Pigment>& edits,
                                                         const sg::SourceLocation& at) {
    return [this, at, change = material_pigment_edit(edits, at), fallback = default_texture()](ShapeValue& s) {
        if (refuse_layer_over_pattern(s, at)) return;
        sg::Material material = current_in_parent_space(s, fallback);
        change(material);
        written_at(material, at);
        attach_in_parent_space(s, material);
    };
}

std::function<void(ShapeValue&)> Evaluator::finish_edit(const Edits<sg::Finish>& edits, const sg::SourceLocation& at) {
    return [this, at, change = material_finish_edit(edits, at), fallback = default_texture()](ShapeValue& s) {
        if (refuse_layer_over_pattern(s, at)) return;
        sg::Material material = current_in_parent_space(s, fallback);
        change(material);
        written_at(material, at);
        attach_in_parent_space(s, material);
    };
}

std::function<void(ShapeValue&)> Evaluator::normal_edit(const Edits<sg::Normal>& edits, const sg::SourceLocation& at) {
    return [this, at, change = material_normal_edit(edits, at), fallback = default_texture()](ShapeValue& s) {
        if (refuse_layer_over_pattern(s, at)) return;
        sg::Material material = current_in_parent_space(s, fallback);
        change(material);
        written_at(material, at);
        attach_in_parent_space(s, material);
    };
}

std::function<void(ShapeValue&)> Evaluator::interior_edit(std::shared_ptr<sg::Interior> interior) {
    return [interior, fallback = default_texture()](ShapeValue& s) {
        sg::Material material = current_in_parent_space(s, fallback);
        material.interior = *interior;
        material.has_interior = true;
        attach_in_parent_space(s, material);
    };
}

std::function<void(ShapeValue&)> Evaluator::child_edit(ShapePtr child) {
    return [child](ShapeValue& s) {
        sg::Object object = child->object;
        for (sg::Light light : child->lights) {
            transform_light(light, object.parent_from_object);
            s.lights.push_back(light);
        }
        if (!object.material && s.object.material) {
            give_material(object, in_child_space(s.object.material, object.parent_from_object), true);
        } else if (s.object.material && s.object.material->has_interior) {
            give_interior(object, in_child_space(s.object.material, object.parent_from_object));
        }
        std::get<sg::Group>(s.object.shape).children.push_back(std::move(object));
    };
}

// ------------------------------------------------------------ transforms

sg::Mat4 Evaluator::translation(const Value& v, const SourceRange& where) {
    return glm::translate(sg::Mat4(1.0), to_vec3(v, where));
}

// Degrees about x, then y, then z (POV-Ray's order and sense).
sg::Mat4 Evaluator::rotation(const Value& v, const SourceRange& where) {
    sg::Vec3 degrees = to_vec3(v, where);
    sg::Mat4 m = glm::rotate(sg::Mat4(1.0), glm::radians(degrees.x), sg::Vec3(1, 0, 0));
    m = glm::rotate(sg::Mat4(1.0), glm::radians(degrees.y), sg::Vec3(0, 1, 0)) * m;
    return glm::rotate(sg::Mat4(1.0), glm::radians(degrees.z), sg::Vec3(0, 0, 1)) * m;
}

sg::Mat4 Evaluator::scaling(const Value& v, const SourceRange& where) {
    sg::Vec3 s = to_vec3(v, where);
    for (int i = 0; i < 3; ++i) {
        if (s[i] == 0.0) {
            warning(where.begin, "scale by 0 along an axis; using 1 there (as POV-Ray does)");
            s[i] = 1.0;
        }
    }
    return glm::scale(sg::Mat4(1.0), s);
}

// matrix <m00, m01, m02, m10, ..., m32>: POV's rows act on row vectors,
// so row j of POV's matrix is column j of GLM's.
sg::Mat4 Evaluator::matrix(const std::vector<Value>& items, const SourceRange& where) {
    if (items.size() != 12) {
        error(where.begin, "matrix needs 12 values, got " + std::to_string(items.size()));
        return sg::Mat4(1.0);
    }
    sg::Mat4 m(1.0);
    for (int row = 0; row < 4; ++row)
        for (int col = 0; col < 3; ++col) m[row][col] = to_float(items[row * 3 + col], where, "a float matrix entry");
    if (glm::determinant(m) == 0.0) {
        error(where.begin, "matrix is singular (determinant 0)");
        return sg::Mat4(1.0);
    }
    return m;
}

sg::Mat4 Evaluator::inverse(const sg::Mat4& m, const SourceRange& where) {
    if (glm::determinant(m) == 0.0) {
        error(where.begin, "cannot invert a singular transform");
        return m;
    }
    return glm::inverse(m);
}

// ------------------------------------------------------------- materials

std::shared_ptr<sg::Material> Evaluator::build_texture(const Edits<sg::Material>& edits, const sg::SourceLocation& at) {
    auto material = std::make_shared<sg::Material>(default_texture());
    for (const auto& edit : edits) edit(*material);
    if (material->uv_mapping) map_by_uv(*material);
    material->location = at;
    return material;
}

std::shared_ptr<sg::Finish> Evaluator::build_finish(const Edits<sg::Finish>& edits, const sg::SourceLocation& at) {
    // POV modifies the finish a texture starts with: #default's.
    auto finish =
        std::make_shared<sg::Finish>(m_default_texture ? *std::as_const(*m_default_texture).finish : sg::Finish{});
    for (const auto& edit : edits) edit(*finish);
    settle_finish(*finish, at);
    return finish;
}

void Evaluator::settle_finish(sg::Finish& settled, const sg::SourceLocation& at) {
    sg::Finish* finish = &settled;
    // POV-Ray's Parse_Finish: a value given as an albedo becomes the peak
    // that reflects that share, with the finish's final exponents.
    if (finish->diffuse_albedo) {
        finish->diffuse *= (finish->brilliance + 1.0) / 2.0;
        finish->diffuse_back *= (finish->brilliance + 1.0) / 2.0;
    }
    if (finish->phong_albedo) finish->phong *= (finish->phong_size + 1.0) / 2.0;
    if (finish->specular_albedo && finish->roughness > 0.0) {
        const double k = 1.0 / finish->roughness;
        finish->specular *= (k + 2.0) / (4.0 * (2.0 - std::pow(2.0, -k / 2.0)));
    }
    finish->diffuse_albedo = finish->phong_albedo = finish->specular_albedo = false;
    finish->location = at;
    const glm::dvec3 ambient = finish->ambient, emission = finish->emission;
    if (glm::any(glm::lessThan(ambient, glm::dvec3(0.0))) || glm::any(glm::lessThan(emission, glm::dvec3(0.0))) ||
        finish->diffuse < 0.0 || finish->phong < 0.0 || finish->specular < 0.0)
        warning(at,
                "the finish has a negative ambient, emission, diffuse, phong or specular: the surface will "
                "take light away (POV-Ray accepts it too)");
}

std::shared_ptr<sg::Interior> Evaluator::build_interior(const Edits<sg::Interior>& edits,
                                                        const sg::SourceLocation& at) {
    auto interior = std::make_shared<sg::Interior>();
    for (const auto& edit : edits) edit(*interior);
    interior->location = at;
    return interior;
}

std::function<void(sg::Finish&)> Evaluator::finish_scalar(const std::string& name, bool albedo, const Value& v,
                                                          const SourceRange& where) {
    double x = to_float(v, where, "a float for " + name);
    if (!check_renderable(&x, 1, where, name)) x = 0.0;
    if (x < 0.0) error(where.begin, name + " must not be negative, got " + std::to_string(x));
    if (name == "roughness" && x == 0.0) warning(where.begin, "roughness 0 gives an infinitely sharp highlight");
    if (name == "diffuse")
        return [x, albedo](sg::Finish& f) {
            f.diffuse = x;
            f.diffuse_albedo = albedo;
        };
    if (name == "diffuse_back") return [x](sg::Finish& f) { f.diffuse_back = x; };
    if (name == "crand") return [x](sg::Finish& f) { f.crand = x; };
    if (name == "brilliance") return [x](sg::Finish& f) { f.brilliance = x; };
    if (name == "specular")
        return [x, albedo](sg::Finish& f) {
            f.specular = x;
            f.specular_albedo = albedo;
        };
    if (name == "roughness") return [x](sg::Finish& f) { f.roughness = x; };
    if (name == "phong")
        return [x, albedo](sg::Finish& f) {
            f.phong = x;
            f.phong_albedo = albedo;
        };
    if (name == "phong_size") return [x](sg::Finish& f) { f.phong_size = x; };
    return [x](sg::Finish& f) { f.metallic = x; };
}

sg::MapType Evaluator::map_type(const Value& v, const SourceRange& where) {
    int type = to_int(v, where);
    switch (type) {
    case 0: return sg::MapType::Planar;
    case 1: return sg::MapType::Spherical;
    case 2: return sg::MapType::Cylindrical;
    case 5: return sg::MapType::Torus;
    default:
        error(where.begin,
              "unsupported map_type " + std::to_string(type) + " (use 0 planar, 1 spherical, 2 cylindrical, 5 torus)");
        return sg::MapType::UV;
    }
}

bool Evaluator::find_image_file(const std::string& name, const sg::SourceLocation& where, std::string& found) {
    // Relative to the file that names the image, then the include path.
    std::vector<std::string> folders = search_folders(where);
    // Last, the current folder, as before the include path existed.
    folders.push_back("");
    const FileSearch search = find_file(name, folders, where, "image file", found);
    if (search == FileSearch::Missing) error(where, "cannot find image file \"" + name + "\"");
    return search == FileSearch::Found;
}

void Evaluator::finish_image_map(sg::ImageMap& image, const sg::SourceLocation& at) {
    namespace fs = std::filesystem;
    if (image.path.empty()) {
        error(at, "image_map needs a file name, e.g. image_map { png \"wood.png\" }");
        return;
    }
    if (!image.location.file) image.location = at;
    std::string found;
    if (!find_image_file(image.path, image.location, found)) return;
    image.path = found;
    if (image.format == sg::ImageFormat::Unknown) {
        std::string ext = fs::path(found).extension().string();
        for (auto& c : ext) c = static_cast<char>(std::tolower(c));
        if (ext == ".png")
            image.format = sg::ImageFormat::Png;
        else if (ext == ".jpg" || ext == ".jpeg")
            image.format = sg::ImageFormat::Jpeg;
        else if (ext == ".exr")
            image.format = sg::ImageFormat::Exr;
        else if (ext == ".hdr")
            image.format = sg::ImageFormat::Hdr;
        else if (ext == ".tga")
            image.format = sg::ImageFormat::Tga;
        else if (ext == ".tif" || ext == ".tiff")
            image.format = sg::ImageFormat::Tiff;
    }
    if (image.format == sg::ImageFormat::Exr || image.format == sg::ImageFormat::Hdr) image.srgb = false;
    // POV-Ray 3.7 decodes an image's colours only in a 3.7 scene: in one
    // older than 3.7 at this point (gamma modes "none" and "3.6", whatever
    // its assumed_gamma), a file without a gamma of its own is read as
    // stored.
    if (!image.gamma_given && effective_language_version() < 370) image.srgb = false;
    image.working_gamma = m_scene.global.assumed_gamma;
}

// ----------------------------------------------------------------- scene

void Evaluator::add_object(const ShapePtr& shape) {
    if (static_cast<long>(m_scene.objects.size()) >= m_options.max_objects) {
        error(shape->object.location, "the scene has more than " + std::to_string(m_options.max_objects) +
                                          " objects (the limit; ParseOptions::max_objects)");
        abort_parse();
        return;
    }
    for (const auto& light : shape->lights) add_light(light, shape->object.parent_from_object);
    const auto* group = std::get_if<sg::Group>(&shape->object.shape);
    if (group && group->children.empty() && !shape->lights.empty()) return;  // object { Light }
    sg::Object object = shape->object;
    if (m_default_texture) apply_default_material(object, in_child_space(m_default_texture, object.parent_from_object));
    m_scene.objects.push_back(std::move(object));
}

}  // namespace lancer::parse
