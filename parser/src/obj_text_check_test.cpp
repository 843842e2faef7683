// The OBJ text check fed in pieces: wherever the pieces are cut (inside a
// line, between the \r and \n of one line end, inside the first bytes), it
// finds what it finds in the whole text, at the same line.
#include "obj_text_check.h"

#include <string>

#include <gtest/gtest.h>

namespace lancer::parse {
namespace {

struct Verdict {
    std::string not_text;
    std::string face;
};

Verdict check_in_pieces(const std::string& text, std::size_t piece) {
    ObjTextCheck check;
    for (std::size_t at = 0; at < text.size(); at += piece)
        check.feed(text.data() + at, std::min(piece, text.size() - at));
    check.finish();
    return {check.why_not_text() ? check.why_not_text() : "", check.face_problem()};
}

void expect_same_in_every_cut(const std::string& text, const Verdict& expected) {
    for (std::size_t piece = 1; piece <= text.size(); ++piece) {
        const Verdict got = check_in_pieces(text, piece);
        EXPECT_EQ(got.not_text, expected.not_text) << "pieces of " << piece;
        EXPECT_EQ(got.face, expected.face) << "pieces of " << piece;
    }
}

TEST(ObjTextCheck, LineNumbersCountEveryKindOfLineEnd) {
    // Lines end at \n, \r\n and a lone \r: the bad face is on line 6.
    const std::string text = "v 0 0 0\r\nv 1 0 0\rv 0 1 0\n\nf 1 2 3\r\nf 1 2 4294967300\r\nf 1 2 3\n";
    expect_same_in_every_cut(text, {"", "line 6: face index 4294967300 is out of range"});
}

TEST(ObjTextCheck, ALastLineWithoutItsEndIsChecked) {
    expect_same_in_every_cut("v 0 0 0\n f 1/1/1 2/99999999999/2 3",
                             {"", "line 2: face index 99999999999 is out of range"});
}

TEST(ObjTextCheck, GoodTextHasNothingToSay) {
    expect_same_in_every_cut(
        "# a comment f 99999999999\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n"
        "f -3 -2 -1\nf 1/1 2/1 3/1\nf 1//1 2//1 3//1\nf 1/1/1 2/1/1 3/1/1\nf 1 2\n",
        {"", ""});
}

// tinyobjloader reads an index with atoi: 0, and what is not a number, read
// as index 0, which its LoadObj rejected (with only the line number).
TEST(ObjTextCheck, IndicesOfZeroAndWordsAreFoundWithTheirLine) {
    const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\n";
    expect_same_in_every_cut(head + "f 1 2 0\n", {"", "line 5: face index 0 (OBJ counts from 1)"});
    expect_same_in_every_cut(head + "f 1/0 2/1 3/1\n", {"", "line 5: face index 0 (OBJ counts from 1)"});
    expect_same_in_every_cut(head + "f 1 0\n", {"", "line 5: face index 0 (OBJ counts from 1)"});
    expect_same_in_every_cut(head + "f 1 2 3 # done\n", {"", "line 5: face index \"#\" is not a number"});
    expect_same_in_every_cut(head + "f /1 2 3\n", {"", "line 5: face index \"\" is not a number"});
}

TEST(ObjTextCheck, ACornerOfFourPartsIsNamed) {
    const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";
    const std::string why = "\" has more than three parts (OBJ writes v, v/vt, v//vn or v/vt/vn)";
    expect_same_in_every_cut(head + "f 1 2/1/1/1 3\n", {"", "line 6: face corner \"2/1/1/1" + why});
    expect_same_in_every_cut(head + "f 1/1//\t2 3\n", {"", "line 6: face corner \"1/1//" + why});
    expect_same_in_every_cut(head + "f 1 2 3//1/\r\n", {"", "line 6: face corner \"3//1/" + why});
    expect_same_in_every_cut(head + "f 1//1 2/1 3/1/1\n", {"", ""});
}

TEST(ObjTextCheck, AnEmptyPieceChangesNothing) {
    ObjTextCheck check;
    for (const char* piece : {"v 0 0 0\r", "", "\nf 1 2 0\n"}) check.feed(piece, std::string(piece).size());
    check.finish();
    EXPECT_EQ(check.face_problem(), "line 2: face index 0 (OBJ counts from 1)");
}

TEST(ObjTextCheck, BinaryAndUtf16AreFoundAcrossPieces) {
    const std::string png("\x89PNG\r\n\x1a\n\0\0\0\rIHDR", 16);
    expect_same_in_every_cut(png, {"is a PNG image, not text", ""});
    expect_same_in_every_cut(std::string("v 0 0 0\nf 1 2 3\n\0", 17),
                             {"is a binary file, not text (or UTF-16 without a byte order mark)", ""});
    expect_same_in_every_cut(std::string("\xFF\xFEv\0 \0", 6), {"is UTF-16 text; save it as UTF-8 or ASCII", ""});
}

// The mesh is reserved from these counts before tinyobjloader reads it.
TEST(ObjTextCheck, CountsEachKindOfLineAsTinyobjloaderTellsThemApart) {
    const std::string text =
        "v 0 0 0\r\n\tv 1 0 0\rv\t0 1 0\nvt 0 0\nvn 0 0 1\nvp 1 2\nvertex 1\nv\n"
        "f 1 2 3\nf 1 2 3 1/1\n f 1 2\nfo 1 2 3\nusemtl v\n# v 1 1 1\nf 1 2 3 1 2 3";
    for (std::size_t piece = 1; piece <= text.size(); ++piece) {
        ObjTextCheck check;
        for (std::size_t at = 0; at < text.size(); at += piece)
            check.feed(text.data() + at, std::min(piece, text.size() - at));
        check.finish();
        EXPECT_EQ(check.counts().positions, 3u) << "pieces of " << piece;
        EXPECT_EQ(check.counts().uvs, 1u) << "pieces of " << piece;
        EXPECT_EQ(check.counts().normals, 1u) << "pieces of " << piece;
        EXPECT_EQ(check.counts().faces, 3u) << "pieces of " << piece;
        EXPECT_EQ(check.counts().triangles, 1u + 2u + 4u) << "pieces of " << piece;
    }
}

TEST(ObjTextCheck, AFaceOfTooManyVertices) {
    std::string face = "f";
    for (std::size_t i = 0; i <= ObjTextCheck::kMaxFaceVertices; ++i) face += " 1";
    ObjTextCheck check;
    check.feed(face.data(), face.size());
    check.finish();
    EXPECT_EQ(check.face_problem(),
              "line 1: a face of 1000001 vertices (lancer takes at most 1000000 per face; split "
              "it into smaller polygons)");
}

}  // namespace
}  // namespace lancer::parse
