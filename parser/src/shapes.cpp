// POV-Ray's quadric-family primitives: cylinder, cone, torus, disc,
// quadric, with POV-Ray 3.7's argument order, defaults and checks
// (Parse_Cone, Parse_Cylinder, Parse_Torus, Parse_Disc, Parse_Quadric there).
#include <algorithm>
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {

namespace {

constexpr int kMaxPolynomialOrder = 15;  // the renderer's root finder's degree

// POV's loops of points (Parse_Polygon, Parse_Prism): a loop ends where
// its first point comes again, the next starts after it. Closes an open
// last loop by repeating its first point; true if it had to.
template <class Point>
bool close_last_loop(std::vector<Point>& points) {
    std::size_t start = 0;
    bool closed = false;
    for (std::size_t i = 1; i < points.size(); ++i) {
        closed = false;
        if (points[i] == points[start]) {
            closed = true;
            start = i + 1;
            ++i;
        }
    }
    if (closed || start >= points.size()) return false;
    points.push_back(points[start]);
    return true;
}

}  // namespace

ShapePtr Evaluator::make_cone(const std::vector<Value>& values, const std::vector<SourceRange>& where, bool open,
                              const sg::SourceLocation& at, bool cylinder) {
    auto shape = new_shape(cylinder ? sg::Object::Kind::Cylinder : sg::Object::Kind::Cone, at);
    const char* name = cylinder ? "cylinder" : "cone";
    sg::Cone cone;
    cone.base = to_vec3(values[0], where[0]);
    cone.base_radius = to_float(values[1], where[1], std::string("a float ") + (cylinder ? "radius" : "base radius"));
    cone.cap = to_vec3(values[2], where[2]);
    cone.cap_radius = to_float(values[3], where[3], std::string("a float ") + (cylinder ? "radius" : "cap radius"));
    cone.open = open;
    if (!check_renderable(&cone.base_radius, 1, where[1], "the radius")) cone.base_radius = 1.0;
    if (!check_renderable(&cone.cap_radius, 1, where[3], "the radius")) cone.cap_radius = 1.0;
    if (!(glm::length(cone.cap - cone.base) > 0.0)) {
        error(where[2].begin, std::string("degenerate ") + name + ": its base and cap points are the same");
        cone.cap = cone.base + sg::Vec3(0.0, 1.0, 0.0);
    }
    for (int k : {1, 3}) {
        double& radius = k == 1 ? cone.base_radius : cone.cap_radius;
        if (radius < 0.0) {
            warning(where[k].begin, std::string("negative ") + name + " radius; using its magnitude");
            radius = -radius;
        }
        if (cylinder) break;
    }
    if (cylinder) cone.cap_radius = cone.base_radius;
    if (cylinder && cone.base_radius == 0.0) error(where[1].begin, "cylinder radius must be positive, got 0");
    if (!cylinder && cone.base_radius == 0.0 && cone.cap_radius == 0.0)
        error(where[3].begin, "degenerate cone: both radii are 0");
    shape->object.shape = cone;
    return shape;
}

ShapePtr Evaluator::make_torus(const Value& major, const SourceRange& wm, const Value& minor, const SourceRange& wn,
                               const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Torus, at);
    sg::Torus torus;
    torus.major_radius = to_float(major, wm, "a float major radius");
    torus.minor_radius = to_float(minor, wn, "a float minor radius");
    if (!check_renderable(&torus.major_radius, 1, wm, "the torus major radius")) torus.major_radius = 1.0;
    if (!check_renderable(&torus.minor_radius, 1, wn, "the torus minor radius")) torus.minor_radius = 0.25;
    // POV-Ray: a negative radius turns the torus inside out.
    for (double* radius : {&torus.major_radius, &torus.minor_radius}) {
        if (*radius >= 0.0) continue;
        warning(radius == &torus.major_radius ? wm.begin : wn.begin,
                "negative torus radius has the effect of inverting the object; if this is intentional, use the "
                "'inverse' keyword instead");
        *radius = -*radius;
        shape->object.inverse = !shape->object.inverse;
    }
    if (torus.minor_radius == 0.0) error(wn.begin, "torus minor radius must be positive, got 0");
    shape->object.shape = torus;
    return shape;
}

