// spline { … } and its calls, against the values povray's #debug prints for
// the same splines (linear, quadratic, cubic_spline, natural_spline, a
// kind given in the call, float entries, copies), and the located errors.
#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

// The spheres' centres, where the scenes below put each call's value.
std::vector<sg::Vec3> centres(const sg::SceneGraph& scene) {
    std::vector<sg::Vec3> result;
    for (const auto& object : scene.objects) result.push_back(std::get<sg::Sphere>(object.shape).center);
    return result;
}

void expect_near(const sg::Vec3& got, const sg::Vec3& want) {
    for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 5e-7) << k;
}

constexpr const char* kSplines = R"(
    #declare S = spline { linear_spline -1, <0,0,0>, 0, <1,2,0>, 1.5, <2,0,1>, 3, <4,4,4>, 4.5, <0,1,2> }
    #declare Q = spline { S quadratic_spline }
    #declare C = spline { S cubic_spline }
    #declare N = spline { S natural_spline }
)";

TEST(ParserSplines, EveryKindGivesPovRaysValues) {
    const auto scene = parse_ok(std::string(kSplines) + R"(
        #for (T, -0.8, 2.7, 0.7) sphere { S(T), 1 } sphere { Q(T), 1 } sphere { C(T), 1 } sphere { N(T), 1 } #end)");
    const auto v = centres(scene);
    ASSERT_EQ(v.size(), 24u);  // T = -0.8, -0.1, 0.6, 1.3, 2.0, 2.7
    // T = -0.8
    expect_near(v[0], {0.2, 0.4, 0.0});
    expect_near(v[1], {0.221333, 0.613333, -0.042667});
    expect_near(v[2], {1.0, 2.0, 0.0});  // cubic_spline holds its second point before it
    expect_near(v[3], {0.232464, 0.596638, -0.003710});
    // T = 0.6
    expect_near(v[8], {1.4, 1.2, 0.4});
    expect_near(v[9], {1.472, 1.92, 0.256});
    expect_near(v[10], {1.388, 1.272, 0.232});
    expect_near(v[11], {1.288, 1.184, 0.096});
    // T = 2.7
    expect_near(v[20], {3.6, 3.2, 3.4});
    expect_near(v[21], {3.52, 2.72, 3.24});
    expect_near(v[22], {3.968, 3.552, 3.688});
    expect_near(v[23], {3.939826, 3.382261, 3.657391});
}

TEST(ParserSplines, EndsHoldAndACallMayChooseTheKind) {
    const auto scene = parse_ok(std::string(kSplines) + R"(
        sphere { S(-1.5), 1 } sphere { S(4.8), 1 } sphere { C(4.1), 1 }
        sphere { S(-0.8, natural_spline), 1 } sphere { N(-0.8, linear_spline), 1 }
        #declare F = spline { 0, 1, 1, 3, 2, 2 }
        sphere { F(0.6), 1 } sphere { F(-1), 1 }
        #declare One = spline { 5, <1, 2, 3> }
        sphere { One(-100), 1 })");
    const auto v = centres(scene);
    expect_near(v[0], {0, 0, 0});
    expect_near(v[1], {0, 1, 2});
    expect_near(v[2], {4, 4, 4});  // cubic_spline holds its next-to-last point after it
    expect_near(v[3], {0.232464, 0.596638, -0.003710});
    expect_near(v[4], {0.2, 0.4, 0.0});
    EXPECT_NEAR(v[5].x, 2.2, 1e-12);  // a float entry stands for every component
    EXPECT_NEAR(v[5].y, 2.2, 1e-12);
    EXPECT_NEAR(v[6].x, 1.0, 1e-12);
    expect_near(v[7], {1, 2, 3});
}

TEST(ParserSplines, LaterEntriesAtTheSameTimeReplaceEarlierOnes) {
    const auto scene = parse_ok(R"(
        #declare S = spline { linear_spline 1, <1,1,1>, 0, <0,0,0>, 1, <3,3,3> }
        sphere { S(0.5), 1 })");
    expect_near(centres(scene)[0], {1.5, 1.5, 1.5});
}

TEST(ParserSplines, LocatedErrors) {
    const Diagnostic odd = first_error("#declare S = spline { 0, <1,1,1>, 1 }");
    EXPECT_NE(odd.message.find("no value"), std::string::npos) << odd.message;
    const Diagnostic empty = first_error("#declare S = spline { linear_spline }");
    EXPECT_NE(empty.message.find("missing"), std::string::npos) << empty.message;
    EXPECT_EQ(empty.location.column, 37);
    const Diagnostic time = first_error("#declare S = spline { <1,2>, <1,1,1> }");
    EXPECT_NE(time.message.find("float time"), std::string::npos) << time.message;
    EXPECT_EQ(time.location.column, 23);
}

}  // namespace
}  // namespace lancer

namespace lancer {
namespace {

TEST(ParserSplines, TrailingCommaAndSplinesAsMacroArguments) {
    // POV's splinefollow.pov: a comma after the last entry, and a spline
    // handed to transforms.inc's Spline_Trans.
    auto scene = test::parse_ok(R"(
        #include "transforms.inc"
        #declare S = spline { cubic_spline -1, <0,0,0>, 0, <1,0,0>, 1, <2,1,0>, 2, <3,1,1>, 3, <4,0,0>, }
        sphere { 0, 1 Spline_Trans(S, 0.5, y, 0.1, 0.5) })");
    ASSERT_EQ(scene.objects.size(), 1u);
    const sg::Mat4& m = scene.objects[0].parent_from_object;
    EXPECT_NEAR(m[3][0], 1.5, 0.2);  // placed on the spline between <1,0,0> and <2,1,0>
}

TEST(ParserDeclare, AValueAMacroEndsIsStoredWhereTheDirectiveStands) {
    // #local M = Macro(…) inside another macro: the value ends with the
    // inner macro's text; M belongs to the outer macro (transforms.inc's
    // Spline_Trans relies on it), with or without the ';'.
    auto scene = test::parse_ok(R"(
        #macro Shift(V) transform { translate V } #end
        #macro Place(V)
          #local M = Shift(V)
          #local N = Shift(2 * V);
          transform { transform M transform N }
        #end
        sphere { 0, 1 Place(<1, 0, 0>) })");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_DOUBLE_EQ(scene.objects[0].parent_from_object[3][0], 3.0);
}

}  // namespace
}  // namespace lancer
