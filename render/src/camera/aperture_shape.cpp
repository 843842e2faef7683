#include "camera/aperture_shape.h"

#include <algorithm>
#include <cmath>

#include "lancer/scene_error.h"
#include "materials/point_pigment.h"

namespace lancer {
namespace {

// Where u falls in a cumulative table cdf[0] = 0 <= ... <= cdf[n] = 1: the
// cell index plus the fraction of the way through it (empty cells are
// never chosen).
double invert(const std::vector<double>& cdf, std::size_t first, std::size_t cells, double u) {
    const auto begin = cdf.begin() + std::ptrdiff_t(first), end = begin + std::ptrdiff_t(cells) + 1;
    // The first cell whose upper edge lies above u.
    const auto upper = std::upper_bound(begin + 1, end, u);
    const std::size_t cell = std::size_t(std::min(upper, end - 1) - begin) - 1;
    const double low = begin[std::ptrdiff_t(cell)], high = begin[std::ptrdiff_t(cell) + 1];
    const double within = high > low ? std::clamp((u - low) / (high - low), 0.0, 1.0) : 0.5;
    return double(cell) + within;
}

}  // namespace

ApertureShape::ApertureShape(const PointPigment& pigment, const sg::SourceLocation& where) {
    constexpr int n = kResolution;
    std::vector<double> weights(std::size_t(n) * n);
    PatternContext context;
    for (int row = 0; row < n; ++row)
        for (int column = 0; column < n; ++column) {
            const glm::dvec3 point((column + 0.5) / n, (row + 0.5) / n, 0.0);
            context.hit_point = point;
            const double grey = pov_greyscale(pigment.at(point, context).rgb);
            if (!std::isfinite(grey))
                throw SceneError(where, "the bokeh pigment is not finite at <" + std::to_string(point.x) + ", " +
                                            std::to_string(point.y) + ", 0>");
            // POV accepts a lens point with probability min(grey, 1).
            weights[std::size_t(row) * n + column] = std::clamp(grey, 0.0, 1.0);
        }
    m_row_cdf.assign(n + 1, 0.0);
    m_cell_cdf.assign(std::size_t(n) * (n + 1), 0.0);
    for (int row = 0; row < n; ++row) {
        double* cdf = &m_cell_cdf[std::size_t(row) * (n + 1)];
        for (int column = 0; column < n; ++column)
            cdf[column + 1] = cdf[column] + weights[std::size_t(row) * n + column];
        const double row_total = cdf[n];
        m_row_cdf[row + 1] = m_row_cdf[row] + row_total;
        for (int column = 1; column <= n; ++column) cdf[column] = row_total > 0.0 ? cdf[column] / row_total : 0.0;
        if (row_total > 0.0) cdf[n] = 1.0;  // exactly, so that every u < 1 finds an open cell
    }
    const double total = m_row_cdf[n];
    if (!(total > 0.0))
        throw SceneError(where,
                         "the bokeh pigment is black over the whole lens (x and y from 0 to 1, z = 0): no light "
                         "would pass; POV-Ray reads its grey there as the lens' transmission");
    for (double& value : m_row_cdf) value /= total;
    m_row_cdf[n] = 1.0;
}

Vec2 ApertureShape::point(const Vec2& u) const {
    constexpr int n = kResolution;
    const double y = invert(m_row_cdf, 0, n, double(u.y));
    const std::size_t row = std::min(std::size_t(y), std::size_t(n - 1));
    const double x = invert(m_cell_cdf, row * (n + 1), n, double(u.x));
    return Vec2(float(x / n - 0.5), float(y / n - 0.5));
}

}  // namespace lancer
