// POV-Ray's user files (#fopen, #write, #read, #fclose) as POV-Ray 3.7
// reads and writes them (checked against povray's #debug of the same
// scenes), --safe's confinement of them, and the macro a declared value's
// missing ';' must not call early.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::contains;

namespace fs = std::filesystem;

class UserFileTest : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("lancer_user_files_" + std::to_string(::getpid()) + "_" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(m_dir / "scene");
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string path(const std::string& name) const { return (m_dir / name).string(); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(m_dir / name) << text;
        return path(name);
    }
    std::string read(const std::string& name) const {
        std::ifstream in(m_dir / name);
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
    }
    ParseResult parse(const std::string& text, bool safe = false) {
        ParseOptions options;
        options.safe = safe;
        return parse_scene_file(write("scene/scene.pov", text), options);
    }
    fs::path m_dir;
};

TEST_F(UserFileTest, WritesAsPovRayWrites) {
    // povray writes exactly these bytes for the same #write.
    const ParseResult result = parse("#fopen Out \"" + path("data.txt") +
                                     "\" write\n"
                                     "#write (Out, 1.5, \", \", <1, 2, 3>, \",\\\"hello\\\",\", -2e-7, \"\\n\")\n"
                                     "#fclose Out\n"
                                     "#ifdef (Out) #error \"Out is still defined\" #end\n");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(read("data.txt"), "1.5, <1,2,3> ,\"hello\",-2e-07\n");
}

// #write's binary items: each number after the type rounded, clamped to it
// and written in its byte order, up to the next comma ("300 -4" is one
// number, 296). The bytes POV-Ray 3.7 writes for the same line.
TEST_F(UserFileTest, WritesBinaryItemsAsPovRay) {
    const ParseResult result =
        parse("#fopen Out \"" + path("bin.dat") +
              "\" write\n"
              "#write (Out, uint8 65 300 -4, sint16be <258, -2>, \",\", uint16le 70000.7, sint32le -1.5, "
              "sint8 2.5 -2.5, sint32be 1e10, uint16be <1,2,3,4,5>, \"|\", 7)\n"
              "#fclose Out\n");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    const std::string expected(
        "\x41\xff\x01\x02\xff\xfe\x2c\xff\xff\xff\xff\xff\xff\x00\x7f\xff\xff\xff"
        "\x00\x01\x00\x02\x00\x03\x00\x04\x00\x05\x7c\x37",
        30);
    EXPECT_EQ(read("bin.dat"), expected);
    const ParseResult text = parse("#fopen F \"" + path("t.dat") + "\" write\n#write (F, uint8 \"a\")\n");
    EXPECT_TRUE(contains(test::all_diagnostics(text), "uint8 writes numbers and vectors"))
        << test::all_diagnostics(text);
    const ParseResult nothing = parse("#fopen F \"" + path("n.dat") + "\" write\n#write (F, sint8, 1)\n");
    EXPECT_TRUE(contains(test::all_diagnostics(nothing), "needs a number")) << test::all_diagnostics(nothing);
}

TEST_F(UserFileTest, AppendAddsToTheEnd) {
    write("log.txt", "first\n");
    const ParseResult result =
        parse("#fopen Log \"" + path("log.txt") + "\" append #write (Log, \"second\\n\") #fclose Log");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(read("log.txt"), "first\nsecond\n");
}

TEST_F(UserFileTest, ReadsEveryValueOnceThenUndefinesTheHandle) {
    write("scene/values.txt", "1.5, <1,2,3> ,\"hello\",-2e-07, < -1, +2 >,\n");
    const ParseResult counted = parse(R"(
        #fopen In "values.txt" read
        #declare N = 0;
        #declare Sum = 0;
        #while (defined(In))
          #read (In, V)
          #declare N = N + 1;
          #if (N = 1) #declare First = V; #end
          #if (N = 2) #declare Second = V; #end
          #if (N = 3) #declare Third = V; #end
          #if (N = 5) #declare Fifth = V; #end
        #end
        #fopen Again "values.txt" read
        #read (Again, A, B)
        #fclose Again
        sphere { Second + Fifth.x * x, N + First + A + B.y })");
    ASSERT_TRUE(counted.ok()) << test::all_diagnostics(counted);
    const auto& sphere = std::get<sg::Sphere>(counted.scene->objects.at(0).shape);
    // Five values: 1.5, <1,2,3>, "hello", -2e-7, <-1, 2>; N = 5 (no value twice).
    EXPECT_DOUBLE_EQ(sphere.radius, 5.0 + 1.5 + 1.5 + 2.0);
    EXPECT_EQ(sphere.center, sg::Vec3(0.0, 2.0, 3.0));
}

