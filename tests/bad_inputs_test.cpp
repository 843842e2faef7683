// Bad OBJ, MTL and image files, and the resource limits: each gets a located
// error (or a warning and a sensible result), never a crash, a hang or a
// partial image. The files are generated in a temporary folder.
#include <sys/stat.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "lancer/parser.h"
#include "run_command.h"
#include "temp_folder.h"

namespace lancer::test {

namespace {

namespace fs = std::filesystem;

const std::string kTriangle = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
// A PNG signature and the start of an IHDR chunk: what a .png renamed .obj begins with.
constexpr char kPngHeadBytes[] = "\x89PNG\r\n\x1a\n\0\0\0\rIHDR\0\0\0\x10\0\0\0\x10\x08\x02\0\0\0";
const std::string kPngHead(kPngHeadBytes, sizeof kPngHeadBytes - 1);  // the NULs are part of it

std::string all_text(const ParseResult& result) {
    std::string text;
    for (const auto& d : result.diagnostics) text += format_diagnostic(d);
    return text;
}

struct BadFiles : ::testing::Test {
    TempFolder temp;

    // Parses `scene` written as temp/scene.pov.
    ParseResult parse(const std::string& scene, ParseOptions options = {}) {
        return parse_scene_file(temp.write("scene.pov", scene), options);
    }
    // An obj_mesh of `obj_bytes`, at line 2 column 12 of the scene.
    ParseResult parse_obj(const std::string& obj_bytes) {
        temp.write("model.obj", obj_bytes);
        return parse("#version 3.7;\nobj_mesh { \"model.obj\" }\n");
    }
    // The first error, which must sit on the obj_mesh's file name.
    std::string obj_error(const std::string& obj_bytes) {
        ParseResult result = parse_obj(obj_bytes);
        EXPECT_FALSE(result.ok()) << "accepted: " << obj_bytes;
        for (const auto& d : result.diagnostics) {
            if (d.severity != Diagnostic::Severity::Error) continue;
            EXPECT_EQ(d.location.line, 2) << all_text(result);
            EXPECT_EQ(d.location.column, 12) << all_text(result);
            return d.message;
        }
        return "";
    }
};

const sg::TriangleMesh& only_mesh(const sg::SceneGraph& scene) {
    return *std::get<sg::MeshRef>(scene.objects.back().shape);
}

}  // namespace

TEST_F(BadFiles, MissingObjFileIsLocated) {
    ParseResult result = parse("sphere { 0, 1 }\nobj_mesh { \"nowhere.obj\" }\n");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("scene.pov:2:12: error: cannot find OBJ file \"nowhere.obj\""), std::string::npos)
        << all_text(result);
}

TEST_F(BadFiles, EmptyObjHasNoFaces) {
    EXPECT_NE(obj_error("").find("has no faces"), std::string::npos);
}

TEST_F(BadFiles, PointCloudHasNoFaces) {
    EXPECT_NE(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 1\n").find("4 vertices only: a point cloud?"),
              std::string::npos);
}

TEST_F(BadFiles, TruncatedObj) {
    // Cut inside the third vertex: no face survives.
    EXPECT_NE(obj_error("v 0 0 0\nv 1 0 0\nv 0 1").find("no faces"), std::string::npos);
    // Cut inside the face: a face with two corners is no triangle.
    std::string message = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2");
    EXPECT_FALSE(message.empty());
}

TEST_F(BadFiles, PngRenamedObj) {
    EXPECT_NE(obj_error(kPngHead).find("is a PNG image"), std::string::npos);
}

TEST_F(BadFiles, Utf16Obj) {
    std::string utf16 = "\xFF\xFE";
    for (char c : kTriangle) utf16 += std::string{c, '\0'};
    EXPECT_NE(obj_error(utf16).find("UTF-16"), std::string::npos);
    // Without a byte order mark: NUL bytes every other byte.
    EXPECT_NE(obj_error(utf16.substr(2)).find("UTF-16"), std::string::npos);
}

