// libFuzzer target for the analytic shapes' parameters (issues 16, 18): the
// input picks a shape and its parameters, then rays. Every crossing must be
// finite and inside the ray's interval and the shape's bounds, every
// surface normal finite and of unit length; nothing may crash or hang.
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <vector>

#include "geometry/bicubic_patch.h"
#include "geometry/height_field.h"
#include "geometry/isosurface.h"
#include "geometry/julia_fractal.h"
#include "geometry/ovus.h"
#include "geometry/parametric.h"
#include "geometry/shape.h"
#include "geometry/sphere_sweep.h"

namespace {

using lancer::DVec3;

class Input {
  public:
    Input(const std::uint8_t* data, std::size_t size) : m_data(data), m_size(size) {}
    std::uint8_t byte() { return m_offset < m_size ? m_data[m_offset++] : 0; }
    // A value in [-range, range], sometimes at the extremes POV scenes reach.
    double number(double range) {
        std::uint32_t bits = 0;
        for (int i = 0; i < 4; ++i) bits = bits << 8 | byte();
        const double unit = double(bits) / 4294967295.0 * 2.0 - 1.0;
        switch (bits & 7) {
        case 0: return unit * 1e-6;
        case 1: return unit * 1e5;
        default: return unit * range;
        }
    }
    DVec3 vector(double range) { return DVec3(number(range), number(range), number(range)); }
    bool empty() const { return m_offset >= m_size; }

