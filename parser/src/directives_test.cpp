// Directives: loops and macros producing objects, conditionals, #switch,
// and #include (nested, missing, cyclic) with temporary files.
#include <filesystem>
#include <fstream>

#include "lancer/scene_summary.h"
#include "parse_test_helpers.h"

namespace lancer {
namespace {

namespace fs = std::filesystem;
using test::parse_ok;

int sphere_count(const sg::SceneGraph& scene) {
    return summarize_scene(scene).objects_by_kind["sphere"];
}

// povray skips a '#' that no name follows (language/image_size.pov ends a
// look_at with one); '#' before a word that is no directive stays an error.
TEST(ParserDirectives, LoneHashIsSkipped) {
    auto scene = parse_ok("camera { location -5 * z look_at 0 # }\nsphere { 0, 1 # }");
    EXPECT_EQ(scene.objects.size(), 1u);
    EXPECT_NE(test::first_error("#sphere { 0, 1 }").message.find("unknown directive"), std::string::npos);
}

// POV's comma after a macro argument is optional; lancer drops it after an
// object, where nothing else can continue (incdemo/shapes.pov).
TEST(ParserDirectives, MacroArgumentAfterAnObjectNeedsNoComma) {
    auto scene = parse_ok(
        "#macro Place(O, V, S) object { O translate V scale S } #end\n"
        "Place(sphere { 0, 1 } -y, 2)\n"
        "Place(box { 0, 1 } <1, 2, 3>, 2)");
    ASSERT_EQ(scene.objects.size(), 2u);
    const sg::Vec3 centre = sg::Vec3(scene.objects[0].parent_from_object * glm::dvec4(0, 0, 0, 1));
    EXPECT_EQ(centre, sg::Vec3(0, -2, 0));
}

// A macro named right after a declared block waits until the block is
// declared, as POV reads it (incdemo/screen.pov passes the texture it has
// just declared).
TEST(ParserDirectives, MacroAfterADeclaredBlockSeesIt) {
    auto scene = parse_ok(
        "#macro M(T) sphere { 0, 1 texture { T } } #end\n"
        "#declare T = texture { pigment { rgb x } }\n"
        "M(T)\n"
        "#declare O = union { sphere { 0, 1 } }\n"
        "M(texture { pigment { rgb y } })");
    ASSERT_EQ(scene.objects.size(), 2u);
    EXPECT_EQ(scene.objects[0].material->pigment.color.rgb, sg::Vec3(1, 0, 0));
}

TEST(ParserDirectives, WhileLoopMakesObjects) {
    auto scene = parse_ok("#declare I = 0;\n#while (I < 10)\n  sphere { <I, 0, 0>, 0.1 }\n  #declare I = I + 1;\n#end");
    ASSERT_EQ(scene.objects.size(), 10u);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[9].shape).center.x, 9.0);
}

TEST(ParserDirectives, ForLoopsNestedInsideAUnion) {
    auto scene = parse_ok("union { #for (I, 1, 3) #for (J, 0, 4, 2) sphere { <I, J, 0>, 0.1 } #end #end translate z }");
    ASSERT_EQ(scene.objects.size(), 1u);
    EXPECT_EQ(std::get<sg::Group>(scene.objects[0].shape).children.size(), 9u);
}

TEST(ParserDirectives, DirectivesInsideBlocks) {
    auto scene = parse_ok(R"(
        #declare Shiny = true;
        sphere { 0, 1
            texture {
                pigment { rgb 1 }
                #if (Shiny) finish { phong 1 } #else finish { phong 0 } #end
            }
            #declare Offset = 2;
            translate x * Offset
        })");
    EXPECT_DOUBLE_EQ(scene.objects[0].material->finish->phong, 1.0);
    EXPECT_DOUBLE_EQ(scene.objects[0].parent_from_object[3][0], 2.0);
}

TEST(ParserDirectives, IfElseifIfdefIfndefUndef) {
    auto scene = parse_ok(R"(
        #declare A = 2;
        #if (A = 1) sphere { 0, 1 } #elseif (A = 2) sphere { 0, 2 } #else sphere { 0, 3 } #end
        #ifdef (A) sphere { 0, 4 } #end
        #undef A
        #ifndef (A) sphere { 0, 5 } #end
        #if (0) #if (1) sphere { 0, 6 } #end #else sphere { 0, 7 } #end)");
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[0].shape).radius, 2);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[2].shape).radius, 5);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[3].shape).radius, 7);
}

