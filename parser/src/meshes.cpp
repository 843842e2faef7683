// Triangle meshes: triangle, smooth_triangle, mesh, mesh2 (with index
// validation) and the obj_mesh extension (Wavefront OBJ via tinyobjloader).
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <sstream>

#include <tiny_obj_loader.h>

#include "evaluator.h"
#include "huge_pages.h"
#include "number_limits.h"
#include "obj_faces.h"
#include "obj_text_check.h"
#include "obj_text_without_geometry.h"
#include "polygon_triangulation.h"

namespace lancer::parse {

namespace {

namespace fs = std::filesystem;

sg::TriangleMesh& mutable_mesh(ShapeValue& shape) {
    return const_cast<sg::TriangleMesh&>(*std::get<sg::MeshRef>(shape.object.shape));
}

// The first few lines of tinyobjloader's messages: it reports per line, and
// a broken file would otherwise print thousands.
std::string first_lines(const std::string& message, int keep = 5) {
    std::string out;
    int lines = 0, dropped = 0;
    size_t start = 0;
    while (start < message.size()) {
        size_t end = message.find('\n', start);
        if (end == std::string::npos) end = message.size();
        if (end > start) {
            if (lines < keep)
                out += (lines ? "; " : "") + message.substr(start, std::min<size_t>(end - start, 200));
            else
                ++dropped;
            ++lines;
        }
        start = end + 1;
    }
    if (dropped) out += " (and " + std::to_string(dropped) + " more)";
    return out;
}

bool degenerate(const sg::Vec3& a, const sg::Vec3& b, const sg::Vec3& c) {
    return glm::length(glm::cross(b - a, c - a)) == 0.0;
}

}  // namespace

ShapePtr Evaluator::make_triangle(const std::vector<Value>& points, const std::vector<SourceRange>& where,
                                  const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    bool smooth = points.size() == 6;
    shape->object.kind = smooth ? sg::Object::Kind::SmoothTriangle : sg::Object::Kind::Triangle;
    shape->object.location = at;
    auto mesh = std::make_shared<sg::TriangleMesh>();
    shape->object.shape = sg::MeshRef(mesh);
    mesh_triangle_edit(points, where, std::nullopt, {}, at)(*shape);
    return shape;
}

ShapePtr Evaluator::make_mesh(const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = sg::Object::Kind::Mesh;
    shape->object.location = at;
    shape->object.shape = sg::MeshRef(std::make_shared<sg::TriangleMesh>());
    return shape;
}

ShapePtr Evaluator::declared_mesh(const std::shared_ptr<const ShapeValue>& declared, const std::string& name,
                                  sg::Object::Kind kind, const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>(*declared);
    shape->object.name = name;
    shape->object.location = at;
    if (shape->object.kind != sg::Object::Kind::Mesh && shape->object.kind != sg::Object::Kind::Mesh2) {
        error(at, name + " is not a mesh: " + std::string(kind == sg::Object::Kind::Mesh ? "mesh" : "mesh2") + " { " +
                      name + " } copies a declared mesh or mesh2 (use object { " + name + " })");
    }
    return shape;
}

void Evaluator::finish_mesh(ShapeValue& shape, const sg::SourceLocation& at) {
    if (mutable_mesh(shape).faces.empty()) error(at, "mesh has no triangles");
}

std::optional<sg::Vec3> Evaluator::inside_vector(const Value& vector, const SourceRange& where) {
    const sg::Vec3 v = to_vec3(vector, where);
    double xyz[3] = {v.x, v.y, v.z};
    if (!check_renderable(xyz, 3, where, "inside_vector")) return std::nullopt;
    // POV-Ray takes a zero vector as none.
    if (glm::length(v) < 1e-10) {
        warning(where.begin, "inside_vector is zero: the mesh has no inside (as in POV-Ray)");
        return std::nullopt;
    }
    return glm::normalize(v);
}

std::function<void(ShapeValue&)> Evaluator::mesh_inside_vector_edit(const Value& vector, const SourceRange& where) {
    const std::optional<sg::Vec3> v = inside_vector(vector, where);
    return [v](ShapeValue& shape) { mutable_mesh(shape).inside_vector = v; };
}

// One triangle (3 points) or smooth triangle (point, normal) x 3, with an
// optional per-triangle texture.
std::function<void(ShapeValue&)> Evaluator::mesh_triangle_edit(
    const std::vector<Value>& points, const std::vector<SourceRange>& where,
    const std::optional<std::vector<std::pair<Value, SourceRange>>>& uv_vectors,
    const std::vector<std::shared_ptr<sg::Material>>& textures, const sg::SourceLocation& at) {
    add_triangles(1, at);
    bool smooth = points.size() == 6;
    std::vector<sg::Vec3> p, n;
    for (size_t i = 0; i < points.size(); ++i) {
        sg::Vec3 v = to_vec3(points[i], where[i]);
        (smooth && i % 2 == 1 ? n : p).push_back(v);
    }
    if (degenerate(p[0], p[1], p[2])) warning(at, "degenerate triangle (its corners are collinear)");
    if (smooth)
        for (size_t i = 0; i < 3; ++i)
            if (glm::length(n[i]) == 0.0) error(where[2 * i + 1].begin, "smooth_triangle normal must not be zero");
    if (textures.size() > 1) warning(at, "only the first texture of a mesh triangle is used");
    std::vector<sg::Vec2> uv;
    if (uv_vectors) {
        for (const auto& [value, range] : *uv_vectors) {
            sg::Vec2 corner;
            if (!to_uv(value, range, corner)) break;
            uv.push_back(corner);
        }
        if (uv.size() != 3) uv.clear();
    }
    std::shared_ptr<sg::Material> texture = textures.empty() ? nullptr : textures.front();
    return [p, n, uv, texture](ShapeValue& shape) {
        sg::TriangleMesh& mesh = mutable_mesh(shape);
        sg::TriangleMesh::Face face;
        int base = static_cast<int>(mesh.positions.size());
        for (int i = 0; i < 3; ++i) {
            mesh.positions.push_back(p[i]);
            face.position[i] = base + i;
        }
        if (!n.empty()) {
            int normal_base = static_cast<int>(mesh.normals.size());
            for (int i = 0; i < 3; ++i) {
                mesh.normals.push_back(glm::normalize(n[i]));
                face.normal[i] = normal_base + i;
            }
        }
        if (!uv.empty()) {
            const int uv_base = static_cast<int>(mesh.uvs.size());
            for (int i = 0; i < 3; ++i) {
                mesh.uvs.push_back(uv[std::size_t(i)]);
                face.uv[i] = uv_base + i;
            }
        }
        if (texture) {
            face.material = static_cast<int>(mesh.materials.size());
            mesh.materials.push_back(texture);
        }
        mesh.faces.push_back(face);
    };
}

// ----------------------------------------------------------------- mesh2

ShapePtr Evaluator::make_mesh2(const Edits<sg::TriangleMesh>& sections, const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = sg::Object::Kind::Mesh2;
    shape->object.location = at;
    auto mesh = std::make_shared<sg::TriangleMesh>();
    for (const auto& section : sections) section(*mesh);
    if (mesh->positions.empty()) error(at, "mesh2 needs vertex_vectors");
    if (mesh->faces.empty()) error(at, "mesh2 needs face_indices");
    // Without normal_indices (uv_indices), POV pairs normals (uvs) with vertices.
    bool has_normal_indices = !mesh->faces.empty() && mesh->faces.front().normal[0] >= 0;
    if (!mesh->normals.empty() && !has_normal_indices) {
        if (mesh->normals.size() != mesh->positions.size()) {
            error(at, "mesh2 has " + std::to_string(mesh->normals.size()) + " normal_vectors but " +
                          std::to_string(mesh->positions.size()) + " vertex_vectors and no normal_indices");
        } else {
            for (auto& face : mesh->faces)
                for (int i = 0; i < 3; ++i) face.normal[i] = face.position[i];
        }
    }
    bool has_uv_indices = !mesh->faces.empty() && mesh->faces.front().uv[0] >= 0;
    if (!mesh->uvs.empty() && !has_uv_indices) {
        if (mesh->uvs.size() != mesh->positions.size()) {
            error(at, "mesh2 has " + std::to_string(mesh->uvs.size()) + " uv_vectors but " +
                          std::to_string(mesh->positions.size()) + " vertex_vectors and no uv_indices");
        } else {
            for (auto& face : mesh->faces)
                for (int i = 0; i < 3; ++i) face.uv[i] = face.position[i];
        }
    }
    shape->object.shape = sg::MeshRef(mesh);
    return shape;
}

std::function<void(sg::TriangleMesh&)> Evaluator::mesh2_vectors(const std::string& section, const Value& count,
                                                                const SourceRange& wc, const std::vector<Value>& items,
                                                                const SourceRange& wi, const sg::SourceLocation& at) {
    int declared = to_int(count, wc);
    if (declared != static_cast<int>(items.size())) {
        error(at,
              section + " declares " + std::to_string(declared) + " entries but lists " + std::to_string(items.size()));
    }
    bool uv = section == "uv_vectors";
    std::vector<sg::Vec3> vectors;
    for (const auto& item : items) {
        SourceRange here{item.location.file ? item.location : wi.begin, item.location};
        if (uv && !(item.kind == Value::Kind::Vector && item.size == 2)) {
            error(here.begin, "uv_vectors entries must be 2-component vectors <u, v>, found " + describe(item));
            vectors.emplace_back(0.0);
            continue;
        }
        vectors.push_back(to_vec3(item, here));
    }
    return [section, vectors](sg::TriangleMesh& mesh) {
        for (const auto& v : vectors) {
            if (section == "vertex_vectors")
                mesh.positions.push_back(v);
            else if (section == "normal_vectors")
                mesh.normals.push_back(glm::length(v) > 0 ? glm::normalize(v) : v);
            else
                mesh.uvs.emplace_back(v.x, v.y);
        }
    };
}

// Said alike whether the grammar or the scanner read the section (mesh2_sections.cpp).
std::string Evaluator::mesh2_index_out_of_range(const std::string& section, long long index, const char* what,
                                                std::size_t size) {
    return section + " index " + std::to_string(index) + " is out of range: " + what + " has " + std::to_string(size) +
           " entries" + (size ? " (valid 0.." + std::to_string(size - 1) + ")" : "");
}

std::string Evaluator::mesh2_indices_not_per_face(const std::string& section, std::size_t entries, std::size_t faces) {
    return section + " lists " + std::to_string(entries) + " entries but face_indices has " + std::to_string(faces) +
           " (it must come after face_indices, one per face)";
}

std::function<void(sg::TriangleMesh&)> Evaluator::mesh2_indices(const std::string& section, const Value& count,
                                                                const SourceRange& wc, const std::vector<Value>& items,
                                                                const SourceRange& wi, const sg::SourceLocation& at) {
    // Each entry is <a, b, c>; face_indices may follow one with 1 or 3 texture indices.
    struct Entry {
        int index[3];
        int texture = -1;
        sg::SourceLocation where;
    };
    std::vector<Entry> entries;
    bool ok = true;
    for (const auto& item : items) {
        sg::SourceLocation here = item.location.file ? item.location : wi.begin;
        if (item.kind == Value::Kind::Vector && item.size == 3) {
            Entry entry;
            for (int i = 0; i < 3; ++i) {
                const double x = item.v[i];
                if (!whole_int(x, entry.index[i])) {
                    error(here, section + " entries must be whole numbers in int's range, found " + std::to_string(x));
                    ok = false;
                }
            }
            entry.where = here;
            entries.push_back(entry);
        } else if (item.kind == Value::Kind::Float && section == "face_indices" && !entries.empty()) {
            int texture = 0;
            if (!whole_int(item.v[0], texture) || texture < 0) {
                error(here, "a face's texture index must be a whole number from 0, found " + std::to_string(item.v[0]));
                ok = false;
            } else if (entries.back().texture < 0) {
                entries.back().texture = texture;
            }
        } else {
            error(here, section + " entries must be <a, b, c> index vectors, found " + describe(item));
            ok = false;
        }
    }
    if (section == "face_indices") add_triangles(static_cast<long>(entries.size()), at);
    int declared = to_int(count, wc);
    if (declared != static_cast<int>(entries.size())) {
        error(at, section + " declares " + std::to_string(declared) + " entries but lists " +
                      std::to_string(entries.size()));
    }
    Evaluator* ev = this;
    return [ev, section, entries, ok, at](sg::TriangleMesh& mesh) {
        if (!ok) return;
        auto check = [&](int index, size_t size, const char* what, const sg::SourceLocation& where) {
            if (index >= 0 && static_cast<size_t>(index) < size) return true;
            ev->error(where, mesh2_index_out_of_range(section, index, what, size));
            return false;
        };
        if (section == "face_indices") {
            for (const auto& entry : entries) {
                sg::TriangleMesh::Face face;
                for (int i = 0; i < 3; ++i) {
                    face.position[i] = check(entry.index[i], mesh.positions.size(), "vertex_vectors", entry.where)
                                           ? entry.index[i]
                                           : 0;
                }
                if (entry.texture >= 0 && check(entry.texture, mesh.materials.size(), "texture_list", entry.where)) {
                    face.material = entry.texture;
                }
                mesh.faces.push_back(face);
            }
            return;
        }
        bool normals = section == "normal_indices";
        if (entries.size() != mesh.faces.size()) {
            ev->error(at, mesh2_indices_not_per_face(section, entries.size(), mesh.faces.size()));
            return;
        }
        for (size_t f = 0; f < entries.size(); ++f) {
            for (int i = 0; i < 3; ++i) {
                int index = entries[f].index[i];
                if (!check(index, normals ? mesh.normals.size() : mesh.uvs.size(),
                           normals ? "normal_vectors" : "uv_vectors", entries[f].where))
                    index = -1;
                (normals ? mesh.faces[f].normal : mesh.faces[f].uv)[i] = index;
            }
        }
    };
}

std::function<void(sg::TriangleMesh&)> Evaluator::mesh2_textures(
    const Value& count, const SourceRange& wc, const std::vector<std::shared_ptr<sg::Material>>& textures,
    const sg::SourceLocation& at) {
    int declared = to_int(count, wc);
    if (declared != static_cast<int>(textures.size())) {
        error(at, "texture_list declares " + std::to_string(declared) + " textures but lists " +
                      std::to_string(textures.size()));
    }
    return [textures](sg::TriangleMesh& mesh) {
        for (const auto& t : textures) mesh.materials.push_back(t);
    };
}

// -------------------------------------------------------------- obj_mesh

// Reads the MTL files an OBJ names (mtllib), relative to the OBJ's folder:
// through the evaluator, so safe mode, the size limit and the text checks
// apply as for every other file. tinyobjloader's own reader would follow
// "../" and absolute names anywhere.
class Evaluator::ObjMaterialReader : public tinyobj::MaterialReader {
  public:
    // `faces` looks its `usemtl` names up in the map this reader fills.
    ObjMaterialReader(Evaluator& evaluator, fs::path folder, ObjFaceReader& faces)
        : m_evaluator(evaluator), m_folder(std::move(folder)), m_faces(faces) {}

