// pigment_is_opaque: what lets a blocked shadow ray be black at once.
#include "materials/opaque_pigment.h"

#include <memory>

#include <gtest/gtest.h>

namespace lancer {
namespace {

sg::PigmentRef solid(double filter, double transmit) {
    auto pigment = std::make_shared<sg::Pigment>();
    pigment->color.rgb = sg::Vec3(0.5);
    pigment->color.filter = filter;
    pigment->color.transmit = transmit;
    return pigment;
}

TEST(OpaquePigment, ASolidColourIsOpaqueWithoutFilterOrTransmit) {
    EXPECT_TRUE(pigment_is_opaque(*solid(0.0, 0.0)));
    EXPECT_FALSE(pigment_is_opaque(*solid(0.3, 0.0)));
    EXPECT_FALSE(pigment_is_opaque(*solid(0.0, 0.3)));
    EXPECT_FALSE(pigment_is_opaque(*solid(0.0, -99.0)));  // POV's `transmit -99` lets through negative light
}

TEST(OpaquePigment, APatternIsOpaqueWhenEveryColourItCanTakeIs) {
    sg::Pigment checker = sg::checker_pigment(sg::Vec3(1.0), sg::Vec3(0.0));
    EXPECT_TRUE(pigment_is_opaque(checker));
    checker.block_pigments[1] = solid(0.0, 0.5);
    EXPECT_FALSE(pigment_is_opaque(checker));

    sg::Pigment mapped;
    mapped.kind = sg::Pigment::Kind::Patterned;
    auto map = std::make_shared<sg::ColorMap>();
    map->push_back({0.0, sg::Color{sg::Vec3(1.0), 0.0, 0.0}});
    map->push_back({1.0, sg::Color{sg::Vec3(0.0), 0.0, 0.0}});
    mapped.color_map = map;
    EXPECT_TRUE(pigment_is_opaque(mapped));
    map->push_back({1.0, sg::Color{sg::Vec3(0.0), 1.0, 0.0}});
    EXPECT_FALSE(pigment_is_opaque(mapped));

    // Nested: a pigment_map whose entry holds a clear checker block.
    sg::Pigment outer;
    outer.kind = sg::Pigment::Kind::Average;
    outer.pigment_map.push_back({1.0, solid(0.0, 0.0)});
    EXPECT_TRUE(pigment_is_opaque(outer));
    outer.pigment_map.push_back({1.0, std::make_shared<sg::Pigment>(checker)});
    EXPECT_FALSE(pigment_is_opaque(outer));
}

TEST(OpaquePigment, ImagesAndPatternsWithoutValuesAreNotTakenForOpaque) {
    sg::Pigment image;
    image.kind = sg::Pigment::Kind::Image;
    EXPECT_FALSE(pigment_is_opaque(image));
    sg::Pigment bare;
    bare.kind = sg::Pigment::Kind::Patterned;
    EXPECT_FALSE(pigment_is_opaque(bare));
}

}  // namespace
}  // namespace lancer
