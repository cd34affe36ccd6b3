// glTF base colour textures and alpha modes (gltf/gltf_loader.cpp,
// gltf/gltf_model.cpp, render/cutouts.h, render/shading.h): what a file's
// textures, samplers and KHR_texture_transform become in the Scene, the
// pixels a textured or cut-out quad renders -- each worked out by hand from
// the report's shading -- and the one clean error line a bad image gets.
//
// The images are made here: PNGs by the PNG writer's encoder (encode_png for
// RGB; stb_image_write, compiled once in images/png_writer.cpp, for RGBA),
// a JPEG by encode_image, embedded as data: URIs or written beside the file.
//
// The render tests place quads facing up (+z, firsthit's sky) and look
// straight down on them with an orthographic camera; the sun shines along
// -z (or slanted) with an ambient light beside it. A white, matte, non-metal
// surface (metallicFactor 0, roughnessFactor 1: diffuse 1, specular 0)
// lit by ambient 0.2 and a sun of 0.6 straight down is 255 (0.2 + 0.6) = 204
// (an ambient light of 2 against the material's ambient strength of 0.1).
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <vector>

#include "gltf/gltf_quads.h"
#include "images/image_writer.h"
#include "images/png_writer.h"
#include "render/render.h"

namespace fh {
namespace {

using namespace gltf_test;

// ========================================================= loading textures

TEST(GltfTextures, SamplersMapOntoWrapModesAndFilters) {
    // Six quads, each its own material; materials 0-4 show textures 0-4,
    // material 5 texture 0 again. Textures 0, 1 and 4 show image 0 (2 x 1
    // RGBA), 2 and 3 image 1 (1 x 1 RGB grey 188).
    std::vector<Quad> quads;
    for (int m = 0; m < 7; ++m) quads.push_back({-1, 1, -1, 1, double(m), m});
    const std::string json = quads_file(
        quads, surfaces({material("[1, 1, 1, 1]", tex(0)), material("[1, 1, 1, 1]", tex(1)),
                         material("[1, 1, 1, 1]", tex(2)), material("[1, 1, 1, 1]", tex(3)),
                         material("[1, 1, 1, 1]", tex(4)), material("[1, 1, 1, 1]", tex(0)),
                         material("[1, 1, 1, 1]")},
                        {{0, 0}, {1, 0}, {2, 1}, {3, 1}, {-1, 0}},
                        {image_json(rgba_png(2, 1, kRedBlue)), image_json(rgb_png(1, 1, 188, 188, 188))},
                        {sampler_json(kRepeat, kMirrored, kNearest), sampler_json(kClamp, kRepeat, kLinear),
                         sampler_json(kMirrored, kClamp), "{}"}));
    const GltfFile f = load(json);
    EXPECT_TRUE(f.warnings.empty()) << f.warnings[0];
    const Scene& s = f.scene;
    ASSERT_EQ(s.textures.size(), 5u);  // one per glTF texture used
    ASSERT_EQ(s.materials.size(), 8u);  // and the glTF default
    for (int m = 0; m < 5; ++m) EXPECT_EQ(s.materials[size_t(m)].texture, m);
    EXPECT_EQ(s.materials[5].texture, 0);
    EXPECT_EQ(s.materials[6].texture, -1);
    EXPECT_EQ(s.materials[7].texture, -1);

    struct Want {
        Wrap s, t;
        Filter filter;
    };
    const Want want[5] = {{Wrap::repeat, Wrap::mirrored_repeat, Filter::nearest},
                          {Wrap::clamp_to_edge, Wrap::repeat, Filter::bilinear},
                          {Wrap::mirrored_repeat, Wrap::clamp_to_edge, Filter::bilinear},  // no magFilter
                          {Wrap::repeat, Wrap::repeat, Filter::bilinear},                  // sampler {}
                          {Wrap::repeat, Wrap::repeat, Filter::bilinear}};                 // no sampler
    for (size_t t = 0; t < 5; ++t) {
        EXPECT_EQ(s.textures[t].wrap_s, want[t].s) << "texture " << t;
        EXPECT_EQ(s.textures[t].wrap_t, want[t].t) << "texture " << t;
        EXPECT_EQ(s.textures[t].filter, want[t].filter) << "texture " << t;
        ASSERT_TRUE(s.textures[t].image) << "texture " << t;
    }
    // Each image decoded once and shared by the textures that show it.
    EXPECT_EQ(s.textures[0].image, s.textures[1].image);
    EXPECT_EQ(s.textures[0].image, s.textures[4].image);
    EXPECT_EQ(s.textures[2].image, s.textures[3].image);
    EXPECT_NE(s.textures[0].image, s.textures[2].image);
    const TextureImage& rb = *s.textures[0].image;
    EXPECT_EQ(rb.width, 2);
    EXPECT_EQ(rb.height, 1);
    EXPECT_EQ(rb.rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 0, 255, 255}));
    const TextureImage& grey = *s.textures[2].image;
    EXPECT_EQ(grey.width, 1);
    EXPECT_EQ(grey.height, 1);
    EXPECT_EQ(grey.rgba, (std::vector<std::uint8_t>{188, 188, 188, 255}));  // RGB: alpha 255

    // The meshes' texture coordinates are the file's; the untextured
    // material's quad has none (its TEXCOORD_0 is not read).
    ASSERT_EQ(s.meshes.size(), 7u);
    for (size_t m = 0; m < 6; ++m) {
        const std::vector<dvec2>& uv = s.meshes[m].mesh->uvs;
        ASSERT_EQ(uv.size(), 4u) << "mesh " << m;
        EXPECT_EQ(uv[0], dvec2(0, 0));
        EXPECT_EQ(uv[1], dvec2(1, 0));
        EXPECT_EQ(uv[2], dvec2(1, 1));
        EXPECT_EQ(uv[3], dvec2(0, 1));
    }
    EXPECT_TRUE(s.meshes[6].mesh->uvs.empty());
}

TEST(GltfTextures, TheImageTextureCoordinatesAndSamplerAreWhatReadsReturn) {
    // Through the loaded texture: texel (1, 0) of the red|blue image is
    // blue, linear (0, 0, 1, 1); nearest at u = 0.25 red, 0.75 blue; the
    // grey 188 texel reads 0.5029 in each colour channel.
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}, {-1, 1, -1, 1, 1, 1}},
        surfaces({material("[1, 1, 1, 1]", tex(0)), material("[1, 1, 1, 1]", tex(1))}, {{0, 0}, {-1, 1}},
                 {image_json(rgba_png(2, 1, kRedBlue)), image_json(rgb_png(2, 2, 188, 188, 188))},
                 {sampler_json(kClamp, kClamp, kNearest)}));
    const Scene s = load(json).scene;
    ASSERT_EQ(s.textures.size(), 2u);
    const auto red = s.textures[0].sample(0.25, 0.5), blue = s.textures[0].sample(0.75, 0.5);
    EXPECT_EQ(red, (std::array<float, 4>{1, 0, 0, 1}));
    EXPECT_EQ(blue, (std::array<float, 4>{0, 0, 1, 1}));
    const auto grey = s.textures[1].sample(0.3, 0.7);
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(grey[k], srgb_to_linear(188), 1e-7);
    EXPECT_EQ(grey[3], 1.0f);
}

