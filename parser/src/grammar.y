/* The scene grammar (POV-Ray 3.7 subset plus lancer's extensions).
 *
 * The parser never sees a directive: the token stream (token_stream.cpp)
 * runs #declare/#if/#while/#macro/#include ... itself and hands over the
 * tokens that remain, with every identifier already looked up and typed
 * (OBJECT_ID, TEXTURE_ID, VALUE_ID ...). Actions therefore evaluate as they
 * reduce: an expression folds to a Value, a block folds to a list of edits
 * applied in the order written (evaluator.h explains the design).
 *
 * Several entry points share the grammar: a whole scene, the value of a
 * #declare, a directive's expression, a macro's arguments. The token stream
 * selects one by sending a START_* token first.
 */
%skeleton "lalr1.cc"
%require "3.8"
%header
%define api.namespace {lancer::parse}
%define api.parser.class {Parser}
%define api.token.constructor
%define api.token.raw
%define api.value.type variant
%define api.token.prefix {TOK_}
%define api.location.type {lancer::parse::SourceRange}
%define parse.error detailed
%define parse.lac none  // nested parses end on a default reduction, which LAC would refuse
%locations
%param {Evaluator& ev}

%code requires {
#include "value.h"
namespace lancer::parse { class Evaluator; }
}

%code {
#include "evaluator.h"
namespace lancer::parse {
Parser::symbol_type yylex(Evaluator& ev) { return ev.next_token(); }

// Bison's stack pushes a default-made symbol and then moves the new one into
// it: a zero-fill and two moves through the switch over every semantic type,
// for each shift and each reduction, which is a quarter of a loop's parse. One
// move construction does the same (the moved-from symbol is left empty,
// as bison's own move leaves it). Written for bison 3.8's lalr1.cc, whose
// stack is std::vector; another skeleton's stack fails to compile here.
template <>
void Parser::stack<Parser::stack_symbol_type, std::vector<Parser::stack_symbol_type>>::push(stack_symbol_type&& symbol) {
    seq_.emplace_back(std::move(symbol));
}
}
#define LOC(range) (range).begin
}

%token END 0 "end of file"
%token START_SCENE "start of scene" START_VALUE "start of value" START_EXPR "start of expression"
       START_ARGS "start of arguments" START_COND "start of condition" START_STRING "start of file name"
       START_INDEX "start of an index"
%token LBRACE "{" RBRACE "}" LPAREN "(" RPAREN ")" LBRACKET "[" RBRACKET "]"
       LT "<" GT ">" LE "<=" GE ">=" EQ "=" NE "!=" PLUS "+" MINUS "-" STAR "*" SLASH "/"
       COMMA "," SEMI ";" DOT "." QUESTION "?" COLON ":" AND "&" OR "|" NOT "!"
%token <TokenValue> NUMBER "number" STRING "string" CONSTANT "constant" BUILTIN "function"
       VALUE_ID "identifier" OBJECT_ID "object identifier" TEXTURE_ID "texture identifier"
       PIGMENT_ID "pigment identifier" FINISH_ID "finish identifier"
       NORMAL_ID "normal identifier" COLOR_MAP_ID "color_map identifier"
       PIGMENT_MAP_ID "pigment_map identifier" NORMAL_MAP_ID "normal_map identifier"
       INTERIOR_ID "interior identifier" CAMERA_ID "camera identifier"
       LIGHT_ID "light_source identifier" TRANSFORM_ID "transform identifier"
       FUNCTION_LITERAL "function definition" FUNCTION_ID "function identifier" SPLINE_ID "spline identifier" MEDIA_ID "media identifier"
       SKY_SPHERE_ID "sky_sphere identifier" FOG_ID "fog identifier" RAINBOW_ID "rainbow identifier"
       UNDECLARED_ID "undeclared identifier" DIRECTIVE "directive" FUNCTION_OPEN "function {"
       UNSUPPORTED "unsupported keyword" VECTOR_LITERAL "vector"
       MESH2_SECTION "mesh2 section"

/* Keywords: the alias is the spelling; token_stream.cpp (keyword_table) builds its table from these. */
%token SPHERE "sphere" PLANE "plane" BOX "box" TRIANGLE "triangle" SMOOTH_TRIANGLE "smooth_triangle"
       MESH "mesh" MESH2 "mesh2" UNION "union" MERGE "merge" DIFFERENCE "difference"
       INTERSECTION "intersection" OBJECT "object" OBJ_MESH "obj_mesh"
       LIGHT_GROUP "light_group" GLOBAL_LIGHTS "global_lights"
       LIGHT_SOURCE "light_source" CAMERA "camera" MESH_CAMERA "mesh_camera" BACKGROUND "background"
       SKY_SPHERE "sky_sphere" FOG "fog" FOG_TYPE "fog_type" FOG_OFFSET "fog_offset" FOG_ALT "fog_alt"
       TURB_DEPTH "turb_depth" DISTANCE "distance" RAINBOW "rainbow" WIDTH "width" ARC_ANGLE "arc_angle"
       FALLOFF_ANGLE "falloff_angle"
       GLOBAL_SETTINGS "global_settings" RENDER_SETTINGS "render_settings"
       TRANSLATE "translate" ROTATE "rotate" SCALE "scale" MATRIX "matrix" TRANSFORM "transform"
       INVERSE "inverse" TEXTURE "texture" PIGMENT "pigment" FINISH "finish" INTERIOR "interior"
       MATERIAL "material" NO_SHADOW "no_shadow" HOLLOW "hollow" DOUBLE_ILLUMINATE "double_illuminate"
       INTERIOR_TEXTURE "interior_texture"
       NO_IMAGE "no_image" NO_REFLECTION "no_reflection" INSIDE_VECTOR "inside_vector"
       COLOR "color" COLOUR "colour" RGB "rgb" RGBF "rgbf" RGBT "rgbt" RGBFT "rgbft"
       SRGB "srgb" SRGBF "srgbf" SRGBT "srgbt" SRGBFT "srgbft"
       RED "red" GREEN "green" BLUE "blue" FILTER "filter" TRANSMIT "transmit" GRAY "gray" GREY "grey"
       CHECKER "checker" TILES "tiles" TILE2 "tile2" IMAGE_MAP "image_map" PNG "png" JPEG "jpeg" EXR "exr" HDR "hdr" TGA "tga"
       TIFF "tiff" MAP_TYPE "map_type" INTERPOLATE "interpolate" ONCE "once" ALL "all" GAMMA "gamma"
       IMAGE_PATTERN "image_pattern" USE_ALPHA "use_alpha" IRID "irid" THICKNESS "thickness"
       IRID_WAVELENGTH "irid_wavelength" ARRAY "array"
       QUICK_COLOR "quick_color" QUICK_COLOUR "quick_colour" NO_RADIOSITY "no_radiosity" MM_PER_UNIT "mm_per_unit"
       AMBIENT "ambient" EMISSION "emission" DIFFUSE "diffuse" BRILLIANCE "brilliance"
       SPECULAR "specular" ROUGHNESS "roughness" PHONG "phong" PHONG_SIZE "phong_size"
       METALLIC "metallic" REFLECTION "reflection" REFLECTION_EXPONENT "reflection_exponent" FRESNEL "fresnel" FALLOFF "falloff"
       EXPONENT "exponent" ALBEDO "albedo" CONSERVE_ENERGY "conserve_energy" CRAND "crand"
       IOR "ior" CAUSTICS "caustics" DISPERSION "dispersion" DISPERSION_SAMPLES "dispersion_samples"
       VERTEX_VECTORS "vertex_vectors" NORMAL_VECTORS "normal_vectors" UV_VECTORS "uv_vectors"
       FACE_INDICES "face_indices" NORMAL_INDICES "normal_indices" UV_INDICES "uv_indices"
       TEXTURE_LIST "texture_list"
       LOCATION "location" LOOK_AT "look_at" ANGLE "angle" UP "up" RIGHT "right" SKY "sky"
       DIRECTION "direction" PERSPECTIVE "perspective" ORTHOGRAPHIC "orthographic"
       APERTURE "aperture" BLUR_SAMPLES "blur_samples" FOCAL_POINT "focal_point"
       CONFIDENCE "confidence" VARIANCE "variance" BOKEH "bokeh" FISHEYE "fisheye" ULTRA_WIDE_ANGLE "ultra_wide_angle"
       OMNIMAX "omnimax" PANORAMIC "panoramic"
       PARALLEL "parallel" POINT_AT "point_at" AREA_LIGHT "area_light" JITTER "jitter"
       ADAPTIVE "adaptive" CIRCULAR "circular" ORIENT "orient" AREA_SPHERE "area_sphere" AREA_RECTANGLE "area_rectangle" CYLINDER "cylinder" PROJECTED_THROUGH "projected_through"
       FADE_DISTANCE "fade_distance" FADE_POWER "fade_power" SHADOWLESS "shadowless"
       AREA_ILLUMINATION "area_illumination" LOOKS_LIKE "looks_like" SPOTLIGHT "spotlight"
       RADIUS "radius" TIGHTNESS "tightness" MEDIA_INTERACTION "media_interaction"
       MEDIA_ATTENUATION "media_attenuation"
       ASSUMED_GAMMA "assumed_gamma" MAX_TRACE_LEVEL "max_trace_level" AMBIENT_LIGHT "ambient_light"
       ADC_BAILOUT "adc_bailout" CHARSET "charset" NUMBER_OF_WAVES "number_of_waves"
       NOISE_GENERATOR "noise_generator" MAX_INTERSECTIONS "max_intersections"
       CONE "cone" TORUS "torus" DISC "disc" QUADRIC "quadric"
       POLYGON "polygon" POLY "poly" CUBIC "cubic" QUARTIC "quartic" SUPERELLIPSOID "superellipsoid"
       TEXT "text" TTF "ttf" INTERNAL "internal" SOR "sor" LATHE "lathe" PRISM "prism" LINEAR_SWEEP "linear_sweep" CONIC_SWEEP "conic_sweep" LINEAR_SPLINE "linear_spline"
       QUADRATIC_SPLINE "quadratic_spline" CUBIC_SPLINE "cubic_spline" BEZIER_SPLINE "bezier_spline"
       BLOB "blob" THRESHOLD "threshold" COMPONENT "component" STRENGTH "strength" HIERARCHY "hierarchy" OPEN "open" STURM "sturm"
       CLIPPED_BY "clipped_by" BOUNDED_BY "bounded_by"
       OVUS "ovus" SPHERE_SWEEP "sphere_sweep" B_SPLINE "b_spline" TOLERANCE "tolerance"
       BICUBIC_PATCH "bicubic_patch" TYPE "type" FLATNESS "flatness" U_STEPS "u_steps" V_STEPS "v_steps"
       ACCURACY "accuracy"
       JULIA_FRACTAL "julia_fractal" QUATERNION "quaternion" HYPERCOMPLEX "hypercomplex"
       MAX_ITERATION "max_iteration" PRECISION "precision" SLICE "slice" CUBE "cube" RECIPROCAL "reciprocal" PWR "pwr"
       HEIGHT_FIELD "height_field" WATER_LEVEL "water_level" SMOOTH "smooth" PREMULTIPLIED "premultiplied"
       GIF "gif" PGM "pgm" PPM "ppm" BMP "bmp" SYS "sys" IFF "iff" POT "pot"
       POLYNOMIAL "polynomial" XYZ "xyz" HF_GRAY_16 "hf_gray_16"
       UV_MAPPING "uv_mapping" PIGMENT_PATTERN "pigment_pattern" FADE_COLOR "fade_color" FADE_COLOUR "fade_colour" TEXTURE_MAP "texture_map" MATERIAL_MAP "material_map" NORMAL "normal" COLOR_MAP "color_map" COLOUR_MAP "colour_map" PIGMENT_MAP "pigment_map"
       NORMAL_MAP "normal_map" SLOPE_MAP "slope_map" BUMP_SIZE "bump_size" BUMP_MAP "bump_map"
       USE_COLOR "use_color" USE_COLOUR "use_colour" USE_INDEX "use_index" AVERAGE "average"
       AGATE "agate" AOI "aoi" BOXED "boxed" BOZO "bozo" SPOTTED "spotted" BUMPS "bumps" CELLS "cells"
       CRACKLE "crackle" CYLINDRICAL "cylindrical" DENTS "dents" FACETS "facets" GRADIENT "gradient"
       GRANITE "granite" HEXAGON "hexagon" LEOPARD "leopard" MARBLE "marble" ONION "onion" PAVEMENT "pavement"
       PLANAR "planar" QUILTED "quilted" RADIAL "radial" RIPPLES "ripples" SLOPE "slope" SPHERICAL "spherical"
       SPIRAL1 "spiral1" SPIRAL2 "spiral2" SQUARE "square" TILING "tiling" TRIANGULAR "triangular"
       WAVES "waves" WOOD "wood" WRINKLES "wrinkles" BRICK "brick" MANDEL "mandel" JULIA "julia" MAGNET "magnet"
       TURBULENCE "turbulence" OCTAVES "octaves" OMEGA "omega" LAMBDA "lambda" FREQUENCY "frequency"
       PHASE "phase" RAMP_WAVE "ramp_wave" TRIANGLE_WAVE "triangle_wave" SINE_WAVE "sine_wave"
       SCALLOP_WAVE "scallop_wave" CUBIC_WAVE "cubic_wave" POLY_WAVE "poly_wave" WARP "warp"
       REPEAT "repeat" OFFSET "offset" FLIP "flip" BLACK_HOLE "black_hole" TOROIDAL "toroidal"
       ORIENTATION "orientation" DIST_EXP "dist_exp" MAJOR_RADIUS "major_radius"
       AGATE_TURB "agate_turb" BRICK_SIZE "brick_size" MORTAR "mortar" FORM "form" METRIC "metric"
       SOLID "solid" COORDS "coords" SIZE "size" EXTERIOR "exterior" CONTROL0 "control0" CONTROL1 "control1"
       NUMBER_OF_SIDES "number_of_sides" NUMBER_OF_TILES "number_of_tiles" ALTITUDE "altitude"
       DENSITY_FILE "density_file" DF3 "df3" PATTERN "pattern"
       ISOSURFACE "isosurface" CONTAINED_BY "contained_by" MAX_GRADIENT "max_gradient" EVALUATE "evaluate"
       MAX_TRACE "max_trace" ALL_INTERSECTIONS "all_intersections" PARAMETRIC "parametric" PRECOMPUTE "precompute"
       TRACE "trace" INSIDE "inside" MIN_EXTENT "min_extent" MAX_EXTENT "max_extent"
       SPLINE "spline" NATURAL_SPLINE "natural_spline"
       MEDIA "media" ABSORPTION "absorption" SCATTERING "scattering" ECCENTRICITY "eccentricity"
       EXTINCTION "extinction" DENSITY "density" METHOD "method" INTERVALS "intervals" SAMPLES "samples"
       RATIO "ratio" AA_LEVEL "aa_level" AA_THRESHOLD "aa_threshold" COLLECT "collect" DENSITY_MAP "density_map"

