// The evaluator: runs a scene from tokens to a scene graph.
//
// Design. POV-Ray's language is not context free in the useful sense: a
// directive can appear between any two tokens (inside a finish, between the
// items of a union), a #macro expands to whatever tokens its body holds (an
// object, a vector, half a texture), and a #while body is re-read every
// iteration. So lancer does what POV-Ray itself does, with a real grammar on
// top:
//
//   1. lexer.l scans each file once into raw tokens (raw_token.h);
//   2. the token stream (token_stream.cpp, directives.cpp) walks those tokens
//      with a stack of frames (files, macro bodies), executes directives as
//      it meets them (#declare, #if, #while by jumping back to the loop's
//      condition, #macro by pushing the body as a frame, #include by pushing
//      another file), and looks every identifier up, so the parser receives
//      typed tokens (VALUE_ID, OBJECT_ID, ...) that already carry their
//      values;
//   3. grammar.y (bison, LALR(1)) parses what remains and its actions
//      evaluate as they reduce: expressions fold to Values, blocks become
//      ordered lists of edits applied to a scene-graph node.
//
// Directives that need a value (#declare X = ..., #if (...), macro
// arguments) run a nested parser over the same token stream from a
// dedicated start token. Because identifiers are resolved when they are
// read, a value never depends on when bison decides to reduce.
#pragma once

#include <fstream>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <random>
#include <set>
#include <string>
#include <unordered_map>
#include <vector>

#include "grammar.tab.hpp"
#include "lancer/parser.h"
#include "memory_budget.h"
#include "name_table.h"
#include "raw_token.h"
#include "value.h"

namespace lancer::parse {

// Pattern and light transforms, shared by grammar actions and objects.cpp.
void transform_pattern(sg::Pigment& pigment, const sg::Mat4& world_from_local);
// A pigment's pattern, to write to. A solid pigment has none until then
// (sg::Pigment::pattern); the one made here starts from the moves the
// pigment met, as if it had been there all along.
sg::Pattern& pigment_pattern_of(sg::Pigment& pigment);
// POV's hollow: on a CSG or union, every part is hollow too (Set_CSG_Children_Flag).
void set_hollow(sg::Object& object, bool hollow);
// A transform written in a media block: moves the densities given before it (POV's Transform_Density).
void transform_densities(sg::Media& media, const sg::Mat4& world_from_local);
void transform_normal(sg::Normal& normal, const sg::Mat4& world_from_local);
void transform_material(sg::Material& material, const sg::Mat4& world_from_local);
// Re-expresses every pattern of a material (pigments, normals, nested
// maps) for a point that is first mapped by `inner_from_outer`: what
// attaching a texture to a transformed object does.
void move_patterns(sg::Material& material, const sg::Mat4& inner_from_outer, bool object_move = true);
// Whether a medium of the interior has a density (a pattern that moves with the object).
bool has_media_densities(const sg::Interior& interior);
void transform_light(sg::Light& light, const sg::Mat4& world_from_local);
// `sky_along_view` (when not null) is set when look_at looks along the sky.
sg::Camera resolve_camera(const CameraSpec& spec, bool* sky_along_view = nullptr);
bool is_reserved_word(const std::string& name);
// What an identifier token's spelling makes it (kept on the token).
WordClass word_class_of(const RawToken& raw);
// A number POV truncates to an integer, without overflow: values past
// int's range (clamped to +-2e9) are out of every setting's range anyway,
// and the caller's checks report them; NaN gives 0.
int saturated_int(double value);
// A new object of `kind` written at `at`, its shape still to be set.
inline ShapePtr new_shape(sg::Object::Kind kind, const sg::SourceLocation& at) {
    auto shape = std::make_shared<ShapeValue>();
    shape->object.kind = kind;
    shape->object.location = at;
    return shape;
}
// Levenshtein distance, case-insensitive: how far a typo is from a name.
size_t edit_distance(const std::string& a, const std::string& b);

class Evaluator {
  public:
    using Symbol = Parser::symbol_type;
    using Kind = Parser::token_kind_type;

    explicit Evaluator(const ParseOptions& options);
    ParseResult run(std::string text, const std::string& label, const std::string& path, const std::string& folder);
    // The scene file at `path`, open as `file`, read as an include is
    // (read_file): straight into one string of its size, within
    // ParseOptions::max_file_bytes. Read from `file`, not opened again: a
    // named pipe opened a second time waits for a writer that has gone.
    ParseResult run_file(std::ifstream& file, const std::string& path, const std::string& folder);

    sg::SceneGraph& scene() { return m_scene; }
    const ParseOptions& options() const { return m_options; }

    // ---- token stream (token_stream.cpp)
    Symbol next_token();
    void finish_nested(Value value, const SourceRange& where, bool had_lookahead);
    void finish_arguments(std::vector<MacroArgument> arguments);
    // A macro argument written at `where`: by reference when it is exactly
    // the identifier (or array element) the token stream read last.
    MacroArgument macro_argument(Value value, const SourceRange& where);
    void begin_value_barrier();
    void end_value_barrier();

    // ---- diagnostics (diagnostics.cpp)
    void error(const sg::SourceLocation& where, const std::string& message);
    void warning(const sg::SourceLocation& where, const std::string& message);
    void note(const sg::SourceLocation& where, const std::string& message);
    // Stores a diagnostic; false when a warning or note was dropped (past kMaxWarnings).
    bool add_diagnostic(Diagnostic::Severity severity, const sg::SourceLocation& where, const std::string& message);
    static constexpr int kMaxWarnings = 200;
    void ignored(const sg::SourceLocation& where, const std::string& what);
    // interior { dispersion_samples N }: checked as POV-Ray checks it (at
    // least 2), then ignored with dispersion itself.
    void dispersion_samples(const sg::SourceLocation& keyword, const Value& count, const SourceRange& where);
    void unknown_identifier(const std::string& name, const sg::SourceLocation& where, const std::string& expected);
    void syntax_error(const SourceRange& where, const std::string& message);
    std::string suggestion(const std::string& name) const;
    bool failed() const { return m_error_count > 0; }