ShapePtr Evaluator::make_disc(const std::vector<Value>& values, const std::vector<SourceRange>& where,
                              const std::optional<std::pair<Value, SourceRange>>& hole, const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Disc, at);
    sg::Disc disc;
    disc.center = to_vec3(values[0], where[0]);
    disc.normal = glm::normalize(nonzero_vec3(values[1], where[1], "the disc normal"));
    disc.radius = std::fabs(to_float(values[2], where[2], "a float radius"));
    if (!check_renderable(&disc.radius, 1, where[2], "the disc radius")) disc.radius = 1.0;
    if (hole) {
        disc.hole_radius = std::fabs(to_float(hole->first, hole->second, "a float hole radius"));
        if (!check_renderable(&disc.hole_radius, 1, hole->second, "the disc hole radius")) disc.hole_radius = 0.0;
        if (disc.hole_radius >= disc.radius)
            warning(hole->second.begin, "the disc's hole radius is not smaller than its radius: nothing is left");
    }
    shape->object.shape = disc;
    return shape;
}

ShapePtr Evaluator::make_quadric(const std::vector<Value>& values, const std::vector<SourceRange>& where,
                                 const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Quadric, at);
    sg::Quadric quadric;
    quadric.square_terms = to_vec3(values[0], where[0]);
    quadric.mixed_terms = to_vec3(values[1], where[1]);
    quadric.linear_terms = to_vec3(values[2], where[2]);
    quadric.constant = to_float(values[3], where[3], "a float constant term");
    if (!check_renderable(&quadric.constant, 1, where[3], "the quadric's constant")) quadric.constant = 0.0;
    if (quadric.square_terms == sg::Vec3(0.0) && quadric.mixed_terms == sg::Vec3(0.0) &&
        quadric.linear_terms == sg::Vec3(0.0))
        error(where[0].begin, "quadric has no term in x, y or z: it is no surface");
    shape->object.shape = quadric;
    return shape;
}

ShapePtr Evaluator::make_superellipsoid(const Value& exponents, const SourceRange& where,
                                        const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Superellipsoid, at);
    sg::Superellipsoid superellipsoid;
    if (exponents.kind != Value::Kind::Vector && exponents.kind != Value::Kind::Float) {
        error(where.begin, "superellipsoid needs a 2-D vector <e, n>");
    } else {
        // A float stands for <f, f>, as POV's Parse_UV_Vect reads it.
        superellipsoid.east_west = exponents.v[0];
        superellipsoid.north_south = exponents.kind == Value::Kind::Float ? exponents.v[0] : exponents.v[1];
        double both[2] = {superellipsoid.east_west, superellipsoid.north_south};
        if (!check_renderable(both, 2, where, "the superellipsoid's exponents")) {
            superellipsoid = sg::Superellipsoid{};
        } else if (!(both[0] > 0.0 && both[1] > 0.0)) {
            error(where.begin, "superellipsoid exponents must be positive");
            superellipsoid = sg::Superellipsoid{};
        } else if (both[0] > 100.0 || both[1] > 100.0) {
            // The renderer's cap: beyond it the shape's powers overflow.
            warning(where.begin, "superellipsoid exponents above 100 are taken as 100");
            superellipsoid.east_west = std::min(both[0], 100.0);
            superellipsoid.north_south = std::min(both[1], 100.0);
        }
    }
    shape->object.shape = superellipsoid;
    return shape;
}

