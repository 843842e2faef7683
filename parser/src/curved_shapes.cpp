// POV-Ray's ovus, sphere_sweep, bicubic_patch, julia_fractal and
// height_field: their arguments, defaults and checks as POV-Ray 3.7 reads
// them (Parse_Ovus, Parse_Sphere_Sweep, Parse_Bicubic_Patch,
// Parse_Julia_Fractal and Parse_HField in its parse.cpp).
#include <algorithm>
#include <cctype>
#include <cmath>
#include <filesystem>

#include "evaluator.h"

namespace lancer::parse {

namespace {

// A 4-D vector as POV's Parse_Vector4D reads one: a float stands for all
// four components; a shorter vector is padded with zeros.
bool four_components(const Value& value, glm::dvec4& out) {
    if (value.kind == Value::Kind::Float) {
        out = glm::dvec4(value.v[0]);
        return true;
    }
    if (value.kind != Value::Kind::Vector && value.kind != Value::Kind::Color) return false;
    out = glm::dvec4(0.0);
    for (int i = 0; i < std::min(value.size, 4); ++i) out[i] = value.v[std::size_t(i)];
    return true;
}

}  // namespace

// ----------------------------------------------------------------- ovus

ShapePtr Evaluator::make_ovus(const Value& bottom, const SourceRange& wb, const Value& top, const SourceRange& wt,
                              const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Ovus, at);
    sg::Ovus ovus;
    ovus.bottom_radius = to_float(bottom, wb, "a float bottom radius");
    ovus.top_radius = to_float(top, wt, "a float top radius");
    double both[2] = {ovus.bottom_radius, ovus.top_radius};
    if (!check_renderable(both, 2, wb, "the ovus' radii")) {
        ovus = sg::Ovus{};
    } else if (!(ovus.bottom_radius > 0.0)) {
        error(wb.begin, "ovus: the bottom radius must be positive");
        ovus = sg::Ovus{};
    } else if (ovus.top_radius < 0.0) {
        error(wt.begin, "ovus: the top radius must not be negative (POV-Ray's \"both ovus radii must be positive\")");
        ovus = sg::Ovus{};
    } else if (ovus.top_radius >= 2.0 * ovus.bottom_radius) {
        warning(wt.begin,
                "ovus: a top radius of twice the bottom radius or more makes a sphere; POV-Ray substitutes "
                "sphere { <0, bottom_radius, 0>, top_radius }, and so does lancer");
    }
    shape->object.shape = ovus;
    return shape;
}

// ---------------------------------------------------------- sphere_sweep

ShapePtr Evaluator::make_sphere_sweep(int spline, const Value& count_value, const SourceRange& wc,
                                      const std::vector<Value>& items, const SourceRange& wi,
                                      const std::optional<std::pair<Value, SourceRange>>& tolerance,
                                      const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::SphereSweep, at);
    sg::SphereSweep sweep;
    sweep.spline = sg::SphereSweep::Spline(spline);
    const int count = to_int(count_value, wc);
    const int least = sweep.spline == sg::SphereSweep::Spline::Linear ? 2 : 4;
    if (count < least) {
        error(wc.begin, "sphere_sweep: a " +
                            std::string(sweep.spline == sg::SphereSweep::Spline::Linear ? "linear_spline" : "spline") +
                            " sweep needs at least " + std::to_string(least) + " spheres, got " +
                            std::to_string(count) + " (POV-Ray's \"too few modeling spheres\")");
    } else if (items.size() != std::size_t(count) * 2) {
        error(wi.begin, "sphere_sweep: " + std::to_string(count) + " spheres need " + std::to_string(2 * count) +
                            " values (a centre and a radius each), got " + std::to_string(items.size()));
    } else {
        for (int i = 0; i < count; ++i) {
            const Value& centre = items[std::size_t(2 * i)];
            const Value& radius = items[std::size_t(2 * i + 1)];
            const SourceRange wcentre{centre.location, centre.location};
            const SourceRange wradius{radius.location, radius.location};
            sg::SphereSweep::Sphere sphere;
            sphere.center = to_vec3(centre, wcentre);
            sphere.radius = to_float(radius, wradius, "a float radius");
            double values[4] = {sphere.center.x, sphere.center.y, sphere.center.z, sphere.radius};
            if (!check_renderable(values, 4, wcentre, "the sphere")) continue;
            sphere.radius = std::fabs(sphere.radius);  // POV-Ray does not check; its magnitude counts
            sweep.spheres.push_back(sphere);
        }
    }
    if (tolerance) {
        sweep.tolerance = to_float(tolerance->first, tolerance->second, "a float tolerance");
        if (!check_renderable(&sweep.tolerance, 1, tolerance->second, "the tolerance") || sweep.tolerance < 0.0) {
            if (sweep.tolerance < 0.0)
                error(tolerance->second.begin, "sphere_sweep: the tolerance must not be negative");
            sweep.tolerance = 1e-6;
        }
    }
    if (sweep.spheres.size() != std::size_t(std::max(count, 0))) sweep.spheres.clear();
    shape->object.shape = std::move(sweep);
    return shape;
}

