// What `lancer render` hands the user beside the beauty: the --aov layers
// in one EXR (checked against Intel Open Image Denoise's input contract and
// against the scene's geometry), the alpha channel against POV-Ray 3.7's
// own +UA renders (tests/reference/pov/alpha/), JPEG, 16-bit PNG, and
// metadata that tells the truth.
#include <OpenImageIO/imageio.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "lancer/host/aov.h"
#include "lancer/host/image_io.h"
#include "run_command.h"
#include "temp_folder.h"

namespace lancer::test {
namespace {

namespace fs = std::filesystem;

#define EXPECT_CONTAINS(text, part) EXPECT_NE(std::string(text).find(part), std::string::npos) << "in: " << (text)

// Every channel of an image as stored (alpha not multiplied in on reading).
struct StoredImage {
    int width = 0, height = 0;
    OIIO::ImageSpec spec;
    std::vector<float> values;

    int channel(const std::string& name) const {
        for (int c = 0; c < spec.nchannels; ++c)
            if (spec.channelnames[c] == name) return c;
        return -1;
    }
    float at(int x, int y, const std::string& name) const {
        const int c = channel(name);
        EXPECT_GE(c, 0) << "no channel " << name;
        return c < 0 ? 0.0f : values[(std::size_t(y) * width + x) * spec.nchannels + c];
    }
    std::string metadata(const std::string& key) const { return spec.get_string_attribute(key); }
};

StoredImage read_stored(const std::string& path) {
    StoredImage image;
    OIIO::ImageSpec config;
    config.attribute("oiio:UnassociatedAlpha", 1);
    auto input = OIIO::ImageInput::open(path, &config);
    if (!input) {
        ADD_FAILURE() << "cannot read " << path;
        return image;
    }
    image.spec = input->spec();
    image.width = image.spec.width;
    image.height = image.spec.height;
    image.values.resize(std::size_t(image.width) * image.height * image.spec.nchannels);
    input->read_image(0, 0, 0, image.spec.nchannels, OIIO::TypeDesc::FLOAT, image.values.data());
    return image;
}

// A plane, a matte sphere, a mirror sphere and a clear glass sphere.
constexpr const char* kGuidesScene =
    "camera { location <0, 1.5, -5> look_at <0, 0.6, 0> angle 55 }\n"
    "light_source { <4, 6, -5> color rgb 1 }\n"
    "plane { y, 0 pigment { checker rgb <0.8, 0.2, 0.2> rgb 0.9 } }\n"
    "sphere { <-1.5, 0.6, 0>, 0.6 pigment { rgb <0.2, 0.7, 0.3> } }\n"
    "sphere { <0, 0.6, 0>, 0.6 pigment { rgb 1 } finish { diffuse 0 reflection 1 } }\n"
    "sphere { <1.5, 0.6, 0>, 0.6 pigment { rgbf 1 } finish { diffuse 0 } interior { ior 1.5 } }\n";
constexpr float kCamera[3] = {0.0f, 1.5f, -5.0f};
constexpr float kMatteCentre[3] = {-1.5f, 0.6f, 0.0f}, kMirrorCentre[3] = {0.0f, 0.6f, 0.0f},
                kGlassCentre[3] = {1.5f, 0.6f, 0.0f};
constexpr float kRadius = 0.6f;

class RenderOutputs : public ::testing::Test {
  protected:
    std::string path(const std::string& name) const { return (m_folder.path() / name).string(); }
    CommandResult render(const std::string& scene, const std::string& output, const std::string& extra) {
        return run_lancer("render '" + scene + "' --width 64 --height 48 -q -o '" + path(output) + "' " + extra);
    }
    std::string guides_scene() { return m_folder.write("guides.pov", kGuidesScene); }

