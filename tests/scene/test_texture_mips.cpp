// Mipmaps (scene/texture.h, scene/texture.cpp) worked out by hand: each
// level the mean of the texels its span covers in linear values, rounded
// to bytes once, level by level from the unrounded values; and which level, or which two, a read takes for a
// footprint of 2^lod in (u, v) units -- lambda = lod + log2 sqrt(w h) --
// for each of glTF's minFilters, lane by lane, with infinite and NaN lods;
// and a slanted footprint read as several reads along its length.
//
// A mean of linear 0.5 is the sRGB byte 188: 1.055 * 0.5^(1/2.4) - 0.055 =
// 0.73535, times 255 = 187.51.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "scene/texture.h"

namespace fh {
namespace mipmaps_test {

constexpr double kInf = std::numeric_limits<double>::infinity();

// A w x h image of grey texels (r = g = b = grey[k]) with alpha alpha[k]
// (255 where not given).
std::shared_ptr<const TextureImage> grey_image(int w, int h, const std::vector<int>& grey,
                                               const std::vector<int>& alpha = {}) {
    TextureImage im{w, h, {}};
    for (size_t k = 0; k < grey.size(); ++k) {
        const auto g = std::uint8_t(grey[k]);
        im.rgba.insert(im.rgba.end(), {g, g, g, std::uint8_t(alpha.empty() ? 255 : alpha[k])});
    }
    return std::make_shared<const TextureImage>(std::move(im));
}

// Texel (i, j) of level `level` (from 1), channel c.
int texel(const MipChain& m, int level, int i, int j, int c = 0) {
    const MipChain::Level& l = m.levels[size_t(level - 1)];
    return m.rgba[l.offset + 4 * (size_t(j) * size_t(l.width) + size_t(i)) + size_t(c)];
}

TEST(Mipmaps, LinearToSrgbByteInvertsTheTable) {
    for (int b = 0; b < 256; ++b) EXPECT_EQ(linear_to_srgb_byte(kSrgbToLinear[size_t(b)]), b) << b;
    EXPECT_EQ(linear_to_srgb_byte(0.5), 188);
    EXPECT_EQ(linear_to_srgb_byte(-1), 0);
    EXPECT_EQ(linear_to_srgb_byte(7), 255);
}

TEST(Mipmaps, LevelsHalveColourInLinearValues) {
    // 4 x 2, opaque: colours [0 255 255 255 / 0 255 0 0].
    const auto im = grey_image(4, 2, {0, 255, 255, 255, 0, 255, 0, 0});
    const auto m = mip_chain(*im, true);
    ASSERT_EQ(m->levels.size(), 2u);
    EXPECT_EQ(m->levels[0].width, 2);
    EXPECT_EQ(m->levels[0].height, 1);
    EXPECT_EQ(m->levels[1].width, 1);
    EXPECT_EQ(m->levels[1].height, 1);
    EXPECT_EQ(m->levels[1].offset, 8u);  // after level 1's two texels
    // Level 1: blocks {0, 255, 0, 255} and {255, 255, 0, 0}, each linear 0.5.
    for (int c = 0; c < 3; ++c) {
        EXPECT_EQ(texel(*m, 1, 0, 0, c), 188);
        EXPECT_EQ(texel(*m, 1, 1, 0, c), 188);
        EXPECT_EQ(texel(*m, 2, 0, 0, c), 188);
    }
    EXPECT_EQ(texel(*m, 1, 0, 0, 3), 255);
    // As data, the same bytes average as they are: 127.5 -> 128.
    const auto d = mip_chain(*im, false);
    EXPECT_EQ(texel(*d, 1, 0, 0), 128);
    EXPECT_EQ(texel(*d, 2, 0, 0), 128);
}

TEST(Mipmaps, ColourIsWeightedByAlphaWhereAlphaHidesTexels) {
    // 4 x 1: red opaque, blue clear, white opaque, black at alpha 51; the
    // levels of a see-through surface's base colour (alpha_weighted).
    TextureImage im{4, 1, {255, 0, 0, 255, 0, 0, 255, 0, 255, 255, 255, 255, 0, 0, 0, 51}};
    const auto m = mip_chain(im, true, true);
    // Texel 0: red alone (the clear blue lends nothing), alpha 127.5 -> 128.
    EXPECT_EQ(texel(*m, 1, 0, 0, 0), 255);
    EXPECT_EQ(texel(*m, 1, 0, 0, 2), 0);
    EXPECT_EQ(texel(*m, 1, 0, 0, 3), 128);
    // Texel 1: white 1.0 at weight 1, black at 0.2: linear 1 / 1.2 =
    // 0.8333 -> sRGB 235 (1.055 * 0.8333^(1/2.4) - 0.055 = 0.92282, * 255 =
    // 235.32); alpha (255 + 51) / 2 = 153.
    for (int c = 0; c < 3; ++c) EXPECT_EQ(texel(*m, 1, 1, 0, c), 235);
    EXPECT_EQ(texel(*m, 1, 1, 0, 3), 153);
    // Level 2 from level 1's unrounded values, weights 0.5 and 0.6: red
    // (0.5 * 1 + 0.6 * 0.8333) / 1.1 = 0.9091 linear (sRGB 0.95893 * 255 =
    // 244.53 -> 245), green 0.6 * 0.8333 / 1.1 = 0.4545 (0.70459 * 255 =
    // 179.67 -> 180); alpha (0.5 + 0.6) / 2 = 0.55 -> 140.25 -> 140.
    EXPECT_EQ(texel(*m, 2, 0, 0, 0), 245);
    EXPECT_EQ(texel(*m, 2, 0, 0, 1), 180);
    EXPECT_EQ(texel(*m, 2, 0, 0, 3), 140);
    // All clear: the plain mean. As data: always the plain mean.
    TextureImage clear{2, 1, {255, 0, 0, 0, 0, 0, 255, 0}};
    EXPECT_EQ(texel(*mip_chain(clear, true, true), 1, 0, 0, 0), 188);
    EXPECT_EQ(texel(*mip_chain(im, false), 1, 0, 0, 2), 128);
    // Where alpha hides nothing (an OPAQUE surface, an emissive texture),
    // glTF ignores it, and so do the levels: red and blue average to linear
    // (0.5, 0, 0.5), sRGB (188, 0, 188), as the two texels look up close.
    const auto opaque = mip_chain(im, true);
    EXPECT_EQ(texel(*opaque, 1, 0, 0, 0), 188);
    EXPECT_EQ(texel(*opaque, 1, 0, 0, 2), 188);
    EXPECT_EQ(texel(*opaque, 1, 0, 0, 3), 128);  // alpha averaged all the same
}

TEST(Mipmaps, EachLevelComesFromTheUnroundedOneAbove) {
    // 4 x 2 data [3 0 0 0 / 0 0 0 0]: level 1 [0.75 0] rounds to bytes
    // [1 0], but level 2 is the mean of 0.75 and 0, 0.375 -> 0, not the
    // bytes' (1 + 0) / 2.
    const auto m = mip_chain(*grey_image(4, 2, {3, 0, 0, 0, 0, 0, 0, 0}), false);
    EXPECT_EQ(texel(*m, 1, 0, 0), 1);
    EXPECT_EQ(texel(*m, 1, 1, 0), 0);
    EXPECT_EQ(texel(*m, 2, 0, 0), 0);
}

TEST(Mipmaps, OddSidesTakeThreeTexelsAndOneTexelHasNoLevels) {
    // 3 x 1 -> 1 x 1: all three, (0 + 255 + 255) / 3 = 170.
    EXPECT_EQ(texel(*mip_chain(*grey_image(3, 1, {0, 255, 255}), false), 1, 0, 0), 170);
    // 5 x 1 -> 2 x 1: texels [0, 3) and [2, 5); -> 1 x 1: their mean.
    const auto m = mip_chain(*grey_image(5, 1, {0, 0, 0, 255, 255}), false);
    ASSERT_EQ(m->levels.size(), 2u);
    EXPECT_EQ(texel(*m, 1, 0, 0), 0);
    EXPECT_EQ(texel(*m, 1, 1, 0), 170);
    EXPECT_EQ(texel(*m, 2, 0, 0), 85);
    // 1 x 4: only rows halve.
    const auto tall = mip_chain(*grey_image(1, 4, {0, 255, 0, 0}), false);
    ASSERT_EQ(tall->levels.size(), 2u);
    EXPECT_EQ(tall->levels[0].width, 1);
    EXPECT_EQ(tall->levels[0].height, 2);
    EXPECT_EQ(texel(*tall, 1, 0, 0), 128);
    EXPECT_EQ(texel(*tall, 1, 0, 1), 0);
    EXPECT_EQ(texel(*tall, 2, 0, 0), 64);  // 255 / 4 = 63.75
    EXPECT_TRUE(mip_chain(*grey_image(1, 1, {9}), false)->levels.empty());
}

// A 4 x 4 checkerboard of 0 and 255, read as data: level 1 (2 x 2) is 128
// everywhere (127.5), level 2 (1 x 1) 128 too.
Texture checker(MipFilter mips, Filter min_filter = Filter::bilinear) {
    std::vector<int> g;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) g.push_back((i + j) % 2 ? 255 : 0);
    Texture t;
    t.image = grey_image(4, 4, g);
    t.srgb = false;
    t.min_filter = min_filter;
    t.mips = mips;
    if (mips != MipFilter::none) t.smaller = mip_chain(*t.image, false);
    return t;
}

// u, v at texel (0, 0)'s centre: 0 there, bilinear or nearest.
constexpr double kU = 0.125, kV = 0.125;
constexpr double kGrey = 128 / 255.0;

TEST(Mipmaps, TrilinearReadsTheTwoLevelsRoundLambda) {
    const Texture t = checker(MipFilter::linear);
    EXPECT_TRUE(t.minifies());
    // lambda = lod + 2.
    EXPECT_FLOAT_EQ(t.sample(kU, kV, -kInf)[0], 0);   // a point: magnified
    EXPECT_FLOAT_EQ(t.sample(kU, kV, -2)[0], 0);      // lambda 0: still magnified
    EXPECT_FLOAT_EQ(t.sample(kU, kV, -1)[0], kGrey);  // lambda 1: level 1
    EXPECT_FLOAT_EQ(t.sample(kU, kV, -1.5)[0], 0.5 * kGrey);   // halfway: 0.5 level 0 + 0.5 level 1
    EXPECT_FLOAT_EQ(t.sample(kU, kV, -1.75)[0], 0.25 * kGrey);
    EXPECT_FLOAT_EQ(t.sample(kU, kV, 0)[0], kGrey);    // lambda 2: level 2, the last
    EXPECT_FLOAT_EQ(t.sample(kU, kV, 10)[0], kGrey);   // beyond: the last
    EXPECT_FLOAT_EQ(t.sample(kU, kV, kInf)[0], kGrey);  // a grazing ray
    EXPECT_FLOAT_EQ(t.sample(kU, kV, std::nan(""))[0], 0);  // no footprint: magnified
    EXPECT_FLOAT_EQ(t.sample(kU, kV, -1)[3], 1);  // alpha 255 throughout
}

TEST(Mipmaps, NearestMipmapsRoundLambda) {
    const Texture t = checker(MipFilter::nearest);
    EXPECT_FLOAT_EQ(t.sample(kU, kV, -1.6)[0], 0);      // lambda 0.4: level 0
    EXPECT_FLOAT_EQ(t.sample(kU, kV, -1.4)[0], kGrey);  // lambda 0.6: level 1
}

TEST(Mipmaps, WithoutMipmapsTheMinFilterReadsTheImage) {
    // Between texels (0, 0) and (1, 0): bilinear blends 0 and 255 halfway,
    // nearest takes texel 1 (u * 4 = 1 exactly).
    Texture t = checker(MipFilter::none, Filter::nearest);
    EXPECT_TRUE(t.minifies());
    EXPECT_FLOAT_EQ(t.sample(0.25, kV, -kInf)[0], 0.5);  // magnified: bilinear
    EXPECT_FLOAT_EQ(t.sample(0.25, kV, 5)[0], 1);        // minified: nearest
    t.min_filter = Filter::bilinear;
    EXPECT_FALSE(t.minifies());
    EXPECT_FLOAT_EQ(t.sample(0.25, kV, 5)[0], 0.5);
}

TEST(Mipmaps, EachLaneReadsItsOwnLevels) {
    // A packet whose lanes ask for different levels reads, in each lane,
    // what that lane reads alone -- to the bit, float and double.
    const Texture t = checker(MipFilter::linear);
    const double lods[] = {-kInf, -1.5, -1, 10, std::nan(""), -1.75, 0.3, -2};
    auto check = [&](auto zero) {
        using T = decltype(zero);
        Lanes<T> u, v, lod;
        for (int k = 0; k < kLanes<T>; ++k) u[k] = T(0.05 + 0.1 * k), v[k] = T(0.9 - 0.1 * k), lod[k] = T(lods[k % 8]);
        const TexelLanes<T> all = t.sample<T>(u, v, lod);
        for (int k = 0; k < kLanes<T>; ++k) {
            const TexelLanes<T> one = t.sample<T>(splat(u[k]), splat(v[k]), splat(lod[k]));
            EXPECT_EQ(all.r[k], one.r[0]) << "lane " << k;
            EXPECT_EQ(all.a[k], one.a[0]) << "lane " << k;
            EXPECT_TRUE(std::isfinite(all.r[k])) << "lane " << k;
        }
    };
    check(0.0);
    check(0.0f);
}

// The read at (u, v) of the footprint whose conjugate diameters are
// (g1u, g1v) and (g2u, g2v): lane 0 of a packet of it.
double along(const Texture& t, double u, double v, double g1u, double g1v, double g2u, double g2v) {
    const UvFootprint<double> f{splat(g1u), splat(g1v), splat(g2u), splat(g2v)};
    return t.sample<double>(splat(u), splat(v), f).r[0];
}

TEST(Mipmaps, ASlantedFootprintIsReadAlongItsLength) {
    // (The 4 x 4 checker: a texel is 1/4 in u and v.)
    const Texture t = checker(MipFilter::linear);
    const double r = 0.25 * std::sqrt(2);
    // A circle sqrt(2) texels across: one read at lambda 0.5, as a read of
    // lod -1.5.
    EXPECT_NEAR(along(t, kU, kV, r, 0, 0, r), t.sample(kU, kV, -1.5)[0], 1e-6);
    // 2 texels long along u, a tenth of one wide: two reads a texel wide,
    // magnified (bilinear), at u = 0 and 1/4 -- halfway between texel 0
    // (0) and its neighbours 3 (wrapped) and 1 (both 1): 0.5 each, where
    // the centre reads 0.
    EXPECT_DOUBLE_EQ(along(t, kU, kV, 0.5, 0, 0, 0.025), 0.5);
    // The same along v: rows 3 and 1, both 1.
    EXPECT_DOUBLE_EQ(along(t, kU, kV, 0.025, 0, 0, 0.5), 0.5);
    // Less than a texel long: one read, at the centre (reads closer than
    // a texel would see what a bilinear read between them sees).
    EXPECT_DOUBLE_EQ(along(t, kU, kV, 0.2, 0, 0, 0.0025), 0);
    // 3 sqrt(2) texels long, sqrt(2) wide: three reads at lambda 0.5,
    // sqrt(2) texels apart. Nearest within a level: texels 3, 0 and 1 of
    // row 0 (1, 0, 1), each half that and half level 1's grey.
    const Texture nearest = checker(MipFilter::linear, Filter::nearest);
    EXPECT_NEAR(along(nearest, kU, kV, 3 * r, 0, 0, r), 0.5 * (2.0 / 3) + 0.5 * kGrey, 1e-6);
    // 8 times as long as wide or more: reads an eighth of the length wide.
    // 64 texels long (lambda 3: level 2, the last) -- all grey.
    EXPECT_NEAR(along(t, kU, kV, 16, 0, 0, 0.001), kGrey, 1e-6);
    // Without mipmaps the footprint is read once, over its length: 128
    // texels, minified, nearest, at u = 1/4 -- texel 1, where two reads
    // at u = 3/16 and 5/16 would find texels 0 and 1. A point: magnified,
    // bilinear, once.
    const Texture plain = checker(MipFilter::none, Filter::nearest);
    EXPECT_DOUBLE_EQ(along(plain, 0.25, kV, 32, 0, 0, 0.25), 1);
    EXPECT_DOUBLE_EQ(along(plain, 0.25, kV, 0, 0, 0, 0), 0.5);
}

TEST(Mipmaps, AFootprintsAxesAreFoundFromAnyTwoConjugateDiameters) {
    // An ellipse 4 texels long along u and 1 wide, given by the conjugate
    // diameters (4 cos 45, sin 45) and (-4 sin 45, cos 45) texels: its
    // axes, not the longer of those (2.9 texels, diagonal), are read -- 4
    // reads along u, 1.5 and 0.5 texels either side of texel 0's centre.
    // On stripes one texel wide along u (0 1 0 1) each read, magnified
    // (bilinear), falls halfway between two texels: 0.5. (3 reads along
    // the diagonal would give about 0.63; one, 0.)
    std::vector<int> g;
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) g.push_back(i % 2 ? 255 : 0);
    Texture t;
    t.image = grey_image(4, 4, g);
    t.srgb = false;
    t.mips = MipFilter::linear;
    t.smaller = mip_chain(*t.image, false);
    const double c = std::sqrt(0.5) / 4;  // cos 45 = sin 45, in (u, v) units
    EXPECT_NEAR(along(t, kU, kV, 4 * c, c, -4 * c, c), 0.5, 1e-12);
}