// --------------------------------------------------------- bicubic_patch

std::function<void(sg::BicubicPatch&)> Evaluator::patch_option(const std::string& keyword, const Value& value,
                                                               const SourceRange& where) {
    if (keyword == "type") {
        int type = to_int(value, where);
        if (type < 0) {
            error(where.begin, "bicubic_patch: type must be 0 or 1, got " + std::to_string(type));
            type = 0;
        } else if (type > 1) {
            warning(where.begin, "bicubic_patch type " + std::to_string(type) +
                                     " is no longer supported; using type 1 (as POV-Ray)");
            type = 1;
        }
        return [type](sg::BicubicPatch& p) { p.type = type; };
    }
    if (keyword == "u_steps" || keyword == "v_steps") {
        int steps = to_int(value, where);
        constexpr int kMaxSteps = 10;  // 2^10 x 2^10 pieces: 2 million triangles
        if (steps < 0 || steps > kMaxSteps) {
            error(where.begin, "bicubic_patch: " + keyword + " must be 0 to " + std::to_string(kMaxSteps) + ", got " +
                                   std::to_string(steps));
            steps = std::clamp(steps, 0, kMaxSteps);
        }
        if (keyword == "u_steps") return [steps](sg::BicubicPatch& p) { p.u_steps = steps; };
        return [steps](sg::BicubicPatch& p) { p.v_steps = steps; };
    }
    double number = to_float(value, where, "a float " + keyword);
    if (!check_renderable(&number, 1, where, "the " + keyword)) number = 0.0;
    if (keyword == "flatness") return [number](sg::BicubicPatch& p) { p.flatness = number; };
    // accuracy: POV's limit on subdividing type 0 patches, which lancer
    // meets through u_steps and v_steps.
    return [](sg::BicubicPatch&) {};
}

bool Evaluator::to_uv(const Value& c, const SourceRange& where, sg::Vec2& uv) {
    if (c.kind == Value::Kind::Vector && c.size >= 2) {
        uv = sg::Vec2(c.v[0], c.v[1]);
    } else if (c.kind == Value::Kind::Float) {
        uv = sg::Vec2(c.v[0]);
    } else {
        error(where.begin, "uv_vectors expects 2-D vectors <u, v>");
        return false;
    }
    double both[2] = {uv.x, uv.y};
    return check_renderable(both, 2, where, "the uv vector");
}

std::function<void(sg::BicubicPatch&)> Evaluator::patch_uv_vectors(const std::vector<Value>& corners,
                                                                   const std::vector<SourceRange>& where) {
    sg::Vec2 uv[4];
    for (int i = 0; i < 4; ++i) {
        if (!to_uv(corners[std::size_t(i)], where[std::size_t(i)], uv[i])) return [](sg::BicubicPatch&) {};
    }
    return [uv0 = uv[0], uv1 = uv[1], uv2 = uv[2], uv3 = uv[3]](sg::BicubicPatch& p) {
        p.uv_corners[0] = uv0;
        p.uv_corners[1] = uv1;
        p.uv_corners[2] = uv2;
        p.uv_corners[3] = uv3;
    };
}