TEST(ParserDirectives, SwitchCaseRangeBreak) {
    auto scene = parse_ok(R"(
        #for (K, 0, 3)
          #switch (K)
            #case (0) sphere { 0, 10 } #break
            #range (1, 2) sphere { 0, 20 } #break
            #else sphere { 0, 30 }
          #end
        #end)");
    ASSERT_EQ(scene.objects.size(), 4u);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[0].shape).radius, 10);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[2].shape).radius, 20);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[3].shape).radius, 30);
}

TEST(ParserDirectives, MacrosProduceObjectsValuesAndModifiers) {
    auto scene = parse_ok(R"(
        #macro Ball(P, R) sphere { P, R } #end
        #macro Double(V) (V * 2) #end
        #macro Lift() translate y #end
        #macro Row(N) #local I = 0; #while (I < N) Ball(<I, 0, 0>, 0.5) #local I = I + 1; #end #end
        Ball(<1, 2, 3>, Double(0.25))
        sphere { 0, 1 Lift() }
        Row(3)
        #ifdef (I) sphere { 0, 99 } #end)");
    ASSERT_EQ(scene.objects.size(), 5u);  // I was local to Row
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(scene.objects[0].shape).radius, 0.5);
    EXPECT_DOUBLE_EQ(scene.objects[1].parent_from_object[3][1], 1.0);
}

// A macro whose value ends with its own ';' (`Q;` as its last words, as
// language/tracevines.pov's FindTmp): the #local that called it still
// declares its name where the directive stands, not in the macro's scope.
TEST(ParserDirectives, LocalTakesAValueAMacroEndsWithASemicolon) {
    auto scene = parse_ok(R"(
        #macro Pick(A) #local Q = A * 2; #if (A.x > 0) Q; #else <0, 0, 0>; #end #end
        #macro Twice(A) #local Q = A * 2; Q; #end
        #macro Use(A) #local Inner = Twice(A) sphere { Inner, 1 } #end
        #local N = Pick(<1, 2, 3>)
        #local M = Twice(<0, 1, 0>)
        sphere { N, 1 }
        sphere { M, 1 }
        Use(<3, 0, 0>)
        #ifdef (Q) sphere { 0, 99 } #end
        #ifdef (Inner) sphere { 0, 99 } #end)");
    ASSERT_EQ(scene.objects.size(), 3u);  // Q and Inner stayed in their macros
    EXPECT_EQ(std::get<sg::Sphere>(scene.objects[0].shape).center, sg::Vec3(2, 4, 6));
    EXPECT_EQ(std::get<sg::Sphere>(scene.objects[1].shape).center, sg::Vec3(0, 2, 0));
    EXPECT_EQ(std::get<sg::Sphere>(scene.objects[2].shape).center, sg::Vec3(6, 0, 0));
}

// POV-Ray passes an identifier (or an array element) given as a macro
// argument by reference: the macro reads the variable itself, and its
// #declare or #local of the parameter writes the variable. Anything else
// (an expression, a parenthesised identifier) is passed by value. The
// values are what Debian's povray 3.7 prints for the same text.
TEST(ParserDirectives, IdentifierArgumentsArePassedByReference) {
    auto scene = parse_ok(R"(
        #macro SetLocal(P) #local P = 5; #end
        #macro Increment(P) #declare P = P + 1; #end
        #macro ReadAfterChange(P) #declare B = 3; sphere { 0, P } #end
        #macro Outer() #local L = 1; SetLocal(L) sphere { 0, L } #end
        #macro Forward(Q) SetLocal(Q) #end
        #declare A = 1;
        SetLocal(A)
        sphere { 0, A }
        Increment(A)
        sphere { 0, A }
        #declare B = 1;
        ReadAfterChange(B)
        Outer()
        #declare Arr = array[2] {1, 2};
        Increment(Arr[1])
        sphere { 0, Arr[1] }
        #declare C = 1;
        Forward(C)
        sphere { 0, C }
        #declare D = 1;
        SetLocal((D))
        Increment(D + 0)
        sphere { 0, D })");
    std::vector<double> radii;
    for (const auto& object : scene.objects) radii.push_back(std::get<sg::Sphere>(object.shape).radius);
    EXPECT_EQ(radii, (std::vector<double>{5, 6, 3, 5, 3, 5, 1}));
}

// A macro takes whatever a #declare can hold: an interior, a media, a
// spline written in the call (advanced/mediasky.pov passes interior { }).
TEST(ParserDirectives, MacroArgumentsMayBeBlocks) {
    auto scene = parse_ok(R"(
        #declare M = media { emission 0.1 }
        #macro Shell(I) sphere { 0, 1 hollow interior { I } } #end
        #macro WithMedia(Md) sphere { 0, 1 hollow interior { media { Md } } } #end
        #macro At(Sp) sphere { Sp(0.5), 1 } #end
        Shell(interior { ior 1.5 media { emission 0.2 } })
        WithMedia(M)
        WithMedia(media { emission 0.3 })
        At(spline { linear_spline 0, <0, 0, 0> 1, <2, 4, 6> }))");
    ASSERT_EQ(scene.objects.size(), 4u);
    const sg::Interior& shell = *scene.objects[0].material->interior;
    EXPECT_DOUBLE_EQ(shell.ior, 1.5);
    ASSERT_EQ(shell.media.size(), 1u);
    EXPECT_DOUBLE_EQ(shell.media[0].emission.x, 0.2);
    EXPECT_DOUBLE_EQ(scene.objects[1].material->interior->media.at(0).emission.x, 0.1);
    EXPECT_DOUBLE_EQ(scene.objects[2].material->interior->media.at(0).emission.x, 0.3);
    EXPECT_EQ(std::get<sg::Sphere>(scene.objects[3].shape).center, sg::Vec3(1, 2, 3));
}

TEST(ParserDirectives, RecursiveMacroWithinDepth) {
    auto scene = parse_ok("#macro Tree(N) #if (N > 0) sphere { <N, 0, 0>, 1 } Tree(N - 1) #end #end Tree(50)");
    EXPECT_EQ(sphere_count(scene), 50);
}

TEST(ParserDirectives, DeclareWithoutSemicolonWarns) {
    ParseResult result = test::parse_snippet("#declare A = 1\n#declare B = A + 1;\nsphere { 0, B }", "s.pov");
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_EQ(test::count_warnings(result), 1);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(result.scene->objects[0].shape).radius, 2.0);
}

