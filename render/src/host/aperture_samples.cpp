// POV-Ray's focal blur sample layout (FocalBlurData in tracepixel.cpp of
// POV-Ray 3.7, read for its rules): with N blur samples, the largest of
// its standard grids that N covers (4 points on a square, or the
// hexagonal lattices of 1, 2 and 3 rings around the centre: 7, 19 and 37
// points), then the remaining points spread over the disc; each sample
// is jittered by up to half the lattice spacing (0.5 / sqrt(N) when N is
// not a grid's own size).
#include "host/aperture_samples.h"

#include <cmath>
#include <limits>

#include "sampling/bit_reversal.h"

namespace lancer {
namespace {

constexpr double kPiDouble = 3.14159265358979323846;

// The hexagonal lattice of `rings` rings around the centre, spanning the
// disc of radius 0.5 less half a spacing: spacing 1 / ((rings + 1) sqrt 3).
std::vector<Vec2> hexagonal_grid(int rings) {
    const double spacing = 1.0 / ((rings + 1) * std::sqrt(3.0));
    std::vector<Vec2> points;
    for (int i = -rings; i <= rings; ++i)
        for (int j = -rings; j <= rings; ++j) {
            // Axial coordinates: the ring is the hexagonal distance.
            if (std::abs(i + j) > rings) continue;
            const double x = spacing * (i + 0.5 * j), y = spacing * (std::sqrt(3.0) / 2.0) * j;
            points.emplace_back(float(x), float(y));
        }
    return points;
}

// Past a few thousand points a point set keeps its own order: ordering
// costs the square of the count.
constexpr int kMostSpreadPoints = 2048;

// The points reordered so that every prefix spreads over the lens: the
// centre-most first, then each time the point farthest from those already
// taken (ties to the earlier one). A pixel that POV's confidence test stops
// after a batch has seen the whole aperture, not one side of it.
std::vector<Vec2> spread_order(std::vector<Vec2> points) {
    if (points.empty()) return points;
    std::vector<Vec2> ordered;
    ordered.reserve(points.size());
    std::size_t first = 0;
    for (std::size_t i = 1; i < points.size(); ++i)
        if (glm::length(points[i]) < glm::length(points[first]) - 1e-6f) first = i;
    std::vector<float> nearest(points.size(), std::numeric_limits<float>::infinity());
    std::vector<bool> taken(points.size(), false);
    for (std::size_t next = first; ordered.size() < points.size();) {
        taken[next] = true;
        ordered.push_back(points[next]);
        std::size_t farthest = points.size();
        for (std::size_t i = 0; i < points.size(); ++i) {
            if (taken[i]) continue;
            nearest[i] = std::min(nearest[i], glm::length(points[i] - points[next]));
            if (farthest == points.size() || nearest[i] > nearest[farthest] + 1e-6f) farthest = i;
        }
        next = farthest;
    }
    return ordered;
}

}  // namespace

Vec2 concentric_disc_point(const Vec2& u) {
    const double a = 2.0 * u.x - 1.0, b = 2.0 * u.y - 1.0;
    if (a == 0.0 && b == 0.0) return Vec2(0.0f);
    double radius, theta;
    if (std::fabs(a) > std::fabs(b)) {
        radius = a;
        theta = (kPiDouble / 4.0) * (b / a);
    } else {
        radius = b;
        theta = kPiDouble / 2.0 - (kPiDouble / 4.0) * (a / b);
    }
    return Vec2(float(0.5 * radius * std::cos(theta)), float(0.5 * radius * std::sin(theta)));
}

ApertureSamples::ApertureSamples(int blur_samples, bool pov_pattern, const ApertureShape* bokeh) : m_bokeh(bokeh) {
    if (!pov_pattern || blur_samples <= 0) return;
    const int n = blur_samples;
    if (bokeh) {
        // A Hammersley set carried through the shape's distribution: as
        // evenly spread as the shape allows (POV draws its points by
        // rejection from a sub-random sequence).
        std::vector<Vec2> points;
        for (int k = 0; k < n; ++k)
            points.push_back(bokeh->point(Vec2(float(radical_inverse_base2(std::uint32_t(k))), float((k + 0.5) / n))));
        m_max_jitter = float(0.5 / std::sqrt(double(n)));
        m_grid = n <= kMostSpreadPoints ? spread_order(std::move(points)) : std::move(points);
        return;
    }
    // The largest standard grid n covers.
    std::vector<Vec2> grid;
    int rings = 0;
    if (n >= 37)
        rings = 3;
    else if (n >= 19)
        rings = 2;
    else if (n >= 7)
        rings = 1;
    if (rings > 0) {
        grid = hexagonal_grid(rings);
    } else {
        grid = {Vec2(-0.25f, 0.25f), Vec2(0.25f, 0.25f), Vec2(-0.25f, -0.25f), Vec2(0.25f, -0.25f)};
    }
    const bool exact_hexagon = rings > 0 && int(grid.size()) == n;
    m_max_jitter = exact_hexagon ? float(0.5 / (std::sqrt(3.0) * (rings + 1))) : float(0.5 / std::sqrt(double(n)));
    if (int(grid.size()) > n) grid.resize(std::size_t(n));
    // The rest evenly over the disc: a golden-angle spiral of equal areas
    // (POV draws them from a sub-random sequence, avoiding taken cells).
    // Each part is spread in order (the standard grid's batches come first);
    // past a few thousand points the spiral's own order, centre outwards, is
    // kept: ordering costs the square of the count.
    const int rest = n - int(grid.size());
    const double golden_angle = kPiDouble * (3.0 - std::sqrt(5.0));
    std::vector<Vec2> spiral;
    for (int k = 0; k < rest; ++k) {
        const double radius = 0.5 * std::sqrt((k + 0.5) / rest), theta = k * golden_angle;
        spiral.emplace_back(float(radius * std::cos(theta)), float(radius * std::sin(theta)));
    }
    m_grid = spread_order(std::move(grid));
    if (rest <= kMostSpreadPoints) spiral = spread_order(std::move(spiral));
    m_grid.insert(m_grid.end(), spiral.begin(), spiral.end());
}

Vec2 ApertureSamples::point(std::uint32_t index, const Vec2& u) const {
    if (m_grid.empty()) return m_bokeh ? m_bokeh->point(u) : concentric_disc_point(u);
    const Vec2 jitter = (2.0f * u - 1.0f) * m_max_jitter;
    return m_grid[index % m_grid.size()] + jitter;
}

}  // namespace lancer