TEST(GltfTextures, TextureIndicesFollowTheirFileIntoAScene) {
    // add_gltf appends a file's textures after the scene's: file b's
    // material 1 shows its texture 1 (green), the scene's 1 + 1 = 2.
    const std::string a = quads_file({{-1, 1, -1, 1, 0, 0}},
                                     surfaces({material("[1, 1, 1, 1]", tex(0))}, {{-1, 0}},
                                              {image_json(rgb_png(1, 1, 255, 0, 0))}));
    const std::string b = quads_file(
        {{-1, 1, -1, 1, 0, 0}, {-1, 1, -1, 1, 1, 1}, {-1, 1, -1, 1, 2, 2}},
        surfaces({material("[1, 1, 1, 1]", tex(0)), material("[1, 1, 1, 1]", tex(1)), material("[1, 1, 1, 1]")},
                 {{-1, 0}, {-1, 1}}, {image_json(rgb_png(1, 1, 0, 0, 255)), image_json(rgb_png(1, 1, 0, 255, 0))}));
    Scene s;
    add_gltf(s, load(a), "a", {});
    add_gltf(s, load(b), "b", {});
    ASSERT_EQ(s.textures.size(), 3u);
    // a: its material and the glTF default; b: three and its default.
    ASSERT_EQ(s.materials.size(), 6u);
    EXPECT_EQ(s.material_names[3], "b/material 1");
    EXPECT_EQ(s.materials[0].texture, 0);
    EXPECT_EQ(s.materials[1].texture, -1);
    EXPECT_EQ(s.materials[2].texture, 1);
    EXPECT_EQ(s.materials[3].texture, 2);
    EXPECT_EQ(s.materials[4].texture, -1);
    EXPECT_EQ(s.textures[0].image->rgba, (std::vector<std::uint8_t>{255, 0, 0, 255}));
    EXPECT_EQ(s.textures[1].image->rgba, (std::vector<std::uint8_t>{0, 0, 255, 255}));
    EXPECT_EQ(s.textures[2].image->rgba, (std::vector<std::uint8_t>{0, 255, 0, 255}));
}

TEST(GltfTextures, AnImageBesideTheFileInABufferViewOrAsAJpeg) {
    // Beside the file: uri "tex/red.png".
    TempFolder dir("textures_beside");
    dir.write("tex/red.png", rgb_png(1, 1, 255, 0, 0));
    const std::string path = dir.write(
        "beside.gltf",
        quads_file({{-1, 1, -1, 1, 0, 0}},
                   surfaces({material("[1, 1, 1, 1]", tex(0))}, {{-1, 0}}, {"{\"uri\": \"tex/red.png\"}"})));
    const GltfFile beside = load_gltf(path);
    ASSERT_EQ(beside.scene.textures.size(), 1u);
    EXPECT_EQ(beside.scene.textures[0].image->rgba, (std::vector<std::uint8_t>{255, 0, 0, 255}));

    // In a GLB's binary chunk, by a buffer view.
    Bin bin;
    std::string body = quads_body(bin, {{-1, 1, -1, 1, 0, 0}}, "");
    const int view = bin.raw(rgba_png(2, 1, kRedBlue));
    body += ",\n" + surfaces({material("[1, 1, 1, 1]", tex(0))}, {{-1, 0}},
                             {"{\"bufferView\": " + std::to_string(view) + ", \"mimeType\": \"image/png\"}"});
    const GltfFile packed = load(glb(gltf_json(body, bin, in_glb()), bin.bytes()));
    ASSERT_EQ(packed.scene.textures.size(), 1u);
    EXPECT_EQ(packed.scene.textures[0].image->width, 2);
    EXPECT_EQ(packed.scene.textures[0].image->rgba, (std::vector<std::uint8_t>{255, 0, 0, 255, 0, 0, 255, 255}));

    // A JPEG (told by its first bytes, though its mimeType says PNG): 8 x 8
    // of grey 188, back within a count or two of 188.
    const std::string jpeg = as_string(encode_image(flat_image(8, 8, 188, 188, 188), ImageFormat::jpeg));
    ASSERT_EQ(std::uint8_t(jpeg[0]), 0xff);
    const GltfFile j = load(quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        surfaces({material("[1, 1, 1, 1]", tex(0))}, {{-1, 0}},
                 {"{\"uri\": \"data:image/jpeg;base64," + base64(jpeg) + "\", \"mimeType\": \"image/png\"}"})));
    ASSERT_EQ(j.scene.textures.size(), 1u);
    const TextureImage& im = *j.scene.textures[0].image;
    ASSERT_EQ(im.width, 8);
    ASSERT_EQ(im.height, 8);
    for (size_t i = 0; i < im.rgba.size(); ++i)
        EXPECT_NEAR(im.rgba[i], i % 4 == 3 ? 255 : 188, i % 4 == 3 ? 0 : 2) << "byte " << i;
}

// ===================================================== KHR_texture_transform

void expect_uvs(const std::vector<dvec2>& got, const std::vector<dvec2>& want, const std::string& what) {
    ASSERT_EQ(got.size(), want.size()) << what;
    for (size_t i = 0; i < got.size(); ++i) {
        EXPECT_NEAR(got[i].x, want[i].x, 1e-12) << what << ": u of vertex " << i;
        EXPECT_NEAR(got[i].y, want[i].y, 1e-12) << what << ": v of vertex " << i;
    }
}

std::string transformed_file(const std::string& transform, int tex_coord = -1) {
    return "{\"index\": 0" + (tex_coord >= 0 ? ", \"texCoord\": " + std::to_string(tex_coord) : std::string()) +
           ", \"extensions\": {\"KHR_texture_transform\": " + transform + "}}";
}

const char* kTransformUsed =
    "\"extensionsUsed\": [\"KHR_texture_transform\"], \"extensionsRequired\": [\"KHR_texture_transform\"]";

TEST(GltfTextureTransform, OffsetRotationAndScaleEachAlone) {
    // TEXCOORD_0 (0,0) (1,0) (1,1) (0,1) at the quad's corners.
    //   offset (0.5, -0.25): each moved by it.
    //   rotation pi/2, R = [[cos, sin], [-sin, cos]] = [[0, 1], [-1, 0]]:
    //     (u, v) -> (v, -u): (0,0) (0,-1) (1,-1) (1,0). (The glTF sample
    //     viewer's, three.js's and Blender's sense -- KhronosGroup/glTF
    //     #1563; reading the spec's GLSL listing column-major gives the
    //     opposite, (0,1) for (1,0).)
    //   scale (2, 3): (0,0) (2,0) (2,3) (0,3).
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}, {-1, 1, -1, 1, 1, 1}, {-1, 1, -1, 1, 2, 2}},
        std::string(kTransformUsed) + ",\n" +
            surfaces({material("[1, 1, 1, 1]", transformed_file("{\"offset\": [0.5, -0.25]}")),
                      material("[1, 1, 1, 1]", transformed_file("{\"rotation\": " + num(kPi / 2) + "}")),
                      material("[1, 1, 1, 1]", transformed_file("{\"scale\": [2, 3]}"))},
                     {{-1, 0}}, {image_json(rgb_png(1, 1, 9, 9, 9))}));
    const Scene s = load(json).scene;
    ASSERT_EQ(s.meshes.size(), 3u);
    expect_uvs(s.meshes[0].mesh->uvs, {{0.5, -0.25}, {1.5, -0.25}, {1.5, 0.75}, {0.5, 0.75}}, "offset");
    expect_uvs(s.meshes[1].mesh->uvs, {{0, 0}, {0, -1}, {1, -1}, {1, 0}}, "rotation");
    expect_uvs(s.meshes[2].mesh->uvs, {{0, 0}, {2, 0}, {2, 3}, {0, 3}}, "scale");
}

