// glTF emissive and occlusion textures (gltf/gltf_materials.cpp,
// gltf/gltf_texture_coords.cpp, render/shading.h's `textured`): which are
// drawn, what the Scene holds, and the pixels a quad renders, worked out by
// hand from the report's shading as test_gltf_textures.cpp does (quads
// facing up, seen straight down; a white matte surface under ambient 0.2
// and a sun of 0.6 straight down is 255 (0.2 + 0.6) = 204, of which the
// ambient term is 51).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gltf/gltf_quads.h"

namespace fh {
namespace {

using namespace gltf_test;

// `members` (", \"emissiveTexture\": ...") added to a matte non-metal
// material of base colour `color`, its base colour texture `texture` (or none).
std::string with(const std::string& color, const std::string& members, const std::string& texture = "") {
    return material(color, texture, members);
}

const std::string kNearestClamp = sampler_json(kClamp, kClamp, kNearest);

TEST(GltfEmission, TheEmissiveTextureTimesTheFactorIsAddedUnlit) {
    // Base colour 0.2 lit: 204 x 0.2 = 40.8 in each channel. Emissive factor
    // (0.4, 0.4, 0.4) = 102 a channel, times the texel's linear colour: the
    // 2 x 1 texture red | blue (nearest, clamped) adds (102, 0, 0) on the
    // left half, (0, 0, 102) on the right. Without any light the emission
    // alone remains.
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        surfaces({with("[0.2, 0.2, 0.2, 1]", ", \"emissiveFactor\": [0.4, 0.4, 0.4], \"emissiveTexture\": {\"index\": 0}")},
                 {{0, 0}}, {image_json(rgba_png(2, 1, kRedBlue))}, {kNearestClamp}));
    const GltfFile f = load(json);
    EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
    EXPECT_EQ(f.scene.materials[0].texture, -1);
    EXPECT_EQ(f.scene.materials[0].emissive_texture, 0);
    EXPECT_EQ(f.scene.meshes[0].mesh->uvs.size(), 4u);  // the emissive texture's coordinates
    for (const Precision p : kPrecisions) {
        const std::string what = precision_name(p);
        const Image im = top_view(lit(json), p);
        expect_columns(im, 0, 4, {143, 41, 41}, what + ", left");
        expect_columns(im, 4, 8, {41, 41, 143}, what + ", right");
        const Image dark = top_view(lit(json, {0.0, 0.0}), p);
        expect_columns(dark, 0, 4, {102, 0, 0}, what + ", unlit left");
        expect_columns(dark, 4, 8, {0, 0, 102}, what + ", unlit right");
    }
}

TEST(GltfEmission, TheEmissiveTexelIsSrgbAndTheBaseColourTextureStillTints) {
    // Base colour texture: sRGB 188 grey (linear 0.50289), factor 1: lit
    // 204 x 0.50289 = 102.59. Emissive texture sRGB (188, 100, 0) on the
    // same coordinates, factor (1, 1, 1) strength 0.2 by
    // KHR_materials_emissive_strength: 255 x 0.2 x (0.50289, 0.12744, 0) =
    // (25.65, 6.50, 0). Sum (128.2, 109.1, 102.6).
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        "\"extensionsUsed\": [\"KHR_materials_emissive_strength\"],\n" +
            surfaces({with("[1, 1, 1, 1]",
                           ", \"emissiveFactor\": [1, 1, 1], \"emissiveTexture\": {\"index\": 1}, \"extensions\": "
                           "{\"KHR_materials_emissive_strength\": {\"emissiveStrength\": 0.2}}",
                           tex(0))},
                     {{-1, 0}, {-1, 1}}, {image_json(rgb_png(1, 1, 188, 188, 188)), image_json(rgb_png(1, 1, 188, 100, 0))}));
    const double grey = 204 * srgb_to_linear(188);
    const Rgb want{int(std::lround(grey + 51 * srgb_to_linear(188))), int(std::lround(grey + 51 * srgb_to_linear(100))),
                   int(std::lround(grey))};
    EXPECT_EQ(want, (Rgb{128, 109, 103}));
    for (const Precision p : kPrecisions) expect_columns(top_view(lit(json), p), 0, 8, want, precision_name(p));
}

