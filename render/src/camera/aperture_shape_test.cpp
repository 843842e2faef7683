// POV's bokeh pigment as a lens: points fall only where the pigment lets
// light through, in proportion to its grey (clamped to 1 as POV's
// acceptance test does), and a lens that lets nothing through is an error.
#include "camera/aperture_shape.h"

#include <gtest/gtest.h>

#include "lancer/scene_error.h"
#include "materials/point_pigment.h"

namespace lancer {
namespace {

std::unique_ptr<PointPigment> solid(double grey) {
    sg::Pigment pigment;
    pigment.color.rgb = sg::Vec3(grey);
    return make_point_pigment(pigment, MaterialBuild());
}

// gradient x: black below x = 0.5, `right` from there on.
std::unique_ptr<PointPigment> right_half_open(double right) {
    sg::Pigment pigment;
    pigment.kind = sg::Pigment::Kind::Patterned;
    pigment.pattern->kind = sg::Pattern::Kind::Gradient;
    auto entries = std::make_shared<std::vector<sg::ColorMapEntry>>();
    entries->push_back(sg::ColorMapEntry{0.5, sg::Color{}});
    sg::Color open;
    open.rgb = sg::Vec3(right);
    entries->push_back(sg::ColorMapEntry{0.5, open});
    pigment.color_map = entries;
    return make_point_pigment(pigment, MaterialBuild());
}

Vec2 grid_u(int i, int j, int n) {
    return Vec2((float(i) + 0.5f) / float(n), (float(j) + 0.5f) / float(n));
}

TEST(ApertureShape, AnEvenlyOpenLensMapsTheUnitSquareOntoItself) {
    // Grey 3 opens the lens no more than grey 1 does.
    for (const double grey : {1.0, 3.0}) {
        const ApertureShape shape(*solid(grey), sg::SourceLocation{});
        for (int j = 0; j < 16; ++j)
            for (int i = 0; i < 16; ++i) {
                const Vec2 u = grid_u(i, j, 16);
                const Vec2 p = shape.point(u);
                EXPECT_NEAR(p.x, u.x - 0.5f, 1e-5f);
                EXPECT_NEAR(p.y, u.y - 0.5f, 1e-5f);
            }
    }
}

TEST(ApertureShape, PointsFallOnlyWhereThePigmentIsOpen) {
    const ApertureShape shape(*right_half_open(0.7), sg::SourceLocation{});
    constexpr int n = 64;
    double mean_x = 0.0, mean_y = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) {
            const Vec2 p = shape.point(grid_u(i, j, n));
            ASSERT_GE(p.x, 0.0f);  // pigment x >= 0.5
            ASSERT_LE(p.x, 0.5f);
            ASSERT_GE(p.y, -0.5f);
            ASSERT_LE(p.y, 0.5f);
            mean_x += p.x;
            mean_y += p.y;
        }
    // Evenly over the open half.
    EXPECT_NEAR(mean_x / (n * n), 0.25, 1e-3);
    EXPECT_NEAR(mean_y / (n * n), 0.0, 1e-3);
}

TEST(ApertureShape, ABlackLensIsALocatedError) {
    sg::SourceLocation where;
    where.file = std::make_shared<const std::string>("lens.pov");
    where.line = 4;
    where.column = 9;
    try {
        ApertureShape shape(*solid(0.0), where);
        FAIL() << "a black bokeh was accepted";
    } catch (const SceneError& error) {
        EXPECT_EQ(error.location().line, 4);
        EXPECT_NE(std::string(error.what()).find("black"), std::string::npos);
    }
    EXPECT_THROW(ApertureShape(*solid(-1.0), where), SceneError);
}

}  // namespace
}  // namespace lancer
