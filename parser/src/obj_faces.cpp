#include "obj_faces.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <utility>

#include "polygon_triangulation.h"

namespace lancer::parse {
namespace {

// A face slot kept for a polygon's triangles that its polygon did not need.
constexpr int kEmptySlot = INT_MIN;
// A normal or uv index the face line does not write.
constexpr int kNotWritten = INT_MIN;

ObjFaceReader& reader(void* user_data) {
    return *static_cast<ObjFaceReader*>(user_data);
}

// An OBJ index as tinyobjloader's LoadObj resolves it: 1-based, or negative
// counting back from the last element read; 0 (not written) is `missing`.
int resolve(int raw, std::size_t read_so_far, int missing) {
    if (raw > 0) return raw - 1;
    if (raw < 0) return int(read_so_far) + raw;
    return missing;
}

}  // namespace

tinyobj::callback_t ObjFaceReader::callbacks() {
    tinyobj::callback_t callbacks;
    callbacks.vertex_cb = [](void* user_data, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z,
                             tinyobj::real_t) { reader(user_data).add_vertex(x, y, z); };
    callbacks.normal_cb = [](void* user_data, tinyobj::real_t x, tinyobj::real_t y, tinyobj::real_t z) {
        reader(user_data).add_normal(x, y, z);
    };
    callbacks.texcoord_cb = [](void* user_data, tinyobj::real_t u, tinyobj::real_t v, tinyobj::real_t) {
        reader(user_data).add_uv(u, v);
    };
    callbacks.index_cb = [](void* user_data, tinyobj::index_t* indices, int count) {
        reader(user_data).add_face(indices, count);
    };
    callbacks.usemtl_cb = [](void* user_data, const char* name, int) { reader(user_data).use_material(name); };
    callbacks.mtllib_cb = [](void* user_data, const tinyobj::material_t* materials, int count) {
        reader(user_data).materials.assign(materials, materials + count);
    };
    callbacks.group_cb = [](void* user_data, const char** names, int count) {
        std::string joined;
        for (int i = 0; i < count; ++i) joined += (i ? " " : "") + std::string(names[i]);
        reader(user_data).start_group(std::move(joined));
    };
    callbacks.object_cb = [](void* user_data, const char* name) { reader(user_data).start_group(name); };
    return callbacks;
}

void ObjFaceReader::add_vertex(double x, double y, double z) {
    if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) non_finite_vertex = true;
    m_mesh.positions.emplace_back(x, y, z);
}

void ObjFaceReader::use_material(const char* line) {
    // LoadObj takes the first word; the streaming reader passes the rest of
    // the line, blanks before the name included.
    std::string name(line);
    const std::size_t start = std::min(name.size(), name.find_first_not_of(" \t"));
    name = name.substr(start, name.find_first_of(" \t\r", start) - start);
    m_material = -1;
    if (m_material_names) {
        const auto found = m_material_names->find(name);
        if (found != m_material_names->end()) m_material = found->second;
    }
    if (m_material < 0) warnings += "material [ '" + name + "' ] not found in .mtl\n";
}

void ObjFaceReader::start_group(std::string name) {
    m_group = std::move(name);
    m_face_in_group = 0;
}

std::string ObjFaceReader::label() const {
    return "face " + std::to_string(m_face_in_group) + (m_group.empty() ? "" : " of '" + m_group + "'");
}

void ObjFaceReader::fail(std::size_t ordinal) {
    m_failed = true;
    m_failed_ordinal = ordinal;
    m_failed_label = label();
}

void ObjFaceReader::add_face(const tinyobj::index_t* indices, int count) {
    if (count < 3) {  // LoadObj drops them
        ++short_faces;
        return;
    }
    ++m_face_in_group;
    const std::size_t ordinal = m_faces_read++;
    if (m_failed) return;
    const std::size_t read = m_mesh.positions.size();
    m_corners.resize(std::size_t(count));
    int largest = -1;
    for (int k = 0; k < count; ++k) {
        Corner& corner = m_corners[std::size_t(k)];
        corner.position = resolve(indices[k].vertex_index, read, -1);
        corner.normal = resolve(indices[k].normal_index, m_mesh.normals.size(), kNotWritten);
        corner.uv = resolve(indices[k].texcoord_index, m_mesh.uvs.size(), kNotWritten);
        if (corner.position < 0) return fail(ordinal);
        largest = std::max(largest, corner.position);
    }
    const bool all_read = std::size_t(largest) < read;
    if (count == 3) {
        sg::TriangleMesh::Face face;
        for (int i = 0; i < 3; ++i) {
            face.position[i] = m_corners[std::size_t(i)].position;
            face.normal[i] = m_corners[std::size_t(i)].normal;
            face.uv[i] = m_corners[std::size_t(i)].uv;
        }
        face.material = m_material;
        m_mesh.faces.push_back(face);
        if (!all_read) m_ahead.push_back({largest, ordinal, label()});
        return;
    }
    if (all_read) {
        add_polygon(m_corners, m_material, label(), ordinal, m_mesh.faces.size(), m_mesh.faces.size());
        return;
    }
    // Room for its triangles until its vertices are read. A reading that
    // fails leaves these slots in the mesh: their corners are set too.
    sg::TriangleMesh::Face empty;
    empty.position[0] = empty.position[1] = empty.position[2] = -1;
    empty.material = kEmptySlot;
    m_waiting.push_back({m_mesh.faces.size(), m_corners, m_material, ordinal, label()});
    m_mesh.faces.insert(m_mesh.faces.end(), std::size_t(count - 2), empty);
}

