// The scene graph: what a scene file means, after every directive has run and
// every expression has been folded. The evaluator builds it as it parses (there
// is no AST); the host compiles it into a RenderScene (compile_scene,
// lancer/host/scene_compiler.h). It knows nothing of Embree or plugins.
//
// Conventions (POV-Ray's): left-handed, +y up, lengths in scene units,
// colours linear RGB. Every node carries the source location it came from so
// later stages can report errors where the user can act on them.
#pragma once

#include <array>
#include <cstdint>
#include <limits>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include <glm/glm.hpp>

#include "lancer/copy_on_write.h"
#include "lancer/function.h"
#include "lancer/on_demand.h"

namespace lancer::sg {

using Vec2 = glm::dvec2;
using Vec3 = glm::dvec3;
using Mat4 = glm::dmat4;  // column-major, acts on column vectors (GLM)

struct SourceLocation {
    std::shared_ptr<const std::string> file;  // path as the user named it
    int line = 0;                             // 1-based; 0 = unknown
    int column = 0;                           // 1-based
};

// A colour with POV-Ray's optional filter and transmit channels.
struct Color {
    Vec3 rgb{0.0};
    double filter = 0.0;    // fraction of light passing through, tinted by rgb
    double transmit = 0.0;  // fraction of light passing through untinted
};

}  // namespace lancer::sg

#include "lancer/scene_media.h"

namespace lancer::sg {

// ---------------------------------------------------------------- textures

enum class ImageFormat { Png, Jpeg, Exr, Hdr, Tga, Tiff, Gif, Bmp, Pnm, Iff, Unknown };

// An image_map's `filter N, v`, `transmit N, v` (one palette entry) or
// `filter all v`, `transmit all v` (every entry), in the order written:
// POV-Ray sets them on a colour-mapped image's palette, one after another.
struct PaletteSetting {
    bool transmit = false;  // else filter
    int index = -1;         // -1: all entries
    double value = 0.0;
    SourceLocation location;
};

// POV-Ray map_type values: 0 planar, 1 spherical, 2 cylindrical, 5 torus.
enum class MapType { Planar = 0, Spherical = 1, Cylindrical = 2, Torus = 5, UV = 100 };

struct ImageMap {
    std::string path;  // resolved to an existing file at evaluation time
    ImageFormat format = ImageFormat::Unknown;
    // POV-Ray's defaults: the planar projection and no interpolation. An
    // OBJ material's texture and uv_mapping take the surface's (u,v).
    MapType map_type = MapType::Planar;
    int interpolate = 0;                           // 0 none, 2 bilinear, 4 normalized distance (POV)
    bool once = false;                             // no repeat outside [0,1]^2
    std::vector<PaletteSetting> palette_settings;  // and `filter all`, `transmit all`
    bool srgb = true;                              // 8-bit formats are sRGB-encoded; EXR/HDR are linear
    // POV decodes an image_map's colours; a bump_map's or image_pattern's
    // values are read as stored unless `gamma` is given.
    bool gamma_given = false;
    // The scene's assumed_gamma when the image was named: POV-Ray shades
    // in that working space, so a decoded colour is encoded into it
    // (v^(1/G)); 1: linear, nothing to do.
    double working_gamma = 1.0;
    SourceLocation location;
    bool use_alpha = false;  // image_pattern: the value is the alpha (or red)
    SourceLocation use_alpha_location;
    // Written inside a bump_map block (POV allows them there as well as
    // after it); an image_map refuses them.
    std::optional<double> bump_size;
    std::optional<bool> use_color;
    SourceLocation bump_item_location;
};

// ---------------------------------------------------------------- patterns

// One step of POV-Ray's warp { ... } list, or a transform written between
// warps. A pattern's point passes through its steps from the last written
// to the first (a step written later acts on everything written before
// it), then reaches the pattern function.
struct Warp {
    enum class Kind { Transform, Turbulence, Repeat, BlackHole, Cylindrical, Spherical, Toroidal, Planar };
    Kind kind = Kind::Transform;
    Mat4 inner_from_outer{1.0};  // Transform: maps the point into the space the earlier steps see
    // Turbulence (and black_hole's jitter): POV's turbulence vector, octaves, omega, lambda.
    Vec3 turbulence{0.0};
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
    // Repeat: the cell vector (one axis), offset and flip per cell; BlackHole's repeat too.
    Vec3 repeat{0.0};
    Vec3 offset{0.0};
    Vec3 flip{0.0};
    // BlackHole
    Vec3 center{0.0};
    double radius = 1.0;
    double falloff = 2.0;
    double strength = 1.0;
    bool inverse = false;
    // Cylindrical, Spherical, Toroidal: the axis; dist_exp; toroidal's major radius.
    Vec3 orientation{0.0, 0.0, 1.0};
    double dist_exp = 0.0;
    double major_radius = 1.0;
    // Planar: the plane's normal and distance.
    Vec3 normal{0.0, 0.0, 1.0};
    double distance = 0.0;
    SourceLocation location;
};

// POV-Ray's wave types: how a pattern's value (after frequency and phase)
// becomes the index into its map.
enum class WaveType { Ramp, Triangle, Sine, Scallop, Cubic, Poly };

struct Pigment;
struct Object;

// A POV-Ray pattern: a function from a point (and, for a few, the surface
// or the ray) to a value, usually in [0, 1], that maps index. The same
// struct serves pigments, normals, textures and (later) densities.
struct Pattern {
    enum class Kind {
        Agate,
        Aoi,
        Boxed,
        Brick,
        Bozo,
        Bumps,
        Cells,
        Checker,
        Crackle,
        Cubic,
        Cylindrical,
        DensityFile,
        Dents,
        Facets,
        Mandel,
        Julia,
        Magnet,
        Function,
        Gradient,
        Granite,
        Hexagon,
        ImagePattern,
        Leopard,
        Marble,
        Object,
        Onion,
        Pavement,
        PigmentPattern,
        Planar,
        Quilted,
        Radial,
        Ripples,
        Slope,
        Spherical,
        Spiral1,
        Spiral2,
        Spotted,
        Square,
        Tiling,
        Triangular,
        Waves,
        Wood,
        Wrinkles
    };
    Kind kind = Kind::Gradient;

