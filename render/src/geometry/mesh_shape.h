// POV-Ray's triangle meshes (mesh, mesh2, and a lone triangle or
// smooth_triangle) as a Shape, so they can be CSG children, be inverted or
// be clipped: every crossing of a line through a BVH over the triangles,
// and POV's inside test, which needs the mesh's inside_vector
// (mesh_shape.cpp says how both are computed).
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <vector>

#include "geometry/shape.h"

namespace lancer {

struct MeshShapeParameters {
    // One triangle: three indices into `positions`; optionally three into
    // `normals` (a smooth triangle) and three into `uvs`. An index of -1 (in
    // the first slot) means none; an out-of-range normal or uv index adds
    // nothing to the interpolation, as lancer's mesh hit completion does.
    struct Face {
        int position[3] = {0, 0, 0};
        int normal[3] = {-1, -1, -1};
        int uv[3] = {-1, -1, -1};
    };
    std::vector<DVec3> positions;
    std::vector<DVec3> normals;  // need not be unit
    std::vector<glm::dvec2> uvs;
    std::vector<Face> faces;
    // POV's inside_vector, in the mesh's object space: the direction of the
    // ray whose crossings decide inside. None (or a zero or non-finite
    // vector): the mesh has no inside, as in POV-Ray.
    std::optional<DVec3> inside_vector;
};

// The mesh as a Shape. `face` in crossings and surface() is the index into
// MeshShapeParameters::faces. Triangles of zero area or with a position
// index out of range or a non-finite corner are dropped (POV-Ray drops
// degenerate triangles while parsing). Null when no triangle is left.
std::shared_ptr<const Shape> make_mesh_shape(MeshShapeParameters mesh);

// Positions from lancer's packed float xyz arrays (MeshData::
// object_positions, whose trailing padding float is ignored).
std::vector<DVec3> mesh_positions_from_xyz(const std::vector<float>& xyz);

}  // namespace lancer
