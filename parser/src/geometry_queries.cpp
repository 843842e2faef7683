// POV-Ray's questions to the objects declared so far, asked while parsing
// (Parse_Trace, Parse_Inside and min_extent / max_extent in its
// express.cpp): answered by ParseOptions::geometry_queries, which the render
// core provides.
#include <cmath>
#include <stdexcept>

#include "evaluator.h"

namespace lancer::parse {

namespace {

// POV's bounding box of an unbounded object (BOUND_HUGE / 2 each way).
constexpr double kUnboundedExtent = 1e10;

std::shared_ptr<const sg::Object> shared_object(const Value& value) {
    return std::shared_ptr<const sg::Object>(value.shape(), &value.shape()->object);
}

}  // namespace

const sg::GeometryQueries* Evaluator::geometry_queries(const std::string& what, const sg::SourceLocation& at) {
    if (!m_options.geometry_queries) error(at, what + "() needs the renderer's geometry, which this parse lacks");
    return m_options.geometry_queries;
}

Value Evaluator::trace(const Value& object, const SourceRange& wo, const Value& origin, const SourceRange& w1,
                       const Value& direction, const SourceRange& w2, const std::string& normal_name,
                       const SourceRange& where) {
    const sg::Vec3 from = to_vec3(origin, w1), along = to_vec3(direction, w2);
    const double components[6] = {from.x, from.y, from.z, along.x, along.y, along.z};
    if (!check_renderable(components, 3, w1, "trace()'s start") ||
        !check_renderable(components + 3, 3, w2, "trace()'s direction"))
        return Value::vec3(sg::Vec3(0.0));
    if (!(glm::length(along) > 0.0)) {
        error(w2.begin, "trace(): the direction has zero length");
        return Value::vec3(sg::Vec3(0.0));
    }
    const sg::GeometryQueries* queries = geometry_queries("trace", where.begin);
    if (!queries || !object.shape()) return Value::vec3(sg::Vec3(0.0));
    sg::GeometryQueries::Crossing crossing;
    try {
        crossing = queries->trace(shared_object(object), m_scene.global, from, along);
    } catch (const std::exception& e) {
        error(wo.begin, std::string("trace(): ") + e.what());
        return Value::vec3(sg::Vec3(0.0));
    }
    // POV: no crossing gives <0, 0, 0> for the point and the normal.
    if (!normal_name.empty())
        store(normal_name, Value::vec3(crossing.found ? crossing.normal : sg::Vec3(0.0)), false, where.begin);
    return Value::vec3(crossing.found ? crossing.point : sg::Vec3(0.0));
}

Value Evaluator::inside(const Value& object, const SourceRange& wo, const Value& point, const SourceRange& wp) {
    const sg::Vec3 p = to_vec3(point, wp);
    const double components[3] = {p.x, p.y, p.z};
    if (!check_renderable(components, 3, wp, "inside()'s point")) return Value::number(0.0);
    const sg::GeometryQueries* queries = geometry_queries("inside", wo.begin);
    if (!queries || !object.shape()) return Value::number(0.0);
    try {
        return Value::number(queries->inside(shared_object(object), m_scene.global, p) ? 1.0 : 0.0);
    } catch (const std::exception& e) {
        error(wo.begin, std::string("inside(): ") + e.what());
        return Value::number(0.0);
    }
}

Value Evaluator::extent(const Value& object, const SourceRange& wo, bool upper_corner) {
    const std::string what = upper_corner ? "max_extent" : "min_extent";
    const sg::GeometryQueries* queries = geometry_queries(what, wo.begin);
    if (!queries || !object.shape()) return Value::vec3(sg::Vec3(0.0));
    sg::Vec3 lower(-kUnboundedExtent), upper(kUnboundedExtent);
    try {
        if (!queries->bounds(shared_object(object), m_scene.global, lower, upper)) {
            lower = sg::Vec3(-kUnboundedExtent);
            upper = sg::Vec3(kUnboundedExtent);
        }
    } catch (const std::exception& e) {
        error(wo.begin, what + "(): " + e.what());
        return Value::vec3(sg::Vec3(0.0));
    }
    return Value::vec3(upper_corner ? upper : lower);
}

}  // namespace lancer::parse