%nterm <Value> declared_non_scalar declared_identifier array_scalar expr arith postfix primary colour colour_base declared_value string_value bare_colour
%nterm <std::vector<Value>> arith_seq mesh2_items expr_list opt_args vector_items
%nterm <std::vector<MacroArgument>> macro_args macro_arg_list macro_arg_list_plain macro_arg_list_object
%nterm <Value> macro_arg vector_item spline_literal angle_without_comma
%nterm <std::vector<int>> array_sizes
%nterm <ArrayInit> array_init array_item array_scalar_item
%nterm <std::vector<ArrayInit>> array_items
%nterm <std::string> component param_name
%nterm <ShapePtr> object object_ref
%nterm <Edits<ShapeValue>> object_mods union_items mesh_items light_group_items
%nterm <std::function<void(ShapeValue&)>> object_mod union_item mesh_item light_group_item
%nterm <sg::Mat4> transform_item transform_block transform_items
%nterm <std::shared_ptr<sg::Material>> texture material
%nterm <Edits<sg::Material>> texture_items material_items
%nterm <std::shared_ptr<sg::Pigment>> pigment
%nterm <Edits<sg::Pigment>> pigment_mods pigment_block pigment_edits
%nterm <std::function<void(sg::Pigment&)>> pigment_start pigment_type unweighted_start
%nterm <std::shared_ptr<sg::Pigment>> unweighted_pigment
%nterm <sg::ImageMap> image_map image_items
%nterm <std::shared_ptr<sg::Finish>> finish
%nterm <Edits<sg::Finish>> finish_items reflection_items reflection_opts finish_block irid_items
%nterm <std::function<void(sg::Finish&)>> finish_item reflection_item
%nterm <std::shared_ptr<sg::Interior>> interior
%nterm <Edits<sg::Interior>> interior_items
%nterm <std::shared_ptr<sg::Media>> media
%nterm <std::shared_ptr<sg::SkySphere>> sky_sphere
%nterm <Edits<sg::SkySphere>> sky_sphere_items
%nterm <std::shared_ptr<sg::Fog>> fog
%nterm <std::shared_ptr<sg::Rainbow>> rainbow
%nterm <Edits<sg::Rainbow>> rainbow_items
%nterm <std::function<void(sg::Rainbow&)>> rainbow_item
%nterm <Edits<sg::Fog>> fog_items
%nterm <std::function<void(sg::Fog&)>> fog_item
%nterm <Edits<sg::Media>> media_items scattering_items
%nterm <std::function<void(sg::Media&)>> media_item
%nterm <std::shared_ptr<sg::Light>> light
%nterm <Edits<sg::Light>> light_items
%nterm <std::function<void(sg::Light&)>> light_item
%nterm <std::shared_ptr<CameraSpec>> camera
%nterm <Edits<CameraSpec>> camera_items
%nterm <std::function<void(CameraSpec&)>> camera_item
%nterm <sg::Camera::Projection> camera_type
%nterm <std::function<void(CameraSpec&)>> mesh_camera
%nterm <std::vector<std::pair<ShapePtr, sg::SourceLocation>>> mesh_camera_meshes
%nterm <std::optional<std::pair<Value, SourceRange>>> mesh_camera_reach
%nterm <std::optional<std::vector<std::pair<Value, SourceRange>>>> opt_uv_vectors
%nterm <Edits<ParameterList>> param_items
%nterm <bool> opt_bool opt_albedo opt_open
%nterm <Edits<sg::Prism>> prism_options
%nterm <Edits<sg::Blob>> blob_items
%nterm <std::function<void(sg::Blob&)>> blob_item
%nterm <Edits<sg::Blob::Component>> blob_component_mods
%nterm <std::vector<ShapePtr>> clip_objects
%nterm <std::optional<std::pair<Value, SourceRange>>> opt_hole opt_tolerance
%nterm <int> sweep_spline
%nterm <Edits<sg::BicubicPatch>> patch_options
%nterm <std::function<void(sg::BicubicPatch&)>> patch_option
%nterm <Edits<sg::JuliaFractal>> julia_items
%nterm <std::function<void(sg::JuliaFractal&)>> julia_item
%nterm <Edits<sg::HeightField>> height_field_items
%nterm <Edits<sg::Isosurface>> isosurface_items
%nterm <std::function<void(sg::Isosurface&)>> isosurface_item
%nterm <Value> isosurface_function
%nterm <std::function<void(sg::FunctionContainer&)>> contained_by
%nterm <Edits<sg::Parametric>> parametric_items
%nterm <std::function<void(sg::Parametric&)>> parametric_item
%nterm <std::vector<std::string>> precompute_axes
%nterm <std::string> trace_normal
%nterm <int> spline_kind
%nterm <std::vector<int>> spline_kinds
%nterm <std::function<void(sg::HeightField&)>> height_field_item
%nterm <Edits<sg::Polynomial>> polynomial_terms
%nterm <int> colour_channel
%nterm <Edits<sg::TriangleMesh>> mesh2_sections
%nterm <std::function<void(sg::TriangleMesh&)>> mesh2_section
%nterm <std::vector<std::shared_ptr<sg::Material>>> texture_seq texture_list
%nterm <std::function<void(sg::Pattern&)>> pattern_name pattern_modifier block_pattern_name
%nterm <std::vector<Value>> block_colours
%nterm <std::vector<std::shared_ptr<sg::Pigment>>> block_pigments
%nterm <Edits<sg::Warp>> warp_items
%nterm <std::function<void(sg::Warp&)>> warp_item
%nterm <sg::ColorMapRef> color_map color_map_body
%nterm <std::vector<std::pair<Value, std::vector<Value>>>> color_map_entries
%nterm <std::vector<Value>> colour_seq
%nterm <std::shared_ptr<std::vector<sg::PigmentMapEntry>>> pigment_map pigment_map_entries density_map_entries
%nterm <std::shared_ptr<sg::Pigment>> pigment_body
%nterm <sg::NormalRef> normal normal_body
%nterm <std::vector<sg::NormalRef>> block_normals
%nterm <Edits<sg::Normal>> normal_mods normal_block normal_edits
%nterm <std::function<void(sg::Normal&)>> normal_start normal_type normal_mod
%nterm <std::shared_ptr<std::vector<sg::NormalMapEntry>>> normal_map normal_map_entries
%nterm <std::vector<sg::SlopeMapEntry>> slope_map_entries
%nterm <std::optional<std::pair<Value, SourceRange>>> opt_amount
%nterm <std::function<void(sg::Pattern&)>> slope_block
%nterm <std::optional<std::pair<double, double>>> opt_range
%nterm <std::shared_ptr<sg::Material>> texture_layers texture_body
%nterm <std::vector<sg::TextureMapEntry>> texture_map_entries

%precedence OPT_EMPTY
/* After an optional argument (poly_wave [exponent]), an identifier is the argument. */
%precedence UNDECLARED_ID SPLINE_ID
/* A function or spline name followed by "(" is called, not juxtaposed with a
 * parenthesised vector. */
%precedence "("
/* A leading uv_mapping belongs to the pigment or normal it starts. */
%precedence UV_MAPPING
%right "?" ":"
%left "|"
%left "&"
%left "=" "!=" "<" "<=" ">" ">="
/* rgb and its kin take the whole arithmetic expression after them, as
 * POV-Ray's Parse_Colour does: `rgb 0.6 + 0.5 * x` is one grey. */
%precedence COLOUR_KEYWORD
%left "+" "-"
%left "*" "/"
%precedence UNARY
%precedence VECTOR_ITEM

%start start

%%

start
  : START_SCENE scene_items "end of file"
  | START_VALUE declared_value { ev.finish_nested(std::move($2), @2, !yyla.empty()); YYACCEPT; }
  | START_EXPR expr            { ev.finish_nested(std::move($2), @2, !yyla.empty()); YYACCEPT; }
  | START_ARGS "(" macro_args ")" { ev.finish_arguments(std::move($3)); YYACCEPT; }
  /* Directive arguments end at a token that needs no lookahead, so the
   * token after them is read only once the directive has run. */
  | START_COND "(" expr ")"  { ev.finish_nested(std::move($3), @3, !yyla.empty()); YYACCEPT; }
  | START_STRING string_value { ev.finish_nested(std::move($2), @2, !yyla.empty()); YYACCEPT; }
  | START_INDEX "[" expr "]" { ev.finish_nested(std::move($3), @3, !yyla.empty()); YYACCEPT; }
  ;

array_sizes
  : "[" expr "]"       { $$.push_back(ev.array_size($2, @2)); }
  | array_sizes "[" expr "]" { $$ = std::move($1); $$.push_back(ev.array_size($3, @3)); }
  ;

array_init
  : "{" array_items opt_comma "}" { $$.items = std::move($2); $$.location = LOC(@1); }
  ;

/* POV reads exactly the declared number of items, each comma optional
 * (`Red, White Green`, `"Average""Boxed"`, `<1, 2> <3, 4>`), each value a
 * bare float expression as POV's Parse_RValue reads it: compare inside
 * ( ). Objects, textures and arrays still need their comma: a texture
 * after a texture is its next layer. */
array_items
  : array_item         { $$.push_back(std::move($1)); }
  | array_items "," array_item { $$ = std::move($1); $$.push_back(std::move($3)); }
  | array_items array_scalar_item { $$ = std::move($1); $$.push_back(std::move($2)); }
  | array_items declared_identifier { $$ = std::move($1); ArrayInit item; item.value = std::move($2); item.location = LOC(@2); $$.push_back(std::move(item)); }
  ;

array_item
  : array_scalar_item  { $$ = std::move($1); }
  | declared_non_scalar { $$.value = std::move($1); $$.location = LOC(@1); }
  | array_init         { $$ = std::move($1); }
  ;

array_scalar_item
  : begin_value array_scalar end_value { $$.value = std::move($2); $$.location = LOC(@2); }
  ;

array_scalar
  : arith %prec OPT_EMPTY { $$ = std::move($1); }
  | colour_keyword arith %prec OPT_EMPTY { $$ = ev.colour_from($2, @2); }
  | colour_keyword colour_channel arith %prec OPT_EMPTY
      { $$ = ev.colour_component(Value::color(sg::Color{}), @1, $2, $3, @3); }
  | array_scalar colour_channel arith %prec OPT_EMPTY { $$ = ev.colour_component($1, @1, $2, $3, @3); }
  ;

string_value
  : STRING             { $$ = std::move($1.value); }
  | VALUE_ID           { $$ = std::move($1.value); }
  | BUILTIN "(" opt_args ")" { $$ = ev.call_builtin($1.text, $3, @$); }
  ;

/* ------------------------------------------------------------ scene level */

scene_items
  : %empty
  | scene_items scene_item
  ;

scene_item
  : object             { ev.add_object($1); }
  | light              { ev.add_light(*$1, sg::Mat4(1.0)); }
  | camera             { ev.set_camera(*$1); }
  | "background" "{" colour "}"   {
        const sg::Color colour = ev.to_color($3, @3);
        ev.scene().background = colour.rgb;
        ev.scene().background_transmit = colour.transmit;
    }
  | media              { ev.scene().atmosphere.push_back(*$1); }
  | sky_sphere         { ev.scene().sky_sphere = *$1; }
  | fog                { ev.scene().fogs.push_back(*$1); }
  | rainbow            { ev.scene().rainbows.push_back(*$1); }
  | "global_settings" "{" global_items "}"
  | "render_settings" "{" render_items "}" { ev.scene().render.location = LOC(@1); }
  | ";"                { ev.warning(LOC(@1), "stray ';' ignored"); }
  ;

declared_value
  : begin_value colour end_value { $$ = std::move($2); }
  | declared_non_scalar { $$ = std::move($1); }
  ;

/* Everything a declaration holds but a float, vector, colour or string. */
declared_non_scalar
  : object             { $$ = ev.object_value($1); }
  | texture_layers end_value { $$.kind = Value::Kind::Texture; $$.payload = $1; }
  | pigment            { $$.kind = Value::Kind::Pigment; $$.payload = $1; }
  | finish             { $$.kind = Value::Kind::Finish; $$.payload = $1; }
  | interior           { $$.kind = Value::Kind::Interior; $$.payload = $1; }
  | media              { $$.kind = Value::Kind::Media; $$.payload = $1; }
  | sky_sphere         { $$.kind = Value::Kind::SkySphere; $$.payload = $1; }
  | fog                { $$.kind = Value::Kind::Fog; $$.payload = $1; }
  | rainbow            { $$.kind = Value::Kind::Rainbow; $$.payload = $1; }
  | "density" "{" pigment_edits "}" { $$.kind = Value::Kind::Pigment; $$.payload = ev.build_density($3, LOC(@1)); }
  | material           { $$.kind = Value::Kind::Texture; $$.payload = $1; }
  | camera             { $$.kind = Value::Kind::Camera; $$.payload = std::move($1); }
  | light              { $$.kind = Value::Kind::Light; $$.payload = std::move($1); }
  | transform_block    { $$.kind = Value::Kind::Transform; $$.set_transform($1); }
  | normal             { $$.kind = Value::Kind::Normal; $$.payload = $1; }
  | FUNCTION_LITERAL   { $$ = std::move($1.value); }
  /* The barrier keeps a directive after `array[N]` (no ; needed) unrun
   * while it is only looked at. */
  | "array" begin_value array_sizes end_value { $$ = ev.make_array($3, {}, LOC(@1)); }
  | "array" begin_value array_sizes end_value array_init { $$ = ev.make_array($3, $5, LOC(@1)); }
  | FUNCTION_OPEN "pattern" "{" pigment_edits "}" "}" { $$ = ev.pattern_function($4, LOC(@1)); }
  | FUNCTION_OPEN pigment "}" { $$ = ev.pigment_function($2, LOC(@1)); }
  | FUNCTION_OPEN transform_block "}" { $$ = ev.transform_function($2, LOC(@1)); }
  | FUNCTION_OPEN spline_literal "}" { $$ = ev.spline_function($2, LOC(@1)); }
  | spline_literal     { $$ = std::move($1); }
  | color_map          { $$.kind = Value::Kind::ColorMap; $$.payload = $1; }
  | pigment_map        { $$.kind = Value::Kind::PigmentMap; $$.payload = $1; }
  | normal_map         { $$.kind = Value::Kind::NormalMap; $$.payload = $1; }
  | declared_identifier { $$ = std::move($1); }
  ;

spline_literal
  : "spline" "{" spline_kinds arith_seq opt_comma "}" { $$ = ev.make_spline({}, $3, $4, LOC(@1)); }
  | "spline" "{" SPLINE_ID spline_kinds "}" { $$ = ev.make_spline($3.value, $4, {}, LOC(@1)); }
  | "spline" "{" SPLINE_ID spline_kinds arith_seq opt_comma "}" { $$ = ev.make_spline($3.value, $4, $5, LOC(@1)); }
  ;

/* A declared non-scalar, one token: in an array it needs no comma. */
declared_identifier
  : NORMAL_ID          { $$ = std::move($1.value); }
  | COLOR_MAP_ID       { $$ = std::move($1.value); }
  | PIGMENT_MAP_ID     { $$ = std::move($1.value); }
  | NORMAL_MAP_ID      { $$ = std::move($1.value); }
  | OBJECT_ID          { $$ = std::move($1.value); }
  | TEXTURE_ID         { $$ = std::move($1.value); }
  | PIGMENT_ID         { $$ = std::move($1.value); }
  | FINISH_ID          { $$ = std::move($1.value); }
  | INTERIOR_ID        { $$ = std::move($1.value); }
  | CAMERA_ID          { $$ = std::move($1.value); }
  | LIGHT_ID           { $$ = std::move($1.value); }
  | TRANSFORM_ID       { $$ = std::move($1.value); }
  ;

/* The value of `#declare X = <expression>` ends where the expression ends;
 * directives after it must wait until the declaration is stored. */
begin_value: %empty { ev.begin_value_barrier(); } ;
end_value: %empty { ev.end_value_barrier(); } ;

opt_comma
  : %empty %prec OPT_EMPTY
  | ","
  ;

opt_bool
  : %empty %prec OPT_EMPTY { $$ = true; }
  | expr               { $$ = ev.to_float($1, @1, "an on/off value") != 0.0; }
  ;

/* ---------------------------------------------------------------- objects */

