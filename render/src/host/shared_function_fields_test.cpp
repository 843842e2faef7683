// A function height field is made once while its shape is in use (traced
// while parsing, then rendered), and made again for anything that could
// change it or once nobody holds it.
#include "host/shared_function_fields.h"

#include <gtest/gtest.h>

#include "geometry/height_field.h"

namespace lancer {
namespace {

struct Counted {
    int made = 0;
    std::shared_ptr<const Shape> operator()() {
        ++made;
        return make_height_field_shape(HeightFieldGrid{2, 2, std::vector<float>(4, 0.5f)}, false, 0.0);
    }
};

sg::HeightField field_of(const sg::FunctionRef& function) {
    sg::HeightField field;
    field.function = function;
    field.function_width = field.function_height = 2;
    return field;
}

TEST(SharedFunctionFields, AFieldInUseIsMadeOnce) {
    const auto function = std::make_shared<const sg::Function>();
    Counted counted;
    const auto make = [&] { return counted(); };
    const sg::HeightField field = field_of(function);
    const auto first = shared_function_height_field(field, 2, make);
    const auto second = shared_function_height_field(field, 2, make);
    EXPECT_EQ(counted.made, 1);
    EXPECT_EQ(first.get(), second.get());
}

TEST(SharedFunctionFields, WhatCouldChangeItMakesItAgain) {
    const auto function = std::make_shared<const sg::Function>();
    Counted counted;
    const auto make = [&] { return counted(); };
    const sg::HeightField field = field_of(function);
    const auto kept = shared_function_height_field(field, 2, make);
    std::vector<std::shared_ptr<const Shape>> others;
    others.push_back(shared_function_height_field(field, 1, make));  // another noise generator
    sg::HeightField changed = field;
    changed.function_width = 3;
    others.push_back(shared_function_height_field(changed, 2, make));
    changed = field;
    changed.smooth = true;
    others.push_back(shared_function_height_field(changed, 2, make));
    changed = field;
    changed.water_level = 0.25;
    others.push_back(shared_function_height_field(changed, 2, make));
    // The same text in another function: nothing says it gives the same values.
    others.push_back(shared_function_height_field(field_of(std::make_shared<const sg::Function>()), 2, make));
    EXPECT_EQ(counted.made, 6);
    for (const auto& other : others) EXPECT_NE(other.get(), kept.get());
}

TEST(SharedFunctionFields, NothingIsKeptOnceReleased) {
    const auto function = std::make_shared<const sg::Function>();
    Counted counted;
    const auto make = [&] { return counted(); };
    const sg::HeightField field = field_of(function);
    std::weak_ptr<const Shape> first = shared_function_height_field(field, 2, make);
    EXPECT_TRUE(first.expired());
    const auto second = shared_function_height_field(field, 2, make);
    EXPECT_EQ(counted.made, 2);
}

}  // namespace
}  // namespace lancer