TEST_F(BadFiles, FaceIndexOutOfRange) {
    EXPECT_NE(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 7\n").find("does not exist"), std::string::npos);
}

TEST_F(BadFiles, FaceIndexZeroOrTooNegative) {
    EXPECT_FALSE(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n").empty());
    EXPECT_FALSE(obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -9 1 2\n").empty());
}

// tinyobjloader reads face indices into int: 2^32 + 4 wrapped to vertex 4.
TEST_F(BadFiles, FaceIndexBeyondIntIsAnError) {
    const std::string message = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nf 1 2 4294967300\n");
    EXPECT_NE(message.find("line 5: face index 4294967300 is out of range"), std::string::npos) << message;
    const std::string slashed = obj_error("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nf 1/1 2/99999999999 3/1\n");
    EXPECT_NE(slashed.find("out of range"), std::string::npos) << slashed;
}

// A face of n corners as an OBJ (its corners in order, then one face line).
std::string obj_face(const std::vector<glm::dvec2>& corners) {
    std::string obj, face = "f";
    char line[96];
    for (size_t i = 0; i < corners.size(); ++i) {
        std::snprintf(line, sizeof line, "v %.17g %.17g 0\n", corners[i].x, corners[i].y);
        obj += line;
        face += " " + std::to_string(i + 1);
    }
    return obj + face + "\n";
}

// The area of the mesh's triangles (each counted once, however wound), and
// the area of its vertices read as one polygon in the xy plane.
double triangle_area(const sg::TriangleMesh& mesh) {
    double sum = 0.0;
    for (const auto& f : mesh.faces) {
        const auto& p = mesh.positions;
        sum += 0.5 * glm::length(glm::cross(p[f.position[1]] - p[f.position[0]], p[f.position[2]] - p[f.position[0]]));
    }
    return sum;
}
double polygon_area(const sg::TriangleMesh& mesh) {
    double sum = 0.0;
    const auto& p = mesh.positions;
    for (size_t i = 0; i < p.size(); ++i) {
        const auto& a = p[i];
        const auto& b = p[(i + 1) % p.size()];
        sum += a.x * b.y - a.y * b.x;
    }
    return 0.5 * std::abs(sum);
}

// tinyobjloader's triangulation took time growing with the square of a
// face's size (a face of 200,000 vertices took 55 s, so faces were capped at
// 256); lancer's takes O(n log n): a fan where the face is convex.
TEST_F(BadFiles, HugeConvexFaceIsTriangulated) {
    constexpr int kVertices = 200000;
    std::vector<glm::dvec2> corners;
    for (int i = 0; i < kVertices; ++i) {
        const double angle = 6.283185307179586 * i / kVertices;
        corners.emplace_back(std::cos(angle), std::sin(angle));
    }
    ParseResult result = parse_obj(obj_face(corners));
    ASSERT_TRUE(result.ok()) << all_text(result);
    EXPECT_TRUE(result.diagnostics.empty()) << all_text(result);
    const sg::TriangleMesh& mesh = only_mesh(*result.scene);
    EXPECT_EQ(mesh.faces.size(), static_cast<size_t>(kVertices - 2));
    EXPECT_NEAR(triangle_area(mesh), polygon_area(mesh), 1e-9);
    EXPECT_NEAR(triangle_area(mesh), 3.14159265, 1e-6);
}

// A star of 100,000 corners is concave at every other corner: the sweep
// splits it into monotone pieces, and its triangles cover it exactly once.
TEST_F(BadFiles, HugeStarFaceIsTriangulated) {
    constexpr int kVertices = 100000;
    std::vector<glm::dvec2> corners;
    for (int i = 0; i < kVertices; ++i) {
        const double angle = 6.283185307179586 * i / kVertices, radius = i % 2 ? 0.5 : 1.0;
        corners.emplace_back(radius * std::cos(angle), radius * std::sin(angle));
    }
    ParseResult result = parse_obj(obj_face(corners));
    ASSERT_TRUE(result.ok()) << all_text(result);
    EXPECT_TRUE(result.diagnostics.empty()) << all_text(result);
    const sg::TriangleMesh& mesh = only_mesh(*result.scene);
    EXPECT_EQ(mesh.faces.size(), static_cast<size_t>(kVertices - 2));
    const double area = polygon_area(mesh);
    EXPECT_NEAR(area, 0.25 * kVertices * std::sin(6.283185307179586 / kVertices), 1e-5);  // n triangles 1 x 0.5 about 0
    EXPECT_NEAR(triangle_area(mesh), area, 1e-9 * area);
}

// A comb: teeth of one unit on a bar, 100,000 corners, half of them concave.
TEST_F(BadFiles, HugeCombFaceIsTriangulated) {
    constexpr int kTeeth = 25000;
    std::vector<glm::dvec2> corners{{0, 0}, {2 * kTeeth - 1, 0}};
    for (int i = kTeeth - 1; i >= 0; --i) {
        corners.emplace_back(2 * i + 1, 3);
        corners.emplace_back(2 * i, 3);
        if (i > 0) {
            corners.emplace_back(2 * i, 1);
            corners.emplace_back(2 * i - 1, 1);
        }
    }
    ParseResult result = parse_obj(obj_face(corners));
    ASSERT_TRUE(result.ok()) << all_text(result);
    const sg::TriangleMesh& mesh = only_mesh(*result.scene);
    EXPECT_EQ(mesh.faces.size(), corners.size() - 2);
    EXPECT_DOUBLE_EQ(polygon_area(mesh), 4.0 * kTeeth - 1);
    EXPECT_NEAR(triangle_area(mesh), 4.0 * kTeeth - 1, 1e-6);
}

// tinyobjloader keeps a face's size modulo 256: lancer counts the vertices
// of each face line itself (with \r\n line ends, a two-vertex line that
// tinyobjloader drops, faces before and after).
TEST_F(BadFiles, FacesOfMoreThan255VerticesAmongOthers) {
    std::vector<glm::dvec2> corners;
    for (int i = 0; i < 300; ++i)
        corners.emplace_back(std::cos(6.283185307179586 * i / 300), std::sin(6.283185307179586 * i / 300));
    std::string obj = obj_face(corners);
    obj.insert(obj.rfind("f "), "f 1 2\r\nf 1 2 3\r\n");
    obj += "f 4 5 6 7\r\n";
    ParseResult result = parse_obj(obj);
    ASSERT_TRUE(result.ok()) << all_text(result);
    EXPECT_EQ(only_mesh(*result.scene).faces.size(), 1u + 298u + 2u);
}

// Faces beyond a million vertices are still refused before tinyobjloader
// reads the file, naming the line.
TEST_F(BadFiles, FaceBeyondTheCapIsRefusedQuickly) {
    std::string face = "f";
    face.reserve(6000010);
    for (int i = 0; i < 1000001; ++i) face += i % 2 ? " 2" : " 3";
    const std::string message = obj_error(kTriangle + face + "\n");
    EXPECT_NE(message.find("line 5: a face of 1000001 vertices (lancer takes at most 1000000 per face"),
              std::string::npos)
        << message;
}

// A face whose edges cross has no inside: it becomes a fan, with a warning;
// one whose corners lie on a line has no triangles.
TEST_F(BadFiles, FacesThatCrossThemselvesOrHaveNoArea) {
    ParseResult crossing = parse_obj("v 0 0 0\nv 2 2 0\nv 2 0 0\nv 0 2 0\nv -1 1 0\nf 1 2 3 4 5\nf 1 3 2\n");
    ASSERT_TRUE(crossing.ok()) << all_text(crossing);
    EXPECT_EQ(only_mesh(*crossing.scene).faces.size(), 4u);
    EXPECT_NE(all_text(crossing).find("scene.pov:2:12: warning: OBJ \"model.obj\": 1 face crosses its own edges "
                                      "(first: face 1); triangulated as a fan from the first corner"),
              std::string::npos)
        << all_text(crossing);
    ParseResult flat = parse_obj("v 0 0 0\nv 1 1 1\nv 2 2 2\nv 3 3 3\nv 0 1 0\nf 1 2 3 4\nf 1 2 5\n");
    ASSERT_TRUE(flat.ok()) << all_text(flat);
    EXPECT_EQ(only_mesh(*flat.scene).faces.size(), 1u);
    EXPECT_NE(all_text(flat).find("1 face has no area (first: face 1; its corners lie on one line) and is left out"),
              std::string::npos)
        << all_text(flat);
}

TEST_F(BadFiles, NegativeIndicesCountFromTheEnd) {
    ParseResult result = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nf -3 -2 -1\n");
    ASSERT_TRUE(result.ok()) << all_text(result);
    EXPECT_EQ(only_mesh(*result.scene).faces.size(), 1u);
}

TEST_F(BadFiles, NanCoordinatesNeverReachTheScene) {
    // tinyobjloader may read "nan" as 0; either way no coordinate is non-finite.
    ParseResult result = parse_obj("v nan 0 0\nv 1 inf 0\nv 0 1 0\nf 1 2 3\n");
    if (result.ok()) {
        for (const auto& p : only_mesh(*result.scene).positions)
            EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    } else {
        EXPECT_NE(all_text(result).find("scene.pov:2:12"), std::string::npos) << all_text(result);
    }
}

TEST_F(BadFiles, MissingMtlWarnsAndUsesTheDefaultMaterial) {
    ParseResult result = parse_obj("mtllib gone.mtl\nusemtl red\n" + kTriangle);
    ASSERT_TRUE(result.ok()) << all_text(result);
    EXPECT_NE(all_text(result).find("scene.pov:2:12: warning: OBJ \"model.obj\": MTL file \"gone.mtl\" not found"),
              std::string::npos)
        << all_text(result);
    EXPECT_EQ(only_mesh(*result.scene).faces.at(0).material, -1);
}

TEST_F(BadFiles, BinaryMtlWarns) {
    temp.write("bad.mtl", kPngHead);
    ParseResult result = parse_obj("mtllib bad.mtl\nusemtl red\n" + kTriangle);
    ASSERT_TRUE(result.ok()) << all_text(result);
    EXPECT_NE(all_text(result).find("is a PNG image"), std::string::npos) << all_text(result);
}

TEST_F(BadFiles, GoodMtlStillMaps) {
    temp.write("good.mtl", "newmtl red\nKd 1 0 0\n");
    ParseResult result = parse_obj("mtllib good.mtl\nusemtl red\n" + kTriangle);
    ASSERT_TRUE(result.ok()) << all_text(result);
    const auto& mesh = only_mesh(*result.scene);
    ASSERT_EQ(mesh.materials.size(), 1u);
    EXPECT_EQ(mesh.faces.at(0).material, 0);
    EXPECT_EQ(mesh.materials[0]->pigment.color.rgb, sg::Vec3(1, 0, 0));
}

// `Ks 1e999` is infinity to tinyobjloader and blackened the object with
// only a count of dropped samples; `Kd -5` did the same.
TEST_F(BadFiles, MtlValuesMustBeFiniteAndReflectancesNonNegative) {
    temp.write("inf.mtl", "newmtl shiny\nKd 1 1 1\nKs 1e999 0 0\n");
    ParseResult infinite = parse_obj("mtllib inf.mtl\nusemtl shiny\n" + kTriangle);
    ASSERT_FALSE(infinite.ok());
    EXPECT_NE(all_text(infinite).find("scene.pov:2:12: error: OBJ \"model.obj\": material 'shiny': Ks is not a finite"),
              std::string::npos)
        << all_text(infinite);
    temp.write("neg.mtl", "newmtl dark\nKd -5 0.5 1\n");
    ParseResult negative = parse_obj("mtllib neg.mtl\nusemtl dark\n" + kTriangle);
    ASSERT_TRUE(negative.ok()) << all_text(negative);
    EXPECT_NE(all_text(negative).find("material 'dark': Kd has a negative value"), std::string::npos)
        << all_text(negative);
    EXPECT_EQ(only_mesh(*negative.scene).materials[0]->pigment.color.rgb, sg::Vec3(0, 0.5, 1));
}

TEST_F(BadFiles, ObjLargerThanTheLimit) {
    temp.write("model.obj", kTriangle);
    ParseOptions options;
    options.max_file_bytes = 10;
    ParseResult result = parse("obj_mesh { \"model.obj\" }\n", options);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("too large"), std::string::npos) << all_text(result);
}

// The scene file itself is read as an include is: under the same limit.
TEST_F(BadFiles, SceneFileLargerThanTheLimit) {
    ParseOptions options;
    options.max_file_bytes = 10;
    ParseResult result = parse("sphere { 0, 1 }\n", options);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("scene file \""), std::string::npos) << all_text(result);
    EXPECT_NE(all_text(result).find("is too large: 16 bytes (the limit is 10)"), std::string::npos) << all_text(result);
    options.max_file_bytes = 16;
    EXPECT_TRUE(parse("sphere { 0, 1 }\n", options).ok());
}

// A named pipe as the scene: read from the one opening. Opened a second
// time, it waited for a writer that had already written and gone.
TEST_F(BadFiles, SceneFromANamedPipeIsReadOnce) {
    const std::string pipe = (temp.path() / "scene.pov").string();
    ASSERT_EQ(mkfifo(pipe.c_str(), 0600), 0);
    std::thread writer([&] { std::ofstream(pipe) << "sphere { 0, 1 }\n"; });
    std::future<ParseResult> result = std::async(std::launch::async, [&] { return parse_scene_file(pipe); });
    writer.join();
    if (result.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
        std::ofstream{pipe};  // a second writer lets the stuck reading end
        result.wait();
        FAIL() << "the scene's reading waited for a second writer";
    }
    const ParseResult parsed = result.get();
    ASSERT_TRUE(parsed.ok()) << all_text(parsed);
    EXPECT_EQ(parsed.scene->objects.size(), 1u);
}

// ---------------------------------------------------- images, through render

struct BadImages : BadFiles {
    // Renders temp/scene.pov (a sphere textured with `image`) and returns the run.
    CommandResult render_with_image(const std::string& image_bytes) {
        temp.write("texture.png", image_bytes);
        temp.write("scene.pov",
                   "camera { location <0, 0, -3> look_at 0 }\nlight_source { <0, 5, -5>, 1 }\n"
                   "sphere { 0, 1\n  pigment { image_map { png \"texture.png\" } } }\n");
        return run_lancer("render " + (temp.path() / "scene.pov").string() + " -o " + output() +
                          " --width 16 --height 16 --integrator raycast 2>&1");
    }
    std::string output() const { return (temp.path() / "out.png").string(); }
};

TEST_F(BadImages, CorruptPngIsALocatedErrorAndWritesNothing) {
    CommandResult result = render_with_image("this is not a PNG at all");
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("scene.pov:4:"), std::string::npos) << result.output;
    EXPECT_NE(result.output.find("cannot read image"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(output()));
}

TEST_F(BadImages, TruncatedPngIsALocatedErrorAndWritesNothing) {
    CommandResult result = render_with_image(kPngHead);
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("scene.pov:4:"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(output()));
}

// A PNG whose whole file is valid but for `damage` applied to the bytes
// after its header: the real texture of scenes/assets, cut or corrupted.
std::string damaged_texture(bool truncate) {
    std::ifstream in(source_path("scenes/assets/uv_grid.png"), std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (truncate) return bytes.substr(0, bytes.size() / 2);
    for (std::size_t i = bytes.size() / 3; i < bytes.size() / 3 + 64 && i < bytes.size(); ++i) bytes[i] ^= 0x5a;
    return bytes;
}

// PNG's CRC-32 (ISO 3309), bit by bit: chunks need it to be read at all.
std::uint32_t png_crc(const std::string& bytes) {
    std::uint32_t crc = 0xffffffffu;
    for (unsigned char byte : bytes) {
        crc ^= byte;
        for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
    return crc ^ 0xffffffffu;
}

// A valid header that decodes (libpng reads the IHDR only) and claims
// 100000 x 100000 pixels in a file of a few dozen bytes.
std::string png_claiming(std::uint32_t width, std::uint32_t height) {
    auto big_endian = [](std::uint32_t v) { return std::string{char(v >> 24), char(v >> 16), char(v >> 8), char(v)}; };
    auto chunk = [&](const std::string& type, const std::string& data) {
        const std::string body = type + data;
        return big_endian(std::uint32_t(data.size())) + body + big_endian(png_crc(body));
    };
    const std::string header = big_endian(width) + big_endian(height) + std::string("\x08\x02\x00\x00\x00", 5);
    // The header is read up to the first IDAT, whose data is never reached.
    return std::string("\x89PNG\r\n\x1a\n", 8) + chunk("IHDR", header) + chunk("IDAT", "not zlib") + chunk("IEND", "");
}

TEST_F(BadImages, TextureCutShortOrCorruptIsAnErrorNotABlackTexture) {
    for (bool truncate : {true, false}) {
        CommandResult result = render_with_image(damaged_texture(truncate));
        EXPECT_EQ(result.exit_code, 1) << result.output;
        EXPECT_NE(result.output.find("scene.pov:4:"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("cannot read image '"), std::string::npos) << result.output;
        EXPECT_NE(result.output.find("texture.png': "), std::string::npos) << result.output;
        EXPECT_FALSE(fs::exists(output()));
    }
}

TEST_F(BadImages, HeaderClaimingHugeSizeIsRefusedBeforeDecoding) {
    CommandResult result = render_with_image(png_claiming(100000, 100000));
    EXPECT_EQ(result.exit_code, 1) << result.output;
    EXPECT_NE(result.output.find("claims 100000 x 100000 pixels"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists(output()));
}

// ---------------------------------------------------------- resource limits

// A string doubled in a loop, or grown by a recursive macro, reached 7 GB
// before std::bad_alloc with no location; concat() now counts against one
// budget and stops at the call that crosses it.
TEST(ResourceLimits, GrowingStringsStopAtALocatedError) {
    ParseOptions options;
    options.max_string_bytes = 1 << 20;
    for (const char* scene :
         {"#declare S = \"ab\";\n#while (1)\n  #declare S = concat(S, S);\n#end\n",
          "#macro Grow(S, N) #if (N > 0) Grow(concat(S, S), N - 1) #end #end\nGrow(\"abc\", 150)\n"}) {
        ParseResult result = parse_scene_string(scene, "grow.pov", options);
        ASSERT_FALSE(result.ok()) << scene;
        EXPECT_NE(all_text(result).find("grow.pov:"), std::string::npos) << all_text(result);
        EXPECT_NE(all_text(result).find("strings have grown past 1 MiB"), std::string::npos) << all_text(result);
    }
    EXPECT_TRUE(parse_scene_string("#declare S = concat(\"a\", \"b\");", "fine.pov", options).ok());
}

// Arrays kept in an array, a union that holds two copies of itself, a
// recursive macro that builds a tree of unions: each grew memory until
// std::bad_alloc (or the machine's end). The parse now stops at its memory
// budget with an error at the loop, the macro call or the array.
TEST(ResourceLimits, GrowingArraysObjectsAndMacrosStopAtTheMemoryBudget) {
    ParseOptions options;
    options.max_memory_bytes = 64 << 20;
    struct Case {
        const char* scene;
        const char* where;
    };
    for (const Case& c : {
             Case{"#declare Keep = array[1000];\n#for (I, 0, 999)\n  #declare Keep[I] = array[100000];\n#end\n",
                  "grow.pov:"},
             Case{
                 "#declare U = sphere { 0, 1 }\n#while (1)\n  #declare U = union { object { U } object { U } }\n#end\n",
                 "grow.pov:2:1: error: the parse holds"},
             Case{"#macro Tree(N) #if (N > 0) union { Tree(N - 1) Tree(N - 1) } #else sphere { 0, 1 } #end #end\n"
                  "object { Tree(40) }\n",
                  "grow.pov:1:"},
             Case{"#declare Big = array[5000000];\n", "grow.pov:1:16: error: this needs about"},
         }) {
        ParseResult result = parse_scene_string(c.scene, "grow.pov", options);
        ASSERT_FALSE(result.ok()) << c.scene;
        EXPECT_NE(all_text(result).find(c.where), std::string::npos) << all_text(result);
        EXPECT_NE(all_text(result).find("past its memory budget of 64 MiB (--max-memory"), std::string::npos)
            << all_text(result);
    }
    EXPECT_TRUE(parse_scene_string("#declare A = array[1000];\n#declare U = union { sphere { 0, 1 } sphere { x, 1 } }",
                                   "fine.pov", options)
                    .ok());
}

TEST(ResourceLimits, MaxTraceLevelOutOfRange) {
    ParseResult result = parse_scene_string("global_settings { max_trace_level 1e9 }", "limits.pov");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("limits.pov:1:35: error: max_trace_level must lie in 1..256, got 1000000000"),
              std::string::npos)
        << all_text(result);
    result = parse_scene_string("global_settings { max_trace_level 1e12 }", "limits.pov");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("limits.pov:1:35: error: integer out of range"), std::string::npos)
        << all_text(result);
}

TEST(ResourceLimits, Mesh2HugeDeclaredCountIsCheckedAgainstTheEntries) {
    // Nothing is reserved from the declared count; it only has to match.
    ParseResult result = parse_scene_string(
        "mesh2 { vertex_vectors { 2000000000, <0,0,0>, <1,0,0>, <0,1,0> } face_indices { 2000000000, <0,1,2> } }",
        "limits.pov");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("declares 2000000000 entries but lists 3"), std::string::npos) << all_text(result);
}

TEST(ResourceLimits, TriangleBudget) {
    ParseOptions options;
    options.max_triangles = 100;
    ParseResult result = parse_scene_string(
        "mesh {\n#for (I, 0, 1000)\n triangle { <I,0,0>, <I+1,0,0>, <I,1,0> }\n#end\n}", "limits.pov", options);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("limits.pov:3:2: error: the scene has more than 100 triangles"), std::string::npos)
        << all_text(result);
}

TEST(ResourceLimits, RenderSizeAndSamples) {
    ParseResult result = parse_scene_string("render_settings { width 100000000 }", "limits.pov");
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("unreasonably large"), std::string::npos) << all_text(result);
}