    // ---- conversions and operators (expressions.cpp)
    double to_float(const Value& value, const SourceRange& where, const std::string& what = "a float");
    int to_int(const Value& value, const SourceRange& where);
    double positive(const Value& value, const SourceRange& where, const std::string& what);
    sg::Vec3 to_vec3(const Value& value, const SourceRange& where);
    // An error at `where` unless every value is finite and fits single
    // precision (what the renderer stores).
    bool check_renderable(const double* values, int count, const SourceRange& where, const std::string& what);
    sg::Vec3 nonzero_vec3(const Value& value, const SourceRange& where, const std::string& what);
    sg::Color to_color(const Value& value, const SourceRange& where);
    std::string to_string(const Value& value, const SourceRange& where);
    Value arithmetic(char op, const Value& a, const Value& b, const SourceRange& where);
    Value compare(const std::string& op, const Value& a, const SourceRange& wa, const Value& b, const SourceRange& wb);
    Value logical(char op, const Value& a, const SourceRange& wa, const Value& b, const SourceRange& wb);
    Value negate(const Value& a, const SourceRange& where);
    Value component(const Value& a, const SourceRange& wa, const std::string& name, const SourceRange& wn);
    Value make_vector(const std::vector<Value>& items, const SourceRange& where);
    Value colour_keyword(const std::string& keyword, const Value& operand, const SourceRange& where);
    Value colour_from(const Value& operand, const SourceRange& where);
    Value colour_component(const Value& colour, const SourceRange& wc, int channel, const Value& v,
                           const SourceRange& wv);
    Value checked(Value value, const SourceRange& where, const std::string& what);
    void remember_location(Value& value, const SourceRange& where) { value.location = where.begin; }

    // ---- built-in functions (builtins.cpp)
    Value call_builtin(const std::string& name, const std::vector<Value>& args, const SourceRange& where);

    // ---- objects and materials (objects.cpp, meshes.cpp)
    ShapePtr make_sphere(const Value& c, const SourceRange& wc, const Value& r, const SourceRange& wr,
                         const sg::SourceLocation& at);
    ShapePtr make_plane(const Value& n, const SourceRange& wn, const Value& d, const SourceRange& wd,
                        const sg::SourceLocation& at);
    ShapePtr make_box(const Value& a, const SourceRange& wa, const Value& b, const SourceRange& wb,
                      const sg::SourceLocation& at);
    ShapePtr make_triangle(const std::vector<Value>& points, const std::vector<SourceRange>& where,
                           const sg::SourceLocation& at);
    ShapePtr make_mesh(const sg::SourceLocation& at);
    void finish_mesh(ShapeValue& shape, const sg::SourceLocation& at);
    ShapePtr make_mesh2(const Edits<sg::TriangleMesh>& sections, const sg::SourceLocation& at);
    ShapePtr make_obj_mesh(const Value& file, const SourceRange& where, const sg::SourceLocation& at);
    ShapePtr make_union(const sg::SourceLocation& at);
    ShapePtr make_light_group(const Edits<ShapeValue>& edits, const sg::SourceLocation& at);
    // cylinder { base, cap, radius } reads (base, radius, cap, radius).
    ShapePtr make_cone(const std::vector<Value>& values, const std::vector<SourceRange>& where, bool open,
                       const sg::SourceLocation& at, bool cylinder);
    ShapePtr make_torus(const Value& major, const SourceRange& wm, const Value& minor, const SourceRange& wn,
                        const sg::SourceLocation& at);
    ShapePtr make_disc(const std::vector<Value>& values, const std::vector<SourceRange>& where,
                       const std::optional<std::pair<Value, SourceRange>>& hole, const sg::SourceLocation& at);
    ShapePtr make_quadric(const std::vector<Value>& values, const std::vector<SourceRange>& where,
                          const sg::SourceLocation& at);
    ShapePtr make_polygon(const Value& count, const SourceRange& wc, const std::vector<Value>& points,
                          const SourceRange& wp, const sg::SourceLocation& at);
    ShapePtr make_polynomial(sg::Object::Kind kind, const Value& order, const SourceRange& wo,
                             const std::vector<Value>& coefficients, const SourceRange& wc,
                             const sg::SourceLocation& at);
    ShapePtr make_superellipsoid(const Value& exponents, const SourceRange& where, const sg::SourceLocation& at);
    // values: height1, height2, the point count.
    ShapePtr make_prism(const Edits<sg::Prism>& options, const std::vector<Value>& values,
                        const std::vector<SourceRange>& where, const std::vector<Value>& points, const SourceRange& wp,
                        bool open, const sg::SourceLocation& at);
    ShapePtr make_lathe(const Edits<sg::Prism>& options, const Value& count, const SourceRange& wc,
                        const std::vector<Value>& points, const SourceRange& wp, const sg::SourceLocation& at);
    // text { internal N … }: POV-Ray's built-in fonts, which it also ships
    // as files in its include folder: 1 timrom, 2 cyrvetic, 3 crystal,
    // any other number povlogo.
    Value internal_font(const Value& number, const SourceRange& where);
    ShapePtr make_text(const Value& font, const SourceRange& wf, const Value& string, const SourceRange& ws,
                       const Value& thickness, const SourceRange& wt, const Value& offset, const SourceRange& wo,
                       const sg::SourceLocation& at);
    ShapePtr make_sor(const Value& count, const SourceRange& wc, const std::vector<Value>& points,
                      const SourceRange& wp, bool open, const sg::SourceLocation& at);
    ShapePtr make_blob(const Edits<sg::Blob>& items, const sg::SourceLocation& at);
    // values: centre (or base), apex, radius, strength.
    std::function<void(sg::Blob&)> blob_component(bool cylinder, const std::vector<Value>& values,
                                                  const std::vector<SourceRange>& where,
                                                  const Edits<sg::Blob::Component>& mods, const sg::SourceLocation& at);
    // polynomial { order, xyz(i, j, k): c, ... } (shapes.cpp)
    std::function<void(sg::Polynomial&)> polynomial_term(const std::vector<Value>& values,
                                                         const std::vector<SourceRange>& where);
    ShapePtr make_polynomial_from_terms(const Value& order, const SourceRange& wo, const Edits<sg::Polynomial>& terms,
                                        const sg::SourceLocation& at);
    // ---- ovus, sphere_sweep, bicubic_patch, julia_fractal, height_field (curved_shapes.cpp)
    ShapePtr make_ovus(const Value& bottom, const SourceRange& wb, const Value& top, const SourceRange& wt,
                       const sg::SourceLocation& at);
    ShapePtr make_sphere_sweep(int spline, const Value& count, const SourceRange& wc, const std::vector<Value>& items,
                               const SourceRange& wi, const std::optional<std::pair<Value, SourceRange>>& tolerance,
                               const sg::SourceLocation& at);
    std::function<void(sg::BicubicPatch&)> patch_option(const std::string& keyword, const Value& value,
                                                        const SourceRange& where);
    std::function<void(sg::BicubicPatch&)> patch_uv_vectors(const std::vector<Value>& corners,
                                                            const std::vector<SourceRange>& where);
    ShapePtr make_bicubic_patch(const Edits<sg::BicubicPatch>& options, std::vector<Value> values,
                                const SourceRange& where, const sg::SourceLocation& at);
    std::function<void(sg::JuliaFractal&)> julia_max_iteration(const Value& value, const SourceRange& where);
    std::function<void(sg::JuliaFractal&)> julia_precision(const Value& value, const SourceRange& where);
    std::function<void(sg::JuliaFractal&)> julia_slice(const Value& normal, const SourceRange& wn,
                                                       const Value& distance, const SourceRange& wd);
    std::function<void(sg::JuliaFractal&)> julia_power(const Value& x, const SourceRange& wx, const Value& y,
                                                       const SourceRange& wy);
    std::function<void(sg::JuliaFractal&)> julia_function(const std::string& name, const sg::SourceLocation& at);
    ShapePtr make_julia_fractal(const Value& julia, const SourceRange& where, const Edits<sg::JuliaFractal>& items,
                                const sg::SourceLocation& at);
    std::function<void(sg::HeightField&)> unsupported_height_field_format(const std::string& keyword,
                                                                          const sg::SourceLocation& at);
    ShapePtr make_height_field(const Edits<sg::HeightField>& items, const sg::SourceLocation& at);
    std::function<void(sg::HeightField&)> height_field_function(const Value& function, const sg::SourceLocation& at);
    // ---- isosurface (isosurface.cpp)
    std::function<void(sg::FunctionContainer&)> container_box(const Value& a, const SourceRange& wa, const Value& b,
                                                              const SourceRange& wb);
    std::function<void(sg::FunctionContainer&)> container_sphere(const Value& center, const SourceRange& wc,
                                                                 const Value& radius, const SourceRange& wr);
    std::function<void(sg::Isosurface&)> isosurface_number(const std::string& keyword, const Value& value,
                                                           const SourceRange& where);
    std::function<void(sg::Isosurface&)> isosurface_evaluate(const std::array<Value, 3>& values,
                                                             const std::array<SourceRange, 3>& where);
    ShapePtr make_isosurface(const Value& function, const SourceRange& where, const Edits<sg::Isosurface>& items,
                             const sg::SourceLocation& at);
    // ---- parametric (parametric.cpp)
    std::function<void(sg::Parametric&)> parametric_number(const std::string& keyword, const Value& value,
                                                           const SourceRange& where);
    std::function<void(sg::Parametric&)> parametric_precompute(const Value& depth, const SourceRange& where,
                                                               const std::vector<std::string>& axes,
                                                               const sg::SourceLocation& axes_at);
    ShapePtr make_parametric(const std::array<Value, 3>& functions, const std::array<SourceRange, 3>& where,
                             const Value& uv_min, const SourceRange& wmin, const Value& uv_max, const SourceRange& wmax,
                             const Edits<sg::Parametric>& items, const sg::SourceLocation& at);
    // ---- CSG (csg.cpp)
    ShapePtr make_csg(sg::Object::Kind kind, const sg::SourceLocation& at);
    void finish_csg(ShapeValue& shape);
    std::function<void(ShapeValue&)> clip_edit(const std::vector<ShapePtr>& clips, const sg::SourceLocation& at);
    std::function<void(ShapeValue&)> clip_by_bounds_edit(const sg::SourceLocation& at);
    std::function<void(ShapeValue&)> bound_edit(const std::vector<ShapePtr>& bounds, const sg::SourceLocation& at);
    void apply(ShapePtr& shape, const Edits<ShapeValue>& edits);
    Value object_value(const ShapePtr& shape);

