// glTF textures seen from far away (gltf/gltf_materials.cpp, scene/texture.h,
// render/texture_footprint.h): each minFilter as the texture's filters,
// mipmaps made once per image, the pixels of a fine checkerboard that a
// pixel covers 8 x 8 texels of, and of stripes on a slanted quad -- worked
// out by hand.
//
// The quad x in [-1, 1], y in [-0.99, 1.01] at z = 0 carries a 64 x 64
// checkerboard of single black and white texels (TEXCOORD_0 over the whole
// quad). The 8 x 8 orthographic top view (half height 1) makes each pixel
// 0.25 units wide, and so its ray cone; on the quad, u runs 1/2 a unit, so
// the footprint is 1/8 of the image each way: lod -3, lambda = -3 + log2 64
// = 3. Level 3 averages 8 x 8 blocks, half black and half white: linear
// 0.5, the sRGB byte 188, which reads as linear 0.50289 -- as does every
// level below the image. Lit by ambient 0.2 and a sun of 0.6 straight
// down: 255 * 0.8 * 0.50289 = 102.6, the pixel 103.
//
// Read without mipmaps (minFilter NEAREST), every pixel centre lands on a
// white texel -- x = -0.825 + 0.25 i gives column (x + 1) * 32 = 5.6 + 8 i,
// texel 5 + 8 i; y = 0.875 - 0.25 j gives row (1.01 - y) * 32 = 4.32 + 8 j,
// texel 4 + 8 j; (5 + 4) is odd: white -- and the image is 204 throughout:
// the aliasing mipmaps are for.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "gltf/gltf_quads.h"
#include "images/png_writer.h"
#include "render/texture_footprint.h"

