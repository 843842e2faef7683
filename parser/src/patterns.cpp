// Patterns, warps, colour and pigment maps, block patterns, normals: the
// scene graph's sg::Pattern, sg::Pigment and sg::Normal as POV-Ray 3.7
// reads them (its defaults, including each pattern's default colour map,
// measured from Debian's povray; docs/scene-language.md, "Patterns, maps
// and normals").
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>

#include "evaluator.h"

namespace lancer::parse {

namespace {

// An average's entries written without a weight get POV's 1; every other
// map needs a value in each entry. False when one is missing.
template <class Entry>
bool settle_weights(std::vector<Entry>& entries, bool average) {
    bool complete = true;
    for (Entry& entry : entries) {
        if (entry.value != sg::kUnweighted) continue;
        if (average)
            entry.value = 1.0;
        else
            complete = false;
    }
    return complete;
}

using PatternKind = sg::Pattern::Kind;

sg::Color rgb(double r, double g, double b) {
    return sg::Color{sg::Vec3(r, g, b)};
}

std::shared_ptr<const sg::ColorMap> make_map(std::initializer_list<std::pair<double, sg::Color>> entries) {
    auto map = std::make_shared<sg::ColorMap>();
    for (const auto& [value, colour] : entries) map->push_back({value, colour});
    return map;
}

// The colour map POV gives a pattern written without one (measured from
// povray 3.7: `function { pigment { P } }` against `function { pattern { P } }`).
sg::ColorMapRef default_color_map(PatternKind kind) {
    static const auto grey = make_map({{0.0, rgb(0, 0, 0)}, {1.0, rgb(1, 1, 1)}});
    static const auto bozo = make_map({{0.4, rgb(1, 1, 1)},
                                       {0.4, rgb(0, 1, 0)},
                                       {0.6, rgb(0, 1, 0)},
                                       {0.6, rgb(0, 0, 1)},
                                       {0.8, rgb(0, 0, 1)},
                                       {0.8, rgb(1, 0, 0)}});
    static const auto wood = make_map({{0.6, rgb(0.666, 0.312, 0.2)}, {0.6, rgb(0.4, 0.1333, 0.066)}});
    static const auto marble = make_map({{0.0, rgb(0.9, 0.8, 0.8)}, {0.9, rgb(0.9, 0.08, 0.08)}, {0.9, rgb(0, 0, 0)}});
    static const auto radial =
        make_map({{0.0, rgb(0, 1, 1)}, {0.333, rgb(1, 1, 0)}, {0.666, rgb(1, 0, 1)}, {1.0, rgb(0, 1, 1)}});
    static const auto agate = make_map({{0.0, rgb(1, 1, 1)},
                                        {0.5, rgb(0.95, 0.75, 0.5)},
                                        {0.5, rgb(0.9, 0.7, 0.5)},
                                        {0.6, rgb(0.9, 0.7, 0.4)},
                                        {0.6, rgb(1.0, 0.7, 0.4)},
                                        {1.0, rgb(0.6, 0.3, 0.0)}});
    static const auto mandel = make_map({{0.001, rgb(0, 0, 0)},
                                         {0.001, rgb(0, 1, 1)},
                                         {0.012, rgb(1, 1, 0)},
                                         {0.015, rgb(1, 0, 1)},
                                         {0.1, rgb(0, 1, 1)}});
    switch (kind) {
    case PatternKind::Mandel: return mandel;
    case PatternKind::Bozo: return bozo;
    case PatternKind::Wood: return wood;
    case PatternKind::Marble: return marble;
    case PatternKind::Radial: return radial;
    case PatternKind::Agate: return agate;
    default: return grey;
    }
}

// Whether `map` is one settle_pigment gave a pattern written without one.
bool is_default_color_map(const sg::ColorMapRef& map) {
    if (!map) return false;
    for (PatternKind kind : {PatternKind::Gradient, PatternKind::Mandel, PatternKind::Bozo, PatternKind::Wood,
                             PatternKind::Marble, PatternKind::Radial, PatternKind::Agate})
        if (map == default_color_map(kind)) return true;
    return false;
}

// Block patterns' default colours and how many entries each takes.
std::vector<sg::Color> default_block_colours(PatternKind kind) {
    switch (kind) {
    case PatternKind::Checker:
    case PatternKind::Object: return {rgb(0, 0, 1), rgb(0, 1, 0)};  // POV gives object checker's map
    case PatternKind::Hexagon: return {rgb(0, 0, 1), rgb(0, 1, 0), rgb(1, 0, 0)};
    case PatternKind::Brick: return {rgb(0.5, 0.5, 0.5), rgb(0.6, 0.15, 0.15)};
    case PatternKind::Square: return {rgb(1, 0, 0), rgb(0, 1, 0), rgb(0, 0, 1), rgb(1, 1, 0)};
    case PatternKind::Triangular:
    case PatternKind::Cubic:
        return {rgb(1, 0, 0), rgb(0, 1, 0), rgb(0, 0, 1), rgb(1, 1, 0), rgb(0, 1, 1), rgb(1, 0, 1)};
    default: return {};
    }
}

bool is_block_pattern(PatternKind kind) {
    return !default_block_colours(kind).empty();
}

const char* block_pattern_name(PatternKind kind) {
    switch (kind) {
    case PatternKind::Checker: return "checker";
    case PatternKind::Hexagon: return "hexagon";
    case PatternKind::Brick: return "brick";
    case PatternKind::Square: return "square";
    case PatternKind::Triangular: return "triangular";
    case PatternKind::Object: return "object";
    default: return "cubic";
    }
}

std::shared_ptr<sg::Pigment> solid_pigment(const sg::Color& colour) {
    auto pigment = std::make_shared<sg::Pigment>();
    pigment->color = colour;
    return pigment;
}

// A transform or a move applied to everything a pattern already holds:
// the point meets it first.
void move_pattern(sg::Pattern& pattern, const sg::Mat4& inner_from_outer) {
    pattern.pattern_from_object = pattern.pattern_from_object * inner_from_outer;
}

// POV evaluates a map's pigments and normals at their parent's pattern
// point (after the parent's transforms and warps): a transform written on
// the parent moves only the parent's own pattern. A uv-mapped pattern lives
// on the surface: moving the object does not move it.
void move_pigment(sg::Pigment& pigment, const sg::Mat4& inner_from_outer, bool object_move = false) {
    // A solid pigment without a pattern keeps its moves here alone.
    if (pigment.kind != sg::Pigment::Kind::Solid || pigment.pattern.has_value()) {
        sg::Pattern& pattern = pigment_pattern_of(pigment);
        if (!(object_move && pattern.uv_mapping)) move_pattern(pattern, inner_from_outer);
    }
    pigment.pattern_from_object = pigment.pattern_from_object * inner_from_outer;
}

void move_normal(sg::Normal& normal, const sg::Mat4& inner_from_outer, bool object_move = false) {
    if (!(object_move && normal.pattern->uv_mapping)) move_pattern(*normal.pattern, inner_from_outer);
}

sg::NormalRef moved_normal(const sg::NormalRef& normal, const sg::Mat4& inner_from_outer, bool object_move) {
    if (!normal) return normal;
    auto moved = std::make_shared<sg::Normal>(*normal);
    move_normal(*moved, inner_from_outer, object_move);
    return moved;
}

// A warp goes after the transforms written before it: those become a step
// of their own, so a later transform acts on the warped pattern.
void add_warp(sg::Pattern& pattern, const sg::Warp& warp) {
    if (pattern.pattern_from_object != sg::Mat4(1.0)) {
        sg::Warp step;
        step.kind = sg::Warp::Kind::Transform;
        step.inner_from_outer = pattern.pattern_from_object;
        pattern.warps.push_back(step);
        pattern.pattern_from_object = sg::Mat4(1.0);
    }
    pattern.warps.push_back(warp);
}

}  // namespace

sg::Pattern& pigment_pattern_of(sg::Pigment& pigment) {
    if (!pigment.pattern.has_value()) pigment.pattern->pattern_from_object = pigment.pattern_from_object;
    return *pigment.pattern;
}

void transform_pattern(sg::Pigment& pigment, const sg::Mat4& world_from_local) {
    move_pigment(pigment, glm::inverse(world_from_local));
}

void transform_densities(sg::Media& media, const sg::Mat4& world_from_local) {
    for (auto& density : media.densities) {
        auto moved = std::make_shared<sg::Pigment>(*density);
        transform_pattern(*moved, world_from_local);
        density = moved;
    }
}

void transform_normal(sg::Normal& normal, const sg::Mat4& world_from_local) {
    move_normal(normal, glm::inverse(world_from_local));
}

void transform_material(sg::Material& material, const sg::Mat4& world_from_local) {
    move_patterns(material, glm::inverse(world_from_local), false);
}

bool has_media_densities(const sg::Interior& interior) {
    return std::any_of(interior.media.begin(), interior.media.end(),
                       [](const sg::Media& m) { return !m.densities.empty(); });
}

void move_patterns(sg::Material& material, const sg::Mat4& inner_from_outer, bool object_move) {
    move_pigment(material.pigment, inner_from_outer, object_move);
    // Interior media's densities move with the object, as its pigment does
    // (asked through a const view first: writing would unshare the interior).
    if (has_media_densities(*std::as_const(material).interior)) {
        for (sg::Media& media : material.interior->media)
            for (auto& density : media.densities) {
                auto moved = std::make_shared<sg::Pigment>(*density);
                move_pigment(*moved, inner_from_outer, object_move);
                density = moved;
            }
    }
    material.normal = moved_normal(material.normal, inner_from_outer, object_move);
    // A patterned texture's entries live in its pattern space: only the
    // pattern moves. Layers are whole textures of their own: each moves.
    if (material.pattern && !(object_move && material.pattern->uv_mapping))
        move_pattern(*material.pattern, inner_from_outer);
    for (auto& layer : material.layers_above) {
        auto moved = std::make_shared<sg::Material>(*layer);
        move_patterns(*moved, inner_from_outer, object_move);
        layer = moved;
    }
    if (material.interior_texture) {
        auto moved = std::make_shared<sg::Material>(*material.interior_texture);
        move_patterns(*moved, inner_from_outer, object_move);
        material.interior_texture = moved;
    }
}

// ------------------------------------------------------------- patterns

namespace {
// A new pattern written in a pigment or normal: a pigment being edited
// keeps its transforms and warps, as POV's Parse_Pattern does.
void restart_pattern(sg::Pattern& pattern, const std::function<void(sg::Pattern&)>& kind, int waves,
                     const sg::SourceLocation& at) {
    sg::Pattern fresh;
    fresh.pattern_from_object = pattern.pattern_from_object;
    fresh.warps = pattern.warps;
    // POV-Ray 3.7 keeps classic turbulence among the warps.
    fresh.turbulence = pattern.turbulence;
    fresh.octaves = pattern.octaves;
    fresh.omega = pattern.omega;
    fresh.lambda = pattern.lambda;
    fresh.number_of_waves = waves;
    pattern = fresh;
    kind(pattern);
    pattern.location = at;
}

// POV gives marble, wood and the spirals a triangle wave unless another is
// written.
sg::WaveType default_wave(PatternKind kind) {
    switch (kind) {
    case PatternKind::Marble:
    case PatternKind::Wood:
    case PatternKind::Spiral1:
    case PatternKind::Spiral2: return sg::WaveType::Triangle;
    default: return sg::WaveType::Ramp;
    }
}
}  // namespace

Evaluator::PatternEdit Evaluator::pattern_kind(sg::Pattern::Kind kind) {
    return [kind](sg::Pattern& p) {
        p.kind = kind;
        p.wave = default_wave(kind);
    };
}

Evaluator::PatternEdit Evaluator::gradient_pattern(const Value& v, const SourceRange& where) {
    const sg::Vec3 direction = to_vec3(v, where);
    if (direction == sg::Vec3(0.0)) warning(where.begin, "gradient along a zero vector: the pattern is 0 everywhere");
    return [direction](sg::Pattern& p) {
        p.kind = PatternKind::Gradient;
        p.vector = direction;
    };
}

Evaluator::PatternEdit Evaluator::spiral_pattern(sg::Pattern::Kind kind, const Value& arms, const SourceRange& where) {
    const int count = to_int(arms, where);
    return [kind, count](sg::Pattern& p) {
        p.kind = kind;
        p.wave = default_wave(kind);
        p.spiral_arms = count;
    };
}

Evaluator::PatternEdit Evaluator::tiling_pattern(const Value& v, const SourceRange& where) {
    int type = to_int(v, where);
    if (type < 1 || type > 27) {
        error(where.begin, "tiling type must be 1 to 27, got " + std::to_string(type));
        type = 1;
    }
    return [type](sg::Pattern& p) {
        p.kind = PatternKind::Tiling;
        p.tiling_type = type;
    };
}

// density_file df3 "name": POV's DF3 file, three big-endian 16-bit sizes
// (x, y, z) and then the voxels, x fastest, of 1, 2 or 4 big-endian bytes
// each (the size of the rest of the file decides which). Read here, so a
// missing or malformed file is an error at the name.
Evaluator::PatternEdit Evaluator::density_file_pattern(const std::string& name, const sg::SourceLocation& where) {
    auto voxels = std::make_shared<std::vector<double>>();
    glm::ivec3 size(0);
    std::vector<std::string> folders = search_folders(where);
    folders.push_back("");
    std::string found, bytes;
    const FileSearch search = find_file(name, folders, where, "density file", found);
    if (search == FileSearch::Missing) error(where, "cannot find density file \"" + name + "\"");
    if (search == FileSearch::Found && read_file(found, where, "density file", bytes)) {
        auto byte = [&bytes](std::size_t i) {
            return static_cast<std::uint32_t>(static_cast<unsigned char>(bytes[i]));
        };
        if (bytes.size() < 6) {
            error(where, "density file \"" + name + "\" is too short for a df3 header (6 bytes)");
        } else {
            size = glm::ivec3(int(byte(0) << 8 | byte(1)), int(byte(2) << 8 | byte(3)), int(byte(4) << 8 | byte(5)));
            const std::size_t count = std::size_t(size.x) * std::size_t(size.y) * std::size_t(size.z);
            const std::size_t data = bytes.size() - 6;
            // POV tries 4, then 2, then 1 bytes per voxel.
            std::size_t width = 0;
            if (count * 4 == data)
                width = 4;
            else if (count * 2 == data)
                width = 2;
            else if (count == data)
                width = 1;
            if (width == 0) {
                error(where, "density file \"" + name + "\": " + std::to_string(size.x) + "x" + std::to_string(size.y) +
                                 "x" + std::to_string(size.z) + " voxels do not fit its " + std::to_string(data) +
                                 " data bytes (1, 2 or 4 bytes a voxel)");
                size = glm::ivec3(0);
            } else {
                const double top = width == 4 ? 4294967295.0 : width == 2 ? 65535.0 : 255.0;
                voxels->resize(count);
                for (std::size_t i = 0; i < count; ++i) {
                    std::uint32_t v = 0;
                    for (std::size_t b = 0; b < width; ++b) v = v << 8 | byte(6 + i * width + b);
                    (*voxels)[i] = double(v) / top;
                }
            }
        }
    }
    const std::string file = found.empty() ? name : found;
    return [voxels, size, file](sg::Pattern& p) {
        p.kind = PatternKind::DensityFile;
        p.file = file;
        p.density_voxels = voxels;
        p.density_size = size;
    };
}

Evaluator::PatternEdit Evaluator::slope_pattern(const Value& v, const SourceRange& where) {
    sg::Vec3 direction = to_vec3(v, where);
    if (glm::length(direction) == 0.0) {
        error(where.begin, "slope needs a non-zero direction");
        direction = sg::Vec3(0, 1, 0);
    }
    return [direction](sg::Pattern& p) {
        p.kind = PatternKind::Slope;
        p.vector = direction;
    };
}

Evaluator::PatternEdit Evaluator::slope_block(const Value& direction, const SourceRange& where,
                                              const std::optional<std::pair<double, double>>& slope_range,
                                              const std::optional<std::pair<Value, SourceRange>>& altitude,
                                              const std::optional<std::pair<double, double>>& altitude_range,
                                              bool point_at) {
    const sg::Vec3 vector = to_vec3(direction, where);
    if (!point_at && glm::length(vector) == 0.0 && !altitude) error(where.begin, "slope needs a non-zero direction");
    sg::Vec3 altitude_vector(0.0);
    if (altitude) altitude_vector = to_vec3(altitude->first, altitude->second);
    return [=](sg::Pattern& p) {
        p.kind = PatternKind::Slope;
        p.vector = vector;
        p.slope_point_at = point_at;
        if (slope_range) p.slope_range = sg::Vec2(slope_range->first, slope_range->second);
        if (altitude) {
            p.slope_altitude = altitude_vector;
            p.slope_has_altitude = true;
        }
        if (altitude_range) p.altitude_range = sg::Vec2(altitude_range->first, altitude_range->second);
    };
}

Evaluator::PatternEdit Evaluator::fractal_pattern(sg::Pattern::Kind kind, const Value& iterations,
                                                  const SourceRange& where, const Value* julia_parameter,
                                                  const SourceRange& wj) {
    int count = to_int(iterations, where);
    if (count < 1) {
        error(where.begin, "a fractal pattern needs at least 1 iteration, got " + std::to_string(count));
        count = 1;
    }
    sg::Vec2 parameter(0.0);
    if (julia_parameter) {
        const sg::Vec3 c = to_vec3(*julia_parameter, wj);
        parameter = sg::Vec2(c.x, c.y);
    }
    return [kind, count, parameter](sg::Pattern& p) {
        p.kind = kind;
        p.fractal_iterations = count;
        p.julia_parameter = parameter;
    };
}

Evaluator::PatternEdit Evaluator::magnet_pattern(const Value& type, const SourceRange& where, PatternEdit fractal) {
    int magnet = to_int(type, where);
    if (magnet != 1 && magnet != 2) {
        error(where.begin, "magnet type must be 1 or 2, got " + std::to_string(magnet));
        magnet = 1;
    }
    return [magnet, fractal](sg::Pattern& p) {
        fractal(p);
        p.magnet_julia = p.kind == PatternKind::Julia;
        p.kind = PatternKind::Magnet;
        p.magnet_type = magnet;
    };
}

Evaluator::PatternEdit Evaluator::pattern_scalar(const std::string& name, const Value& v, const SourceRange& where) {
    const double value = to_float(v, where, "a float " + name);
    if (!std::isfinite(value)) {
        error(where.begin, name + " must be finite");
        return [](sg::Pattern&) {};
    }
    if (name == "octaves") {
        int octaves = saturated_int(value);
        if (octaves < 1 || octaves > 10) {
            warning(where.begin,
                    "octaves is limited to 1..10 (as in POV-Ray); using " + std::to_string(std::clamp(octaves, 1, 10)));
            octaves = std::clamp(octaves, 1, 10);
        }
        return [octaves](sg::Pattern& p) { p.octaves = octaves; };
    }
    if (name == "omega") return [value](sg::Pattern& p) { p.omega = value; };
    if (name == "lambda") return [value](sg::Pattern& p) { p.lambda = value; };
    if (name == "frequency") return [value](sg::Pattern& p) { p.frequency = value; };
    if (name == "phase") return [value](sg::Pattern& p) { p.phase = value; };
    if (name == "poly_wave")
        return [value](sg::Pattern& p) {
            p.wave = sg::WaveType::Poly;
            p.wave_exponent = value;
        };
    if (name == "noise_generator") {
        const int generator = noise_generator(v, where);
        return [generator](sg::Pattern& p) { p.noise_generator = generator; };
    }
    if (name == "agate_turb") return [value](sg::Pattern& p) { p.agate_turbulence = value; };
    if (name == "mortar") return [value](sg::Pattern& p) { p.mortar = value; };
    if (name == "metric") {
        if (value <= 0.0) error(where.begin, "crackle metric must be positive");
        return [value](sg::Pattern& p) { p.crackle_metric = value; };
    }
    if (name == "offset") return [value](sg::Pattern& p) { p.crackle_offset = value; };
    if (name == "coords") return [value](sg::Pattern& p) { p.facets_coords = value; };
    if (name == "size") return [value](sg::Pattern& p) { p.facets_size = value; };
    if (name == "exponent") {
        const int exponent = saturated_int(value);
        if (exponent < 2 || exponent > 33) error(where.begin, "fractal exponent must be 2 to 33");
        return [exponent](sg::Pattern& p) { p.fractal_exponent = std::clamp(exponent, 2, 33); };
    }
    if (name == "control0") return [value](sg::Pattern& p) { p.quilted_control0 = value; };
    if (name == "control1") return [value](sg::Pattern& p) { p.quilted_control1 = value; };
    if (name == "number_of_sides") return [value](sg::Pattern& p) { p.pavement_sides = saturated_int(value); };
    if (name == "number_of_tiles") return [value](sg::Pattern& p) { p.pavement_tiles = saturated_int(value); };
    // pavement's pattern N, and its one-number exterior N / interior N
    // (a fractal's take a factor too: pattern_pair).
    if (name == "pattern") return [value](sg::Pattern& p) { p.pavement_number = saturated_int(value); };
    if (name == "exterior") return [value](sg::Pattern& p) { p.pavement_exterior = saturated_int(value); };
    if (name == "interior") return [value](sg::Pattern& p) { p.pavement_interior = saturated_int(value); };
    if (name == "interpolate") return [value](sg::Pattern& p) { p.file_interpolate = saturated_int(value); };
    error(where.begin, "unknown pattern setting " + name);
    return [](sg::Pattern&) {};
}

Evaluator::PatternEdit Evaluator::pattern_vector(const std::string& name, const Value& v, const SourceRange& where) {
    const sg::Vec3 value = to_vec3(v, where);
    if (name == "turbulence") return [value](sg::Pattern& p) { p.turbulence = value; };
    if (name == "brick_size") return [value](sg::Pattern& p) { p.brick_size = value; };
    if (name == "form")
        return [value](sg::Pattern& p) {
            // pavement's form is a number (POV reads a float there).
            if (p.kind == PatternKind::Pavement)
                p.pavement_form = saturated_int(value.x);
            else
                p.crackle_form = value;
        };
    if (name == "altitude")
        return [value](sg::Pattern& p) {
            p.slope_altitude = value;
            p.slope_has_altitude = true;
        };
    error(where.begin, "unknown pattern setting " + name);
    return [](sg::Pattern&) {};
}

Evaluator::PatternEdit Evaluator::pattern_pair(const std::string& name, const Value& a, const SourceRange& wa,
                                               const Value& b, const SourceRange& wb) {
    const int type = to_int(a, wa);
    const double factor = to_float(b, wb, "a float factor");
    if (type < 0 || type > 8) error(wa.begin, name + " type must be 0 to 8, got " + std::to_string(type));
    if (name == "exterior")
        return [type, factor](sg::Pattern& p) {
            p.exterior_type = type;
            p.exterior_factor = factor;
        };
    return [type, factor](sg::Pattern& p) {
        p.interior_type = type;
        p.interior_factor = factor;
    };
}

int Evaluator::noise_generator(const Value& v, const SourceRange& where) {
    const int generator = to_int(v, where);
    // 0 is POV's "the global setting" in a pattern (and generator 1 in
    // global_settings, which the caller decides).
    if (generator < 0 || generator > 3) {
        error(where.begin, "noise_generator must be 0, 1, 2 or 3, got " + std::to_string(generator));
        return 2;
    }
    return generator;
}

// -------------------------------------------------------------------- warps

Evaluator::PatternEdit Evaluator::warp_edit(const Edits<sg::Warp>& items, const sg::SourceLocation& at) {
    sg::Warp warp;
    for (const auto& item : items) item(warp);
    warp.location = at;
    if (warp.kind == sg::Warp::Kind::Transform) {
        error(at, "warp { } needs a kind: turbulence, repeat, black_hole, cylindrical, spherical, toroidal or planar");
        return [](sg::Pattern&) {};
    }
    if (warp.kind == sg::Warp::Kind::Repeat) {
        int axes = 0;
        for (int i = 0; i < 3; ++i) axes += warp.repeat[i] != 0.0;
        if (axes != 1) {
            error(at, "warp { repeat } takes a vector along one axis (as POV-Ray)");
            return [](sg::Pattern&) {};
        }
    }
    return [warp](sg::Pattern& p) { add_warp(p, warp); };
}

namespace {
// The first kind-giving word of a warp block decides its kind; later words
// (black_hole's turbulence, its repeat) are its settings.
void give_kind(sg::Warp& w, sg::Warp::Kind kind) {
    if (w.kind == sg::Warp::Kind::Transform) w.kind = kind;
}
}  // namespace

std::function<void(sg::Warp&)> Evaluator::warp_scalar(const std::string& name, const Value& v,
                                                      const SourceRange& where) {
    const double value = to_float(v, where, "a float " + name);
    if (name == "octaves") {
        const int octaves = std::clamp(saturated_int(value), 1, 10);
        return [octaves](sg::Warp& w) { w.octaves = octaves; };
    }
    if (name == "omega") return [value](sg::Warp& w) { w.omega = value; };
    if (name == "lambda") return [value](sg::Warp& w) { w.lambda = value; };
    if (name == "falloff") return [value](sg::Warp& w) { w.falloff = value; };
    if (name == "strength") return [value](sg::Warp& w) { w.strength = value; };
    if (name == "dist_exp") return [value](sg::Warp& w) { w.dist_exp = value; };
    return [value](sg::Warp& w) { w.major_radius = value; };
}

std::function<void(sg::Warp&)> Evaluator::warp_vector(const std::string& name, const Value& v,
                                                      const SourceRange& where) {
    const sg::Vec3 value = to_vec3(v, where);
    if (name == "turbulence")
        return [value](sg::Warp& w) {
            give_kind(w, sg::Warp::Kind::Turbulence);
            w.turbulence = value;
        };
    if (name == "repeat")
        return [value](sg::Warp& w) {
            give_kind(w, sg::Warp::Kind::Repeat);
            w.repeat = value;
        };
    if (name == "offset") return [value](sg::Warp& w) { w.offset = value; };
    if (name == "flip") return [value](sg::Warp& w) { w.flip = value; };
    return [value](sg::Warp& w) { w.orientation = value; };
}

std::function<void(sg::Warp&)> Evaluator::warp_kind(sg::Warp::Kind kind) {
    return [kind](sg::Warp& w) { give_kind(w, kind); };
}

std::function<void(sg::Warp&)> Evaluator::black_hole(const Value& center, const SourceRange& wc, const Value& radius,
                                                     const SourceRange& wr) {
    const sg::Vec3 c = to_vec3(center, wc);
    const double r = to_float(radius, wr, "a float radius");
    if (!(r > 0.0)) error(wr.begin, "black_hole radius must be positive");
    return [c, r](sg::Warp& w) {
        give_kind(w, sg::Warp::Kind::BlackHole);
        w.center = c;
        w.radius = r;
    };
}

std::function<void(sg::Warp&)> Evaluator::planar_warp(const Value& normal, const SourceRange& wn, const Value& distance,
                                                      const SourceRange& wd) {
    const sg::Vec3 n = to_vec3(normal, wn);
    const double d = to_float(distance, wd, "a float distance");
    return [n, d](sg::Warp& w) {
        give_kind(w, sg::Warp::Kind::Planar);
        w.normal = n;
        w.distance = d;
    };
}

// ----------------------------------------------------------------- pigments

// A pattern written into a pigment that already has one (after a pigment
// identifier, or in a texture's pigment edit) keeps, as in POV-Ray, the
// pigment's moves, warps and turbulence; the map is the next functions'.
namespace {
void start_pattern(sg::Pigment& p, const Evaluator::PatternEdit& pattern, int waves, const sg::SourceLocation& at) {
    p.kind = sg::Pigment::Kind::Patterned;
    restart_pattern(pigment_pattern_of(p), pattern, waves, at);
}
}  // namespace

Evaluator::PigmentEdit Evaluator::patterned_pigment(const PatternEdit& pattern, const sg::SourceLocation& at) {
    // ripples and waves take global_settings' number_of_waves (written,
    // as POV scenes do, before the objects).
    return [pattern, at, waves = m_scene.global.number_of_waves](sg::Pigment& p) {
        start_pattern(p, pattern, waves, at);
        // POV-Ray keeps the map the pigment was given, and reads a block
        // pattern's list as a map with entry i at value i. A map the
        // earlier pattern had only by default is its own, not kept.
        if (is_default_color_map(p.color_map)) p.color_map.reset();
        if (!p.block_pigments.empty()) {
            p.color_map.reset();
            p.pigment_map.clear();
            for (std::size_t i = 0; i < p.block_pigments.size(); ++i)
                p.pigment_map.push_back(sg::PigmentMapEntry{double(i), p.block_pigments[i]});
            p.block_pigments.clear();
        }
    };
}

Evaluator::PigmentEdit Evaluator::block_pigment(const PatternEdit& pattern, const std::vector<Value>& colours,
                                                const SourceRange& where, const sg::SourceLocation& at) {
    std::vector<sg::PigmentRef> pigments;
    for (const Value& colour : colours) pigments.push_back(solid_pigment(to_color(colour, where)));
    return block_pigment(pattern, pigments, at);
}

Evaluator::PigmentEdit Evaluator::block_pigment(const PatternEdit& pattern,
                                                const std::vector<std::shared_ptr<sg::Pigment>>& list,
                                                const sg::SourceLocation& at) {
    return block_pigment(pattern, std::vector<sg::PigmentRef>(list.begin(), list.end()), at);
}

// A block pattern's list (the missing entries its defaults, filled in when
// the pigment is settled) replaces any map, as in POV-Ray.
Evaluator::PigmentEdit Evaluator::block_pigment(const PatternEdit& pattern, const std::vector<sg::PigmentRef>& pigments,
                                                const sg::SourceLocation& at) {
    return [pattern, at, waves = m_scene.global.number_of_waves, pigments](sg::Pigment& p) {
        start_pattern(p, pattern, waves, at);
        p.color_map.reset();
        p.pigment_map.clear();
        p.block_pigments = pigments;
    };
}

Evaluator::PigmentEdit Evaluator::average_pigment(const sg::SourceLocation& at) {
    return [at](sg::Pigment& p) {
        pigment_pattern_of(p);  // the entries are read at its pattern's point
        p.kind = sg::Pigment::Kind::Average;
        p.location = at;
    };
}

Evaluator::PigmentEdit Evaluator::uv_mapping_pigment() {
    return [](sg::Pigment& p) {
        pigment_pattern_of(p).uv_mapping = true;
        p.image->map_type = sg::MapType::UV;
    };
}

Evaluator::PatternEdit Evaluator::pigment_pattern(const std::shared_ptr<sg::Pigment>& pigment,
                                                  const sg::SourceLocation& at) {
    sg::PigmentRef inner = pigment;
    return [inner, at](sg::Pattern& p) {
        p.kind = PatternKind::PigmentPattern;
        p.pigment = inner;
        p.location = at;
    };
}

Evaluator::PigmentEdit Evaluator::pigment_pattern_edit(const PatternEdit& edit, const sg::SourceLocation&) {
    // POV accepts pattern modifiers on any pigment; on one without a
    // pattern (a plain colour, an image) they change nothing.
    return [edit](sg::Pigment& p) {
        if (p.kind != sg::Pigment::Kind::Solid) edit(pigment_pattern_of(p));
    };
}

Evaluator::PigmentEdit Evaluator::color_map_edit(const sg::ColorMapRef& map, const sg::SourceLocation& at) {
    return [this, map, at](sg::Pigment& p) {
        if (p.kind != sg::Pigment::Kind::Patterned) {
            warning(at, "color_map on a pigment without a pattern is ignored (write the pattern first)");
            return;
        }
        if (is_block_pattern(p.pattern->kind)) {
            error(at, std::string("a ") + block_pattern_name(p.pattern->kind) +
                          " pattern takes a list of colours, not a color_map");
            return;
        }
        p.color_map = map;
        p.pigment_map.clear();
    };
}

Evaluator::PigmentEdit Evaluator::pigment_map_edit(const std::shared_ptr<std::vector<sg::PigmentMapEntry>>& map,
                                                   const sg::SourceLocation& at) {
    return [this, map, at](sg::Pigment& p) {
        if (p.kind != sg::Pigment::Kind::Patterned && p.kind != sg::Pigment::Kind::Average) {
            warning(at, "pigment_map on a pigment without a pattern is ignored (write the pattern first)");
            return;
        }
        if (p.kind == sg::Pigment::Kind::Patterned && is_block_pattern(p.pattern->kind)) {
            error(at, std::string("a ") + block_pattern_name(p.pattern->kind) +
                          " pattern takes a list of pigments, not a pigment_map");
            return;
        }
        if (map->empty()) error(at, "pigment_map needs at least one entry");
        p.pigment_map = *map;
        p.color_map.reset();
    };
}

sg::ColorMapRef Evaluator::build_color_map(const std::vector<std::pair<Value, std::vector<Value>>>& entries,
                                           const sg::SourceLocation& at) {
    auto map = std::make_shared<sg::ColorMap>();
    SourceRange where{at, at};
    for (const auto& [value, colours] : entries) {
        const double first = to_float(value, where, "a map value");
        if (colours.size() == 1) {
            map->push_back({first, to_color(colours[0], where)});
        } else if (colours.size() == 3) {
            // POV's old form [v1 v2 colour1 colour2]: a ramp between two values.
            map->push_back({first, to_color(colours[1], where)});
            map->push_back({to_float(colours[0], where, "a map value"), to_color(colours[2], where)});
        } else {
            error(at, "a color_map entry is [value colour] (or POV's old [value1 value2 colour1 colour2])");
        }
    }
    if (map->empty()) error(at, "color_map needs at least one entry");
    if (map->size() > 256) error(at, "color_map has more than 256 entries (POV-Ray's limit)");
    for (size_t i = 1; i < map->size(); ++i) {
        if ((*map)[i].value < (*map)[i - 1].value) {
            warning(at, "color_map values must not decrease; POV-Ray reads them in the order written");
            break;
        }
    }
    return map;
}

std::shared_ptr<sg::Pigment> Evaluator::build_pigment(const Edits<sg::Pigment>& edits, const sg::SourceLocation& at) {
    auto pigment = std::make_shared<sg::Pigment>();
    for (const auto& edit : edits) edit(*pigment);
    settle_pigment(*pigment, at);
    return pigment;
}

// POV's density: a pattern without a map reads as its value in grey (the
// pigment defaults of bozo, wood … do not apply), densities being factors.
std::shared_ptr<sg::Pigment> Evaluator::build_density(const Edits<sg::Pigment>& edits, const sg::SourceLocation& at) {
    auto density = std::make_shared<sg::Pigment>();
    density->color = sg::Color{sg::Vec3(1.0)};  // an empty density is 1: it changes nothing
    for (const auto& edit : edits) edit(*density);
    if (density->kind == sg::Pigment::Kind::Patterned && !is_block_pattern(density->pattern->kind) &&
        !density->color_map && density->pigment_map.empty())
        density->color_map = default_color_map(PatternKind::Gradient);
    settle_pigment(*density, at);
    return density;
}

void Evaluator::settle_pigment(sg::Pigment& settled, const sg::SourceLocation& at) {
    sg::Pigment* pigment = &settled;
    pigment->location = at;
    if (pigment->kind == sg::Pigment::Kind::Patterned) {
        const PatternKind kind = pigment->pattern->kind;
        if (is_block_pattern(kind)) {
            const std::vector<sg::Color> defaults = default_block_colours(kind);
            if (pigment->block_pigments.size() > defaults.size()) {
                error(at, std::string(block_pattern_name(kind)) + " takes at most " + std::to_string(defaults.size()) +
                              " colours or pigments, got " + std::to_string(pigment->block_pigments.size()));
                pigment->block_pigments.resize(defaults.size());
            }
            for (size_t i = pigment->block_pigments.size(); i < defaults.size(); ++i)
                pigment->block_pigments.push_back(solid_pigment(defaults[i]));
        } else if (!pigment->color_map && pigment->pigment_map.empty()) {
            pigment->color_map = default_color_map(kind);
        }
    }
    if (pigment->kind == sg::Pigment::Kind::Average && pigment->pigment_map.empty())
        error(at, "average needs a pigment_map of the pigments to average");
    if (!settle_weights(pigment->pigment_map, pigment->kind == sg::Pigment::Kind::Average))
        missing_weight(at, "pigment_map");
    // POV-Ray accepts a negative colour; on a surface it takes light away
    // from what it reflects, which surprises more often than it is meant.
    auto negative = [](const sg::Color& c) { return c.rgb.x < 0.0 || c.rgb.y < 0.0 || c.rgb.z < 0.0; };
    bool any_negative = pigment->kind == sg::Pigment::Kind::Solid && negative(pigment->color);
    if (pigment->color_map)
        for (const auto& entry : *pigment->color_map) any_negative = any_negative || negative(entry.color);
    if (any_negative)
        warning(at,
                "the pigment has a negative colour component: the surface will take light away (POV-Ray "
                "accepts it too)");
}

// ------------------------------------------------------------------ normals

sg::NormalRef Evaluator::build_normal(const Edits<sg::Normal>& edits, const sg::SourceLocation& at) {
    // A declared normal starts from #default's, as POV's Parse_Tnormal.
    auto normal = std::make_shared<sg::Normal>(
        m_default_texture && m_default_texture->normal ? *m_default_texture->normal : sg::Normal{});
    for (const auto& edit : edits) edit(*normal);
    settle_normal(*normal, at);
    return normal;
}

void Evaluator::settle_normal(sg::Normal& normal, const sg::SourceLocation& at) {
    normal.location = at;
    if (normal.kind == sg::Normal::Kind::Average && normal.normal_map.empty())
        error(at, "average needs a normal_map of the normals to average");
    if (!settle_weights(normal.normal_map, normal.kind == sg::Normal::Kind::Average)) missing_weight(at, "normal_map");
}

namespace {
// The layer a pigment, normal or finish written after a layered texture
// changes: the top one (POV's texture list starts with the newest layer).
sg::Material& top_layer(sg::Material& material) {
    if (material.layers_above.empty()) return material;
    auto top = std::make_shared<sg::Material>(*material.layers_above.back());
    material.layers_above.back() = top;
    return *top;
}
}  // namespace

// POV edits the pigment, normal or finish a texture already has (a copy of
// a declared one, or #default's): `texture { T finish { phong 1 } }` keeps
// the rest of T's finish.
std::function<void(sg::Material&)> Evaluator::material_pigment_edit(const Edits<sg::Pigment>& edits,
                                                                    const sg::SourceLocation& at) {
    return [this, edits, at](sg::Material& m) {
        sg::Material& target = top_layer(m);
        for (const auto& edit : edits) edit(target.pigment);
        settle_pigment(target.pigment, at);
    };
}

std::function<void(sg::Material&)> Evaluator::material_normal_edit(const Edits<sg::Normal>& edits,
                                                                   const sg::SourceLocation& at) {
    return [this, edits, at](sg::Material& m) {
        sg::Material& target = top_layer(m);
        auto normal = std::make_shared<sg::Normal>(target.normal ? *target.normal : sg::Normal{});
        for (const auto& edit : edits) edit(*normal);
        settle_normal(*normal, at);
        target.normal = normal;
    };
}

std::function<void(sg::Material&)> Evaluator::material_finish_edit(const Edits<sg::Finish>& edits,
                                                                   const sg::SourceLocation& at) {
    return [this, edits, at](sg::Material& m) {
        sg::Material& target = top_layer(m);
        sg::Finish& finish = *target.finish;
        for (const auto& edit : edits) edit(finish);
        settle_finish(finish, at);
    };
}

Evaluator::NormalEdit Evaluator::patterned_normal(const PatternEdit& pattern,
                                                  const std::optional<std::pair<Value, SourceRange>>& amount,
                                                  const sg::SourceLocation& at) {
    std::optional<double> size;
    if (amount) size = to_float(amount->first, amount->second, "a bump size");
    return [pattern, size, at, waves = m_scene.global.number_of_waves](sg::Normal& n) {
        n.kind = sg::Normal::Kind::Patterned;
        restart_pattern(*n.pattern, pattern, waves, at);
        if (size) n.bump_size = *size;
        // As for pigments: a block pattern's list, followed by a pattern
        // that is not one, reads as a map with entry i at value i.
        if (!n.block_normals.empty() && !is_block_pattern(n.pattern->kind)) {
            n.normal_map.clear();
            for (std::size_t i = 0; i < n.block_normals.size(); ++i)
                n.normal_map.push_back(sg::NormalMapEntry{double(i), n.block_normals[i]});
            n.block_normals.clear();
        }
    };
}

Evaluator::NormalEdit Evaluator::block_normal(const PatternEdit& pattern,
                                              const std::optional<std::pair<Value, SourceRange>>& amount,
                                              const std::vector<sg::NormalRef>& normals, const sg::SourceLocation& at) {
    NormalEdit start = patterned_normal(pattern, amount, at);
    return [this, start, normals, at](sg::Normal& n) {
        start(n);
        n.normal_map.clear();
        n.block_normals = normals;
        const std::size_t count = default_block_colours(n.pattern->kind).size();
        if (n.block_normals.size() > count) {
            error(at, std::string(block_pattern_name(n.pattern->kind)) + " takes at most " + std::to_string(count) +
                          " normals, got " + std::to_string(n.block_normals.size()));
            n.block_normals.resize(count);
        }
        // POV leaves the blocks without a normal of their own flat.
        while (n.block_normals.size() < count) {
            auto flat = std::make_shared<sg::Normal>();
            flat->bump_size = 0.0;
            n.block_normals.push_back(flat);
        }
    };
}

void Evaluator::missing_weight(const sg::SourceLocation& at, const char* map) {
    error(at, std::string("each ") + map +
                  " entry needs its value first ([0.5 …]); only average's entries may leave it out");
}

void Evaluator::refuse_foreign_image_items(const sg::ImageMap& image, const char* block) {
    const std::string name = block;
    if (name != "bump_map" && (image.bump_size || image.use_color))
        error(image.bump_item_location, "bump_size, use_color and use_index belong in a bump_map, not in " + name);
    if (name != "image_pattern" && image.use_alpha)
        error(image.use_alpha_location, "use_alpha belongs in an image_pattern, not in " + name);
    if (name != "image_map" && !image.palette_settings.empty())
        error(image.palette_settings.front().location, "filter and transmit belong in an image_map, not in " + name);
}

Evaluator::PatternEdit Evaluator::object_pattern(const std::shared_ptr<ShapeValue>& shape,
                                                 const sg::SourceLocation& at) {
    auto object = std::make_shared<sg::Object>(shape->object);
    if (!shape->lights.empty()) warning(at, "the object pattern ignores the light sources in its object");
    return [object](sg::Pattern& p) {
        p.kind = PatternKind::Object;
        p.object = object;
    };
}

Evaluator::PatternEdit Evaluator::image_pattern(const sg::ImageMap& image, const sg::SourceLocation& at) {
    auto map = std::make_shared<sg::ImageMap>(image);
    finish_image_map(*map, at);
    refuse_foreign_image_items(*map, "image_pattern");
    if (!map->gamma_given) map->srgb = false;
    return [map](sg::Pattern& p) {
        p.kind = PatternKind::ImagePattern;
        p.image = map;
    };
}

Evaluator::NormalEdit Evaluator::bump_map_normal(const sg::ImageMap& image,
                                                 const std::optional<std::pair<Value, SourceRange>>& amount,
                                                 const sg::SourceLocation& at) {
    sg::ImageMap map = image;
    finish_image_map(map, at);
    refuse_foreign_image_items(map, "bump_map");
    if (!map.gamma_given) map.srgb = false;
    std::optional<double> size = map.bump_size;
    if (amount) size = to_float(amount->first, amount->second, "a bump size");
    return [map, size](sg::Normal& n) {
        n.kind = sg::Normal::Kind::BumpMap;
        n.bump_map = map;
        if (size) n.bump_size = *size;
        if (map.use_color) n.bump_map_use_color = *map.use_color;
    };
}

Evaluator::NormalEdit Evaluator::normal_pattern_edit(const PatternEdit& edit, const sg::SourceLocation&) {
    return [edit](sg::Normal& n) { edit(*n.pattern); };
}

Evaluator::NormalEdit Evaluator::normal_accuracy(const Value& v, const SourceRange& where) {
    const double accuracy = to_float(v, where, "a float accuracy");
    if (!(accuracy > 0.0)) {
        error(where.begin, "accuracy must be positive");
        return [](sg::Normal&) {};
    }
    return [accuracy](sg::Normal& n) { n.accuracy = accuracy; };
}

sg::SlopeMapEntry Evaluator::slope_entry(const Value& value, const SourceRange& wv, const Value& slope,
                                         const SourceRange& ws) {
    sg::SlopeMapEntry entry;
    entry.value = to_float(value, wv, "a map value");
    const sg::Vec3 pair = to_vec3(slope, ws);
    entry.height = pair.x;
    entry.slope = pair.y;
    return entry;
}

sg::PaletteSetting Evaluator::palette_setting(bool transmit, const Value& index, const SourceRange& wi,
                                              const Value& value, const SourceRange& wv) {
    sg::PaletteSetting setting;
    setting.transmit = transmit;
    setting.location = wi.begin;
    // POV truncates the index after adding 0.01; whether it names an entry
    // of the palette is known once the image is read.
    const double number = to_float(index, wi, "a palette index");
    if (!(number + 0.01 >= 0.0 && number + 0.01 < 256.0))
        error(wi.begin, std::string("the palette index of ") + (transmit ? "transmit" : "filter") +
                            " must be 0 to 255 (a palette has at most 256 entries)");
    else
        setting.index = int(number + 0.01);
    setting.value = to_float(value, wv, transmit ? "a transmit amount" : "a filter amount");
    return setting;
}

// ------------------------------------------------------ patterned textures

sg::Material Evaluator::default_texture() const {
    sg::Material texture;
    if (m_default_texture) {
        texture.pigment = m_default_texture->pigment;
        texture.normal = m_default_texture->normal;
        texture.finish = m_default_texture->finish;
    }
    return texture;
}

bool Evaluator::top_layer_is_patterned(const sg::Material& texture) {
    const sg::Material& top = texture.layers_above.empty() ? texture : *texture.layers_above.back();
    return top.pattern.has_value();
}

// POV-Ray's Link_Textures: a layer lies over a plain texture, and a
// patterned texture is never a layer (each entry of its map may be layered).
std::shared_ptr<sg::Material> Evaluator::layer_texture(std::shared_ptr<sg::Material> below,
                                                       const std::shared_ptr<sg::Material>& above) {
    if (top_layer_is_patterned(*below)) {
        error(above->location,
              "cannot layer over a patterned texture (POV-Ray refuses it too; layer the textures of its map "
              "instead)");
        return below;
    }
    if (top_layer_is_patterned(*above)) {
        error(above->location, "cannot layer a patterned texture over another (POV-Ray refuses it too)");
        return below;
    }
    auto top = std::make_shared<sg::Material>(*above);
    top->layers_above.clear();
    below->layers_above.push_back(top);
    for (const auto& layer : above->layers_above) below->layers_above.push_back(layer);
    return below;
}

std::function<void(sg::Material&)> Evaluator::texture_pattern(const PatternEdit& pattern,
                                                              const std::vector<std::shared_ptr<sg::Material>>& blocks,
                                                              const sg::SourceLocation& at) {
    std::vector<sg::MaterialRef> textures(blocks.begin(), blocks.end());
    return [this, pattern, textures, at](sg::Material& m) {
        m.pattern = sg::Pattern{};
        pattern(*m.pattern);
        m.pattern->location = at;
        m.texture_map.clear();
        m.block_textures = textures;
        if (is_block_pattern(m.pattern->kind)) {
            const std::size_t count = default_block_colours(m.pattern->kind).size();
            if (m.block_textures.size() > count) {
                error(at, std::string(block_pattern_name(m.pattern->kind)) + " takes at most " + std::to_string(count) +
                              " textures");
                m.block_textures.resize(count);
            }
            // POV fills the missing blocks with its default texture.
            while (m.block_textures.size() < count) m.block_textures.push_back(std::make_shared<sg::Material>());
        } else if (!textures.empty()) {
            error(at,
                  "only block patterns (checker, hexagon, brick, square, triangular, cubic) take a list of "
                  "textures; write a texture_map");
        }
    };
}

std::function<void(sg::Material&)> Evaluator::material_map_edit(
    const sg::ImageMap& image, const std::vector<std::shared_ptr<sg::Material>>& blocks, const sg::SourceLocation& at) {
    auto map = std::make_shared<sg::ImageMap>(image);
    finish_image_map(*map, at);
    refuse_foreign_image_items(*map, "material_map");
    // The file's values pick the textures: read as stored, not decoded.
    if (!map->gamma_given) map->srgb = false;
    if (blocks.empty()) error(at, "material_map needs a list of textures after its image");
    std::vector<sg::MaterialRef> textures(blocks.begin(), blocks.end());
    return [map, textures, at](sg::Material& m) {
        m.pattern = sg::Pattern{};
        m.pattern->kind = PatternKind::ImagePattern;
        m.pattern->image = map;
        m.pattern->location = at;
        m.texture_map.clear();
        m.block_textures = textures;
        if (m.block_textures.empty()) m.block_textures.push_back(std::make_shared<sg::Material>());
    };
}

std::function<void(sg::Material&)> Evaluator::average_texture(const sg::SourceLocation& at) {
    return [at](sg::Material& m) {
        m.pattern = sg::Pattern{};
        m.pattern->location = at;
        m.average = true;
        m.texture_map.clear();
        m.block_textures.clear();
    };
}

std::function<void(sg::Material&)> Evaluator::texture_map_edit(const std::vector<sg::TextureMapEntry>& entries,
                                                               const sg::SourceLocation& at) {
    return [this, entries, at](sg::Material& m) {
        if (!m.pattern) {
            error(at, "texture_map needs a pattern before it (texture { gradient x texture_map { ... } })");
            return;
        }
        if (entries.empty()) error(at, "texture_map needs at least one entry");
        m.texture_map = entries;
        if (!settle_weights(m.texture_map, m.average)) missing_weight(at, "texture_map");
        m.block_textures.clear();
    };
}

}  // namespace lancer::parse
