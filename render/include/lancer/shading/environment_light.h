// What escaping rays see (the background, or POV's sky_sphere) as a light
// for next-event estimation. The sky's brightness is tabulated over a grid
// of latitude-longitude cells and directions are drawn in proportion to
// it, so a small bright patch (a sun drawn in a sky pigment) is found by
// shadow rays instead of waiting for a bounce to hit it by chance.
//
// The table only guides the choice: sample() returns the sky's true
// radiance in the chosen direction (RenderScene::background), and every
// direction keeps a non-zero density, so an estimator weighting by pdf()
// stays unbiased however coarse the grid is against the sky's detail.
#pragma once

#include <vector>

#include "lancer/light.h"

namespace lancer {

class RenderScene;

class EnvironmentLight final : public Light {
  public:
    // Tabulates scene.background() over `columns` (longitude) by `rows`
    // (latitude, from +y down) cells, probed at 2x2 directions in each; a
    // cell is drawn in proportion to its solid angle times the brightest
    // probe among it and its neighbours. `scene` must outlive the light.
    explicit EnvironmentLight(const RenderScene& scene, int columns = 256, int rows = 128);

    Kind kind() const override { return Kind::Environment; }
    // A direction drawn by the table; `point` lies kDistance along it,
    // where escaping rays end for participating media.
    LightSample sample(const Vec3& p, const Vec2& u) const override;
    float pdf(const Vec3& p, const Vec3& wi, const Hit& light_hit) const override { return pdf(wi); }
    // Solid-angle density of sample() drawing the unit direction `wi`.
    float pdf(const Vec3& wi) const;
    // 4 pi times the table's mean brightness (grey): only a scale for
    // light selection, which `path` does not use (the sky takes a fixed
    // share of its draws).
    Color power() const override { return m_power; }

    static constexpr float kDistance = 2.0e10f;  // POV's BOUND_HUGE, as kMediaEscapeDistance

  private:
    int cell_of(int row, float phi) const;

    const RenderScene& m_scene;
    int m_columns, m_rows;
    std::vector<float> m_row_cdf;     // rows + 1 entries, 0 to 1
    std::vector<float> m_column_cdf;  // per row, columns + 1 entries, 0 to 1
    std::vector<float> m_cell_pdf;    // solid-angle density inside each cell
    Color m_power{0.0f};
};

}  // namespace lancer