TEST(Mipmaps, EachLaneReadsItsOwnFootprint) {
    // Lanes of 1 to 8 reads, from a point to a grazing ray, none known
    // (NaN), each read in its lane as alone -- to the bit, float and
    // double, and never NaN.
    const Texture t = checker(MipFilter::linear);
    const double inf = kInf, nan = std::nan("");
    const double lengths[] = {0, 0.5, 0.3, 40, nan, inf, 3, 0.05};
    auto check = [&](auto zero) {
        using T = decltype(zero);
        Lanes<T> u, v;
        UvFootprint<T> f;
        for (int k = 0; k < kLanes<T>; ++k) {
            u[k] = T(0.05 + 0.1 * k), v[k] = T(0.9 - 0.1 * k);
            const double l = lengths[k % 8];
            f.g1u[k] = T(l);
            if (std::isfinite(l)) {
                f.g1v[k] = T(0.3 * l * (k % 3));
                f.g2u[k] = T(-0.1 * l), f.g2v[k] = T(l / (1 + k % 5));
            }
        }
        const TexelLanes<T> all = t.sample<T>(u, v, f);
        for (int k = 0; k < kLanes<T>; ++k) {
            const UvFootprint<T> one{splat(f.g1u[k]), splat(f.g1v[k]), splat(f.g2u[k]), splat(f.g2v[k])};
            const TexelLanes<T> alone = t.sample<T>(splat(u[k]), splat(v[k]), one);
            EXPECT_EQ(all.r[k], alone.r[0]) << "lane " << k;
            EXPECT_TRUE(std::isfinite(all.r[k])) << "lane " << k;
        }
    };
    check(0.0);
    check(0.0f);
}

}  // namespace mipmaps_test
}  // namespace fh
