// sg::OnDemand: empty until written, reads see the default, copies are deep.
#include "lancer/on_demand.h"

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace lancer {
namespace {

struct Settings {
    int count = 7;
    std::vector<std::string> names;
};

TEST(OnDemand, ReadingAnEmptyOneSeesTheDefaultAndMakesNothing) {
    const sg::OnDemand<Settings> empty;
    EXPECT_FALSE(empty.has_value());
    EXPECT_EQ(empty->count, 7);
    EXPECT_TRUE((*empty).names.empty());
    EXPECT_FALSE(empty.has_value());
}

TEST(OnDemand, WritingMakesItAndCopiesAreDeep) {
    sg::OnDemand<Settings> written;
    written->names.push_back("first");
    ASSERT_TRUE(written.has_value());
    sg::OnDemand<Settings> copy = written;
    copy->names.push_back("second");
    EXPECT_EQ(written->names.size(), 1u);
    EXPECT_EQ(copy->names.size(), 2u);

    sg::OnDemand<Settings> assigned;
    assigned = copy;
    copy->count = 1;
    EXPECT_EQ(assigned->count, 7);
    assigned = sg::OnDemand<Settings>();
    EXPECT_FALSE(assigned.has_value());

    sg::OnDemand<Settings> moved = std::move(copy);
    EXPECT_EQ(moved->count, 1);
    moved.reset();
    EXPECT_FALSE(moved.has_value());
    EXPECT_EQ(moved.emplace().count, 7);
    EXPECT_TRUE(moved.has_value());
}

TEST(OnDemand, AssigningAValueMakesIt) {
    sg::OnDemand<Settings> value;
    value = Settings{3, {"x"}};
    EXPECT_TRUE(value);
    EXPECT_EQ(value->count, 3);
}

}  // namespace
}  // namespace lancer