    bool operator()(const std::string& id, std::vector<tinyobj::material_t>* materials, std::map<std::string, int>* map,
                    std::string* warn, std::string* err) override {
        if (refused) return false;
        m_faces.use_material_names(map);
        fs::path path = fs::path(id).is_absolute() ? fs::path(id) : m_folder / id;
        if (!m_evaluator.allowed_file(path.string())) {
            refused = true;
            refused_name = id;
            return false;
        }
        std::error_code ec;
        auto size = fs::file_size(path, ec);
        std::ifstream in(path, std::ios::binary);
        if (ec || !fs::is_regular_file(path, ec) || !in) {
            missing.push_back(id);
            return false;
        }
        m_evaluator.m_scene.input_files.push_back(path.string());
        if (size > static_cast<std::uintmax_t>(m_evaluator.m_options.max_file_bytes)) {
            if (err) *err += "MTL file " + id + " is larger than the file size limit\n";
            return false;
        }
        std::ostringstream text;
        text << in.rdbuf();
        if (const char* problem = not_text(text.str())) {
            if (warn) *warn += "MTL file " + id + " " + problem + "\n";
            return false;
        }
        std::istringstream stream(text.str());
        tinyobj::LoadMtl(map, materials, &stream, warn, err);
        return true;
    }

    bool refused = false;
    std::string refused_name;
    std::vector<std::string> missing;

