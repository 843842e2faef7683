// sg::CopyOnWrite: copies share one value until one of them is written;
// reads of an empty one see the default.
#include "lancer/copy_on_write.h"

#include <string>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

struct Settings {
    int count = 7;
    std::vector<std::string> names;
};

TEST(CopyOnWrite, ReadingAnEmptyOneSeesTheDefaultAndMakesNothing) {
    const sg::CopyOnWrite<Settings> empty;
    EXPECT_FALSE(empty.has_value());
    EXPECT_EQ(empty->count, 7);
    EXPECT_TRUE((*empty).names.empty());
    EXPECT_FALSE(empty.has_value());
}

TEST(CopyOnWrite, CopiesShareUntilOneIsWritten) {
    sg::CopyOnWrite<Settings> original;
    original->names.push_back("first");
    sg::CopyOnWrite<Settings> copy = original;
    EXPECT_TRUE(copy.shares_with(original));
    EXPECT_EQ(std::as_const(copy)->names.size(), 1u);
    EXPECT_TRUE(copy.shares_with(original));  // a const read keeps sharing

    copy->names.push_back("second");
    EXPECT_FALSE(copy.shares_with(original));
    EXPECT_EQ(original->names.size(), 1u);
    EXPECT_EQ(copy->names.size(), 2u);

    // Writing the original leaves a copy made before unchanged too.
    sg::CopyOnWrite<Settings> before = original;
    original->count = 3;
    EXPECT_EQ(before->count, 7);
    EXPECT_EQ(original->count, 3);
}

TEST(CopyOnWrite, AssigningAValueGivesThisCopyItsOwn) {
    sg::CopyOnWrite<Settings> a;
    a->count = 1;
    sg::CopyOnWrite<Settings> b = a;
    b = Settings{5, {}};
    EXPECT_EQ(a->count, 1);
    EXPECT_EQ(b->count, 5);
}

// Objects that keep the default texture share its finish and interior; one
// whose finish is written has its own, and the others do not see it.
TEST(CopyOnWrite, ObjectsShareTheDefaultTexturesFinishUntilOneWritesIt) {
    auto scene = test::parse_ok(
        "sphere { 0, 1 pigment { rgb 1 } }\n"
        "sphere { 0, 1 pigment { rgb 0.5 } }\n"
        "sphere { 0, 1 pigment { rgb 0.5 } finish { phong 1 } interior { ior 1.5 } }\n"
        "#default { finish { ambient 0 } }\n"
        "sphere { 0, 1 pigment { rgb 0.2 } }\n");
    ASSERT_EQ(scene.objects.size(), 4u);
    const sg::Material& first = *scene.objects[0].material;
    const sg::Material& second = *scene.objects[1].material;
    const sg::Material& own = *scene.objects[2].material;
    const sg::Material& after_default = *scene.objects[3].material;
    EXPECT_TRUE(first.finish.shares_with(second.finish));
    EXPECT_TRUE(first.interior.shares_with(second.interior));
    EXPECT_FALSE(own.finish.shares_with(first.finish));
    EXPECT_DOUBLE_EQ(own.finish->phong, 1.0);
    EXPECT_DOUBLE_EQ(first.finish->phong, 0.0);
    EXPECT_DOUBLE_EQ(own.interior->ior, 1.5);
    EXPECT_DOUBLE_EQ(first.interior->ior, 1.0);
    // The later #default changes what comes after it only.
    EXPECT_EQ(after_default.finish->ambient, sg::Vec3(0.0));
    EXPECT_EQ(first.finish->ambient, sg::Vec3(0.1));
}

}  // namespace
}  // namespace lancer