    TempFolder m_folder;
};

float distance_to(const StoredImage& image, int x, int y, const float centre[3]) {
    const float dx = image.at(x, y, "P.X") - centre[0], dy = image.at(x, y, "P.Y") - centre[1],
                dz = image.at(x, y, "P.Z") - centre[2];
    return std::sqrt(dx * dx + dy * dy + dz * dz);
}

TEST(AovList, ParsesKnownNamesOnceEach) {
    std::string problem;
    const std::vector<Aov> layers = parse_aov_list("normal,albedo,depth", problem);
    EXPECT_TRUE(problem.empty()) << problem;
    EXPECT_EQ(layers, (std::vector<Aov>{Aov::Normal, Aov::Albedo, Aov::Depth}));
    EXPECT_TRUE(parse_aov_list("albedo,colour", problem).empty());
    EXPECT_CONTAINS(problem, "unknown AOV 'colour'");
    EXPECT_CONTAINS(problem, "position");
    EXPECT_TRUE(parse_aov_list("depth,depth", problem).empty());
    EXPECT_CONTAINS(problem, "named twice");
    EXPECT_TRUE(parse_aov_list("", problem).empty());
    EXPECT_EQ(aov_samples_for(0.2), 1);
    EXPECT_EQ(aov_samples_for(4.0), 4);
    EXPECT_EQ(aov_samples_for(900.0), 16);
}

TEST_F(RenderOutputs, EveryLayerInOneExrBesideTheBeauty) {
    const CommandResult result =
        render(guides_scene(), "all.exr", "-i whitted --aov albedo,normal,depth,position,alpha");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const StoredImage image = read_stored(path("all.exr"));
    ASSERT_EQ(image.width, 64);
    for (const char* name :
         {"R", "G", "B", "A", "albedo.R", "albedo.G", "albedo.B", "N.X", "N.Y", "N.Z", "Z", "P.X", "P.Y", "P.Z"})
        EXPECT_GE(image.channel(name), 0) << name << " missing";
}

// OIDN's contract: albedo linear in [0, 1], normals unencoded in [-1, 1];
// both taken through perfect mirrors and clear glass, never black there.
TEST_F(RenderOutputs, AlbedoAndNormalFollowTheDenoiserContract) {
    ASSERT_EQ(render(guides_scene(), "guides.exr", "-i whitted --aov albedo,normal,position,depth").exit_code, 0);
    const StoredImage image = read_stored(path("guides.exr"));
    int matte = 0, plane = 0, mirror = 0, mirror_lit = 0, glass = 0, glass_lit = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float albedo[3] = {image.at(x, y, "albedo.R"), image.at(x, y, "albedo.G"),
                                     image.at(x, y, "albedo.B")};
            for (float a : albedo) {
                EXPECT_GE(a, 0.0f);
                EXPECT_LE(a, 1.0f);
            }
            const float n[3] = {image.at(x, y, "N.X"), image.at(x, y, "N.Y"), image.at(x, y, "N.Z")};
            const float length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
            if (std::isinf(image.at(x, y, "Z"))) {
                EXPECT_EQ(length, 0.0f) << "a pixel that hits nothing has no normal";
                continue;
            }
            const float brightest = std::max({albedo[0], albedo[1], albedo[2]});
            if (std::abs(distance_to(image, x, y, kMatteCentre) - kRadius) < 1e-3f) {
                ++matte;  // the sphere's own normal and pigment
                EXPECT_NEAR(length, 1.0f, 1e-3f);
                for (int c = 0; c < 3; ++c)
                    EXPECT_NEAR(n[c],
                                (image.at(x, y,
                                          c == 0   ? "P.X"
                                          : c == 1 ? "P.Y"
                                                   : "P.Z") -
                                 kMatteCentre[c]) /
                                    kRadius,
                                2e-3f);
                EXPECT_NEAR(albedo[1], 0.7f * 0.6f, 1e-3f);  // pigment x POV's default diffuse 0.6
            } else if (std::abs(image.at(x, y, "P.Y")) < 1e-3f) {
                ++plane;
                EXPECT_NEAR(n[1], 1.0f, 1e-3f);
            } else if (std::abs(distance_to(image, x, y, kMirrorCentre) - kRadius) < 1e-3f) {
                ++mirror;
                mirror_lit += brightest > 0.05f;
            } else if (std::abs(distance_to(image, x, y, kGlassCentre) - kRadius) < 1e-3f) {
                ++glass;
                glass_lit += brightest > 0.05f;
            }
        }
    EXPECT_GT(matte, 50);
    EXPECT_GT(plane, 500);
    EXPECT_GT(mirror, 50);
    EXPECT_GT(glass, 50);
    // The mirror shows the plane below its equator, the glass the plane
    // behind it: most of each is the albedo of what they show.
    EXPECT_GT(mirror_lit, mirror / 3);
    EXPECT_GT(glass_lit, glass / 2);
}

// Z is the distance from the camera to the position P, which lies on the
// scene's surfaces.
TEST_F(RenderOutputs, DepthIsTheDistanceToThePosition) {
    ASSERT_EQ(render(guides_scene(), "depth.exr", "-i path --spp 2 --aov depth,position").exit_code, 0);
    const StoredImage image = read_stored(path("depth.exr"));
    int hits = 0, misses = 0;
    for (int y = 0; y < image.height; ++y)
        for (int x = 0; x < image.width; ++x) {
            const float z = image.at(x, y, "Z");
            if (std::isinf(z)) {
                ++misses;
                EXPECT_EQ(image.at(x, y, "P.X"), 0.0f);
                continue;
            }
            const float dx = image.at(x, y, "P.X") - kCamera[0], dy = image.at(x, y, "P.Y") - kCamera[1],
                        dz = image.at(x, y, "P.Z") - kCamera[2];
            const float to_position = std::sqrt(dx * dx + dy * dy + dz * dz);
            // Pixels whose two samples hit different surfaces hold means
            // of both; the rest agree to float precision.
            hits += std::abs(z - to_position) < 1e-3f * z;
        }
    EXPECT_GT(misses, 100);  // the sky above the horizon
    EXPECT_GT(hits, (64 * 48 - misses) * 9 / 10);
}

// Each scene of tests/reference/pov/alpha/ against POV-Ray's +UA render:
// a 16-bit RGBA PNG, straight alpha, that lancer must match code value
// for code value (alpha within one 16-bit step, colour within three).
class PovAlpha : public RenderOutputs, public ::testing::WithParamInterface<const char*> {};

TEST_P(PovAlpha, MatchesPovRayPlusUA) {
    const std::string name = GetParam();
    const std::string scene = source_path("tests/reference/pov/alpha/" + name + ".pov");
    const CommandResult result = run_lancer("render '" + scene + "' -i whitted --width 160 --height 120 --spp 1 -q " +
                                            "--alpha --bits 16 -o '" + path(name + ".png") + "'");
    ASSERT_EQ(result.exit_code, 0) << result.output;
    const StoredImage ours = read_stored(path(name + ".png"));
    const StoredImage pov = read_stored(source_path("tests/reference/pov/alpha/" + name + ".png"));
    ASSERT_EQ(ours.spec.nchannels, 4);
    ASSERT_EQ(pov.spec.nchannels, 4);
    ASSERT_EQ(ours.values.size(), pov.values.size());
    int alpha_off = 0, colour_off = 0, translucent = 0;
    for (std::size_t i = 0; i < ours.values.size(); i += 4) {
        alpha_off += std::abs(ours.values[i + 3] - pov.values[i + 3]) > 1.5f / 65535.0f;
        translucent += pov.values[i + 3] > 0.0f && pov.values[i + 3] < 1.0f;
        if (pov.values[i + 3] == 0.0f) continue;  // no colour to compare
        for (int c = 0; c < 3; ++c) colour_off += std::abs(ours.values[i + c] - pov.values[i + c]) > 3.0f / 65535.0f;
    }
    EXPECT_EQ(alpha_off, 0);
    EXPECT_EQ(colour_off, 0);
    if (name != "alpha_opaque_background") {
        EXPECT_GT(translucent, 1000);
    }
}

INSTANTIATE_TEST_SUITE_P(Scenes, PovAlpha,
                         ::testing::Values("alpha_no_background", "alpha_background_transmit",
                                           "alpha_opaque_background"));

// POV-Ray writes EXR premultiplied, PNG straight; the beauty is the same
// with or without an alpha channel.
TEST_F(RenderOutputs, ExrIsPremultipliedAndPngStraight) {
    const std::string scene = source_path("tests/reference/pov/alpha/alpha_background_transmit.pov");
    ASSERT_EQ(render(scene, "alpha.exr", "-i whitted --alpha").exit_code, 0);
    ASSERT_EQ(render(scene, "plain.exr", "-i whitted").exit_code, 0);
    ASSERT_EQ(render(scene, "alpha.png", "-i whitted --alpha --bits 16").exit_code, 0);
    const StoredImage exr = read_stored(path("alpha.exr")), plain = read_stored(path("plain.exr")),
                      png = read_stored(path("alpha.png"));
    ASSERT_EQ(exr.spec.nchannels, 4);
    ASSERT_EQ(plain.spec.nchannels, 3);
    for (int y = 0; y < exr.height; y += 3)
        for (int x = 0; x < exr.width; x += 3) {
            const float alpha = exr.at(x, y, "A");
            ASSERT_NEAR(alpha, png.at(x, y, "A"), 1e-4f);
            for (const char* c : {"R", "G", "B"}) {
                EXPECT_FLOAT_EQ(exr.at(x, y, c), plain.at(x, y, c));
                EXPECT_NEAR(srgb_to_linear(png.at(x, y, c)) * alpha, exr.at(x, y, c), 2e-4f);
            }
        }
    // The sky: rgbt <0.2, 0.4, 0.8, 0.4> is 0.6 opaque, straight 0.2 red.
    EXPECT_NEAR(exr.at(0, 0, "A"), 0.6f, 1e-6f);
    EXPECT_NEAR(exr.at(0, 0, "R"), 0.12f, 1e-6f);
    EXPECT_NEAR(srgb_to_linear(png.at(0, 0, "R")), 0.2f, 1e-4f);
}

TEST_F(RenderOutputs, PovSwitchesForAlphaLastOneWins) {
    const std::string scene = guides_scene();
    ASSERT_EQ(render(scene, "plus.png", "+UA").exit_code, 0);
    ASSERT_EQ(render(scene, "minus.png", "+UA -UA").exit_code, 0);
    ASSERT_EQ(render(scene, "again.png", "-UA +UA").exit_code, 0);
    EXPECT_EQ(read_stored(path("plus.png")).spec.nchannels, 4);
    EXPECT_EQ(read_stored(path("minus.png")).spec.nchannels, 3);
    EXPECT_EQ(read_stored(path("again.png")).spec.nchannels, 4);
}

TEST_F(RenderOutputs, SixteenBitPngAgreesWithEightBit) {
    const std::string scene = guides_scene();
    ASSERT_EQ(render(scene, "eight.png", "").exit_code, 0);
    ASSERT_EQ(render(scene, "sixteen.png", "--bits 16").exit_code, 0);
    const StoredImage eight = read_stored(path("eight.png")), sixteen = read_stored(path("sixteen.png"));
    EXPECT_EQ(eight.spec.format, OIIO::TypeDesc::UINT8);
    EXPECT_EQ(sixteen.spec.format, OIIO::TypeDesc::UINT16);
    ASSERT_EQ(eight.values.size(), sixteen.values.size());
    int finer = 0;
    for (std::size_t i = 0; i < eight.values.size(); ++i) {
        EXPECT_NEAR(eight.values[i], sixteen.values[i], 0.5f / 255.0f + 1e-6f);
        finer += std::abs(std::round(sixteen.values[i] * 255.0f) / 255.0f - sixteen.values[i]) > 1e-4f;
    }
    EXPECT_GT(finer, int(eight.values.size()) / 2) << "the 16-bit file holds only 8-bit values";
}

TEST_F(RenderOutputs, JpegWithAQuality) {
    const std::string scene = guides_scene();
    ASSERT_EQ(render(scene, "best.jpg", "--quality 100").exit_code, 0);
    ASSERT_EQ(render(scene, "small.jpeg", "--quality 10").exit_code, 0);
    ASSERT_EQ(render(scene, "reference.png", "").exit_code, 0);
    const StoredImage best = read_stored(path("best.jpg")), small = read_stored(path("small.jpeg")),
                      reference = read_stored(path("reference.png"));
    EXPECT_EQ(best.spec.nchannels, 3);
    EXPECT_LT(fs::file_size(path("small.jpeg")) * 2, fs::file_size(path("best.jpg")));
    double best_error = 0.0, small_error = 0.0;
    for (std::size_t i = 0; i < reference.values.size(); ++i) {
        best_error += std::abs(best.values[i] - reference.values[i]);
        small_error += std::abs(small.values[i] - reference.values[i]);
    }
    best_error /= double(reference.values.size());
    small_error /= double(reference.values.size());
    EXPECT_LT(best_error, 0.01);
    EXPECT_LT(best_error * 2, small_error);
}

TEST_F(RenderOutputs, MetadataSaysHowLongTheRenderTook) {
    ASSERT_EQ(render(guides_scene(), "timed.exr", "-i path --spp 2").exit_code, 0);
    const StoredImage image = read_stored(path("timed.exr"));
    const double seconds = std::stod(image.metadata("lancer:seconds"));
    const double render_seconds = std::stod(image.metadata("lancer:render_seconds"));
    EXPECT_GT(render_seconds, 0.0);
    EXPECT_GE(seconds, render_seconds);
    EXPECT_EQ(image.metadata("lancer:integrator"), "path");
}

TEST_F(RenderOutputs, OptionsTheFormatCannotHoldAreErrors) {
    const std::string scene = guides_scene();
    const struct {
        const char* output;
        const char* options;
        const char* says;
    } cases[] = {
        {"x.png", "--aov albedo", "multi-layer EXR"},
        {"x.jpg", "--alpha", "needs a format that holds one"},
        {"x.hdr", "--aov alpha", "needs a format that holds one"},
        {"x.hdr", "--alpha", "needs a format that holds one"},
        {"x.exr", "--bits 16", "--bits chooses a PNG's depth"},
        {"x.png", "--bits 12", "--bits must be 8 or 16"},
        {"x.jpg", "--quality 0", "--quality must be 1 to 100"},
        {"x.png", "--quality 50", "--quality is a JPEG's"},
        {"x.exr", "--aov albedo,colour", "unknown AOV 'colour'"},
        {"x.exr", "--aov ''", "no AOV named"},
    };
    for (const auto& bad : cases) {
        const CommandResult result = render(scene, bad.output, bad.options);
        EXPECT_NE(result.exit_code, 0) << bad.options;
        EXPECT_CONTAINS(result.output, bad.says);
        EXPECT_FALSE(fs::exists(path(bad.output))) << bad.options;
    }
}

TEST_F(RenderOutputs, PreviewArgumentsAreChecked) {
    CommandResult result = render(guides_scene(), "x.png", "--port 8080");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_CONTAINS(result.output, "--port is the preview's: add --preview");
    result = run_lancer("live '" + path("missing.pov") + "'");
    EXPECT_EQ(result.exit_code, 1);
    EXPECT_CONTAINS(result.output, "no such file");
    result = run_lancer("live '" + guides_scene() + "' --width 10");
    EXPECT_EQ(result.exit_code, 2);
    EXPECT_CONTAINS(result.output, "--width and --height go together");
}

}  // namespace
}  // namespace lancer::test