namespace fh {
namespace gltf_mipmaps_test {

using namespace gltf_test;

constexpr int kMinNearest = 9728, kMinLinear = 9729;
constexpr int kNearestMipmapNearest = 9984, kLinearMipmapNearest = 9985, kNearestMipmapLinear = 9986,
              kLinearMipmapLinear = 9987;

// A PNG of an n x n checkerboard of single texels, white where i + j is odd.
std::string checker_png(int n) {
    Image im(n, n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c) im.rgb[3 * (size_t(j) * size_t(n) + size_t(i)) + size_t(c)] = (i + j) % 2 ? 255 : 0;
    return as_string(encode_png(im));
}

// The quad with the checkerboard, through sampler `sampler` (empty: none).
std::string checker_file(const std::string& sampler, double node_scale = 1) {
    Quad q{-1, 1, -0.99, 1.01, 0, 0};
    q.scale = node_scale;
    return quads_file({q}, surfaces({material("[1, 1, 1, 1]", tex(0))}, {{sampler.empty() ? -1 : 0, 0}},
                                    {image_json(checker_png(64))},
                                    sampler.empty() ? std::vector<std::string>{} : std::vector<std::string>{sampler}));
}

const Rgb kWhite = {204, 204, 204};
const Rgb kGrey = {103, 103, 103};

TEST(GltfMipmaps, MinFiltersMapOntoLevelsAndFilters) {
    struct Case {
        int min;
        Filter within;
        MipFilter between;
    };
    const Case cases[] = {{-1, Filter::bilinear, MipFilter::linear},  // undefined: trilinear
                          {kMinNearest, Filter::nearest, MipFilter::none},
                          {kMinLinear, Filter::bilinear, MipFilter::none},
                          {kNearestMipmapNearest, Filter::nearest, MipFilter::nearest},
                          {kLinearMipmapNearest, Filter::bilinear, MipFilter::nearest},
                          {kNearestMipmapLinear, Filter::nearest, MipFilter::linear},
                          {kLinearMipmapLinear, Filter::bilinear, MipFilter::linear}};
    for (const Case& c : cases) {
        const GltfFile f = load(checker_file(sampler_json(kRepeat, kRepeat, kNearest, c.min)));
        ASSERT_EQ(f.scene.textures.size(), 1u);
        const Texture& t = f.scene.textures[0];
        EXPECT_EQ(t.filter, Filter::nearest) << c.min;  // magFilter as before
        EXPECT_EQ(t.min_filter, c.within) << c.min;
        EXPECT_EQ(t.mips, c.between) << c.min;
        ASSERT_EQ(t.smaller != nullptr, c.between != MipFilter::none) << c.min;
        if (t.smaller) EXPECT_EQ(t.smaller->levels.size(), 6u) << c.min;  // 32, 16, 8, 4, 2, 1
    }
    // No sampler at all: glTF's "auto filtering", trilinear.
    const GltfFile f = load(checker_file(""));
    EXPECT_EQ(f.scene.textures[0].mips, MipFilter::linear);
}

TEST(GltfMipmaps, TexturesOfOneImageShareItsMipmaps) {
    // Two textures of image 0 through two samplers, both read as colour.
    const std::string json = quads_file(
        {{-1, 0, -1, 1, 0, 0}, {0, 1, -1, 1, 0, 1}},
        surfaces({material("[1, 1, 1, 1]", tex(0)), material("[1, 1, 1, 1]", tex(1))}, {{0, 0}, {1, 0}},
                 {image_json(checker_png(8))},
                 {sampler_json(kRepeat, kRepeat), sampler_json(kClamp, kClamp, -1, kNearestMipmapNearest)}));
    const GltfFile f = load(json);
    ASSERT_EQ(f.scene.textures.size(), 2u);
    EXPECT_EQ(f.scene.textures[0].smaller, f.scene.textures[1].smaller);
}

TEST(GltfMipmaps, OnlySeeThroughBaseColoursWeighColourByAlpha) {
    // One glTF texture, red opaque beside blue clear, on an OPAQUE and a
    // MASKed material. Only the MASKed surface's mipmaps leave the clear
    // blue out (level 1: red 255); the OPAQUE one, whose alpha glTF
    // ignores, shows both up close and their mean far away (188, 0, 188).
    const std::string json = quads_file(
        {{-1, 0, -1, 1, 0, 0}, {0, 1, -1, 1, 0, 1}},
        surfaces({material("[1, 1, 1, 1]", tex(0)), material("[1, 1, 1, 1]", tex(0), ", \"alphaMode\": \"MASK\"")},
                 {{-1, 0}}, {image_json(rgba_png(2, 1, {{255, 0, 0, 255}, {0, 0, 255, 0}}))}));
    const GltfFile f = load(json);
    const Scene& s = f.scene;
    ASSERT_EQ(s.textures.size(), 2u);
    const MipChain& opaque = *s.textures[size_t(s.materials[0].texture)].smaller;
    const MipChain& masked = *s.textures[size_t(s.materials[1].texture)].smaller;
    EXPECT_EQ(opaque.rgba[0], 188);
    EXPECT_EQ(opaque.rgba[2], 188);
    EXPECT_EQ(masked.rgba[0], 255);
    EXPECT_EQ(masked.rgba[2], 0);
}

TEST(GltfMipmaps, AFineCheckerboardSeenFromFarIsItsMean) {
    for (Precision p : kPrecisions) {
        for (int min : {-1, kLinearMipmapLinear, kNearestMipmapNearest, kLinearMipmapNearest, kNearestMipmapLinear})
            expect_columns(top_view(lit(checker_file(sampler_json(kRepeat, kRepeat, -1, min))), p), 0, 8, kGrey,
                           "minFilter " + std::to_string(min) + ", " + precision_name(p));
        // Without mipmaps: one texel per pixel, all white here.
        expect_columns(top_view(lit(checker_file(sampler_json(kRepeat, kRepeat, -1, kMinNearest))), p), 0, 8, kWhite,
                       std::string("NEAREST, ") + precision_name(p));
    }
}

TEST(GltfMipmaps, TheFootprintFollowsTheInstancesScale) {
    // The quad's positions halved and its node scaled by 2: the same quad
    // in the world, its triangles half as big in their own space -- the
    // same footprint, the same grey.
    for (Precision p : kPrecisions)
        expect_columns(top_view(lit(checker_file(sampler_json(kRepeat, kRepeat), 2)), p), 0, 8, kGrey,
                       precision_name(p));
}

// A PNG of n x n texels in vertical stripes `width` texels wide, black
// first (across: horizontal ones, black at the top).
std::string stripes_png(int n, int width, bool across = false) {
    Image im(n, n);
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i)
            for (int c = 0; c < 3; ++c)
                im.rgb[3 * (size_t(j) * size_t(n) + size_t(i)) + size_t(c)] = ((across ? j : i) / width) % 2 ? 255 : 0;
    return as_string(encode_png(im));
}

// The quad q with stripes 8 texels wide (across: horizontal), trilinear.
std::string striped(const Quad& q, bool across = false) {
    return quads_file({q}, surfaces({material("[1, 1, 1, 1]", tex(0))}, {{0, 0}},
                                    {image_json(stripes_png(64, 8, across))}, {sampler_json(kRepeat, kRepeat)}));
}

TEST(GltfMipmaps, LambdaPicksTheLevel) {
    // 64 x 64 texels in stripes 8 wide: levels 0-3 keep them, 8 to 1
    // texels wide; level 4 is grey. At lambda = 3 a pixel is level 3
    // alone: pixel column i (u * 64 = 5.6 + 8 i) has u * 8 - 1/2 = 0.2 + i
    // there, 0.8 of texel i (stripe i) and 0.2 of texel i + 1. Linear:
    // white columns (odd i) 0.8 * 204 = 163.2 -> 163, black ones (even i)
    // 0.2 * 204 = 40.8 -> 41. A tenth of a level more would blend in a
    // tenth of level 4's grey (157 and 47).
    //
    // The same quad, its node stretched 2 or 1/4 along x (its positions'
    // x divided by that): the same world, the same footprint, the same
    // pixels -- a footprint taken in the mesh's own space with one scale
    // would be sqrt(2) too wide. Stretched 3 along its normal: nothing
    // moves (the quad lies at z = 0), and nothing changes.
    struct Node {
        double stretch, lift;
    };
    for (const Node node : {Node{1, 1}, Node{2, 1}, Node{0.25, 1}, Node{1, 3}}) {
        Quad q{-1, 1, -0.99, 1.01, 0, 0};
        q.stretch = node.stretch;
        q.lift = node.lift;
        for (Precision p : kPrecisions) {
            const Image im = top_view(lit(striped(q)), p);
            const std::string what =
                "stretch " + num(node.stretch) + ", lift " + num(node.lift) + ", " + precision_name(p);
            for (int i = 0; i < 8; ++i) {
                const int v = i % 2 ? 163 : 41;
                for (int j = 0; j < 8; ++j) expect_pixel(im, i, j, {v, v, v}, what);
            }
        }
    }
}

// The quad turned 60 degrees about x (its normal (0, -sin 60, cos 60)),
// seen from above by 8 x 4 pixels 0.25 wide (half height 0.5), lit along
// its normal as the flat quad is from above. Pixel row j sees y = 0.375 -
// 0.25 j, where the quad's own y is twice that: v = (1.01 - y) / 2 = 0.13
// + 0.25 j; columns see the flat quad's u. Across the rays, x, a pixel's
// footprint is 1/8 of the image as before; along v it falls on 1 / cos 60
// = 2 times as much of the quad: 1/4. So two reads at lambda 3, at v
// -+ 1/16 -- where a footprint read once by its length would be lambda 4,
// level 4's grey: 103.
Quad tilted() {
    Quad q{-1, 1, -0.99, 1.01, 0, 0};
    q.tilt = 60;
    return q;
}
Lighting along_tilted_normal() {
    Lighting l;
    l.direction = {0, std::sin(kPi / 3), -std::cos(kPi / 3)};
    return l;
}

TEST(GltfMipmaps, ASlantedQuadKeepsItsStripesAcross) {
    // Stripes across x, the footprint's width: both reads see level 3's
    // 0.8 and 0.2 of the flat quad -- 163 and 41.
    for (Precision p : kPrecisions) {
        const Image im = top_view(lit(striped(tilted()), along_tilted_normal()), p, 8, 4, 0.5);
        for (int i = 0; i < 8; ++i) {
            const int v = i % 2 ? 163 : 41;
            for (int j = 0; j < 4; ++j) expect_pixel(im, i, j, {v, v, v}, precision_name(p));
        }
    }
}

TEST(GltfMipmaps, ASlantedQuadIsReadAlongItsLength) {
    // Horizontal stripes, along the footprint's length: the reads at v =
    // 0.0675 + 0.25 j and 0.1925 + 0.25 j find level 3's rows (one a
    // stripe, black first) at v * 8 - 1/2 = 0.04 + 2 j and 1.04 + 2 j:
    // 0.04 and 0.96 of white, 0.5 together: 0.5 * 204 = 102. (One read at
    // the centre, 0.54 + 2 j: 110.)
    for (Precision p : kPrecisions) {
        const Image im = top_view(lit(striped(tilted(), true), along_tilted_normal()), p, 8, 4, 0.5);
        for (int i = 0; i < 8; ++i)
            for (int j = 0; j < 4; ++j) expect_pixel(im, i, j, {102, 102, 102}, precision_name(p));
    }
}

TEST(GltfMipmaps, ANonSquareTextureIsReadInItsTexels) {
    // 128 x 64 texels on the square quad, in vertical stripes 16 wide: a
    // pixel's footprint, 1/8 of the image each way, is 16 texels along u
    // and 8 along v -- two reads along u at lambda 3, at u -+ 4/128. Level
    // 3 (16 x 8) has stripes 2 wide; column i (u * 16 = 1.4 + 2 i) reads
    // it at 0.9 + 2 i, all stripe i, and 1.9 + 2 i, 0.6 of stripe i and
    // 0.4 of stripe i + 1: 0.8 and 0.2 together -- 163 and 41. Measured in
    // (u, v) the footprint would be round: one read at lambda 3.5, 0.9 and
    // 0.1 (184 and 20).
    const std::string json = quads_file({{-1, 1, -0.99, 1.01, 0, 0}},
                                        surfaces({material("[1, 1, 1, 1]", tex(0))}, {{0, 0}},
                                                 {image_json([] {
                                                     Image im(128, 64);
                                                     for (size_t k = 0; k < im.rgb.size(); ++k)
                                                         im.rgb[k] = (k / 3 % 128 / 16) % 2 ? 255 : 0;
                                                     return as_string(encode_png(im));
                                                 }())},
                                                 {sampler_json(kRepeat, kRepeat)}));
    for (Precision p : kPrecisions) {
        const Image im = top_view(lit(json), p);
        for (int i = 0; i < 8; ++i) {
            const int v = i % 2 ? 163 : 41;
            for (int j = 0; j < 8; ++j) expect_pixel(im, i, j, {v, v, v}, precision_name(p));
        }
    }
}

TEST(GltfMipmaps, TheFootprintIsTheConesShadowUnderAnyNodeMatrix) {
    // The quad placed by a node matrix that turns, shears and stretches
    // (and, negated, mirrors): footprint_on's ellipse against one found
    // the long way -- points of the cone's round cross-section carried
    // along the ray onto the quad's plane in the world, and into (u, v)
    // by the quad's own corners there. For the diameters g1, g2 of any
    // ellipse, the points' mean of p p^T is (g1 g1^T + g2 g2^T) / 8, which
    // the two must agree on, for rays from every side. A map taken the
    // wrong way round (L^T for L) gives another ellipse.
    for (const double sign : {1.0, -1.0}) {
        Quad q{-1, 1, -0.99, 1.01, 0, 0};
        q.matrix = {1.3 * sign, 0.1, -0.3, 0, 0.4, 0.7, 0.2, 0, -0.2, 0.5, 1.1, 0, 0.5, -0.2, 0.3, 1};
        const Scene s = z_up(striped(q));
        const auto flat = FlatScene<double>::build(s, plan_effects(s, Effects{}, 5));
        ASSERT_TRUE(flat.instances != nullptr);
        const FlatInstance<double>& instance = flat.instances->instances[0];
        const FlatGeometry<double>& mesh = *flat.instances->meshes[size_t(instance.mesh)];
        // The quad's corners and their (u, v) in the world: the uv map of
        // its plane, u = u0 + (p - c0) . gu and so on.
        const Mesh& m = *s.meshes[0].mesh;
        const auto& t = m.triangles[0];
        dvec3 c[3];
        for (int k = 0; k < 3; ++k) c[k] = dvec3(s.instances[0].to_world * glm::dvec4(m.positions[t[size_t(k)]], 1));
        const dvec3 e1 = c[1] - c[0], e2 = c[2] - c[0], n = glm::cross(e1, e2);
        const dvec2 d1 = m.uvs[t[1]] - m.uvs[t[0]], d2 = m.uvs[t[2]] - m.uvs[t[0]];
        auto uv_of = [&](const dvec3& p) {  // (u, v) - (u0, v0) at p on the plane, by Cramer's rule
            const double a = glm::dot(glm::cross(p - c[0], e2), n) / glm::dot(n, n);
            const double b = glm::dot(glm::cross(e1, p - c[0]), n) / glm::dot(n, n);
            return a * d1 + b * d2;
        };
        const double width = 0.01;
        Vec3Lanes<double> direction;
        for (int k = 0; k < kLanes<double>; ++k) {
            const dvec3 d = glm::normalize(dvec3(std::sin(1.3 * k + 0.2), std::cos(0.7 * k + 0.5), 0.4 * k - 1.5));
            direction.x[k] = d.x, direction.y[k] = d.y, direction.z[k] = d.z;
        }
        for (const int prim : {0, 1}) {
            const UvFootprint<double> f =
                footprint_on(mesh, prim, instance, direction, splat(width), first_lanes<double>(kLanes<double>));
            for (int k = 0; k < kLanes<double>; ++k) {
                const dvec3 d(direction.x[k], direction.y[k], direction.z[k]);
                const dvec3 s1 = glm::normalize(glm::cross(d, dvec3(0.3, 0.5, 0.8))), s2 = glm::cross(d, s1);
                const dvec3 centre = (c[0] + c[1] + c[2]) / 3.0;
                double mean[3] = {0, 0, 0};  // of p_u^2, p_u p_v, p_v^2
                const int points = 16;
                for (int i = 0; i < points; ++i) {
                    const double phi = 2 * kPi * i / points;
                    const dvec3 q0 = centre + 0.5 * width * (std::cos(phi) * s1 + std::sin(phi) * s2);
                    const dvec3 on = q0 + d * (glm::dot(n, centre - q0) / glm::dot(n, d));
                    const dvec2 p = uv_of(on) - uv_of(centre);
                    mean[0] += p.x * p.x / points, mean[1] += p.x * p.y / points, mean[2] += p.y * p.y / points;
                }
                const double g[3] = {f.g1u[k] * f.g1u[k] + f.g2u[k] * f.g2u[k], f.g1u[k] * f.g1v[k] + f.g2u[k] * f.g2v[k],
                                     f.g1v[k] * f.g1v[k] + f.g2v[k] * f.g2v[k]};
                const double scale = 8 * (mean[0] + mean[2]);
                for (int e = 0; e < 3; ++e)
                    EXPECT_NEAR(g[e], 8 * mean[e], 1e-9 * scale) << "sign " << sign << ", prim " << prim << ", lane " << k;
            }
        }
    }
}

TEST(GltfMipmaps, APerspectiveCameraReadsTheSameMean) {
    // The eye 10 above the quad, the image plane at 9: the cone is
    // 0.25 / 9 * 10 wide there, lambda = 3.15 -- levels 3 and 4, both the
    // same grey. (Column 7 looks past the quad's edge: x = 1.02.)
    for (Precision p : kPrecisions)
        expect_columns(top_view(lit(checker_file(sampler_json(kRepeat, kRepeat))), p, 8, 8, 1, 0.05,
                                Projection::perspective),
                       0, 7, kGrey, precision_name(p));
}

template <typename T>
void expect_every_cone_as_wide(T tolerance) {
    // A perspective camera at the origin looking down -z, the image plane
    // at 2, 8 x 8 pixels 0.25 wide (half height 1): spread 0.125. A plane
    // z = -10 facing it shows every pixel as a square 1.25 wide (0.25 x
    // 10 / 2), and every ray's cone there is 1.25 wide: t = 10 |v| / 2 along
    // the ray through the image-plane point v = (x, y, -2), times the
    // share cos(theta) = 2 / |v|. (Without the share, the corner pixel's
    // would be 1.25 |(0.875, 0.875, -2)| / 2 = 1.4553.)
    Camera camera;
    camera.projection = Projection::perspective;
    camera.view_point = {0, 0, 0};
    camera.look_at = {0, 0, -1};
    camera.up = {0, 1, 0};
    camera.width = camera.height = 8;
    camera.half_height = 1;
    camera.projection_distance = 2;
    const PixelCone<T> cone = PixelCone<T>::of(camera, 1);
    const CameraRays<T> rays(camera);
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
            const Ray<T> r = rays.generate(T(i + 0.5), T(j + 0.5));
            const T t = T(10) / -r.direction.z;
            const Vec3Lanes<T> d = Vec3Lanes<T>::splat(r.direction);
            EXPECT_NEAR((cone.at(splat(t)) * cone.share(d))[0], T(1.25), tolerance) << i << ", " << j;
        }
    // An orthographic camera's rays are all alike: the share is 1.
    camera.projection = Projection::orthographic;
    const PixelCone<T> parallel = PixelCone<T>::of(camera, 1);
    EXPECT_EQ(parallel.width, T(0.25));
    EXPECT_EQ(parallel.share(Vec3Lanes<T>::splat(Vec3<T>(T(0.6), T(0), T(-0.8))))[0], T(1));
}