ShapePtr Evaluator::make_prism(const Edits<sg::Prism>& options, const std::vector<Value>& values,
                               const std::vector<SourceRange>& where, const std::vector<Value>& points,
                               const SourceRange& wp, bool open, const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Prism, at);
    sg::Prism prism;
    for (const auto& option : options) option(prism);
    prism.open = open;
    prism.height1 = to_float(values[0], where[0], "a float height");
    prism.height2 = to_float(values[1], where[1], "a float height");
    double heights[2] = {prism.height1, prism.height2};
    if (!check_renderable(heights, 2, where[0], "the prism's heights")) prism.height1 = 0, prism.height2 = 1;
    if (prism.height1 > prism.height2) std::swap(prism.height1, prism.height2);
    const int n = to_int(values[2], where[2]);
    using Spline = sg::Prism::Spline;
    // POV-Ray's Parse_Prism checks.
    if (prism.spline == Spline::Linear && n < 3)
        error(where[2].begin, "prism with linear splines must have at least three points");
    if (prism.spline == Spline::Quadratic && n < 5)
        error(where[2].begin, "prism with quadratic splines must have at least five points");
    if (prism.spline == Spline::Cubic && n < 6)
        error(where[2].begin, "prism with cubic splines must have at least six points");
    if (prism.spline == Spline::Bezier && (n <= 0 || n % 4 != 0))
        error(where[2].begin, "prism with Bezier splines must have four points per segment");
    if (n > 0 && std::size_t(n) != points.size())
        error(wp.begin,
              "prism: " + std::to_string(n) + " points announced, " + std::to_string(points.size()) + " given");
    for (const Value& point : points) {
        if (point.kind == Value::Kind::Float) {
            prism.points.push_back(sg::Vec2(point.v[0], point.v[0]));
        } else if (point.kind == Value::Kind::Vector) {
            prism.points.push_back(sg::Vec2(point.v[0], point.v[1]));
        } else {
            error(wp.begin, "prism points are 2-D vectors <x, z>");
        }
    }
    for (const sg::Vec2& p : prism.points) {
        double xy[2] = {p.x, p.y};
        if (!check_renderable(xy, 2, wp, "a prism point")) break;
    }
    // POV-Ray: an open last loop of a linear prism is closed, with a warning.
    if (prism.spline == Spline::Linear && prism.points.size() >= 3 && close_last_loop(prism.points))
        warning(at, "linear prism not closed; closing it (as POV-Ray does)");
    shape->object.shape = std::move(prism);
    return shape;
}

ShapePtr Evaluator::make_lathe(const Edits<sg::Prism>& options, const Value& count, const SourceRange& wc,
                               const std::vector<Value>& points, const SourceRange& wp, const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Lathe, at);
    sg::Prism settings;
    for (const auto& option : options) option(settings);
    if (settings.conic) error(at, "a lathe has no sweep (linear_sweep and conic_sweep belong to prism)");
    sg::Lathe lathe;
    lathe.spline = settings.spline;
    const int n = to_int(count, wc);
    using Spline = sg::Prism::Spline;
    // POV-Ray's Parse_Lathe checks.
    if (lathe.spline == Spline::Linear && n < 2)
        error(wc.begin, "lathe with linear splines must have at least two points");
    if (lathe.spline == Spline::Quadratic && n < 3)
        error(wc.begin, "lathe with quadratic splines must have at least three points");
    if (lathe.spline == Spline::Cubic && n < 4)
        error(wc.begin, "lathe with cubic splines must have at least four points");
    if (lathe.spline == Spline::Bezier && (n <= 0 || n % 4 != 0))
        error(wc.begin, "lathe with Bezier splines must have four points per segment");
    if (n > 0 && std::size_t(n) != points.size())
        error(wp.begin,
              "lathe: " + std::to_string(n) + " points announced, " + std::to_string(points.size()) + " given");
    for (const Value& point : points) {
        if (point.kind == Value::Kind::Float) {
            lathe.points.push_back(sg::Vec2(point.v[0], point.v[0]));
        } else if (point.kind == Value::Kind::Vector) {
            lathe.points.push_back(sg::Vec2(point.v[0], point.v[1]));
        } else {
            error(wp.begin, "lathe points are 2-D vectors <radius, y>");
            lathe.points.push_back(sg::Vec2(0.0));
        }
        double xy[2] = {lathe.points.back().x, lathe.points.back().y};
        if (!check_renderable(xy, 2, wp, "a lathe point")) lathe.points.back() = sg::Vec2(0.0);
    }
    shape->object.shape = std::move(lathe);
    return shape;
}

