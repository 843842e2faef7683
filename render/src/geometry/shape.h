// Analytic shapes behind one interface (internal to liblancer): what the
// Embree user geometry and CSG need of a surface, in the shape's own object
// space and in double precision (see shapes.h for why double).
//
// Each shape kind is one file of this room (cone.cpp, torus.cpp, disc.cpp,
// quadric.cpp, ...); spheres, boxes and planes also have the direct
// functions of shapes.h, which the fast paths for them call.
#pragma once

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

#include "geometry/planar_spline.h"
#include "geometry/shapes.h"

namespace lancer {

// Where a line crosses a surface: its parameter and which part of the
// shape (a cap, a side; the shape's own numbering) was crossed.
struct ShapeCrossing {
    double t = 0.0;
    int face = 0;
};

// The crossings of one line with one shape. No shape of POV-Ray's crosses a
// line more often than its degree allows; the highest here is 16.
struct ShapeCrossings {
    static constexpr int kCapacity = 16;
    // Left unwritten until added: zeroing 256 bytes for each shape a CSG
    // asks was a fifth of its crossing gathering (POV-Ray's abyss.pov).
    ShapeCrossings() {}
    union {
        ShapeCrossing items[kCapacity];
    };
    int count = 0;
    void add(double t, int face) {
        if (count < kCapacity) items[count++] = ShapeCrossing{t, face};
    }
};

class Shape {
  public:
    virtual ~Shape() = default;
    // Every crossing of o + t d (d need not be unit) with the surface for t
    // in the open interval (t_min, t_max), in any order.
    virtual void crossings(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossings& out) const = 0;
    // The nearest crossing; false if none. The first of crossings() with the
    // least t; a shape may find it without the others.
    virtual bool nearest(const DVec3& o, const DVec3& d, double t_min, double t_max, ShapeCrossing& hit) const;
    // Surface details at a point already on the shape, on `face`.
    virtual SurfaceGeometry surface(const DVec3& p, int face) const = 0;
    // surface() with the (u, v) left zero, for a scene whose textures read
    // none (SceneData::reads_surface_uv): a shape whose (u, v) costs an arc
    // tangent skips it.
    virtual SurfaceGeometry surface_without_uv(const DVec3& p, int face) const {
        SurfaceGeometry g = surface(p, face);
        g.uv = Vec2(0.0f);
        return g;
    }
    // POV-Ray's inside test (what CSG and clipped_by use): the solid the
    // surface bounds; for a flat or infinite shape POV's half-space.
    virtual bool inside(const DVec3& p) const = 0;
    // Object-space bounds; false for an unbounded shape.
    virtual bool bounds(DVec3& lower, DVec3& upper) const = 0;
    // Narrows the object-space box [lower, upper] (sides may be infinite)
    // to one that still holds all of the solid inside it (its complement
    // when `inverted`): how CSG bounds an intersection of unbounded shapes,
    // such as a quadric between two planes. The default keeps what bounds()
    // holds of an upright solid and leaves the box alone otherwise.
    virtual void narrow_box(DVec3& lower, DVec3& upper, bool inverted) const;
    // False for what POV-Ray calls a patch object (a triangle, a mesh
    // without inside_vector, a polygon, a bicubic patch): it has no inside,
    // inverted or not, and CSG only keeps or drops pieces of its surface.
    virtual bool solid() const { return true; }
    // False where the inside reaches beyond bounds(): a disc's inside is
    // POV's half-space behind it, its bounds only the flat disc.
    virtual bool inside_within_bounds() const { return true; }
    // False for a shape that searches from where a ray enters it and keeps
    // its first few roots (isosurface, parametric, julia_fractal): its
    // crossings past a t_min beyond the first are found only by a ray
    // started there, so a shadow ray's surfaces on it are walked, not
    // gathered (RenderScene::shadow_crossings).
    virtual bool finds_crossings_past_t_min() const { return true; }
};

// Newton steps from p along the gradient onto value = level (an implicit
// surface): a hit point from the ray carries the float rounding of its t,
// far more than the error bound spawned rays are offset by. Stops where the
// gradient vanishes or a step would leave the finite numbers.
template <class Value, class Gradient>
DVec3 project_onto_level(DVec3 p, const Value& value, const Gradient& gradient, double level) {
    for (int step = 0; step < 2; ++step) {
        const DVec3 g = gradient(p);
        const double length2 = glm::dot(g, g);
        if (!(length2 > 0.0)) break;
        const DVec3 moved = p - ((value(p) - level) / length2) * g;
        if (!std::isfinite(moved.x + moved.y + moved.z)) break;
        p = moved;
    }
    return p;
}

// Adds the roots of a polynomial solved from an origin moved `shift` along
// the ray (t = root + shift) that lie in (t_min, t_max).
inline void add_shifted_roots(const double* roots, int count, double shift, double t_min, double t_max, int face,
                              ShapeCrossings& out) {
    for (int i = 0; i < count; ++i) {
        const double t = roots[i] + shift;
        if (t > t_min && t < t_max) out.add(t, face);
    }
}

std::shared_ptr<const Shape> make_sphere_shape(const AnalyticSphere& sphere);
std::shared_ptr<const Shape> make_box_shape(const AnalyticBox& box);
std::shared_ptr<const Shape> make_plane_shape(const AnalyticPlane& plane);

// POV's cone and cylinder: the solid between the discs about `base` and
// `cap` (radii base_radius, cap_radius); `open` drops the end discs from the
// surface (not from the solid POV's inside test sees).
struct ConeParameters {
    DVec3 base{0.0};
    DVec3 cap{0.0, 1.0, 0.0};
    double base_radius = 1.0;
    double cap_radius = 1.0;
    bool open = false;
};
std::shared_ptr<const Shape> make_cone_shape(const ConeParameters& cone);

// POV's torus: about the y axis, centre at the origin.
std::shared_ptr<const Shape> make_torus_shape(double major_radius, double minor_radius);

// POV's disc: a flat ring about `center` facing `normal` (unit), between
// hole_radius and radius; its inside is the half-space behind the normal.
struct DiscParameters {
    DVec3 center{0.0};
    DVec3 normal{0.0, 1.0, 0.0};
    double radius = 1.0;
    double hole_radius = 0.0;
};
std::shared_ptr<const Shape> make_disc_shape(const DiscParameters& disc);

// POV's quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }: A x^2 + B y^2 + C z^2 +
// D xy + E xz + F yz + G x + H y + I z + J = 0.
struct QuadricParameters {
    DVec3 square_terms{1.0};
    DVec3 mixed_terms{0.0};
    DVec3 linear_terms{0.0};
    double constant = -1.0;
};
std::shared_ptr<const Shape> make_quadric_shape(const QuadricParameters& quadric);

// POV's poly { n, <coefficients> } (and cubic, n = 3; quartic, n = 4): the
// coefficients of x^i y^j z^k for i from n down to 0, then j from n - i
// down, then k from n - i - j down (POV's order). Null when the count is
// not polynomial_term_count(order), the order is out of range or every
// coefficient is 0.
constexpr int kMaxPolynomialShapeOrder = 15;
int polynomial_term_count(int order);
std::shared_ptr<const Shape> make_polynomial_shape(int order, const std::vector<double>& coefficients);

// POV's superellipsoid { <e, n> } (both positive): the unit box-bounded
// solid ((|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n)) <= 1.
// Exponents are capped at kMaxSuperellipsoidExponent.
constexpr double kMaxSuperellipsoidExponent = 100.0;
std::shared_ptr<const Shape> make_superellipsoid_shape(double east_west, double north_south);

// POV's blob: components (spheres about `center`; cylinders from `center`
// to `apex` with hemispherical ends), each in its own space
// (blob_from_component), adding strength (1 - r^2/radius^2)^2 within reach;
// the surface is where the sum equals the threshold.
struct BlobComponent {
    enum class Kind { Sphere, Cylinder };
    Kind kind = Kind::Sphere;
    DVec3 center{0.0};
    DVec3 apex{0.0};
    double radius = 1.0;
    double strength = 1.0;
    DMat4 blob_from_component{1.0};
};
struct BlobParameters {
    double threshold = 1.0;
    std::vector<BlobComponent> components;
};
std::shared_ptr<const Shape> make_blob_shape(BlobParameters blob);

// POV's prism: closed curves of `points` (x, z) swept along y from height1
// to height2, straight or (conic) towards the origin; `open` drops the caps.
struct PrismParameters {
    SplineKind spline = SplineKind::Linear;
    std::vector<glm::dvec2> points;
    double height1 = 0.0, height2 = 1.0;
    bool conic = false;
    bool open = false;
};
std::shared_ptr<const Shape> make_prism_shape(const PrismParameters& prism);

// POV's lathe: the open spline curve through `points` <r, y> turned about y.
std::shared_ptr<const Shape> make_lathe_shape(SplineKind spline, const std::vector<glm::dvec2>& points);

// POV's text: closed curves in the x-y plane extruded along z from 0 to
// thickness (a prism on its side). Null without segments.
std::shared_ptr<const Shape> make_text_shape(std::vector<SplineSegment> segments, double thickness);
// A linear-sweep prism straight from its curve segments.
std::shared_ptr<const Shape> make_prism_shape(std::vector<SplineSegment> segments, double height1, double height2);

// POV's sor: points <r, y> (at least four, the first and last control
// points only); null when two points a segment spans share a height.
std::shared_ptr<const Shape> make_sor_shape(const std::vector<glm::dvec2>& points, bool open);

// POV's polygon: its points as written (a loop closes where a point repeats
// the loop's first). Null when no loop of three points spans a plane.
std::shared_ptr<const Shape> make_polygon_shape(const std::vector<DVec3>& points);

// Narrows (t_min, t_max) to the stretch of o + t d (one axis's o and d,
// `inverse` = 1 / d) between the planes at lower and upper; false when
// none of it is.
inline bool ray_slab_interval(double o, double d, double inverse, double lower, double upper, double& t_min,
                              double& t_max) {
    if (d == 0.0) return !(o < lower || o > upper);
    double t0 = (lower - o) * inverse, t1 = (upper - o) * inverse;
    if (t0 > t1) std::swap(t0, t1);
    t_min = std::max(t_min, t0);
    t_max = std::min(t_max, t1);
    return !(t_min > t_max);
}

// Narrows (t_min, t_max) to the stretch of o + t d inside the box
// [lower, upper]; false when none of it is.
bool ray_box_interval(const DVec3& lower, const DVec3& upper, const DVec3& o, const DVec3& d, double& t_min,
                      double& t_max);

}  // namespace lancer