TEST(GltfMipmaps, EveryPixelsConeIsAsWideOnAPlaneFacingTheCamera) {
    expect_every_cone_as_wide<double>(1e-12);
    expect_every_cone_as_wide<float>(1e-5f);
}

TEST(GltfMipmaps, TheConeGoesOnPastAClearPane) {
    // A pane of alpha 0 (BLEND) at z = 5, between the eye (z = 10) and the
    // striped floor: the rays go on past it, their cones counting the whole
    // path -- the floor's pixels as without the pane. Were the cone to
    // start again at the pane, its width at the floor would halve and
    // lambda drop by one (levels 2 and 3 instead of 3 and 4).
    Quad floor{-1, 1, -0.99, 1.01, 0, 0};
    const Quad pane{-3, 3, -3, 3, 5, 1};
    auto file = [&](bool with_pane) {
        std::vector<Quad> quads = {floor};
        if (with_pane) quads.push_back(pane);
        return quads_file(quads, surfaces({material("[1, 1, 1, 1]", tex(0)),
                                           material("[1, 1, 1, 0]", "", ", \"alphaMode\": \"BLEND\"")},
                                          {{0, 0}}, {image_json(stripes_png(64, 8))}, {sampler_json(kRepeat, kRepeat)}));
    };
    for (Precision p : kPrecisions) {
        const Image without = top_view(lit(file(false)), p, 8, 8, 1, 0.05, Projection::perspective);
        const Image with = top_view(lit(file(true)), p, 8, 8, 1, 0.05, Projection::perspective);
        for (int j = 0; j < 8; ++j)
            for (int i = 0; i < 7; ++i) expect_pixel(with, i, j, pixel(without, i, j), precision_name(p));
        // (The stripes show: not one grey.)
        EXPECT_GT(pixel(without, 1, 4)[0] - pixel(without, 0, 4)[0], 100) << precision_name(p);
    }
}

