// Lights and the scene-level settings, including lancer's render_settings
// extension (the camera is in camera.cpp).
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

#include "evaluator.h"

namespace lancer::parse {

sg::Light Evaluator::make_light(const Value& position, const SourceRange& wp, const Value& colour,
                                const SourceRange& wc, const sg::SourceLocation& at) {
    sg::Light light;
    light.location = at;
    light.position = to_vec3(position, wp);
    light.color = to_color(colour, wc).rgb;
    return light;
}

void Evaluator::apply_light(sg::Light& light, const Edits<sg::Light>& edits) {
    for (const auto& edit : edits) edit(light);
}

std::function<void(sg::Light&)> Evaluator::area_light(const Value& a1, const SourceRange& w1, const Value& a2,
                                                      const SourceRange& w2, const Value& n1, const SourceRange& wn1,
                                                      const Value& n2, const SourceRange& wn2) {
    sg::Vec3 axis1 = to_vec3(a1, w1), axis2 = to_vec3(a2, w2);
    // POV truncates the sizes to integers.
    int size1 = saturated_int(to_float(n1, wn1, "a grid size")),
        size2 = saturated_int(to_float(n2, wn2, "a grid size"));
    if (size1 < 1 || size2 < 1) {
        error((size1 < 1 ? wn1 : wn2).begin, "area_light grid sizes must be at least 1");
        size1 = std::max(size1, 1);
        size2 = std::max(size2, 1);
    }
    constexpr int kMaxGridSize = 1024;  // POV traces up to size1 * size2 shadow rays per shading point
    if (size1 > kMaxGridSize || size2 > kMaxGridSize) {
        error((size1 > kMaxGridSize ? wn1 : wn2).begin,
              "area_light grid sizes must be at most " + std::to_string(kMaxGridSize));
        size1 = std::min(size1, kMaxGridSize);
        size2 = std::min(size2, kMaxGridSize);
    }
    return [=](sg::Light& l) {
        l.area_light = true;
        l.axis1 = axis1;
        l.axis2 = axis2;
        l.samples1 = size1;
        l.samples2 = size2;
    };
}

std::function<void(sg::Light&)> Evaluator::area_rectangle(const Value& a1, const SourceRange& w1, const Value& a2,
                                                          const SourceRange& w2) {
    sg::Vec3 axis1 = to_vec3(a1, w1), axis2 = to_vec3(a2, w2);
    if (!(glm::length(glm::cross(axis1, axis2)) > 0.0))
        error(w1.begin, "area_rectangle axes must be non-zero and not parallel (they span the emitting rectangle)");
    return [=](sg::Light& l) {
        l.kind = sg::Light::Kind::AreaRectangle;
        l.axis1 = axis1;
        l.axis2 = axis2;
    };
}

// POV's Parse_Light_Source: the object moves to the light's position as it
// is then, the block's own modifiers follow, and it casts no shadow.
std::function<void(sg::Light&)> Evaluator::looks_like(const ShapePtr& shape, const Edits<ShapeValue>& edits) {
    return [this, shape, edits](sg::Light& l) {
        if (l.looks_like) warning(l.location, "only one looks_like is allowed per light_source: the last one is used");
        auto moved = std::make_shared<ShapeValue>(*shape);
        moved->object.parent_from_object = glm::translate(sg::Mat4(1.0), l.position) * moved->object.parent_from_object;
        apply(moved, edits);
        moved->object.no_shadow = true;
        if (!moved->lights.empty()) warning(l.location, "lights inside a looks_like object are ignored");
        l.looks_like = std::make_shared<sg::Object>(moved->object);
    };
}

std::function<void(sg::Light&)> Evaluator::projected_through(const ShapePtr& shape, const Edits<ShapeValue>& edits) {
    auto projector = std::make_shared<ShapeValue>(*shape);
    apply(projector, edits);
    const bool has_lights = !projector->lights.empty();
    auto object = std::make_shared<const sg::Object>(projector->object);
    return [this, object, has_lights](sg::Light& l) {
        if (l.projected_through)
            warning(l.location, "only one projected_through is allowed per light_source: the last one is used");
        if (has_lights) warning(l.location, "lights inside a projected_through object are ignored");
        l.projected_through = object;
    };
}

namespace {

bool is_physical_lamp(const sg::Light& light) {
    return light.kind == sg::Light::Kind::AreaRectangle || light.kind == sg::Light::Kind::AreaSphere;
}

}  // namespace

void Evaluator::add_light(const sg::Light& local, const sg::Mat4& world_from_local) {
    sg::Light light = local;
    transform_light(light, world_from_local);
    if (light.parallel && light.kind == sg::Light::Kind::Point) {
        light.kind = sg::Light::Kind::Directional;
        if (glm::length(light.point_at - light.position) == 0.0) {
            error(light.location, "parallel light: point_at must differ from the light's position");
        }
    }
    if (light.fade_distance < 0.0 || light.fade_power < 0.0)
        error(light.location, "fade_distance and fade_power must not be negative");
    if (light.spot_parameters_given && !light.spotlight && !light.cylinder)
        error(light.location,
              "radius, falloff and tightness belong to a spotlight or cylinder light (write `spotlight` or "
              "`cylinder` before them)");
    if (light.cylinder) {
        if (!is_physical_lamp(light) && glm::length(light.point_at - light.position) == 0.0)
            error(light.location, "cylinder light: point_at must differ from the light's position");
        if (light.tightness < 0.0) error(light.location, "tightness must not be negative");
        if (light.spot_falloff <= 0.0) error(light.location, "a cylinder light's falloff must be positive");
        if (is_physical_lamp(light))
            error(light.location, "cylinder cannot be combined with area_rectangle or area_sphere");
    }
    if (light.spotlight) {
        if (light.kind != sg::Light::Kind::Point)
            error(light.location,
                  "spotlight cannot be combined with parallel, area_rectangle or area_sphere in lancer");
        else if (glm::length(light.point_at - light.position) == 0.0)
            error(light.location, "spotlight: point_at must differ from the light's position");
        if (light.tightness < 0.0) error(light.location, "tightness must not be negative");
    }
    check_area_light(light);
    if (light.projected_through && is_physical_lamp(light)) {
        error(light.location, "projected_through belongs to POV's lights, not to area_rectangle or area_sphere");
        light.projected_through.reset();
    }
    if (light.shadowless && is_physical_lamp(light)) {
        // A physical lamp is a surface that rays find: it cannot let light
        // through what stands between.
        warning(light.location, "shadowless is ignored on lancer's physical lamps (area_rectangle, area_sphere)");
        light.shadowless = false;
    }
    if (light.looks_like) {
        // The object joins the scene as any other; the light keeps no copy.
        auto shape = std::make_shared<ShapeValue>();
        shape->object = *light.looks_like;
        light.looks_like.reset();
        add_object(shape);
    }
    m_scene.lights.push_back(light);
}

// POV's checks of an area light (parser.cpp, Parse_Light_Source and
// Post_Process), with its warnings; the modifiers of an area light without
// one are warned about and dropped.
void Evaluator::check_area_light(sg::Light& light) {
    if (light.area_light && is_physical_lamp(light)) {
        error(light.location,
              "area_light is POV-Ray's light (lit from its centre, shadows sampled over a grid); it cannot be "
              "combined with lancer's physical lamps area_rectangle or area_sphere");
        light.area_light = false;
    }
    if (!light.area_light) {
        if (light.jitter || light.circular || light.orient || light.area_illumination || light.adaptive != 100)
            warning(light.location,
                    is_physical_lamp(light)
                        ? "jitter, adaptive, circular, orient and area_illumination are POV's area_light "
                          "modifiers; lancer's physical lamps are sampled physically and ignore them"
                        : "jitter, adaptive, circular, orient and area_illumination only affect an area_light");
        light.jitter = light.circular = light.orient = light.area_illumination = false;
        light.adaptive = 100;
        return;
    }
    if (light.kind == sg::Light::Kind::Directional) {
        warning(light.location, std::string("a ") + (light.cylinder ? "cylinder" : "parallel") +
                                    " area_light is rendered with hard shadows in lancer (its area is ignored)");
        light.area_light = false;
        return;
    }
    if (light.adaptive < 0) {
        error(light.location, "adaptive must not be negative");
        light.adaptive = 0;
    }
    if (light.orient) {
        if (!light.circular) {
            warning(light.location,
                    "orient can only be used with circular area lights: this area light is now circular");
            light.circular = true;
        }
        if (std::abs(glm::length(light.axis1) - glm::length(light.axis2)) > 1e-10)
            warning(
                light.location,
                "with orient, both axes of an area_light should have the same length: only the first one's is used");
        if (light.samples1 != light.samples2)
            warning(light.location, "with orient, both sample sizes of an area_light should be equal");
    }
    if (light.circular && (light.samples1 <= 1 || light.samples2 <= 1)) {
        error(light.location, "a circular area_light must have more than one sample along each axis");
        light.circular = light.orient = false;
    }
}

void Evaluator::set_assumed_gamma(double gamma) {
    if (m_saw_assumed_gamma) {
        warning(m_last_location, "a second assumed_gamma is ignored, as in POV-Ray");
        return;
    }
    m_scene.global.assumed_gamma = gamma;
    m_saw_assumed_gamma = true;
}

// ---------------------------------------------------------- render_settings

void Evaluator::render_setting(const std::string& name, const SourceRange& wn, const Value& v, const SourceRange& wv,
                               const Edits<ParameterList>& parameters) {
    auto& render = m_scene.render;
    if (name == "integrator") {
        render.integrator = to_string(v, wv);
        for (const auto& edit : parameters) edit(render.parameters);
        return;
    }
    if (!parameters.empty()) error(wn.begin, "only integrator takes a { parameter } block");
    if (name == "width" || name == "height" || name == "samples") {
        int n = to_int(v, wv);
        if (n < 1) {
            error(wv.begin, name + " must be at least 1, got " + std::to_string(n));
            return;
        }
        if (n > 1'000'000) {
            error(wv.begin, name + " is unreasonably large: " + std::to_string(n));
            return;
        }
        (name == "width" ? render.width : name == "height" ? render.height : render.samples) = n;
        return;
    }
    if (name == "seed") {
        double s = to_float(v, wv, "a float seed");
        if (s < 0.0 || s != std::floor(s)) {
            error(wv.begin, "seed must be a non-negative whole number");
            return;
        }
        render.seed = static_cast<std::uint64_t>(s);
        return;
    }
    std::string near;
    for (const char* known : {"integrator", "width", "height", "samples", "seed"}) {
        if (edit_distance(name, known) <= 2) near = known;
    }
    error(wn.begin, "unknown render_settings item '" + name +
                        "' (expected integrator, width, height, samples or seed)" +
                        (near.empty() ? "" : "; did you mean '" + near + "'?"));
}

std::function<void(ParameterList&)> Evaluator::parameter_edit(const std::string& name, const Value& v,
                                                              const SourceRange& where) {
    sg::ParameterValue parameter;
    parameter.location = where.begin;
    switch (v.kind) {
    case Value::Kind::Float:
        if (v.boolean_literal)
            parameter.value = v.v[0] != 0.0;
        else
            parameter.value = v.v[0];
        break;
    case Value::Kind::Vector:
    case Value::Kind::Color:
        parameter.value = to_vec3(v.kind == Value::Kind::Color ? Value::vector({v.v[0], v.v[1], v.v[2]}) : v, where);
        break;
    case Value::Kind::String: parameter.value = v.text; break;
    default:
        error(where.begin, "an integrator parameter must be a number, vector, string or on/off, found " + describe(v));
    }
    return [name, parameter](ParameterList& list) { list[name] = parameter; };
}

}  // namespace lancer::parse