TEST(GltfTextureTransform, AllTogetherOnTheSetItsTexCoordNames) {
    // The textureInfo reads set 0, the transform's texCoord overrides it with
    // set 1: (1,0) (0,1) (0.5,0.5) (0.25,1). uv' = T(offset) R(rotation) S(scale) uv
    // with scale (2, 3), rotation pi/6 (cos = sqrt 3 / 2 = 0.8660254037844386,
    // sin = 1/2), offset (0.5, -0.25):
    //   S:  (2,0)           (0,3)            (1,1.5)           (0.5,3)
    //   R:  u' = c u + s v, v' = -s u + c v
    //       (1.7320508, -1) (1.5, 2.5980762) (1.6160254, 0.7990381) (1.9330127, 2.3480762)
    //   T:  (2.2320508, -1.25) (2, 2.3480762) (2.1160254, 0.5490381) (2.4330127, 2.0980762)
    Quad q{-1, 1, -1, 1, 0, 0};
    q.uv1 = {1, 0, 0, 1, 0.5f, 0.5f, 0.25f, 1};
    const std::string json = quads_file(
        {q}, std::string(kTransformUsed) + ",\n" +
                 surfaces({material("[1, 1, 1, 1]",
                                    transformed_file("{\"offset\": [0.5, -0.25], \"rotation\": " + num(kPi / 6) +
                                                    ", \"scale\": [2, 3], \"texCoord\": 1}",
                                                0))},
                          {{-1, 0}}, {image_json(rgb_png(1, 1, 9, 9, 9))}));
    const double c = 0.86602540378443865, h = 0.5;
    expect_uvs(load(json).scene.meshes[0].mesh->uvs,
               {{c * 2 + 0.5, -h * 2 - 0.25},
                {h * 3 + 0.5, c * 3 - 0.25},
                {c * 1 + h * 1.5 + 0.5, -h * 1 + c * 1.5 - 0.25},
                {c * 0.5 + h * 3 + 0.5, -h * 0.5 + c * 3 - 0.25}},
               "offset, rotation, scale, texCoord 1");
    // The same numbers written out.
    expect_uvs(load(json).scene.meshes[0].mesh->uvs,
               {{2.2320508075688772, -1.25},
                {2.0, 2.3480762113533160},
                {2.1160254037844386, 0.5490381056766580},
                {2.4330127018922193, 2.0980762113533160}},
               "by the numbers");
}

TEST(GltfTextureTransform, TheTextureInfosTexCoordAloneChoosesTheSet) {
    Quad q{-1, 1, -1, 1, 0, 0};
    q.uv1 = {0.25f, 0.5f, 0.75f, 0.5f, 0.75f, 1, 0.25f, 1};
    const std::string json = quads_file(
        {q}, surfaces({material("[1, 1, 1, 1]", "{\"index\": 0, \"texCoord\": 1}")}, {{-1, 0}},
                      {image_json(rgb_png(1, 1, 9, 9, 9))}));
    expect_uvs(load(json).scene.meshes[0].mesh->uvs, {{0.25, 0.5}, {0.75, 0.5}, {0.75, 1}, {0.25, 1}}, "TEXCOORD_1");
}

TEST(GltfTextureTransform, BadTransformsAreRefused) {
    struct Case {
        std::string transform, phrase;
    };
    const Case cases[] = {
        {"{\"offset\": [1]}", "mesh 0 primitive 0: KHR_texture_transform's offset needs 2 numbers"},
        {"{\"scale\": [1, \"x\"]}", "KHR_texture_transform's scale needs 2 numbers"},
        {"{\"rotation\": \"half\"}", "KHR_texture_transform's rotation is not a number"},
        {"{\"texCoord\": -1}", "KHR_texture_transform's texCoord is not a set index"},
        {"{\"texCoord\": 2}", "its material reads TEXCOORD_2, which it does not have"},
        {"{\"scale\": [1e308, 1e308]}", "KHR_texture_transform's numbers are not finite"},
    };
    for (const Case& c : cases) {
        const std::string json = quads_file(
            {{-1, 1, -1, 1, 0, 0}}, std::string(kTransformUsed) + ",\n" +
                                        surfaces({material("[1, 1, 1, 1]", transformed_file(c.transform))}, {{-1, 0}},
                                                 {image_json(rgb_png(1, 1, 9, 9, 9))}));
        expect_input_error([&] { load(json); }, "t.gltf", c.phrase);
    }
}

// Loading json fails with one line holding phrase.
void expect_refused(const std::string& json, const std::string& phrase) {
    expect_input_error([&] { load(json); }, "t.gltf", phrase);
}

TEST(GltfTextureTransform, TransformedTextureCoordinatesStayFinite) {
    // scale (1e300, 1), finite, on u = 1e10 (a float TEXCOORD_0 may hold it):
    // 1e310 is past a double. The loader refuses non-finite values
    // everywhere else (accessors, transforms); here the product must be
    // finite or refused -- not an infinite u, and not the NaN v that
    // -sin(0) u = -0 x inf makes.
    Bin bin;
    const int p = bin.f32({-1, 0, -1, 1, 0, -1, 1, 0, 1});
    const int t = bin.f32({1e10f, 0, 0, 0, 0, 1});
    const std::string json = gltf_json(
        std::string(kTransformUsed) + R"(, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
"meshes": [{"primitives": [{"attributes": {"POSITION": 0, "TEXCOORD_0": 1}, "material": 0}]}],
"accessors": [)" + accessor(p, kFloat, 3, "VEC3") + ", " + accessor(t, kFloat, 3, "VEC2") + "],\n" +
            surfaces({material("[1, 1, 1, 1]", transformed_file("{\"scale\": [1e300, 1]}"))}, {{-1, 0}},
                     {image_json(rgb_png(1, 1, 9, 9, 9))}),
        bin);
    expect_refused(json, "mesh 0 primitive 0: KHR_texture_transform takes TEXCOORD_0 0 past a double's range");
}

