// POV-Ray's isosurface: its function, container and search settings as
// POV-Ray 3.7 reads them (Parse_Isosurface in its parse.cpp), with POV's
// warnings and fallbacks for values it cannot use.
#include <algorithm>
#include <cmath>

#include "evaluator.h"

namespace lancer::parse {

namespace {

constexpr int kMostTraces = 10;  // POV's ISOSURFACE_MAXTRACE

}  // namespace

std::function<void(sg::Isosurface&)> Evaluator::isosurface_box(const Value& a, const SourceRange& wa, const Value& b,
                                                               const SourceRange& wb) {
    const sg::Vec3 p = to_vec3(a, wa), q = to_vec3(b, wb);
    const double corners[6] = {p.x, p.y, p.z, q.x, q.y, q.z};
    if (!check_renderable(corners, 3, wa, "the container's corner") ||
        !check_renderable(corners + 3, 3, wb, "the container's corner"))
        return [](sg::Isosurface&) {};
    return [p, q](sg::Isosurface& iso) {
        iso.container = sg::Isosurface::Container::Box;
        iso.box_corner1 = glm::min(p, q);
        iso.box_corner2 = glm::max(p, q);
    };
}

std::function<void(sg::Isosurface&)> Evaluator::isosurface_sphere(const Value& center, const SourceRange& wc,
                                                                  const Value& radius, const SourceRange& wr) {
    const sg::Vec3 c = to_vec3(center, wc);
    const double r = to_float(radius, wr, "a float radius");
    const double values[4] = {c.x, c.y, c.z, r};
    if (!check_renderable(values, 3, wc, "the container's centre") ||
        !check_renderable(values + 3, 1, wr, "the container's radius"))
        return [](sg::Isosurface&) {};
    if (!(r > 0.0)) {
        error(wr.begin, "isosurface: the container sphere's radius must be positive");
        return [](sg::Isosurface&) {};
    }
    return [c, r](sg::Isosurface& iso) {
        iso.container = sg::Isosurface::Container::Sphere;
        iso.sphere_center = c;
        iso.sphere_radius = r;
    };
}

std::function<void(sg::Isosurface&)> Evaluator::isosurface_number(const std::string& keyword, const Value& value,
                                                                  const SourceRange& where) {
    double number = to_float(value, where, "a float " + keyword);
    if (!check_renderable(&number, 1, where, "isosurface " + keyword)) return [](sg::Isosurface&) {};
    if (keyword == "threshold") return [number](sg::Isosurface& iso) { iso.threshold = number; };
    if (keyword == "accuracy") {
        if (!(number > 0.0)) {
            warning(where.begin, "isosurface 'accuracy' is not positive; using 0.001 (POV-Ray's default)");
            number = 0.001;
        }
        return [number](sg::Isosurface& iso) { iso.accuracy = number; };
    }
    if (keyword == "max_gradient") {
        if (!(number > 0.0)) {
            warning(where.begin, "isosurface 'max_gradient' is not positive; using 1.1 (POV-Ray's default)");
            number = 1.1;
        }
        return [number](sg::Isosurface& iso) { iso.max_gradient = number; };
    }
    // max_trace: POV truncates to a short, then keeps it within 1..10.
    int traces = int(std::clamp(std::trunc(number), -1.0, double(kMostTraces) + 1.0));
    if (traces > kMostTraces) {
        warning(where.begin, "isosurface 'max_trace' exceeds POV-Ray's maximum of 10; using 10");
        traces = kMostTraces;
    } else if (traces < 1) {
        warning(where.begin, "isosurface 'max_trace' is not positive; using 1 (POV-Ray's default)");
        traces = 1;
    }
    return [traces](sg::Isosurface& iso) { iso.max_trace = traces; };
}

std::function<void(sg::Isosurface&)> Evaluator::isosurface_evaluate(const std::array<Value, 3>& values,
                                                                    const std::array<SourceRange, 3>& where) {
    sg::Vec3 parameters;
    for (int i = 0; i < 3; ++i) {
        parameters[i] = to_float(values[std::size_t(i)], where[std::size_t(i)], "a float");
        if (!check_renderable(&parameters[i], 1, where[std::size_t(i)], "isosurface evaluate"))
            return [](sg::Isosurface&) {};
    }
    return [parameters](sg::Isosurface& iso) {
        iso.evaluate = true;
        iso.evaluate_parameters = parameters;
    };
}

ShapePtr Evaluator::make_isosurface(const Value& function, const SourceRange& where, const Edits<sg::Isosurface>& items,
                                    const sg::SourceLocation& at) {
    auto shape = new_shape(sg::Object::Kind::Isosurface, at);
    sg::Isosurface iso;
    iso.location = where.begin;
    if (function.kind != Value::Kind::Function || !function.function) {
        error(where.begin, "isosurface needs a function { … } first");
    } else if (function.function->pigment) {
        error(where.begin, "isosurface: a pigment function has a colour, not a value; use one of its channels");
    } else {
        iso.function = function.function;
        if (const int missing = sg::first_unsupported_internal(*iso.function); missing >= 0)
            error(where.begin, "POV-Ray 3.7 has no internal function " + std::to_string(missing));
    }
    for (const auto& item : items) item(iso);
    shape->object.shape = iso;
    return shape;
}

}  // namespace lancer::parse
