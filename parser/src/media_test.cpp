// Parsing POV-Ray's media: keywords and POV 3.7's defaults, declared media
// and densities, scene-level media, hollow reaching a union's parts, and
// located errors for values POV refuses.
#include "parse_test_helpers.h"

namespace lancer {
namespace {

using test::first_error;
using test::parse_ok;

const sg::Media& first_media(const sg::SceneGraph& scene) {
    return scene.objects.at(0).material->interior->media.at(0);
}

TEST(ParserMedia, DefaultsAreThoseOfPovRay37) {
    const auto scene = parse_ok("sphere { 0, 1 hollow interior { media { } } }");
    const sg::Media& m = first_media(scene);
    EXPECT_EQ(m.method, 3);
    EXPECT_EQ(m.intervals, 1);
    EXPECT_EQ(m.samples_min, 10);
    EXPECT_EQ(m.samples_max, 10);
    EXPECT_EQ(m.aa_level, 3);
    EXPECT_DOUBLE_EQ(m.aa_threshold, 0.1);
    EXPECT_DOUBLE_EQ(m.ratio, 0.9);
    EXPECT_DOUBLE_EQ(m.confidence, 0.9);
    EXPECT_DOUBLE_EQ(m.variance, 1.0 / 128.0);
    EXPECT_DOUBLE_EQ(m.jitter, 0.0);
    EXPECT_EQ(m.scattering_type, sg::Media::ScatteringType::Isotropic);
    EXPECT_TRUE(scene.objects[0].hollow);
}

TEST(ParserMedia, EveryKeyword) {
    const auto scene = parse_ok(
        "box { 0, 1 hollow interior { media {\n"
        "  emission <0.1, 0.2, 0.3> absorption 0.5\n"
        "  scattering { 5, rgb <0.4, 0.5, 0.6> eccentricity 0.25 extinction 0.75 }\n"
        "  method 3 intervals 4 samples 3, 7 confidence 0.8 variance 0.01 ratio 0.5\n"
        "  aa_level 5 aa_threshold 0.05 jitter 0.3\n"
        "  density { spherical } density { rgb <1, 0.5, 0.25> }\n"
        "} media { absorption 1 } } }");
    const auto& media = scene.objects[0].material->interior->media;
    ASSERT_EQ(media.size(), 2u);
    const sg::Media& m = media[0];
    EXPECT_EQ(m.emission, sg::Vec3(0.1, 0.2, 0.3));
    EXPECT_EQ(m.absorption, sg::Vec3(0.5));
    EXPECT_EQ(m.scattering, sg::Vec3(0.4, 0.5, 0.6));
    EXPECT_EQ(m.scattering_type, sg::Media::ScatteringType::HenyeyGreenstein);
    EXPECT_DOUBLE_EQ(m.eccentricity, 0.25);
    EXPECT_DOUBLE_EQ(m.extinction, 0.75);
    EXPECT_EQ(m.intervals, 4);
    EXPECT_EQ(m.samples_min, 3);
    EXPECT_EQ(m.samples_max, 7);
    EXPECT_EQ(m.aa_level, 5);
    EXPECT_DOUBLE_EQ(m.jitter, 0.3);
    ASSERT_EQ(m.densities.size(), 2u);
    // A density pattern without a map reads as its value in grey.
    ASSERT_TRUE(m.densities[0]->color_map);
    EXPECT_EQ(m.densities[0]->color_map->front().color.rgb, sg::Vec3(0.0));
    EXPECT_EQ(m.densities[0]->color_map->back().color.rgb, sg::Vec3(1.0));
}

TEST(ParserMedia, DeclaredMediaAndDensityAndAtmosphere) {
    const auto scene = parse_ok(
        "#declare Glow = media { emission 0.5 }\n"
        "#declare Blob = density { spherical scale 2 }\n"
        "media { Glow absorption 0.1 }\n"
        "sphere { 0, 1 hollow interior { media { Glow density { Blob } } } }");
    ASSERT_EQ(scene.atmosphere.size(), 1u);
    EXPECT_EQ(scene.atmosphere[0].emission, sg::Vec3(0.5));
    EXPECT_EQ(scene.atmosphere[0].absorption, sg::Vec3(0.1));
    const sg::Media& m = first_media(scene);
    EXPECT_EQ(m.emission, sg::Vec3(0.5));
    ASSERT_EQ(m.densities.size(), 1u);
    EXPECT_EQ(m.densities[0]->pattern->kind, sg::Pattern::Kind::Spherical);
}

TEST(ParserMedia, DensityMapAndLightsMediaSwitches) {
    const auto scene = parse_ok(
        "light_source { 0, 1 media_interaction off media_attenuation on }\n"
        "sphere { 0, 1 hollow interior { media { emission 1 density { spherical density_map {\n"
        "  [0 density { rgb 0 }] [1 density { bozo }] } } } } }");
    EXPECT_FALSE(scene.lights.at(0).media_interaction);
    EXPECT_TRUE(scene.lights.at(0).media_attenuation);
    const sg::Media& m = first_media(scene);
    ASSERT_EQ(m.densities.size(), 1u);
    ASSERT_EQ(m.densities[0]->pigment_map.size(), 2u);
    // The bozo density reads as grey, not as bozo's pigment colours.
    EXPECT_EQ(m.densities[0]->pigment_map[1].pigment->color_map->back().color.rgb, sg::Vec3(1.0));
}

TEST(ParserMedia, HollowReachesEveryPartOfAUnion) {
    const auto scene = parse_ok("union { sphere { 0, 1 } box { 0, 1 } hollow }");
    const auto& group = std::get<sg::Group>(scene.objects[0].shape);
    for (const auto& child : group.children) EXPECT_TRUE(child.hollow);
}

TEST(ParserMedia, ValuesPovRefusesAreLocatedErrors) {
    const Diagnostic eccentric =
        first_error("sphere { 0, 1 interior { media { scattering { 1, 0.5 eccentricity 0.5 } } } }");
    EXPECT_NE(eccentric.message.find("eccentricity"), std::string::npos) << eccentric.message;
    EXPECT_EQ(eccentric.location.line, 1);
    const Diagnostic samples = first_error("media {\n samples 5, 2 }");
    EXPECT_NE(samples.message.find("samples"), std::string::npos) << samples.message;
    EXPECT_EQ(samples.location.line, 2);
    EXPECT_NE(first_error("media { scattering { 7, 1 } }").message.find("type"), std::string::npos);
    EXPECT_NE(first_error("media { intervals 0 }").message.find("intervals"), std::string::npos);
    EXPECT_NE(first_error("media { aa_threshold 0 }").message.find("aa_threshold"), std::string::npos);
    EXPECT_NE(first_error("media { confidence 1 }").message.find("confidence"), std::string::npos);
}

}  // namespace
}  // namespace lancer