    // Classic turbulence (`turbulence` outside warp { }): applied to the
    // point just before the pattern function (marble, wood, agate and the
    // other patterns POV gives their own turbulence use it inside).
    Vec3 turbulence{0.0};
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
    double frequency = 1.0;
    double phase = 0.0;
    WaveType wave = WaveType::Ramp;
    double wave_exponent = 1.0;  // poly_wave's exponent
    int noise_generator = 0;     // 1, 2, 3; 0: global_settings' (POV's default 2)
    bool uv_mapping = false;     // the point is the surface's (u, v, 0), not the hit's position
    std::vector<Warp> warps;     // in the order written
    // Transforms written after the last warp (all of them when there is
    // none), and the moves of the object the pattern is attached to.
    Mat4 pattern_from_object{1.0};

    // Parameters of particular patterns (POV-Ray's defaults).
    Vec3 vector{1.0, 0.0, 0.0};  // gradient's direction; slope's direction <0,1,0>
    double agate_turbulence = 1.0;
    Vec3 brick_size{8.0, 3.0, 4.5};
    double mortar = 0.5;
    Vec3 crackle_form{-1.0, 1.0, 0.0};
    double crackle_metric = 2.0;
    double crackle_offset = 0.0;
    bool crackle_solid = false;
    double facets_size = 0.1;  // facets size (with coords 0)
    double facets_coords = 0.0;
    int fractal_iterations = 0;  // mandel/julia/magnet: required
    Vec2 julia_parameter{0.0};
    int fractal_exponent = 2;
    int magnet_type = 1;
    int exterior_type = 1;
    double exterior_factor = 1.0;
    int interior_type = 0;
    double interior_factor = 1.0;
    double quilted_control0 = 1.0;
    double quilted_control1 = 1.0;
    int spiral_arms = 1;
    int tiling_type = 1;
    int pavement_sides = 3, pavement_tiles = 1, pavement_number = 1, pavement_exterior = 0, pavement_interior = 0,
        pavement_form = 0;
    // slope { direction [, lo_slope, hi_slope] [altitude <a> [, lo, hi]] }
    Vec3 slope_altitude{0.0};
    Vec2 slope_range{0.0, 1.0};
    Vec2 altitude_range{0.0, 1.0};
    bool slope_has_altitude = false;
    std::shared_ptr<const Object> object;    // object pattern
    std::shared_ptr<const Pigment> pigment;  // pigment_pattern
    std::shared_ptr<const ImageMap> image;   // image_pattern
    FunctionRef function;                    // function { … } as a pattern
    std::string file;                        // density_file df3
    int file_interpolate = 0;
    SourceLocation location;
    // Appended for the pattern evaluator (POV's defaults):
    int number_of_waves = 10;     // global_settings number_of_waves (ripples, waves)
    bool magnet_julia = false;    // magnet N julia <c>, I (true) or magnet N mandel I
    bool slope_point_at = false;  // slope { point_at <p> ... }: vector is the point
    double facets_metric = 2.0;   // facets metric
    // density_file df3: the voxels (x fastest, then y, then z), each
    // divided by its type's maximum as POV does, and the grid's size; read
    // by the parser from `file` (0 voxels: the pattern is 0 everywhere).
    std::shared_ptr<const std::vector<double>> density_voxels;
    glm::ivec3 density_size{0};
};
using PatternRef = std::shared_ptr<const Pattern>;

// POV's color_map: colours at increasing values, blended linearly between
// (filter and transmit too); below the first and above the last the end
// colours hold.
struct ColorMapEntry {
    double value = 0.0;
    Color color;
};
using ColorMap = std::vector<ColorMapEntry>;
using ColorMapRef = std::shared_ptr<const ColorMap>;

using PigmentRef = std::shared_ptr<const Pigment>;
// The weight of an average's map entry written without one; POV gives it
// 1, and any other map refuses it.
inline constexpr double kUnweighted = -std::numeric_limits<double>::infinity();

struct PigmentMapEntry {
    double value = 0.0;
    PigmentRef pigment;
};

struct Pigment {
    // Solid: one colour. Image: image_map. Patterned: a pattern through a colour map, a pigment map, or (block
    // patterns: checker, hexagon, brick, square, triangular, cubic) a list of
    // colours or pigments. Average: the mean of pigment_map's pigments,
    // weighted by their values.
    enum class Kind { Solid, Image, Patterned, Average };
    Kind kind = Kind::Solid;
    Color color;               // Solid; POV default pigment is black
    OnDemand<ImageMap> image;  // Image
    // Patterned: exactly one of color_map, pigment_map, block_pigments
    // holds the pattern's values (the parser fills POV's default map when
    // the scene gives none). A solid pigment keeps none until one is
    // written: the moves it meets until then are pattern_from_object's
    // below, which a pattern made later starts from (the parser's
    // pigment_pattern_of).
    OnDemand<Pattern> pattern;
    ColorMapRef color_map;
    std::vector<PigmentMapEntry> pigment_map;  // also Average's list
    std::vector<PigmentRef> block_pigments;    // block patterns' list, in order
    // Every move the pigment met (scale/rotate/translate written inside the
    // pigment or texture, and its object's): maps object space to pigment
    // space. The renderer reads only the pattern's own, which warps and
    // uv_mapping may make differ; a solid pigment keeps its moves here
    // alone until a pattern is made from them.
    Mat4 pattern_from_object{1.0};
    SourceLocation location;
};

// POV's `checker A, B`, as the parser builds it.
inline Pigment checker_pigment(const Vec3& first, const Vec3& second) {
    Pigment pigment;
    pigment.kind = Pigment::Kind::Patterned;
    pigment.pattern->kind = Pattern::Kind::Checker;
    for (const Vec3& rgb : {first, second}) {
        auto block = std::make_shared<Pigment>();
        block->color.rgb = rgb;
        pigment.block_pigments.push_back(block);
    }
    return pigment;
}

// POV's normal { }: perturbs the shading normal. A pattern that POV gives
// a normal of its own (bumps, dents, ripples, waves, wrinkles, quilted,
// facets) perturbs by it; any other pattern by the slope of its value
// (through slope_map when given) over `accuracy`. normal_map blends the
// perturbed normals of several normals by the pattern's value;
// block patterns pick one of block_normals.
struct Normal;
using NormalRef = std::shared_ptr<const Normal>;
struct NormalMapEntry {
    double value = 0.0;
    NormalRef normal;
};
struct SlopeMapEntry {
    double value = 0.0;
    double height = 0.0;
    double slope = 0.0;
};
struct Normal {
    enum class Kind { Patterned, BumpMap, Average };
    Kind kind = Kind::Patterned;
    OnDemand<Pattern> pattern;
    double bump_size = 0.5;  // POV's amount
    double accuracy = 0.02;
    std::vector<SlopeMapEntry> slope_map;
    std::vector<NormalMapEntry> normal_map;  // also Average's list
    std::vector<NormalRef> block_normals;
    ImageMap bump_map;  // BumpMap
    // POV-Ray 3.7's default, measured against its renders: the grey of the
    // colour; `use_index` reads a colour-mapped file's palette indices.
    bool bump_map_use_color = true;
    SourceLocation location;
};

struct Reflection {
    Vec3 min{0.0};          // reflectance at normal incidence ...
    Vec3 max{0.0};          // ... and at grazing incidence
    double falloff = 1.0;   // POV's falloff exponent
    bool fresnel = false;   // use the interior's ior instead of falloff
    double exponent = 1.0;  // as written: POV raises the reflected colour to 1 / exponent
    double metallic = 0.0;
};

// Finish defaults are POV-Ray 3.7's (texture.cpp:Create_Finish).
struct Finish {
    Vec3 ambient{0.1};
    Vec3 emission{0.0};  // radiance emitted = emission * pigment colour
    double diffuse = 0.6;
    double brilliance = 1.0;
    double specular = 0.0;  // peak of the specular highlight (POV's meaning)
    double roughness = 0.05;
    double phong = 0.0;  // peak of the Phong highlight
    double phong_size = 40.0;
    double metallic = 0.0;
    double diffuse_back = 0.0;  // POV's `diffuse a, b`: light arriving from behind the surface
    double crand = 0.0;         // POV's grain: a random share taken from the diffuse light
    // POV's irid { amount thickness t turbulence f }: thin-film tint of the
    // light the surface reflects.
    double irid = 0.0;
    double irid_thickness = 0.0;
    double irid_turbulence = 0.0;
    Reflection reflection;
    bool conserve_energy = false;  // transmitted light scaled by 1 - reflection
    // `diffuse albedo`, `phong albedo`, `specular albedo`: the value was the
    // reflected share; the parser rescales it to POV's peak once the whole
    // finish is read and clears these.
    bool diffuse_albedo = false;
    bool phong_albedo = false;
    bool specular_albedo = false;
    SourceLocation location;
};

struct Interior {
    double ior = 1.0;
    // POV's fade: light travelling a distance d inside is multiplied by
    // fade_color + (1 - fade_color) / (1 + (d / fade_distance)^fade_power),
    // or exp(-(1 - fade_color) d / fade_distance) when fade_power >= 1000.
    // fade_distance 0: no fade.
    double fade_distance = 0.0;
    double fade_power = 0.0;
    Vec3 fade_color{0.0};
    // POV's fake caustics: shadows through the object brighten where the
    // shadow ray meets its surface head on (0: none; POV's range 0..1).
    double caustics = 0.0;
    // POV's media in the interior; seen only when the object is `hollow`,
    // as in POV-Ray (scene_media.h).
    std::vector<Media> media;
    SourceLocation location;
};

// A texture in POV terms: pigment + normal + finish (+ the object's
// interior, which POV keeps separately but every integrator needs at the
// same hit). A texture may instead be patterned (POV's texture_map, or a
// block pattern's list of textures), and may carry layers: textures
// written after it on the same object or declaration, each on top of the
// one before.
struct Material;
using MaterialRef = std::shared_ptr<const Material>;
struct TextureMapEntry {
    double value = 0.0;
    MaterialRef texture;
};
struct Material {
    Pigment pigment;
    NormalRef normal;  // null: the surface's own normal
    // Shared with the texture they came from until written (most objects
    // keep the default texture's).
    CopyOnWrite<Finish> finish;
    CopyOnWrite<Interior> interior;
    // An interior { } was written for it (on the object, or in its
    // material { }): else, as in POV-Ray, the object takes its group's.
    bool has_interior = false;
    // Patterned: the pattern whose value picks among texture_map's entries
    // (blended between two) or block_textures (one per block).
    OnDemand<Pattern> pattern;  // empty: not patterned
    std::vector<TextureMapEntry> texture_map;
    std::vector<MaterialRef> block_textures;
    std::vector<MaterialRef> layers_above;  // bottom to top
    // POV's interior_texture: what the surface shows where a ray meets it
    // from inside (against its normal), in the same space as the rest; its
    // own interior is unused (the object's is this material's).
    MaterialRef interior_texture;
    bool average = false;     // texture { average texture_map { … } }: the entries weighted
    bool uv_mapping = false;  // POV's texture { uv_mapping … }: every pattern of it at (u, v, 0)
    std::string name;         // the #declare'd name, if any, for summaries and errors
    SourceLocation location;
};

// ------------------------------------------------------------------ shapes

struct Sphere {
    Vec3 center{0.0};
    double radius = 1.0;
};

// Points p with dot(p, normal) = distance (POV's plane { normal, distance }).
struct Plane {
    Vec3 normal{0.0, 1.0, 0.0};
    double distance = 0.0;
};

struct Box {
    Vec3 corner1{-1.0};
    Vec3 corner2{1.0};
};

// POV's cone { base, base_radius, cap, cap_radius [open] }; a cylinder is
// one with equal radii.
struct Cone {
    Vec3 base{0.0};
    Vec3 cap{0.0, 1.0, 0.0};
    double base_radius = 1.0;
    double cap_radius = 1.0;
    bool open = false;  // no end discs
};

// POV's torus { major, minor }: about the y axis, in the plane y = 0.
struct Torus {
    double major_radius = 1.0;
    double minor_radius = 0.25;
};

// POV's quadric { <A,B,C>, <D,E,F>, <G,H,I>, J }: A x^2 + B y^2 + C z^2 +
// D xy + E xz + F yz + G x + H y + I z + J = 0, inside where it is <= 0.
struct Quadric {
    Vec3 square_terms{1.0};
    Vec3 mixed_terms{0.0};  // xy, xz, yz
    Vec3 linear_terms{0.0};
    double constant = -1.0;
};

// POV's polygon { n, points }: flat loops, filled even-odd; a loop closes
// where a point repeats its first point.
struct Polygon {
    std::vector<Vec3> points;
};

// POV's poly { order, <coefficients> }, cubic and quartic: the
// coefficients of x^i y^j z^k in POV's order (i from `order` down, then j,
// then k), inside where the polynomial is negative.
struct Polynomial {
    int order = 2;
    std::vector<double> coefficients;
};

// POV's superellipsoid { <e, n> }: within the unit box,
// (|x|^(2/e) + |y|^(2/e))^(e/n) + |z|^(2/n) <= 1.
struct Superellipsoid {
    double east_west = 1.0;    // e
    double north_south = 1.0;  // n
};

// POV's blob: where the summed field of the components equals the
// threshold (inside where it is above). A component of strength s and
// radius R adds s (1 - r^2/R^2)^2 within distance R of its centre (sphere)
// or of its segment (cylinder, from center to apex).
struct Blob {
    struct Component {
        enum class Kind { Sphere, Cylinder };
        Kind kind = Kind::Sphere;
        Vec3 center{0.0};
        Vec3 apex{0.0};
        double radius = 1.0;
        double strength = 1.0;
        Mat4 blob_from_component{1.0};  // the component's own transforms
        SourceLocation location;
    };
    double threshold = 1.0;
    std::vector<Component> components;
};

// POV's prism: closed spline curves through `points` (x, z) swept along y
// from height1 to height2 (height1 <= height2), straight or, with a conic
// sweep, scaled by y towards the origin; `open` drops the caps.
struct Prism {
    enum class Spline { Linear, Quadratic, Cubic, Bezier };
    Spline spline = Spline::Linear;
    bool conic = false;
    double height1 = 0.0, height2 = 1.0;
    std::vector<Vec2> points;
    bool open = false;
};

// POV's lathe: the open spline curve through `points` <r, y> turned about
// the y axis.
struct Lathe {
    Prism::Spline spline = Prism::Spline::Linear;
    std::vector<Vec2> points;
};

// POV's text: the closed outlines of a string's glyphs (in the x-y plane,
// one unit per em, laid out as POV-Ray lays them), extruded along +z from
// 0 to `thickness`. Each segment is a cubic Bezier p[0..3], or a straight
// line from p[0] to p[3].
struct Text {
    struct Segment {
        Vec2 p[4];
        bool line = false;
    };
    std::vector<Segment> segments;
    double thickness = 1.0;
    std::string font;  // the file, as found
};

// POV's sor: a surface of revolution about y whose squared radius is a
// cubic in y between consecutive points (the first and last are control
// points only), closed by discs unless open.
struct Sor {
    std::vector<Vec2> points;  // <r, y>
    bool open = false;
};

// POV's ovus { bottom_radius, top_radius }: an egg about the y axis, a
// sphere of bottom_radius at the origin joined smoothly to a sphere of
// top_radius above it.
struct Ovus {
    double bottom_radius = 1.0;
    double top_radius = 0.5;
};

// POV's sphere_sweep: the surface a sphere sweeps moving along a spline
// through the modelling spheres (centre, radius), both interpolated.
struct SphereSweep {
    enum class Spline { Linear, BSpline, CubicSpline };
    struct Sphere {
        Vec3 center{0.0};
        double radius = 1.0;
    };
    Spline spline = Spline::Linear;
    std::vector<Sphere> spheres;
    double tolerance = 1e-6;  // POV's depth tolerance
};

// POV's bicubic_patch: a Bezier patch over 4 x 4 control points (row by
// row as written), subdivided into 2^u_steps x 2^v_steps flat pieces.
struct BicubicPatch {
    int type = -1;  // required: 0 or 1
    double flatness = 0.0;
    int u_steps = 0, v_steps = 0;
    // Always 16; on the heap, so that every object (all sharing the shape
    // variant's size) does not carry 384 bytes for the rare patch.
    std::vector<Vec3> points = std::vector<Vec3>(16);
    Vec2 uv_corners[4] = {{0.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}, {0.0, 1.0}};
};

// POV's julia_fractal: the 3-D slice of a 4-D Julia set of z -> f(z) + c,
// c = julia, in quaternion or hypercomplex algebra.
struct JuliaFractal {
    enum class Algebra { Quaternion, Hypercomplex };
    enum class Function {
        Sqr,
        Cube,
        Exp,
        Reciprocal,
        Sin,
        Asin,
        Sinh,
        Asinh,
        Cos,
        Acos,
        Cosh,
        Acosh,
        Tan,
        Atan,
        Tanh,
        Atanh,
        Ln,
        Pwr
    };
    glm::dvec4 julia{0.0};
    Algebra algebra = Algebra::Quaternion;
    Function function = Function::Sqr;
    Vec2 power{0.0};  // pwr(x, y)
    int max_iteration = 20;
    double precision = 20.0;       // as written, at least 1
    glm::dvec4 slice{0, 0, 0, 1};  // unit, t component not 0
    double slice_distance = 0.0;
};

// POV's isosurface: where function(x, y, z) = threshold inside its
// container (a box or a sphere); the solid is where the function is below
// the threshold. The function's roots are found by subdividing the ray's
// chord while max_gradient (a Lipschitz bound) allows a root between two
// samples, down to intervals of `accuracy`.
// What an isosurface or a parametric is drawn inside (contained_by).
struct FunctionContainer {
    enum class Container { Box, Sphere };
    Container container = Container::Box;
    Vec3 box_corner1{-1.0}, box_corner2{1.0};  // ordered per axis
    Vec3 sphere_center{0.0};
    double sphere_radius = 1.0;
};

struct Isosurface : FunctionContainer {
    FunctionRef function;
    double threshold = 0.0;
    double accuracy = 0.001;
    double max_gradient = 1.1;
    // evaluate P0, P1, P2: POV's adaptive max_gradient (a minimum, a
    // growth factor and an attenuation).
    bool evaluate = false;
    Vec3 evaluate_parameters{0.0};
    bool open = false;  // the container's surface is not part of the object
    int max_trace = 1;  // crossings looked for per ray; all_intersections: 10
    SourceLocation location;
};

// POV's parametric: the surface (x(u, v), y(u, v), z(u, v)) for (u, v) in
// [uv_min, uv_max], drawn only inside its container. POV-Ray finds a ray's
// nearest crossing by halving the (u, v) rectangle while the box that
// max_gradient bounds each coordinate in may still meet the ray, down to
// `accuracy`. The functions read u and v (x and y). No inside: a patch.
struct Parametric : FunctionContainer {
    std::array<FunctionRef, 3> functions;
    Vec2 uv_min{0.0}, uv_max{1.0};  // ordered per coordinate
    double accuracy = 0.001;
    double max_gradient = 1.0;
    // precompute DEPTH, x, y, z: the coordinates whose bounds are computed
    // before rendering for the first DEPTH levels of halving (bit 0 x,
    // bit 1 y, bit 2 z).
    int precompute_depth = 0;
    int precompute_axes = 0;
    SourceLocation location;
};

// POV's height_field: an image's values as heights over the unit square
// (x across the image, z along it), in the box <0,0,0> .. <1,1,1>.
struct HeightField {
    std::string path;     // the file found
    std::string written;  // as the scene wrote it, for messages
    double gamma = 0.0;   // 0: none given
    bool premultiplied = false;
    bool smooth = false;
    double water_level = 0.0;
    SourceLocation location;  // of the file name (or of the function)
    // POV's `function W, H { … }` instead of a file: the function's values
    // at x = column / (W - 1), y = row / (H - 1), z = 0 as a 16-bit image.
    FunctionRef function;
    int function_width = 0, function_height = 0;
    // global_settings' noise_generator where the height field was written:
    // POV-Ray makes the function's image there, so a noise_generator set
    // later changes neither trace() nor the render.
    int function_noise_generator = 2;
};

// POV's disc { center, normal, radius [, hole_radius] }.
struct Disc {
    Vec3 center{0.0};
    Vec3 normal{0.0, 1.0, 0.0};  // unit
    double radius = 1.0;
    double hole_radius = 0.0;
};

// Indexed triangles. `triangle`, `smooth_triangle`, `mesh`, `mesh2` and
// `obj_mesh` all produce one; a mesh reused through `object { Name }` is the
// same shared_ptr, so the renderer can build it once and instance it.
struct TriangleMesh {
    struct Face {
        int position[3];
        int normal[3] = {-1, -1, -1};  // -1: flat shading
        int uv[3] = {-1, -1, -1};      // -1: barycentric (u,v)
        int material = -1;             // index into materials; -1: the object's
    };
    std::vector<Vec3> positions;
    std::vector<Vec3> normals;
    std::vector<Vec2> uvs;
    std::vector<Face> faces;
    std::vector<MaterialRef> materials;  // per-face textures, MTL materials
    std::string source;                  // OBJ path, when loaded from a file
    // POV's inside_vector: the mesh is a solid (for CSG) whose inside is
    // where a ray along this vector crosses it an odd number of times.
    std::optional<Vec3> inside_vector;
};
using MeshRef = std::shared_ptr<const TriangleMesh>;

struct Object;
// The children of a union, merge, intersection or difference (the kind
// says which; POV-Ray's CSG rules are in the renderer's csg.h).
struct Group {
    std::vector<Object> children;
};

struct Object {
    enum class Kind {
        Sphere,
        Plane,
        Box,
        Triangle,
        SmoothTriangle,
        Mesh,
        Mesh2,
        ObjMesh,
        Union,
        Cylinder,
        Cone,
        Torus,
        Disc,
        Quadric,
        Polygon,
        Poly,
        Cubic,
        Quartic,
        Superellipsoid,
        Blob,
        Prism,
        Lathe,
        Text,
        Sor,
        Merge,
        Intersection,
        Difference,
        Ovus,
        SphereSweep,
        BicubicPatch,
        JuliaFractal,
        HeightField,
        Isosurface,
        Parametric
    };
    Kind kind = Kind::Sphere;
    std::variant<Sphere, Plane, Box, MeshRef, Group, Cone, Torus, Disc, Quadric, Polygon, Polynomial, Superellipsoid,
                 Blob, Prism, Lathe, Text, Sor, Ovus, SphereSweep, BicubicPatch, JuliaFractal, HeightField, Isosurface,
                 Parametric>
        shape;
    // POV's inverse: inside and outside swapped (what CSG and clipped_by see).
    bool inverse = false;
    // POV's clipped_by: only the parts of this object's surface inside every
    // one of these are kept (in this object's space).
    std::vector<Object> clipped_by;
    // POV's bounded_by (in this object's space): a ray that neither meets
    // nor starts in every one of these misses the object (Ray_In_Bound), so
    // a bound smaller than the object cuts it where the rays miss it.
    std::vector<Object> bounded_by;
    // Maps this object's own space to its parent's space (the group it is
    // in, or the world). Children of a union compose with their parent's.
    Mat4 parent_from_object{1.0};
    MaterialRef material;            // null: inherit from the enclosing group, else default
    bool inherits_material = false;  // `material` came from an enclosing group
    bool no_shadow = false;
    bool hollow = false;
    // POV's double_illuminate, when the scene sets it (on or off). On a
    // group it is set on every object inside, whatever they said: the
    // outermost setting wins.
    std::optional<bool> double_illuminate;
    // POV's no_image and no_reflection: camera rays (and what they refract
    // into), or mirror rays, pass through the object; it still casts
    // shadows. On a group they reach everything inside it.
    bool no_image = false;
    bool no_reflection = false;
    // POV's light_group: an index into SceneGraph::light_groups (children
    // without one of their own are in it too); -1: none.
    int light_group = -1;
    std::string name;  // the #declare'd name it was instanced from, if any
    SourceLocation location;
};

// ------------------------------------------------------------------ lights

// POV's light_group { objects lights [global_lights on] }: its lights
// light only its objects, which the scene's other lights reach only with
// global_lights on (off by default).
struct LightGroup {
    bool global_lights = false;
};
inline constexpr int kMaxLightGroups = 32767;  // a scene's; more is an error

struct Object;

struct Light {
    // Point and Directional are POV-Ray's lights (a Point may be a
    // spotlight, and either may carry POV's area_light). AreaRectangle and
    // AreaSphere are lancer's physical lamps (extensions `area_rectangle`,
    // `area_sphere`): surfaces that rays hit and that emit.
    enum class Kind { Point, Directional, AreaRectangle, AreaSphere };
    Kind kind = Kind::Point;
    // POV's light_group it belongs to (SceneGraph::light_groups): it lights
    // only that group's objects. -1: a global light, which lights every
    // object outside the groups and those of groups with global_lights.
    int light_group = -1;
    Vec3 position{0.0};            // world space, transforms applied
    Vec3 color{1.0};               // see docs/scene-language.md for the unit
    Vec3 point_at{0.0, 0.0, 1.0};  // Directional: light travels position -> point_at
    // POV's area_light, or the rectangle of an AreaRectangle: position
    // ± axis1/2 ± axis2/2.
    Vec3 axis1{0.0};
    Vec3 axis2{0.0};
    // POV's area_light: lit from `position`, its shadows sampled over an
    // samples1 × samples2 grid spanning the rectangle (corners included).
    bool area_light = false;
    int samples1 = 1;
    int samples2 = 1;
    bool jitter = false;
    int adaptive = 100;  // POV's default: every grid point is traced
    bool circular = false;
    bool orient = false;
    bool area_illumination = false;  // each grid point lights with its own direction
    double radius = 0.0;             // AreaSphere
    // POV's fade: attenuation 2 / (1 + (d / fade_distance)^fade_power) when
    // fade_distance > 0, d^-fade_power when fade_distance is 0; otherwise a
    // POV light does not fall off (lancer's physical lamps do: inverse square).
    double fade_distance = 0.0;
    double fade_power = 0.0;
    bool parallel = false;
    bool shadowless = false;         // POV's shadowless: lights what faces it, through anything
    bool media_interaction = true;   // participating media scatter this light
    bool media_attenuation = false;  // the atmosphere dims it on its way to surfaces (classic integrators)
    // POV's spotlight: a point light whose light narrows to a cone about
    // point_at. Angles in degrees from the axis (POV's defaults); tightness
    // raises the cone's cosine to a power.
    bool spotlight = false;
    double spot_radius = 30.0;   // full light inside
    double spot_falloff = 45.0;  // none outside; a smooth step between
    double tightness = 0.0;
    bool spot_parameters_given = false;  // radius, falloff or tightness was written
    // POV's cylinder light: a parallel light (Directional) confined to a
    // beam about the line from position towards point_at; spot_radius and
    // spot_falloff are then distances from that axis (POV's defaults 0.75
    // and 1), and tightness sharpens the beam.
    bool cylinder = false;
    // POV's looks_like: an object drawn where the light is (moved to the
    // light's position, then by the block's later transforms), which
    // casts no shadow. The parser adds it to the scene's objects.
    std::shared_ptr<const Object> looks_like;
    // POV's projected_through: the light reaches a point only along rays
    // that pass through this object (not drawn; moved by the block's
    // transforms as the light is).
    std::shared_ptr<const Object> projected_through;
    SourceLocation location;
};

// ------------------------------------------------------------------ camera

// POV's mesh_camera { rays_per_pixel, distribution_type [, max_ray_distance]
// mesh { } ... [smooth] }: every ray leaves a face of a mesh along its
// normal (docs/scene-language.md says which face each pixel takes).
struct MeshCamera {
    struct Mesh {
        MeshRef mesh;
        Mat4 world_from_mesh{1.0};  // the mesh's own transforms
        // POV's mesh { } drops triangles whose corners are collinear and
        // mesh2 keeps them: face numbers count the faces POV keeps.
        bool drops_degenerate_faces = false;
        SourceLocation location;
    };
    int rays_per_pixel = 1;
    int distribution = 0;           // POV's distribution types 0 to 3
    double max_ray_distance = 0.0;  // a camera ray's reach; 0: unlimited
    bool smooth = false;            // type 3: the vertex normals interpolated
    std::vector<Mesh> meshes;       // at least one
};

// Resolved as POV-Ray 3.7 does (pov-3.7-semantics.md §1): the vectors
// below are the ones POV's CreateCameraRay reads, after look_at, angle and
// the block's transforms. For the perspective camera the ray through
// normalized image coordinates (x0, y0) in [-0.5, 0.5] is
// normalize(direction + x0 * right + y0 * up) from location; the other
// projections are in docs/scene-language.md (render/src/camera/ has them).
struct Camera {
    enum class Projection {
        Perspective,
        Orthographic,
        Fisheye,
        UltraWideAngle,
        Omnimax,
        Panoramic,
        Cylinder1,  // cylinder 1: vertical axis, rays from the location
        Cylinder2,  // cylinder 2: horizontal axis, rays from the location
        Cylinder3,  // cylinder 3: vertical axis, rays from a vertical line
        Cylinder4,  // cylinder 4: horizontal axis, rays from a horizontal line
        Spherical,
        Mesh,  // mesh_camera: rays from mesh faces (`mesh` below)
    };
    Projection projection = Projection::Perspective;
    Vec3 location{0.0};
    Vec3 direction{0.0, 0.0, 1.0};
    Vec3 right{1.33, 0.0, 0.0};
    Vec3 up{0.0, 1.0, 0.0};
    // POV's `angle` as the non-perspective projections read it, in degrees
    // (fisheye: the whole field; ultra_wide_angle and cylinders: across the
    // image). POV's default when none is given is 90.
    double angle = 90.0;
    // The spherical camera's `angle H, V`: the longitude and latitude spans.
    double horizontal_angle = 360.0, vertical_angle = 180.0;
    // Focal blur: on when aperture != 0 and blur_samples > 0. A point at
    // focal_distance along `direction` (measured in units of |direction|,
    // as POV-Ray does) stays sharp.
    double aperture = 0.0;
    int blur_samples = 0;      // the most samples per pixel POV takes
    int blur_samples_min = 0;  // POV's least before its confidence test may stop
    double confidence = 0.9;
    double variance = 1.0 / 10000.0;
    double focal_distance = 1.0;
    // POV's bokeh { pigment { } }: the aperture's shape and transmission,
    // the pigment's grey over x, y in [0, 1] (z = 0) spanning the square
    // lens; null: POV's round lens, evenly open.
    std::shared_ptr<const Pigment> bokeh;
    // normal { } on a camera: each ray's direction is bent as a surface
    // normal would be, the pattern read at (x0, y0, 0) of the image plane.
    NormalRef normal;
    // The mesh camera's meshes and settings (Projection::Mesh). POV reads
    // location.z as how far a ray starts off its face, along the normal,
    // and a direction.z below zero as rays turned against the normal.
    std::shared_ptr<const MeshCamera> mesh;
    SourceLocation location_in_source;