TEST(ParserDirectives, DefaultTexture) {
    auto scene = parse_ok("#default { finish { ambient 0 } } sphere { 0, 1 } sphere { 0, 1 pigment { rgb 1 } }");
    ASSERT_TRUE(scene.objects[0].material);
    EXPECT_DOUBLE_EQ(scene.objects[0].material->finish->ambient.x, 0.0);
}

class IncludeTest : public ::testing::Test {
  protected:
    void SetUp() override {
        m_dir = fs::temp_directory_path() / ("lancer_include_test_" + std::to_string(::getpid()) + "_" +
                                             ::testing::UnitTest::GetInstance()->current_test_info()->name());
        fs::create_directories(m_dir / "sub");
    }
    void TearDown() override { fs::remove_all(m_dir); }
    std::string write(const std::string& name, const std::string& text) {
        std::ofstream(m_dir / name) << text;
        return (m_dir / name).string();
    }
    fs::path m_dir;
};

TEST_F(IncludeTest, NestedIncludesResolveAgainstTheIncludingFolder) {
    write("sub/inner.inc", "#declare Inner = 3;\n");
    write("sub/outer.inc", "#include \"inner.inc\"\n#declare Outer = Inner + 1;\n");
    std::string scene_path = write("scene.pov", "#include \"sub/outer.inc\"\nsphere { 0, Outer }\n");
    ParseResult result = parse_scene_file(scene_path);
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_DOUBLE_EQ(std::get<sg::Sphere>(result.scene->objects[0].shape).radius, 4.0);
}