TEST(GltfOcclusion, TheRedChannelReadLinearDimsTheAmbientTermAlone) {
    // White base colour. Occlusion texture: left texel (255, 0, 0) --
    // nothing occluded --, right texel (64, 200, 10): R = 64 / 255 =
    // 0.25098, read as data (as sRGB it would be 0.0513). Strength 1: the
    // ambient 51 becomes 51 x 0.25098 = 12.80, the sun's 153 stays: 165.8.
    // Strength 0.5: 51 (1 + 0.5 (0.25098 - 1)) = 31.90, 184.9. The green
    // and blue channels (metal and roughness, in packed textures) are not read.
    for (const double strength : {1.0, 0.5}) {
        const std::string json = quads_file(
            {{-1, 1, -1, 1, 0, 0}},
            surfaces({with("[1, 1, 1, 1]",
                           ", \"occlusionTexture\": {\"index\": 0, \"strength\": " + num(strength) + "}")},
                     {{0, 0}}, {image_json(rgba_png(2, 1, {{255, 0, 0, 255}, {64, 200, 10, 255}}))}, {kNearestClamp}));
        const GltfFile f = load(json);
        EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
        ASSERT_EQ(f.scene.materials[0].occlusion_texture, 0);
        EXPECT_EQ(f.scene.materials[0].occlusion_strength, strength);
        ASSERT_EQ(f.scene.textures.size(), 1u);
        EXPECT_FALSE(f.scene.textures[0].srgb);
        const double right = 51 * (1 + strength * (64 / 255.0 - 1)) + 153;
        const int r = int(std::lround(right));
        EXPECT_EQ(r, strength == 1 ? 166 : 185);
        for (const Precision p : kPrecisions) {
            const std::string what = std::string(precision_name(p)) + ", strength " + num(strength);
            const Image im = top_view(lit(json), p);
            expect_columns(im, 0, 4, {204, 204, 204}, what + ", left");
            expect_columns(im, 4, 8, {r, r, r}, what + ", right");
            // The sun alone: occlusion changes nothing.
            expect_columns(top_view(lit(json, {0.0, 0.6}), p), 0, 8, {153, 153, 153}, what + ", sun only");
        }
    }
}

TEST(GltfOcclusion, OneTextureAsEmissiveColourAndAsOcclusionDataIsReadBothWays) {
    // glTF texture 0 is both: two scene textures, one sRGB and one linear,
    // sharing one decoded image.
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        surfaces({with("[1, 1, 1, 1]",
                       ", \"emissiveFactor\": [1, 1, 1], \"emissiveTexture\": {\"index\": 0}, \"occlusionTexture\": "
                       "{\"index\": 0}")},
                 {{-1, 0}}, {image_json(rgb_png(1, 1, 64, 64, 64))}));
    const Scene& s = load(json).scene;
    ASSERT_EQ(s.textures.size(), 2u);
    const Material<double>& m = s.materials[0];
    ASSERT_GE(m.emissive_texture, 0);
    ASSERT_GE(m.occlusion_texture, 0);
    EXPECT_TRUE(s.textures[size_t(m.emissive_texture)].srgb);
    EXPECT_FALSE(s.textures[size_t(m.occlusion_texture)].srgb);
    EXPECT_EQ(s.textures[0].image, s.textures[1].image);
    // Lit: ambient 51 x 64/255 = 12.80, sun 153, emission 255 x lin(64) = 13.07.
    const int want = int(std::lround(51 * 64 / 255.0 + 153 + 255 * srgb_to_linear(64)));
    for (const Precision p : kPrecisions) expect_columns(top_view(lit(json), p), 0, 8, {want, want, want}, precision_name(p));
}

