// Texture reads (scene/texture.h) worked out by hand: which texel each wrap
// mode picks for any whole index, and what the nearest and bilinear filters
// return at texel centres, on texel edges, outside [0, 1] and for
// coordinates no long holds. Texels are sRGB-encoded colour and linear
// alpha; a read is linear colour by the sRGB transfer function (computed
// here from its formula, IEC 61966-2-1) and alpha byte / 255.
#include <gtest/gtest.h>

#include <array>
#include <climits>
#include <cmath>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "scene/texture.h"

namespace fh {
namespace {

using Rgba = std::array<float, 4>;
using Bytes4 = std::array<std::uint8_t, 4>;

// The sRGB transfer function inverted, in double, from its formula.
double srgb_to_linear(int byte) {
    const double c = byte / 255.0;
    return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

// What a texel of these bytes reads as: linear colour, linear alpha.
Rgba linear(const Bytes4& b) {
    return {float(srgb_to_linear(b[0])), float(srgb_to_linear(b[1])), float(srgb_to_linear(b[2])),
            float(b[3] / 255.0)};
}

// a + f (b - a), channel by channel: bilinear's blend of two texels.
Rgba mix(const Rgba& a, const Rgba& b, double f) {
    Rgba out;
    for (size_t k = 0; k < 4; ++k) out[k] = float(a[k] + f * (b[k] - a[k]));
    return out;
}

// Four texels told apart by every channel: red (alpha 255), green (alpha
// 188), blue (alpha 0), grey 188 (alpha 255).
const Bytes4 kRed{255, 0, 0, 255}, kGreen{0, 255, 0, 188}, kBlue{0, 0, 255, 0}, kGrey{188, 188, 188, 255};

// A texture of `texels` (rows from the top), w x h.
Texture texture(int w, int h, const std::vector<Bytes4>& texels, Wrap wrap_s, Wrap wrap_t, Filter filter) {
    TextureImage image{w, h, {}};
    for (const Bytes4& t : texels) image.rgba.insert(image.rgba.end(), t.begin(), t.end());
    Texture out;
    out.image = std::make_shared<const TextureImage>(std::move(image));
    out.wrap_s = wrap_s;
    out.wrap_t = wrap_t;
    out.filter = filter;
    return out;
}

// The 4 x 1 row red, green, blue, grey, one wrap mode along u (and v).
Texture row(Wrap wrap, Filter filter) { return texture(4, 1, {kRed, kGreen, kBlue, kGrey}, wrap, wrap, filter); }
// The 2 x 2 image red green / blue grey.
Texture square(Wrap wrap_s, Wrap wrap_t, Filter filter) {
    return texture(2, 2, {kRed, kGreen, kBlue, kGrey}, wrap_s, wrap_t, filter);
}

std::string show(const Rgba& c) {
    return "(" + std::to_string(c[0]) + ", " + std::to_string(c[1]) + ", " + std::to_string(c[2]) + ", " +
           std::to_string(c[3]) + ")";
}

// Exactly these four floats.
void expect_exact(const Rgba& got, const Rgba& want, const std::string& where) {
    for (size_t k = 0; k < 4; ++k)
        EXPECT_EQ(got[k], want[k]) << where << ": channel " << k << " of " << show(got) << ", wanted " << show(want);
}

void expect_rgba_near(const Rgba& got, const Rgba& want, const std::string& where, double tol = 1e-6) {
    for (size_t k = 0; k < 4; ++k)
        EXPECT_NEAR(got[k], want[k], tol) << where << ": channel " << k << " of " << show(got) << ", wanted "
                                          << show(want);
}

const char* name(Wrap w) {
    return w == Wrap::repeat ? "repeat" : w == Wrap::mirrored_repeat ? "mirrored_repeat" : "clamp_to_edge";
}

// ----------------------------------------------------------- sRGB table

TEST(TextureSrgb, TheTableIsTheTransferFunctionInverted) {
    // 188 / 255 = 0.7372549: ((c + 0.055) / 1.055)^2.4 = 0.5028864580...;
    // 10 / 255 = 0.0392157 is on the straight segment: c / 12.92 = 0.0030353.
    EXPECT_NEAR(kSrgbToLinear[188], 0.5028864580, 1e-7);
    EXPECT_NEAR(kSrgbToLinear[10], 0.0030352698, 1e-9);
    EXPECT_EQ(kSrgbToLinear[0], 0.0f);
    EXPECT_EQ(kSrgbToLinear[255], 1.0f);
    for (int i = 0; i < 256; ++i) EXPECT_NEAR(kSrgbToLinear[size_t(i)], srgb_to_linear(i), 1e-7) << "byte " << i;
    for (int i = 1; i < 256; ++i) EXPECT_GT(kSrgbToLinear[size_t(i)], kSrgbToLinear[size_t(i - 1)]) << "byte " << i;
}

TEST(TextureSrgb, ColourIsLinearisedAlphaIsNot) {
    // Texel 1 of the row (u = 0.375) is green with alpha 188: its alpha reads
    // 188 / 255 = 0.7372549, not the sRGB curve's 0.5029; its green 1, red
    // and blue 0.
    const Texture t = row(Wrap::repeat, Filter::nearest);
    const Rgba c = t.sample(0.375, 0.5);
    EXPECT_EQ(c[0], 0.0f);
    EXPECT_EQ(c[1], 1.0f);
    EXPECT_EQ(c[2], 0.0f);
    EXPECT_FLOAT_EQ(c[3], 188.0f / 255);
    EXPECT_GT(std::fabs(c[3] - kSrgbToLinear[188]), 0.2f);
    // Grey 188 (texel 3, u = 0.875) reads 0.5029 in each colour channel.
    const Rgba g = t.sample(0.875, 0.5);
    for (size_t k = 0; k < 3; ++k) EXPECT_NEAR(g[k], 0.5028864580, 1e-7);
    EXPECT_EQ(g[3], 1.0f);
}

// -------------------------------------------------------------- wrap_texel

TEST(TextureWrap, RepeatTiles) {
    // i mod 4, taken into 0..3 for negative i.
    const std::vector<std::pair<long, int>> cases = {{0, 0},   {3, 3},  {4, 0},   {5, 1},   {7, 3},  {8, 0},
                                                     {-1, 3},  {-2, 2}, {-4, 0},  {-5, 3},  {-8, 0}, {1001, 1},
                                                     {-1001, 3}};
    for (const auto& [i, want] : cases) EXPECT_EQ(wrap_texel(i, 4, Wrap::repeat), want) << "i = " << i;
}

TEST(TextureWrap, MirroredRepeatFlipsEveryOtherCopy) {
    // Period 2n = 8: 0 1 2 3 | 3 2 1 0 | 0 1 2 3 ...; to the left of 0 the
    // flipped copy: -1 -> 0, -4 -> 3, -5 -> 3 (the unflipped one again).
    const std::vector<std::pair<long, int>> cases = {{0, 0},  {3, 3},  {4, 3},  {5, 2},  {7, 0},  {8, 0},
                                                     {9, 1},  {12, 3}, {-1, 0}, {-2, 1}, {-4, 3}, {-5, 3},
                                                     {-8, 0}, {-9, 0}, {-12, 3}};
    for (const auto& [i, want] : cases) EXPECT_EQ(wrap_texel(i, 4, Wrap::mirrored_repeat), want) << "i = " << i;
}

TEST(TextureWrap, ClampToEdgeHoldsTheEdgeTexel) {
    const std::vector<std::pair<long, int>> cases = {{0, 0}, {2, 2}, {3, 3}, {4, 3}, {100, 3}, {-1, 0}, {-100, 0}};
    for (const auto& [i, want] : cases) EXPECT_EQ(wrap_texel(i, 4, Wrap::clamp_to_edge), want) << "i = " << i;
}

TEST(TextureWrap, OneTexelAndTheLongsEnds) {
    for (const Wrap w : {Wrap::repeat, Wrap::mirrored_repeat, Wrap::clamp_to_edge})
        for (const long i : {0L, 1L, -1L, 12345L, LONG_MAX, LONG_MIN}) EXPECT_EQ(wrap_texel(i, 1, w), 0) << name(w);
    // LONG_MAX = 2^63 - 1 = 3 mod 4 and 7 mod 8; LONG_MIN = 0 mod 8.
    EXPECT_EQ(wrap_texel(LONG_MAX, 4, Wrap::repeat), 3);
    EXPECT_EQ(wrap_texel(LONG_MAX, 4, Wrap::mirrored_repeat), 0);
    EXPECT_EQ(wrap_texel(LONG_MAX, 4, Wrap::clamp_to_edge), 3);
    EXPECT_EQ(wrap_texel(LONG_MIN, 4, Wrap::repeat), 0);
    EXPECT_EQ(wrap_texel(LONG_MIN, 4, Wrap::mirrored_repeat), 0);
    EXPECT_EQ(wrap_texel(LONG_MIN, 4, Wrap::clamp_to_edge), 0);
    // 2^63 = 2 mod 3, so LONG_MAX = 1 mod 3 and 1 mod 6.
    EXPECT_EQ(wrap_texel(LONG_MAX, 3, Wrap::repeat), 1);
    EXPECT_EQ(wrap_texel(LONG_MAX, 3, Wrap::mirrored_repeat), 1);
}

// --------------------------------------------------------------- nearest

TEST(TextureNearest, TexelCentresAndLeftEdgesReadThatTexel) {
    // Texel i covers u in [i/4, (i+1)/4): its centre (i + 1/2)/4 and its left
    // edge i/4 both read it, whatever the wrap mode (inside [0, 1)).
    const Bytes4 texels[4] = {kRed, kGreen, kBlue, kGrey};
    for (const Wrap w : {Wrap::repeat, Wrap::mirrored_repeat, Wrap::clamp_to_edge}) {
        const Texture t = row(w, Filter::nearest);
        for (int i = 0; i < 4; ++i) {
            expect_exact(t.sample((i + 0.5) / 4, 0.5), linear(texels[i]), std::string(name(w)) + " centre " + std::to_string(i));
            expect_exact(t.sample(i / 4.0, 0.5), linear(texels[i]), std::string(name(w)) + " edge " + std::to_string(i));
        }
    }
}

TEST(TextureNearest, OutsideTheImageEachWrapMode) {
    // x = 4u: u = 1 -> texel 4, 1.125 -> 4, 1.375 -> 5, 2.125 -> 8,
    // -0.125 -> -1, -0.375 -> -2, -1.125 -> -5; then wrap_texel's tables.
    struct Case {
        double u;
        Bytes4 repeat, mirrored, clamped;
    };
    const Case cases[] = {
        {1.0, kRed, kGrey, kGrey},      {1.125, kRed, kGrey, kGrey},   {1.375, kGreen, kBlue, kGrey},
        {2.125, kRed, kRed, kGrey},     {-0.125, kGrey, kRed, kRed},   {-0.375, kBlue, kGreen, kRed},
        {-1.125, kGrey, kGrey, kRed},   {-0.0, kRed, kRed, kRed},
    };
    const Texture rep = row(Wrap::repeat, Filter::nearest), mir = row(Wrap::mirrored_repeat, Filter::nearest),
                  cla = row(Wrap::clamp_to_edge, Filter::nearest);
    for (const Case& c : cases) {
        const std::string at = "u = " + std::to_string(c.u);
        expect_exact(rep.sample(c.u, 0.5), linear(c.repeat), "repeat " + at);
        expect_exact(mir.sample(c.u, 0.5), linear(c.mirrored), "mirrored " + at);
        expect_exact(cla.sample(c.u, 0.5), linear(c.clamped), "clamp " + at);
    }
}

TEST(TextureNearest, VAlongTheColumnsWithItsOwnWrapMode) {
    // 2 x 2: red green / blue grey. v = 0.25 row 0, 0.75 row 1; v = -0.25
    // is row -1: repeat 1, mirrored and clamp 0; v = 1.25 row 2: repeat 0,
    // mirrored and clamp 1.
    for (const Wrap w : {Wrap::repeat, Wrap::mirrored_repeat, Wrap::clamp_to_edge}) {
        const Texture t = square(w, w, Filter::nearest);
        const std::string n = name(w);
        expect_exact(t.sample(0.25, 0.25), linear(kRed), n);
        expect_exact(t.sample(0.75, 0.25), linear(kGreen), n);
        expect_exact(t.sample(0.25, 0.75), linear(kBlue), n);
        expect_exact(t.sample(0.75, 0.75), linear(kGrey), n);
        expect_exact(t.sample(0.25, -0.25), linear(w == Wrap::repeat ? kBlue : kRed), n + " v = -0.25");
        expect_exact(t.sample(0.75, 1.25), linear(w == Wrap::repeat ? kGreen : kGrey), n + " v = 1.25");
    }
    // Each axis its own mode: (-0.25, -0.25) is texel (-1, -1); repeat along u
    // and clamp along v read (1, 0), green; the other way round (0, 1), blue.
    expect_exact(square(Wrap::repeat, Wrap::clamp_to_edge, Filter::nearest).sample(-0.25, -0.25), linear(kGreen),
                 "repeat s, clamp t");
    expect_exact(square(Wrap::clamp_to_edge, Wrap::repeat, Filter::nearest).sample(-0.25, -0.25), linear(kBlue),
                 "clamp s, repeat t");
    expect_exact(square(Wrap::mirrored_repeat, Wrap::repeat, Filter::nearest).sample(-0.25, -0.25), linear(kBlue),
                 "mirrored s, repeat t");
}

// -------------------------------------------------------------- bilinear

TEST(TextureBilinear, TexelCentresReadTheTexelExactly) {
    const Bytes4 texels[4] = {kRed, kGreen, kBlue, kGrey};
    for (const Wrap w : {Wrap::repeat, Wrap::mirrored_repeat, Wrap::clamp_to_edge}) {
        const Texture t = row(w, Filter::bilinear);
        for (int i = 0; i < 4; ++i)
            expect_exact(t.sample((i + 0.5) / 4, 0.5), linear(texels[i]), std::string(name(w)) + " centre " + std::to_string(i));
        const Texture s = square(w, w, Filter::bilinear);
        expect_exact(s.sample(0.25, 0.25), linear(kRed), name(w));
        expect_exact(s.sample(0.75, 0.25), linear(kGreen), name(w));
        expect_exact(s.sample(0.25, 0.75), linear(kBlue), name(w));
        expect_exact(s.sample(0.75, 0.75), linear(kGrey), name(w));
    }
}

TEST(TextureBilinear, EdgesBetweenTexelsAverageTheTwoInLinearColour) {
    // u = 1/4: half way between the centres of texels 0 and 1, and so on.
    // In linear colour: red and grey average to ((1 + 0.5029) / 2, 0.2514,
    // 0.2514), not to sRGB's byte 222.
    for (const Wrap w : {Wrap::repeat, Wrap::mirrored_repeat, Wrap::clamp_to_edge}) {
        const Texture t = row(w, Filter::bilinear);
        expect_rgba_near(t.sample(0.25, 0.5), mix(linear(kRed), linear(kGreen), 0.5), name(w));
        expect_rgba_near(t.sample(0.5, 0.5), mix(linear(kGreen), linear(kBlue), 0.5), name(w));
        expect_rgba_near(t.sample(0.75, 0.5), mix(linear(kBlue), linear(kGrey), 0.5), name(w));
        // A quarter of the way from texel 1's centre to texel 2's: x = 4u - 1/2 = 1.25.
        expect_rgba_near(t.sample(0.4375, 0.5), mix(linear(kGreen), linear(kBlue), 0.25), name(w));
        // 2 x 2: its middle is the mean of all four; (1/4, 1/2) of the left column.
        const Texture s = square(w, w, Filter::bilinear);
        const Rgba mean = mix(mix(linear(kRed), linear(kGreen), 0.5), mix(linear(kBlue), linear(kGrey), 0.5), 0.5);
        expect_rgba_near(s.sample(0.5, 0.5), mean, name(w));
        expect_rgba_near(s.sample(0.25, 0.5), mix(linear(kRed), linear(kBlue), 0.5), name(w));
    }
    const Rgba red_grey = row(Wrap::repeat, Filter::bilinear).sample(1.0, 0.5);  // texels 3 and 4 = 0
    EXPECT_NEAR(red_grey[0], (1 + 0.5028864580) / 2, 1e-7);
    EXPECT_NEAR(red_grey[1], 0.5028864580 / 2, 1e-7);
}

TEST(TextureBilinear, TheImagesOwnEdgesAndOutsideEachWrapMode) {
    // x = 4u - 1/2, blended between floor(x) and floor(x) + 1, each wrapped.
    //   u = 0:     x = -0.5: texels -1, 0 at 1/2 -> repeat grey|red, mirrored and clamp red
    //   u = 1:     x = 3.5:  texels 3, 4 at 1/2  -> repeat grey|red, mirrored and clamp grey
    //   u = 1.125: x = 4:    texel 4             -> repeat red, mirrored and clamp grey
    //   u = -0.125: x = -1:  texel -1            -> repeat grey, mirrored and clamp red
    //   u = 1.25:  x = 4.5:  texels 4, 5         -> repeat red|green, mirrored grey|blue, clamp grey
    //   u = -0.25: x = -1.5: texels -2, -1       -> repeat blue|grey, mirrored green|red, clamp red
    //   u = -2.875: x = -12: texel -12           -> repeat red (0), mirrored grey (-12 -> 3), clamp red
    const Rgba red = linear(kRed), green = linear(kGreen), blue = linear(kBlue), grey = linear(kGrey);
    struct Case {
        double u;
        Rgba repeat, mirrored, clamped;
    };
    const Case cases[] = {
        {0.0, mix(grey, red, 0.5), red, red},
        {1.0, mix(grey, red, 0.5), grey, grey},
        {1.125, red, grey, grey},
        {-0.125, grey, red, red},
        {1.25, mix(red, green, 0.5), mix(grey, blue, 0.5), grey},
        {-0.25, mix(blue, grey, 0.5), mix(green, red, 0.5), red},
        {-2.875, red, grey, red},  // x = -12 exactly: texel -12 (and -11 at weight 0)
    };
    const Texture rep = row(Wrap::repeat, Filter::bilinear), mir = row(Wrap::mirrored_repeat, Filter::bilinear),
                  cla = row(Wrap::clamp_to_edge, Filter::bilinear);
    for (const Case& c : cases) {
        const std::string at = "u = " + std::to_string(c.u);
        expect_rgba_near(rep.sample(c.u, 0.5), c.repeat, "repeat " + at);
        expect_rgba_near(mir.sample(c.u, 0.5), c.mirrored, "mirrored " + at);
        expect_rgba_near(cla.sample(c.u, 0.5), c.clamped, "clamp " + at);
    }
    // Along v of the 2 x 2, at u = 1/4 (column 0 exactly): v = 0 is y = -0.5,
    // rows -1 and 0 at 1/2 -> repeat blue|red, clamp and mirrored red.
    expect_rgba_near(square(Wrap::repeat, Wrap::repeat, Filter::bilinear).sample(0.25, 0.0), mix(blue, red, 0.5), "v = 0 repeat");
    expect_rgba_near(square(Wrap::repeat, Wrap::clamp_to_edge, Filter::bilinear).sample(0.25, 0.0), red, "v = 0 clamp");
    expect_rgba_near(square(Wrap::repeat, Wrap::mirrored_repeat, Filter::bilinear).sample(0.25, 0.0), red, "v = 0 mirrored");
}

TEST(TextureBilinear, ReadsAreTheSameOneImageWidthOver) {
    // repeat: u and u + k read the same for whole k; mirrored: u and u + 2k.
    const Texture rep = row(Wrap::repeat, Filter::bilinear), mir = row(Wrap::mirrored_repeat, Filter::bilinear);
    for (const double u : {0.0, 0.1, 0.3125, 0.5, 0.77, 0.99}) {
        for (const double k : {-3.0, -1.0, 1.0, 5.0}) {
            expect_rgba_near(rep.sample(u + k, 0.5), rep.sample(u, 0.5), "repeat u = " + std::to_string(u), 1e-6);
            expect_rgba_near(mir.sample(u + 2 * k, 0.5), mir.sample(u, 0.5), "mirrored u = " + std::to_string(u), 1e-6);
        }
        // mirrored: u and -u read the same (the copy left of 0 is flipped).
        expect_rgba_near(mir.sample(-u, 0.5), mir.sample(u, 0.5), "mirrored -u, u = " + std::to_string(u), 1e-6);
    }
}

// ------------------------------------------------- coordinates out of range

// One of the image's four texels, exactly.
bool is_a_texel(const Rgba& c) {
    for (const Bytes4& t : {kRed, kGreen, kBlue, kGrey})
        if (c == linear(t)) return true;
    return false;
}

const double kNaN = std::numeric_limits<double>::quiet_NaN();
const double kInf = std::numeric_limits<double>::infinity();
const double kOdd[] = {kNaN, -kNaN, kInf, -kInf, 1e300, -1e300, 0x1p60, -0x1p60, 0x1p52, 3e9, -3e9};

TEST(TextureOutOfRange, NearestReadsSomeTexelForNaNAndHugeCoordinates) {
    for (const Wrap w : {Wrap::repeat, Wrap::mirrored_repeat, Wrap::clamp_to_edge})
        for (const double u : kOdd)
            for (const double v : {0.3, kNaN, 1e300}) {
                const Rgba c = square(w, w, Filter::nearest).sample(u, v);
                EXPECT_TRUE(is_a_texel(c)) << name(w) << " (" << u << ", " << v << ") read " << show(c);
            }
}

TEST(TextureOutOfRange, BilinearReadsStayInZeroOneForNaNAndHugeCoordinates) {
    // texture.h: "a read returns linear colour ... and alpha, in [0, 1]";
    // coordinates past a long's range or NaN "read texel 0's row or
    // column: never undefined". A blend of texels is in [0, 1] -- NaN, an
    // infinity or a weight of 2^60 is not.
    for (const Wrap w : {Wrap::repeat, Wrap::mirrored_repeat, Wrap::clamp_to_edge})
        for (const double u : kOdd)
            for (const double v : {0.3, kNaN, 1e300}) {
                const Rgba c = square(w, w, Filter::bilinear).sample(u, v);
                for (size_t k = 0; k < 4; ++k)
                    EXPECT_TRUE(c[k] >= 0 && c[k] <= 1)
                        << name(w) << " (" << u << ", " << v << ") read " << show(c) << ": channel " << k;
            }
}

TEST(TextureOutOfRange, ValuesJustInsideALongsRangeStillWrap) {
    // x = 4u = 2^40 + 1 exactly: texel 2^40 + 1, which repeat takes to 1.
    const double u = (0x1p40 + 1) / 4 + 0.125 / 4;  // x = 2^40 + 1.125
    expect_exact(row(Wrap::repeat, Filter::nearest).sample(u, 0.5), linear(kGreen), "repeat");
    // mirrored: 2^40 + 1 mod 8 = 1 -> 1; clamp: 3.
    expect_exact(row(Wrap::mirrored_repeat, Filter::nearest).sample(u, 0.5), linear(kGreen), "mirrored");
    expect_exact(row(Wrap::clamp_to_edge, Filter::nearest).sample(u, 0.5), linear(kGrey), "clamp");
    expect_exact(row(Wrap::clamp_to_edge, Filter::nearest).sample(-u, 0.5), linear(kRed), "clamp, negative");
}

}  // namespace
}  // namespace fh
