// POV-Ray's bicubic_patch: a cubic Bezier patch over 4 x 4 control points,
// drawn as POV-Ray 3.7 draws it, as the flat pieces of a subdivision (see
// bicubic_patch.cpp for the rules, the normals and the (u,v)).
#pragma once

#include <array>
#include <memory>

#include "geometry/shape.h"

namespace lancer {

// Finer subdivisions are clamped to this many halvings per direction
// (4^10 pieces per patch, ~200 MB; POV-Ray has no limit and runs out of
// memory instead). Pieces 1/1024 of the patch wide do not show as facets.
constexpr int kMaxBicubicPatchSteps = 10;

struct BicubicPatchParameters {
    // 0 (POV subdivides per ray) or 1 (POV subdivides once): the same
    // pieces either way. Negative is refused (POV: "Undefined bicubic patch
    // type."); above 1 is type 1 (POV warns "Patch type no longer supported.
    // Using type 1.").
    int type = 0;
    // A subpatch whose control points all lie closer than this to the plane
    // of three of its corners is not split further; 0 (POV's default) or
    // less: always split to u_steps, v_steps.
    double flatness = 0.0;
    // Halvings of the patch along u and v at most (POV's default 0: two
    // triangles); negative counts as 0, above kMaxBicubicPatchSteps is
    // clamped.
    int u_steps = 0, v_steps = 0;
    // Read by POV-Ray 3.7 and never used.
    double accuracy = 0.01;
    // The control points as written: points[4 * i + j] is row i (the patch
    // parameter u) and column j (the parameter v).
    std::array<DVec3, 16> points{};
    // uv_vectors: the texture (u,v) of the patch corners (u,v) = (0,0),
    // (0,1), (1,1), (1,0) in POV's (texture u follows the patch's v).
    std::array<glm::dvec2, 4> uv_corners{glm::dvec2(0.0, 0.0), glm::dvec2(1.0, 0.0), glm::dvec2(1.0, 1.0),
                                         glm::dvec2(0.0, 1.0)};
    // The object's transform, where POV-Ray has moved the control points
    // before it subdivides: flatness is a distance in those (world) units,
    // and a corner whose normal is undefined gets world +x as POV gives it.
    DMat4 world_from_object{1.0};
};

// Null when type < 0 or a control point is not finite.
std::shared_ptr<const Shape> make_bicubic_patch_shape(const BicubicPatchParameters& patch);

}  // namespace lancer