TEST(GltfEmission, TexturesOnOtherCoordinatesThanTheBaseColoursAreCountedNotDrawn) {
    // Base colour texture on TEXCOORD_0; emissive, normal and
    // metallic-roughness textures on TEXCOORD_1 and an occlusion texture on
    // TEXCOORD_0 moved by a transform: the mesh carries one set of
    // coordinates, so none of them is drawn: one warning counting 4. All
    // five read one grey texel, sRGB 128 (linear 0.21586): the base colour
    // lit, 204 x 0.21586 = 44.04, plus the emissive factor untextured, 51 in
    // green: (44, 95, 44). (Drawn, the emissive texel would make the green
    // 44 + 11.0, the occlusion the grey 38.6.)
    Quad q{-1, 1, -1, 1, 0, 0};
    q.uv1 = {0, 0, 1, 0, 1, 1, 0, 1};
    const std::string rest =
        "\"extensionsUsed\": [\"KHR_texture_transform\"],\n" +
        surfaces({"{\"pbrMetallicRoughness\": {\"baseColorFactor\": [1, 1, 1, 1], \"metallicFactor\": 0, "
                  "\"roughnessFactor\": 1, \"baseColorTexture\": {\"index\": 0}, \"metallicRoughnessTexture\": "
                  "{\"index\": 0, \"texCoord\": 1}}, \"normalTexture\": {\"index\": 0, \"texCoord\": 1}, \"emissiveFactor\": [0, 0.2, 0], "
                  "\"emissiveTexture\": {\"index\": 0, \"texCoord\": 1}, \"occlusionTexture\": {\"index\": 0, "
                  "\"extensions\": {\"KHR_texture_transform\": {\"offset\": [0.5, 0]}}}}"},
                 {{-1, 0}}, {image_json(rgb_png(1, 1, 128, 128, 128))});
    const std::string json = quads_file({q}, rest);
    const GltfFile f = load(json);
    ASSERT_EQ(f.warnings.size(), 1u);
    EXPECT_EQ(f.warnings[0],
              "t.gltf: warning: 4 texture(s) not drawn (emissive, occlusion, normal or metallic-roughness textures "
              "on other coordinates than their mesh carries)");
    EXPECT_EQ(f.scene.materials[0].texture, 0);
    EXPECT_EQ(f.scene.materials[0].emissive_texture, -1);
    EXPECT_EQ(f.scene.materials[0].occlusion_texture, -1);
    EXPECT_EQ(f.scene.materials[0].normal_texture, -1);
    const int grey = int(std::lround(204 * srgb_to_linear(128)));
    EXPECT_EQ(grey, 44);
    for (const Precision p : kPrecisions)
        expect_columns(top_view(lit(json), p), 0, 8, {grey, grey + 51, grey}, precision_name(p));

    // The same textures on the base colour's own coordinates are drawn.
    std::string same = rest;
    for (const std::string from : {std::string(", \"texCoord\": 1"),
                                   std::string(", \"extensions\": {\"KHR_texture_transform\": {\"offset\": [0.5, 0]}}")})
        for (size_t at; (at = same.find(from)) != std::string::npos;) same.erase(at, from.size());
    const GltfFile g = load(quads_file({q}, same));
    EXPECT_TRUE(g.warnings.empty()) << g.warnings[0];
    EXPECT_GE(g.scene.materials[0].emissive_texture, 0);
    EXPECT_GE(g.scene.materials[0].occlusion_texture, 0);
    EXPECT_GE(g.scene.materials[0].normal_texture, 0);
    EXPECT_GE(g.scene.materials[0].metal_rough_texture, 0);
}