  private:
    const std::uint8_t* m_data;
    std::size_t m_size;
    std::size_t m_offset = 0;
};

const char* g_kind = "";  // the shape under test, for the failure message
char g_parameters[256] = "";

[[noreturn]] void fail(const char* what, double value) {
    std::fprintf(stderr, "fuzz_shapes: %s (%s): %s (%g)\n", g_kind, g_parameters, what, value);
    std::abort();
}

std::shared_ptr<const lancer::Shape> make_shape(Input& in) {
    // 18 kinds: a regression file's first byte (below 17 for the first
    // seventeen) keeps naming its shape.
    static const char* const kinds[] = {"cone",          "torus",          "disc",         "quadric", "poly",
                                        "polygon",       "superellipsoid", "sphere",       "ovus",    "sphere_sweep",
                                        "bicubic_patch", "julia_fractal",  "height_field", "blob",    "lathe",
                                        "sor",           "isosurface",     "parametric"};
    const int kind = in.byte() % 18;
    g_kind = kinds[kind];
    g_parameters[0] = 0;
    switch (kind) {
    case 0: {
        lancer::ConeParameters cone;
        cone.base = in.vector(4);
        cone.cap = in.vector(4);
        if (!(glm::length(cone.cap - cone.base) > 1e-9)) return nullptr;
        cone.base_radius = std::fabs(in.number(3));
        cone.cap_radius = in.byte() & 1 ? cone.base_radius : std::fabs(in.number(3));
        cone.open = in.byte() & 1;
        std::snprintf(g_parameters, sizeof g_parameters, "base %g %g %g r %g cap %g %g %g r %g", cone.base.x,
                      cone.base.y, cone.base.z, cone.base_radius, cone.cap.x, cone.cap.y, cone.cap.z, cone.cap_radius);
        return lancer::make_cone_shape(cone);
    }
    case 1: {
        const double major = std::fabs(in.number(4)), minor = std::fabs(in.number(2)) + 1e-9;
        std::snprintf(g_parameters, sizeof g_parameters, "major %.17g minor %.17g", major, minor);
        return lancer::make_torus_shape(major, minor);
    }
    case 2: {
        lancer::DiscParameters disc;
        disc.center = in.vector(4);
        const DVec3 normal = in.vector(1);
        if (!(glm::length(normal) > 1e-9)) return nullptr;
        disc.normal = glm::normalize(normal);
        disc.radius = std::fabs(in.number(3));
        disc.hole_radius = std::fabs(in.number(3));
        return lancer::make_disc_shape(disc);
    }
    case 3: return lancer::make_quadric_shape({in.vector(3), in.vector(3), in.vector(3), in.number(3)});
    case 4: {
        const int order = 2 + in.byte() % 5;
        std::vector<double> coefficients(std::size_t(lancer::polynomial_term_count(order)));
        for (double& c : coefficients) c = in.byte() & 1 ? 0.0 : in.number(2);
        return lancer::make_polynomial_shape(order, coefficients);
    }
    case 5: {
        std::vector<DVec3> points(3 + in.byte() % 14);
        for (DVec3& p : points) p = in.vector(3);
        if (in.byte() & 1) points.push_back(points.front());
        return lancer::make_polygon_shape(points);
    }
    case 6: {
        const double e = 0.05 + std::fabs(in.number(3)), n = 0.05 + std::fabs(in.number(3));
        std::snprintf(g_parameters, sizeof g_parameters, "e %.17g n %.17g", e, n);
        return lancer::make_superellipsoid_shape(e, n);
    }
    case 7: return lancer::make_sphere_shape({in.vector(3), std::fabs(in.number(3))});
    case 8: {
        const double bottom = std::fabs(in.number(3)), top = std::fabs(in.number(3));
        std::snprintf(g_parameters, sizeof g_parameters, "bottom %.17g top %.17g", bottom, top);
        return lancer::make_ovus_shape(bottom, top);
    }
    case 9: {
        const auto spline = lancer::SphereSweepSpline(in.byte() % 3);
        std::vector<glm::dvec4> spheres(2 + in.byte() % 8);
        for (auto& sphere : spheres) sphere = glm::dvec4(in.vector(3), std::fabs(in.number(1)));
        return lancer::make_sphere_sweep_shape(spline, spheres, in.byte() & 1 ? 1e-6 : std::fabs(in.number(1)));
    }
    case 10: {
        lancer::BicubicPatchParameters patch;
        patch.type = in.byte() % 2;
        patch.u_steps = in.byte() % 6;
        patch.v_steps = in.byte() % 6;
        patch.flatness = in.byte() & 1 ? 0.0 : std::fabs(in.number(1));
        for (auto& p : patch.points) p = in.vector(3);
        return lancer::make_bicubic_patch_shape(patch);
    }
    case 11: {
        lancer::JuliaFractalParameters julia;
        julia.julia_parameter = glm::dvec4(in.vector(1), in.number(1));
        julia.algebra = in.byte() & 1 ? lancer::JuliaFractalParameters::Algebra::Hypercomplex
                                      : lancer::JuliaFractalParameters::Algebra::Quaternion;
        julia.function = lancer::JuliaFractalParameters::Function(in.byte() % 18);
        julia.power = glm::dvec2(in.number(3), in.number(3));
        julia.max_iteration = 1 + in.byte() % 40;
        julia.precision = 1.0 + std::fabs(in.number(50));
        julia.slice_normal = glm::dvec4(in.vector(1), in.number(1));
        julia.slice_distance = in.number(1);
        return lancer::make_julia_fractal_shape(julia);
    }
    case 12: {
        lancer::HeightFieldGrid grid;
        grid.columns = 2 + in.byte() % 20;
        grid.rows = 2 + in.byte() % 20;
        grid.heights.resize(std::size_t(grid.columns) * grid.rows);
        for (float& h : grid.heights) h = float(in.byte()) / 255.0f;
        return lancer::make_height_field_shape(std::move(grid), in.byte() & 1, in.byte() / 255.0);
    }
    case 13: {
        lancer::BlobParameters blob;
        blob.threshold = in.number(2);
        blob.components.resize(1 + in.byte() % 6);
        for (auto& c : blob.components) {
            c.kind = in.byte() & 1 ? lancer::BlobComponent::Kind::Cylinder : lancer::BlobComponent::Kind::Sphere;
            c.center = in.vector(2);
            c.apex = in.vector(2);
            c.radius = std::fabs(in.number(2)) + 1e-6;
            c.strength = in.number(3);
        }
        return lancer::make_blob_shape(blob);
    }
    case 14: {
        std::vector<glm::dvec2> points(2 + in.byte() % 10);
        for (auto& p : points) p = glm::dvec2(std::fabs(in.number(2)), in.number(3));
        return lancer::make_lathe_shape(lancer::SplineKind(in.byte() % 4), points);
    }
    case 15: {
        std::vector<glm::dvec2> points(4 + in.byte() % 8);
        for (auto& p : points) p = glm::dvec2(std::fabs(in.number(2)), in.number(3));
        return lancer::make_sor_shape(points, in.byte() & 1);
    }
    default: {
        // a (x^2 + y^2 + z^2) - b + c sin(k x) sin(k z), in a box or sphere.
        using Op = lancer::sg::Function::Op;
        auto f = std::make_shared<lancer::sg::Function>();
        f->parameters = {"x", "y", "z"};
        f->constants = {in.number(3), in.number(3), in.number(2), in.number(40)};
        const auto op = [](Op code, int index = 0) {
            lancer::sg::Function::Instruction instruction;
            instruction.op = code;
            instruction.index = index;
            return instruction;
        };
        const int sin_code = lancer::sg::Function::Sin;
        f->code = {op(Op::Parameter, 0),    op(Op::Parameter, 0), op(Op::Multiply),     op(Op::Parameter, 1),
                   op(Op::Parameter, 1),    op(Op::Multiply),     op(Op::Add),          op(Op::Parameter, 2),
                   op(Op::Parameter, 2),    op(Op::Multiply),     op(Op::Add),          op(Op::Constant, 0),
                   op(Op::Multiply),        op(Op::Constant, 1),  op(Op::Subtract),     op(Op::Constant, 2),
                   op(Op::Constant, 3),     op(Op::Parameter, 0), op(Op::Multiply),     op(Op::Math1, sin_code),
                   op(Op::Multiply),        op(Op::Constant, 3),  op(Op::Parameter, 2), op(Op::Multiply),
                   op(Op::Math1, sin_code), op(Op::Multiply),     op(Op::Add)};
        f->stack_size = 4;
        lancer::IsosurfaceParameters iso;
        iso.function = f;
        iso.container.sphere = in.byte() & 1;
        iso.container.box_lower = in.vector(4);
        iso.container.box_upper = in.vector(4);
        iso.container.sphere_center = in.vector(4);
        iso.container.sphere_radius = std::fabs(in.number(4));
        iso.threshold = in.number(2);
        iso.accuracy = std::fabs(in.number(0.1));
        iso.max_gradient = std::fabs(in.number(50));
        iso.evaluate = in.byte() & 1;
        iso.evaluate_parameters = glm::abs(in.vector(3));
        iso.open = in.byte() & 1;
        iso.max_trace = 1 + in.byte() % 10;
        std::snprintf(g_parameters, sizeof g_parameters, "a %g b %g c %g k %g accuracy %g max_gradient %g",
                      f->constants[0], f->constants[1], f->constants[2], f->constants[3], iso.accuracy,
                      iso.max_gradient);
        return lancer::make_isosurface_shape(iso);
    }
    case 17: {
        using Op = lancer::sg::Function::Op;
        // x = a sin(k u) v, y = b cos(v), z = c u: a wavy sheet whose
        // bounds the fuzzer may make loose (max_gradient, range) or tight.
        const double a = in.number(3), b = in.number(3), c = in.number(3), k = in.number(40);
        const auto constant = [](double value) {
            auto f = std::make_shared<lancer::sg::Function>();
            f->parameters = {"x", "y", "z"};
            f->constants = {value};
            return f;
        };
        const auto op = [](Op code, int index = 0) {
            lancer::sg::Function::Instruction instruction;
            instruction.op = code;
            instruction.index = index;
            return instruction;
        };
        auto fx = constant(a), fy = constant(b), fz = constant(c);
        fx->constants.push_back(k);
        fx->code = {op(Op::Constant, 0),
                    op(Op::Constant, 1),
                    op(Op::Parameter, 0),
                    op(Op::Multiply),
                    op(Op::Math1, lancer::sg::Function::Sin),
                    op(Op::Multiply),
                    op(Op::Parameter, 1),
                    op(Op::Multiply)};
        fy->code = {op(Op::Constant, 0), op(Op::Parameter, 1), op(Op::Math1, lancer::sg::Function::Cos),
                    op(Op::Multiply)};
        fz->code = {op(Op::Constant, 0), op(Op::Parameter, 0), op(Op::Multiply)};
        fx->stack_size = fy->stack_size = fz->stack_size = 3;
        lancer::ParametricParameters parametric;
        parametric.functions = {fx, fy, fz};
        parametric.uv_min = {in.number(10), in.number(10)};
        parametric.uv_max = {in.number(10), in.number(10)};
        parametric.container.sphere = in.byte() & 1;
        parametric.container.box_lower = in.vector(4);
        parametric.container.box_upper = in.vector(4);
        parametric.container.sphere_center = in.vector(4);
        parametric.container.sphere_radius = std::fabs(in.number(4));
        parametric.accuracy = std::fabs(in.number(0.1));
        parametric.max_gradient = std::fabs(in.number(50));
        if (in.byte() & 1) {
            parametric.precompute_depth = 1 + in.byte() % 12;
            parametric.precompute_axes = 1 + in.byte() % 7;
        }
        std::snprintf(g_parameters, sizeof g_parameters, "a %g b %g c %g k %g accuracy %g max_gradient %g", a, b, c, k,
                      parametric.accuracy, parametric.max_gradient);
        return lancer::make_parametric_shape(parametric);
    }
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    Input in(data, size);
    const auto shape = make_shape(in);
    if (!shape) return 0;
    DVec3 lower, upper;
    const bool bounded = shape->bounds(lower, upper);
    for (int ray = 0; ray < 8 && !in.empty(); ++ray) {
        const DVec3 o = in.vector(10);
        const DVec3 d = in.vector(2);
        if (!(glm::length(d) > 1e-9)) continue;
        const double t_min = in.byte() & 1 ? 0.0 : std::fabs(in.number(2));
        const double t_max = in.byte() & 1 ? INFINITY : t_min + std::fabs(in.number(50));
        lancer::ShapeCrossings crossings;
        shape->crossings(o, d, t_min, t_max, crossings);
        for (int i = 0; i < crossings.count; ++i) {
            const double t = crossings.items[i].t;
            if (!std::isfinite(t)) fail("non-finite crossing", t);
            if (!(t > t_min && t < t_max)) fail("crossing outside the ray's interval", t);
            const DVec3 p = o + t * d;
            if (bounded) {
                const double slack = 1e-6 * (1.0 + glm::length(upper - lower)) + 1e-9 * glm::length(o);
                for (int axis = 0; axis < 3; ++axis)
                    if (p[axis] < lower[axis] - slack || p[axis] > upper[axis] + slack) {
                        std::fprintf(stderr, "axis %d: %.17g not in [%.17g, %.17g], o %g %g %g d %g %g %g t %.17g\n",
                                     axis, p[axis], lower[axis], upper[axis], o.x, o.y, o.z, d.x, d.y, d.z, t);
                        fail("crossing outside the shape's bounds", p[axis]);
                    }
            }
            const lancer::SurfaceGeometry g = shape->surface(p, crossings.items[i].face);
            const double length = glm::length(g.normal);
            if (!std::isfinite(length) || std::fabs(length - 1.0) > 1e-6)
                fail("surface normal not of unit length", length);
            if (!std::isfinite(g.point.x + g.point.y + g.point.z)) fail("non-finite surface point", 0.0);
            (void)shape->inside(p);
        }
    }
    return 0;
}
