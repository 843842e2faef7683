// lancer's whitted against POV-Ray 3.7's own renders of POV-valid scenes
// (tests/reference/pov/: each scene beside the PNG POV-Ray made of it, and
// render-references.sh, the command that made them). Both trace every
// pixel once through its centre at 160x120 and write 8-bit sRGB, so the
// images should agree to the code value: the lights (point, fade,
// shadowless, spot, cylinder, parallel, POV's area light with adaptive,
// circular, orient and area_illumination, looks_like, projected_through,
// a negative light),
// the finishes (peak phong and specular, metallic, brilliance, albedo,
// reflection metallic, exponent and fresnel, conserve_energy), gamma, and
// a pre-3.7 scene's legacy gamma and `version`, POV's sizing of
// orthographic views (also one looking straight down its sky), and the
// shapes: cylinder, cone, torus, disc, quadric, polygon, poly, cubic,
// quartic, superellipsoid, blob, prism, lathe, sor, text (POV's own fonts, from
// Debian's fonts-povray), ovus, sphere_sweep, bicubic_patch, julia_fractal,
// height_field (8- and 16-bit grey images), CSG (difference,
// intersection, merge, inverse, clipped_by, textures per child; in glass,
// refracting at every face a difference keeps), and the patterns (each on a
// flat tile showing the pigment itself: the geometric, block and noise
// patterns, wave types, warps, colour and pigment maps, average, the
// tilings 1 to 27 and pavements of squares, triangles and hexagons) and
// normals (own normals, slopes of values, slope_map, normal_map), layered
// and patterned textures, #default and interior fade, uv_mapping, and
// images (image_map's projections, image_pattern, bump_map) and the object
// pattern, irid and diffuse backside, user functions as patterns, and
// isosurfaces.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>

#include "image_compare.h"
#include "run_command.h"
#include "temp_folder.h"

namespace lancer {
namespace {

namespace fs = std::filesystem;

class PovReference : public ::testing::TestWithParam<const char*> {};

TEST_P(PovReference, WhittedMatchesPovRay) {
    const std::string name = GetParam();
    const std::string scene = test::source_path("tests/reference/pov/" + name + ".pov");
    const std::string reference = test::source_path("tests/reference/pov/" + name + ".png");
    test::TempFolder folder;
    const std::string output = (folder.path() / (name + ".png")).string();
    const test::CommandResult result =
        test::run_lancer("render '" + scene + "' -i whitted --width 160 --height 120 --spp 1 -q -o '" + output + "'");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const testing::Image render = testing::load_image(output);
    const testing::Image pov = testing::load_image(reference);
    // Measured when these references were made: ten scenes within one code
    // value of POV-Ray's, finishes.pov 0.0006 mean with 0.08 % of pixels
    // (glass edges, where one ray refracts differently) off by more than 0.1.
    constexpr double kMaxMeanDifference = 0.002;
    constexpr long kMaxPixelsOff = 160 * 120 / 200;  // 0.5 %
    fs::create_directories(test::binary_path("pov_reference_failures"));
    std::string message;
    EXPECT_TRUE(testing::images_match(render, pov, kMaxMeanDifference, 0.1, kMaxPixelsOff,
                                      test::binary_path("pov_reference_failures/" + name), &message))
        << message;
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovReference,
                         ::testing::Values("wall_point_light", "spotlights", "area_room", "area_circular",
                                           "cylinder_parallel", "looks_like_projected", "finishes", "gamma",
                                           "legacy_gamma", "area_illumination", "orthographic_down",
                                           "orthographic_default_size", "quadric_family", "csg_solids", "csg_glass",
                                           "polygons_polynomials", "superellipsoids", "blobs", "prisms", "lathes",
                                           "text", "sors", "ovus", "sphere_sweeps", "bicubic_patches", "julia_fractals",
                                           "height_fields", "patterns_geometric", "patterns_blocks", "patterns_noise",
                                           "patterns_warps", "patterns_tilings", "patterns_tilings_more", "normals",
                                           "textures", "uv_mapping", "csg_meshes", "images", "object_pattern",
                                           "irid_backside", "functions", "isosurfaces"),
                         [](const ::testing::TestParamInfo<const char*>& info) { return std::string(info.param); });

}  // namespace
}  // namespace lancer
