// Triangulation of one polygon (an OBJ face) in O(n log n) at worst.
//
// tinyobjloader's ear clipping takes time growing with the square of a
// face's size (a face of 200,000 vertices took 55 s); this one is a fan when
// the face is verified convex, and otherwise a decomposition into y-monotone
// pieces by a plane sweep (de Berg et al., Computational Geometry, ch. 3),
// each piece triangulated in linear time.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "lancer/scene_graph.h"

namespace lancer::parse {

struct PolygonTriangulation {
    enum class Kind {
        Convex,     // a fan (a convex quad is split along its shorter diagonal, as tinyobjloader does)
        General,    // a simple polygon, concave: monotone pieces
        NotSimple,  // the boundary crosses or touches itself: a fan, which the caller should report
        NoArea,     // fewer than three distinct corners, or all on one line: no triangles
    };
    Kind kind = Kind::NoArea;
    // Corners of each triangle as indices into the polygon's points, wound
    // as the polygon is (so a face's normal keeps its side).
    std::vector<std::array<std::uint32_t, 3>> triangles;
};

// Triangulates the closed polygon `points` (in order, at least 3). A polygon
// that is not planar is triangulated as its projection on the plane of its
// Newell normal (the plane it is closest to lying in); duplicate consecutive
// corners are skipped. Time O(n log n), memory O(n).
PolygonTriangulation triangulate_polygon(const std::vector<sg::Vec3>& points);

}  // namespace lancer::parse