TEST(GltfMipmaps, WithoutMipmapsEveryTextureIsReadAsMagnified) {
    // --no-mipmaps (RenderSettings::mipmaps false): the checkerboard, seen
    // from far through LINEAR_MIPMAP_LINEAR, comes out as the file whose
    // sampler says LINEAR both ways renders it -- the same bytes, not the
    // mean grey the mipmaps give -- at 1 and 4 samples, float and double.
    const Scene mipmapped = lit(checker_file(sampler_json(kRepeat, kRepeat, kLinear, kLinearMipmapLinear)));
    const Scene linear = lit(checker_file(sampler_json(kRepeat, kRepeat, kLinear, kMinLinear)));
    for (Precision p : kPrecisions)
        for (const int spp : {1, 4}) {
            RenderSettings on, off;
            on.precision = off.precision = p;
            on.samples_per_pixel = off.samples_per_pixel = spp;
            off.mipmaps = false;
            const std::string what = std::string(precision_name(p)) + ", " + std::to_string(spp) + " samples";
            const Image without = render_frame(mipmapped, top_camera(), off, nullptr).image;
            EXPECT_EQ(without.rgb, render_frame(linear, top_camera(), on, nullptr).image.rgb) << what;
            EXPECT_NE(without.rgb, render_frame(mipmapped, top_camera(), on, nullptr).image.rgb) << what;
        }
    EXPECT_FALSE(FlatScene<double>::build(mipmapped, plan_effects(mipmapped, [] {
                     RenderSettings off;
                     off.mipmaps = false;
                     return off;
                 }())).minified);
}