TEST(GltfTextureTransform, ItsTexCoordReplacesTheTextureInfosWhichNeedNotExist) {
    // texCoord 1 in the texture info, 0 in the transform: only TEXCOORD_0
    // exists, and it is what the texture reads.
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}}, std::string(kTransformUsed) + ",\n" +
                                    surfaces({material("[1, 1, 1, 1]", transformed_file("{\"texCoord\": 0}", 1))},
                                             {{-1, 0}}, {image_json(rgb_png(1, 1, 9, 9, 9))}));
    EXPECT_EQ(load(json).scene.meshes[0].mesh->uvs.size(), 4u);
}

// ================================================================ rendering

TEST(GltfTextureRender, AUniformTextureLooksLikeItsLinearBaseColourFactor) {
    // Texture: 2 x 2 of sRGB 188, base colour factor 1. Untextured: factor
    // 188's linear value, 0.5028864580. Each: 255 x 0.8 x 0.5028865 = 102.59.
    const std::string textured = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        surfaces({material("[1, 1, 1, 1]", tex(0))}, {{-1, 0}}, {image_json(rgb_png(2, 2, 188, 188, 188))}));
    const double l = srgb_to_linear(188);
    const std::string plain = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        surfaces({material("[" + num(l) + ", " + num(l) + ", " + num(l) + ", 1]")}));
    for (const Precision p : kPrecisions) {
        const Image a = top_view(lit(textured), p), b = top_view(lit(plain), p);
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 8; ++i) {
                const Rgb x = pixel(a, i, j), y = pixel(b, i, j);
                for (size_t k = 0; k < 3; ++k) {
                    EXPECT_NEAR(x[k], y[k], 1) << precision_name(p) << " pixel (" << i << ", " << j << ")";
                    EXPECT_NEAR(x[k], 102.59, 0.6) << precision_name(p) << " pixel (" << i << ", " << j << ")";
                }
            }
    }
}

TEST(GltfTextureRender, TheLeftHalfRedTheRightHalfBlue) {
    // 2 x 1 texture red | blue, nearest, clamped: pixel centres x < 0
    // (columns 0-3) read u < 1/2, red: 255 x 0.8 = 204; the others blue.
    // The same with a zero-area triangle first in the mesh (left out of the
    // BVH, so the triangles' texture coordinates must follow their own
    // triangle, not their place in it).
    for (const bool degenerate : {false, true}) {
        Quad q{-1, 1, -1, 1, 0, 0};
        q.degenerate_first = degenerate;
        const std::string json = quads_file(
            {q}, surfaces({material("[1, 1, 1, 1]", tex(0))}, {{0, 0}}, {image_json(rgba_png(2, 1, kRedBlue))},
                          {sampler_json(kClamp, kClamp, kNearest)}));
        for (const Precision p : kPrecisions) {
            const std::string what = std::string(precision_name(p)) + (degenerate ? ", degenerate first" : "");
            const Image im = top_view(lit(json), p);
            expect_columns(im, 0, 4, {204, 0, 0}, what + ", left");
            expect_columns(im, 4, 8, {0, 0, 204}, what + ", right");
        }
    }
}

TEST(GltfTextureRender, BilinearRepeatBlendsInLinearColourAcrossTheWrap) {
    // The same texture with the default sampler (bilinear, repeat). Column
    // i sees x = -0.825 + 0.25 i, u = (x + 1) / 2, texel position 2u - 1/2:
    //   i = 0: -0.325, between texel -1 (blue, wrapped) and 0 at 0.675:
    //          red 0.675 x 204 = 137.7, blue 0.325 x 204 = 66.3
    //   i = 2:  0.175: red 0.825 x 204 = 168.3, blue 35.7
    //   i = 5:  0.925: red 0.075 x 204 = 15.3, blue 188.7
    //   i = 7:  1.425, between texel 1 and 2 (red, wrapped) at 0.425:
    //          red 86.7, blue 117.3
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        surfaces({material("[1, 1, 1, 1]", tex(0))}, {{-1, 0}}, {image_json(rgba_png(2, 1, kRedBlue))}));
    for (const Precision p : kPrecisions) {
        const Image im = top_view(lit(json), p);
        for (int j = 0; j < 8; ++j) {
            expect_pixel(im, 0, j, {138, 0, 66}, precision_name(p));
            expect_pixel(im, 2, j, {168, 0, 36}, precision_name(p));
            expect_pixel(im, 5, j, {15, 0, 189}, precision_name(p));
            expect_pixel(im, 7, j, {87, 0, 117}, precision_name(p));
        }
    }
}

TEST(GltfTextureRender, ATextureTransformMovesWhatThePixelsShow) {
    // scale (-1, 1) then offset (1, 0): u' = 1 - u, the texture mirrored --
    // blue on the left, red on the right.
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        std::string(kTransformUsed) + ",\n" +
            surfaces({material("[1, 1, 1, 1]", transformed_file("{\"offset\": [1, 0], \"scale\": [-1, 1]}"))}, {{0, 0}},
                     {image_json(rgba_png(2, 1, kRedBlue))}, {sampler_json(kClamp, kClamp, kNearest)}));
    for (const Precision p : kPrecisions) {
        const Image im = top_view(lit(json), p);
        expect_columns(im, 0, 4, {0, 0, 204}, precision_name(p));
        expect_columns(im, 4, 8, {204, 0, 0}, precision_name(p));
    }
}

TEST(GltfTextureRender, TheBaseColourFactorTintsTheTexture) {
    // Factor (0.5, 1, 0.25) times texel grey 188 (0.5028865): 204 x
    // (0.2514432, 0.5028865, 0.1257216) = (51.3, 102.6, 25.6).
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        surfaces({material("[0.5, 1, 0.25, 1]", tex(0))}, {{-1, 0}}, {image_json(rgb_png(1, 1, 188, 188, 188))}));
    for (const Precision p : kPrecisions) expect_columns(top_view(lit(json), p), 0, 8, {51, 103, 26}, precision_name(p));
}

TEST(GltfTextureRender, ATextureTransformOfHugeScaleStillReadsTheTexture) {
    // scale (1e300, 1e300), finite as the loader requires: u and v up to
    // 1e300, far past where a texel index can be told -- but every texel of
    // the texture is grey 188, so whatever is read is 0.5029: 102.6 as in
    // the uniform test above, and no sample NaN.
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 0, 0}},
        std::string(kTransformUsed) + ",\n" +
            surfaces({material("[1, 1, 1, 1]", transformed_file("{\"scale\": [1e300, 1e300]}"))}, {{-1, 0}},
                     {image_json(rgb_png(2, 2, 188, 188, 188))}));
    for (const Precision p : kPrecisions) expect_columns(top_view(lit(json), p), 0, 8, {103, 103, 103}, precision_name(p));
}

// ================================================================== cutouts

// A cut-out quad at height 1 over an opaque green one at height 0 (twice
// as wide), both lit from straight above; material 0 the cut-out's,
// material 1 green. Seen from above, 8 x 8 over x, y in [-1, 1].
std::string over_green(const std::string& front, const std::vector<TextureRef>& textures = {},
                       const std::vector<std::string>& images = {}, const std::vector<std::string>& samplers = {},
                       double front_scale = 1) {
    Quad q{-1, 1, -1, 1, 1, 0};
    q.scale = front_scale;
    return quads_file({q, {-2, 2, -2, 2, 0, 1}},
                      surfaces({front, material("[0, 1, 0, 1]")}, textures, images, samplers));
}