    std::function<void(ShapeValue&)> transform_edit(const sg::Mat4& transform);
    // An object's own uv_mapping, before its texture (POV-Ray's UV_FLAG).
    std::function<void(ShapeValue&)> object_uv_mapping(const sg::SourceLocation& at);
    std::function<void(ShapeValue&)> texture_edit(std::shared_ptr<sg::Material> texture);
    std::function<void(ShapeValue&)> interior_texture_edit(std::shared_ptr<sg::Material> texture);
    std::function<void(ShapeValue&)> material_edit(std::shared_ptr<sg::Material> material);
    std::function<void(ShapeValue&)> pigment_edit(const Edits<sg::Pigment>& edits, const sg::SourceLocation& at);
    std::function<void(ShapeValue&)> finish_edit(const Edits<sg::Finish>& edits, const sg::SourceLocation& at);
    std::function<void(ShapeValue&)> interior_edit(std::shared_ptr<sg::Interior> interior);
    std::function<void(ShapeValue&)> child_edit(ShapePtr child);
    // A mesh's triangle or smooth triangle, with its uv_vectors if given.
    std::function<void(ShapeValue&)> mesh_triangle_edit(
        const std::vector<Value>& points, const std::vector<SourceRange>& where,
        const std::optional<std::vector<std::pair<Value, SourceRange>>>& uv_vectors,
        const std::vector<std::shared_ptr<sg::Material>>& textures, const sg::SourceLocation& at);
    // One uv_vectors entry, <u, v> (a float stands for <f, f>); false after
    // reporting a value that is not one.
    bool to_uv(const Value& value, const SourceRange& where, sg::Vec2& uv);
    // POV's mesh { M ... } and mesh2 { M ... }: a copy of the declared mesh M.
    ShapePtr declared_mesh(const std::shared_ptr<const ShapeValue>& declared, const std::string& name,
                           sg::Object::Kind kind, const sg::SourceLocation& at);
    std::function<void(sg::TriangleMesh&)> mesh2_vectors(const std::string& section, const Value& count,
                                                         const SourceRange& wc, const std::vector<Value>& items,
                                                         const SourceRange& wi, const sg::SourceLocation& at);
    std::function<void(sg::TriangleMesh&)> mesh2_indices(const std::string& section, const Value& count,
                                                         const SourceRange& wc, const std::vector<Value>& items,
                                                         const SourceRange& wi, const sg::SourceLocation& at);
    static std::string mesh2_index_out_of_range(const std::string& section, long long index, const char* what,
                                                std::size_t size);
    static std::string mesh2_indices_not_per_face(const std::string& section, std::size_t entries, std::size_t faces);
    // A mesh2 section of literal data, scanned as one token (mesh2_sections.cpp):
    // the token's value, then the section's edit of the mesh.
    Value mesh2_section_token(const RawToken& raw);
    std::function<void(sg::TriangleMesh&)> literal_mesh2_section(const Value& handle, const sg::SourceLocation& at);
    // POV's inside_vector of a mesh or mesh2: normalised; none when zero.
    std::optional<sg::Vec3> inside_vector(const Value& vector, const SourceRange& where);
    std::function<void(ShapeValue&)> mesh_inside_vector_edit(const Value& vector, const SourceRange& where);
    std::function<void(sg::TriangleMesh&)> mesh2_textures(const Value& count, const SourceRange& wc,
                                                          const std::vector<std::shared_ptr<sg::Material>>& textures,
                                                          const sg::SourceLocation& at);