object
  : "sphere" "{" arith opt_comma arith object_mods "}"
      { $$ = ev.make_sphere($3, @3, $5, @5, LOC(@1)); ev.apply($$, $6); }
  | "plane" "{" arith opt_comma arith object_mods "}"
      { $$ = ev.make_plane($3, @3, $5, @5, LOC(@1)); ev.apply($$, $6); }
  | "box" "{" arith opt_comma arith object_mods "}"
      { $$ = ev.make_box($3, @3, $5, @5, LOC(@1)); ev.apply($$, $6); }
  | "cylinder" "{" arith opt_comma arith opt_comma arith opt_open object_mods "}"
      { $$ = ev.make_cone({$3, $7, $5, $7}, {@3, @7, @5, @7}, $8, LOC(@1), true); ev.apply($$, $9); }
  | "cone" "{" arith opt_comma arith opt_comma arith opt_comma arith opt_open object_mods "}"
      { $$ = ev.make_cone({$3, $5, $7, $9}, {@3, @5, @7, @9}, $10, LOC(@1), false); ev.apply($$, $11); }
  | "torus" "{" arith opt_comma arith object_mods "}"
      { $$ = ev.make_torus($3, @3, $5, @5, LOC(@1)); ev.apply($$, $6); }
  | "disc" "{" arith opt_comma arith opt_comma arith opt_hole object_mods "}"
      { $$ = ev.make_disc({$3, $5, $7}, {@3, @5, @7}, $8, LOC(@1)); ev.apply($$, $9); }
  | "quadric" "{" arith opt_comma arith opt_comma arith opt_comma arith object_mods "}"
      { $$ = ev.make_quadric({$3, $5, $7, $9}, {@3, @5, @7, @9}, LOC(@1)); ev.apply($$, $10); }
  | "prism" "{" prism_options arith opt_comma arith opt_comma arith opt_comma arith_seq opt_comma opt_open object_mods "}"
      { $$ = ev.make_prism($3, {$4, $6, $8}, {@4, @6, @8}, $10, @10, $12, LOC(@1)); ev.apply($$, $13); }
  | "text" "{" "ttf" arith opt_comma arith opt_comma arith opt_comma arith object_mods "}"
      { $$ = ev.make_text($4, @4, $6, @6, $8, @8, $10, @10, LOC(@1)); ev.apply($$, $11); }
  | "text" "{" "internal" arith opt_comma arith opt_comma arith opt_comma arith object_mods "}"
      { $$ = ev.make_text(ev.internal_font($4, @4), @4, $6, @6, $8, @8, $10, @10, LOC(@1)); ev.apply($$, $11); }
  | "sor" "{" arith opt_comma arith_seq opt_comma opt_open object_mods "}"
      { $$ = ev.make_sor($3, @3, $5, @5, $7, LOC(@1)); ev.apply($$, $8); }
  | "lathe" "{" prism_options arith opt_comma arith_seq opt_comma object_mods "}"
      { $$ = ev.make_lathe($3, $4, @4, $6, @6, LOC(@1)); ev.apply($$, $8); }
  | "blob" "{" blob_items object_mods "}"
      { $$ = ev.make_blob($3, LOC(@1)); ev.apply($$, $4); }
  | "superellipsoid" "{" arith object_mods "}"
      { $$ = ev.make_superellipsoid($3, @3, LOC(@1)); ev.apply($$, $4); }
  | "polygon" "{" arith opt_comma arith_seq opt_comma object_mods "}"
      { $$ = ev.make_polygon($3, @3, $5, @5, LOC(@1)); ev.apply($$, $7); }
  | "poly" "{" arith opt_comma "<" vector_items ">" object_mods "}"
      { $$ = ev.make_polynomial(sg::Object::Kind::Poly, $3, @3, $6, @6, LOC(@1)); ev.apply($$, $8); }
  | "cubic" "{" "<" vector_items ">" object_mods "}"
      { $$ = ev.make_polynomial(sg::Object::Kind::Cubic, Value::number(3), @1, $4, @4, LOC(@1)); ev.apply($$, $6); }
  | "quartic" "{" "<" vector_items ">" object_mods "}"
      { $$ = ev.make_polynomial(sg::Object::Kind::Quartic, Value::number(4), @1, $4, @4, LOC(@1)); ev.apply($$, $6); }
  | "polynomial" "{" expr opt_comma polynomial_terms object_mods "}"
      { $$ = ev.make_polynomial_from_terms($3, @3, $5, LOC(@1)); ev.apply($$, $6); }
  | "ovus" "{" arith opt_comma arith object_mods "}"
      { $$ = ev.make_ovus($3, @3, $5, @5, LOC(@1)); ev.apply($$, $6); }
  | "sphere_sweep" "{" sweep_spline opt_comma arith opt_comma arith_seq opt_comma opt_tolerance object_mods "}"
      { $$ = ev.make_sphere_sweep($3, $5, @5, $7, @7, $9, LOC(@1)); ev.apply($$, $10); }
  | "bicubic_patch" "{" patch_options opt_comma arith_seq opt_comma object_mods "}"
      { $$ = ev.make_bicubic_patch($3, $5, @5, LOC(@1)); ev.apply($$, $7); }
  | "julia_fractal" "{" expr julia_items object_mods "}"
      { $$ = ev.make_julia_fractal($3, @3, $4, LOC(@1)); ev.apply($$, $5); }
  | "height_field" "{" height_field_items object_mods "}"
      { $$ = ev.make_height_field($3, LOC(@1)); ev.apply($$, $4); }
  | "isosurface" "{" isosurface_function isosurface_items object_mods "}"
      { $$ = ev.make_isosurface($3, @3, $4, LOC(@1)); ev.apply($$, $5); }
  | "parametric" "{" isosurface_function opt_comma isosurface_function opt_comma isosurface_function
    arith opt_comma arith parametric_items object_mods "}"
      { $$ = ev.make_parametric({$3, $5, $7}, {@3, @5, @7}, $8, @8, $10, @10, $11, LOC(@1)); ev.apply($$, $12); }
  | "triangle" "{" arith opt_comma arith opt_comma arith object_mods "}"
      { $$ = ev.make_triangle({$3, $5, $7}, {@3, @5, @7}, LOC(@1)); ev.apply($$, $8); }
  | "smooth_triangle" "{" arith opt_comma arith opt_comma arith opt_comma arith opt_comma arith opt_comma arith object_mods "}"
      { $$ = ev.make_triangle({$3, $5, $7, $9, $11, $13}, {@3, @5, @7, @9, @11, @13}, LOC(@1));
        ev.apply($$, $14); }
  | "mesh" "{" mesh_items "}"
      { $$ = ev.make_mesh(LOC(@1)); ev.apply($$, $3); ev.finish_mesh(*$$, LOC(@1)); }
  | "mesh" "{" OBJECT_ID object_mods "}"
      { $$ = ev.declared_mesh($3.value.shape(), $3.text, sg::Object::Kind::Mesh, LOC(@1)); ev.apply($$, $4); }
  | "mesh2" "{" mesh2_sections object_mods "}"
      { $$ = ev.make_mesh2($3, LOC(@1)); ev.apply($$, $4); }
  | "mesh2" "{" OBJECT_ID object_mods "}"
      { $$ = ev.declared_mesh($3.value.shape(), $3.text, sg::Object::Kind::Mesh2, LOC(@1)); ev.apply($$, $4); }
  | "obj_mesh" "{" expr object_mods "}"
      { $$ = ev.make_obj_mesh($3, @3, LOC(@1)); ev.apply($$, $4); }
  | "union" "{" union_items "}"
      { $$ = ev.make_union(LOC(@1)); ev.apply($$, $3); }
  | "light_group" "{" light_group_items "}"
      { $$ = ev.make_light_group($3, LOC(@1)); }
  | "merge" "{" union_items "}"
      { $$ = ev.make_csg(sg::Object::Kind::Merge, LOC(@1)); ev.apply($$, $3); ev.finish_csg(*$$); }
  | "difference" "{" union_items "}"
      { $$ = ev.make_csg(sg::Object::Kind::Difference, LOC(@1)); ev.apply($$, $3); ev.finish_csg(*$$); }
  | "intersection" "{" union_items "}"
      { $$ = ev.make_csg(sg::Object::Kind::Intersection, LOC(@1)); ev.apply($$, $3); ev.finish_csg(*$$); }
  | "object" "{" object_ref object_mods "}"
      { $$ = $3; $$->object.location = LOC(@1); ev.apply($$, $4); }
  ;

object_ref
  : OBJECT_ID          { $$ = std::make_shared<ShapeValue>(*$1.value.shape()); $$->object.name = $1.text; }
  | object             { $$ = std::move($1); }
  | LIGHT_ID           { $$ = ev.make_union(LOC(@1)); $$->lights.push_back(*$1.value.light()); }
  | UNDECLARED_ID      { ev.unknown_identifier($1.text, LOC(@1), "an object"); $$ = ev.make_union(LOC(@1)); }
  ;

object_mods
  : %empty             {}
  | object_mods object_mod { $$ = std::move($1); $$.push_back($2); }
  ;

object_mod
  : transform_item     { $$ = ev.transform_edit($1); }
  | texture            { $$ = ev.texture_edit($1); }
  | "interior_texture" "{" texture_body "}" { $$ = ev.interior_texture_edit($3); }
  | pigment_block      { $$ = ev.pigment_edit($1, LOC(@1)); }
  | finish_block       { $$ = ev.finish_edit($1, LOC(@1)); }
  | normal_block       { $$ = ev.normal_edit($1, LOC(@1)); }
  | interior           { $$ = ev.interior_edit($1); }
  | material           { $$ = ev.material_edit($1); }
  | "no_shadow"        { $$ = [](ShapeValue& s) { s.object.no_shadow = true; }; }
  | "uv_mapping"       { $$ = ev.object_uv_mapping(LOC(@1)); }
  | "hollow" opt_bool  { bool on = $2; $$ = [on](ShapeValue& s) { set_hollow(s.object, on); }; }
  | "double_illuminate" opt_bool { bool on = $2; $$ = [on](ShapeValue& s) { s.object.double_illuminate = on; }; }
  | "no_image" opt_bool { bool on = $2; $$ = [on](ShapeValue& s) { s.object.no_image = on; }; }
  | "no_reflection" opt_bool { bool on = $2; $$ = [on](ShapeValue& s) { s.object.no_reflection = on; }; }
  | "no_radiosity"     { $$ = [](ShapeValue&) {}; ev.ignored(LOC(@1), "no_radiosity"); }
  | "inverse"          { $$ = [](ShapeValue& s) { s.object.inverse = !s.object.inverse; }; }
  | "sturm"            { $$ = [](ShapeValue&) {}; }
  | "hierarchy" opt_bool { $$ = [](ShapeValue&) {}; }
  | "clipped_by" "{" clip_objects "}" { $$ = ev.clip_edit($3, LOC(@1)); }
  | "clipped_by" "{" "bounded_by" "}" { $$ = ev.clip_by_bounds_edit(LOC(@1)); }
  | "bounded_by" "{" clip_objects "}" { $$ = ev.bound_edit($3, LOC(@1)); }
  | "bounded_by" "{" "clipped_by" "}" { $$ = [](ShapeValue&) {}; }
  ;

/* The objects of clipped_by or bounded_by, then transforms for all of them. */
clip_objects
  : %empty             {}
  | clip_objects object { $$ = std::move($1); $$.push_back($2); }
  | clip_objects OBJECT_ID { $$ = std::move($1); $$.push_back(std::make_shared<ShapeValue>(*$2.value.shape())); }
  | clip_objects transform_item { $$ = std::move($1);
                                  for (auto& o : $$) { auto moved = std::make_shared<ShapeValue>(*o);
                                                       ev.apply(moved, {ev.transform_edit($2)}); o = moved; } }
  ;

prism_options
  : %empty             {}
  | prism_options "linear_sweep" { $$ = std::move($1); $$.push_back([](sg::Prism& p) { p.conic = false; }); }
  | prism_options "conic_sweep" { $$ = std::move($1); $$.push_back([](sg::Prism& p) { p.conic = true; }); }
  | prism_options "linear_spline" { $$ = std::move($1); $$.push_back([](sg::Prism& p) { p.spline = sg::Prism::Spline::Linear; }); }
  | prism_options "quadratic_spline" { $$ = std::move($1); $$.push_back([](sg::Prism& p) { p.spline = sg::Prism::Spline::Quadratic; }); }
  | prism_options "cubic_spline" { $$ = std::move($1); $$.push_back([](sg::Prism& p) { p.spline = sg::Prism::Spline::Cubic; }); }
  | prism_options "bezier_spline" { $$ = std::move($1); $$.push_back([](sg::Prism& p) { p.spline = sg::Prism::Spline::Bezier; }); }
  ;

/* blob { threshold T  sphere { <c>, r, [strength] s mods }  cylinder { <a>, <b>, r, [strength] s mods }
 *        component s, r, <c> ... } */
blob_items
  : %empty             {}
  | blob_items blob_item { $$ = std::move($1); $$.push_back($2); }
  ;

blob_item
  : "threshold" expr   { double t = ev.to_float($2, @2, "a float threshold"); $$ = [t](sg::Blob& b) { b.threshold = t; }; }
  | "component" arith opt_comma arith opt_comma arith
      { $$ = ev.blob_component(false, {$6, $6, $4, $2}, {@6, @6, @4, @2}, {}, LOC(@1)); }
  | "sphere" "{" arith opt_comma arith opt_comma opt_strength arith blob_component_mods "}"
      { $$ = ev.blob_component(false, {$3, $3, $5, $8}, {@3, @3, @5, @8}, $9, LOC(@1)); }
  | "cylinder" "{" arith opt_comma arith opt_comma arith opt_comma opt_strength arith blob_component_mods "}"
      { $$ = ev.blob_component(true, {$3, $5, $7, $10}, {@3, @5, @7, @10}, $11, LOC(@1)); }
  ;

opt_strength
  : %empty %prec OPT_EMPTY
  | "strength"
  ;

blob_component_mods
  : %empty             {}
  | blob_component_mods transform_item { $$ = std::move($1); sg::Mat4 m = $2;
      $$.push_back([m](sg::Blob::Component& c) { c.blob_from_component = m * c.blob_from_component; }); }
  | blob_component_mods texture { $$ = std::move($1); ev.ignored(LOC(@2), "a blob component's own texture (the blob's is used)"); }
  | blob_component_mods pigment { $$ = std::move($1); ev.ignored(LOC(@2), "a blob component's own pigment (the blob's is used)"); }
  | blob_component_mods finish { $$ = std::move($1); ev.ignored(LOC(@2), "a blob component's own finish (the blob's is used)"); }
  ;

opt_open
  : %empty %prec OPT_EMPTY { $$ = false; }
  | "open"             { $$ = true; }
  ;

opt_hole
  : %empty %prec OPT_EMPTY {}
  | "," arith          { $$ = std::make_pair($2, @2); }
  ;

/* polynomial { order, xyz(i, j, k): c, ... } (POV 3.7's Parse_Polynom) */
polynomial_terms
  : %empty             {}
  | polynomial_terms "xyz" "(" expr opt_comma expr opt_comma expr ")" ":" arith opt_comma
      { $$ = std::move($1); $$.push_back(ev.polynomial_term({$4, $6, $8, $11}, {@4, @6, @8, @11})); }
  ;

sweep_spline
  : "linear_spline"    { $$ = int(sg::SphereSweep::Spline::Linear); }
  | "b_spline"         { $$ = int(sg::SphereSweep::Spline::BSpline); }
  | "cubic_spline"     { $$ = int(sg::SphereSweep::Spline::CubicSpline); }
  ;

opt_tolerance
  : %empty             {}
  | "tolerance" expr   { $$ = std::make_pair($2, @2); }
  ;

/* bicubic_patch's keywords before its points (Parse_Bicubic_Patch) */
patch_options
  : %empty             {}
  | patch_options patch_option { $$ = std::move($1); $$.push_back($2); }
  ;

patch_option
  : "type" arith %prec OPT_EMPTY { $$ = ev.patch_option("type", $2, @2); }
  | "flatness" arith %prec OPT_EMPTY { $$ = ev.patch_option("flatness", $2, @2); }
  | "u_steps" arith %prec OPT_EMPTY { $$ = ev.patch_option("u_steps", $2, @2); }
  | "v_steps" arith %prec OPT_EMPTY { $$ = ev.patch_option("v_steps", $2, @2); }
  | "accuracy" arith %prec OPT_EMPTY { $$ = ev.patch_option("accuracy", $2, @2); }
  | "uv_vectors" arith opt_comma arith opt_comma arith opt_comma arith %prec OPT_EMPTY
      { $$ = ev.patch_uv_vectors({$2, $4, $6, $8}, {@2, @4, @6, @8}); }
  ;

/* julia_fractal's options (Parse_Julia_Fractal): the function keywords
 * that are also builtins (sqr, exp, sin, ...) arrive as BUILTIN */
julia_items
  : %empty             {}
  | julia_items julia_item { $$ = std::move($1); $$.push_back($2); }
  ;

julia_item
  : "quaternion"       { $$ = [](sg::JuliaFractal& j) { j.algebra = sg::JuliaFractal::Algebra::Quaternion; }; }
  | "hypercomplex"     { $$ = [](sg::JuliaFractal& j) { j.algebra = sg::JuliaFractal::Algebra::Hypercomplex; }; }
  | "max_iteration" expr %prec OPT_EMPTY { $$ = ev.julia_max_iteration($2, @2); }
  | "precision" expr %prec OPT_EMPTY { $$ = ev.julia_precision($2, @2); }
  | "slice" arith opt_comma arith %prec OPT_EMPTY { $$ = ev.julia_slice($2, @2, $4, @4); }
  | "cube"             { $$ = [](sg::JuliaFractal& j) { j.function = sg::JuliaFractal::Function::Cube; }; }
  | "reciprocal"       { $$ = [](sg::JuliaFractal& j) { j.function = sg::JuliaFractal::Function::Reciprocal; }; }
  | "pwr" "(" expr "," expr ")" { $$ = ev.julia_power($3, @3, $5, @5); }
  | BUILTIN            { $$ = ev.julia_function($1.text, LOC(@1)); }
  ;

/* isosurface { function { f(x, y, z) } [contained_by { box { <a>, <b> } | sphere { <c>, r } }]
 *              [threshold t] [accuracy a] [max_gradient g] [evaluate p0, p1, p2] [open]
 *              [max_trace n | all_intersections] } (Parse_Isosurface: the function comes first) */
isosurface_function
  : FUNCTION_LITERAL   { $$ = std::move($1.value); }
  | FUNCTION_OPEN "pattern" "{" pigment_edits "}" "}" { $$ = ev.pattern_function($4, LOC(@1)); }
  ;

isosurface_items
  : %empty             {}
  | isosurface_items isosurface_item { $$ = std::move($1); $$.push_back($2); }
  ;

contained_by
  : "contained_by" "{" "}" { $$ = [](sg::FunctionContainer&) {}; }
  | "contained_by" "{" "box" "{" arith opt_comma arith "}" "}" { $$ = ev.container_box($5, @5, $7, @7); }
  | "contained_by" "{" "sphere" "{" arith opt_comma arith "}" "}" { $$ = ev.container_sphere($5, @5, $7, @7); }
  ;

isosurface_item
  : contained_by       { $$ = [container = $1](sg::Isosurface& i) { container(i); }; }
  | "threshold" expr %prec OPT_EMPTY { $$ = ev.isosurface_number("threshold", $2, @2); }
  | "accuracy" expr %prec OPT_EMPTY { $$ = ev.isosurface_number("accuracy", $2, @2); }
  | "max_gradient" expr %prec OPT_EMPTY { $$ = ev.isosurface_number("max_gradient", $2, @2); }
  | "max_trace" expr %prec OPT_EMPTY { $$ = ev.isosurface_number("max_trace", $2, @2); }
  | "evaluate" arith opt_comma arith opt_comma arith %prec OPT_EMPTY
      { $$ = ev.isosurface_evaluate({$2, $4, $6}, {@2, @4, @6}); }
  | "open"             { $$ = [](sg::Isosurface& i) { i.open = true; }; }
  | "all_intersections" { $$ = [](sg::Isosurface& i) { i.max_trace = 10; }; }
  ;

