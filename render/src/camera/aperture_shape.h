// POV-Ray's bokeh: a pigment that shapes focal blur's lens. Its grey over
// x, y in [0, 1] (z = 0) is how much light each point of the square lens
// lets through; lens points are drawn in proportion to it (internal to
// liblancer).
#pragma once

#include <vector>

#include "lancer/ray.h"
#include "lancer/scene_graph.h"

namespace lancer {

class PointPigment;

class ApertureShape {
  public:
    // The pigment's grey is read at the centres of a kResolution² grid of
    // cells, clamped to [0, 1] as POV's acceptance test reads it; each cell is then open evenly. Throws
    // lancer::SceneError (at `where`) when the pigment is black everywhere
    // or not finite: no light would pass the lens.
    static constexpr int kResolution = 128;
    ApertureShape(const PointPigment& pigment, const sg::SourceLocation& where);

    // The lens point, in POV's sample-grid units (x, y in [-0.5, 0.5] with
    // the pigment's (0.5, 0.5) at the centre), that u in [0, 1)^2 maps to:
    // distributed as the lens' transmission (a piecewise-constant density;
    // u's strata stay compact along each row).
    Vec2 point(const Vec2& u) const;

  private:
    std::vector<double> m_row_cdf;   // kResolution + 1 entries, from 0 to 1
    std::vector<double> m_cell_cdf;  // per row, kResolution + 1 entries from 0 to 1
};

}  // namespace lancer