TEST_F(IncludeTest, IncludePathIsSearchedAndColorsIncIsBuiltIn) {
    fs::create_directories(m_dir / "lib");
    write("lib/shapes.inc", "#declare Unit = sphere { 0, 1 }\n");
    std::string scene_path =
        write("scene.pov", "#include \"colors.inc\"\n#include \"shapes.inc\"\nobject { Unit pigment { SkyBlue } }\n");
    ParseOptions options;
    options.include_path = {(m_dir / "lib").string()};
    ParseResult result = parse_scene_file(scene_path, options);
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    EXPECT_NEAR(result.scene->objects[0].material->pigment.color.rgb.z, 0.8, 1e-9);
}

TEST_F(IncludeTest, MissingIncludeIsLocated) {
    std::string scene_path = write("scene.pov", "sphere { 0, 1 }\n  #include \"nowhere.inc\"\n");
    ParseResult result = parse_scene_file(scene_path);
    ASSERT_FALSE(result.ok());
    const auto& d = result.diagnostics.front();
    EXPECT_NE(d.message.find("cannot find include file \"nowhere.inc\""), std::string::npos);
    EXPECT_EQ(d.location.line, 2);
    EXPECT_EQ(d.location.column, 3);
}

TEST_F(IncludeTest, CycleIsAnErrorWithTheIncludeChain) {
    write("a.inc", "#include \"b.inc\"\n");
    write("b.inc", "\n#include \"a.inc\"\n");
    std::string scene_path = write("scene.pov", "#include \"a.inc\"\n");
    ParseResult result = parse_scene_file(scene_path);
    ASSERT_FALSE(result.ok());
    const auto& d = result.diagnostics.front();
    EXPECT_NE(d.message.find("include cycle"), std::string::npos);
    EXPECT_EQ(d.location.line, 2);  // in b.inc
    ASSERT_EQ(d.include_chain.size(), 2u);
    EXPECT_NE(format_diagnostic(d).find("note: included from here"), std::string::npos);
}

TEST_F(IncludeTest, ErrorInsideIncludedFileShowsTheChain) {
    write("broken.inc", "sphere { 0, }\n");
    std::string scene_path = write("scene.pov", "// first line\n#include \"broken.inc\"\n");
    ParseResult result = parse_scene_file(scene_path);
    ASSERT_FALSE(result.ok());
    const auto& d = result.diagnostics.front();
    EXPECT_NE(d.location.file->find("broken.inc"), std::string::npos);
    EXPECT_EQ(d.location.line, 1);
    EXPECT_EQ(d.location.column, 13);
    ASSERT_EQ(d.include_chain.size(), 1u);
    EXPECT_EQ(d.include_chain[0].line, 2);
}

TEST_F(IncludeTest, ObjMeshWithMtlMaterials) {
    write("sub/box.mtl", "newmtl red\nKd 1 0 0\nKs 0.5 0.5 0.5\nNs 100\n");
    write("sub/box.obj",
          "mtllib box.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
          "usemtl red\nf 1/1 2/2 3/3 4/4\n");
    std::string scene_path = write(
        "scene.pov", "obj_mesh { \"sub/box.obj\" translate x }\nobj_mesh { \"sub/box.obj\" pigment { rgb 1 } }\n");
    ParseResult result = parse_scene_file(scene_path);
    ASSERT_TRUE(result.ok()) << test::all_diagnostics(result);
    auto mesh = std::get<sg::MeshRef>(result.scene->objects[0].shape);
    EXPECT_EQ(result.scene->objects[0].kind, sg::Object::Kind::ObjMesh);
    ASSERT_EQ(mesh->faces.size(), 2u);  // the quad, triangulated
    ASSERT_EQ(mesh->materials.size(), 1u);
    EXPECT_EQ(mesh->faces[0].material, 0);
    EXPECT_DOUBLE_EQ(mesh->materials[0]->pigment.color.rgb.x, 1.0);
    EXPECT_DOUBLE_EQ(mesh->materials[0]->finish->roughness, 0.01);
    EXPECT_EQ(mesh->faces[0].uv[1], 1);
    // A texture on the object replaces the MTL materials.
    auto textured = std::get<sg::MeshRef>(result.scene->objects[1].shape);
    EXPECT_TRUE(textured->materials.empty());
    EXPECT_EQ(textured->faces[0].material, -1);
}

}  // namespace
}  // namespace lancer