TEST(GltfMipmaps, SupersamplingNarrowsTheCone) {
    // 4 samples a pixel: each stands for half the pixel's width, lambda =
    // 2 -- level 2, again the mean 188 -- and the samples, all grey,
    // average to the same 103. (With 64, lambda = 0 would read the image
    // itself. Column 7's and row 7's pixels reach past the quad's edges: x
    // up to 1.05, y down to -1.)
    RenderSettings settings;
    settings.samples_per_pixel = 4;
    const Image im = render_frame(lit(checker_file(sampler_json(kRepeat, kRepeat))), top_camera(), settings, nullptr).image;
    for (int j = 0; j < 7; ++j)
        for (int i = 0; i < 7; ++i) expect_pixel(im, i, j, kGrey, "4 samples");
}

TEST(GltfMipmaps, RefinedPixelsNarrowTheConeAsUniformSamplesDo) {
    // Adaptive anti-aliasing gives the stripes' pixels (each 122 from its
    // neighbours) 4 stratified samples instead of 1: each stands for half
    // the pixel, as in a frame of 4 samples a pixel -- the same pixels. A
    // refined pixel's cone left a whole pixel wide would read level 3
    // instead of 2.
    const Scene s = lit(quads_file({{-1, 1, -0.99, 1.01, 0, 0}},
                                   surfaces({material("[1, 1, 1, 1]", tex(0))}, {{0, 0}},
                                            {image_json(stripes_png(64, 8))}, {sampler_json(kRepeat, kRepeat)})));
    for (Precision p : kPrecisions) {
        RenderSettings uniform, adaptive;
        uniform.precision = adaptive.precision = p;
        uniform.samples_per_pixel = 4;
        adaptive.adaptive = true;
        adaptive.adaptive_samples = 4;
        const FrameResult a = render_frame(s, top_camera(), adaptive, nullptr);
        const Image u = render_frame(s, top_camera(), uniform, nullptr).image;
        EXPECT_EQ(a.refined_pixels, 64u) << precision_name(p);
        for (int j = 0; j < 7; ++j)
            for (int i = 0; i < 8; ++i) expect_pixel(a.image, i, j, pixel(u, i, j), precision_name(p));
    }
}

}  // namespace gltf_mipmaps_test
}  // namespace fh
