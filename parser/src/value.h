// Values the evaluator computes: what an expression folds to and what a
// #declare'd identifier holds. Numbers, vectors and colours share one
// representation (POV-Ray promotes floats to vectors and colours); scene
// items (objects, textures, ...) are shared immutable payloads.
#pragma once

#include <array>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "lancer/scene_graph.h"

namespace lancer::parse {

// An object as the evaluator carries it: the scene-graph node plus the
// light sources written inside it (POV allows lights in unions), kept in
// the object's own space so they follow its transforms.
struct ShapeValue {
    sg::Object object;
    std::vector<sg::Light> lights;
    // bounded_by's objects, in the object's space: a hint lancer does not
    // need, kept for `clipped_by { bounded_by }`.
    std::vector<sg::Object> bounded_by;
    bool global_lights = false;  // a light_group's global_lights, while it is read
    // The object's own `uv_mapping`: textures given after it map by the
    // surface's (u, v), as though each said uv_mapping itself.
    bool uv_mapping = false;
};

// A camera block's settings as written; resolved in POV's fixed order
// (right, direction, angle, up, sky, location, look_at, focal_point) by
// resolve_camera.
struct CameraSpec {
    sg::Camera::Projection projection = sg::Camera::Projection::Perspective;
    std::optional<sg::Vec3> location, look_at, direction, right, up, sky, focal_point;
    // `angle`: the first value; the spherical camera's second one, if given.
    // An orthographic `angle` may have no value (POV reads it as 0).
    std::optional<double> angle, vertical_angle;
    bool angle_has_value = false;
    sg::SourceLocation angle_location;
    double aperture = 0.0;
    int blur_samples = 0, blur_samples_min = 0;
    double confidence = 0.9, variance = 1.0 / 10000.0;
    sg::NormalRef normal;
    std::shared_ptr<const sg::Pigment> bokeh;
    std::shared_ptr<const sg::MeshCamera> mesh;  // mesh_camera's settings and meshes
    sg::Mat4 world_from_camera{1.0};             // transforms written in the block
    sg::SourceLocation location_in_source;
    // POV-Ray reads the camera type before any other item: a type after
    // one is an error (set_camera reports it).
    bool other_item_seen = false;
    std::optional<sg::SourceLocation> late_type_location;

    void set_projection(sg::Camera::Projection type, const sg::SourceLocation& at) {
        if (other_item_seen && !late_type_location) late_type_location = at;
        projection = type;
    }
    void set_angle(double first, std::optional<double> second, const sg::SourceLocation& at, bool has_value) {
        angle = first;
        vertical_angle = second;
        angle_has_value = has_value;
        angle_location = at;
        other_item_seen = true;
    }
};

struct ArrayData;
struct UserFile;

// POV's spline { … }: values (up to 5 components) at increasing times.
struct SplineData {
    enum class Kind { Linear, Quadratic, Cubic, Natural };  // cubic_spline is POV's Catmull-Rom
    struct Entry {
        double t = 0.0;
        std::array<double, 5> v{};
    };
    Kind kind = Kind::Linear;
    std::vector<Entry> entries;  // sorted by t, no two alike
    int terms = 2;               // components a call returns: the widest entry, at least 2
};
// The spline's value at t, evaluated as `kind` (splines.cpp).
std::array<double, 5> spline_at(const SplineData& spline, SplineData::Kind kind, double t);

struct Value {
    enum class Kind {
        Float,
        Vector,
        Color,
        String,
        Object,
        Texture,
        Pigment,
        Finish,
        Interior,
        Camera,
        Light,
        Transform,
        Normal,
        ColorMap,
        PigmentMap,
        NormalMap,
        Function,
        Array,
        File,
        Spline,
        Media,
        SkySphere,
        Fog,
        Rainbow
    };
    // What a non-scalar value holds: one shared payload, chosen by kind. An
    // array and a #fopen'd file are shared and mutable; the rest immutable.
    // One variant, not a member for each kind, keeps a Value small: the
    // grammar moves and destroys several for every token it reads.
    using Payload = std::variant<
        std::monostate, std::shared_ptr<const ShapeValue>, std::shared_ptr<const sg::Material>,
        std::shared_ptr<const sg::Pigment>, std::shared_ptr<const sg::Finish>, std::shared_ptr<const sg::Interior>,
        std::shared_ptr<const sg::Media>, std::shared_ptr<const sg::SkySphere>, std::shared_ptr<const sg::Fog>,
        std::shared_ptr<const sg::Rainbow>, std::shared_ptr<const CameraSpec>, std::shared_ptr<const sg::Light>,
        sg::NormalRef, sg::ColorMapRef, std::shared_ptr<const std::vector<sg::PigmentMapEntry>>,
        std::shared_ptr<const std::vector<sg::NormalMapEntry>>, sg::FunctionRef, std::shared_ptr<ArrayData>,
        std::shared_ptr<UserFile>, std::shared_ptr<const SplineData>, std::shared_ptr<const sg::Mat4>>;

    Kind kind = Kind::Float;
    int size = 1;
    bool boolean_literal = false;  // written as on/off/true/false/yes/no
    // Float: v[0]. Vector: v[0..size). Color: r g b filter transmit.
    std::array<double, 5> v{0.0, 0.0, 0.0, 0.0, 0.0};
    std::string text;  // String
    Payload payload;
    // `function W, H { … }`: the size of the image POV makes of the function.
    std::optional<std::pair<int, int>> image_size;
    sg::SourceLocation location;  // where it was written, when a check needs it later

