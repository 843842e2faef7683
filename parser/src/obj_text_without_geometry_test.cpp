// Geometry lines read by lancer instead of tinyobjloader
// (obj_text_without_geometry.h): for every text, and wherever the file's
// pieces are cut, the mesh (every number to the bit), its warnings and the
// face a message would name are what tinyobjloader's own reading of the
// whole text gives.
#include "obj_text_without_geometry.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "temp_folder.h"

namespace lancer::parse {
namespace {

// Everything the reader made, as text to compare.
std::string outcome(sg::TriangleMesh& mesh, ObjFaceReader& faces, bool loaded, const std::string& warnings) {
    std::ostringstream out;
    const bool finished = faces.finish();
    out << "loaded " << loaded << " finished " << finished << " bad '" << faces.bad_face << "' short "
        << faces.short_faces << " misnamed " << faces.misnamed_normals << "/" << faces.misnamed_uvs << " crossing "
        << faces.crossing.count << " '" << faces.crossing.first << "' flat " << faces.flat.count << " '"
        << faces.flat.first << "' warnings '" << warnings << faces.warnings << "'\n";
    out << mesh.positions.size() << " positions, " << mesh.normals.size() << " normals, " << mesh.uvs.size()
        << " uvs\n";
    // Every number exactly (hexadecimal), a sign of zero and NaN included.
    char number[64];
    auto put = [&](double value) {
        std::snprintf(number, sizeof number, " %a", value);
        out << number;
    };
    for (const auto& p : mesh.positions) put(p.x), put(p.y), put(p.z), out << "\n";
    for (const auto& n : mesh.normals) put(n.x), put(n.y), put(n.z), out << "\n";
    for (const auto& uv : mesh.uvs) put(uv.x), put(uv.y), out << "\n";
    for (const sg::TriangleMesh::Face& face : mesh.faces) {
        for (int i = 0; i < 3; ++i) out << face.position[i] << "/" << face.uv[i] << "/" << face.normal[i] << " ";
        out << "m" << face.material << "\n";
    }
    return out.str();
}

std::string read_by_tinyobjloader(const std::string& text) {
    sg::TriangleMesh mesh;
    ObjFaceReader faces(mesh);
    std::istringstream in(text);
    std::string warnings, errors;
    const bool loaded =
        tinyobj::LoadObjWithCallback(in, ObjFaceReader::callbacks(), &faces, nullptr, &warnings, &errors);
    return outcome(mesh, faces, loaded, warnings + errors);
}

std::string read_with_faces_aside(const std::string& path, std::size_t size, std::size_t piece) {
    sg::TriangleMesh mesh;
    ObjFaceReader faces(mesh);
    ObjTextWithoutGeometry text(path, size, faces, piece);
    std::istream in(&text);
    std::string warnings, errors;
    const bool loaded =
        tinyobj::LoadObjWithCallback(in, ObjFaceReader::callbacks(), &faces, nullptr, &warnings, &errors);
    EXPECT_FALSE(text.failed());
    return outcome(mesh, faces, loaded, warnings + errors);
}

void expect_as_tinyobjloader_reads_it(const std::string& text) {
    test::TempFolder temp;
    const std::string path = temp.write("model.obj", text);
    const std::string expected = read_by_tinyobjloader(text);
    for (std::size_t piece = 1; piece <= text.size() + 1; ++piece)
        EXPECT_EQ(read_with_faces_aside(path, text.size(), piece), expected) << "pieces of " << piece;
}

TEST(ObjTextWithoutGeometry, EveryKindOfLineEnd) {
    expect_as_tinyobjloader_reads_it(
        "v 0 0 0\r\nv 1 0 0\rv 0 1 0\nf 1 2 3\rf 3 2 1\r\nvt 0 0\nvt 1 0\rvt 0 1\r\n"
        "f 1/1 2/2 3/3\r\rf 1/3 2/2 3/1\n\nf 2 3 1");
}

TEST(ObjTextWithoutGeometry, FacesSeeOnlyTheVerticesBeforeThem) {
    // Relative indices count back from what is read so far; a polygon
    // naming a later vertex waits for it in its place.
    expect_as_tinyobjloader_reads_it(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\nf 1 2 4 5\n"
        "v 5 0 0\nv 6 0 0\nv 5 1 0\nf -3 -2 -1\nf 1 2 6\nv 1 1 0\n");
}

TEST(ObjTextWithoutGeometry, CornersOfEveryShape) {
    expect_as_tinyobjloader_reads_it(
        "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 1\nvn 0 0 1\n"
        "f 1//1 2//1 3//1\nf 1/1/1 2/2/1 3/1/1\nf 1/1 2/2 3/1\nf 1/ 2/ 3/\nf 1/1/ 2/2/ 3/2/\n"
        "f +1 +2 +3\nf 1x 2y/2 3z//1\nf\t1\t2\t3\t\n  \tf 4 3 2  \nf 1 2 -1\n");
}

TEST(ObjTextWithoutGeometry, AtoiQuirksAreKept) {
    // atoi skips blanks: tinyobjloader reads "1/ 2" as vertex 1 with
    // texture coordinate 2, then a corner of vertex 2.
    expect_as_tinyobjloader_reads_it("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 1\nf 1/ 2 3 4\nf 3/\v1 2 1\n");
}

TEST(ObjTextWithoutGeometry, LinesThatAreNotFaces) {
    expect_as_tinyobjloader_reads_it(
        "# f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\nfo 1 2 3\nf\nf \nf 1 2\nf 1\n"
        "g part one\nf 1 2 3\no thing\nf 3 2 1\nusemtl red\nf 1 3 2\ns 1\nf 2 1 3\n#\nf 1 2 3 # comment?\n");
}

TEST(ObjTextWithoutGeometry, FacesNamingNoVertexAreReportedInFileOrder) {
    expect_as_tinyobjloader_reads_it("v 0 0 0\nv 1 0 0\nv 0 1 0\ng a\nf 1 2 3\nf 1 2 9 8\ng b\nf 1 2 7\nf -5 1 2\n");
}

TEST(ObjTextWithoutGeometry, NumbersOfEveryForm) {
    // tinyobjloader's number fields: signs, leading and trailing points,
    // exponents, junk after a number, fields that are not numbers (their
    // default), missing fields, overflow and underflow.
    expect_as_tinyobjloader_reads_it(
        "v 1 2 3\nv -1.5 +2.25 .5\nv -.5 5. 1.e2\nv 1e5 -2E-3 +3e+2\nv 0.1 0.2 0.3\n"
        "v 123456789 0.000001 1234.5678\nv 1.5x 2e3y 7abc\nv x 2 3\nv 1\nv\t4\t5\t6\t7\nv . -. +.\n"
        "v 1e 1e+ 2\nv 1e999 -1e999 1e-999\nv 0e99 -0 0.0\nv inf nan 3\nv 1e99999999999 2 3\n"
        "v 3.14159265358979323846 2.718281828459045 1.4142135623730951\nv -.e5 .e1 0.e400\n"
        "vn 0 0 1\nvn .6 -.8\nvn 1e-40 1e-46 -1e-39\nvt 0.25 0.75\nvt 1\nvt 0.5 0.5 0.5\nvt a b\n"
        "v  \t 7 8 9  \nvn\t1 2 3\nv1 2 3\nvx 1 2 3\n");
}

// Where tinyobjloader's arithmetic is not the decimal's: a number is the
// decimal written, rounded once to a float (strtof's value), at a tie, just
// off one, over hundreds of digits and with exponents past 2^31.
TEST(ObjTextWithoutGeometry, NumbersAreTheirDecimalsRoundedOnce) {
    const std::vector<std::string> fields = {"0e999",
                                             "-0.0e999",
                                             "-1.913208e+09",
                                             "5.06470e+08",
                                             "5.606209653261e-17",
                                             "-2.039405178067e-08",
                                             "1" + std::string(309, '0') + "e-309",
                                             "-0." + std::string(420, '0') + "1e421",
                                             "1e2147483648",
                                             "1e-2147483648",
                                             "-1e2147483647",
                                             "3.4028235e38",
                                             "3.4028236e38",
                                             "1e-45",
                                             "7e-46",
                                             "0.1",
                                             "-123.456"};
    std::string text;
    for (const std::string& field : fields) text += "vn " + field + " 0 0\n";
    test::TempFolder temp;
    const std::string path = temp.write("model.obj", text);
    sg::TriangleMesh mesh;
    ObjFaceReader faces(mesh);
    ObjTextWithoutGeometry reading(path, text.size(), faces);
    std::istream in(&reading);
    std::string warnings, errors;
    ASSERT_TRUE(tinyobj::LoadObjWithCallback(in, ObjFaceReader::callbacks(), &faces, nullptr, &warnings, &errors));
    ASSERT_EQ(mesh.normals.size(), fields.size());
    for (std::size_t k = 0; k < fields.size(); ++k) {
        const float expected = std::strtof(fields[k].c_str(), nullptr);
        const float got = float(mesh.normals[k].x);
        EXPECT_EQ(std::memcmp(&got, &expected, sizeof got), 0)
            << fields[k].substr(0, 40) << ": " << got << " against strtof's " << expected;
    }
}

TEST(ObjTextWithoutGeometry, OnlyFacesOrNothing) {
    expect_as_tinyobjloader_reads_it("f 1 2 3\nf 4 5 6\n");
    expect_as_tinyobjloader_reads_it("\n");
    expect_as_tinyobjloader_reads_it("f 1 2 3");
}

TEST(ObjTextWithoutGeometry, ReadsNoFurtherThanTheLimit) {
    test::TempFolder temp;
    const std::string text = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 3 2 1\n";
    const std::string path = temp.write("model.obj", text + "f 1 3 2\nv 9 9 9\n");
    for (std::size_t piece : {1, 3, 64})
        EXPECT_EQ(read_with_faces_aside(path, text.size(), piece), read_by_tinyobjloader(text));
}

}  // namespace
}  // namespace lancer::parse