    bool focal_blur() const { return aperture != 0.0 && blur_samples > 0; }
};

// ---------------------------------------------------------------- settings

struct GlobalSettings {
    double assumed_gamma = 1.0;
    Vec3 irid_wavelength{0.70, 0.52, 0.48};  // POV's default
    // False in POV-Ray's legacy mode (a scene whose #version is below 3.7,
    // or which has none, and which sets no assumed_gamma): image files
    // receive the working values unchanged, as POV-Ray 3.6 wrote them.
    bool gamma_correction = true;
    // The #version in force when parsing ended; 3.62 when the scene has no
    // #version (POV-Ray's EffectiveLanguageVersion).
    double language_version = 3.7;
    int max_trace_level = 5;
    Vec3 ambient_light{1.0};
    double adc_bailout = 1.0 / 255.0;
    int noise_generator = 2;   // POV's default for patterns that do not choose
    int number_of_waves = 10;  // ripples and waves: how many wave sources
};

// One integrator parameter as written in the scene, kept typed and located
// so the plugin host can reject a parameter the plugin does not declare.
struct ParameterValue {
    std::variant<double, Vec3, std::string, bool> value;
    SourceLocation location;
};

// lancer extension: `render_settings { ... }`. Unset fields take the command
// line's value, then lancer's default.
struct RenderSettings {
    std::optional<std::string> integrator;
    std::map<std::string, ParameterValue> parameters;
    std::optional<int> width;
    std::optional<int> height;
    std::optional<int> samples;
    std::optional<std::uint64_t> seed;
    SourceLocation location;
};

// POV's sky_sphere: pigments seen in the direction of every ray that
// escapes, layered with the last written on top, over the background.
struct SkySphere {
    std::vector<Pigment> pigments;
    Mat4 transform{1.0};  // world from sky: the pigments are read at its inverse applied to the direction
    Vec3 emission{1.0};
    SourceLocation location;
};

// POV's fog: the view fades into `color` with distance, evenly (type 1) or
// thicker near the ground (type 2: density 1 below fog_offset along `up`,
// 1/(1+h^2) at h fog_alts above it), broken up by turbulence.
struct Fog {
    enum class Type { Constant = 1, Ground = 2 };
    Type type = Type::Constant;
    double distance = 0.0;  // where the fog lets 1/e through; 0: no fog
    Color color;            // filter tints what it lets through; transmit is its least transmittance
    double offset = 0.0;    // fog_offset
    double alt = 0.0;       // fog_alt
    Vec3 up{0.0, 1.0, 0.0};
    bool turbulent = false;  // turbulence, octaves, omega or lambda given
    Vec3 turbulence{0.0};
    double turb_depth = 0.5;
    int octaves = 6;
    double omega = 0.5;
    double lambda = 2.0;
    SourceLocation location;
};

// POV's rainbow: a colour map laid around the antisolar direction, from
// `angle - width/2` to `angle + width/2` degrees off it, over an arc.
struct Rainbow {
    double angle = 0.0;     // degrees
    double width = 0.0;     // degrees; 0: no rainbow
    double distance = 1e7;  // POV's MAX_DISTANCE
    double jitter = 0.0;
    Vec3 direction{0.0};  // the antisolar direction (not zero)
    Vec3 up{0.0, 1.0, 0.0};
    // POV's half-angles in radians once given; POV keeps 180 (as radians:
    // every direction) when neither is.
    double arc_angle = 180.0;
    double falloff_angle = 180.0;
    bool arc_angle_given = false;
    bool falloff_angle_given = false;
    ColorMapRef color_map;
    SourceLocation location;
};

struct SceneGraph {
    std::optional<Camera> camera;  // absent: POV's default camera
    std::vector<Light> lights;
    std::vector<Object> objects;
    std::vector<LightGroup> light_groups;
    Vec3 background{0.0};
    // The background statement's transmit: what an alpha channel sees
    // through where rays escape (POV's +UA), and the share of its colour
    // taken away. Empty: no background statement, POV's transparent black.
    std::optional<double> background_transmit;
    std::optional<SkySphere> sky_sphere;  // the last one written
    std::vector<Fog> fogs;                // every one applies
    std::vector<Rainbow> rainbows;        // every one applies
    std::vector<Media> atmosphere;        // scene-level media: fill the open, hollow objects included
    GlobalSettings global;
    RenderSettings render;
    std::string main_file;  // the scene file's path
    // Every file the scene read (includes, images, OBJ and MTL files), as
    // found, in reading order: what a render must never overwrite.
    std::vector<std::string> input_files;
};

}  // namespace lancer::sg