TEST_F(UserFileTest, LocatedErrors) {
    write("scene/bad.txt", "1, sphere");
    const ParseResult bad = parse("#fopen F \"bad.txt\" read\n#read (F, A, B)\n");
    ASSERT_FALSE(bad.ok());
    EXPECT_TRUE(contains(test::all_diagnostics(bad), "expected a float, vector or string"))
        << test::all_diagnostics(bad);
    const ParseResult missing = parse("#fopen F \"nowhere.txt\" read\n");
    ASSERT_FALSE(missing.ok());
    EXPECT_EQ(missing.diagnostics.front().location.line, 1);
    const ParseResult mode = parse("#fopen F \"x.txt\" rw\n");
    EXPECT_TRUE(contains(test::all_diagnostics(mode), "read, write or append"));
    const ParseResult wrong_way = parse("#fopen F \"" + path("w.txt") + "\" write\n#read (F, A)\n");
    EXPECT_TRUE(contains(test::all_diagnostics(wrong_way), "opened to write"));
    const ParseResult not_a_file = parse("#declare F = 1;\n#write (F, \"x\")\n");
    EXPECT_TRUE(contains(test::all_diagnostics(not_a_file), "opened with #fopen"));
    const ParseResult object = parse("#fopen F \"" + path("o.txt") + "\" write\n#write (F, sphere { 0, 1 })\n");
    EXPECT_TRUE(contains(test::all_diagnostics(object), "strings, floats and vectors"));
}

// #write writes in the current folder, where POV-Ray also looks for
// includes: strings.inc's Parse_String includes the file it has just
// written from the library's folder.
TEST_F(UserFileTest, AnIncludeFindsWhatTheSceneWroteInTheCurrentFolder) {
    fs::create_directories(m_dir / "lib" / "work");
    write("lib/parse_like.inc",
          "#macro Parse_Like(S) #fopen F \"made.tmp\" write #write (F, S) #fclose F #include \"made.tmp\" #end\n");
    const fs::path before = fs::current_path();
    fs::current_path(m_dir / "lib" / "work");
    ParseOptions options;
    options.include_path = {path("lib")};
    const ParseResult result = parse_scene_file(
        write("scene/scene.pov", "#include \"parse_like.inc\"\nParse_Like(\"sphere { 0, 2 }\")\n"), options);
    fs::current_path(before);
    EXPECT_TRUE(result.ok()) << test::all_diagnostics(result);
    ASSERT_TRUE(result.scene);
    EXPECT_EQ(result.scene->objects.size(), 1u);
    EXPECT_TRUE(fs::exists(m_dir / "lib" / "work" / "made.tmp"));
}

TEST_F(UserFileTest, SafeModeWritesOnlyInTheScenesFolder) {
    const ParseResult outside = parse("#fopen F \"" + path("escape.txt") + "\" write\n", true);
    ASSERT_FALSE(outside.ok());
    EXPECT_TRUE(contains(test::all_diagnostics(outside), "--safe"));
    EXPECT_FALSE(fs::exists(m_dir / "escape.txt"));
    const ParseResult inside =
        parse("#fopen F \"" + path("scene/kept.txt") + "\" write\n#write (F, \"ok\")\n#fclose F\n", true);
    ASSERT_TRUE(inside.ok()) << test::all_diagnostics(inside);
    EXPECT_EQ(read("scene/kept.txt"), "ok");
    const ParseResult read_outside = parse("#fopen F \"/etc/hostname\" read\n", true);
    EXPECT_FALSE(read_outside.ok());
}

TEST(UserFileDeclare, AMacroAfterADeclaredValueWithoutSemicolonRunsAfterTheDeclaration) {
    // POV-Ray's portfolio scenes: #declare Comment="" then HTMLgen(…, Comment).
    auto scene = test::parse_ok(R"(
        #macro Ball(R) sphere { 0, R } #end
        #macro Radius(S) strlen(S) + 1 #end
        #declare Text = "ab"
        Ball(Radius(Text))
        #declare Size = 2
        Ball(Size)
        #declare Total = 1 + Radius("abc");
        Ball(Total))");
    ASSERT_EQ(scene.objects.size(), 3u);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[0].shape).radius, 3.0);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[1].shape).radius, 2.0);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[2].shape).radius, 5.0);
}

}  // namespace
}  // namespace lancer