    sg::Mat4 translation(const Value& v, const SourceRange& where);
    sg::Mat4 rotation(const Value& v, const SourceRange& where);
    sg::Mat4 scaling(const Value& v, const SourceRange& where);
    sg::Mat4 matrix(const std::vector<Value>& items, const SourceRange& where);
    sg::Mat4 inverse(const sg::Mat4& m, const SourceRange& where);

    std::shared_ptr<sg::Material> build_texture(const Edits<sg::Material>& edits, const sg::SourceLocation& at);
    std::shared_ptr<sg::Pigment> build_pigment(const Edits<sg::Pigment>& edits, const sg::SourceLocation& at);
    std::shared_ptr<sg::Finish> build_finish(const Edits<sg::Finish>& edits, const sg::SourceLocation& at);
    std::shared_ptr<sg::Interior> build_interior(const Edits<sg::Interior>& edits, const sg::SourceLocation& at);

    // ---- media (media.cpp)
    std::shared_ptr<sg::Media> build_media(const Edits<sg::Media>& edits, const sg::SourceLocation& at);
    std::shared_ptr<sg::Rainbow> build_rainbow(const Edits<sg::Rainbow>& edits, const sg::SourceLocation& at);
    std::function<void(sg::Rainbow&)> rainbow_angle(bool arc, const Value& v, const SourceRange& where);
    std::shared_ptr<sg::Fog> build_fog(const Edits<sg::Fog>& edits, const sg::SourceLocation& at);
    std::function<void(sg::Fog&)> fog_value(const Value& v, const SourceRange& where);
    std::function<void(sg::Fog&)> fog_type(const Value& v, const SourceRange& where);
    std::function<void(sg::Fog&)> fog_octaves(const Value& v, const SourceRange& where);
    std::function<void(sg::Fog&)> fog_transform(const sg::Mat4& transform, const SourceRange& where);
    std::shared_ptr<sg::SkySphere> build_sky_sphere(const Edits<sg::SkySphere>& edits, const sg::SourceLocation& at);
    // A density is a pigment whose pattern without a map reads as grey, its value.
    std::shared_ptr<sg::Pigment> build_density(const Edits<sg::Pigment>& edits, const sg::SourceLocation& at);
    std::function<void(sg::Media&)> media_scattering(const Value& type, const SourceRange& type_at, const Value& colour,
                                                     const SourceRange& colour_at, const Edits<sg::Media>& options);
    std::function<void(sg::Media&)> media_integer(const std::string& name, const Value& v, const SourceRange& where,
                                                  int lowest, int highest);
    std::function<void(sg::Media&)> media_real(const std::string& name, const Value& v, const SourceRange& where,
                                               double lowest, double highest);
    std::function<void(sg::Media&)> media_samples(const Value& min, const SourceRange& min_at, const Value& max,
                                                  const SourceRange& max_at);
    void finish_image_map(sg::ImageMap& image, const sg::SourceLocation& at);
    // POV's EffectiveLanguageVersion now, in whole hundredths as POV
    // compares it (3.7 is 370): the #version in force, 362 before any.
    int effective_language_version() const;
    sg::MapType map_type(const Value& v, const SourceRange& where);
    std::function<void(sg::Finish&)> finish_scalar(const std::string& name, bool albedo, const Value& v,
                                                   const SourceRange& where);

    // ---- patterns, maps and normals (patterns.cpp)
    using PatternEdit = std::function<void(sg::Pattern&)>;
    using PigmentEdit = std::function<void(sg::Pigment&)>;
    PatternEdit pattern_kind(sg::Pattern::Kind kind);
    PatternEdit gradient_pattern(const Value& v, const SourceRange& where);
    PatternEdit spiral_pattern(sg::Pattern::Kind kind, const Value& arms, const SourceRange& where);
    PatternEdit tiling_pattern(const Value& v, const SourceRange& where);
    PatternEdit density_file_pattern(const std::string& name, const sg::SourceLocation& where);
    PatternEdit slope_pattern(const Value& v, const SourceRange& where);
    PatternEdit slope_block(const Value& direction, const SourceRange& where,
                            const std::optional<std::pair<double, double>>& slope_range,
                            const std::optional<std::pair<Value, SourceRange>>& altitude,
                            const std::optional<std::pair<double, double>>& altitude_range, bool point_at);
    PatternEdit fractal_pattern(sg::Pattern::Kind kind, const Value& iterations, const SourceRange& where,
                                const Value* julia_parameter, const SourceRange& wj);
    PatternEdit magnet_pattern(const Value& type, const SourceRange& where, PatternEdit fractal);
    PatternEdit pattern_scalar(const std::string& name, const Value& v, const SourceRange& where);
    PatternEdit pattern_vector(const std::string& name, const Value& v, const SourceRange& where);
    PatternEdit pattern_pair(const std::string& name, const Value& a, const SourceRange& wa, const Value& b,
                             const SourceRange& wb);
    PatternEdit warp_edit(const Edits<sg::Warp>& items, const sg::SourceLocation& at);
    std::function<void(sg::Warp&)> warp_scalar(const std::string& name, const Value& v, const SourceRange& where);
    std::function<void(sg::Warp&)> warp_vector(const std::string& name, const Value& v, const SourceRange& where);
    std::function<void(sg::Warp&)> warp_kind(sg::Warp::Kind kind);
    std::function<void(sg::Warp&)> black_hole(const Value& center, const SourceRange& wc, const Value& radius,
                                              const SourceRange& wr);
    std::function<void(sg::Warp&)> planar_warp(const Value& normal, const SourceRange& wn, const Value& distance,
                                               const SourceRange& wd);
    int noise_generator(const Value& v, const SourceRange& where);

