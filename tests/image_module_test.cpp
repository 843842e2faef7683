// Whether `lancer` loads OpenImageIO (through liblancer_images.so) only when
// a command reads or writes an image that is not a PNG or a JPEG it reads. The dynamic
// loader lists what it maps when LD_DEBUG=libs is set (glibc).
#include <cstdlib>
#include <string>

#include <gtest/gtest.h>

#include "run_command.h"
#include "temp_folder.h"

namespace lancer::test {
namespace {

// Runs lancer with the loader's library trace on.
CommandResult run_traced(const std::string& arguments) {
    setenv("LD_DEBUG", "libs", 1);
    CommandResult result = run_lancer(arguments);
    unsetenv("LD_DEBUG");
    return result;
}

bool loaded_image_stack(const CommandResult& result) {
    return result.output.find("liblancer_images.so") != std::string::npos ||
           result.output.find("libOpenImageIO") != std::string::npos;
}

class ImageModule : public ::testing::Test {
  protected:
    void SetUp() override {
        m_scene = m_folder.write("ball.pov",
                                 "camera { location <0, 0, -4> look_at 0 }\n"
                                 "light_source { <3, 4, -5> rgb 1 }\n"
                                 "sphere { 0, 1 pigment { rgb <1, 0.5, 0.2> } }\n");
    }
    std::string out(const std::string& name) const { return (m_folder.path() / name).string(); }
    TempFolder m_folder;
    std::string m_scene;
};

TEST_F(ImageModule, CheckAndPngRenderOfASceneWithoutImagesDoNotLoadIt) {
    const CommandResult check = run_traced("check " + m_scene);
    ASSERT_EQ(check.exit_code, 0) << check.output;
    EXPECT_FALSE(loaded_image_stack(check)) << check.output;
    const CommandResult render = run_traced("render " + m_scene + " --width 16 --height 12 -q -o " + out("b.png"));
    ASSERT_EQ(render.exit_code, 0) << render.output;
    EXPECT_FALSE(loaded_image_stack(render));
    // The trace is on: the loader did report the libraries it mapped.
    EXPECT_NE(render.output.find("liblancer.so"), std::string::npos) << render.output;
}

TEST_F(ImageModule, ExrOutputLoadsIt) {
    const CommandResult render = run_traced("render " + m_scene + " --width 16 --height 12 -q -o " + out("b.exr"));
    ASSERT_EQ(render.exit_code, 0) << render.output;
    EXPECT_TRUE(loaded_image_stack(render));
}

// A PNG map is read with libpng (film/png_reader.h); another format
// through the module.
TEST_F(ImageModule, PngAndJpegImageMapsDoNotLoadItAnExrOneDoes) {
    for (const std::string format : {"png", "jpg", "exr"})
        ASSERT_EQ(run_lancer("render " + m_scene + " --width 4 --height 4 -q -o " + out("map." + format)).exit_code, 0);
    for (const std::string format : {"png", "jpg", "exr"}) {
        const std::string mapped = m_folder.write("mapped_" + format + ".pov",
                                                  "camera { location <0, 0, -4> look_at 0 }\n"
                                                  "plane { -z, 0 pigment { image_map { " +
                                                      (format == "jpg" ? std::string("jpeg") : format) + " \"" +
                                                      out("map." + format) + "\" } } finish { ambient 1 } }\n");
        const CommandResult render =
            run_traced("render " + mapped + " --width 16 --height 12 -q -o " + out("m_" + format + ".png"));
        ASSERT_EQ(render.exit_code, 0) << render.output;
        EXPECT_EQ(loaded_image_stack(render), format == "exr") << format;
    }
}

}  // namespace
}  // namespace lancer::test
