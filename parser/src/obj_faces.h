// An OBJ's vertices and faces read straight into a mesh, as
// tinyobjloader's streaming reader (LoadObjWithCallback) would hand them
// over: lancer reads those lines itself (obj_text_without_geometry.h) and
// calls the same add_vertex, add_normal, add_uv and add_face.
//
// tinyobjloader's LoadObj keeps every face in a vector of its own and every
// attribute twice (its arrays, then lancer's): a million-triangle OBJ with
// normals and texture coordinates peaked at 315 bytes a triangle. Here each
// face becomes the mesh's triangles as it is read, and nothing is kept
// beside the mesh but the faces that name a vertex not read yet (allowed
// by tinyobjloader, so kept working) until the end. What LoadObj decided is
// decided the same way: indices relative to what is read so far, faces of
// fewer than three vertices dropped, `usemtl` by the first word of its
// line, faces numbered within each `g` / `o` group for messages.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <vector>

#include <tiny_obj_loader.h>

#include "lancer/scene_graph.h"

namespace lancer::parse {

class ObjFaceReader {
  public:
    explicit ObjFaceReader(sg::TriangleMesh& mesh) : m_mesh(mesh) {}
    ObjFaceReader(const ObjFaceReader&) = delete;
    ObjFaceReader& operator=(const ObjFaceReader&) = delete;

    // The callbacks for tinyobj::LoadObjWithCallback, with this as user_data.
    static tinyobj::callback_t callbacks();
    // The MTL materials' names as tinyobjloader numbers them (the map its
    // MaterialReader fills): `usemtl` is looked up there.
    void use_material_names(const std::map<std::string, int>* names) { m_material_names = names; }

    // After the parse: places the faces that waited for their vertices,
    // drops normal and uv indices that name nothing, and checks that every
    // face's vertices exist. False when one does not (see bad_face).
    bool finish();
    // One face line's corners, as tinyobjloader's index callback hands them.
    void add_face(const tinyobj::index_t* indices, int count);
    // One v, vn or vt line's numbers, as its callbacks hand them.
    void add_vertex(double x, double y, double z);
    void add_normal(float x, float y, float z) { m_mesh.normals.emplace_back(x, y, z); }
    void add_uv(float u, float v) { m_mesh.uvs.emplace_back(u, v); }

    struct Skipped {
        std::size_t count = 0;
        std::string first;  // "face N of 'group'"
        std::size_t first_ordinal = SIZE_MAX;
    };
    bool non_finite_vertex = false;
    std::size_t short_faces = 0;       // of fewer than three vertices, left out
    std::size_t misnamed_normals = 0;  // triangles naming a normal that does not exist: shaded flat
    std::size_t misnamed_uvs = 0;      // the same for texture coordinates
    std::string bad_face;              // the first face naming a vertex that does not exist
    Skipped crossing, flat;
    std::vector<tinyobj::material_t> materials;  // from the MTL files, in tinyobjloader's order
    std::string warnings;                        // as tinyobjloader's LoadObj words them

  private:
    struct Corner {
        int position, normal, uv;
    };
    // A polygon that names a vertex not read yet: its triangles go into
    // `slot` (room for count - 2 of them) at the end.
    struct Waiting {
        std::size_t slot;
        std::vector<Corner> corners;
        int material;
        std::size_t ordinal;
        std::string label;
    };
    // A triangle that names a vertex not read yet: fine if it exists at the end.
    struct Ahead {
        int largest_position;
        std::size_t ordinal;
        std::string label;
    };

    void use_material(const char* name);
    void start_group(std::string name);
    std::string label() const;
    // Places the triangles of a polygon whose vertices all exist in the
    // faces [slot, slot_end) kept for them, inserting any beyond (none when
    // the room is n - 2); returns how many were inserted. `ordinal`: the
    // face's place in the file, for the warnings' first face.
    std::size_t add_polygon(const std::vector<Corner>& corners, int material, const std::string& label,
                            std::size_t ordinal, std::size_t slot, std::size_t slot_end);
    // The face numbered `ordinal` in the file names a vertex that cannot exist.
    void fail(std::size_t ordinal);

    sg::TriangleMesh& m_mesh;
    const std::map<std::string, int>* m_material_names = nullptr;
    int m_material = -1;
    std::string m_group;
    std::size_t m_face_in_group = 0;  // faces of three or more vertices, as LoadObj counts them
    std::size_t m_faces_read = 0;
    bool m_failed = false;  // faces after it are read for their numbers only
    std::size_t m_failed_ordinal = 0;
    std::string m_failed_label;
    std::vector<Corner> m_corners;
    std::vector<Waiting> m_waiting;
    std::vector<Ahead> m_ahead;
};

}  // namespace lancer::parse