std::size_t ObjFaceReader::add_polygon(const std::vector<Corner>& corners, int material, const std::string& label,
                                       std::size_t ordinal, std::size_t slot, std::size_t slot_end) {
    std::vector<sg::Vec3> points;
    points.reserve(corners.size());
    for (const Corner& corner : corners) points.push_back(m_mesh.positions[std::size_t(corner.position)]);
    const PolygonTriangulation triangulation = triangulate_polygon(points);
    std::size_t inserted = 0;
    // Waiting polygons are placed at the end: the first noted is the first in the file.
    auto note = [&](Skipped& skipped) {
        ++skipped.count;
        if (ordinal < skipped.first_ordinal) {
            skipped.first_ordinal = ordinal;
            skipped.first = label;
        }
    };
    if (triangulation.kind == PolygonTriangulation::Kind::NotSimple) note(crossing);
    if (triangulation.kind == PolygonTriangulation::Kind::NoArea) note(flat);
    for (const auto& triangle : triangulation.triangles) {
        sg::TriangleMesh::Face face;
        for (int i = 0; i < 3; ++i) {
            const Corner& corner = corners[triangle[std::size_t(i)]];
            face.position[i] = corner.position;
            face.normal[i] = corner.normal;
            face.uv[i] = corner.uv;
        }
        face.material = material;
        // A polygon of n corners has at most n - 2 triangles (the room kept
        // for it); past that, or when appending, the face is inserted.
        if (slot < slot_end) {
            m_mesh.faces[slot] = face;
        } else {
            m_mesh.faces.insert(m_mesh.faces.begin() + std::ptrdiff_t(slot), face);
            ++slot_end;
            ++inserted;
        }
        ++slot;
    }
    return inserted;
}

bool ObjFaceReader::finish() {
    const std::size_t read = m_mesh.positions.size();
    // The first face, in the file's order, naming a vertex that does not exist.
    std::size_t first_bad = m_failed ? m_failed_ordinal : SIZE_MAX;
    if (m_failed) bad_face = m_failed_label;
    for (const Ahead& ahead : m_ahead)
        if (std::size_t(ahead.largest_position) >= read && ahead.ordinal < first_bad) {
            first_bad = ahead.ordinal;
            bad_face = ahead.label;
        }
    for (const Waiting& waiting : m_waiting) {
        const bool exists = std::all_of(waiting.corners.begin(), waiting.corners.end(),
                                        [&](const Corner& c) { return std::size_t(c.position) < read; });
        if (!exists && waiting.ordinal < first_bad) {
            first_bad = waiting.ordinal;
            bad_face = waiting.label;
        }
    }
    if (first_bad != SIZE_MAX) return false;
    std::size_t inserted = 0;  // faces placed past a polygon's room move the later slots
    for (const Waiting& waiting : m_waiting) {
        const std::size_t slot = waiting.slot + inserted;
        inserted += add_polygon(waiting.corners, waiting.material, waiting.label, waiting.ordinal, slot,
                                slot + waiting.corners.size() - 2);
    }
    if (!m_waiting.empty())
        m_mesh.faces.erase(std::remove_if(m_mesh.faces.begin(), m_mesh.faces.end(),
                                          [](const sg::TriangleMesh::Face& f) { return f.material == kEmptySlot; }),
                           m_mesh.faces.end());
    // Normals and uvs that name nothing are left out, all three or none.
    const std::size_t normals = m_mesh.normals.size(), uvs = m_mesh.uvs.size(), kinds = materials.size();
    auto keep_all_or_none = [](int(&index)[3], std::size_t size, std::size_t& misnamed) {
        bool all_exist = true, names_missing = false;
        for (const int i : index) {
            const bool exists = i >= 0 && std::size_t(i) < size;
            all_exist = all_exist && exists;
            names_missing = names_missing || (!exists && i != kNotWritten);
        }
        if (names_missing) ++misnamed;
        if (!all_exist) index[0] = index[1] = index[2] = -1;
    };
    for (sg::TriangleMesh::Face& face : m_mesh.faces) {
        keep_all_or_none(face.normal, normals, misnamed_normals);
        keep_all_or_none(face.uv, uvs, misnamed_uvs);
        if (face.material < 0 || std::size_t(face.material) >= kinds) face.material = -1;
    }
    return true;
}

}  // namespace lancer::parse