const Rgb kLitRed{204, 0, 0}, kLitGreen{0, 204, 0};

TEST(GltfCutouts, CameraRaysSeeThroughTheHoles) {
    // Texture 2 x 1: left blue with alpha 0, right red with alpha 255;
    // MASK at 0.5. Left: the green quad behind, lit (its shadow ray goes
    // through the same hole): 204 green. Right: red, 204. The cut-out quad
    // also as half its size on a node scaled by 2; and seen in perspective
    // from 10 above, each pixel's ray in its own direction: at height 1 it
    // meets the x the orthographic view does, at height 0 x' = 0.05 + 10/9
    // (x - 0.05), which is < 0 (under the hole) wherever x < 0.
    const std::vector<Bytes4> holed = {{0, 0, 255, 0}, {255, 0, 0, 255}};
    for (const double scale : {1.0, 2.0}) {
        const std::string json =
            over_green(material("[1, 1, 1, 1]", tex(0), ", \"alphaMode\": \"MASK\", \"alphaCutoff\": 0.5"), {{0, 0}},
                       {image_json(rgba_png(2, 1, holed))}, {sampler_json(kClamp, kClamp, kNearest)}, scale);
        const Scene s = lit(json);
        ASSERT_EQ(s.materials.size(), 3u);
        EXPECT_TRUE(s.materials[0].cutout);
        EXPECT_DOUBLE_EQ(s.materials[0].alpha, 1);
        EXPECT_DOUBLE_EQ(s.materials[0].alpha_cutoff, 0.5);
        EXPECT_FALSE(s.materials[1].cutout);
        for (const Precision p : kPrecisions)
            for (const Projection proj : {Projection::orthographic, Projection::perspective}) {
                const std::string what = std::string(precision_name(p)) + ", node scale " + num(scale) +
                                         (proj == Projection::perspective ? ", perspective" : "");
                const Image im = top_view(s, p, 8, 8, 1, 0.05, proj);
                expect_columns(im, 0, 4, kLitGreen, what + ", through the hole");
                expect_columns(im, 4, 8, kLitRed, what + ", the solid half");
            }
    }
}

TEST(GltfCutouts, ShadowRaysPassTheHolesAndStopAtTheSolidPart) {
    // A white floor at height 0 (x in [-4, 4]); the cut-out quad at height 1
    // over x, y in [-1, 1], solid red on the left (x < 0), a hole on the
    // right. The sun travels along (1, 0, -1) / sqrt 2: a floor point's
    // shadow ray meets height 1 at x - 1. Lit: 255 (0.2 + 0.6 cos 45°) =
    // 159.2; in shadow, ambient alone: 51. 24 x 8 pixels over x in
    // [-2.95, 3.05]: column i sees x = -2.825 + 0.25 i.
    //   i  0-7  (x < -1):     floor, its shadow ray misses the quad: 159
    //   i  8-11 (-1 < x < 0): the quad's solid half: red 159
    //   i 12-15 (0 < x < 1):  floor through the hole; the shadow ray meets
    //                         the solid half at x - 1 < 0: 51
    //   i 16-19 (1 < x < 2):  floor; the shadow ray goes through the hole: 159
    //   i 20-23 (x > 2):      floor, lit: 159
    const std::vector<Bytes4> half = {{255, 0, 0, 255}, {0, 0, 255, 0}};
    const std::string json = quads_file(
        {{-1, 1, -1, 1, 1, 0}, {-4, 4, -2, 2, 0, 1}},
        surfaces({material("[1, 1, 1, 1]", tex(0), ", \"alphaMode\": \"MASK\""), material("[1, 1, 1, 1]")}, {{0, 0}},
                 {image_json(rgba_png(2, 1, half))}, {sampler_json(kClamp, kClamp, kNearest)}));
    Lighting slanted;
    slanted.direction = {1, 0, -1};
    for (const Precision p : kPrecisions) {
        const Image im = top_view(lit(json, slanted), p, 24, 8, 1);
        const std::string what = precision_name(p);
        expect_columns(im, 0, 8, {159, 159, 159}, what + ", floor beside");
        expect_columns(im, 8, 12, {159, 0, 0}, what + ", the solid half");
        expect_columns(im, 12, 16, {51, 51, 51}, what + ", floor in the solid half's shadow");
        expect_columns(im, 16, 20, {159, 159, 159}, what + ", floor lit through the hole");
        expect_columns(im, 20, 24, {159, 159, 159}, what + ", floor beyond");
    }
}

TEST(GltfCutouts, ManyLayersOfOneMeshUpToTheDocumentedBound) {
    // One primitive of n copies of the holed quad, 0.01 apart from height 1
    // up, over the green quad. Through the left half a ray crosses every
    // copy's hole: 10 or 63 of them, and it reaches the green quad (lit: its
    // shadow ray crosses them too). docs/gltf.md: "A ray that has crossed 63
    // holes of one mesh stops at the 64th as if it were solid" -- with 64
    // copies or more the left half shows the lowest copy's hole texel, blue
    // (its shadow ray crosses the 63 above it and is lit): 204 blue.
    const std::vector<Bytes4> holed = {{0, 0, 255, 0}, {255, 0, 0, 255}};
    for (const int layers : {10, 63, 64, 70}) {
        Quad q{-1, 1, -1, 1, 1, 0};
        q.layers = layers;
        const std::string json = quads_file(
            {q, {-2, 2, -2, 2, 0, 1}},
            surfaces({material("[1, 1, 1, 1]", tex(0), ", \"alphaMode\": \"MASK\""), material("[0, 1, 0, 1]")},
                     {{0, 0}}, {image_json(rgba_png(2, 1, holed))}, {sampler_json(kClamp, kClamp, kNearest)}));
        for (const Precision p : kPrecisions) {
            const std::string what = std::string(precision_name(p)) + ", " + std::to_string(layers) + " layers";
            const Image im = top_view(lit(json), p);
            expect_columns(im, 0, 4, layers < 64 ? kLitGreen : Rgb{0, 0, 204}, what + ", through the holes");
            expect_columns(im, 4, 8, kLitRed, what + ", the solid half");
        }
    }
}

TEST(GltfCutouts, WithoutATextureTheFactorsAlphaDecidesForTheWholeQuad) {
    // alpha 0.3 < cutoff 0.5: not there at all -- the green quad behind is
    // seen and lit; 0.7: there; 0.5 = cutoff: there (at least the cutoff).
    // No alphaCutoff: 0.5 by default (0.45 not there, 0.55 there).
    struct Case {
        std::string color, cutoff;
        bool there;
    };
    const Case cases[] = {{"[1, 0, 0, 0.3]", "0.5", false}, {"[1, 0, 0, 0.7]", "0.5", true},
                          {"[1, 0, 0, 0.5]", "0.5", true},  {"[1, 0, 0, 0.45]", "", false},
                          {"[1, 0, 0, 0.55]", "", true},    {"[1, 0, 0, 1]", "0", true},
                          {"[1, 0, 0, 0.9]", "0.95", false}};
    for (const Case& c : cases) {
        const std::string json = over_green(material(
            c.color, "", ", \"alphaMode\": \"MASK\"" + (c.cutoff.empty() ? "" : ", \"alphaCutoff\": " + c.cutoff)));
        for (const Precision p : kPrecisions) {
            const std::string what = std::string(precision_name(p)) + " alpha " + c.color + " cutoff " + c.cutoff;
            expect_columns(top_view(lit(json), p), 0, 8, c.there ? kLitRed : kLitGreen, what);
        }
    }
}

