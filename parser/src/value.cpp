#include "value.h"

namespace lancer::parse {

Value Value::vector(std::initializer_list<double> components) {
    Value result;
    result.kind = Kind::Vector;
    result.size = 0;
    for (double c : components) {
        if (result.size < 5) result.v[result.size++] = c;
    }
    return result;
}

Value Value::color(const sg::Color& c) {
    Value result;
    result.kind = Kind::Color;
    result.size = 5;
    result.v = {c.rgb.r, c.rgb.g, c.rgb.b, c.filter, c.transmit};
    return result;
}

Value Value::string(std::string s) {
    Value result;
    result.kind = Kind::String;
    result.text = std::move(s);
    return result;
}

std::string describe(Value::Kind kind) {
    switch (kind) {
    case Value::Kind::Float: return "a float";
    case Value::Kind::Vector: return "a vector";
    case Value::Kind::Color: return "a colour";
    case Value::Kind::String: return "a string";
    case Value::Kind::Object: return "an object";
    case Value::Kind::Texture: return "a texture";
    case Value::Kind::Pigment: return "a pigment";
    case Value::Kind::Finish: return "a finish";
    case Value::Kind::Interior: return "an interior";
    case Value::Kind::Media: return "a media";
    case Value::Kind::SkySphere: return "a sky_sphere";
    case Value::Kind::Fog: return "a fog";
    case Value::Kind::Rainbow: return "a rainbow";
    case Value::Kind::Camera: return "a camera";
    case Value::Kind::Light: return "a light_source";
    case Value::Kind::Transform: return "a transform";
    case Value::Kind::Normal: return "a normal";
    case Value::Kind::ColorMap: return "a color_map";
    case Value::Kind::PigmentMap: return "a pigment_map";
    case Value::Kind::NormalMap: return "a normal_map";
    case Value::Kind::Function: return "a function";
    case Value::Kind::Array: return "an array";
    case Value::Kind::File: return "a file handle";
    case Value::Kind::Spline: return "a spline";
    }
    return "a value";
}

std::string describe(const Value& value) {
    if (value.kind == Value::Kind::Vector) return "a " + std::to_string(value.size) + "-component vector";
    return describe(value.kind);
}

}  // namespace lancer::parse