/* parametric { function { x(u, v) } [,] function { y(u, v) } [,] function { z(u, v) } <u1, v1> [,] <u2, v2>
 *              [contained_by { box { … } | sphere { … } }] [max_gradient g] [accuracy a]
 *              [precompute DEPTH [,] [x] [,] [y] [,] [z]] } (Parse_Parametric) */
parametric_items
  : %empty             {}
  | parametric_items parametric_item { $$ = std::move($1); $$.push_back($2); }
  ;

parametric_item
  : contained_by       { $$ = [container = $1](sg::Parametric& p) { container(p); }; }
  | "accuracy" expr %prec OPT_EMPTY { $$ = ev.parametric_number("accuracy", $2, @2); }
  | "max_gradient" expr %prec OPT_EMPTY { $$ = ev.parametric_number("max_gradient", $2, @2); }
  | "precompute" expr precompute_axes { $$ = ev.parametric_precompute($2, @2, $3, LOC(@3)); }
  ;

precompute_axes
  : %empty             {}
  | precompute_axes opt_comma CONSTANT { $$ = std::move($1); $$.push_back($3.text); }
  ;

/* height_field { [type] "file" [gamma g] [premultiplied b] [smooth] [water_level w] } */
height_field_items
  : %empty             {}
  | height_field_items height_field_item { $$ = std::move($1); $$.push_back($2); }
  ;

height_field_item
  /* The type keyword only names what the reader finds in the file. */
  : "png"              { $$ = [](sg::HeightField&) {}; }
  | "jpeg"             { $$ = [](sg::HeightField&) {}; }
  | "exr"              { $$ = [](sg::HeightField&) {}; }
  | "hdr"              { $$ = [](sg::HeightField&) {}; }
  | "tga"              { $$ = [](sg::HeightField&) {}; }
  | "tiff"             { $$ = [](sg::HeightField&) {}; }
  | "gif"              { $$ = [](sg::HeightField&) {}; }
  | "pgm"              { $$ = [](sg::HeightField&) {}; }
  | "ppm"              { $$ = [](sg::HeightField&) {}; }
  | "bmp"              { $$ = [](sg::HeightField&) {}; }
  | "pot"              { $$ = [](sg::HeightField&) {}; }
  | "sys"              { $$ = ev.unsupported_height_field_format("sys", LOC(@1)); }
  | "iff"              { $$ = ev.unsupported_height_field_format("iff", LOC(@1)); }
  | string_value       { std::string path = ev.to_string($1, @1); auto at = LOC(@1);
                         $$ = [path, at](sg::HeightField& h) { h.written = path; h.location = at; }; }
  | "gamma" expr       { double g = ev.to_float($2, @2, "a float gamma"); $$ = [g](sg::HeightField& h) { h.gamma = g; }; }
  | "premultiplied" expr { bool on = ev.to_float($2, @2, "a boolean") != 0.0;
                           $$ = [on](sg::HeightField& h) { h.premultiplied = on; }; }
  | "smooth"           { $$ = [](sg::HeightField& h) { h.smooth = true; }; }
  | FUNCTION_LITERAL   { $$ = ev.height_field_function($1.value, LOC(@1)); }
  | FUNCTION_OPEN pigment "}"
      { Value f = ev.pigment_function($2, LOC(@1)); f.image_size = $1.value.image_size;
        $$ = ev.height_field_function(f, LOC(@1)); }
  | "water_level" expr { double w = ev.to_float($2, @2, "a float water level");
                         $$ = [w](sg::HeightField& h) { h.water_level = w; }; }
  ;

union_items
  : %empty             {}
  | union_items union_item { $$ = std::move($1); $$.push_back($2); }
  ;

union_item
  : object             { $$ = ev.child_edit($1); }
  | light              { sg::Light light = *$1; $$ = [light](ShapeValue& s) { s.lights.push_back(light); }; }
  | object_mod         { $$ = std::move($1); }
  ;

/* light_group { objects, lights, [global_lights on] and transforms } */
light_group_items
  : %empty             {}
  | light_group_items light_group_item { $$ = std::move($1); $$.push_back($2); }
  ;

light_group_item
  : union_item         { $$ = std::move($1); }
  | "global_lights" opt_bool { bool on = $2; $$ = [on](ShapeValue& s) { s.global_lights = on; }; }
  ;

/* mesh { triangle { a, b, c [texture { T }] } ... modifiers } */
mesh_items
  : %empty             {}
  | mesh_items mesh_item { $$ = std::move($1); $$.push_back($2); }
  ;

mesh_item
  : "triangle" "{" arith opt_comma arith opt_comma arith opt_uv_vectors texture_seq "}"
      { $$ = ev.mesh_triangle_edit({$3, $5, $7}, {@3, @5, @7}, $8, $9, LOC(@1)); }
  | "smooth_triangle" "{" arith opt_comma arith opt_comma arith opt_comma arith opt_comma arith opt_comma arith opt_uv_vectors texture_seq "}"
      { $$ = ev.mesh_triangle_edit({$3, $5, $7, $9, $11, $13}, {@3, @5, @7, @9, @11, @13}, $14, $15, LOC(@1)); }
  | "inside_vector" expr { $$ = ev.mesh_inside_vector_edit($2, @2); }
  | object_mod         { $$ = std::move($1); }
  ;

/* A mesh triangle's uv_vectors <u1,v1>, <u2,v2>, <u3,v3>. */
opt_uv_vectors
  : %empty             {}
  | "uv_vectors" arith opt_comma arith opt_comma arith
      { $$ = std::vector<std::pair<Value, SourceRange>>{{$2, @2}, {$4, @4}, {$6, @6}}; }
  ;

/* texture_list { N, texture {...}, texture {...} } */
texture_list
  : %empty             {}
  | texture_list texture opt_comma { $$ = std::move($1); $$.push_back($2); }
  ;

texture_seq
  : %empty             {}
  | texture_seq texture { $$ = std::move($1); $$.push_back($2); }
  | texture_seq "," texture { $$ = std::move($1); $$.push_back($3); }  /* object_pattern.pov */
  ;

mesh2_sections
  : %empty             {}
  | mesh2_sections mesh2_section { $$ = std::move($1); $$.push_back($2); }
  ;

mesh2_section
  : MESH2_SECTION                    { $$ = ev.literal_mesh2_section($1.value, LOC(@1)); }
  | "vertex_vectors" "{" arith mesh2_items "}" { $$ = ev.mesh2_vectors("vertex_vectors", $3, @3, $4, @4, LOC(@1)); }
  | "normal_vectors" "{" arith mesh2_items "}" { $$ = ev.mesh2_vectors("normal_vectors", $3, @3, $4, @4, LOC(@1)); }
  | "uv_vectors" "{" arith mesh2_items "}"     { $$ = ev.mesh2_vectors("uv_vectors", $3, @3, $4, @4, LOC(@1)); }
  | "face_indices" "{" arith mesh2_items "}"   { $$ = ev.mesh2_indices("face_indices", $3, @3, $4, @4, LOC(@1)); }
  | "normal_indices" "{" arith mesh2_items "}" { $$ = ev.mesh2_indices("normal_indices", $3, @3, $4, @4, LOC(@1)); }
  | "uv_indices" "{" arith mesh2_items "}"     { $$ = ev.mesh2_indices("uv_indices", $3, @3, $4, @4, LOC(@1)); }
  | "texture_list" "{" expr opt_comma texture_list "}" { $$ = ev.mesh2_textures($3, @3, $5, LOC(@1)); }
  | "inside_vector" expr { auto v = ev.inside_vector($2, @2); $$ = [v](sg::TriangleMesh& m) { m.inside_vector = v; }; }
  ;

/* A mesh2 section's items after its count, each comma optional: POV reads
 * the count as a bare float, so `14 <-1, -1, -1>` is a count and a point. */
mesh2_items
  : opt_comma          {}
  | opt_comma arith_seq opt_comma { $$ = std::move($2); }
  ;

/* Separated by optional commas, as POV reads a patch's points. */
arith_seq
  : arith %prec OPT_EMPTY { ev.remember_location($1, @1); $$.push_back($1); }
  | arith_seq opt_comma arith %prec OPT_EMPTY { $$ = std::move($1); ev.remember_location($3, @3); $$.push_back($3); }
  ;

/* ------------------------------------------------------------- transforms */

transform_item
  : "translate" expr %prec OPT_EMPTY { $$ = ev.translation($2, @2); }
  | "rotate" expr %prec OPT_EMPTY { $$ = ev.rotation($2, @2); }
  | "scale" expr %prec OPT_EMPTY  { $$ = ev.scaling($2, @2); }
  | "matrix" "<" vector_items ">" { $$ = ev.matrix($3, @3); }
  | transform_block    { $$ = std::move($1); }
  ;

transform_block
  : "transform" TRANSFORM_ID { $$ = $2.value.transform(); }
  | "transform" "{" transform_items "}" { $$ = std::move($3); }
  ;

transform_items
  : %empty             { $$ = sg::Mat4(1.0); }
  | transform_items transform_item { $$ = $2 * $1; }
  | transform_items TRANSFORM_ID   { $$ = $2.value.transform() * $1; }
  | transform_items "inverse"      { $$ = ev.inverse($1, @2); }
  ;

/* --------------------------------------------------------------- textures */

texture
  : "texture" "{" texture_body "}" { $$ = $3; $$->location = LOC(@1); }
  ;

texture_body
  : texture_items      { $$ = ev.build_texture($1, LOC(@1)); }
  ;

/* POV's layered texture: each texture after the first lies on top. A
 * directive after a texture waits until the declaration is stored (the
 * barrier), but runs as usual inside the next layer. */
texture_layers
  : texture            { $$ = $1; ev.begin_value_barrier(); }
  | texture_layers layer_gap texture { $$ = ev.layer_texture($1, $3); ev.begin_value_barrier(); }
  ;

layer_gap: %empty { ev.end_value_barrier(); } ;

texture_map_entries
  : %empty             {}
  | texture_map_entries "[" arith opt_comma texture_body "]"
      { $$ = std::move($1); $$.push_back(sg::TextureMapEntry{ev.to_float($3, @3, "a map value"), $5}); }
  /* An average's entry may leave out its weight (POV's default 1). */
  | texture_map_entries "[" texture_body "]"
      { $$ = std::move($1); $$.push_back(sg::TextureMapEntry{sg::kUnweighted, $3}); }
  ;

texture_items
  : %empty %prec OPT_EMPTY {}
  | texture_items TEXTURE_ID { $$ = std::move($1); auto t = $2.value.texture();
                               $$.push_back([t](sg::Material& m) { m = *t; }); }
  | texture_items UNDECLARED_ID { $$ = std::move($1); ev.unknown_identifier($2.text, LOC(@2), "a texture"); }
  | texture_items pigment_block { $$ = std::move($1); $$.push_back(ev.material_pigment_edit($2, LOC(@2))); }
  | texture_items finish_block  { $$ = std::move($1); $$.push_back(ev.material_finish_edit($2, LOC(@2))); }
  | texture_items normal_block  { $$ = std::move($1); $$.push_back(ev.material_normal_edit($2, LOC(@2))); }
  | texture_items pattern_name { $$ = std::move($1); $$.push_back(ev.texture_pattern($2, {}, LOC(@2))); }
  | texture_items "average" { $$ = std::move($1); $$.push_back(ev.average_texture(LOC(@2))); }
  | texture_items block_pattern_name texture_seq { $$ = std::move($1); $$.push_back(ev.texture_pattern($2, $3, LOC(@2))); }
  | texture_items "object" "{" object_ref texture_seq "}"
      { $$ = std::move($1); $$.push_back(ev.texture_pattern(ev.object_pattern($4, LOC(@2)), $5, LOC(@2))); }
  | texture_items pattern_modifier { $$ = std::move($1); auto e = $2;
                               $$.push_back([e](sg::Material& m) { if (m.pattern) e(*m.pattern); }); }
  | texture_items "uv_mapping" { $$ = std::move($1); $$.push_back([](sg::Material& m) { m.uv_mapping = true; }); }
  /* POV's old form of a checker of textures, each side layered; povray
   * puts the first where checker puts its second (measured). */
  | texture_items "tiles" "{" texture_layers layer_gap "tile2" texture_layers layer_gap "}"
      { $$ = std::move($1); $$.push_back(ev.texture_pattern(ev.pattern_kind(sg::Pattern::Kind::Checker), {$7, $4}, LOC(@2))); }
  | texture_items "texture_map" "{" texture_map_entries "}" { $$ = std::move($1); $$.push_back(ev.texture_map_edit($4, LOC(@2))); }
  | texture_items "material_map" "{" image_items texture_seq "}"
      { $$ = std::move($1); $$.push_back(ev.material_map_edit($4, $5, LOC(@2))); }
  | texture_items transform_item { $$ = std::move($1); sg::Mat4 t = $2;
                               $$.push_back([t](sg::Material& m) { transform_material(m, t); }); }
  ;

material
  : "material" "{" material_items "}" { $$ = ev.build_texture($3, LOC(@1)); }
  ;

material_items
  : %empty             {}
  /* A declared material: its texture and its interior. */
  | material_items TEXTURE_ID { $$ = std::move($1); auto t = $2.value.texture();
                                $$.push_back([t](sg::Material& m) { m = *t; }); }
  | material_items texture  { $$ = std::move($1); auto t = $2;
                              $$.push_back([t](sg::Material& m) { sg::CopyOnWrite<sg::Interior> keep = m.interior; const bool had = m.has_interior;
                                                                  m = *t; m.interior = keep; m.has_interior = had; }); }
  | material_items interior { $$ = std::move($1); auto i = $2;
                              $$.push_back([i](sg::Material& m) { m.interior = *i; m.has_interior = true; }); }
  | material_items transform_item { $$ = std::move($1); sg::Mat4 t = $2;
                              $$.push_back([t](sg::Material& m) { transform_material(m, t); }); }
  ;

/* POV's order: the colour or pattern first, then modifiers. */
pigment
  : "pigment" "{" pigment_body "}" { $$ = $3; $$->location = LOC(@1); }
  ;

/* In a texture or on an object: edits of the pigment already there. */
pigment_block
  : "pigment" "{" pigment_edits "}" { $$ = std::move($3); }
  ;

/* A pigment's items, also a pigment_map entry's (without braces). */
pigment_body
  : pigment_edits      { $$ = ev.build_pigment($1, LOC(@1)); }
  ;

pigment_edits
  : pigment_start pigment_mods { $$ = std::move($2); $$.insert($$.begin(), $1); }
  /* POV writes uv_mapping before the pattern too. */
  | "uv_mapping" pigment_start pigment_mods
      { $$ = std::move($3); $$.insert($$.begin(), $2); $$.push_back(ev.uv_mapping_pigment()); }
  ;

pigment_start
  : %empty %prec OPT_EMPTY { $$ = [](sg::Pigment&) {}; }
  | PIGMENT_ID         { auto p = $1.value.pigment(); $$ = [p](sg::Pigment& target) { target = *p; }; }
  /* POV-Ray: a pigment identifier, then a new colour or pattern for it. */
  | PIGMENT_ID pigment_type
      { auto p = $1.value.pigment(); auto type = $2; $$ = [p, type](sg::Pigment& target) { target = *p; type(target); }; }
  | pigment_type       { $$ = std::move($1); }
  ;

pigment_type
  : colour             { sg::Color c = ev.to_color($1, @1);
                         $$ = [c](sg::Pigment& p) { p.kind = sg::Pigment::Kind::Solid; p.color = c; }; }
  /* POV also reads a colour given by its channels alone: pigment { red 1 green 0.5 } */
  | bare_colour        { sg::Color c = ev.to_color($1, @1);
                         $$ = [c](sg::Pigment& p) { p.kind = sg::Pigment::Kind::Solid; p.color = c; }; }
  | image_map          { sg::ImageMap image = $1;
                         $$ = [image](sg::Pigment& p) { pigment_pattern_of(p); p.kind = sg::Pigment::Kind::Image; p.image = image; }; }
  | pattern_name       { $$ = ev.patterned_pigment($1, LOC(@1)); }
  | block_pattern_name { $$ = ev.block_pigment($1, std::vector<Value>{}, @1, LOC(@1)); }
  | block_pattern_name block_colours { $$ = ev.block_pigment($1, $2, @2, LOC(@1)); }
  | block_pattern_name block_pigments { $$ = ev.block_pigment($1, $2, LOC(@1)); }
  | "object" "{" object_ref "}"
      { $$ = ev.block_pigment(ev.object_pattern($3, LOC(@1)), std::vector<Value>{}, @1, LOC(@1)); }
  | "object" "{" object_ref block_colours "}"
      { $$ = ev.block_pigment(ev.object_pattern($3, LOC(@1)), $4, @4, LOC(@1)); }
  | "object" "{" object_ref block_pigments "}"
      { $$ = ev.block_pigment(ev.object_pattern($3, LOC(@1)), $4, LOC(@1)); }
  | "average"          { $$ = ev.average_pigment(LOC(@1)); }
  ;

