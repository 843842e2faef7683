// The gather integrator's point set: n points spread evenly on the unit
// sphere (a spherical Fibonacci lattice), with the jitter that smooths the
// image. Header-only so the statistical test checks the very code the
// plugin runs.
//
// Point i lies in the i-th of n bands of equal area (y from 1 - 2i/n down
// to 1 - 2(i+1)/n; equal y-steps are equal areas on a sphere), at longitude
// 2π·frac(i/φ) (φ the golden ratio), which spreads consecutive points evenly
// around the axis.
//
// Jitter j in [0, 1] moves every point within its band (by up to j/2 of the
// band's height either side of the centre) and turns the whole lattice about
// +y by a random angle in [0, 2πj). At j = 1 each point is uniform over its
// band (height uniform in the band, longitude uniform), so the pooled points
// are exactly uniform on the sphere and, for any unit N, normalize(s + N) is
// exactly cosine-distributed about N: the lattice then stratifies the
// hemisphere instead of fixing the directions. At j = 0 it is the fixed
// lattice of the seed.
#pragma once

#include <cmath>
#include <vector>

#include <lancer/ray.h>

namespace lancer {

class SphereLattice {
  public:
    explicit SphereLattice(int point_count) {
        const double golden_ratio = 0.5 * (1.0 + std::sqrt(5.0));
        m_longitudes.reserve(point_count);
        for (int i = 0; i < point_count; ++i) {
            const double turns = double(i) / golden_ratio;
            const double angle = 2.0 * double(kPi) * (turns - std::floor(turns));
            m_longitudes.push_back({float(std::cos(angle)), float(std::sin(angle))});
        }
    }

    int size() const { return int(m_longitudes.size()); }

    // A turn of the whole lattice about +y, shared by the points of one hit.
    struct Turn {
        float cos_angle = 1.0f;
        float sin_angle = 0.0f;
    };
    static Turn turn(float jitter, float u) {
        const float angle = 2.0f * kPi * jitter * u;
        return {std::cos(angle), std::sin(angle)};
    }

    // Point i, moved within its band by jitter j and u in [0, 1), turned by `turn`.
    Vec3 point(int i, float jitter, float u, const Turn& turn) const {
        const float band_position = 0.5f + jitter * (u - 0.5f);  // 0: top of the band, 1: bottom
        const float n = float(size());
        const float y = glm::clamp(1.0f - 2.0f * (float(i) + band_position) / n, -1.0f, 1.0f);
        const float ring = std::sqrt(glm::max(0.0f, 1.0f - y * y));
        const Vec2& longitude = m_longitudes[i];
        const float c = longitude.x * turn.cos_angle - longitude.y * turn.sin_angle;
        const float s = longitude.y * turn.cos_angle + longitude.x * turn.sin_angle;
        return {ring * c, y, ring * s};
    }

  private:
    std::vector<Vec2> m_longitudes;  // (cos, sin) of each point's longitude
};

}  // namespace lancer