TEST(GltfCutouts, AlphaIsTheFactorTimesTheTexelAgainstTheCutoff) {
    // Texels red, alpha 127 | 128 (0.498 | 0.502), cutoff 0.5, factor alpha
    // 1: the left half a hole, the right solid. Then factor alpha 0.8, texels
    // alpha 255 | 160, cutoff 0.7: 0.8 solid on the left, 0.8 x 0.627 =
    // 0.502 a hole on the right.
    const std::string edge = over_green(
        material("[1, 1, 1, 1]", tex(0), ", \"alphaMode\": \"MASK\", \"alphaCutoff\": 0.5"), {{0, 0}},
        {image_json(rgba_png(2, 1, {{255, 0, 0, 127}, {255, 0, 0, 128}}))}, {sampler_json(kClamp, kClamp, kNearest)});
    const std::string product = over_green(
        material("[1, 1, 1, 0.8]", tex(0), ", \"alphaMode\": \"MASK\", \"alphaCutoff\": 0.7"), {{0, 0}},
        {image_json(rgba_png(2, 1, {{255, 0, 0, 255}, {255, 0, 0, 160}}))}, {sampler_json(kClamp, kClamp, kNearest)});
    for (const Precision p : kPrecisions) {
        const Image a = top_view(lit(edge), p), b = top_view(lit(product), p);
        expect_columns(a, 0, 4, kLitGreen, std::string(precision_name(p)) + ", alpha 127");
        expect_columns(a, 4, 8, kLitRed, std::string(precision_name(p)) + ", alpha 128");
        expect_columns(b, 0, 4, kLitRed, std::string(precision_name(p)) + ", 0.8 x 1");
        expect_columns(b, 4, 8, kLitGreen, std::string(precision_name(p)) + ", 0.8 x 160/255");
    }
}

TEST(GltfCutouts, AVertexAlphaMultipliesTheMaterialsAlpha) {
    // COLOR_0 white, its alpha 0 at the cut-out quad's left edge (x = -1)
    // and 1 at its right (x = 1): alpha (x + 1) / 2 across both triangles.
    // MASK at 0.5: a hole where x < 0 (the green quad behind, lit through
    // it), red where x > 0 (columns 4-7; column 3 sees x = -0.125, alpha
    // 0.4375; column 4 x = 0.125, 0.5625). Factor alpha 0.8 and cutoff 0.5:
    // solid where 0.8 (x + 1) / 2 >= 0.5, x >= 0.25: column 5 (x = 0.375) on.
    // OPAQUE: red throughout.
    Quad q{-1, 1, -1, 1, 1, 0};
    q.colors = {1, 1, 1, 0, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 1, 0};
    q.color_kind = "VEC4";
    auto json = [&](const std::string& color, const std::string& mode) {
        return quads_file({q, {-2, 2, -2, 2, 0, 1}},
                          surfaces({material(color, "", ", \"alphaMode\": \"" + mode + "\""), material("[0, 1, 0, 1]")}));
    };
    for (const Precision p : kPrecisions) {
        const std::string what = precision_name(p);
        const Image half = top_view(lit(json("[1, 0, 0, 1]", "MASK")), p);
        expect_columns(half, 0, 4, kLitGreen, what + ", alpha under 0.5");
        expect_columns(half, 4, 8, kLitRed, what + ", alpha over 0.5");
        const Image factor = top_view(lit(json("[1, 0, 0, 0.8]", "MASK")), p);
        expect_columns(factor, 0, 5, kLitGreen, what + ", 0.8 x alpha under 0.5");
        expect_columns(factor, 5, 8, kLitRed, what + ", 0.8 x alpha over 0.5");
        expect_columns(top_view(lit(json("[1, 0, 0, 1]", "OPAQUE")), p), 0, 8, kLitRed, what + ", opaque");
    }
}

TEST(GltfCutouts, OpaqueIgnoresAlpha) {
    // alphaMode OPAQUE (and none): factor alpha 0 and texel alpha 0 are
    // still drawn, red.
    for (const std::string mode : {"", ", \"alphaMode\": \"OPAQUE\""}) {
        const std::string json =
            over_green(material("[1, 1, 1, 0]", tex(0), mode), {{-1, 0}},
                       {image_json(rgba_png(1, 1, {{255, 0, 0, 0}}))});
        const Scene s = lit(json);
        EXPECT_FALSE(s.materials[0].cutout);
        for (const Precision p : kPrecisions) expect_columns(top_view(s, p), 0, 8, kLitRed, precision_name(p) + mode);
    }
}

TEST(GltfCutouts, BadAlphaModesAndCutoffsAreRefused) {
    expect_input_error([&] { load(over_green(material("[1, 1, 1, 1]", "", ", \"alphaMode\": \"CLIP\""))); }, "t.gltf",
                       "material 0: alphaMode 'CLIP' is not OPAQUE, MASK or BLEND");
    expect_input_error(
        [&] { load(over_green(material("[1, 1, 1, 1]", "", ", \"alphaMode\": \"MASK\", \"alphaCutoff\": -0.5"))); },
        "t.gltf", "material 0: alphaCutoff must be >= 0");
}

// =============================================================== bad images

// A file whose one material shows texture 0, with these textures, images
// and samplers.
std::string textured_file(const std::vector<TextureRef>& textures, const std::vector<std::string>& images,
                          const std::vector<std::string>& samplers = {}) {
    return quads_file({{-1, 1, -1, 1, 0, 0}}, surfaces({material("[1, 1, 1, 1]", tex(0))}, textures, images, samplers));
}


TEST(GltfTextureBadImages, NeitherPngNorJpeg) {
    const std::string gif = "GIF89a: six bytes of signature, then anything";
    expect_refused(textured_file({{-1, 0}}, {image_json(gif)}), "image 0: not a PNG or JPEG image");
    expect_refused(textured_file({{-1, 0}}, {image_json(gif, ", \"name\": \"leaf\"")}),
                   "image 0 ('leaf'): not a PNG or JPEG image");
    // The first bytes decide, not the mimeType.
    expect_refused(textured_file({{-1, 0}}, {"{\"uri\": \"data:image/png;base64," + base64("plain text, not pixels") + "\"}"}),
                   "image 0: not a PNG or JPEG image");
}

