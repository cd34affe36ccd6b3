// glTF metallic-roughness textures (gltf/gltf_materials.cpp,
// render/metal_rough.h): pixels worked out by hand from docs/gltf.md's
// mapping, per hit. The quads of gltf_quads.h face up and are seen straight
// down (the viewer along +z); under gltf_quads.h's lights a surface of
// base colour c shows 51 c of ambient light, and the sun, of 0.6 x 255 =
// 153 a channel, adds 153 (n.l) d c + 153 (n.h)^e s (m c + 1 - m): d and s
// the diffuse and specular strengths, e the Phong exponent, all from the
// hit's metalness m and roughness r.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "gltf/gltf_quads.h"
#include "render/effect_plan.h"
#include "render/flat_scene.h"

namespace fh {
namespace {

using namespace gltf_test;

const dvec3 kBase{1, 0.5, 0.25};

// The pixel of a hit of metalness m and roughness r, lit by the sun
// travelling along `travel`, in channel k: the mapping written out.
int metal_rough_pixel(double m, double r, dvec3 travel, int k) {
    const dvec3 n{0, 0, 1}, view{0, 0, 1}, l = -glm::normalize(travel);
    double value = 51 * kBase[k];
    const double n_dot_l = glm::dot(n, l);
    if (n_dot_l > 0) {
        const double d = (1 - m) + m * r, s = (0.04 + 0.96 * m) * (1 - r);
        const double a = std::max(r * r, 0.01), e = std::min(2 / (a * a) - 2, 10000.0);
        const double n_dot_h = std::max(0.0, glm::dot(n, glm::normalize(l + view)));
        value += 153 * n_dot_l * d * kBase[k] + 153 * std::pow(n_dot_h, e) * s * (m * kBase[k] + 1 - m);
    }
    return int(std::lround(std::min(value, 255.0)));
}

Rgb metal_rough_rgb(double m, double r, dvec3 travel) {
    return {metal_rough_pixel(m, r, travel, 0), metal_rough_pixel(m, r, travel, 1), metal_rough_pixel(m, r, travel, 2)};
}

// A quad of base colour kBase, metallic and roughness factors as given,
// its metallic-roughness texture the 2 x 1 image `texels` (nearest,
// clamped), or none.
std::string metal_rough_quad(double metallic, double roughness, const std::vector<Bytes4>& texels) {
    const std::string factors = "{\"baseColorFactor\": [1, 0.5, 0.25, 1], \"metallicFactor\": " + num(metallic) +
                                ", \"roughnessFactor\": " + num(roughness) +
                                (texels.empty() ? "" : ", \"metallicRoughnessTexture\": {\"index\": 0}") + "}";
    if (texels.empty()) return quads_file({{-1, 1, -1, 1, 0, 0}}, surfaces({"{\"pbrMetallicRoughness\": " + factors + "}"}));
    return quads_file({{-1, 1, -1, 1, 0, 0}},
                      surfaces({"{\"pbrMetallicRoughness\": " + factors + "}"}, {{0, 0}},
                               {image_json(rgba_png(2, 1, texels))}, {sampler_json(kClamp, kClamp, kNearest)}));
}

// Suns from above and from four sides, 45 degrees up (the highlight's
// n.h is 1 from above, cos 22.5 degrees from a side).
const dvec3 kSunsAround[] = {{0, 0, -1}, {-1, 0, -1}, {1, 0, -1}, {0, -1, -1}, {0, 1, -1}};

TEST(GltfMetalRough, BlueIsMetalnessAndGreenRoughnessPerHit) {
    // Factors 1 and 1. Left texel (0, 128, 255): m = 1, r = 128 / 255 =
    // 0.50196 -- a rough metal, tinted highlight, e = 29.50, not polished
    // (r >= 0.5). Right (0, 255, 0): m = 0, r = 1 -- matte, no highlight.
    // The red channel is not read.
    const std::string json = metal_rough_quad(1, 1, {{200, 128, 255, 255}, {0, 255, 0, 255}});
    const GltfFile f = load(json);
    EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
    ASSERT_EQ(f.scene.materials[0].metal_rough_texture, 0);
    EXPECT_FALSE(f.scene.textures[0].srgb);
    const double r = 128 / 255.0;
    // Worked once by hand, from the side: n.l = 0.70711, n.h = 0.92388.
    // Red: 51 + 153 x 0.70711 x 0.50196 + 153 x 0.92388^29.50 x 0.49804 x 1 = 51 + 54.31 + 7.37.
    EXPECT_EQ(metal_rough_pixel(1, r, {-1, 0, -1}, 0), 113);
    EXPECT_EQ(metal_rough_rgb(0, 1, {-1, 0, -1}), (Rgb{159, 80, 40}));  // 51 c + 108.2 c
    for (const Precision p : kPrecisions)
        for (const dvec3& sun : kSunsAround) {
            const Image im = top_view(lit(json, {0.2, 0.6, sun}), p);
            const std::string what = std::string(precision_name(p)) + ", sun along (" + num(sun.x) + ", " +
                                     num(sun.y) + ", " + num(sun.z) + ")";
            expect_columns(im, 0, 4, metal_rough_rgb(1, r, sun), what + ", left");
            expect_columns(im, 4, 8, metal_rough_rgb(0, 1, sun), what + ", right");
        }
}

TEST(GltfMetalRough, TexelsOfOneGiveTheFactorsAlone) {
    // B = G = 255: m and r are the factors, the same mapping as a material
    // without the texture (to rounding, its terms multiplied in another order).
    // (0.9, 0.2) is a mirror: both add the same reflected sky, not worked by hand.
    for (const auto [metallic, roughness] : {std::pair{0.3, 0.6}, {0.9, 0.7}, {0.0, 0.2}, {0.9, 0.2}}) {
        const std::string textured = metal_rough_quad(metallic, roughness, {{0, 255, 255, 255}, {0, 255, 255, 255}});
        const std::string plain = metal_rough_quad(metallic, roughness, {});
        for (const Precision p : kPrecisions)
            for (const dvec3& sun : kSunsAround) {
                const Image a = top_view(lit(textured, {0.2, 0.6, sun}), p), b = top_view(lit(plain, {0.2, 0.6, sun}), p);
                const std::string what = std::string(precision_name(p)) + ", factors " + num(metallic) + " " +
                                         num(roughness) + ", sun along (" + num(sun.x) + ", " + num(sun.y) + ")";
                expect_columns(a, 0, 8, pixel(b, 0, 0), what);
                if (roughness >= 0.5 || metallic <= 0.5)
                    expect_columns(a, 0, 8, metal_rough_rgb(metallic, roughness, sun), what + ", by hand");
            }
    }
}

TEST(GltfMetalRough, APolishedTexelMirrorsAndOnlyThere) {
    // Left texel (0, 0, 255): m = 1, r = 0 -- polished, reflectivity 1: its
    // 32 camera rays send 32 reflection rays; the right (0, 255, 0) none.
    // The factors (1, 1) alone are no mirror, but the plan keeps glazing for
    // a metal's texture (metallic > 0.5), and drops it for metallic 0.4.
    const std::string json = metal_rough_quad(1, 1, {{0, 0, 255, 255}, {0, 255, 0, 255}});
    // And the other way round: left (0, 0, 0), m = 0 and r = 0, smooth but
    // no metal, no mirror; right (0, 64, 255), m = 1, r = 0.251, a mirror.
    const std::string swapped = metal_rough_quad(1, 1, {{0, 0, 0, 255}, {0, 64, 255, 255}});
    for (const Precision p : kPrecisions)
        for (const std::string& file : {json, swapped}) {
            RayCounts counts;
            top_view(lit(file), p, 8, 8, 1, 0.05, Projection::orthographic, &counts);
            EXPECT_EQ(counts.primary, 64u) << precision_name(p);
            EXPECT_EQ(counts.reflection, 32u) << precision_name(p);
        }
    const Scene s = lit(json);
    const EffectPlan plan = plan_effects(s, Effects{}, 5);
    EXPECT_TRUE(plan.effects.glazing);
    EXPECT_TRUE(plan.effects.specular);
    const Scene dull = lit(metal_rough_quad(0.4, 1, {{0, 0, 255, 255}, {0, 255, 0, 255}}));
    EXPECT_FALSE(plan_effects(dull, Effects{}, 5).effects.glazing);
    // Roughness factor 1 alone has no highlight; its texture may: specular stays.
    EXPECT_TRUE(plan_effects(dull, Effects{}, 5).effects.specular);
    EXPECT_FALSE(plan_effects(lit(metal_rough_quad(0.4, 1, {})), Effects{}, 5).effects.specular);
}

TEST(GltfMetalRough, ItIsReadOnlyWhereALightOrAMirrorShowsIt) {
    const Scene s = lit(metal_rough_quad(1, 1, {{0, 128, 255, 255}, {0, 255, 0, 255}}));
    expect_read_only_when_lit(s, &MaterialShading<double>::metal_rough_texture, &FlatScene<double>::metal_rough, 0);
    // Its exponent varies per hit: std::pow.
    EXPECT_TRUE(FlatScene<double>::build(s, plan_effects(s, Effects{}, 5)).fractional_exponents);
    // Without the diffuse term, none per hit either; without the specular,
    // no highlight's colours (sun 0.6 x 255 = 153 a channel, times the base).
    Effects no_diffuse, no_specular;
    no_diffuse.diffuse = no_specular.specular = false;
    auto expect_terms = [](const dvec3& got, const dvec3& want, const char* what) {
        for (int k = 0; k < 3; ++k) EXPECT_NEAR(got[k], want[k], 1e-9) << what << ", channel " << k;
    };
    const dvec3 base = 153.0 * kBase, none(0), white(153);
    const LightTerms<double> a = FlatScene<double>::build(s, plan_effects(s, no_diffuse, 5)).directional_terms[0];
    expect_terms(a.diffuse_unit, none, "no diffuse: its unit");
    expect_terms(a.tinted, base, "no diffuse: the tint");
    expect_terms(a.white, white, "no diffuse: the white");
    const LightTerms<double> b = FlatScene<double>::build(s, plan_effects(s, no_specular, 5)).directional_terms[0];
    expect_terms(b.diffuse_unit, base, "no specular: the diffuse unit");
    expect_terms(b.tinted, none, "no specular: the tint");
    expect_terms(b.white, none, "no specular: the white");
}

}  // namespace
}  // namespace fh
