// POV-Ray's focal blur sample layout (FocalBlurData in tracepixel.cpp of
// POV-Ray 3.7, read for its rules): with N blur samples, the largest of
// its standard grids that N covers (4 points on a square, or the
// hexagonal lattices of 1, 2 and 3 rings around the centre: 7, 19 and 37
// points), then the remaining points spread over the disc; each sample
// is jittered by up to half the lattice spacing (0.5 / sqrt(N) when N is
// not a grid's own size).
#include "host/aperture_samples.h"

#include <cmath>

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

ApertureSamples::ApertureSamples(int blur_samples, bool pov_pattern) {
    if (!pov_pattern || blur_samples <= 0) return;
    const int n = blur_samples;
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
    const int rest = n - int(grid.size());
    const double golden_angle = kPiDouble * (3.0 - std::sqrt(5.0));
    for (int k = 0; k < rest; ++k) {
        const double radius = 0.5 * std::sqrt((k + 0.5) / rest), theta = k * golden_angle;
        grid.emplace_back(float(radius * std::cos(theta)), float(radius * std::sin(theta)));
    }
    m_grid = std::move(grid);
}

Vec2 ApertureSamples::point(std::uint32_t index, const Vec2& u) const {
    if (m_grid.empty()) return concentric_disc_point(u);
    const Vec2 jitter = (2.0f * u - 1.0f) * m_max_jitter;
    return m_grid[index % m_grid.size()] + jitter;
}

}  // namespace lancer