TEST(GltfEmission, ATransformsTexCoordNamesTheSetAMeshMustHave) {
    // The first test's quad and emissive texture, its coordinates in
    // TEXCOORD_1 only: the emissive and normal textures say texCoord 0, but
    // their KHR_texture_transform's texCoord 1 overrides it, so the file
    // is whole (it was refused for lacking TEXCOORD_0) and the emission
    // drawn as before; so is the normal texture, whose one texel (128,
    // 128, 255) leaves the normal as it is to a 1e-5 of the sun's light.
    Quad q{-1, 1, -1, 1, 0, 0};
    q.uvs = false;
    q.uv1 = {0, 0, 1, 0, 1, 1, 0, 1};
    const std::string to_set_1 = "\"texCoord\": 0, \"extensions\": {\"KHR_texture_transform\": {\"texCoord\": 1}}";
    const std::string json = quads_file(
        {q}, "\"extensionsUsed\": [\"KHR_texture_transform\"],\n" +
                 surfaces({with("[0.2, 0.2, 0.2, 1]", ", \"emissiveFactor\": [0.4, 0.4, 0.4], \"emissiveTexture\": {\"index\": 0, " +
                                                          to_set_1 + "}, \"normalTexture\": {\"index\": 1, " + to_set_1 + "}")},
                          {{0, 0}, {-1, 1}}, {image_json(rgba_png(2, 1, kRedBlue)), image_json(rgb_png(1, 1, 128, 128, 255))},
                          {kNearestClamp}));
    const GltfFile f = load(json);
    EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
    EXPECT_EQ(f.scene.materials[0].emissive_texture, 0);
    EXPECT_EQ(f.scene.materials[0].normal_texture, 1);
    for (const Precision p : kPrecisions) {
        const Image im = top_view(lit(json), p);
        expect_columns(im, 0, 4, {143, 41, 41}, std::string(precision_name(p)) + ", left");
        expect_columns(im, 4, 8, {41, 41, 143}, std::string(precision_name(p)) + ", right");
    }
    // Without the override the material reads TEXCOORD_0, which it lacks.
    std::string plain = json;
    for (size_t at; (at = plain.find(", \"extensions\": {\"KHR_texture_transform\": {\"texCoord\": 1}}")) != std::string::npos;)
        plain.erase(at, std::string(", \"extensions\": {\"KHR_texture_transform\": {\"texCoord\": 1}}").size());
    expect_input_error([&] { load(plain); }, "t.gltf", "its material reads TEXCOORD_0, which it does not have");
}

TEST(GltfOcclusion, AStrengthOutsideZeroToOneIsRefused) {
    for (const std::string strength : {"1.5", "-0.25"}) {
        const std::string json = quads_file(
            {{-1, 1, -1, 1, 0, 0}},
            surfaces({with("[1, 1, 1, 1]", ", \"occlusionTexture\": {\"index\": 0, \"strength\": " + strength + "}")},
                     {{-1, 0}}, {image_json(rgb_png(1, 1, 9, 9, 9))}));
        expect_input_error([&] { load(json); }, "t.gltf", "occlusionTexture's strength must be in [0, 1]");
    }
}

TEST(GltfEmission, TheTextureIndicesFollowTheirFileIntoAScene) {
    // The same file placed twice: the second copy's materials name the
    // second copy's textures.
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        surfaces({with("[1, 1, 1, 1]",
                       ", \"emissiveFactor\": [1, 1, 1], \"emissiveTexture\": {\"index\": 0}, \"occlusionTexture\": "
                       "{\"index\": 1}")},
                 {{-1, 0}, {-1, 1}}, {image_json(rgb_png(1, 1, 64, 64, 64)), image_json(rgb_png(1, 1, 9, 9, 9))}));
    Scene s;
    add_gltf(s, load(json), "a", {});
    add_gltf(s, load(json), "b", {});
    ASSERT_EQ(s.textures.size(), 4u);
    const Material<double>& a = s.materials[0];
    const Material<double>& b = s.materials[2];  // after a's material and its glTF default
    EXPECT_EQ(b.emissive_texture, a.emissive_texture + 2);
    EXPECT_EQ(b.occlusion_texture, a.occlusion_texture + 2);
    EXPECT_TRUE(s.textures[size_t(b.emissive_texture)].srgb);
    EXPECT_FALSE(s.textures[size_t(b.occlusion_texture)].srgb);
}

}  // namespace
}  // namespace fh
