// Where on the lens each camera sample of a focal-blurred render starts
// (Camera::generate_ray's `lens`, in POV's sample-grid units: the disc of
// radius 0.5). Internal to liblancer.
#pragma once

#include <cstdint>
#include <vector>

#include "camera/aperture_shape.h"
#include "lancer/ray.h"

namespace lancer {

class ApertureSamples {
  public:
    // `pov_pattern`: POV-Ray's own layout (its 4-point square or 7-, 19-
    // and 37-point hexagonal grids, jittered, the rest spread evenly over
    // the disc), for the deterministic integrators that reproduce POV's
    // pictures; otherwise each sample is uniform over the disc, so a Monte
    // Carlo integrator stays unbiased with a thin lens. With a `bokeh`
    // (which must outlive this), the lens is its shape instead: POV's
    // pattern is blur_samples points spread in proportion to its
    // transmission, jittered as above; a Monte Carlo sample is drawn from
    // it.
    ApertureSamples(int blur_samples, bool pov_pattern, const ApertureShape* bokeh = nullptr);

    // The lens point of a pixel's sample `index`, from a uniform pair u
    // in [0, 1)^2 (the sample's own random numbers).
    Vec2 point(std::uint32_t index, const Vec2& u) const;

  private:
    std::vector<Vec2> m_grid;  // POV's pattern, one point per blur sample; empty: uniform
    float m_max_jitter = 0.0f;
    const ApertureShape* m_bokeh = nullptr;
};

// The uniform point of the disc of radius 0.5 that u in [0, 1)^2 maps to
// (Shirley and Chiu's concentric map: strata stay compact).
Vec2 concentric_disc_point(const Vec2& u);

}  // namespace lancer
