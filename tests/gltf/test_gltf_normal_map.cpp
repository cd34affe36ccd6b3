// glTF normal textures (gltf/gltf_materials.cpp, render/normal_map.h): the
// pixels a quad renders, worked out by hand from docs/gltf.md's formula.
// The quads of gltf_quads.h face up (n = +z) and are seen straight down; a
// white matte surface is 51 of ambient light plus 153 (n'.l) of a sun,
// n' the turned normal: the texel (x, y, z) = 2 texel / 255 - 1 read along
// the quad's u (+x), the image's up (+y, as v runs along -y) and +z.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "gltf/gltf_quads.h"
#include "render/effect_plan.h"
#include "render/flat_scene.h"
#include "scene/deformation.h"

namespace fh {
namespace {

using namespace gltf_test;

// A texel channel as a component of the direction: 2 n / 255 - 1.
double component(int n) { return 2 * n / 255.0 - 1; }

// 51 + 153 max(0, n.l) for the direction (x, y, z) in the world (made unit)
// and the sun's light travelling along `travel`.
int lit_pixel(dvec3 n, dvec3 travel) {
    const double n_dot_l = glm::dot(glm::normalize(n), -glm::normalize(travel));
    return int(std::lround(51 + 153 * std::max(0.0, n_dot_l)));
}

// A white matte material whose normal texture is `info` (", \"scale\": ..."
// and the like inside its braces).
std::string bumpy_material(const std::string& info = "") {
    return material("[1, 1, 1, 1]", "", ", \"normalTexture\": {\"index\": 0" + info + "}");
}

// The 2 x 1 texture (nearest, clamped): left (218, 128, 218), turned 45
// degrees towards +u; right (128, 218, 218), 45 degrees towards the image's up.
const std::vector<Bytes4> kTwoTilts = {{218, 128, 218, 255}, {128, 218, 218, 255}};
const std::string kNearestClampedSampler = sampler_json(kClamp, kClamp, kNearest);

// "(x, y, z)" of a sun's direction, for messages.
std::string along(const dvec3& d) { return "(" + num(d.x) + ", " + num(d.y) + ", " + num(d.z) + ")"; }

// Suns from above and from four sides, 45 degrees up.
const dvec3 kSuns[] = {{0, 0, -1}, {-1, 0, -1}, {1, 0, -1}, {0, -1, -1}, {0, 1, -1}};

// The file's left and right halves, under each of kSuns, in both
// precisions: what normals `left` and `right` (the world's) show.
void expect_halves_under_suns(const std::string& json, const dvec3& left, const dvec3& right,
                              const std::string& what = "") {
    for (const Precision p : kPrecisions)
        for (const dvec3& sun : kSuns) {
            const Image im = top_view(lit(json, {0.2, 0.6, sun}), p);
            const std::string named = what + precision_name(p) + ", sun along " + along(sun);
            const int l = lit_pixel(left, sun), r = lit_pixel(right, sun);
            expect_columns(im, 0, 4, {l, l, l}, named + ", left");
            expect_columns(im, 4, 8, {r, r, r}, named + ", right");
        }
}

TEST(GltfNormalTexture, ATexelTurnsTheNormalInTheTangentFrame) {
    const std::string json = quads_file({{-1, 1, -1, 1, 0, 0}},
                                        surfaces({bumpy_material()}, {{0, 0}}, {image_json(rgba_png(2, 1, kTwoTilts))},
                                                 {kNearestClampedSampler}));
    const GltfFile f = load(json);
    EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
    ASSERT_EQ(f.scene.materials[0].normal_texture, 0);
    EXPECT_EQ(f.scene.materials[0].normal_scale, 1.0);
    EXPECT_FALSE(f.scene.textures[0].srgb);  // data: 218 is 0.7098 along u, not sRGB's
    const double a = component(218), e = component(128);
    const dvec3 left{a, e, a}, right{e, a, a};
    // Worked once by hand: a = 0.709804, e = 0.003922, |n| = 1.003823.
    EXPECT_EQ(lit_pixel(left, {0, 0, -1}), 159);   // 51 + 153 x 0.707089
    EXPECT_EQ(lit_pixel(left, {-1, 0, -1}), 204);  // from +x: n.l = 0.999992
    EXPECT_EQ(lit_pixel(right, {-1, 0, -1}), 128); // 51 + 153 x 0.502759
    EXPECT_EQ(lit_pixel(left, {1, 0, -1}), 51);    // from -x: n.l = 0, unlit
    expect_halves_under_suns(json, left, right);
}

TEST(GltfNormalTexture, MirroredCoordinatesTurnTheBitangentNotTheImage) {
    // TEXCOORD_1 runs u along -x (v still along -y): the right half reads
    // the left texel, turned towards -x now; the left half the right texel,
    // still towards +y -- the image's up, whichever way u runs.
    Quad q{-1, 1, -1, 1, 0, 0};
    q.uv1 = {1, 0, 0, 0, 0, 1, 1, 1};
    const std::string json = quads_file({q}, surfaces({bumpy_material(", \"texCoord\": 1")}, {{0, 0}},
                                                      {image_json(rgba_png(2, 1, kTwoTilts))}, {kNearestClampedSampler}));
    const double a = component(218), e = component(128);
    const dvec3 right{-a, e, a}, left{-e, a, a};
    expect_halves_under_suns(json, left, right);
}

// The quad of the first test with NORMALs up and a TANGENT at each vertex.
std::string tangent_quad(std::vector<float> tangent, bool normals = true) {
    Quad q{-1, 1, -1, 1, 0, 0};
    q.normals = normals;
    for (int v = 0; v < 4; ++v) q.tangents.insert(q.tangents.end(), tangent.begin(), tangent.end());
    return quads_file({q}, surfaces({bumpy_material()}, {{0, 0}}, {image_json(rgba_png(2, 1, kTwoTilts))},
                                    {kNearestClampedSampler}));
}

TEST(GltfNormalTexture, AMeshsTangentsReplaceTheTrianglesOwn) {
    // TANGENT (0, 0, -1) in the file's axes is the world's +y: t = +y and,
    // w = 1, b = n x t = -x. The left texel (a, e, a) along (t, b, n) is
    // (-e, a, a) in the world, the right one's (e, a, a) is (-a, e, a). With
    // w = -1, b = +x: (e, a, a) and (a, e, a). Without NORMALs the file's
    // tangents are ignored (as glTF requires): the triangles' own, as in the
    // first test; with NORMALs and no TANGENT, the corners' are made from
    // the quad: the same.
    const double a = component(218), e = component(128);
    struct Case {
        std::vector<float> tangent;
        bool normals;
        dvec3 left, right;
    };
    const Case cases[] = {{{0, 0, -1, 1}, true, {-e, a, a}, {-a, e, a}},
                          {{0, 0, -1, -1}, true, {e, a, a}, {a, e, a}},
                          {{0, 0, -1, 1}, false, {a, e, a}, {e, a, a}},
                          {{}, true, {a, e, a}, {e, a, a}}};  // no TANGENT: made from the quad, +x
    for (const Case& c : cases) {
        const std::string json = tangent_quad(c.tangent, c.normals);
        const GltfFile f = load(json);
        const Mesh& mesh = *f.scene.meshes[0].mesh;
        EXPECT_EQ(mesh.tangents.size(), c.normals && !c.tangent.empty() ? 4u : 0u);
        EXPECT_EQ(mesh.make_tangents, c.normals && c.tangent.empty());
        expect_halves_under_suns(json, c.left, c.right,
                                 (c.tangent.empty() ? "no TANGENT" : "w " + num(c.tangent[3])) +
                                     (c.normals ? "" : ", no normals") + ", ");
    }
    // A tangent along the normal has no direction in the surface: the
    // normal stays (51 + 153 x cos 45 degrees from +x).
    for (const Precision p : kPrecisions)
        expect_columns(top_view(lit(tangent_quad({0, 1, 0, 1}), {0.2, 0.6, {-1, 0, -1}}), p), 0, 8, {159, 159, 159},
                       precision_name(p));
}

TEST(GltfNormalTexture, ATangentCountOtherThanThePositionsIsOneLine) {
    Quad q{-1, 1, -1, 1, 0, 0};
    q.normals = true;
    q.tangents = {1, 0, 0, 1, 1, 0, 0, 1, 1, 0, 0, 1};  // three, for four vertices
    const std::string json = quads_file({q}, surfaces({bumpy_material()}, {{0, 0}}, {image_json(rgba_png(2, 1, kTwoTilts))},
                                                      {kNearestClampedSampler}));
    expect_input_error([&] { load(json); }, "t.gltf", "mesh 0 primitive 0: TANGENT has 3 elements, POSITION 4");
}

TEST(GltfNormalTexture, NormalsAgainstTheWindingKeepTheirFrame) {
    // The quad wound facing down but its NORMALs up, seen from above (their
    // side): shading turns the normals to the face's side, and the tangent
    // frame with them, so what shows is the file's own frame, as for a quad
    // wound up -- the first test's pixels -- with a TANGENT (+x, w 1) and
    // with tangents made from the normals.
    const double a = component(218), e = component(128);
    const dvec3 left{a, e, a}, right{e, a, a};
    for (const bool given : {true, false}) {
        Quad q{-1, 1, -1, 1, 0, 0};
        q.down = true;
        q.normals = true;
        if (given)
            for (int v = 0; v < 4; ++v) q.tangents.insert(q.tangents.end(), {1, 0, 0, 1});
        const std::string json = quads_file({q}, surfaces({bumpy_material()}, {{0, 0}},
                                                          {image_json(rgba_png(2, 1, kTwoTilts))}, {kNearestClampedSampler}));
        expect_halves_under_suns(json, left, right, given ? "TANGENT given, " : "tangents made, ");
    }
}

TEST(GltfNormalTexture, AHugeScaleStaysADirection) {
    // scale 1e20 is held at 1e6, past which the direction no longer
    // changes: the left texel's normal lies almost along (a, e, 0): unlit
    // from above (51 + 153 x 1e-6), from +x lit by cos 45 degrees (159).
    const std::string json = quads_file({{-1, 1, -1, 1, 0, 0}},
                                        surfaces({bumpy_material(", \"scale\": 1e20")}, {{0, 0}},
                                                 {image_json(rgba_png(2, 1, kTwoTilts))}, {kNearestClampedSampler}));
    EXPECT_EQ(load(json).scene.materials[0].normal_scale, 1e6);
    for (const Precision p : kPrecisions) {
        expect_columns(top_view(lit(json), p), 0, 4, {51, 51, 51}, precision_name(p));
        expect_columns(top_view(lit(json, {0.2, 0.6, {-1, 0, -1}}), p), 0, 4, {159, 159, 159}, precision_name(p));
    }
}

TEST(GltfNormalTexture, TangentsMorphAndSkinWithTheirMesh) {
    // deformed() on one vertex: the rest tangent (1, 0, 0), w -1; a target
    // adding (-1, 1, 0) at weight 0.5 makes it (0.5, 0.5, 0); a joint turned
    // 90 degrees about z and scaled 2 carries it to (-1, 1, 0) -- as an
    // edge, not as a normal (whose matrix would halve it) -- and w stays.
    auto rest = std::make_shared<Mesh>();
    rest->positions = {{1, 0, 0}};
    rest->normals = {{0, 0, 1}};
    rest->tangents = {{1, 0, 0, -1}};
    Deformation d;
    d.rest = rest;
    d.targets = std::make_shared<const std::vector<MorphTarget>>(
        std::vector<MorphTarget>{{{{0, 0, 0}}, {}, {{-1, 1, 0}}}});
    const Mesh morphed = deformed(d, {0.5}, {});
    EXPECT_EQ(morphed.tangents[0], glm::dvec4(0.5, 0.5, 0, -1));
    auto weights = std::make_shared<SkinWeights>();
    weights->influences = 1;
    weights->joint = {0};
    weights->weight = {1};
    d.skin.joints = {0};
    d.skin.inverse_binds = {glm::dmat4(1.0)};
    d.skin.weights = weights;
    const glm::dmat4 turn{{0, 2, 0, 0}, {-2, 0, 0, 0}, {0, 0, 2, 0}, {0, 0, 0, 1}};  // columns
    const Mesh skinned = deformed(d, {0.5}, {turn});
    EXPECT_EQ(skinned.tangents[0], glm::dvec4(-1, 1, 0, -1));
    EXPECT_EQ(skinned.normals[0], dvec3(0, 0, 0.5));
    // A joint that mirrors x: the tangent (-0.5, 0.5, 0) and its sign turned, w 1.
    const glm::dmat4 mirror{{-1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 1, 0}, {0, 0, 0, 1}};
    EXPECT_EQ(deformed(d, {0.5}, {mirror}).tangents[0], glm::dvec4(-0.5, 0.5, 0, 1));
}

TEST(GltfNormalTexture, SeenFromBehindTheTurnedNormalTurnsWithTheFace) {
    // The quad wound facing down, seen from above: its back. Lighting uses
    // the turned normal flipped whole, as the face's: the left texel's
    // (a, e, a) becomes (-a, -e, a), turned towards -x.
    Quad q{-1, 1, -1, 1, 0, 0};
    q.down = true;
    const std::string json = quads_file({q}, surfaces({bumpy_material()}, {{0, 0}},
                                                      {image_json(rgba_png(2, 1, kTwoTilts))}, {kNearestClampedSampler}));
    const double a = component(218), e = component(128);
    const dvec3 left{-a, -e, a}, right{-e, -a, a};
    EXPECT_EQ(lit_pixel(left, {1, 0, -1}), 204);
    expect_halves_under_suns(json, left, right);
}

TEST(GltfNormalTexture, TheScaleShortensTheTangentialPart) {
    // scale s: (s x, s y, z). The left texel under a sun straight down:
    // s = 0.5, n.l = a / |(a/2, e/2, a)| = 0.894424: 187.8; s = 0, the
    // normal itself: 204; s = -1 turns it the other way: 159 as for s = 1.
    const double a = component(218), e = component(128);
    for (const double s : {0.5, 0.0, -1.0}) {
        const std::string json = quads_file(
            {{-1, 1, -1, 1, 0, 0}}, surfaces({bumpy_material(", \"scale\": " + num(s))}, {{0, 0}},
                                             {image_json(rgba_png(2, 1, kTwoTilts))}, {kNearestClampedSampler}));
        EXPECT_EQ(load(json).scene.materials[0].normal_scale, s);
        const int want = lit_pixel({s * a, s * e, a}, {0, 0, -1});
        EXPECT_EQ(want, s == 0.5 ? 188 : s == 0 ? 204 : 159);
        const dvec3 from_x{-1, 0, -1};
        for (const Precision p : kPrecisions) {
            const std::string what = std::string(precision_name(p)) + ", scale " + num(s);
            expect_columns(top_view(lit(json), p), 0, 4, {want, want, want}, what);
            const int side = lit_pixel({s * a, s * e, a}, from_x);
            expect_columns(top_view(lit(json, {0.2, 0.6, from_x}), p), 0, 4, {side, side, side}, what + ", from +x");
        }
    }
}

TEST(GltfNormalTexture, NormalsBelowTheSurfaceAndFlatCoordinatesStayFinite) {
    // A texel (0, 128, 0) points into the surface: (-1, e, -1). Under a sun
    // straight down nothing is lit, only the ambient 51 -- and a polished
    // metal's mirrored ray, sent into the surface, brings back a finite
    // colour (top_view counts non-finite samples). Coordinates that do not
    // span the quad (all four (0.5, 0.5)) give no tangent: the normal stays.
    const std::string below =
        surfaces({bumpy_material()}, {{-1, 0}}, {image_json(rgb_png(1, 1, 0, 128, 0))});
    for (const Precision p : kPrecisions)
        expect_columns(top_view(lit(quads_file({{-1, 1, -1, 1, 0, 0}}, below)), p), 0, 8, {51, 51, 51},
                       precision_name(p));
    const std::string mirror =
        surfaces({"{\"pbrMetallicRoughness\": {\"metallicFactor\": 1, \"roughnessFactor\": 0}, \"normalTexture\": "
                  "{\"index\": 0}}"},
                 {{-1, 0}}, {image_json(rgb_png(1, 1, 0, 128, 0))});
    for (const Precision p : kPrecisions) top_view(lit(quads_file({{-1, 1, -1, 1, 0, 0}}, mirror)), p);

    Quad q{-1, 1, -1, 1, 0, 0};
    q.uv1 = {0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5, 0.5};
    const std::string json = quads_file({q}, surfaces({bumpy_material(", \"texCoord\": 1")}, {{0, 0}},
                                                      {image_json(rgba_png(2, 1, kTwoTilts))}, {kNearestClampedSampler}));
    for (const Precision p : kPrecisions)
        expect_columns(top_view(lit(json, {0.2, 0.6, {-1, 0, -1}}), p), 0, 8, {159, 159, 159}, precision_name(p));
}

TEST(GltfNormalTexture, ItIsTracedOnlyWhereALightOrAMirrorShowsIt) {
    // Ambient light alone: the turned normal changes no pixel, so the
    // effect plan leaves it out (the material is not even textured), and
    // no hit's footprint is worked out for its mipmaps.
    const Scene s = lit(quads_file({{-1, 1, -1, 1, 0, 0}}, surfaces({bumpy_material()}, {{0, 0}},
                                                                      {image_json(rgba_png(2, 1, kTwoTilts))},
                                                                      {kNearestClampedSampler})));
    expect_read_only_when_lit(s, &MaterialShading<double>::normal_texture, &FlatScene<double>::textured, 0);
    expect_read_only_when_lit(s, &MaterialShading<double>::normal_texture, &FlatScene<double>::minified, 0);
}

}  // namespace
}  // namespace fh
