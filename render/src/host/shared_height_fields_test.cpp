// A height field (from a function or an image file) is made once while its
// shape is in use (traced while parsing, then rendered; placed twice), and
// made again for anything that could change it or once nobody holds it.
#include "host/shared_height_fields.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

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

TEST(SharedHeightFields, AFieldInUseIsMadeOnce) {
    const auto function = std::make_shared<const sg::Function>();
    Counted counted;
    const auto make = [&] { return counted(); };
    const sg::HeightField field = field_of(function);
    const auto first = shared_function_height_field(field, make);
    const auto second = shared_function_height_field(field, make);
    EXPECT_EQ(counted.made, 1);
    EXPECT_EQ(first.get(), second.get());
}

TEST(SharedHeightFields, WhatCouldChangeItMakesItAgain) {
    const auto function = std::make_shared<const sg::Function>();
    Counted counted;
    const auto make = [&] { return counted(); };
    const sg::HeightField field = field_of(function);
    const auto kept = shared_function_height_field(field, make);
    std::vector<std::shared_ptr<const Shape>> others;
    sg::HeightField other_generator = field;
    other_generator.function_noise_generator = 1;
    others.push_back(shared_function_height_field(other_generator, make));
    sg::HeightField changed = field;
    changed.function_width = 3;
    others.push_back(shared_function_height_field(changed, make));
    changed = field;
    changed.smooth = true;
    others.push_back(shared_function_height_field(changed, make));
    changed = field;
    changed.water_level = 0.25;
    others.push_back(shared_function_height_field(changed, make));
    // The same text in another function: nothing says it gives the same values.
    others.push_back(shared_function_height_field(field_of(std::make_shared<const sg::Function>()), make));
    EXPECT_EQ(counted.made, 6);
    for (const auto& other : others) EXPECT_NE(other.get(), kept.get());
}

TEST(SharedHeightFields, NothingIsKeptOnceReleased) {
    const auto function = std::make_shared<const sg::Function>();
    Counted counted;
    const auto make = [&] { return counted(); };
    const sg::HeightField field = field_of(function);
    std::weak_ptr<const Shape> first = shared_function_height_field(field, make);
    EXPECT_TRUE(first.expired());
    const auto second = shared_function_height_field(field, make);
    EXPECT_EQ(counted.made, 2);
}

// make() stands in for the image reader: the files here are not images,
// only their path and bytes count.
void write_file(const std::string& path, const std::string& bytes) {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << bytes;
}

sg::HeightField image_field(const std::string& path) {
    sg::HeightField field;
    field.path = path;
    return field;
}

TEST(SharedHeightFields, AnImageFieldInUseIsReadOnce) {
    const std::string path = (std::filesystem::temp_directory_path() / "lancer_shared_field_once.png").string();
    write_file(path, "first");
    Counted counted;
    const auto make = [&] { return counted(); };
    const auto first = shared_image_height_field(image_field(path), make);
    const auto second = shared_image_height_field(image_field(path), make);
    EXPECT_EQ(counted.made, 1);
    EXPECT_EQ(first.get(), second.get());
    std::filesystem::remove(path);
}

TEST(SharedHeightFields, AnotherFileGammaOrContentIsReadAgain) {
    const auto dir = std::filesystem::temp_directory_path();
    const std::string path = (dir / "lancer_shared_field_a.png").string();
    const std::string other = (dir / "lancer_shared_field_b.png").string();
    write_file(path, "first");
    write_file(other, "first");
    Counted counted;
    const auto make = [&] { return counted(); };
    const auto kept = shared_image_height_field(image_field(path), make);
    std::vector<std::shared_ptr<const Shape>> others;
    others.push_back(shared_image_height_field(image_field(other), make));
    sg::HeightField changed = image_field(path);
    changed.gamma = 2.2;
    others.push_back(shared_image_height_field(changed, make));
    changed = image_field(path);
    changed.smooth = true;
    others.push_back(shared_image_height_field(changed, make));
    // Rewritten while the first is in use: other bytes of the same length
    // (a scene that #writes its image again, on a clock too coarse to tell),
    // then a longer file.
    write_file(path, "fir5t");
    others.push_back(shared_image_height_field(image_field(path), make));
    write_file(path, "second, longer");
    others.push_back(shared_image_height_field(image_field(path), make));
    // A file that is not there: read afresh (the reader reports it).
    others.push_back(shared_image_height_field(image_field((dir / "lancer_shared_field_none.png").string()), make));
    EXPECT_EQ(counted.made, 7);
    for (const auto& shape : others) EXPECT_NE(shape.get(), kept.get());
    std::filesystem::remove(path);
    std::filesystem::remove(other);
}

TEST(SharedHeightFields, AFailedReadKeepsNothing) {
    const std::string path = (std::filesystem::temp_directory_path() / "lancer_shared_field_fails.png").string();
    write_file(path, "bytes");
    int calls = 0;
    const auto failing = [&]() -> std::shared_ptr<const Shape> {
        ++calls;
        throw std::runtime_error("unreadable");
    };
    EXPECT_THROW(shared_image_height_field(image_field(path), failing), std::runtime_error);
    EXPECT_THROW(shared_image_height_field(image_field(path), failing), std::runtime_error);
    EXPECT_EQ(calls, 2);
    std::filesystem::remove(path);
}

}  // namespace
}  // namespace lancer