    PigmentEdit patterned_pigment(const PatternEdit& pattern, const sg::SourceLocation& at);
    PigmentEdit block_pigment(const PatternEdit& pattern, const std::vector<Value>& colours, const SourceRange& where,
                              const sg::SourceLocation& at);
    PigmentEdit block_pigment(const PatternEdit& pattern, const std::vector<sg::PigmentRef>& pigments,
                              const sg::SourceLocation& at);
    PigmentEdit block_pigment(const PatternEdit& pattern, const std::vector<std::shared_ptr<sg::Pigment>>& pigments,
                              const sg::SourceLocation& at);
    PigmentEdit average_pigment(const sg::SourceLocation& at);
    PigmentEdit uv_mapping_pigment();
    PatternEdit pigment_pattern(const std::shared_ptr<sg::Pigment>& pigment, const sg::SourceLocation& at);
    PigmentEdit pigment_pattern_edit(const PatternEdit& edit, const sg::SourceLocation& at);
    PigmentEdit color_map_edit(const sg::ColorMapRef& map, const sg::SourceLocation& at);
    PigmentEdit pigment_map_edit(const std::shared_ptr<std::vector<sg::PigmentMapEntry>>& map,
                                 const sg::SourceLocation& at);
    sg::ColorMapRef build_color_map(const std::vector<std::pair<Value, std::vector<Value>>>& entries,
                                    const sg::SourceLocation& at);

    using NormalEdit = std::function<void(sg::Normal&)>;
    sg::NormalRef build_normal(const Edits<sg::Normal>& edits, const sg::SourceLocation& at);
    NormalEdit patterned_normal(const PatternEdit& pattern, const std::optional<std::pair<Value, SourceRange>>& amount,
                                const sg::SourceLocation& at);
    NormalEdit bump_map_normal(const sg::ImageMap& image, const std::optional<std::pair<Value, SourceRange>>& amount,
                               const sg::SourceLocation& at);
    NormalEdit block_normal(const PatternEdit& pattern, const std::optional<std::pair<Value, SourceRange>>& amount,
                            const std::vector<sg::NormalRef>& normals, const sg::SourceLocation& at);
    // An image block's items that belong to another kind of image block
    // (bump_size in an image_map, use_alpha in a bump_map).
    void refuse_foreign_image_items(const sg::ImageMap& image, const char* block);
    PatternEdit image_pattern(const sg::ImageMap& image, const sg::SourceLocation& at);
    // Arrays (arrays.cpp).
    int array_size(const Value& size, const SourceRange& where);
    Value make_array(const std::vector<int>& sizes, const ArrayInit& init, const sg::SourceLocation& at);
    // The element named by the [i][j]… that follows in the token stream.
    // `flat`, if given, receives the element's row-major index.
    Value array_element(const Value& array, const sg::SourceLocation& at, std::size_t* flat_index = nullptr);
    // #declare A[i]… = value: reads the indices and the value, and stores it.
    void assign_array_element(const std::string& name, const RawToken& directive, bool local,
                              const sg::SourceLocation& where);
    bool read_array_indices(const ArrayData& data, const sg::SourceLocation& at, std::size_t& flat,
                            std::vector<int>& indices);
    // Functions (functions.cpp, patterns.cpp).
    Value call_function(const Value& function, const std::vector<Value>& arguments, const SourceRange& where);
    // ---- splines (splines.cpp)
    Value make_spline(const Value& base, const std::vector<int>& kinds, const std::vector<Value>& entries,
                      const sg::SourceLocation& at);
    Value call_spline(const Value& spline, const Value& time, const SourceRange& where, int kind);
    // ---- trace(), inside(), min_extent(), max_extent() (geometry_queries.cpp)
    Value trace(const Value& object, const SourceRange& wo, const Value& origin, const SourceRange& w1,
                const Value& direction, const SourceRange& w2, const std::string& normal_name,
                const SourceRange& where);
    Value inside(const Value& object, const SourceRange& wo, const Value& point, const SourceRange& wp);
    Value extent(const Value& object, const SourceRange& wo, bool upper_corner);
    const sg::GeometryQueries* geometry_queries(const std::string& what, const sg::SourceLocation& at);
    Value pattern_function(const Edits<sg::Pigment>& edits, const sg::SourceLocation& at);
    Value pigment_function(const std::shared_ptr<sg::Pigment>& pigment, const sg::SourceLocation& at);
    Value transform_function(const sg::Mat4& transform, const sg::SourceLocation& at);
    // function { spline { … } }: the spline called with the first argument.
    Value spline_function(const Value& spline, const sg::SourceLocation& at);
    PatternEdit function_pattern(const Value& function, const sg::SourceLocation& at);
    // object { O [list] }: inside O (1) or outside (0), a block pattern of two.
    PatternEdit object_pattern(const std::shared_ptr<ShapeValue>& shape, const sg::SourceLocation& at);
    void missing_weight(const sg::SourceLocation& at, const char* map);
    NormalEdit normal_pattern_edit(const PatternEdit& edit, const sg::SourceLocation& at);
    NormalEdit normal_accuracy(const Value& v, const SourceRange& where);
    sg::SlopeMapEntry slope_entry(const Value& value, const SourceRange& wv, const Value& slope, const SourceRange& ws);
    // An image_map's `filter N, v` or `transmit N, v`.
    sg::PaletteSetting palette_setting(bool transmit, const Value& index, const SourceRange& wi, const Value& value,
                                       const SourceRange& wv);
    std::function<void(ShapeValue&)> normal_edit(const Edits<sg::Normal>& edits, const sg::SourceLocation& at);
    // A pigment, normal or finish block written in a texture or on an
    // object: edits of what the texture has (its top layer's).
    std::function<void(sg::Material&)> material_pigment_edit(const Edits<sg::Pigment>& edits,
                                                             const sg::SourceLocation& at);
    std::function<void(sg::Material&)> material_normal_edit(const Edits<sg::Normal>& edits,
                                                            const sg::SourceLocation& at);
    std::function<void(sg::Material&)> material_finish_edit(const Edits<sg::Finish>& edits,
                                                            const sg::SourceLocation& at);
    // What every built pigment, normal and finish gets once its items ran:
    // POV's default maps and block colours, albedo rescaling, checks.
    void settle_pigment(sg::Pigment& pigment, const sg::SourceLocation& at);
    void settle_normal(sg::Normal& normal, const sg::SourceLocation& at);
    void settle_finish(sg::Finish& finish, const sg::SourceLocation& at);
    // Patterned and layered textures (patterns.cpp). POV-Ray layers only
    // over a plain texture, and never a patterned one.
    static bool top_layer_is_patterned(const sg::Material& texture);
    // An error, and true, when an object's pigment, normal or finish would
    // lie over its patterned texture (objects.cpp).
    bool refuse_layer_over_pattern(const ShapeValue& s, const sg::SourceLocation& at);
    std::shared_ptr<sg::Material> layer_texture(std::shared_ptr<sg::Material> below,
                                                const std::shared_ptr<sg::Material>& above);
    // POV's material_map: the image's palette index (or its red, 0-255) at
    // a point picks the texture, counted modulo the list.
    std::function<void(sg::Material&)> material_map_edit(const sg::ImageMap& image,
                                                         const std::vector<std::shared_ptr<sg::Material>>& textures,
                                                         const sg::SourceLocation& at);
    std::function<void(sg::Material&)> texture_pattern(const PatternEdit& pattern,
                                                       const std::vector<std::shared_ptr<sg::Material>>& blocks,
                                                       const sg::SourceLocation& at);
    std::function<void(sg::Material&)> average_texture(const sg::SourceLocation& at);
    std::function<void(sg::Material&)> texture_map_edit(const std::vector<sg::TextureMapEntry>& entries,
                                                        const sg::SourceLocation& at);
    // The texture a new texture, or an object's first pigment or finish,
    // starts from: POV's #default texture (without its layers or pattern).
    sg::Material default_texture() const;