ShapePtr Evaluator::make_sor(const Value& count, const SourceRange& wc, const std::vector<Value>& points,
                             const SourceRange& wp, bool open, const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Sor, at);
    sg::Sor sor;
    sor.open = open;
    const int n = to_int(count, wc);
    if (n < 4) error(wc.begin, "sor needs at least four points, got " + std::to_string(n));
    if (n >= 4 && std::size_t(n) != points.size())
        error(wp.begin, "sor: " + std::to_string(n) + " points announced, " + std::to_string(points.size()) + " given");
    for (const Value& point : points) {
        if (point.kind == Value::Kind::Vector) {
            sor.points.push_back(sg::Vec2(point.v[0], point.v[1]));
        } else {
            error(wp.begin, "sor points are 2-D vectors <radius, y>");
            sor.points.push_back(sg::Vec2(0.0));
        }
        double xy[2] = {sor.points.back().x, sor.points.back().y};
        if (!check_renderable(xy, 2, wp, "a sor point")) sor.points.back() = sg::Vec2(0.0);
    }
    // POV-Ray's checks (Parse_Sor): radii not negative, heights rising
    // from the second point to the last but one.
    bool rising = true;
    for (std::size_t i = 0; i < sor.points.size() && rising; ++i) {
        const sg::SourceLocation where = i < points.size() && points[i].location.file ? points[i].location : wp.begin;
        if (sor.points[i].x < 0.0) {
            error(where, "incorrect point in surface of revolution: point " + std::to_string(i + 1) +
                             " has a negative radius");
            rising = false;
        } else if (i > 1 && i + 1 < sor.points.size() && !(sor.points[i].y > sor.points[i - 1].y)) {
            error(where, "incorrect point in surface of revolution: point " + std::to_string(i + 1) +
                             " is not above point " + std::to_string(i) +
                             " (the heights of the second to the last but one point must rise)");
            rising = false;
        }
    }
    for (std::size_t i = 0; rising && i + 2 < sor.points.size(); ++i)
        if (sor.points[i + 2].y == sor.points[i].y) {
            error(wp.begin, "incorrect point in surface of revolution: points " + std::to_string(i + 1) + " and " +
                                std::to_string(i + 3) + " share a height");
            break;
        }
    shape->object.shape = std::move(sor);
    return shape;
}

ShapePtr Evaluator::make_blob(const Edits<sg::Blob>& items, const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Blob, at);
    sg::Blob blob;
    for (const auto& item : items) item(blob);
    if (blob.components.empty()) error(at, "blob needs at least one component");
    if (!check_renderable(&blob.threshold, 1, SourceRange{at, at}, "the blob threshold")) blob.threshold = 1.0;
    if (blob.threshold <= 0.0) warning(at, "a blob threshold at or below 0 makes all space outside it inside");
    shape->object.shape = std::move(blob);
    return shape;
}

std::function<void(sg::Blob&)> Evaluator::blob_component(bool cylinder, const std::vector<Value>& values,
                                                         const std::vector<SourceRange>& where,
                                                         const Edits<sg::Blob::Component>& mods,
                                                         const sg::SourceLocation& at) {
    sg::Blob::Component component;
    component.kind = cylinder ? sg::Blob::Component::Kind::Cylinder : sg::Blob::Component::Kind::Sphere;
    component.center = to_vec3(values[0], where[0]);
    component.apex = to_vec3(values[1], where[1]);
    component.radius = to_float(values[2], where[2], "a float radius");
    component.strength = to_float(values[3], where[3], "a float strength");
    component.location = at;
    double numbers[2] = {component.radius, component.strength};
    if (!check_renderable(numbers, 2, where[2], "the blob component's radius and strength")) {
        component.radius = 1.0;
        component.strength = 0.0;
    }
    if (component.radius == 0.0) warning(where[2].begin, "a blob component of radius 0 adds nothing");
    if (cylinder && !(glm::length(component.apex - component.center) > 0.0))
        error(where[1].begin, "degenerate cylindrical component in blob: its two ends are the same point");
    for (const auto& mod : mods) mod(component);
    return [component](sg::Blob& blob) { blob.components.push_back(component); };
}

ShapePtr Evaluator::make_polygon(const Value& count, const SourceRange& wc, const std::vector<Value>& points,
                                 const SourceRange& wp, const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Polygon, at);
    sg::Polygon polygon;
    const int n = to_int(count, wc);
    if (n < 3) error(wc.begin, "polygon needs at least three points, got " + std::to_string(n));
    if (n >= 3 && std::size_t(n) != points.size())
        error(wp.begin,
              "polygon: " + std::to_string(n) + " points announced, " + std::to_string(points.size()) + " given");
    for (const Value& point : points) {
        const SourceRange where{point.location, point.location};
        polygon.points.push_back(to_vec3(point, point.location.file ? where : wp));
    }
    // POV-Ray: an open last loop is closed, with a warning.
    if (polygon.points.size() >= 3 && close_last_loop(polygon.points))
        warning(at, "polygon not closed; closing it (as POV-Ray does)");
    shape->object.shape = std::move(polygon);
    return shape;
}

