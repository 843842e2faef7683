// POV-Ray 3.7's gamma (reference/pov-3.7-semantics.md section 9): the scene
// is shaded in the working space that assumed_gamma sets; the file receives
// its values decoded to linear and encoded as the format wants; srgb
// colours are decoded into the working space. Checked on a background,
// which passes through shading unchanged.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "lancer/host/image_io.h"
#include "lancer/host/rgb_image.h"
#include "run_command.h"
#include "temp_folder.h"

namespace lancer::test {
namespace {

// The linear value the written PNG holds at its centre (red channel).
float rendered_background(const std::string& global_settings, const std::string& background) {
    TempFolder folder;
    const std::string scene = folder.write("scene.pov", "#version 3.7;\nglobal_settings { " + global_settings +
                                                            " }\nbackground { color " + background + " }\n");
    const std::string image = (folder.path() / "out.png").string();
    const CommandResult result = run_lancer("render " + scene + " -o " + image + " --width 4 --height 4 -q");
    EXPECT_EQ(result.exit_code, 0) << result.output;
    return read_rgb_image(image).at(2, 2).r;
}

// The 8-bit code a linear value gets in a PNG.
int png_code(float linear) {
    return int(std::floor(linear_to_srgb(linear) * 255.0f + 0.5f));
}

TEST(Gamma, AssumedGammaOneWritesValuesAsLinear) {
    EXPECT_EQ(png_code(rendered_background("assumed_gamma 1.0", "rgb 0.5")), png_code(0.5f));  // 188
}

// POV-Ray writes rgb 0.5 under assumed_gamma 2.2 as the code of 0.5^2.2
// (128, display value 0.502), not of 0.5 (188).
TEST(Gamma, AssumedGammaDecodesTheWorkingSpace) {
    const float linear = rendered_background("assumed_gamma 2.2", "rgb 0.5");
    EXPECT_EQ(png_code(linear), 128);
    EXPECT_EQ(png_code(linear), png_code(float(std::pow(0.5, 2.2))));
}

// An srgb colour means the same display colour whatever the working space.
TEST(Gamma, SrgbColoursMeanOneDisplayColourInEveryWorkingSpace) {
    const int linear_space = png_code(rendered_background("assumed_gamma 1.0", "srgb <0.4, 0.4, 0.4>"));
    const int gamma_space = png_code(rendered_background("assumed_gamma 2.2", "srgb <0.4, 0.4, 0.4>"));
    EXPECT_EQ(linear_space, 102);  // 0.4 * 255
    EXPECT_EQ(gamma_space, linear_space);
}

}  // namespace
}  // namespace lancer::test