unweighted_pigment
  : unweighted_start pigment_mods { $2.insert($2.begin(), $1); $$ = ev.build_pigment($2, LOC(@1)); }
  ;

unweighted_start
  : PIGMENT_ID         { auto p = $1.value.pigment(); $$ = [p](sg::Pigment& target) { target = *p; }; }
  | pattern_name       { $$ = ev.patterned_pigment($1, LOC(@1)); }
  | block_pattern_name { $$ = ev.block_pigment($1, std::vector<Value>{}, @1, LOC(@1)); }
  ;

block_colours
  : colour             { $$.push_back($1); }
  | block_colours opt_comma colour { $$ = std::move($1); $$.push_back($3); }
  ;

block_pigments
  : pigment            { $$.push_back($1); }
  | block_pigments opt_comma pigment { $$ = std::move($1); $$.push_back($3); }
  ;

pigment_mods
  : %empty             {}
  | pigment_mods transform_item { $$ = std::move($1); sg::Mat4 t = $2;
                                  $$.push_back([t](sg::Pigment& p) { transform_pattern(p, t); }); }
  | pigment_mods "quick_color" colour { $$ = std::move($1); ev.ignored(LOC(@2), "quick_color"); }
  | pigment_mods "quick_colour" colour { $$ = std::move($1); ev.ignored(LOC(@2), "quick_colour"); }
  | pigment_mods "quick_color" bare_colour { $$ = std::move($1); ev.ignored(LOC(@2), "quick_color"); }
  | pigment_mods "quick_colour" bare_colour { $$ = std::move($1); ev.ignored(LOC(@2), "quick_colour"); }
  | pigment_mods "uv_mapping" { $$ = std::move($1); $$.push_back(ev.uv_mapping_pigment()); }
  | pigment_mods pattern_modifier { $$ = std::move($1); $$.push_back(ev.pigment_pattern_edit($2, LOC(@2))); }
  | pigment_mods color_map { $$ = std::move($1); $$.push_back(ev.color_map_edit($2, LOC(@2))); }
  | pigment_mods pigment_map { $$ = std::move($1); $$.push_back(ev.pigment_map_edit($2, LOC(@2))); }
  ;

/* ---------------------------------------------------------------- patterns */

pattern_name
  : "agate"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Agate); }
  | "image_pattern" "{" image_items "}" { $$ = ev.image_pattern($3, LOC(@1)); }
  | FUNCTION_LITERAL   { $$ = ev.function_pattern($1.value, LOC(@1)); }
  | "aoi"              { $$ = ev.pattern_kind(sg::Pattern::Kind::Aoi); }
  | "boxed"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Boxed); }
  | "bozo"             { $$ = ev.pattern_kind(sg::Pattern::Kind::Bozo); }
  | "spotted"          { $$ = ev.pattern_kind(sg::Pattern::Kind::Spotted); }
  | "bumps"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Bumps); }
  | "cells"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Cells); }
  | "crackle"          { $$ = ev.pattern_kind(sg::Pattern::Kind::Crackle); }
  | "cylindrical"      { $$ = ev.pattern_kind(sg::Pattern::Kind::Cylindrical); }
  | "dents"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Dents); }
  | "facets"           { $$ = ev.pattern_kind(sg::Pattern::Kind::Facets); }
  | "gradient" arith %prec OPT_EMPTY  { $$ = ev.gradient_pattern($2, @2); }
  | "granite"          { $$ = ev.pattern_kind(sg::Pattern::Kind::Granite); }
  | "leopard"          { $$ = ev.pattern_kind(sg::Pattern::Kind::Leopard); }
  | "marble"           { $$ = ev.pattern_kind(sg::Pattern::Kind::Marble); }
  | "onion"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Onion); }
  | "planar"           { $$ = ev.pattern_kind(sg::Pattern::Kind::Planar); }
  | "quilted"          { $$ = ev.pattern_kind(sg::Pattern::Kind::Quilted); }
  | "radial"           { $$ = ev.pattern_kind(sg::Pattern::Kind::Radial); }
  | "ripples"          { $$ = ev.pattern_kind(sg::Pattern::Kind::Ripples); }
  | "spherical"        { $$ = ev.pattern_kind(sg::Pattern::Kind::Spherical); }
  | "spiral1" arith %prec OPT_EMPTY   { $$ = ev.spiral_pattern(sg::Pattern::Kind::Spiral1, $2, @2); }
  | "spiral2" arith %prec OPT_EMPTY   { $$ = ev.spiral_pattern(sg::Pattern::Kind::Spiral2, $2, @2); }
  | "waves"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Waves); }
  | "wood"             { $$ = ev.pattern_kind(sg::Pattern::Kind::Wood); }
  | "wrinkles"         { $$ = ev.pattern_kind(sg::Pattern::Kind::Wrinkles); }
  | "pigment_pattern" "{" pigment_body "}" { $$ = ev.pigment_pattern($3, LOC(@1)); }
  | "pavement"         { $$ = ev.pattern_kind(sg::Pattern::Kind::Pavement); }
  | "tiling" arith %prec OPT_EMPTY    { $$ = ev.tiling_pattern($2, @2); }
  | "density_file" "df3" STRING { $$ = ev.density_file_pattern($3.text, LOC(@3)); }
  | "slope" arith %prec OPT_EMPTY     { $$ = ev.slope_pattern($2, @2); }
  | "slope" "{" slope_block "}"        { $$ = $3; }
  | "mandel" arith %prec OPT_EMPTY    { $$ = ev.fractal_pattern(sg::Pattern::Kind::Mandel, $2, @2, nullptr, {}); }
  | "julia" arith opt_comma arith %prec OPT_EMPTY { $$ = ev.fractal_pattern(sg::Pattern::Kind::Julia, $4, @4, &$2, @2); }
  | "magnet" arith "mandel" arith %prec OPT_EMPTY
      { $$ = ev.magnet_pattern($2, @2, ev.fractal_pattern(sg::Pattern::Kind::Mandel, $4, @4, nullptr, {})); }
  | "magnet" arith "julia" arith opt_comma arith %prec OPT_EMPTY
      { $$ = ev.magnet_pattern($2, @2, ev.fractal_pattern(sg::Pattern::Kind::Julia, $6, @6, &$4, @4)); }
  ;

/* Patterns whose values are a list of entries (POV's block patterns). */
block_pattern_name
  : "checker"          { $$ = ev.pattern_kind(sg::Pattern::Kind::Checker); }
  | "hexagon"          { $$ = ev.pattern_kind(sg::Pattern::Kind::Hexagon); }
  | "brick"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Brick); }
  | "square"           { $$ = ev.pattern_kind(sg::Pattern::Kind::Square); }
  | "triangular"       { $$ = ev.pattern_kind(sg::Pattern::Kind::Triangular); }
  | "cubic"            { $$ = ev.pattern_kind(sg::Pattern::Kind::Cubic); }
  ;

pattern_modifier
  : "turbulence" arith { $$ = ev.pattern_vector("turbulence", $2, @2); }
  | "octaves" arith    { $$ = ev.pattern_scalar("octaves", $2, @2); }
  | "omega" arith      { $$ = ev.pattern_scalar("omega", $2, @2); }
  | "lambda" arith     { $$ = ev.pattern_scalar("lambda", $2, @2); }
  | "frequency" arith  { $$ = ev.pattern_scalar("frequency", $2, @2); }
  | "phase" arith      { $$ = ev.pattern_scalar("phase", $2, @2); }
  | "ramp_wave"        { $$ = [](sg::Pattern& p) { p.wave = sg::WaveType::Ramp; }; }
  | "triangle_wave"    { $$ = [](sg::Pattern& p) { p.wave = sg::WaveType::Triangle; }; }
  | "sine_wave"        { $$ = [](sg::Pattern& p) { p.wave = sg::WaveType::Sine; }; }
  | "scallop_wave"     { $$ = [](sg::Pattern& p) { p.wave = sg::WaveType::Scallop; }; }
  | "cubic_wave"       { $$ = [](sg::Pattern& p) { p.wave = sg::WaveType::Cubic; }; }
  | "poly_wave" %prec OPT_EMPTY { $$ = [](sg::Pattern& p) { p.wave = sg::WaveType::Poly; p.wave_exponent = 1.0; }; }
  | "poly_wave" arith  { $$ = ev.pattern_scalar("poly_wave", $2, @2); }
  | "noise_generator" arith { $$ = ev.pattern_scalar("noise_generator", $2, @2); }
  | "warp" "{" warp_items "}" { $$ = ev.warp_edit($3, LOC(@1)); }
  | "agate_turb" arith { $$ = ev.pattern_scalar("agate_turb", $2, @2); }
  | "brick_size" arith { $$ = ev.pattern_vector("brick_size", $2, @2); }
  | "mortar" arith     { $$ = ev.pattern_scalar("mortar", $2, @2); }
  | "form" arith       { $$ = ev.pattern_vector("form", $2, @2); }
  | "metric" arith     { $$ = ev.pattern_scalar("metric", $2, @2); }
  | "offset" arith     { $$ = ev.pattern_scalar("offset", $2, @2); }
  | "solid"            { $$ = [](sg::Pattern& p) { p.crackle_solid = true; }; }
  | "coords" arith     { $$ = ev.pattern_scalar("coords", $2, @2); }
  | "size" arith       { $$ = ev.pattern_scalar("size", $2, @2); }
  | "exponent" arith   { $$ = ev.pattern_scalar("exponent", $2, @2); }
  | "exterior" arith opt_comma arith { $$ = ev.pattern_pair("exterior", $2, @2, $4, @4); }
  /* pavement's exterior N (a fractal's takes a factor too); an unknown name
   * after the number is read as the factor, as before. */
  | "exterior" arith %prec OPT_EMPTY { $$ = ev.pattern_scalar("exterior", $2, @2); }
  | "exterior" arith UNDECLARED_ID { ev.unknown_identifier($3.text, LOC(@3), "a value");
                                   $$ = ev.pattern_pair("exterior", $2, @2, Value::number(0.0), @3); }
  | "interior" arith opt_comma arith { $$ = ev.pattern_pair("interior", $2, @2, $4, @4); }
  /* pavement's interior N (a fractal's takes a factor too); an unknown name
   * after the number is read as the factor, as before. */
  | "interior" arith %prec OPT_EMPTY { $$ = ev.pattern_scalar("interior", $2, @2); }
  | "interior" arith UNDECLARED_ID { ev.unknown_identifier($3.text, LOC(@3), "a value");
                                   $$ = ev.pattern_pair("interior", $2, @2, Value::number(0.0), @3); }
  | "control0" arith   { $$ = ev.pattern_scalar("control0", $2, @2); }
  | "control1" arith   { $$ = ev.pattern_scalar("control1", $2, @2); }
  | "number_of_sides" arith { $$ = ev.pattern_scalar("number_of_sides", $2, @2); }
  | "number_of_tiles" arith { $$ = ev.pattern_scalar("number_of_tiles", $2, @2); }
  | "pattern" arith    { $$ = ev.pattern_scalar("pattern", $2, @2); }
  | "interpolate" arith { $$ = ev.pattern_scalar("interpolate", $2, @2); }
  | "altitude" arith   { $$ = ev.pattern_vector("altitude", $2, @2); }
  ;

warp_items
  : %empty             {}
  | warp_items warp_item { $$ = std::move($1); $$.push_back($2); }
  ;

warp_item
  : "turbulence" arith { $$ = ev.warp_vector("turbulence", $2, @2); }
  | "octaves" arith    { $$ = ev.warp_scalar("octaves", $2, @2); }
  | "omega" arith      { $$ = ev.warp_scalar("omega", $2, @2); }
  | "lambda" arith     { $$ = ev.warp_scalar("lambda", $2, @2); }
  | "repeat" arith     { $$ = ev.warp_vector("repeat", $2, @2); }
  | "offset" arith     { $$ = ev.warp_vector("offset", $2, @2); }
  | "flip" arith       { $$ = ev.warp_vector("flip", $2, @2); }
  | "black_hole" arith opt_comma arith { $$ = ev.black_hole($2, @2, $4, @4); }
  | "falloff" arith    { $$ = ev.warp_scalar("falloff", $2, @2); }
  | "strength" arith   { $$ = ev.warp_scalar("strength", $2, @2); }
  | "inverse"          { $$ = [](sg::Warp& w) { w.inverse = true; }; }
  | "cylindrical"      { $$ = ev.warp_kind(sg::Warp::Kind::Cylindrical); }
  | "spherical"        { $$ = ev.warp_kind(sg::Warp::Kind::Spherical); }
  | "toroidal"         { $$ = ev.warp_kind(sg::Warp::Kind::Toroidal); }
  | "planar"           { $$ = ev.warp_kind(sg::Warp::Kind::Planar); }
  | "planar" arith opt_comma arith { $$ = ev.planar_warp($2, @2, $4, @4); }
  | "orientation" arith { $$ = ev.warp_vector("orientation", $2, @2); }
  | "dist_exp" arith   { $$ = ev.warp_scalar("dist_exp", $2, @2); }
  | "major_radius" arith { $$ = ev.warp_scalar("major_radius", $2, @2); }
  ;

/* color_map { [value colour] ... }, POV's old [v1 v2 colour1 colour2] too. */
color_map
  : "color_map" "{" color_map_body "}" { $$ = $3; }
  | "colour_map" "{" color_map_body "}" { $$ = $3; }
  ;

color_map_body
  : COLOR_MAP_ID       { $$ = $1.value.color_map(); }
  | color_map_entries  { $$ = ev.build_color_map($1, LOC(@1)); }
  ;

color_map_entries
  : %empty             {}
  | color_map_entries "[" arith opt_comma colour_seq "]" { $$ = std::move($1); $$.emplace_back($3, $5); }
  ;

colour_seq
  : colour             { $$.push_back($1); }
  | bare_colour        { $$.push_back($1); }
  | colour_seq opt_comma colour { $$ = std::move($1); $$.push_back($3); }
  | colour_seq "," bare_colour { $$ = std::move($1); $$.push_back($3); }
  ;

pigment_map
  : "pigment_map" "{" PIGMENT_MAP_ID "}" { $$ = std::make_shared<std::vector<sg::PigmentMapEntry>>(*$3.value.pigment_map()); }
  | "pigment_map" "{" pigment_map_entries "}" { $$ = $3; }
  /* A density's map of densities (POV's density_map): a pigment_map of them. */
  | "density_map" "{" density_map_entries "}" { $$ = $3; }
  ;

density_map_entries
  : %empty             { $$ = std::make_shared<std::vector<sg::PigmentMapEntry>>(); }
  | density_map_entries "[" arith opt_comma "density" "{" pigment_edits "}" "]"
      { $$ = $1; $$->push_back(sg::PigmentMapEntry{ev.to_float($3, @3, "a map value"), ev.build_density($7, LOC(@5))}); }
  /* A declared density (#declare D = density { … }) as the entry. */
  | density_map_entries "[" arith opt_comma PIGMENT_ID "]"
      { $$ = $1; $$->push_back(sg::PigmentMapEntry{ev.to_float($3, @3, "a map value"), $5.value.pigment()}); }
  ;

pigment_map_entries
  : %empty             { $$ = std::make_shared<std::vector<sg::PigmentMapEntry>>(); }
  | pigment_map_entries "[" arith opt_comma pigment_body "]"
      { $$ = $1; $$->push_back(sg::PigmentMapEntry{ev.to_float($3, @3, "a map value"), $5}); }
  /* An average's entry may leave out its weight (POV's 1) when it starts
   * with a pattern or a declared pigment rather than a number. */
  | pigment_map_entries "[" unweighted_pigment "]"
      { $$ = $1; $$->push_back(sg::PigmentMapEntry{sg::kUnweighted, $3}); }
  ;

/* ----------------------------------------------------------------- normals */

normal
  : "normal" "{" normal_body "}" { $$ = $3; }
  ;

normal_block
  : "normal" "{" normal_edits "}" { $$ = std::move($3); }
  ;

normal_body
  : normal_edits       { $$ = ev.build_normal($1, LOC(@1)); }
  ;

normal_edits
  : normal_start normal_mods { $$ = std::move($2); $$.insert($$.begin(), $1); }
  | "uv_mapping" normal_start normal_mods
      { $$ = std::move($3); $$.insert($$.begin(), $2); $$.push_back([](sg::Normal& n) { n.pattern->uv_mapping = true; }); }
  ;

normal_start
  : %empty %prec OPT_EMPTY { $$ = [](sg::Normal&) {}; }
  | NORMAL_ID          { auto n = $1.value.normal(); $$ = [n](sg::Normal& target) { target = *n; }; }
  /* POV-Ray: a normal identifier, then a new pattern for it. */
  | NORMAL_ID normal_type
      { auto n = $1.value.normal(); auto type = $2; $$ = [n, type](sg::Normal& target) { target = *n; type(target); }; }
  | normal_type        { $$ = std::move($1); }
  ;

