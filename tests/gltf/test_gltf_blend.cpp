// glTF's alphaMode BLEND (render/shading.h's go_on, render/cutouts.h): a
// see-through surface's colour counts by its opacity a, what lies behind
// it by 1 - a, and a shadow ray through it carries 1 - a of its light on
// (render/cutouts.h's light_through: the diffuse and specular terms of a
// point behind it are dimmed so). Pixels worked
// out by hand as test_gltf_textures.cpp does: quads facing up, seen straight
// down, ambient 0.2 and a sun of 0.6 straight down, so a lit white matte
// surface is 204 and one in shadow 51 (the ambient term alone).
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "gltf/gltf_quads.h"

namespace fh {
namespace {

using namespace gltf_test;

std::string blend(const std::string& color, const std::string& texture = "") {
    return material(color, texture, ", \"alphaMode\": \"BLEND\"");
}

// The render's ray counts, as top_view renders it.
RayCounts counts_of(const Scene& s, Precision precision) {
    RenderSettings settings;
    settings.precision = precision;
    return render_frame(s, top_camera(), settings, nullptr).counts;
}

TEST(GltfBlend, ReadAsSeeThroughWithTheFactorsAlphaAndNoWarning) {
    const std::string json =
        quads_file({{-1, 1, -1, 1, 1, 0}}, surfaces({blend("[1, 0, 0, 0.3]"), material("[1, 1, 1, 0.3]")}));
    const GltfFile f = load(json);
    EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
    EXPECT_TRUE(f.scene.materials[0].blend);
    EXPECT_FALSE(f.scene.materials[0].cutout);
    EXPECT_DOUBLE_EQ(f.scene.materials[0].alpha, 0.3);
    EXPECT_FALSE(f.scene.materials[1].blend);  // OPAQUE: its alpha is not read
}

TEST(GltfBlend, TheColourIsAlphaTimesTheSurfacePlusTheRestFromBehind) {
    // A white BLEND quad at height 1 over an opaque red one at 0. The white
    // is lit, 204; the sun reaches the red through it dimmed to 1 - alpha:
    //  - alpha 0.25: the red 51 + 153 x 0.75 = 165.75, and
    //    0.25 (204, 204, 204) + 0.75 (165.75, 0, 0) = (175.31, 51, 51);
    //  - alpha 0.75: the red 51 + 153 x 0.25 = 89.25, and
    //    0.75 (204, 204, 204) + 0.25 (89.25, 0, 0) = (175.31, 153, 153).
    struct Case {
        std::string alpha;
        Rgb want;
    };
    for (const Case& c : {Case{"0.25", {175, 51, 51}}, Case{"0.75", {175, 153, 153}}}) {
        const std::string json = quads_file({{-1, 1, -1, 1, 1, 0}, {-1, 1, -1, 1, 0, 1}},
                                            surfaces({blend("[1, 1, 1, " + c.alpha + "]"), material("[1, 0, 0, 1]")}));
        for (const Precision p : kPrecisions) {
            const std::string what = std::string(precision_name(p)) + ", alpha " + c.alpha;
            expect_columns(top_view(lit(json), p), 0, 8, c.want, what);
            // Each of the 64 camera rays goes on past the white quad once.
            const RayCounts n = counts_of(lit(json), p);
            EXPECT_EQ(n.transmitted, 64u) << what;
            EXPECT_EQ(n.total(), n.primary + n.shadow + n.reflection + n.transmitted) << what;
        }
    }
}

TEST(GltfBlend, PacketsMixingPaneAndWorldLanesOverTheWorldsOwnPlane) {
    // The pane (alpha 0.25) covers x in [-1, -0.5] only, above a plane of
    // the world's own at z = 0 given the file's red material: columns 0-1
    // (x = -0.825, -0.575) see through the pane onto the plane, which it
    // dims as above: (175.31, 51, 51); columns 2-7 the plane alone, lit
    // red. Every packet holds lanes of both at depth 0, and the world's
    // plane takes the opacity-1 path of primitives that are not instances.
    const std::string json =
        quads_file({{-1, -0.5, -1, 1, 1, 0}}, surfaces({blend("[1, 1, 1, 0.25]"), material("[1, 0, 0, 1]")}));
    for (const Precision p : kPrecisions) {
        Scene s = lit(json);
        ASSERT_EQ(s.material_names[1], "m/material 1");
        s.planes.push_back({{0, 0, 1}, 0, 1});
        const Image im = top_view(s, p);
        expect_columns(im, 0, 2, {175, 51, 51}, std::string(precision_name(p)) + ", through the pane");
        expect_columns(im, 2, 8, {204, 0, 0}, std::string(precision_name(p)) + ", the plane alone");
        EXPECT_EQ(counts_of(s, p).transmitted, 16u) << precision_name(p);
    }
}

TEST(GltfBlend, TheTexturesAlphaMultipliesTheFactors) {
    // The white quad's texture: left texel alpha 0, right alpha 1 (nearest,
    // clamped), factor alpha 1: the left half shows the red quad, lit (all
    // the light comes through where alpha is 0); the right half the white
    // quad, 204, and the red under it is in its shadow (not seen).
    const std::vector<Bytes4> half = {{255, 255, 255, 0}, {255, 255, 255, 255}};
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 1, 0}, {-1, 1, -1, 1, 0, 1}},
        surfaces({blend("[1, 1, 1, 1]", tex(0)), material("[1, 0, 0, 1]")}, {{0, 0}},
                 {image_json(rgba_png(2, 1, half))}, {sampler_json(kClamp, kClamp, kNearest)}));
    for (const Precision p : kPrecisions) {
        const Image im = top_view(lit(json), p);
        expect_columns(im, 0, 4, {204, 0, 0}, std::string(precision_name(p)) + ", left");
        expect_columns(im, 4, 8, {204, 204, 204}, std::string(precision_name(p)) + ", right");
    }
}