TEST(GltfTextureBadImages, ATruncatedPngCannotBeDecoded) {
    // 8 x 8 of noise (so its pixel data is more than a few bytes), cut in
    // half: the header is whole, the pixels are not. Cut to 20 bytes: not
    // even the header.
    Image noise(8, 8);
    for (size_t i = 0; i < noise.rgb.size(); ++i) noise.rgb[i] = std::uint8_t((i * 7919u + 13u) % 251u);
    const std::string png = as_string(encode_png(noise));
    ASSERT_GT(png.size(), 100u);
    expect_refused(textured_file({{-1, 0}}, {image_json(png.substr(0, png.size() / 2))}), "image 0: cannot be decoded");
    expect_refused(textured_file({{-1, 0}}, {image_json(png.substr(0, 20))}), "image 0: cannot be decoded");
    // The whole file loads.
    EXPECT_EQ(load(textured_file({{-1, 0}}, {image_json(png)})).scene.textures[0].image->width, 8);
}

TEST(GltfTextureBadImages, AHeaderClaimingTooManyTexels) {
    // Refused from the header alone, before any pixel is allocated: 20000 a
    // side (grey), and 16384 x 4097 = 67,125,248 texels in all (RGB).
    expect_refused(textured_file({{-1, 0}}, {image_json(png_header(20000, 20000, 0))}),
                   "image 0: 20000 x 20000 texels (the limit is 16,384 a side and 67,108,864 in all)");
    expect_refused(textured_file({{-1, 0}}, {image_json(png_header(16384, 4097, 2))}),
                   "image 0: 16384 x 4097 texels (the limit is 16,384 a side and 67,108,864 in all)");
    expect_refused(textured_file({{-1, 0}}, {image_json(png_header(40000, 1, 6))}), "image 0: 40000 x 1 texels (the limit");
}

TEST(GltfTextureBadImages, AnRgbaHeaderClaimingTooManyTexelsNamesTheLimit) {
    // The same 20000 x 20000 claim in RGBA, as a base colour texture with
    // alpha is: the same limit, the same message.
    expect_refused(textured_file({{-1, 0}}, {image_json(png_header(20000, 20000, 6))}),
                   "image 0: 20000 x 20000 texels (the limit is 16,384 a side and 67,108,864 in all)");
}

TEST(GltfTextureBadImages, AnImageFileThatIsNotThere) {
    TempFolder dir("textures_missing");
    const std::string path = dir.write("m.gltf", textured_file({{-1, 0}}, {"{\"uri\": \"missing.png\"}"}));
    expect_input_error([&] { load_gltf(path); }, path, "cannot find 'missing.png' beside the model");
}

TEST(GltfTextureBadImages, SamplersAndTexturesThatAreNotGltfs) {
    const std::string red = image_json(rgb_png(1, 1, 255, 0, 0));
    expect_refused(textured_file({{0, 0}}, {red}, {sampler_json(12345, kRepeat)}),
                   "texture 0: wrap mode 12345 is not glTF's (10497, 33648 or 33071)");
    expect_refused(textured_file({{0, 0}}, {red}, {sampler_json(kRepeat, 9729)}),
                   "texture 0: wrap mode 9729 is not glTF's (10497, 33648 or 33071)");
    expect_refused(textured_file({{0, 0}}, {red}, {sampler_json(kRepeat, kRepeat, 9987)}),
                   "texture 0: magFilter 9987 is not glTF's (9728 or 9729)");
    expect_refused(textured_file({{0, 0}}, {red}, {sampler_json(kRepeat, kRepeat, -1, 9730)}),
                   "texture 0: minFilter 9730 is not glTF's (9728, 9729 or 9984-9987)");
    expect_refused(textured_file({{-1, 5}}, {red}), "texture 0: it has no image firsthit can read");
    expect_refused(textured_file({{-1, -1}}, {red}), "texture 0: it has no image firsthit can read");
    expect_refused(textured_file({{3, 0}}, {red}, {sampler_json(kRepeat, kRepeat)}), "texture 0: sampler 3 does not exist");
    // The material's texture itself missing.
    expect_refused(quads_file({{-1, 1, -1, 1, 0, 0}}, surfaces({material("[1, 1, 1, 1]", tex(2))}, {{-1, 0}}, {red})),
                   "texture 2 does not exist");
}

TEST(GltfTextureBadImages, ABaseColourTextureNeedsItsTexcoordSet) {
    Quad q{-1, 1, -1, 1, 0, 0};
    q.uvs = false;
    expect_refused(quads_file({q}, surfaces({material("[1, 1, 1, 1]", tex(0))}, {{-1, 0}}, {image_json(rgb_png(1, 1, 1, 1, 1))})),
                   "mesh 0 primitive 0: its material reads TEXCOORD_0, which it does not have");
    // Without the texture the same quad loads.
    EXPECT_NO_THROW(load(quads_file({q}, surfaces({material("[1, 1, 1, 1]")}))));
}

// ============================================================ vertex colours

