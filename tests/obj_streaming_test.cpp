// OBJ files read as a stream (parser/src/obj_faces.h): what tinyobjloader's
// LoadObj accepted reads the same, face by face, and what it rejected or
// warned about is still reported.
#include <string>

#include <gtest/gtest.h>

#include "lancer/parser.h"
#include "temp_folder.h"

namespace lancer::test {
namespace {

struct ObjStreaming : ::testing::Test {
    TempFolder temp;

    ParseResult parse_obj(const std::string& obj_bytes) {
        temp.write("model.obj", obj_bytes);
        return parse_scene_file(temp.write("scene.pov", "#version 3.7;\nobj_mesh { \"model.obj\" }\n"), {});
    }
    static std::string all_text(const ParseResult& result) {
        std::string text;
        for (const auto& d : result.diagnostics) text += format_diagnostic(d);
        return text;
    }
    static const sg::TriangleMesh& mesh(const ParseResult& result) {
        return *std::get<sg::MeshRef>(result.scene->objects.back().shape);
    }
};

TEST_F(ObjStreaming, RelativeIndicesCountBackFromWhatIsReadSoFar) {
    const ParseResult result = parse_obj(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n"
        "v 5 0 0\nv 6 0 0\nv 5 1 0\nf -3 -2 -1\n");
    ASSERT_TRUE(result.ok()) << all_text(result);
    const auto& faces = mesh(result).faces;
    ASSERT_EQ(faces.size(), 2u);
    EXPECT_EQ(faces[0].position[0], 0);
    EXPECT_EQ(faces[0].position[2], 2);
    EXPECT_EQ(faces[1].position[0], 3);
    EXPECT_EQ(faces[1].position[2], 5);
}

// A face may name a vertex written after it (tinyobjloader reads such
// files); a polygon waiting for its vertices keeps its place among the faces.
TEST_F(ObjStreaming, FacesNamingLaterVerticesKeepTheirPlace) {
    const ParseResult result = parse_obj(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
        "f 1 2 3\n"
        "f 1 2 4 5\n"  // a quad of vertices not read yet
        "f 1 2 4\n"    // a triangle of one
        "f 3 2 1\n"
        "v 1 1 0\nv 0 2 0\n");
    ASSERT_TRUE(result.ok()) << all_text(result);
    const auto& faces = mesh(result).faces;
    ASSERT_EQ(faces.size(), 5u);
    EXPECT_EQ(faces[0].position[2], 2);
    // The quad's two triangles, second and third: corners 0, 1, 3, 4 only.
    for (int t = 1; t <= 2; ++t)
        for (int i = 0; i < 3; ++i) {
            const int p = faces[std::size_t(t)].position[i];
            EXPECT_TRUE(p == 0 || p == 1 || p == 3 || p == 4) << "triangle " << t << " corner " << p;
        }
    EXPECT_EQ(faces[3].position[2], 3);
    EXPECT_EQ(faces[4].position[0], 2);
}

// Polygons that wait for their vertices are triangulated at the end; the
// warning still names the first face in the file.
TEST_F(ObjStreaming, WarningsNameTheFirstFaceInTheFileOrder) {
    const ParseResult result = parse_obj(
        "v 0 0 0\nv 1 0 0\nv 2 0 0\n"
        "f 1 2 3 4\n"  // waits for vertex 4; all four on one line: no area
        "f 1 2 3 1\n"  // no area either, all its vertices read
        "f 1 2 5\n"
        "v 3 0 0\nv 0 1 0\n");
    ASSERT_TRUE(result.ok()) << all_text(result);
    EXPECT_NE(all_text(result).find("2 faces have no area (first: face 1;"), std::string::npos) << all_text(result);
    EXPECT_EQ(mesh(result).faces.size(), 1u);
}

TEST_F(ObjStreaming, TheFirstFaceNamingNoVertexIsTheOneReported) {
    // Face 2 names vertex 9, which never comes; face 3 names the ninth
    // vertex back, which cannot exist. The first in the file is the one
    // named, with its group.
    const ParseResult result = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\ng part\nf 1 2 3\nf 1 2 9\nf -9 1 2\n");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("face 2 of 'part' refers to a vertex that does not exist"), std::string::npos)
        << all_text(result);
}

TEST_F(ObjStreaming, FacesAreNumberedWithinEachGroup) {
    const ParseResult result = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 3\no second\nf 1 2 3\nf 1 2 -4\n");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("face 2 of 'second' refers"), std::string::npos) << all_text(result);
}

TEST_F(ObjStreaming, ShortFacesAndMissingNormalsAreLeftOutWithAWarning) {
    const ParseResult result = parse_obj(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvt 0 0\n"
        "f 1 2\n"
        "f 1//1 2//1 3//7\n"       // a normal that does not exist: flat
        "f 1/1/1 2/1/1 3/1/1\n");  // normals and uvs that exist
    ASSERT_TRUE(result.ok()) << all_text(result);
    const std::string text = all_text(result);
    EXPECT_NE(text.find("1 face has fewer than three vertices and is left out"), std::string::npos) << text;
    EXPECT_NE(text.find("1 triangle names a normal that does not exist; shaded flat"), std::string::npos) << text;
    const auto& faces = mesh(result).faces;
    ASSERT_EQ(faces.size(), 2u);
    EXPECT_EQ(faces[0].normal[0], -1);
    EXPECT_EQ(faces[0].normal[2], -1);
    EXPECT_EQ(faces[1].normal[2], 0);
    EXPECT_EQ(faces[1].uv[1], 0);
}

TEST_F(ObjStreaming, UsemtlNamesTheMaterialOfTheFacesAfterIt) {
    temp.write("two.mtl", "newmtl red\nKd 1 0 0\nnewmtl blue\nKd 0 0 1\n");
    const ParseResult result = parse_obj(
        "mtllib two.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\n"
        "f 1 2 3\nusemtl blue  \nf 1 2 3\nusemtl  \t red\nf 1 2 3\nusemtl green\nf 1 2 3\n");
    ASSERT_TRUE(result.ok()) << all_text(result);
    EXPECT_NE(all_text(result).find("material [ 'green' ] not found in .mtl"), std::string::npos) << all_text(result);
    const auto& m = mesh(result);
    ASSERT_EQ(m.materials.size(), 2u);
    ASSERT_EQ(m.faces.size(), 4u);
    EXPECT_EQ(m.faces[0].material, -1);
    EXPECT_EQ(m.faces[1].material, 1);  // blanks around the name, as LoadObj reads it
    EXPECT_EQ(m.faces[2].material, 0);
    EXPECT_EQ(m.faces[3].material, -1);
    EXPECT_EQ(m.materials[1]->pigment.color.rgb, sg::Vec3(0, 0, 1));
}

}  // namespace
}  // namespace lancer::test