normal_type
  : pattern_name opt_amount { $$ = ev.patterned_normal($1, $2, LOC(@1)); }
  | block_pattern_name opt_amount { $$ = ev.patterned_normal($1, $2, LOC(@1)); }
  | block_pattern_name opt_amount block_normals { $$ = ev.block_normal($1, $2, $3, LOC(@1)); }
  | "object" "{" object_ref "}" { $$ = ev.block_normal(ev.object_pattern($3, LOC(@1)), std::nullopt, {}, LOC(@1)); }
  | "object" "{" object_ref block_normals "}"
      { $$ = ev.block_normal(ev.object_pattern($3, LOC(@1)), std::nullopt, $4, LOC(@1)); }
  | "bump_map" "{" image_items "}" opt_amount { $$ = ev.bump_map_normal($3, $5, LOC(@1)); }
  | "average"          { $$ = [](sg::Normal& n) { n.kind = sg::Normal::Kind::Average; }; }
  ;

opt_amount
  : %empty %prec OPT_EMPTY { }
  | arith %prec OPT_EMPTY { $$ = std::make_pair($1, @1); }
  | "," arith %prec OPT_EMPTY { $$ = std::make_pair($2, @2); }
  ;

/* slope { <direction> [, lo, hi] [altitude <a> [, lo, hi]] } or
 * slope { point_at <p> [, lo, hi] } */
slope_block
  : arith opt_range    { $$ = ev.slope_block($1, @1, $2, std::nullopt, std::nullopt, false); }
  | arith opt_range "altitude" arith opt_range
      { $$ = ev.slope_block($1, @1, $2, std::make_pair($4, @4), $5, false); }
  | "point_at" arith opt_range { $$ = ev.slope_block($2, @2, $3, std::nullopt, std::nullopt, true); }
  ;

opt_range
  : %empty %prec OPT_EMPTY { }
  | "," arith "," arith %prec OPT_EMPTY { $$ = std::make_pair(ev.to_float($2, @2, "a low value"), ev.to_float($4, @4, "a high value")); }
  ;

normal_mods
  : %empty             {}
  | normal_mods normal_mod { $$ = std::move($1); $$.push_back($2); }
  ;

normal_mod
  : transform_item     { sg::Mat4 t = $1; $$ = [t](sg::Normal& n) { transform_normal(n, t); }; }
  | pattern_modifier   { $$ = ev.normal_pattern_edit($1, LOC(@1)); }
  | "bump_size" arith  { double v = ev.to_float($2, @2, "a bump_size"); $$ = [v](sg::Normal& n) { n.bump_size = v; }; }
  | "accuracy" arith   { $$ = ev.normal_accuracy($2, @2); }
  | "slope_map" "{" slope_map_entries "}" { auto m = $3; $$ = [m](sg::Normal& n) { n.slope_map = m; }; }
  | normal_map         { auto m = $1; $$ = [m](sg::Normal& n) { n.normal_map = *m; n.block_normals.clear(); }; }
  | "use_color"        { $$ = [](sg::Normal& n) { n.bump_map_use_color = true; }; }
  | "use_colour"       { $$ = [](sg::Normal& n) { n.bump_map_use_color = true; }; }
  | "use_index"        { $$ = [](sg::Normal& n) { n.bump_map_use_color = false; }; }
  | "uv_mapping"       { $$ = [](sg::Normal& n) { n.pattern->uv_mapping = true; }; }
  ;

/* checker normal { … } normal { … }: one normal per block. */
block_normals
  : normal             { $$.push_back($1); }
  | block_normals opt_comma normal { $$ = std::move($1); $$.push_back($3); }
  ;

normal_map
  : "normal_map" "{" NORMAL_MAP_ID "}" { $$ = std::make_shared<std::vector<sg::NormalMapEntry>>(*$3.value.normal_map()); }
  | "normal_map" "{" normal_map_entries "}" { $$ = $3; }
  ;

normal_map_entries
  : %empty             { $$ = std::make_shared<std::vector<sg::NormalMapEntry>>(); }
  | normal_map_entries "[" arith opt_comma normal_body "]"
      { $$ = $1; $$->push_back(sg::NormalMapEntry{ev.to_float($3, @3, "a map value"), $5}); }
  | normal_map_entries "[" normal_body "]"
      { $$ = $1; $$->push_back(sg::NormalMapEntry{sg::kUnweighted, $3}); }
  ;

slope_map_entries
  : %empty             {}
  | slope_map_entries "[" arith opt_comma arith "]" { $$ = std::move($1); $$.push_back(ev.slope_entry($3, @3, $5, @5)); }
  ;

image_map
  : "image_map" "{" image_items "}" { $$ = $3; ev.finish_image_map($$, LOC(@1)); ev.refuse_foreign_image_items($$, "image_map"); }
  ;

image_items
  : %empty             { $$ = sg::ImageMap{}; }
  | image_items "png"  { $$ = $1; $$.format = sg::ImageFormat::Png; }
  | image_items "jpeg" { $$ = $1; $$.format = sg::ImageFormat::Jpeg; }
  | image_items "exr"  { $$ = $1; $$.format = sg::ImageFormat::Exr; }
  | image_items "hdr"  { $$ = $1; $$.format = sg::ImageFormat::Hdr; }
  | image_items "tga"  { $$ = $1; $$.format = sg::ImageFormat::Tga; }
  | image_items "tiff" { $$ = $1; $$.format = sg::ImageFormat::Tiff; }
  | image_items STRING { $$ = $1; $$.path = $2.text; $$.location = LOC(@2); }
  | image_items VALUE_ID { $$ = $1; $$.path = ev.to_string($2.value, @2); $$.location = LOC(@2); }
  | image_items "map_type" expr { $$ = $1; $$.map_type = ev.map_type($3, @3); }
  | image_items "interpolate" expr { $$ = $1; $$.interpolate = ev.to_int($3, @3); }
  | image_items "once" { $$ = $1; $$.once = true; }
  | image_items "gif"  { $$ = $1; $$.format = sg::ImageFormat::Gif; }
  | image_items "bmp"  { $$ = $1; $$.format = sg::ImageFormat::Bmp; }
  | image_items "ppm"  { $$ = $1; $$.format = sg::ImageFormat::Pnm; }
  | image_items "pgm"  { $$ = $1; $$.format = sg::ImageFormat::Pnm; }
  | image_items "iff"  { $$ = $1; $$.format = sg::ImageFormat::Iff; }
  | image_items "sys"  { $$ = $1; $$.format = sg::ImageFormat::Png; }
  | image_items "filter" "all" expr
      { $$ = $1; $$.palette_settings.push_back({false, -1, ev.to_float($4, @4), LOC(@2)}); }
  | image_items "transmit" "all" expr
      { $$ = $1; $$.palette_settings.push_back({true, -1, ev.to_float($4, @4), LOC(@2)}); }
  | image_items "filter" arith opt_comma arith
      { $$ = $1; $$.palette_settings.push_back(ev.palette_setting(false, $3, @3, $5, @5)); }
  | image_items "transmit" arith opt_comma arith
      { $$ = $1; $$.palette_settings.push_back(ev.palette_setting(true, $3, @3, $5, @5)); }
  | image_items "gamma" expr { $$ = $1; $$.srgb = ev.to_float($3, @3) != 1.0; $$.gamma_given = true; }
  /* image_pattern's own item */
  | image_items "use_alpha" { $$ = $1; $$.use_alpha = true; $$.use_alpha_location = LOC(@2); }
  /* bump_map's own items (an image_map refuses them) */
  | image_items "bump_size" arith { $$ = $1; $$.bump_size = ev.to_float($3, @3, "a bump_size"); $$.bump_item_location = LOC(@2); }
  | image_items "use_color" { $$ = $1; $$.use_color = true; $$.bump_item_location = LOC(@2); }
  | image_items "use_colour" { $$ = $1; $$.use_color = true; $$.bump_item_location = LOC(@2); }
  | image_items "use_index" { $$ = $1; $$.use_color = false; $$.bump_item_location = LOC(@2); }
  ;

finish
  : "finish" "{" finish_items "}" { $$ = ev.build_finish($3, LOC(@1)); }
  ;

finish_block
  : "finish" "{" finish_items "}" { $$ = std::move($3); }
  ;

finish_items
  : %empty             {}
  | finish_items finish_item { $$ = std::move($1); $$.push_back($2); }
  ;

opt_albedo
  : %empty             { $$ = false; }
  | "albedo"           { $$ = true; }
  ;

finish_item
  : FINISH_ID          { auto f = $1.value.finish(); $$ = [f](sg::Finish& target) { target = *f; }; }
  | "ambient" colour   { sg::Vec3 c = ev.to_color($2, @2).rgb; $$ = [c](sg::Finish& f) { f.ambient = c; }; }
  | "emission" colour  { sg::Vec3 c = ev.to_color($2, @2).rgb; $$ = [c](sg::Finish& f) { f.emission = c; }; }
  | "diffuse" opt_albedo expr { $$ = ev.finish_scalar("diffuse", $2, $3, @3); }
  /* POV's diffuse backside: the share of light arriving from behind */
  | "diffuse" opt_albedo expr "," expr
      { auto front = ev.finish_scalar("diffuse", $2, $3, @3); auto back = ev.finish_scalar("diffuse_back", $2, $5, @5);
        $$ = [front, back](sg::Finish& f) { front(f); back(f); }; }
  | "irid" "{" arith irid_items "}"
      { double amount = ev.to_float($3, @3, "an irid amount"); auto items = $4;
        $$ = [amount, items](sg::Finish& f) { f.irid = amount; f.irid_thickness = 0.0; f.irid_turbulence = 0.0;
                                              for (auto& item : items) item(f); }; }
  | "brilliance" expr  { $$ = ev.finish_scalar("brilliance", false, $2, @2); }
  | "specular" opt_albedo expr { $$ = ev.finish_scalar("specular", $2, $3, @3); }
  | "roughness" expr   { $$ = ev.finish_scalar("roughness", false, $2, @2); }
  | "phong" opt_albedo expr { $$ = ev.finish_scalar("phong", $2, $3, @3); }
  | "phong_size" expr  { $$ = ev.finish_scalar("phong_size", false, $2, @2); }
  | "metallic"         { $$ = [](sg::Finish& f) { f.metallic = 1.0; }; }
  | "metallic" expr    { $$ = ev.finish_scalar("metallic", false, $2, @2); }
  | "reflection" colour { sg::Vec3 c = ev.to_color($2, @2).rgb;
                          $$ = [c](sg::Finish& f) { f.reflection.min = c; f.reflection.max = c; }; }
  | "reflection" "{" reflection_items "}"
      { auto edits = $3; $$ = [edits](sg::Finish& f) { const double exponent = f.reflection.exponent;
                                                        f.reflection = sg::Reflection{}; f.reflection.exponent = exponent;
                                                        for (auto& e : edits) e(f); }; }
  | "reflection_exponent" expr { double v = ev.positive($2, @2, "a reflection exponent");
                                 $$ = [v](sg::Finish& f) { f.reflection.exponent = v; }; }
  | "conserve_energy" opt_bool { bool on = $2; $$ = [on](sg::Finish& f) { f.conserve_energy = on; }; }
  | "crand" expr       { $$ = ev.finish_scalar("crand", false, $2, @2); }
  ;

irid_items
  : %empty             {}
  | irid_items "thickness" arith { $$ = std::move($1); double t = ev.to_float($3, @3, "a film thickness");
                                   $$.push_back([t](sg::Finish& f) { f.irid_thickness = t; }); }
  | irid_items "turbulence" arith { $$ = std::move($1); double t = ev.to_vec3($3, @3).x;
                                    $$.push_back([t](sg::Finish& f) { f.irid_turbulence = t; }); }
  ;

/* reflection { [min,] max [fresnel on] [falloff F] [exponent E] [metallic M] } */
reflection_items
  : colour reflection_opts
      { $$ = std::move($2); sg::Vec3 c = ev.to_color($1, @1).rgb; bool fresnel_min_zero = true;
        $$.insert($$.begin(), [c](sg::Finish& f) { f.reflection.min = c; f.reflection.max = c; });
        $$.push_back([fresnel_min_zero](sg::Finish& f) { if (f.reflection.fresnel && fresnel_min_zero) f.reflection.min = sg::Vec3(0.0); }); }
  | colour opt_comma colour reflection_opts
      { $$ = std::move($4); sg::Vec3 lo = ev.to_color($1, @1).rgb, hi = ev.to_color($3, @3).rgb;
        $$.insert($$.begin(), [lo, hi](sg::Finish& f) { f.reflection.min = lo; f.reflection.max = hi; }); }
  ;

reflection_opts
  : %empty             {}
  | reflection_opts reflection_item { $$ = std::move($1); $$.push_back($2); }
  ;

reflection_item
  : "fresnel" opt_bool { bool on = $2; $$ = [on](sg::Finish& f) { f.reflection.fresnel = on; }; }
  | "falloff" expr     { double v = ev.to_float($2, @2); $$ = [v](sg::Finish& f) { f.reflection.falloff = v; }; }
  | "exponent" expr    { double v = ev.positive($2, @2, "a reflection exponent"); $$ = [v](sg::Finish& f) { f.reflection.exponent = v; }; }
  | "metallic"         { $$ = [](sg::Finish& f) { f.reflection.metallic = 1.0; }; }
  | "metallic" expr    { double v = ev.to_float($2, @2); $$ = [v](sg::Finish& f) { f.reflection.metallic = v; }; }
  ;

interior
  : "interior" "{" interior_items "}" { $$ = ev.build_interior($3, LOC(@1)); }
  ;

interior_items
  : %empty             {}
  | interior_items INTERIOR_ID { $$ = std::move($1); auto i = $2.value.interior();
                                 $$.push_back([i](sg::Interior& target) { target = *i; }); }
  | interior_items "ior" expr { $$ = std::move($1); double v = ev.positive($3, @3, "ior");
                                $$.push_back([v](sg::Interior& i) { i.ior = v; }); }
  | interior_items "caustics" expr { $$ = std::move($1); double v = ev.to_float($3, @3, "a caustics value");
                                     $$.push_back([v](sg::Interior& i) { i.caustics = v; }); }
  | interior_items "dispersion" expr { $$ = std::move($1); ev.ignored(LOC(@2), "dispersion"); }
  | interior_items "dispersion_samples" expr { $$ = std::move($1); ev.dispersion_samples(LOC(@2), $3, @3); }
  | interior_items "fade_distance" expr { $$ = std::move($1); double v = ev.to_float($3, @3, "a fade_distance");
                                          $$.push_back([v](sg::Interior& i) { i.fade_distance = v; }); }
  | interior_items "fade_power" expr { $$ = std::move($1); double v = ev.to_float($3, @3, "a fade_power");
                                       $$.push_back([v](sg::Interior& i) { i.fade_power = v; }); }
  | interior_items "fade_color" colour { $$ = std::move($1); sg::Vec3 c = ev.to_color($3, @3).rgb;
                                         $$.push_back([c](sg::Interior& i) { i.fade_color = c; }); }
  | interior_items "fade_colour" colour { $$ = std::move($1); sg::Vec3 c = ev.to_color($3, @3).rgb;
                                          $$.push_back([c](sg::Interior& i) { i.fade_color = c; }); }
  | interior_items media { $$ = std::move($1); sg::Media m = *$2;
                           $$.push_back([m](sg::Interior& i) { i.media.push_back(m); }); }
  ;

/* ------------------------------------------------------------------- media */

/* POV's media block (scene_media.h); a declared media first, then edits. */
media
  : "media" "{" media_items "}" { $$ = ev.build_media($3, LOC(@1)); }
  ;

media_items
  : %empty             {}
  | media_items MEDIA_ID { $$ = std::move($1); auto m = $2.value.media();
                           $$.push_back([m](sg::Media& target) { target = *m; }); }
  | media_items media_item { $$ = std::move($1); $$.push_back($2); }
  ;

media_item
  : "emission" colour  { sg::Vec3 c = ev.to_color($2, @2).rgb; $$ = [c](sg::Media& m) { m.emission = c; }; }
  | "absorption" colour { sg::Vec3 c = ev.to_color($2, @2).rgb; $$ = [c](sg::Media& m) { m.absorption = c; }; }
  | "scattering" "{" expr "," colour scattering_items "}" { $$ = ev.media_scattering($3, @3, $5, @5, $6); }
  | "density" "{" pigment_edits "}" { auto d = ev.build_density($3, LOC(@1));
                                      $$ = [d](sg::Media& m) { m.densities.push_back(d); }; }
  | "method" expr      { $$ = ev.media_integer("method", $2, @2, 1, 3); }
  | "intervals" expr   { $$ = ev.media_integer("intervals", $2, @2, 1, 1 << 20); }
  | "samples" expr     { $$ = ev.media_samples($2, @2, $2, @2); }
  | "samples" expr "," expr { $$ = ev.media_samples($2, @2, $4, @4); }
  | "confidence" expr  { $$ = ev.media_real("confidence", $2, @2, 0.0, 1.0); }
  | "variance" expr    { $$ = ev.media_real("variance", $2, @2, 0.0, 1e30); }
  | "ratio" expr       { $$ = ev.media_real("ratio", $2, @2, 0.0, 1.0); }
  | "aa_level" expr    { $$ = ev.media_integer("aa_level", $2, @2, 1, 16); }
  | "aa_threshold" expr { $$ = ev.media_real("aa_threshold", $2, @2, 0.0, 1e30); }
  | "jitter" expr      { $$ = ev.media_real("jitter", $2, @2, 0.0, 1e30); }
  | "collect" opt_bool { $$ = [](sg::Media&) {}; ev.ignored(LOC(@1), "collect (photons)"); }
  | transform_item     { sg::Mat4 t = $1; $$ = [t](sg::Media& m) { transform_densities(m, t); }; }
  ;