TEST(GltfVertexColors, ReadAsLinearColoursClampedToOne) {
    // Floats, VEC3: as written, clamped to [0, 1].
    Quad q{-1, 1, -1, 1, 0, 0};
    q.colors = {1, 0, 0, 0.5, 0.25, 0, 0, 0, 1, 2, -1, 0.75};
    GltfFile f = load(quads_file({q}, surfaces({material("[1, 1, 1, 1]")})));
    ASSERT_EQ(f.scene.meshes.size(), 1u);
    const std::vector<dvec3>& c = f.scene.meshes[0].mesh->colors;
    ASSERT_EQ(c.size(), 4u);
    expect_vec(c[0], {1, 0, 0});
    expect_vec(c[1], {0.5, 0.25, 0});
    expect_vec(c[2], {0, 0, 1});
    expect_vec(c[3], {1, 0, 0.75});
    // Normalized unsigned bytes, VEC4 (the alpha is not drawn): c / 255.
    q.colors = {255, 0, 51, 7, 0, 255, 0, 255, 102, 102, 102, 0, 1, 2, 3, 4};
    q.color_kind = "VEC4";
    q.color_type = kUnsignedByte;
    f = load(quads_file({q}, surfaces({material("[1, 1, 1, 1]")})));
    const std::vector<dvec3>& b = f.scene.meshes[0].mesh->colors;
    ASSERT_EQ(b.size(), 4u);
    expect_vec(b[0], {1, 0, 0.2});
    expect_vec(b[2], {0.4, 0.4, 0.4});
    expect_vec(b[3], {1 / 255.0, 2 / 255.0, 3 / 255.0});
    // Their alphas kept (one is under 1), for a MASKed material.
    EXPECT_EQ(f.scene.meshes[0].mesh->alphas, (std::vector<double>{7 / 255.0, 1, 0, 4 / 255.0}));
    // Normalized unsigned shorts: c / 65535.
    q.color_type = kUnsignedShort;
    q.colors = {65535, 0, 0, 0, 0, 65535, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
    f = load(quads_file({q}, surfaces({material("[1, 1, 1, 1]")})));
    expect_vec(f.scene.meshes[0].mesh->colors[0], {1, 0, 0});
    expect_vec(f.scene.meshes[0].mesh->colors[1], {0, 65535 / 65535.0, 0});
    // Alphas all 1 (or a VEC3): none kept.
    q.colors = {65535, 0, 0, 65535, 0, 0, 65535, 65535, 0, 0, 0, 65535, 0, 0, 0, 65535};
    EXPECT_TRUE(load(quads_file({q}, surfaces({material("[1, 1, 1, 1]")}))).scene.meshes[0].mesh->alphas.empty());
}

TEST(GltfVertexColors, WhatTheSpecificationForbidsIsRefused) {
    Quad q{-1, 1, -1, 1, 0, 0};
    q.colors = {1, 1, 1, 1};
    q.color_kind = "SCALAR";
    expect_refused(quads_file({q}, surfaces({material("[1, 1, 1, 1]")})), "mesh 0 primitive 0: COLOR_0 is not a VEC3 or VEC4");
    q.colors = std::vector<double>(16, 255);
    q.color_kind = "VEC4";
    q.color_type = kUnsignedByte;
    q.color_normalized = false;
    expect_refused(quads_file({q}, surfaces({material("[1, 1, 1, 1]")})),
                   "mesh 0 primitive 0: COLOR_0 is not floats or normalized unsigned bytes or shorts");
}

TEST(GltfVertexColors, TheyMultiplyTheBaseColourAndTheTexture) {
    // Ambient light only (a pixel is 255 baseColor COLOR_0, lit()'s
    // ambient 1 being the whole colour): red at the quad's top edge (y = 1:
    // its vertices 0 and 1), blue at its bottom (y = -1), so between them
    // COLOR_0 = ((1 + y) / 2, 0, (1 - y) / 2), linear in y in both of the
    // quad's triangles. Row j sees y = 1 - (j + 1/2) / 4: row 0 y = 0.875,
    // (0.9375, 0, 0.0625) 255 = (239.06, 0, 15.94); row 3 y = 0.125,
    // (0.5625, 0, 0.4375) 255 = (143.44, 0, 111.56); row 7 y = -0.875,
    // (15.94, 0, 239.06).
    Quad q{-1, 1, -1, 1, 0, 0};
    q.colors = {1, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 1};
    const Lighting ambient_only{1.0, 0.0};
    for (const Precision p : kPrecisions) {
        const Image plain = top_view(lit(quads_file({q}, surfaces({material("[1, 1, 1, 1]")})), ambient_only), p);
        for (int i = 0; i < 8; ++i) {
            expect_pixel(plain, i, 0, {239, 0, 16}, "row 0");
            expect_pixel(plain, i, 3, {143, 0, 112}, "row 3");
            expect_pixel(plain, i, 7, {16, 0, 239}, "row 7");
        }
        // Above 19 green layers in the same primitive, written first (40
        // triangles, more than a leaf holds, the top ones first in the file
        // and last in the tree's order): the top layer's own colours.
        Quad layered = q;
        layered.layers = 20;
        layered.layer_step = -0.01;
        for (int k = 0; k < 4 * 19; ++k) layered.colors.insert(layered.colors.end(), {0, 1, 0});
        const Image top = top_view(lit(quads_file({layered}, surfaces({material("[1, 1, 1, 1]")})), ambient_only), p);
        for (int i = 0; i < 8; ++i) expect_pixel(top, i, 3, {143, 0, 112}, "top layer, row 3");
        // A base colour factor of (0.5, 1, 1) halves the red.
        const Image half = top_view(lit(quads_file({q}, surfaces({material("[0.5, 1, 1, 1]")})), ambient_only), p);
        expect_pixel(half, 4, 3, {72, 0, 112}, "half red, row 3");
        // A texture too (nearest texels): white on the left, (0, 0, 255) on
        // the right, so the left half shows the colours and the right only
        // their blue.
        const std::string textured =
            quads_file({q}, surfaces({material("[1, 1, 1, 1]", tex(0))}, {{0, 0}},
                                     {image_json(rgba_png(2, 1, {{255, 255, 255, 255}, {0, 0, 255, 255}}))},
                                     {sampler_json(kRepeat, kRepeat, kNearest)}));
        const Image both = top_view(lit(textured, ambient_only), p);
        expect_pixel(both, 1, 3, {143, 0, 112}, "white texel, row 3");
        expect_pixel(both, 6, 3, {0, 0, 112}, "blue texel, row 3");
    }
}

TEST(GltfVertexColors, EmissiveIsNotMultiplied) {
    // Base colour 0.2, emissive (0, 0.2, 0) = (0, 51, 0), ambient light only
    // (1): a quad with all-red vertex colours is 255 (0.2, 0, 0) + (0, 51, 0)
    // = (51, 51, 0); the same material on a quad without COLOR_0 (0.2, 0.2,
    // 0.2) 255 + (0, 51, 0) = (51, 102, 51), and so is a plane of the
    // world's own (z = -1) given that material by name, seen past the quads
    // (half height 2: columns 0 and 7 see x = -1.7 and 1.8).
    Quad red{-1, 0, -1, 1, 0, 0}, plain{0, 1, -1, 1, 0, 0};
    red.colors = {1, 0, 0, 1, 0, 0, 1, 0, 0, 1, 0, 0};
    const std::string json =
        quads_file({red, plain}, surfaces({material("[0.2, 0.2, 0.2, 1]", "", ", \"emissiveFactor\": [0, 0.2, 0]")}));
    for (const Precision p : kPrecisions) {
        Scene s = lit(json, {1.0, 0.0});
        ASSERT_EQ(s.material_names[0], "m/material 0");
        s.planes.push_back({{0, 0, 1}, -1, 0});
        const Image im = top_view(s, p, 8, 8, 2.0);
        expect_pixel(im, 3, 4, {51, 51, 0}, "coloured quad");
        expect_pixel(im, 4, 4, {51, 102, 51}, "quad without colours");
        expect_pixel(im, 0, 4, {51, 102, 51}, "the world's plane, left");
        expect_pixel(im, 7, 4, {51, 102, 51}, "the world's plane, right");
    }
}

TEST(GltfVertexColors, ATexturedMaterialOnTheWorldsOwnSurfaceKeepsItsEmissive) {
    // A file whose one node holds no mesh, and a textured material with
    // emissive (0, 0.2, 0), given to a plane of the world's own: no
    // instances, no texture coordinates, so albedo 1: 255 0.2 + (0, 51, 0).
    const std::string json = gltf_json(
        "\"scenes\": [{\"nodes\": [0]}], \"nodes\": [{}],\n" +
        surfaces({material("[0.2, 0.2, 0.2, 1]", tex(0), ", \"emissiveFactor\": [0, 0.2, 0]")}, {{-1, 0}},
                 {image_json(rgb_png(1, 1, 9, 9, 9))}));
    for (const Precision p : kPrecisions) {
        Scene s = lit(json, {1.0, 0.0});
        ASSERT_TRUE(s.instances.empty());
        s.planes.push_back({{0, 0, 1}, -1, 0});
        expect_columns(top_view(s, p), 0, 8, {51, 102, 51}, "plane");
    }
}

}  // namespace
}  // namespace fh
