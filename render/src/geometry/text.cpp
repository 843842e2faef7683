// POV-Ray's text: its glyph outlines (x-y, from the parser's FreeType
// reading) extruded along z from 0 to the thickness. That is a prism lying
// on its side, so the shape is prism.cpp's with y and z swapped; POV-Ray
// gives text no (u, v): lancer gives (0, 0).
#include <utility>

#include "geometry/shape.h"

namespace lancer {
namespace {

DVec3 swap_yz(const DVec3& v) {
    return DVec3(v.x, v.z, v.y);
}

class TextShape final : public Shape {
  public:
    explicit TextShape(std::shared_ptr<const Shape> prism) : m_prism(std::move(prism)) {}
    void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const override {
        m_prism->crossings(swap_yz(o), swap_yz(d), t_min, t_max, out);
    }
    SurfaceGeometry surface(const DVec3& p, int face) const override {
        SurfaceGeometry g = m_prism->surface(swap_yz(p), face);
        g.point = swap_yz(g.point);
        g.normal = swap_yz(g.normal);
        return g;
    }
    bool inside(const DVec3& p) const override { return m_prism->inside(swap_yz(p)); }
    bool bounds(DVec3& lower, DVec3& upper) const override {
        if (!m_prism->bounds(lower, upper)) return false;
        lower = swap_yz(lower);
        upper = swap_yz(upper);
        return true;
    }

  private:
    std::shared_ptr<const Shape> m_prism;
};

}  // namespace

std::shared_ptr<const Shape> make_text_shape(std::vector<SplineSegment> segments, double thickness) {
    auto prism = make_prism_shape(std::move(segments), 0.0, thickness);
    if (!prism) return nullptr;
    return std::make_shared<TextShape>(std::move(prism));
}

}  // namespace lancer