ShapePtr Evaluator::make_bicubic_patch(const Edits<sg::BicubicPatch>& options, std::vector<Value> values,
                                       const SourceRange& where, const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::BicubicPatch, at);
    sg::BicubicPatch patch;
    for (const auto& option : options) option(patch);
    // POV-Ray 1's form: type [flatness, for types 2 and 3] u_steps v_steps
    // as bare numbers before the points.
    std::size_t numbers = 0;
    while (numbers < values.size() && values[numbers].kind == Value::Kind::Float) ++numbers;
    if (numbers > 0) {
        // Clamped before the casts: a huge or NaN number is not an int.
        auto small_int = [](double v) { return std::isfinite(v) ? int(std::clamp(v, -1.0, 11.0)) : -1; };
        const int type = small_int(values[0].v[0]);
        const std::size_t expected = type == 2 || type == 3 ? 4 : 3;
        if (numbers != expected) {
            error(where.begin,
                  "bicubic_patch: expected its 16 control points (or POV-Ray 1's type, u_steps, "
                  "v_steps before them)");
            shape->object.shape = patch;
            return shape;
        }
        warning(where.begin,
                "bicubic_patch: bare numbers before the points are POV-Ray 1's syntax; "
                "write type, flatness, u_steps and v_steps");
        patch.type = std::clamp(type, 0, 1);
        if (expected == 4 && std::isfinite(values[1].v[0])) patch.flatness = values[1].v[0];
        patch.u_steps = std::clamp(small_int(values[expected - 2].v[0]), 0, 10);
        patch.v_steps = std::clamp(small_int(values[expected - 1].v[0]), 0, 10);
        values.erase(values.begin(), values.begin() + std::ptrdiff_t(numbers));
    }
    if (patch.type < 0) {
        error(at, "bicubic_patch needs its type: type 0 or type 1 (POV-Ray's \"undefined bicubic patch type\")");
        patch.type = 0;
    }
    if (values.size() != 16) {
        error(where.begin, "bicubic_patch needs 16 control points, got " + std::to_string(values.size()));
        shape->object.shape = patch;
        return shape;
    }
    for (std::size_t i = 0; i < 16; ++i) {
        const SourceRange where{values[i].location, values[i].location};
        patch.points[i] = to_vec3(values[i], where);
        double xyz[3] = {patch.points[i].x, patch.points[i].y, patch.points[i].z};
        if (!check_renderable(xyz, 3, where, "the control point")) patch.points[i] = sg::Vec3(0.0);
    }
    shape->object.shape = patch;
    return shape;
}

// --------------------------------------------------------- julia_fractal

std::function<void(sg::JuliaFractal&)> Evaluator::julia_max_iteration(const Value& value, const SourceRange& where) {
    double n = to_float(value, where, "a float max_iteration");
    if (!check_renderable(&n, 1, where, "max_iteration")) n = 20.0;
    constexpr int kMaxIterations = 10000;
    if (n > kMaxIterations) {
        warning(where.begin, "julia_fractal: max_iteration above " + std::to_string(kMaxIterations) + " is taken as " +
                                 std::to_string(kMaxIterations));
        n = kMaxIterations;
    }
    // POV floors it and takes at least one iteration.
    const int iterations = int(std::floor(std::max(n, 1.0)));
    return [iterations](sg::JuliaFractal& j) { j.max_iteration = iterations; };
}

std::function<void(sg::JuliaFractal&)> Evaluator::julia_precision(const Value& value, const SourceRange& where) {
    double precision = to_float(value, where, "a float precision");
    if (!check_renderable(&precision, 1, where, "the precision")) precision = 20.0;
    precision = std::max(precision, 1.0);  // as POV-Ray
    // A march takes up to about 2 R precision steps: bound what one ray costs.
    constexpr double kMaxPrecision = 10000.0;
    if (precision > kMaxPrecision) {
        warning(where.begin, "julia_fractal: precision above 10000 is taken as 10000");
        precision = kMaxPrecision;
    }
    return [precision](sg::JuliaFractal& j) { j.precision = precision; };
}

std::function<void(sg::JuliaFractal&)> Evaluator::julia_slice(const Value& normal, const SourceRange& wn,
                                                              const Value& distance, const SourceRange& wd) {
    glm::dvec4 slice;
    if (!four_components(normal, slice)) {
        error(wn.begin, "julia_fractal: slice expects a 4-D vector");
        return [](sg::JuliaFractal&) {};
    }
    double d = to_float(distance, wd, "a float slice distance");
    double values[5] = {slice.x, slice.y, slice.z, slice.w, d};
    if (!check_renderable(values, 5, wn, "the slice")) return [](sg::JuliaFractal&) {};
    const double length = glm::length(slice);
    if (!(length > 1e-10)) {
        error(wn.begin, "julia_fractal: the slice vector is zero");
        return [](sg::JuliaFractal&) {};
    }
    if (!(std::fabs(slice.w) > 1e-10)) {
        error(wn.begin, "julia_fractal: the slice vector's t (4th) component must not be zero");
        return [](sg::JuliaFractal&) {};
    }
    slice /= length;
    return [slice, d](sg::JuliaFractal& j) {
        j.slice = slice;
        j.slice_distance = d;
    };
}

std::function<void(sg::JuliaFractal&)> Evaluator::julia_power(const Value& x, const SourceRange& wx, const Value& y,
                                                              const SourceRange& wy) {
    sg::Vec2 power(to_float(x, wx, "a float exponent"), to_float(y, wy, "a float exponent"));
    double both[2] = {power.x, power.y};
    if (!check_renderable(both, 2, wx, "the exponent")) power = sg::Vec2(2.0, 0.0);
    return [power](sg::JuliaFractal& j) {
        j.function = sg::JuliaFractal::Function::Pwr;
        j.power = power;
    };
}