    // The payload of each kind; empty when the value holds another.
    const std::shared_ptr<const ShapeValue>& shape() const { return held<std::shared_ptr<const ShapeValue>>(); }
    const std::shared_ptr<const sg::Material>& texture() const { return held<std::shared_ptr<const sg::Material>>(); }
    const std::shared_ptr<const sg::Pigment>& pigment() const { return held<std::shared_ptr<const sg::Pigment>>(); }
    const std::shared_ptr<const sg::Finish>& finish() const { return held<std::shared_ptr<const sg::Finish>>(); }
    const std::shared_ptr<const sg::Interior>& interior() const { return held<std::shared_ptr<const sg::Interior>>(); }
    const std::shared_ptr<const sg::Media>& media() const { return held<std::shared_ptr<const sg::Media>>(); }
    const std::shared_ptr<const sg::SkySphere>& sky_sphere() const {
        return held<std::shared_ptr<const sg::SkySphere>>();
    }
    const std::shared_ptr<const sg::Fog>& fog() const { return held<std::shared_ptr<const sg::Fog>>(); }
    const std::shared_ptr<const sg::Rainbow>& rainbow() const { return held<std::shared_ptr<const sg::Rainbow>>(); }
    const std::shared_ptr<const CameraSpec>& camera() const { return held<std::shared_ptr<const CameraSpec>>(); }
    const std::shared_ptr<const sg::Light>& light() const { return held<std::shared_ptr<const sg::Light>>(); }
    const sg::NormalRef& normal() const { return held<sg::NormalRef>(); }
    const sg::ColorMapRef& color_map() const { return held<sg::ColorMapRef>(); }
    const std::shared_ptr<const std::vector<sg::PigmentMapEntry>>& pigment_map() const {
        return held<std::shared_ptr<const std::vector<sg::PigmentMapEntry>>>();
    }
    const std::shared_ptr<const std::vector<sg::NormalMapEntry>>& normal_map() const {
        return held<std::shared_ptr<const std::vector<sg::NormalMapEntry>>>();
    }
    const sg::FunctionRef& function() const { return held<sg::FunctionRef>(); }
    const std::shared_ptr<ArrayData>& array() const { return held<std::shared_ptr<ArrayData>>(); }
    const std::shared_ptr<UserFile>& file() const { return held<std::shared_ptr<UserFile>>(); }
    const std::shared_ptr<const SplineData>& spline() const { return held<std::shared_ptr<const SplineData>>(); }
    // A Transform's matrix; the identity for any other value.
    const sg::Mat4& transform() const {
        static const sg::Mat4 identity{1.0};
        const auto& matrix = held<std::shared_ptr<const sg::Mat4>>();
        return matrix ? *matrix : identity;
    }
    void set_transform(const sg::Mat4& matrix) { payload = std::make_shared<const sg::Mat4>(matrix); }

    static Value number(double x) { return Value{}.with_float(x); }
    static Value vector(std::initializer_list<double> components);
    static Value vec3(const sg::Vec3& p) { return vector({p.x, p.y, p.z}); }
    static Value color(const sg::Color& c);
    static Value string(std::string s);

    bool is_numeric() const { return kind == Kind::Float || kind == Kind::Vector || kind == Kind::Color; }
    Value with_float(double x) const {
        Value result;
        result.v[0] = x;
        return result;
    }

  private:
    template <class Held>
    const Held& held() const {
        static const Held none;
        const Held* found = std::get_if<Held>(&payload);
        return found ? *found : none;
    }
};

// POV's array[n1][n2]…: elements in row-major order, unset until assigned.
struct ArrayData {
    std::vector<int> sizes;
    std::vector<std::optional<Value>> elements;
};

// A variable a macro parameter stands for: POV-Ray passes an identifier
// (or an array element) given as a macro argument by reference, so the
// macro reads the variable and its #declare or #local of the parameter
// writes it.
struct VariableReference {
    std::size_t scope = 0;  // a named variable: the scope holding it
    std::string name;
    std::shared_ptr<ArrayData> array;  // or an array's element
    std::size_t element = 0;
};

// A macro argument: its value, and the variable it names if it is one
// identifier alone.
struct MacroArgument {
    Value value;
    std::optional<VariableReference> reference;
};

// An array initializer as written: a value, or a braced list of them.
struct ArrayInit {
    std::optional<Value> value;
    std::vector<ArrayInit> items;
    sg::SourceLocation location;
};

// "a float", "a 3-vector", "a colour", "an object" ... for messages.
std::string describe(const Value& value);
std::string describe(Value::Kind kind);

}  // namespace lancer::parse

#include <functional>

namespace lancer::parse {

// A span of source text; bison's location type.
struct SourceRange {
    sg::SourceLocation begin;
    sg::SourceLocation end;
};

// The semantic value every terminal carries: its spelling and, for
// literals, constants and declared identifiers, the value it stands for.
struct TokenValue {
    std::string text;
    Value value;
};

// Items of a block (camera, finish, object modifiers ...) are edits applied
// in the order written, which is what POV-Ray's order rules need.
template <class T>
using Edits = std::vector<std::function<void(T&)>>;

using ShapePtr = std::shared_ptr<ShapeValue>;
using ParameterList = std::map<std::string, sg::ParameterValue>;

}  // namespace lancer::parse
