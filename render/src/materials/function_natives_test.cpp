// A pigment function called while a scene is parsed takes the
// noise_generator set so far, as POV-Ray's call does: the values POV-Ray 3.7
// prints (#debug, 12 digits) for a bozo pigment with the setting nowhere,
// before the function, between the function and the call, and after it.
#include <gtest/gtest.h>

#include <string>

#include "lancer/host/scene_compiler.h"
#include "lancer/parser.h"

namespace lancer {
namespace {

double value_while_parsing(const std::string& text) {
    const std::unique_ptr<sg::FunctionNatives> natives = make_parse_time_function_natives();
    ParseOptions options;
    options.function_natives = natives.get();
    const ParseResult result = parse_scene_string(text, "natives.pov", options);
    EXPECT_TRUE(result.ok());
    if (!result.ok() || result.scene->objects.empty()) return -1.0;
    return std::get<sg::Sphere>(result.scene->objects[0].shape).radius;
}

TEST(ParseTimeNatives, APigmentFunctionTakesTheNoiseGeneratorSetBeforeItsCall) {
    const std::string function =
        "#declare B = function { pigment { bozo color_map { [0 rgb 0] [1 rgb 1] } scale 0.3 } }\n";
    const std::string call = "sphere { 0, B(0.37, 0.61, 0).red }\n";
    const std::string setting = "global_settings { noise_generator 1 }\n";
    EXPECT_NEAR(value_while_parsing(function + call), 0.428791850805, 1e-11);
    EXPECT_NEAR(value_while_parsing(setting + function + call), 0.322923004627, 1e-11);
    EXPECT_NEAR(value_while_parsing(function + setting + call), 0.322923004627, 1e-11);
    EXPECT_NEAR(value_while_parsing(function + call + setting), 0.428791850805, 1e-11);
}

}  // namespace
}  // namespace lancer
