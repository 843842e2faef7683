// Closed 2-D curves made of POV-Ray's spline segments (linear, quadratic,
// cubic, Bezier), as the prism (and lathe and text after it) read them:
// each segment is p(s) = ((A s + B) s + C) s + D for s in [0, 1].
#pragma once

#include <vector>

#include <glm/glm.hpp>

namespace lancer {

enum class SplineKind { Linear, Quadratic, Cubic, Bezier };

struct SplineSegment {
    glm::dvec2 a{0.0}, b{0.0}, c{0.0}, d{0.0};
    glm::dvec2 at(double s) const { return ((a * s + b) * s + c) * s + d; }
    glm::dvec2 tangent(double s) const { return (3.0 * a * s + 2.0 * b) * s + c; }
};

// The segments POV-Ray's Compute_Prism makes of `points`: consecutive
// points (linear), or with the control points quadratic and cubic splines
// take before and after, or groups of four (Bezier); a loop ends where its
// first point comes again. Empty when there are too few points.
std::vector<SplineSegment> spline_segments(SplineKind kind, const std::vector<glm::dvec2>& points);

// The segments POV-Ray's Compute_Lathe makes of `points`: an open curve,
// each segment starting one point after the previous (four for Bezier).
std::vector<SplineSegment> open_spline_segments(SplineKind kind, const std::vector<glm::dvec2>& points);

// Parameters s in [0, 1) where segment coordinate `axis` (0: x, 1: y)
// equals `value`; returns how many (at most 3).
int segment_roots(const SplineSegment& segment, int axis, double value, double roots[3]);

// The box holding each segment's points for s in [0, 1], widened past the
// slack its roots are sought with: a line that misses it cannot meet the
// segment (what lets a text's many glyph curves be skipped).
struct SegmentBox {
    glm::dvec2 lower{0.0}, upper{0.0};
};
std::vector<SegmentBox> segment_boxes(const std::vector<SplineSegment>& segments);

// Even-odd: whether q is inside the closed curves (a ray from q along +x
// crosses them an odd number of times). `boxes` (segment_boxes) skip the
// segments that ray cannot cross.
bool inside_curves(const std::vector<SplineSegment>& segments, const std::vector<SegmentBox>& boxes,
                   const glm::dvec2& q);

}  // namespace lancer