TEST(GltfBlend, LayersCompositeFrontToBack) {
    // Three white quads of alpha 0.5 at heights 3, 2, 1 over the red at 0,
    // each a mesh of its own. The sun reaches each through the ones above
    // it, halved by each: 204 at the top, then 51 + 153 / 2 = 127.5,
    // 51 + 153 / 4 = 89.25, and the red 51 + 153 / 8 = 70.125.
    //   0.5 x 204 + 0.25 x 127.5 + 0.125 x 89.25 + 0.125 x (70.125, 0, 0)
    //   = (153.80, 145.03, 145.03)
    const std::string json =
        quads_file({{-1, 1, -1, 1, 3, 0}, {-1, 1, -1, 1, 2, 0}, {-1, 1, -1, 1, 1, 0}, {-1, 1, -1, 1, 0, 1}},
                   surfaces({blend("[1, 1, 1, 0.5]"), material("[1, 0, 0, 1]")}));
    for (const Precision p : kPrecisions) {
        const Image im = top_view(lit(json), p);
        expect_columns(im, 0, 8, {154, 145, 145}, precision_name(p));
        EXPECT_EQ(counts_of(lit(json), p).transmitted, 3u * 64u) << precision_name(p);
    }
}

TEST(GltfBlend, TwoLayersOfOneMeshDimTheLightTwice) {
    // Two white layers of alpha 0.5 in one mesh (heights 1 and 1.01) over
    // the red: a shadow ray from the red crosses both in one walk of that
    // mesh. The top lit, 204; the lower 51 + 153 / 2 = 127.5; the red
    // 51 + 153 / 4 = 89.25:
    //   0.5 x 204 + 0.25 x 127.5 + 0.25 x (89.25, 0, 0) = (156.19, 133.88, 133.88)
    Quad pane{-1, 1, -1, 1, 1, 0};
    pane.layers = 2;
    const std::string json =
        quads_file({pane, {-1, 1, -1, 1, 0, 1}}, surfaces({blend("[1, 1, 1, 0.5]"), material("[1, 0, 0, 1]")}));
    for (const Precision p : kPrecisions) expect_columns(top_view(lit(json), p), 0, 8, {156, 134, 134}, precision_name(p));
}

