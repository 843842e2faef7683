// Bands of a shape turned about the y axis (sor, lathe): each segment of
// its curve spans a range of heights and reaches a greatest radius, and a
// ray that never comes within that radius of the axis while it is at those
// heights cannot meet the segment, so its polynomial need not be solved
// (POV-Ray bounds each segment by a cylinder the same way). Internal to
// liblancer.
#pragma once

#include <algorithm>
#include <cmath>

#include "geometry/polynomial_roots.h"
#include "geometry/shapes.h"

namespace lancer {

// A segment's heights and greatest radius, widened by a margin.
struct RevolutionBand {
    double y_low = 0.0, y_high = 0.0;
    double radius = 0.0;

    // Whether o + t d, for t in [t_low, t_high] where its height lies in
    // the band, comes within the radius of the y axis.
    bool may_meet(const DVec3& o, const DVec3& d, double t_low, double t_high) const {
        if (d.y != 0.0) {
            double t1 = (y_low - o.y) / d.y, t2 = (y_high - o.y) / d.y;
            if (t1 > t2) std::swap(t1, t2);
            t_low = std::max(t_low, t1);
            t_high = std::min(t_high, t2);
            if (!(t_low <= t_high)) return false;
        } else if (!(o.y >= y_low && o.y <= y_high)) {
            return false;
        }
        // The distance to the axis squared is convex in t: least at the
        // foot of the perpendicular, or at the nearer end.
        const double across = d.x * d.x + d.z * d.z;
        double t = t_low;
        if (across > 0.0) t = std::clamp(-(o.x * d.x + o.z * d.z) / across, t_low, t_high);
        // Widened by the rounding of a ray from far away.
        const double x = o.x + t * d.x, z = o.z + t * d.z;
        const double reach = radius + 1e-13 * (std::fabs(o.x) + std::fabs(o.z));
        return !(x * x + z * z > reach * reach);
    }
};

}  // namespace lancer