/* --------------------------------------------------------------- sky_sphere */

/* POV's Parse_Skysphere: a declared sky first, then pigments (the last on
   top), emission and transforms of the whole sky. */
sky_sphere
  : "sky_sphere" "{" sky_sphere_items "}" { $$ = ev.build_sky_sphere($3, LOC(@1)); }
  ;

sky_sphere_items
  : %empty             {}
  | sky_sphere_items SKY_SPHERE_ID { $$ = std::move($1); auto s = $2.value.sky_sphere();
                           $$.push_back([s](sg::SkySphere& target) { target = *s; }); }
  | sky_sphere_items pigment { $$ = std::move($1); auto p = $2;
                           $$.push_back([p](sg::SkySphere& s) { s.pigments.push_back(*p); }); }
  | sky_sphere_items "emission" colour { $$ = std::move($1); sg::Vec3 c = ev.to_color($3, @3).rgb;
                           $$.push_back([c](sg::SkySphere& s) { s.emission = c; }); }
  | sky_sphere_items transform_item { $$ = std::move($1); sg::Mat4 t = $2;
                           $$.push_back([t](sg::SkySphere& s) { s.transform = t * s.transform; }); }
  ;

/* --------------------------------------------------------------------- fog */

/* POV's Parse_Fog: a declared fog first, then its items in any order;
   transforms turn only its up vector. */
fog
  : "fog" "{" fog_items "}" { $$ = ev.build_fog($3, LOC(@1)); }
  ;

fog_items
  : %empty             {}
  | fog_items FOG_ID   { $$ = std::move($1); auto f = $2.value.fog();
                         $$.push_back([f](sg::Fog& target) { target = *f; }); }
  | fog_items fog_item { $$ = std::move($1); $$.push_back($2); }
  ;

fog_item
  : colour_keyword arith %prec OPT_EMPTY { sg::Color c = ev.to_color(ev.colour_from($2, @2), @2); $$ = [c](sg::Fog& f) { f.color = c; }; }
  /* POV's CASE_COLOUR and CASE_FLOAT: a colour, or the distance unnamed. */
  | arith %prec OPT_EMPTY              { $$ = ev.fog_value($1, @1); }
  | "distance" arith %prec OPT_EMPTY    { double d = ev.to_float($2, @2, "a fog distance"); $$ = [d](sg::Fog& f) { f.distance = d; }; }
  | "fog_type" arith %prec OPT_EMPTY    { $$ = ev.fog_type($2, @2); }
  | "fog_offset" arith %prec OPT_EMPTY  { double v = ev.to_float($2, @2, "a fog_offset"); $$ = [v](sg::Fog& f) { f.offset = v; }; }
  | "fog_alt" arith %prec OPT_EMPTY     { double v = ev.to_float($2, @2, "a fog_alt"); $$ = [v](sg::Fog& f) { f.alt = v; }; }
  | "turb_depth" arith %prec OPT_EMPTY  { double v = ev.to_float($2, @2, "a turb_depth"); $$ = [v](sg::Fog& f) { f.turb_depth = v; }; }
  | "up" arith %prec OPT_EMPTY          { sg::Vec3 u = ev.nonzero_vec3($2, @2, "a fog's up vector"); $$ = [u](sg::Fog& f) { f.up = u; }; }
  | "turbulence" arith %prec OPT_EMPTY  { sg::Vec3 t = ev.to_vec3($2, @2);
                         $$ = [t](sg::Fog& f) { f.turbulent = true; f.turbulence = t; }; }
  | "octaves" arith %prec OPT_EMPTY     { $$ = ev.fog_octaves($2, @2); }
  | "omega" arith %prec OPT_EMPTY       { double v = ev.to_float($2, @2, "an omega"); $$ = [v](sg::Fog& f) { f.turbulent = true; f.omega = v; }; }
  | "lambda" arith %prec OPT_EMPTY      { double v = ev.to_float($2, @2, "a lambda"); $$ = [v](sg::Fog& f) { f.turbulent = true; f.lambda = v; }; }
  | transform_item     { $$ = ev.fog_transform($1, @1); }
  ;

/* ----------------------------------------------------------------- rainbow */

/* POV's Parse_Rainbow: a declared rainbow first, then its items. */
rainbow
  : "rainbow" "{" rainbow_items "}" { $$ = ev.build_rainbow($3, LOC(@1)); }
  ;

rainbow_items
  : %empty             {}
  | rainbow_items RAINBOW_ID { $$ = std::move($1); auto r = $2.value.rainbow();
                         $$.push_back([r](sg::Rainbow& target) { target = *r; }); }
  | rainbow_items rainbow_item { $$ = std::move($1); $$.push_back($2); }
  ;

rainbow_item
  : "angle" expr       { double v = ev.to_float($2, @2, "a rainbow angle"); $$ = [v](sg::Rainbow& r) { r.angle = v; }; }
  | "width" expr       { double v = ev.to_float($2, @2, "a rainbow width"); $$ = [v](sg::Rainbow& r) { r.width = v; }; }
  | "distance" expr    { double v = ev.to_float($2, @2, "a rainbow distance"); $$ = [v](sg::Rainbow& r) { r.distance = v; }; }
  | "jitter" expr      { double v = ev.to_float($2, @2, "a rainbow jitter"); $$ = [v](sg::Rainbow& r) { r.jitter = v; }; }
  | "direction" expr   { sg::Vec3 v = ev.to_vec3($2, @2); $$ = [v](sg::Rainbow& r) { r.direction = v; }; }
  | "up" expr          { sg::Vec3 v = ev.to_vec3($2, @2); $$ = [v](sg::Rainbow& r) { r.up = v; }; }
  | "arc_angle" expr   { $$ = ev.rainbow_angle(true, $2, @2); }
  | "falloff_angle" expr { $$ = ev.rainbow_angle(false, $2, @2); }
  | color_map          { auto m = $1; $$ = [m](sg::Rainbow& r) { r.color_map = m; }; }
  ;

/* After scattering's type and colour: eccentricity (type 5) and extinction. */
scattering_items
  : %empty             {}
  | scattering_items "eccentricity" expr { $$ = std::move($1); double g = ev.to_float($3, @3, "an eccentricity");
                                           $$.push_back([g](sg::Media& m) { m.eccentricity = g; }); }
  | scattering_items "extinction" expr { $$ = std::move($1); double e = ev.to_float($3, @3, "an extinction");
                                         $$.push_back([e](sg::Media& m) { m.extinction = e; }); }
  ;

/* ----------------------------------------------------------------- colours */

/* A colour: an expression (a colour, or a float/vector promoted to one),
 * optionally after `color`, optionally followed by component overrides
 * (`color red 1 green .5`, `color Gray filter .3`). */
colour
  : colour_base        { $$ = std::move($1); }
  | colour colour_channel expr %prec OPT_EMPTY { $$ = ev.colour_component($1, @1, $2, $3, @3); }
  ;

colour_base
  : expr %prec OPT_EMPTY { $$ = std::move($1); }
  | colour_keyword expr %prec OPT_EMPTY { $$ = ev.colour_from($2, @2); }
  | colour_keyword colour_channel expr %prec OPT_EMPTY
      { $$ = ev.colour_component(Value::color(sg::Color{}), @1, $2, $3, @3); }
  ;

bare_colour
  : colour_channel expr %prec OPT_EMPTY { $$ = ev.colour_component(Value::color(sg::Color{}), @1, $1, $2, @2); }
  | bare_colour colour_channel expr %prec OPT_EMPTY { $$ = ev.colour_component($1, @1, $2, $3, @3); }
  ;

colour_channel
  : "red"              { $$ = 0; }
  | "green"            { $$ = 1; }
  | "blue"             { $$ = 2; }
  | "filter"           { $$ = 3; }
  | "transmit"         { $$ = 4; }
  ;

colour_keyword: "color" | "colour" ;

/* ------------------------------------------------------------- expressions */

/* POV reads an object's float and vector arguments without relational,
 * logical or conditional operators at their top level (Parse_Float is
 * Parse_Rel_Factor): `v_steps 8 <0, 0, 2>` is a count, then a point.
 * `arith` is that expression; `expr` adds the rest. */
expr
  : arith %prec OPT_EMPTY { $$ = std::move($1); }
  | expr "<" expr      { $$ = ev.compare("<", $1, @1, $3, @3); }
  | expr "<=" expr     { $$ = ev.compare("<=", $1, @1, $3, @3); }
  | expr ">" expr      { $$ = ev.compare(">", $1, @1, $3, @3); }
  | expr ">=" expr     { $$ = ev.compare(">=", $1, @1, $3, @3); }
  | expr "=" expr      { $$ = ev.compare("=", $1, @1, $3, @3); }
  | expr "!=" expr     { $$ = ev.compare("!=", $1, @1, $3, @3); }
  | expr "&" expr      { $$ = ev.logical('&', $1, @1, $3, @3); }
  | expr "|" expr      { $$ = ev.logical('|', $1, @1, $3, @3); }
  | expr "?" expr ":" expr { $$ = ev.to_float($1, @1, "a condition") != 0.0 ? $3 : $5; }
  ;

arith
  : postfix            { $$ = std::move($1); }
  | arith "+" arith    { $$ = ev.arithmetic('+', $1, $3, @2); }
  | arith "-" arith    { $$ = ev.arithmetic('-', $1, $3, @2); }
  | arith "*" arith    { $$ = ev.arithmetic('*', $1, $3, @2); }
  | arith "/" arith    { $$ = ev.arithmetic('/', $1, $3, @2); }
  | "-" arith %prec UNARY { $$ = ev.negate($2, @2); }
  | "+" arith %prec UNARY { $$ = std::move($2); }
  | "!" arith %prec UNARY { $$ = Value::number(ev.to_float($2, @2, "an operand of '!'") == 0.0 ? 1.0 : 0.0); }
  | "rgb" arith %prec COLOUR_KEYWORD    { $$ = ev.colour_keyword("rgb", $2, @2); }
  | "rgbf" arith %prec COLOUR_KEYWORD   { $$ = ev.colour_keyword("rgbf", $2, @2); }
  | "rgbt" arith %prec COLOUR_KEYWORD   { $$ = ev.colour_keyword("rgbt", $2, @2); }
  | "rgbft" arith %prec COLOUR_KEYWORD  { $$ = ev.colour_keyword("rgbft", $2, @2); }
  | "srgb" arith %prec COLOUR_KEYWORD   { $$ = ev.colour_keyword("srgb", $2, @2); }
  | "srgbf" arith %prec COLOUR_KEYWORD  { $$ = ev.colour_keyword("srgbf", $2, @2); }
  | "srgbt" arith %prec COLOUR_KEYWORD  { $$ = ev.colour_keyword("srgbt", $2, @2); }
  | "srgbft" arith %prec COLOUR_KEYWORD { $$ = ev.colour_keyword("srgbft", $2, @2); }
  ;

postfix
  : primary            { $$ = std::move($1); }
  | postfix "." component { $$ = ev.component($1, @1, $3, @3); }
  ;

component
  : CONSTANT           { $$ = $1.text; }
  | UNDECLARED_ID      { $$ = $1.text; }
  | "red"              { $$ = "red"; }
  | "green"            { $$ = "green"; }
  | "blue"             { $$ = "blue"; }
  | "filter"           { $$ = "filter"; }
  | "transmit"         { $$ = "transmit"; }
  | "gray"             { $$ = "gray"; }
  | "grey"             { $$ = "gray"; }
  ;

primary
  : NUMBER             { $$ = std::move($1.value); }
  | STRING             { $$ = std::move($1.value); }
  | CONSTANT           { $$ = std::move($1.value); }
  | VALUE_ID           { $$ = std::move($1.value); }
  | UNDECLARED_ID      { ev.unknown_identifier($1.text, LOC(@1), "a value"); $$ = Value::number(0.0); }
  | "(" expr ")"       { $$ = std::move($2); $$.boolean_literal = false; }
  | VECTOR_LITERAL     { $$ = std::move($1.value); }
  | "<" vector_items ">" { $$ = ev.make_vector($2, @$); }
  | "<" vector_items "," ">" { $$ = ev.make_vector($2, @$); }  /* POV's Parse_Comma after each */
  | BUILTIN "(" opt_args ")" { $$ = ev.call_builtin($1.text, $3, @$); }
  | FUNCTION_ID "(" opt_args ")" { $$ = ev.call_function($1.value, $3, @$); }
  /* Uncalled, a function or spline is a value to copy (`#declare G = F;`)
   * or pass to a macro, as in POV. */
  | FUNCTION_ID %prec OPT_EMPTY { $$ = std::move($1.value); }
  | SPLINE_ID %prec OPT_EMPTY { $$ = std::move($1.value); }
  | "trace" "(" OBJECT_ID "," expr "," expr ")" { $$ = ev.trace($3.value, @3, $5, @5, $7, @7, {}, @$); }
  | "trace" "(" OBJECT_ID "," expr "," expr "," trace_normal ")"
      { $$ = ev.trace($3.value, @3, $5, @5, $7, @7, $9, @$); }
  | "inside" "(" OBJECT_ID "," expr ")" { $$ = ev.inside($3.value, @3, $5, @5); }
  | SPLINE_ID "(" expr ")" { $$ = ev.call_spline($1.value, $3, @3, -1); }
  | SPLINE_ID "(" expr "," spline_kind ")" { $$ = ev.call_spline($1.value, $3, @3, $5); }
  | "min_extent" "(" OBJECT_ID ")" { $$ = ev.extent($3.value, @3, false); }
  | "max_extent" "(" OBJECT_ID ")" { $$ = ev.extent($3.value, @3, true); }
  ;

/* spline { [Id] [linear_spline | quadratic_spline | cubic_spline | natural_spline]… t, <v>, … } */
spline_kinds
  /* spline { S … } copies S: a first entry cannot start with a spline call. */
  : %empty %prec OPT_EMPTY {}
  | spline_kinds spline_kind { $$ = std::move($1); $$.push_back($2); }
  ;

spline_kind
  : "linear_spline"    { $$ = int(SplineData::Kind::Linear); }
  | "quadratic_spline" { $$ = int(SplineData::Kind::Quadratic); }
  | "cubic_spline"     { $$ = int(SplineData::Kind::Cubic); }
  | "natural_spline"   { $$ = int(SplineData::Kind::Natural); }
  ;

/* trace()'s fourth argument names the vector that receives the normal. */
trace_normal
  : VALUE_ID           { $$ = $1.text; }
  | UNDECLARED_ID      { $$ = $1.text; }
  ;

vector_items
  : vector_item        { $$.push_back($1); }
  | vector_items "," vector_item { $$ = std::move($1); $$.push_back($3); }
  | vector_items vector_item %prec OPT_EMPTY { $$ = std::move($1); $$.push_back($2); }
  ;

/* Inside < >, a '>' closes the vector (write (a > b) to compare). */
vector_item
  : expr %prec VECTOR_ITEM { $$ = std::move($1); }
  ;

opt_args
  : %empty             {}
  | expr_list          { $$ = std::move($1); }
  ;

expr_list
  : expr               { $$.push_back($1); }
  | expr_list "," expr { $$ = std::move($1); $$.push_back($3); }
  ;

macro_args
  : %empty             {}
  | macro_arg_list     { $$ = std::move($1); }
  ;

/* POV reads a comma after each argument as optional; lancer drops it
 * only after an object, where it is unambiguous (shapes.pov:
 * `Align_Object(Center_Object(…) -y, <0, 0, 0>)`). */
macro_arg_list
  : macro_arg_list_plain { $$ = std::move($1); }
  | macro_arg_list_object { $$ = std::move($1); }
  ;

macro_arg_list_plain
  : macro_arg          { $$.push_back(ev.macro_argument(std::move($1), @1)); }
  | macro_arg_list "," macro_arg { $$ = std::move($1); $$.push_back(ev.macro_argument(std::move($3), @3)); }
  | macro_arg_list_object macro_arg { $$ = std::move($1); $$.push_back(ev.macro_argument(std::move($2), @2)); }
  ;

macro_arg_list_object
  : object             { $$.push_back(MacroArgument{ev.object_value($1), std::nullopt}); }
  | macro_arg_list "," object { $$ = std::move($1); $$.push_back(MacroArgument{ev.object_value($3), std::nullopt}); }
  | macro_arg_list_object object { $$ = std::move($1); $$.push_back(MacroArgument{ev.object_value($2), std::nullopt}); }
  ;