    // ---- lights, camera, settings (lights_camera.cpp)
    sg::Light make_light(const Value& position, const SourceRange& wp, const Value& colour, const SourceRange& wc,
                         const sg::SourceLocation& at);
    void apply_light(sg::Light& light, const Edits<sg::Light>& edits);
    std::function<void(sg::Light&)> area_light(const Value& a1, const SourceRange& w1, const Value& a2,
                                               const SourceRange& w2, const Value& n1, const SourceRange& wn1,
                                               const Value& n2, const SourceRange& wn2);
    std::function<void(sg::Light&)> area_rectangle(const Value& a1, const SourceRange& w1, const Value& a2,
                                                   const SourceRange& w2);
    // ---- the camera (camera.cpp)
    double camera_angle(const Value& v, const SourceRange& where);
    sg::Camera::Projection cylinder_camera(const Value& v, const SourceRange& where);
    std::function<void(CameraSpec&)> blur_samples(const Value& first, const SourceRange& wf, const Value* second,
                                                  const SourceRange& ws);
    std::function<void(CameraSpec&)> blur_confidence(const Value& v, const SourceRange& where);
    std::function<void(CameraSpec&)> blur_variance(const Value& v, const SourceRange& where);
    // ---- the mesh camera (mesh_camera.cpp)
    // mesh_camera { rays_per_pixel, distribution_type [, max_ray_distance]
    // meshes [smooth] }; smooth_at is where `smooth` was written, if it
    // was, and close_at the block's closing brace.
    std::function<void(CameraSpec&)> mesh_camera(const Value& rays, const SourceRange& wr, const Value& distribution,
                                                 const SourceRange& wd,
                                                 const std::optional<std::pair<Value, SourceRange>>& reach,
                                                 const std::vector<std::pair<ShapePtr, sg::SourceLocation>>& meshes,
                                                 const std::optional<sg::SourceLocation>& smooth_at,
                                                 const sg::SourceLocation& at, const sg::SourceLocation& close_at);
    void add_object(const ShapePtr& shape);
    void add_light(const sg::Light& light, const sg::Mat4& world_from_local);
    void check_area_light(sg::Light& light);
    void set_assumed_gamma(double gamma);
    std::function<void(sg::Light&)> looks_like(const ShapePtr& shape, const Edits<ShapeValue>& edits);
    std::function<void(sg::Light&)> projected_through(const ShapePtr& shape, const Edits<ShapeValue>& edits);
    void set_camera(const CameraSpec& spec);
    void render_setting(const std::string& name, const SourceRange& wn, const Value& v, const SourceRange& wv,
                        const Edits<ParameterList>& parameters);
    std::function<void(ParameterList&)> parameter_edit(const std::string& name, const Value& v,
                                                       const SourceRange& where);

