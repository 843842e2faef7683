// --safe (ParseOptions::safe): a scene reads files only from its own folder
// and the include path. Every escape is a located error that names the path
// the scene wrote and never shows a line of the file outside.
#include <filesystem>

#include <gtest/gtest.h>

#include "lancer/parser.h"
#include "run_command.h"
#include "temp_folder.h"

namespace lancer::test {

namespace {

namespace fs = std::filesystem;

// A secret outside the scene's folder; no diagnostic may contain it.
constexpr const char* kSecret = "TOP_SECRET_LINE";

struct SafeFixture : ::testing::Test {
    TempFolder temp;
    std::string outside;    // temp/outside/secret.inc, holds kSecret
    fs::path scene_folder;  // temp/scene

    void SetUp() override {
        outside =
            temp.write("outside/secret.inc", std::string("#declare ") + kSecret + " = 1;\n" + kSecret + " oops\n");
        temp.write("outside/secret.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        temp.write("outside/secret.mtl", std::string("newmtl ") + kSecret + "\nKd 1 0 0\n");
        temp.write("outside/secret.png", kSecret);
        temp.write("scene/inner/ok.inc", "#declare R = 1;\n");
        temp.write("scene/tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
        scene_folder = temp.path() / "scene";
    }

    ParseResult parse(const std::string& scene_text, bool safe = true) {
        std::string scene = temp.write("scene/scene.pov", scene_text);
        ParseOptions options;
        options.safe = safe;
        return parse_scene_file(scene, options);
    }
};

std::string all_text(const ParseResult& result) {
    std::string text;
    for (const auto& d : result.diagnostics) text += format_diagnostic(d);
    return text;
}

void expect_refused(const ParseResult& result, int line, int column) {
    ASSERT_FALSE(result.ok());
    std::string text = all_text(result);
    EXPECT_NE(text.find("refused by --safe"), std::string::npos) << text;
    EXPECT_EQ(text.find(kSecret), std::string::npos) << "outside content leaked:\n" << text;
    const Diagnostic& first = result.diagnostics.front();
    EXPECT_EQ(first.location.line, line) << text;
    EXPECT_EQ(first.location.column, column) << text;
    EXPECT_NE(first.location.file->find("scene.pov"), std::string::npos) << text;
}

}  // namespace

TEST_F(SafeFixture, IncludesInsideTheFolderAndTheStandardPathAreAllowed) {
    ParseResult result = parse(
        "#include \"colors.inc\"\n#include \"inner/ok.inc\"\nsphere { 0, R pigment { White } }\n"
        "obj_mesh { \"tri.obj\" }\n");
    EXPECT_TRUE(result.ok()) << all_text(result);
}

TEST_F(SafeFixture, AbsoluteIncludeOutsideIsRefused) {
    expect_refused(parse("sphere { 0, 1 }\n#include \"" + outside + "\"\n"), 2, 1);
}

TEST_F(SafeFixture, EtcPasswdIsRefusedWithoutEchoingIt) {
    ParseResult result = parse("#include \"/etc/passwd\"\n");
    expect_refused(result, 1, 1);
    EXPECT_EQ(all_text(result).find("root:"), std::string::npos) << all_text(result);
}

TEST_F(SafeFixture, DotDotEscapeIsRefused) {
    expect_refused(parse("#include \"../outside/secret.inc\"\n"), 1, 1);
    expect_refused(parse("#include \"inner/../../outside/secret.inc\"\n"), 1, 1);
}

TEST_F(SafeFixture, MissingFileOutsideIsRefusedToo) {
    // "refused", not "not found": the answer must not reveal what exists outside.
    expect_refused(parse("#include \"/no/such/file.inc\"\n"), 1, 1);
}

TEST_F(SafeFixture, SymlinkEscapingTheFolderIsRefused) {
    fs::create_symlink(outside, scene_folder / "link.inc");
    fs::create_directory_symlink(temp.path() / "outside", scene_folder / "linkdir");
    expect_refused(parse("#include \"link.inc\"\n"), 1, 1);
    expect_refused(parse("#include \"linkdir/secret.inc\"\n"), 1, 1);
}

TEST_F(SafeFixture, SymlinkInsideTheFolderIsAllowed) {
    fs::create_symlink(scene_folder / "inner/ok.inc", scene_folder / "alias.inc");
    ParseResult result = parse("#include \"alias.inc\"\nsphere { 0, R }\n");
    EXPECT_TRUE(result.ok()) << all_text(result);
}

TEST_F(SafeFixture, ObjOutsideIsRefused) {
    expect_refused(parse("sphere { 0, 1 }\nobj_mesh { \"../outside/secret.obj\" }\n"), 2, 12);
}

TEST_F(SafeFixture, MtlOutsideIsRefused) {
    temp.write("scene/escape.obj", "mtllib ../outside/secret.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_refused(parse("obj_mesh { \"escape.obj\" }\n"), 1, 12);
    temp.write("scene/escape2.obj",
               "mtllib " + (temp.path() / "outside/secret.mtl").string() + "\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_refused(parse("obj_mesh { \"escape2.obj\" }\n"), 1, 12);
}

TEST_F(SafeFixture, MtlTextureOutsideIsRefused) {
    temp.write("scene/tex.mtl", "newmtl m\nKd 1 1 1\nmap_Kd ../outside/secret.png\n");
    temp.write("scene/tex.obj", "mtllib tex.mtl\nusemtl m\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    expect_refused(parse("obj_mesh { \"tex.obj\" }\n"), 1, 12);
}

TEST_F(SafeFixture, ImageMapOutsideIsRefused) {
    expect_refused(parse("sphere { 0, 1 pigment { image_map { png \"../outside/secret.png\" } } }\n"), 1, 41);
}

TEST_F(SafeFixture, WithoutSafeTheSameScenesParse) {
    ParseResult result = parse("#include \"../outside/secret.inc\"\n", /*safe=*/false);
    // Not refused; it fails for the file's own syntax, and may quote it: it is trusted.
    EXPECT_EQ(all_text(result).find("refused"), std::string::npos) << all_text(result);
}

TEST_F(SafeFixture, CheckCommandTakesSafe) {
    std::string scene = temp.write("scene/scene.pov", "#include \"" + outside + "\"\n");
    CommandResult result = run_lancer("check --safe " + scene);
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("refused by --safe"), std::string::npos) << result.output;
    EXPECT_EQ(result.output.find(kSecret), std::string::npos) << result.output;
}

}  // namespace lancer::test