std::function<void(sg::JuliaFractal&)> Evaluator::julia_function(const std::string& name,
                                                                 const sg::SourceLocation& at) {
    using F = sg::JuliaFractal::Function;
    static const std::pair<const char*, F> kFunctions[] = {
        {"sqr", F::Sqr},     {"exp", F::Exp},     {"ln", F::Ln},     {"sin", F::Sin},   {"asin", F::Asin},
        {"sinh", F::Sinh},   {"asinh", F::Asinh}, {"cos", F::Cos},   {"acos", F::Acos}, {"cosh", F::Cosh},
        {"acosh", F::Acosh}, {"tan", F::Tan},     {"atan", F::Atan}, {"tanh", F::Tanh}, {"atanh", F::Atanh}};
    for (const auto& entry : kFunctions)
        if (name == entry.first) return [function = entry.second](sg::JuliaFractal& j) { j.function = function; };
    error(at, "julia_fractal has no function '" + name +
                  "' (it takes sqr, cube, exp, reciprocal, ln, pwr(x, y) and the sin/cos/tan family)");
    return [](sg::JuliaFractal&) {};
}

ShapePtr Evaluator::make_julia_fractal(const Value& julia, const SourceRange& where,
                                       const Edits<sg::JuliaFractal>& items, const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::JuliaFractal, at);
    sg::JuliaFractal fractal;
    if (!four_components(julia, fractal.julia)) {
        error(where.begin, "julia_fractal needs a 4-D vector, its Julia parameter");
    } else {
        double values[4] = {fractal.julia.x, fractal.julia.y, fractal.julia.z, fractal.julia.w};
        if (!check_renderable(values, 4, where, "the Julia parameter")) fractal.julia = glm::dvec4(0.0);
    }
    for (const auto& item : items) item(fractal);
    using F = sg::JuliaFractal::Function;
    if (fractal.algebra == sg::JuliaFractal::Algebra::Quaternion && fractal.function != F::Sqr &&
        fractal.function != F::Cube) {
        error(at,
              "julia_fractal: quaternion supports only sqr and cube (POV-Ray's \"illegal function\"); "
              "add hypercomplex for the others");
        fractal.function = F::Sqr;
    }
    shape->object.shape = fractal;
    return shape;
}

// ---------------------------------------------------------- height_field

std::function<void(sg::HeightField&)> Evaluator::unsupported_height_field_format(const std::string& keyword,
                                                                                 const sg::SourceLocation& at) {
    error(at, "height_field: lancer cannot read POV-Ray's '" + keyword +
                  "' images; convert the file to png (16-bit grey keeps every height)");
    return [](sg::HeightField&) {};
}

std::function<void(sg::HeightField&)> Evaluator::height_field_function(const Value& function,
                                                                       const sg::SourceLocation& at) {
    if (function.kind != Value::Kind::Function || !function.function()) return [](sg::HeightField&) {};
    if (!function.image_size) {
        error(at, "height_field: a function needs its image size, as in function 256, 256 { … }");
        return [](sg::HeightField&) {};
    }
    if (const int missing = sg::first_unsupported_internal(*function.function()); missing >= 0)
        error(at, "POV-Ray 3.7 has no internal function " + std::to_string(missing));
    const auto size = *function.image_size;
    return [f = function.function(), size, at, generator = m_scene.global.noise_generator](sg::HeightField& h) {
        h.function = f;
        h.function_width = size.first;
        h.function_height = size.second;
        h.function_noise_generator = generator;
        h.location = at;
    };
}

ShapePtr Evaluator::make_height_field(const Edits<sg::HeightField>& items, const sg::SourceLocation& at) {
    namespace fs = std::filesystem;
    auto shape = new_shape(sg::Object::Kind::HeightField, at);
    sg::HeightField field;
    for (const auto& item : items) item(field);
    if (!field.location.file) field.location = at;
    if (!check_renderable(&field.water_level, 1, SourceRange{at, at}, "the water level")) field.water_level = 0.0;
    if (field.function) {
        if (!field.written.empty()) error(at, "height_field: give an image file or a function, not both");
        shape->object.shape = std::move(field);
        return shape;
    }
    if (field.written.empty()) {
        error(at, "height_field needs an image file, e.g. height_field { png \"mountains.png\" }");
        shape->object.shape = field;
        return shape;
    }
    // Found as image_map's files are: beside the scene file, on the
    // include path, then the current folder.
    std::string found;
    if (find_image_file(field.written, field.location, found)) field.path = found;
    shape->object.shape = std::move(field);
    return shape;
}

}  // namespace lancer::parse