    // ---- files the scene names (files.cpp)
    enum class FileSearch { Found, Missing, Refused };
    // Finds `name`: as is when absolute, else in each folder in turn ("" is
    // the current folder). Refused (already reported at `where`) when safe
    // mode forbids the path; a forbidden name is refused whether or not the
    // file exists, so errors reveal nothing about the disk outside.
    // Where a file named at `where` is looked for: the folder of the file
    // naming it, then the include path.
    std::vector<std::string> search_folders(const sg::SourceLocation& where) const;
    FileSearch find_file(const std::string& name, const std::vector<std::string>& folders,
                         const sg::SourceLocation& where, const std::string& what, std::string& found);
    // An image a scene names (image_map, height_field): beside the file that
    // names it, on the include path, then in the current folder. False
    // (reported at `where`) when missing or refused by safe mode.
    bool find_image_file(const std::string& name, const sg::SourceLocation& where, std::string& found);
    // Safe mode's allowed folders: safe_root (else the scene's folder) and include_path.
    void init_safe_roots(const std::string& scene_folder);
    // False only in safe mode, for a path outside the allowed folders.
    bool allowed_file(const std::string& path) const;
    // False only in safe mode, for a path outside the scene's folder (the
    // only place --safe lets a scene's #fopen write).
    bool allowed_write(const std::string& path) const;
    void refuse_file(const sg::SourceLocation& where, const std::string& what, const std::string& name);
    // True when the file is no larger than max_file_bytes (or its size is
    // unknown); else false with a located error.
    bool within_file_limit(const std::string& path, const sg::SourceLocation& where, const std::string& what);
    // run() and run_file(), given how to get the main file's text (false:
    // it could not be read, and an error says why).
    ParseResult run_with(const std::function<bool(std::string&)>& read_text, const std::string& label,
                         const std::string& path, const std::string& folder);
    // Reads a whole file after checking its size against max_file_bytes;
    // false with a located error when it cannot.
    bool read_file(const std::string& path, const sg::SourceLocation& where, const std::string& what,
                   std::string& text);
    // read_file for the file at `path` already open as `in`.
    bool read_open_file(std::ifstream& in, const std::string& path, const sg::SourceLocation& where,
                        const std::string& what, std::string& text);
    // Counts triangles against max_triangles; false (error reported once) past it.
    bool add_triangles(long count, const sg::SourceLocation& where);

    // ---- for directives.cpp and token_stream.cpp
    struct Frame;
    struct Macro;
    struct Control;
    class ObjMaterialReader;

  private:
    friend struct TokenStreamAccess;
    // token stream internals (token_stream.cpp)
    // A token to read again: a start symbol, or a raw token put back (it is
    // classified again, so it sees declarations made meanwhile).
    struct Pending {
        const RawToken* raw = nullptr;         // points into a buffer kept in m_buffers
        std::shared_ptr<const Symbol> symbol;  // start symbols only
        const void* frame = nullptr;           // where raw was read, so it can be put back
        size_t index = 0;
        bool classified = false;  // its bracket was counted in m_nesting
    };
    void rewind_lookahead();
    bool take_punct(const char* punct);
    // Whether the next raw token is `text` of that kind; take_raw takes it
    // if so.
    bool next_is_raw(RawKind kind, std::string_view text);
    bool take_raw(RawKind kind, std::string_view text);
    bool push_file(std::string text, const std::string& label, const std::string& path, const std::string& folder,
                   const sg::SourceLocation& included_from);
    // Where a name resolves, innermost scope first: its value (null when
    // undeclared), the scope holding it, and the caller's variable when it
    // is a macro parameter that stands for one.
    struct NameLookup {
        const Value* value = nullptr;
        std::size_t scope = 0;
        const VariableReference* reference = nullptr;
    };
    Symbol classify(const RawToken& raw);
    // The value of a RawKind::Vector token read from a file in m_buffers.
    Value vector_literal(const RawToken& raw) const;
    // function [(params)] { … } read from the token stream (functions.cpp):
    // a FUNCTION_LITERAL, or FUNCTION_OPEN before a pattern, pigment or transform body.
    std::optional<Symbol> read_function(const RawToken& keyword);
    Symbol symbol_for_identifier(const RawToken& raw);
    Symbol symbol_for_identifier(const RawToken& raw, const NameLookup& found);
    Symbol symbol_for_constant(const RawToken& raw);
    Kind token_for_value(const Value& value);
    Symbol make_symbol(Kind kind, const RawToken& raw, Value value = {});
    SourceRange token_range(const RawToken& raw) const;  // what its symbol spans
    // A declared value that is a plain expression ending in ';', read and
    // evaluated without the grammar (plain_values.cpp), the ';' left to
    // take; none, with nothing read, for any other value.
    class PlainValueReader;
    std::optional<Value> read_plain_value();
    // The same for a directive's `(condition)`, read with its parentheses,
    // and for an item of #write's list (ending in ',' or ')', left to take).
    std::optional<Value> read_plain_condition();
    std::optional<Value> read_plain_item();
    bool may_read_plain() const;
    std::optional<Value> read_plain(std::size_t first, std::string_view terminators, bool take_terminator);
    const RawToken* peek_raw();
    const RawToken* take_raw();
    bool directives_blocked() const;
    Symbol read_token();
    bool macro_waits_for_value_end() const;
    bool skip_ignored_block(const RawToken& keyword);
    void pop_frame();
    Value parse_nested(Kind start, const sg::SourceLocation& at, bool barrier);
    std::vector<Value> parse_arguments(const sg::SourceLocation& at);
    void abort_parse();

    // directives (directives.cpp)
    void run_directive(const RawToken& directive);
    void directive_declare(const RawToken& directive, bool local);
    void directive_if(const RawToken& directive, bool ifdef, bool negate);
    void directive_else(const RawToken& directive, bool elseif);
    void directive_while(const RawToken& directive);
    void directive_for(const RawToken& directive);
    void directive_switch(const RawToken& directive);
    void directive_case(const RawToken& directive, bool range);
    void directive_break(const RawToken& directive);
    void directive_end(const RawToken& directive);
    void directive_macro(const RawToken& directive);
    void directive_include(const RawToken& directive);
    void directive_message(const RawToken& directive);
    void directive_undef(const RawToken& directive);
    void directive_version(const RawToken& directive);
    void directive_default(const RawToken& directive);
    // user files (user_files.cpp)
    void directive_fopen(const RawToken& directive);
    void directive_fclose(const RawToken& directive);
    void directive_read(const RawToken& directive);
    void directive_write(const RawToken& directive);
    int take_binary_type();  // an index of user_files.cpp's binary types, or -1
    void write_binary_values(const RawToken& directive, int type, std::string& out);
    std::shared_ptr<UserFile> user_file_argument(const RawToken& directive, bool reading, std::string& handle);
    void close_user_file(const std::string& handle);
    std::optional<Value> read_user_value(UserFile& file);
    bool at_user_file_end(UserFile& file);
    void expand_macro(const RawToken& name, const Macro& macro);
    enum class SkipStop { End, ElseOrEnd, CaseOrEnd };
    const RawToken* skip_block(const sg::SourceLocation& opened_at, const std::string& opener, SkipStop stop);
    bool expect_raw_punct(const char* punct, const std::string& context);
    std::string expect_raw_identifier(const std::string& context, sg::SourceLocation* where = nullptr);
    bool evaluate_condition(const RawToken& directive, const std::string& what);
    // A #local goes to scope `local_scope` (an index into m_scopes; the
    // innermost when absent): the scope where its directive stands, which
    // a value written by a macro must not change.
    void store(const std::string& name, Value value, bool local, const sg::SourceLocation& where,
               std::optional<std::size_t> local_scope = std::nullopt);
    const Value* lookup(const std::string& name) const;
    NameLookup find_name(const HashedName& name) const;
    // #ifdef's and defined()'s test: a declared identifier or macro, or for
    // Name[i]… an array element that has a value (the indices are read).
    bool identifier_defined(const std::string& name, const sg::SourceLocation& at);