TEST(ResourceLimits, NestedLoopsStopAtTheTokenBudget) {
    ParseOptions options;
    options.max_loop_iterations = 1000;
    ParseResult result =
        parse_scene_string("#declare A = 0;\n#while (1)\n#declare A = A + 1;\n#end", "limits.pov", options);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("limits.pov:2:1: error: #while loop exceeded 1000 iterations"), std::string::npos)
        << all_text(result);
}

TEST(ResourceLimits, IncludeDepth) {
    TempFolder temp;
    temp.write("self.inc", "#declare N = N + 1;\n#include \"next.inc\"\n");
    temp.write("next.inc", "#include \"self.inc\"\n");
    std::string scene = temp.write("scene.pov", "#declare N = 0;\n#include \"self.inc\"\n");
    ParseResult result = parse_scene_file(scene);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("include cycle"), std::string::npos) << all_text(result);
    // A chain of distinct files stops at max_include_depth.
    for (int i = 0; i < 80; ++i)
        temp.write("chain" + std::to_string(i) + ".inc", "#include \"chain" + std::to_string(i + 1) + ".inc\"\n");
    scene = temp.write("chain.pov", "#include \"chain0.inc\"\n");
    result = parse_scene_file(scene);
    ASSERT_FALSE(result.ok());
    EXPECT_NE(all_text(result).find("#include nested too deeply (more than 64 files)"), std::string::npos)
        << all_text(result);
}

TEST(ResourceLimits, AbsurdResolutionIsRefusedBeforeAllocating) {
    CommandResult result =
        run_lancer("render scenes/demo.pov -o /tmp/lancer-never-written.png --width 100000 --height 100000 2>&1");
    EXPECT_NE(result.exit_code, 0) << result.output;
    EXPECT_NE(result.output.find("GiB"), std::string::npos) << result.output;
    EXPECT_FALSE(fs::exists("/tmp/lancer-never-written.png"));
}

}  // namespace lancer::test