macro_arg
  : colour             { $$ = std::move($1); }
  | OBJECT_ID          { $$ = std::move($1.value); }
  | TEXTURE_ID         { $$ = std::move($1.value); }
  | PIGMENT_ID         { $$ = std::move($1.value); }
  | FINISH_ID          { $$ = std::move($1.value); }
  | INTERIOR_ID        { $$ = std::move($1.value); }
  | CAMERA_ID          { $$ = std::move($1.value); }
  | LIGHT_ID           { $$ = std::move($1.value); }
  | TRANSFORM_ID       { $$ = std::move($1.value); }
  | NORMAL_ID          { $$ = std::move($1.value); }
  | COLOR_MAP_ID       { $$ = std::move($1.value); }
  | PIGMENT_MAP_ID     { $$ = std::move($1.value); }
  | NORMAL_MAP_ID      { $$ = std::move($1.value); }
  | texture            { $$.kind = Value::Kind::Texture; $$.payload = $1; }
  | pigment            { $$.kind = Value::Kind::Pigment; $$.payload = $1; }
  | finish             { $$.kind = Value::Kind::Finish; $$.payload = $1; }
  | normal             { $$.kind = Value::Kind::Normal; $$.payload = $1; }
  | FUNCTION_LITERAL   { $$ = std::move($1.value); }
  /* The barrier keeps a directive after `array[N]` (no ; needed) unrun
   * while it is only looked at. */
  | "array" begin_value array_sizes end_value { $$ = ev.make_array($3, {}, LOC(@1)); }
  | "array" begin_value array_sizes end_value array_init { $$ = ev.make_array($3, $5, LOC(@1)); }
  | FUNCTION_OPEN "pattern" "{" pigment_edits "}" "}" { $$ = ev.pattern_function($4, LOC(@1)); }
  | FUNCTION_OPEN pigment "}" { $$ = ev.pigment_function($2, LOC(@1)); }
  | FUNCTION_OPEN transform_block "}" { $$ = ev.transform_function($2, LOC(@1)); }
  | FUNCTION_OPEN spline_literal "}" { $$ = ev.spline_function($2, LOC(@1)); }
  | transform_block    { $$.kind = Value::Kind::Transform; $$.set_transform($1); }
  | color_map          { $$.kind = Value::Kind::ColorMap; $$.payload = $1; }
  | pigment_map        { $$.kind = Value::Kind::PigmentMap; $$.payload = $1; }
  | normal_map         { $$.kind = Value::Kind::NormalMap; $$.payload = $1; }
  /* What a #declare may hold, a macro may be given (advanced/mediasky.pov:
   * `SkyShell(1000, 1300, interior { media { … } })`). */
  | interior           { $$.kind = Value::Kind::Interior; $$.payload = $1; }
  | media              { $$.kind = Value::Kind::Media; $$.payload = $1; }
  | "density" "{" pigment_edits "}" { $$.kind = Value::Kind::Pigment; $$.payload = ev.build_density($3, LOC(@1)); }
  | material           { $$.kind = Value::Kind::Texture; $$.payload = $1; }
  | sky_sphere         { $$.kind = Value::Kind::SkySphere; $$.payload = $1; }
  | fog                { $$.kind = Value::Kind::Fog; $$.payload = $1; }
  | rainbow            { $$.kind = Value::Kind::Rainbow; $$.payload = $1; }
  | camera             { $$.kind = Value::Kind::Camera; $$.payload = std::move($1); }
  | spline_literal     { $$ = std::move($1); }
  | MEDIA_ID           { $$ = std::move($1.value); }
  | SKY_SPHERE_ID      { $$ = std::move($1.value); }
  | FOG_ID             { $$ = std::move($1.value); }
  | RAINBOW_ID         { $$ = std::move($1.value); }
  ;

/* ------------------------------------------------------------------ lights */

light
  : "light_source" "{" arith opt_comma colour light_items "}"
      { $$ = std::make_shared<sg::Light>(ev.make_light($3, @3, $5, @5, LOC(@1))); ev.apply_light(*$$, $6); }
  | "light_source" "{" LIGHT_ID light_items "}"
      { $$ = std::make_shared<sg::Light>(*$3.value.light()); ev.apply_light(*$$, $4); }
  ;

light_items
  : %empty             {}
  | light_items light_item { $$ = std::move($1); $$.push_back($2); }
  ;

light_item
  : "parallel"         { $$ = [](sg::Light& l) { l.parallel = true; }; }
  | "point_at" expr    { sg::Vec3 p = ev.to_vec3($2, @2); $$ = [p](sg::Light& l) { l.point_at = p; }; }
  | "area_light" arith opt_comma arith opt_comma arith opt_comma arith
      { $$ = ev.area_light($2, @2, $4, @4, $6, @6, $8, @8); }
  | "jitter"           { $$ = [](sg::Light& l) { l.jitter = true; }; }
  | "adaptive" expr    { int a = ev.to_int($2, @2); $$ = [a](sg::Light& l) { l.adaptive = a; }; }
  | "circular"         { $$ = [](sg::Light& l) { l.circular = true; }; }
  | "orient"           { $$ = [](sg::Light& l) { l.orient = true; }; }
  | "area_sphere" expr { double r = ev.positive($2, @2, "area_sphere radius");
                         $$ = [r](sg::Light& l) { l.kind = sg::Light::Kind::AreaSphere; l.radius = r; }; }
  | "area_rectangle" expr opt_comma expr
      { $$ = ev.area_rectangle($2, @2, $4, @4); }
  | "fade_distance" expr { double d = ev.to_float($2, @2); $$ = [d](sg::Light& l) { l.fade_distance = d; }; }
  | "fade_power" expr  { double p = ev.to_float($2, @2); $$ = [p](sg::Light& l) { l.fade_power = p; }; }
  /* POV-Ray keeps one light type: shadowless, spotlight and cylinder
     replace one another, the last written wins (a spotlight made
     shadowless lights every way). */
  | "shadowless"       { $$ = [](sg::Light& l) { l.shadowless = true; l.spotlight = l.cylinder = false; l.spot_parameters_given = false; }; }
  | "area_illumination" opt_bool { bool on = $2; $$ = [on](sg::Light& l) { l.area_illumination = on; }; }
  | "media_interaction" opt_bool { bool on = $2; $$ = [on](sg::Light& l) { l.media_interaction = on; }; }
  | "media_attenuation" opt_bool { bool on = $2; $$ = [on](sg::Light& l) { l.media_attenuation = on; }; }
  | "looks_like" "{" object_ref object_mods "}" { $$ = ev.looks_like($3, $4); }
  | "projected_through" "{" object_ref object_mods "}" { $$ = ev.projected_through($3, $4); }
  | "spotlight"        { $$ = [](sg::Light& l) { l.spotlight = true; l.cylinder = false; l.shadowless = false; l.spot_radius = 30.0; l.spot_falloff = 45.0; l.tightness = 0.0; }; }
  | "cylinder"         { $$ = [](sg::Light& l) { l.cylinder = true; l.spotlight = false; l.shadowless = false; l.parallel = true; l.spot_radius = 0.75; l.spot_falloff = 1.0; l.tightness = 0.0; }; }
  | "radius" expr      { double r = ev.to_float($2, @2); $$ = [r](sg::Light& l) { l.spot_radius = r; l.spot_parameters_given = true; }; }
  | "falloff" expr     { double f = ev.to_float($2, @2); $$ = [f](sg::Light& l) { l.spot_falloff = f; l.spot_parameters_given = true; }; }
  | "tightness" expr   { double t = ev.to_float($2, @2); $$ = [t](sg::Light& l) { l.tightness = t; l.spot_parameters_given = true; }; }
  | transform_item     { sg::Mat4 t = $1; $$ = [t](sg::Light& l) { transform_light(l, t); }; }
  ;

/* ------------------------------------------------------------------ camera */

camera
  : "camera" "{" camera_items "}"
      { $$ = std::make_shared<CameraSpec>(); $$->location_in_source = LOC(@1); for (auto& edit : $3) edit(*$$); }
  ;

camera_items
  : %empty             {}
  | camera_items camera_item { $$ = std::move($1); $$.push_back($2); }
  ;

camera_item
  : CAMERA_ID          { CameraSpec c = *$1.value.camera(); $$ = [c](CameraSpec& target) { target = c; }; }
  | camera_type        { auto p = $1; auto at = LOC(@1); $$ = [p, at](CameraSpec& c) { c.set_projection(p, at); }; }
  | mesh_camera        { $$ = std::move($1); }
  | "location" expr    { auto v = ev.to_vec3($2, @2); $$ = [v](CameraSpec& c) { c.location = v; c.other_item_seen = true; }; }
  | "look_at" expr     { auto v = ev.to_vec3($2, @2); $$ = [v](CameraSpec& c) { c.look_at = v; c.other_item_seen = true; }; }
  | "direction" expr   { auto v = ev.nonzero_vec3($2, @2, "direction"); $$ = [v](CameraSpec& c) { c.direction = v; c.other_item_seen = true; }; }
  | "right" expr       { auto v = ev.nonzero_vec3($2, @2, "right"); $$ = [v](CameraSpec& c) { c.right = v; c.other_item_seen = true; }; }
  | "up" expr          { auto v = ev.nonzero_vec3($2, @2, "up"); $$ = [v](CameraSpec& c) { c.up = v; c.other_item_seen = true; }; }
  | "sky" expr         { auto v = ev.nonzero_vec3($2, @2, "sky"); $$ = [v](CameraSpec& c) { c.sky = v; c.other_item_seen = true; }; }
  | "angle"            { auto at = LOC(@1); $$ = [at](CameraSpec& c) { c.set_angle(0.0, std::nullopt, at, false); }; }
  | "angle" expr       { double a = ev.camera_angle($2, @2); auto at = LOC(@2); $$ = [a, at](CameraSpec& c) { c.set_angle(a, std::nullopt, at, true); }; }
  | "angle" expr "," expr
      { double h = ev.camera_angle($2, @2), v = ev.camera_angle($4, @4); auto at = LOC(@2);
        $$ = [h, v, at](CameraSpec& c) { c.set_angle(h, v, at, true); }; }
  /* POV-Ray's comma between a spherical camera's two angles is optional:
     `angle 360 180`. Written without it, the second is read when it is a
     number, a declared value or in parentheses; other expressions there
     need the comma (POV-Ray reads the first expression as far as it goes,
     so `angle 360 -180` is 180 there too). */
  | "angle" expr angle_without_comma
      { double h = ev.camera_angle($2, @2), v = ev.camera_angle($3, @3); auto at = LOC(@2);
        $$ = [h, v, at](CameraSpec& c) { c.set_angle(h, v, at, true); }; }
  | "aperture" expr    { double a = ev.to_float($2, @2, "a float aperture"); $$ = [a](CameraSpec& c) { c.aperture = a; c.other_item_seen = true; }; }
  | "blur_samples" expr { $$ = ev.blur_samples($2, @2, nullptr, @2); }
  | "blur_samples" expr "," expr { $$ = ev.blur_samples($2, @2, &$4, @4); }
  | "focal_point" expr { auto v = ev.to_vec3($2, @2); $$ = [v](CameraSpec& c) { c.focal_point = v; c.other_item_seen = true; }; }
  | "confidence" expr  { $$ = ev.blur_confidence($2, @2); }
  | "variance" expr    { $$ = ev.blur_variance($2, @2); }
  | "bokeh" "{" pigment "}" { auto p = $3; $$ = [p](CameraSpec& c) { c.bokeh = p; c.other_item_seen = true; }; }
  | normal             { auto n = $1; $$ = [n](CameraSpec& c) { c.normal = n; c.other_item_seen = true; }; }
  | transform_item     { sg::Mat4 t = $1; $$ = [t](CameraSpec& c) { c.world_from_camera = t * c.world_from_camera; c.other_item_seen = true; }; }
  ;

angle_without_comma
  : NUMBER             { $$ = std::move($1.value); }
  | VALUE_ID           { $$ = std::move($1.value); }
  | "(" expr ")"       { $$ = std::move($2); }
  ;

camera_type
  : "perspective"      { $$ = sg::Camera::Projection::Perspective; }
  | "orthographic"     { $$ = sg::Camera::Projection::Orthographic; }
  | "fisheye"          { $$ = sg::Camera::Projection::Fisheye; }
  | "ultra_wide_angle" { $$ = sg::Camera::Projection::UltraWideAngle; }
  | "omnimax"          { $$ = sg::Camera::Projection::Omnimax; }
  | "panoramic"        { $$ = sg::Camera::Projection::Panoramic; }
  | "spherical"        { $$ = sg::Camera::Projection::Spherical; }
  | "cylinder" expr    { $$ = ev.cylinder_camera($2, @2); }
  ;

/* mesh_camera { rays_per_pixel, distribution_type [, max_ray_distance] mesh { } ... [smooth] } */
mesh_camera
  : "mesh_camera" "{" arith opt_comma arith mesh_camera_reach mesh_camera_meshes "}"
      { $$ = ev.mesh_camera($3, @3, $5, @5, $6, $7, std::nullopt, LOC(@1), LOC(@8)); }
  | "mesh_camera" "{" arith opt_comma arith mesh_camera_reach mesh_camera_meshes "smooth" "}"
      { $$ = ev.mesh_camera($3, @3, $5, @5, $6, $7, LOC(@8), LOC(@1), LOC(@9)); }
  ;

mesh_camera_reach
  : %empty %prec OPT_EMPTY {}
  | opt_comma arith    { $$ = std::make_pair($2, @2); }
  ;

mesh_camera_meshes
  : %empty             {}
  | mesh_camera_meshes object { $$ = std::move($1); $$.emplace_back($2, LOC(@2)); }
  ;

/* ------------------------------------------------------ settings, extension */

global_items
  : %empty
  | global_items global_item
  ;

global_item
  : "assumed_gamma" expr { ev.set_assumed_gamma(ev.positive($2, @2, "assumed_gamma")); }
  | "max_trace_level" expr {
      /* POV-Ray's own range; it also bounds the integrators' recursion. */
      int level = ev.to_int($2, @2);
      if (level < 1 || level > 256) ev.error(@2.begin, "max_trace_level must lie in 1..256, got " + std::to_string(level));
      else ev.scene().global.max_trace_level = level;
    }
  | "ambient_light" colour { ev.scene().global.ambient_light = ev.to_color($2, @2).rgb; }
  | "adc_bailout" expr { ev.scene().global.adc_bailout = ev.to_float($2, @2); }
  | "charset" UNDECLARED_ID { ev.ignored(LOC(@1), "charset"); }
  | "mm_per_unit" expr { ev.ignored(LOC(@1), "mm_per_unit (subsurface scattering's scale)"); }
  | "number_of_waves" expr { ev.scene().global.number_of_waves = ev.to_int($2, @2); }
  | "noise_generator" expr { ev.scene().global.noise_generator = std::max(1, ev.noise_generator($2, @2)); }
  | "irid_wavelength" colour { ev.scene().global.irid_wavelength = ev.to_color($2, @2).rgb; }
  | "max_intersections" expr { ev.ignored(LOC(@1), "max_intersections"); }
  | "hf_gray_16" opt_bool { ev.ignored(LOC(@1), "hf_gray_16 (how POV-Ray writes height-field images)"); }
  ;

/* lancer extension: render_settings { integrator "path" { depth 8 } width 640
 * height 480 samples 64 seed 1 } */
render_items
  : %empty
  | render_items param_name expr { ev.render_setting($2, @2, $3, @3, {}); }
  | render_items param_name expr "{" param_items "}" { ev.render_setting($2, @2, $3, @3, $5); }
  ;

param_items
  : %empty             {}
  | param_items param_name expr { $$ = std::move($1); $$.push_back(ev.parameter_edit($2, $3, @3)); }
  ;

/* Parameter names are free words; a few common ones are POV keywords. */
param_name
  : UNDECLARED_ID      { $$ = $1.text; }
  | VALUE_ID           { $$ = $1.text; }
  | BUILTIN            { $$ = $1.text; }
  | "ambient"          { $$ = "ambient"; }
  | "jitter"           { $$ = "jitter"; }
  | "width"            { $$ = "width"; }
  | "adaptive"         { $$ = "adaptive"; }
  | "exponent"         { $$ = "exponent"; }
  | "radius"           { $$ = "radius"; }
  | "falloff"          { $$ = "falloff"; }
  | "gamma"            { $$ = "gamma"; }
  | "max_trace_level"  { $$ = "max_trace_level"; }
  | "adc_bailout"      { $$ = "adc_bailout"; }
  /* media's words, common as settings' names */
  | "samples"          { $$ = "samples"; }
  | "method"           { $$ = "method"; }
  | "ratio"            { $$ = "ratio"; }
  | "intervals"        { $$ = "intervals"; }
  | "density"          { $$ = "density"; }
  ;

%%

void lancer::parse::Parser::error(const location_type& where, const std::string& message) {
    ev.syntax_error(where, message);
}