    ParseOptions m_options;
    std::vector<std::string> m_safe_roots;  // canonical; set by run() in safe mode
    long m_triangles = 0;
    int m_warning_count = 0;  // warnings and notes, stored or dropped
    bool m_triangle_limit_reported = false;
    sg::SceneGraph m_scene;
    std::vector<Diagnostic> m_diagnostics;
    int m_error_count = 0;
    bool m_aborted = false;
    bool m_suppress_syntax_errors = false;

    std::vector<std::shared_ptr<Frame>> m_frames;
    std::vector<Pending> m_pending;
    std::optional<Pending> m_last_returned;
    std::vector<NameMap<Value>> m_scopes;
    // Per scope, the macro parameters that stand for a caller's variable.
    std::vector<NameMap<VariableReference>> m_references;
    void push_scope();
    void pop_scope();
    const Value* referenced_value(const VariableReference& reference) const;
    void write_reference(const VariableReference& reference, Value value);
    // The identifier token read last: where it stood and what it names.
    struct IdentifierUse {
        SourceRange range;
        VariableReference variable;
    };
    std::optional<IdentifierUse> m_last_identifier;
    void remember_identifier(const SourceRange& range, const std::string& name, const NameLookup& found);
    NameMap<std::shared_ptr<const Macro>> m_macros;
    // Every inclusion gets its own label pointer; its include chain is kept here.
    std::map<const std::string*, std::vector<sg::SourceLocation>> m_include_chains;
    std::map<const std::string*, std::shared_ptr<const TokenBuffer>> m_buffers;
    struct Mesh2Section;
    std::vector<Mesh2Section> m_mesh2_sections;  // the MESH2_SECTION tokens read
    int m_barrier_depth = -1;                    // directives in frames at or below this depth wait
    int m_barrier_nesting = 0;                   // the bracket nesting where the declared value began
    Parser::symbol_kind_type m_previous_kind = Parser::symbol_kind::S_YYEMPTY;
    int m_nested_base_depth = 0;
    int m_nesting = 0;  // open ( { [ in the token stream
    long m_tokens_read = 0;
    int m_macro_depth = 0;
    std::optional<Value> m_nested_result;
    std::optional<std::vector<MacroArgument>> m_nested_arguments;
    bool m_nested_had_lookahead = false;
    std::string m_last_undeclared;
    sg::SourceLocation m_last_location;  // end of the last token read, for end-of-file errors
    std::shared_ptr<sg::Material> m_default_texture;
    struct Deprecation {
        std::string message;
        bool once = false;
        bool warned = false;
    };
    std::unordered_map<std::string, Deprecation> m_deprecated;
    bool m_saw_version = false;  // a #version, or ParseOptions::language_version
    bool m_saw_assumed_gamma = false;
    std::size_t m_string_bytes = 0;                     // produced by concat() so far (ParseOptions::max_string_bytes)
    MemoryBudget m_memory{m_options.max_memory_bytes};  // ParseOptions::max_memory_bytes
    // Whether the parse has grown past its memory budget, or would with
    // `more` bytes: then a located error at `at` and the parse stops.
    bool memory_exhausted(const sg::SourceLocation& at, long long more = 0);
    double m_language_version = 3.7;  // POV-Ray's default without #version
    void settle_version_defaults();
    bool m_saw_camera = false;
    // seed()'s streams, numbered from 0 as POV-Ray numbers them: each one
    // the 32-bit state of POV-Ray's generator (builtins.cpp).
    std::vector<std::uint32_t> m_random_streams;
    std::vector<std::unique_ptr<Parser>> m_parsers;  // reused by nested parses, one per level
    size_t m_parser_depth = 0;
    std::string m_previous_word;             // the last word read, names the block a '{' opens
    std::vector<std::string> m_block_names;  // open { } blocks, for syntax error hints
    std::string m_last_closed_block;

    friend class Parser;
    friend class FunctionCompiler;
    friend class ObjMaterialReader;
    friend Value builtin_rand(Evaluator& ev, const std::vector<Value>& args, const SourceRange& where);
    friend Value builtin_seed(Evaluator& ev, const std::vector<Value>& args, const SourceRange& where);
};

// Frames of the token stream: a file or a macro body being read.
struct Evaluator::Control {
    enum class Kind { If, While, For, Switch, Macro };
    Kind kind = Kind::If;
    sg::SourceLocation opened_at;
    size_t loop_position = 0;  // While: the token after #while; For: first body token
    long iterations = 0;
    std::string variable;  // For
    double end = 0.0, step = 1.0;
    double switch_value = 0.0;  // Switch
    bool case_matched = false;  // Switch: a #case ran, later ones are skipped
};

struct Evaluator::Mesh2Section {
    std::shared_ptr<const TokenBuffer> buffer;
    const RawToken* raw = nullptr;  // the RawKind::Mesh2Section token, in buffer
};

struct Evaluator::Frame {
    std::shared_ptr<const TokenBuffer> buffer;
    size_t position = 0;
    size_t end = 0;
    bool is_macro = false;
    bool owns_scope = false;
    std::string name;  // file label or macro name
    sg::SourceLocation called_from;
    std::vector<Control> controls;
};

struct Evaluator::Macro {
    std::string name;
    std::vector<std::string> parameters;
    std::shared_ptr<const TokenBuffer> buffer;
    size_t body_begin = 0, body_end = 0;
    sg::SourceLocation defined_at;
};

}  // namespace lancer::parse