ShapePtr Evaluator::make_polynomial(sg::Object::Kind kind, const Value& order_value, const SourceRange& wo,
                                    const std::vector<Value>& coefficients, const SourceRange& wc,
                                    const sg::SourceLocation& at) {
    auto shape = new_shape(kind, at);
    sg::Polynomial polynomial;
    polynomial.order = to_int(order_value, wo);
    if (polynomial.order < 2 || polynomial.order > kMaxPolynomialOrder) {
        error(wo.begin, "poly order must be 2 to " + std::to_string(kMaxPolynomialOrder) + ", got " +
                            std::to_string(polynomial.order));
        polynomial.order = 2;
    }
    const int n = polynomial.order;
    const std::size_t expected = std::size_t((n + 1) * (n + 2) * (n + 3) / 6);
    if (coefficients.size() != expected)
        error(wc.begin, "a polynomial of order " + std::to_string(n) + " has " + std::to_string(expected) +
                            " coefficients, got " + std::to_string(coefficients.size()));
    for (const Value& c : coefficients) polynomial.coefficients.push_back(to_float(c, wc, "a float coefficient"));
    if (!check_renderable(polynomial.coefficients.data(), int(polynomial.coefficients.size()), wc,
                          "the polynomial's coefficients"))
        polynomial.coefficients.assign(polynomial.coefficients.size(), 0.0);
    shape->object.shape = std::move(polynomial);
    return shape;
}

namespace {

// Where x^i y^j z^k sits in POV's coefficient order (make_polynomial); -1
// when i + j + k exceeds the order.
int polynomial_term_index(int order, int i, int j, int k) {
    int index = 0;
    for (int x = order; x >= 0; --x)
        for (int y = order - x; y >= 0; --y)
            for (int z = order - x - y; z >= 0; --z, ++index)
                if (x == i && y == j && z == k) return index;
    return -1;
}

}  // namespace

std::function<void(sg::Polynomial&)> Evaluator::polynomial_term(const std::vector<Value>& values,
                                                                const std::vector<SourceRange>& where) {
    int powers[3];
    for (int axis = 0; axis < 3; ++axis) powers[axis] = to_int(values[axis], where[axis]);
    double coefficient = to_float(values[3], where[3], "a float coefficient");
    if (!check_renderable(&coefficient, 1, where[3], "the coefficient")) coefficient = 0.0;
    const sg::SourceLocation at = where[0].begin;
    return [this, powers0 = powers[0], powers1 = powers[1], powers2 = powers[2], coefficient,
            at](sg::Polynomial& polynomial) {
        const int index = powers0 < 0 || powers1 < 0 || powers2 < 0
                              ? -1
                              : polynomial_term_index(polynomial.order, powers0, powers1, powers2);
        if (index < 0) {
            error(at, "xyz(" + std::to_string(powers0) + ", " + std::to_string(powers1) + ", " +
                          std::to_string(powers2) + ") is not a term of a polynomial of order " +
                          std::to_string(polynomial.order) + " (POV-Ray's \"coefficient of polynom is out of range\")");
            return;
        }
        polynomial.coefficients[std::size_t(index)] = coefficient;
    };
}

ShapePtr Evaluator::make_polynomial_from_terms(const Value& order_value, const SourceRange& wo,
                                               const Edits<sg::Polynomial>& terms, const sg::SourceLocation& at) {
    // The order's checks and the coefficient count are make_polynomial's.
    int order = to_int(order_value, wo);
    const bool valid = order >= 2 && order <= kMaxPolynomialOrder;
    if (!valid) order = 2;  // make_polynomial says why
    std::vector<Value> zeros(std::size_t((order + 1) * (order + 2) * (order + 3) / 6), Value::number(0.0));
    auto shape = make_polynomial(sg::Object::Kind::Poly, order_value, wo, zeros, wo, at);
    auto& polynomial = std::get<sg::Polynomial>(shape->object.shape);
    if (valid)
        for (const auto& term : terms) term(polynomial);
    return shape;
}

}  // namespace lancer::parse