TEST(GltfBlend, AnOpaqueSurfaceOnTheWayStillCastsAWholeShadow) {
    // The pane (alpha 0.25) at height 2 over the red at 0, and an opaque
    // white quad over the right half at height 11, above the camera (at 10)
    // so that only shadow rays meet it. Left half: the pane lit, 204, the
    // red dimmed by it to 51 + 153 x 0.75 = 165.75:
    //   0.25 x 204 + 0.75 x (165.75, 0, 0) = (175.31, 51, 51).
    // Right half: no light reaches the pane or the red, whatever the pane
    // lets through: 0.25 x 51 + 0.75 x (51, 0, 0) = (51, 12.75, 12.75).
    const std::string json =
        quads_file({{-1, 1, -1, 1, 2, 0}, {0, 1, -1, 1, 11, 2}, {-1, 1, -1, 1, 0, 1}},
                   surfaces({blend("[1, 1, 1, 0.25]"), material("[1, 0, 0, 1]"), material("[1, 1, 1, 1]")}));
    for (const Precision p : kPrecisions) {
        const Image im = top_view(lit(json), p);
        expect_columns(im, 0, 4, {175, 51, 51}, std::string(precision_name(p)) + ", left");
        expect_columns(im, 4, 8, {51, 13, 13}, std::string(precision_name(p)) + ", right");
    }
}

TEST(GltfBlend, ARayGoesPastAtMost64SurfacesAndSeesTheNextAsOpaque) {
    // n fully transparent white layers (alpha 0) over the red quad. With 63
    // the camera rays go past all of them and the red shows, lit (a shadow
    // ray crosses 63 surfaces of one mesh, render/cutouts.h's bound). With
    // 70 a camera ray goes past 64 and takes the 65th as opaque: white -- in
    // shadow, 51, as its own shadow ray meets the 64 layers above it and
    // stops at the 64th as if it were solid (the same bound).
    for (const int n : {63, 70}) {
        Quad layers{-1, 1, -1, 1, 1, 0};
        layers.layers = n;
        const std::string json =
            quads_file({layers, {-1, 1, -1, 1, 0, 1}}, surfaces({blend("[1, 1, 1, 0]"), material("[1, 0, 0, 1]")}));
        const Rgb want = n < 64 ? Rgb{204, 0, 0} : Rgb{51, 51, 51};
        for (const Precision p : kPrecisions) {
            const std::string what = std::string(precision_name(p)) + ", " + std::to_string(n) + " layers";
            expect_columns(top_view(lit(json), p), 0, 8, want, what);
            EXPECT_EQ(counts_of(lit(json), p).transmitted, std::uint64_t(std::min(n, 64)) * 64u) << what;
        }
    }
}

TEST(GltfBlend, AMirrorsRayComesBackThroughTheSurfaceItPassed) {
    // A polished metal floor (metallic 1, roughness 0: glazed,
    // reflectivity 1) under a BLEND quad of alpha 0.25: each camera ray goes
    // through the quad (1), the floor mirrors it (1 reflection), and it goes
    // back up through the quad from below (2) into the sky.
    const std::string metal =
        "{\"pbrMetallicRoughness\": {\"baseColorFactor\": [1, 1, 1, 1], \"metallicFactor\": 1, \"roughnessFactor\": 0}}";
    const std::string json =
        quads_file({{-1, 1, -1, 1, 1, 0}, {-1, 1, -1, 1, 0, 1}}, surfaces({blend("[0, 0, 1, 0.25]"), metal}));
    for (const Precision p : kPrecisions) {
        const RayCounts n = counts_of(lit(json), p);
        EXPECT_EQ(n.transmitted, 2u * 64u) << precision_name(p);
        EXPECT_EQ(n.reflection, 64u) << precision_name(p);
    }
}

}  // namespace
}  // namespace fh
