// What the shape tests share: a line's crossings with a shape, sorted.
#pragma once

#include <algorithm>
#include <cmath>
#include <vector>

#include "geometry/shape.h"

namespace lancer::test {

inline std::vector<double> sorted_crossings(const Shape& shape, const DVec3& o, const DVec3& d, double t_min = 0.0,
                                            double t_max = INFINITY) {
    ShapeCrossings all;
    shape.crossings(o, d, t_min, t_max, all);
    std::vector<double> t;
    for (int i = 0; i < all.count; ++i) t.push_back(all.items[i].t);
    std::sort(t.begin(), t.end());
    return t;
}

}  // namespace lancer::test
