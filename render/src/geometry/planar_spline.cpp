// POV-Ray's spline segments in the plane (planar_spline.h).
#include "geometry/planar_spline.h"

#include <algorithm>
#include <cmath>

#include "geometry/polynomial_roots.h"

namespace lancer {

std::vector<SplineSegment> spline_segments(SplineKind kind, const std::vector<glm::dvec2>& p) {
    std::vector<SplineSegment> segments;
    const int n = int(p.size());
    if (n < 2) return segments;
    glm::dvec2 first = kind == SplineKind::Linear || kind == SplineKind::Bezier ? p[0] : p[std::min(1, n - 1)];
    for (int i = 0; i < n - 1; ++i) {
        const int i1 = i + 1, i2 = i + 2, i3 = i + 3;
        SplineSegment s;
        switch (kind) {
        case SplineKind::Linear:
            s.c = p[i1] - p[i];
            s.d = p[i];
            break;
        case SplineKind::Quadratic:
            if (i2 >= n) return segments;
            s.b = 0.5 * p[i] - p[i1] + 0.5 * p[i2];
            s.c = -0.5 * p[i] + 0.5 * p[i2];
            s.d = p[i1];
            break;
        case SplineKind::Cubic:
            if (i3 >= n) return segments;
            s.a = -0.5 * p[i] + 1.5 * p[i1] - 1.5 * p[i2] + 0.5 * p[i3];
            s.b = p[i] - 2.5 * p[i1] + 2.0 * p[i2] - 0.5 * p[i3];
            s.c = -0.5 * p[i] + 0.5 * p[i2];
            s.d = p[i1];
            break;
        case SplineKind::Bezier:
            if (i3 >= n) return segments;
            s.a = p[i3] - 3.0 * p[i2] + 3.0 * p[i1] - p[i];
            s.b = 3.0 * p[i2] - 6.0 * p[i1] + 3.0 * p[i];
            s.c = 3.0 * p[i1] - 3.0 * p[i];
            s.d = p[i];
            break;
        }
        segments.push_back(s);
        // POV's Compute_Prism: where the loop's first point comes again,
        // skip the control points and start the next loop.
        constexpr double kEpsilon = 1e-10;
        auto is_first = [&](int index) {
            return index < n && std::fabs(p[index].x - first.x) < kEpsilon &&
                   std::fabs(p[index].y - first.y) < kEpsilon;
        };
        switch (kind) {
        case SplineKind::Linear:
            if (is_first(i1)) {
                ++i;
                if (i + 1 < n) first = p[i + 1];
            }
            break;
        case SplineKind::Quadratic:
            if (is_first(i2)) {
                i += 2;
                if (i + 2 < n) first = p[i + 2];
            }
            break;
        case SplineKind::Cubic:
            if (is_first(i2)) {
                i += 3;
                if (i + 2 < n) first = p[i + 2];
            }
            break;
        case SplineKind::Bezier: i += 3; break;
        }
    }
    return segments;
}

std::vector<SplineSegment> open_spline_segments(SplineKind kind, const std::vector<glm::dvec2>& p) {
    std::vector<SplineSegment> segments;
    const int n = int(p.size());
    const int count = kind == SplineKind::Linear      ? n - 1
                      : kind == SplineKind::Quadratic ? n - 2
                      : kind == SplineKind::Cubic     ? n - 3
                                                      : n / 4;
    for (int k = 0, i = 0; k < count; ++k) {
        // The closed-curve reading of these points, one segment at a time.
        const int used = kind == SplineKind::Linear ? 2 : kind == SplineKind::Quadratic ? 3 : 4;
        std::vector<glm::dvec2> window(p.begin() + i, p.begin() + i + used);
        std::vector<SplineSegment> one = spline_segments(kind, window);
        if (!one.empty()) segments.push_back(one.front());
        i += kind == SplineKind::Bezier ? 4 : 1;
    }
    return segments;
}

int segment_roots(const SplineSegment& segment, int axis, double value, double roots[3]) {
    const double c[4] = {segment.d[axis] - value, segment.c[axis], segment.b[axis], segment.a[axis]};
    int degree = 3;
    while (degree > 0 && c[degree] == 0.0) --degree;
    if (degree == 0) return 0;
    double found[kMaxPolynomialDegree];
    // A little past each end, then kept half-open: a curve's shared end
    // point belongs to one segment only.
    const int n = polynomial_roots_in(c, degree, -1e-12, 1.0 + 1e-12, found);
    int count = 0;
    for (int i = 0; i < n && count < 3; ++i) {
        const double s = std::min(std::max(found[i], 0.0), 1.0);
        if (s < 1.0) roots[count++] = s;
    }
    return count;
}

std::vector<SegmentBox> segment_boxes(const std::vector<SplineSegment>& segments) {
    std::vector<SegmentBox> boxes;
    boxes.reserve(segments.size());
    double reach = 0.0;  // the largest coordinate of the whole curve
    for (const SplineSegment& segment : segments) {
        SegmentBox box;
        for (int axis = 0; axis < 2; ++axis) {
            const double c[4] = {segment.d[axis], segment.c[axis], segment.b[axis], segment.a[axis]};
            cubic_range(c, 0.0, 1.0, box.lower[axis], box.upper[axis]);
            reach = std::max({reach, std::fabs(box.lower[axis]), std::fabs(box.upper[axis])});
        }
        boxes.push_back(box);
    }
    // Roots are sought a little past each end (segment_roots), and the
    // ranges and the points rays are tested at round: a margin of the
    // curve's size, not the segment's (a glyph's baseline lies at 0).
    const double margin = 1e-9 * reach + 1e-12;
    for (SegmentBox& box : boxes) {
        box.lower -= margin;
        box.upper += margin;
    }
    return boxes;
}

bool inside_curves(const std::vector<SplineSegment>& segments, const std::vector<SegmentBox>& boxes,
                   const glm::dvec2& q) {
    bool inside = false;
    for (std::size_t index = 0; index < segments.size(); ++index) {
        const SplineSegment& segment = segments[index];
        const SegmentBox& box = boxes[index];
        // Not at q's height, or wholly behind q: no crossing counts.
        if (q.y < box.lower.y || q.y > box.upper.y || box.upper.x <= q.x) continue;
        // Linear segments by the half-open rule, exact at vertices.
        if (segment.a == glm::dvec2(0.0) && segment.b == glm::dvec2(0.0)) {
            const glm::dvec2 p0 = segment.d, p1 = segment.d + segment.c;
            if ((p0.y > q.y) != (p1.y > q.y) && q.x < p0.x + (q.y - p0.y) * (p1.x - p0.x) / (p1.y - p0.y))
                inside = !inside;
            continue;
        }
        double roots[3];
        const int n = segment_roots(segment, 1, q.y, roots);
        for (int i = 0; i < n; ++i)
            if (segment.at(roots[i]).x > q.x) inside = !inside;
    }
    return inside;
}

}  // namespace lancer