  private:
    Evaluator& m_evaluator;
    fs::path m_folder;
    ObjFaceReader& m_faces;
};

ShapePtr Evaluator::make_obj_mesh(const Value& file, const SourceRange& where, const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = sg::Object::Kind::ObjMesh;
    shape->object.location = at;
    auto mesh = std::make_shared<sg::TriangleMesh>();
    shape->object.shape = sg::MeshRef(mesh);
    std::string name = to_string(file, where);
    if (name.empty()) return shape;

    // Relative to the file that names it, then the include path.
    std::vector<std::string> folders = search_folders(where.begin);
    std::string found_name;
    FileSearch search = find_file(name, folders, where.begin, "OBJ file", found_name);
    if (search == FileSearch::Refused) return shape;
    if (search == FileSearch::Missing) {
        error(where.begin, "cannot find OBJ file \"" + name + "\"");
        return shape;
    }
    fs::path found = found_name;
    mesh->source = found.string();

    // The text is checked first (obj_text_check.h), then read by
    // tinyobjloader, its geometry lines by lancer (obj_text_without_geometry.h),
    // each from the file a piece at a time: the file (a regular one, as
    // find_file found it) is read twice rather than held whole, the second
    // time no further than the first, and a file that changed between the
    // two is an error.
    ObjTextCheck check;
    auto stamp = [&] {
        std::error_code ignored;
        return std::make_pair(fs::file_size(found, ignored), fs::last_write_time(found, ignored));
    };
    const auto stamp_before = stamp();
    if (!within_file_limit(found.string(), where.begin, "OBJ file")) return shape;
    std::ifstream in(found, std::ios::binary);
    std::vector<char> piece(1 << 20);
    std::uintmax_t checked = 0;
    while (in && (in.read(piece.data(), std::streamsize(piece.size())) || in.gcount() > 0)) {
        checked += std::uintmax_t(in.gcount());
        if (checked > std::uintmax_t(m_options.max_file_bytes)) {
            error(where.begin, "OBJ file \"" + found.string() + "\" is too large: over " +
                                   std::to_string(m_options.max_file_bytes) + " bytes (the limit)");
            return shape;
        }
        check.feed(piece.data(), std::size_t(in.gcount()));
    }
    ObjFaceReader faces(*mesh);
    ObjTextWithoutGeometry obj_file(found, checked, faces);
    if (in.bad() || !obj_file.is_open()) {
        error(where.begin, "cannot read OBJ file \"" + found.string() + "\"");
        return shape;
    }
    std::istream source(&obj_file);
    check.finish();
    if (const char* problem = check.why_not_text()) {
        error(where.begin, "OBJ file \"" + name + "\" " + problem);
        return shape;
    }
    if (!check.face_problem().empty()) {
        error(where.begin, "OBJ \"" + name + "\", " + check.face_problem());
        return shape;
    }

    const ObjTextCheck::Counts& counts = check.counts();
    reserve_on_huge_pages(mesh->positions, counts.positions);
    reserve_on_huge_pages(mesh->normals, counts.normals);
    reserve_on_huge_pages(mesh->uvs, counts.uvs);
    // Triangles and quads reserve what they make. A polygon of many corners
    // may make few triangles (none without area, at 2 bytes a corner): it
    // does not reserve more than twice the faces, nor past the scene's limit.
    const auto triangle_budget = std::size_t(std::max(0L, m_options.max_triangles - m_triangles));
    reserve_on_huge_pages(mesh->faces, std::min({counts.triangles, 2 * counts.faces, triangle_budget}));
    ObjMaterialReader materials(*this, found.parent_path(), faces);
    std::string obj_warning, obj_error;
    // Streamed: each face goes into the mesh as it is read (obj_faces.h).
    // Faces as written: tinyobjloader's triangulation takes time growing
    // with the square of a face's size; lancer's takes O(n log n).
    const bool loaded =
        tinyobj::LoadObjWithCallback(source, ObjFaceReader::callbacks(), &faces, &materials, &obj_warning, &obj_error);
    if (obj_file.failed()) {
        error(where.begin, "cannot read OBJ file \"" + found.string() + "\"");
        return shape;
    }
    if (stamp() != stamp_before) {
        error(where.begin, "OBJ file \"" + found.string() + "\" changed while it was read; read it again");
        return shape;
    }
    if (materials.refused) {
        refuse_file(where.begin, "MTL file", materials.refused_name);
        return shape;
    }
    if (!loaded) {
        error(where.begin,
              "cannot read OBJ file \"" + name + "\": " + (obj_error.empty() ? "parse error" : first_lines(obj_error)));
        return shape;
    }
    obj_warning += faces.warnings;
    for (const auto& missing : materials.missing)
        warning(where.begin,
                "OBJ \"" + name + "\": MTL file \"" + missing + "\" not found; its faces get the default material");
    if (!obj_error.empty()) warning(where.begin, "OBJ \"" + name + "\": " + first_lines(obj_error));
    if (!obj_warning.empty() && materials.missing.empty())
        warning(where.begin, "OBJ \"" + name + "\": " + first_lines(obj_warning));
    if (faces.non_finite_vertex) {
        error(where.begin, "OBJ \"" + name + "\" has a vertex coordinate that is not a finite number");
        return shape;
    }
    if (!faces.finish()) {
        error(where.begin, "OBJ \"" + name + "\": " + faces.bad_face + " refers to a vertex that does not exist");
        return shape;
    }
    std::vector<tinyobj::material_t>& obj_materials = faces.materials;
    auto count_of = [](std::size_t n, const char* one, const char* many) {
        return std::to_string(n) + " " + (n == 1 ? one : many);
    };
    if (faces.short_faces)
        warning(where.begin, "OBJ \"" + name + "\": " + count_of(faces.short_faces, "face has", "faces have") +
                                 " fewer than three vertices and " + (faces.short_faces == 1 ? "is" : "are") +
                                 " left out");
    if (faces.misnamed_normals)
        warning(where.begin, "OBJ \"" + name +
                                 "\": " + count_of(faces.misnamed_normals, "triangle names", "triangles name") +
                                 " a normal that does not exist; shaded flat");
    if (faces.misnamed_uvs)
        warning(where.begin, "OBJ \"" + name +
                                 "\": " + count_of(faces.misnamed_uvs, "triangle names", "triangles name") +
                                 " texture coordinates that do not exist; mapped by the triangle's own (u, v)");

    // MTL materials, mapped onto POV's model (documented in docs/scene-language.md).
    for (auto& m : obj_materials) {
        // tinyobjloader reads 1e999 as infinity and keeps any sign: a NaN or
        // infinite value is an error, a negative reflectance a warning (and 0).
        const std::string material_name = "OBJ \"" + name + "\": material '" + m.name + "': ";
        struct Field {
            const char* key;
            float* values;
            int count;
            bool reflectance;
        };
        const Field fields[] = {{"Kd", m.diffuse, 3, true},     {"Ka", m.ambient, 3, true},
                                {"Ks", m.specular, 3, true},    {"Ke", m.emission, 3, true},
                                {"Ns", &m.shininess, 1, false}, {"d", &m.dissolve, 1, false},
                                {"Ni", &m.ior, 1, false}};
        for (const Field& field : fields) {
            for (int k = 0; k < field.count; ++k) {
                if (!std::isfinite(field.values[k])) {
                    error(where.begin, material_name + field.key + " is not a finite number");
                    return shape;
                }
            }
            if (!field.reflectance) continue;
            bool negative = false;
            for (int k = 0; k < field.count; ++k)
                if (field.values[k] < 0.0f) {
                    negative = true;
                    field.values[k] = 0.0f;
                }
            if (negative) warning(where.begin, material_name + field.key + " has a negative value; it is taken as 0");
        }
        auto material = std::make_shared<sg::Material>();
        material->name = m.name;
        material->location = where.begin;
        sg::Vec3 kd(m.diffuse[0], m.diffuse[1], m.diffuse[2]);
        material->pigment.color.rgb = kd;
        material->pigment.color.transmit = 1.0 - std::clamp<double>(m.dissolve, 0.0, 1.0);
        if (!m.diffuse_texname.empty()) {
            // map_Kd is relative to the OBJ's folder.
            fs::path texture = found.parent_path() / m.diffuse_texname;
            std::error_code ec;
            if (!allowed_file(texture.string())) {
                refuse_file(where.begin, "texture", m.diffuse_texname);
                return shape;
            }
            if (fs::is_regular_file(texture, ec)) {
                material->pigment.kind = sg::Pigment::Kind::Image;
                sg::ImageMap& image = *material->pigment.image;
                image.path = texture.string();
                image.location = where.begin;
                // An OBJ texture lies on the mesh's texcoords, filtered.
                image.map_type = sg::MapType::UV;
                pigment_pattern_of(material->pigment).uv_mapping = true;
                image.interpolate = 2;
                finish_image_map(image, where.begin);
            } else {
                warning(where.begin,
                        "OBJ material '" + m.name + "': texture \"" + m.diffuse_texname + "\" not found; using Kd");
            }
        }
        material->finish->ambient = sg::Vec3(m.ambient[0], m.ambient[1], m.ambient[2]);
        material->finish->diffuse = 1.0;
        material->finish->specular = (m.specular[0] + m.specular[1] + m.specular[2]) / 3.0;
        material->finish->roughness = 1.0 / std::max<double>(m.shininess, 1.0);
        for (int c = 0; c < 3; ++c) material->finish->emission[c] = kd[c] > 0 ? m.emission[c] / kd[c] : m.emission[c];
        if (m.illum == 3 || m.illum == 5 || m.illum == 7) {
            material->finish->reflection.min = material->finish->reflection.max =
                sg::Vec3(m.specular[0], m.specular[1], m.specular[2]);
        }
        material->interior->ior = m.ior > 0 ? m.ior : 1.0;
        mesh->materials.push_back(material);
    }

    const ObjFaceReader::Skipped& crossing = faces.crossing;
    const ObjFaceReader::Skipped& flat = faces.flat;
    if (crossing.count)
        warning(where.begin, "OBJ \"" + name + "\": " + std::to_string(crossing.count) +
                                 (crossing.count == 1 ? " face crosses its" : " faces cross their") +
                                 " own edges (first: " + crossing.first +
                                 "); triangulated as a fan from the first corner");
    if (flat.count)
        warning(where.begin, "OBJ \"" + name + "\": " + std::to_string(flat.count) +
                                 (flat.count == 1 ? " face has" : " faces have") + " no area (first: " + flat.first +
                                 "; its corners lie on one line) and " + (flat.count == 1 ? "is" : "are") +
                                 " left out");
    if (mesh->faces.empty()) {
        error(where.begin, "OBJ file \"" + name + "\" has no faces" +
                               (mesh->positions.empty() ? ""
                                                        : " (" + std::to_string(mesh->positions.size()) +
                                                              " vertices only: a point cloud?)"));
    } else {
        add_triangles(static_cast<long>(mesh->faces.size()), where.begin);
    }
    return shape;
}

}  // namespace lancer::parse
