// A texture (glTF's base colour, emissive or occlusion texture): an image
// of 8-bit RGBA texels and how a point of it is read -- the sampler's wrap
// mode per axis and its filter. Texture coordinates (u, v) run over the
// image from its top-left corner: u = 1 is one image width to the right,
// v = 1 one height down.
//
// Colour texels hold sRGB-encoded colour and linear alpha, as glTF stores
// them; a read returns linear colour (the spec's transfer function, inverted
// by a 256-entry table) and alpha, in [0, 1]. Data texels (occlusion) are
// linear throughout. Bilinear filtering blends the four nearest texel
// centres in linear values.
//
// Seen from far away, where a pixel covers many texels, a texture is read
// from its mipmaps (glTF's minFilter): the image halved again and again
// down to one texel, each level the box average of the one above in linear
// values. The pixel's footprint, as a ray cone finds it
// (render/texture_footprint.h), is an ellipse: it is read in reads along
// its length, and each read's level is lambda = log2 of its width in
// texels (UvFootprint); LINEAR_MIPMAP_LINEAR blends the two levels round
// lambda (trilinear). Where lambda <= 0 the texture is magnified and read
// as without mipmaps (docs/gltf.md, "Textures").
#pragma once

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

#include "core/simd.h"

namespace fh {

enum class Wrap : std::uint8_t { repeat, mirrored_repeat, clamp_to_edge };
enum class Filter : std::uint8_t { nearest, bilinear };
// Between mipmap levels (glTF's *_MIPMAP_NEAREST, *_MIPMAP_LINEAR); none:
// the image alone, however small it is seen.
enum class MipFilter : std::uint8_t { none, nearest, linear };

struct TextureImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width * height texels, rows from the top
};

// sRGB byte -> linear value in [0, 1] (IEC 61966-2-1).
extern const std::array<float, 256> kSrgbToLinear;
// And back: the nearest sRGB byte of a linear value (clamped into [0, 1]).
std::uint8_t linear_to_srgb_byte(double linear);

// An image's mipmap levels below it: level k (from 1) is
// max(1, width >> k) x max(1, height >> k) texels. Each texel is the mean,
// in linear values, of the texels of the level above that its span covers
// -- a 2 x 2 block, or 3 where an odd side does not halve evenly -- computed
// from the level above's unrounded values and rounded to bytes once.
// alpha_weighted (a MASK or BLEND surface's base colour, whose alpha hides
// texels): colour is weighted by alpha -- the mean of the texels that show,
// all of them where none does -- so that a cutout's clear texels do not
// darken its edges from far away. Elsewhere glTF ignores alpha, and so does
// the mean.
struct MipChain {
    struct Level {
        int width, height;
        size_t offset;  // of its first texel in rgba, in bytes
    };
    std::vector<Level> levels;  // levels 1, 2, ... down to 1 x 1
    std::vector<std::uint8_t> rgba;
};
// srgb: colour texels (averaged as linear values); else data.
std::shared_ptr<const MipChain> mip_chain(const TextureImage& image, bool srgb, bool alpha_weighted = false);

// One texel index along an axis of n texels, for any whole i, by the wrap
// mode: repeat tiles, mirrored_repeat tiles with every other copy flipped,
// clamp_to_edge repeats the edge texel. The rule in plain integers;
// texel_pair below does the same for every lane at once (the tests hold
// each to it).
inline int wrap_texel(long i, int n, Wrap wrap) {
    const long period = wrap == Wrap::mirrored_repeat ? 2L * n : n;
    long m = i % period;
    if (m < 0) m += period;
    switch (wrap) {
    case Wrap::clamp_to_edge: return int(i < 0 ? 0 : i >= n ? n - 1 : i);
    case Wrap::repeat: return int(m);
    default: return int(m < n ? m : 2L * n - 1 - m);
    }
}

// Linear colour and alpha in each lane of a packet.
template <typename T>
struct TexelLanes {
    Lanes<T> r, g, b, a;
};

// How many reads at most one footprint takes along its length: a surface
// seen at a slant is filtered as sharply as head-on up to a footprint this
// many times longer than wide (GPUs offer 2 to 16).
inline constexpr int kMaxProbes = 8;

// A pixel's footprint on a texture where its ray hits, in (u, v) units
// (render/texture_footprint.h): an ellipse, long across the image where
// the surface is seen at a slant, given by two of its diameters that are
// conjugate (the images of two perpendicular diameters of a circle), end
// to end: (g1u, g1v) and (g2u, g2v). Each texture finds its axes in its
// own texels (a w x h image's texels are 1/w by 1/h), and with mipmaps
// reads it as GPUs' anisotropic filtering does: in reads spaced evenly
// along its length, each over its width (at least a texel, at least a
// kMaxProbes-th of its length); without, once, over its length. A lane
// whose footprint is not a real ellipse has g1u = 0 (a point), NaN (none
// known: both read as magnified) or +infinity (a grazing ray: the
// smallest level), and the other three 0.
template <typename T>
struct UvFootprint {
    Lanes<T> g1u = splat(T(0)), g1v = splat(T(0)), g2u = splat(T(0)), g2v = splat(T(0));
};

// Per lane: floor(x).
template <typename T>
FH_HOT_INLINE Lanes<T> floor_lanes(const Lanes<T>& x) {
    Lanes<T> r = x;  // overwritten lane by lane (one vroundps/pd once inlined)
    for (int i = 0; i < kLanes<T>; ++i) r[i] = std::floor(x[i]);
    return r;
}

// wrap_texel of the lanes' texels i = floor(x) and i + 1 (bilinear
// filtering's neighbours), and x's fraction f past i. The period is taken
// off in T first, so the integers stay small; whatever rounding leaves, the
// indices end clamped into [0, n): never a read outside the image.
template <typename T>
FH_HOT_INLINE void texel_pair(Lanes<T> x, int n, Wrap wrap, LaneInts<T>& i, LaneInts<T>& next, Lanes<T>& f) {
    using Ints = LaneInts<T>;
    using Int = typename LaneTypes<T>::Int;
    // NaN, infinities and absurd coordinates read texel 0's neighbourhood.
    x = select(abs(x) < T(1e15), x, splat(T(0)));
    const T period = wrap == Wrap::mirrored_repeat ? T(2) * T(n) : T(n);
    if (wrap == Wrap::clamp_to_edge) x = max(splat(T(-1)), min(splat(T(n)), x));
    else x -= period * floor_lanes<T>(x * (T(1) / period));
    const Lanes<T> whole = floor_lanes<T>(x);
    f = x - whole;
    i = __builtin_convertvector(whole, Ints);
    next = i + 1;
    if (wrap != Wrap::clamp_to_edge) {  // i in [0, period] to rounding: bring it and next into [0, period)
        const Ints p = Ints{} + Int(period);
        i = select(i >= p, i - p, select(i < 0, i + p, i));
        next = select(next >= p, next - p, next);
    }
    if (wrap == Wrap::mirrored_repeat) {  // the second half of a period runs backwards
        const Ints top = Ints{} + Int(2 * n - 1), half = Ints{} + Int(n);
        i = select(i >= half, top - i, i);
        next = select(next >= half, top - next, next);
    }
    const Ints zero = Ints{}, last = Ints{} + Int(n - 1);
    i = max(zero, min(last, i));
    next = max(zero, min(last, next));
}

struct Texture {
    std::shared_ptr<const TextureImage> image;
    Wrap wrap_s = Wrap::repeat, wrap_t = Wrap::repeat;  // along u, along v
    Filter filter = Filter::bilinear;      // magnified (glTF's magFilter)
    Filter min_filter = Filter::bilinear;  // minified, within a level (minFilter)
    MipFilter mips = MipFilter::none;      // minified, between levels (minFilter)
    std::shared_ptr<const MipChain> smaller;  // mips != none: the levels below the image
    // Colour texels are sRGB-encoded (base colour, emissive); data texels
    // (occlusion) are read as they are, n / 255.
    bool srgb = true;

    // Whether a footprint can change what is read: mipmaps, or another
    // filter for the minified.
    bool minifies() const { return mips != MipFilter::none || min_filter != filter; }

    // Linear colour and alpha at each lane's (u, v), read as magnified.
    // Coordinates turn into texels in T, all lanes at once; then each lane
    // reads its texels.
    template <typename T>
    FH_HOT_INLINE TexelLanes<T> sample(const Lanes<T>& u, const Lanes<T>& v) const {
        return sample_level<T>(image->rgba.data(), image->width, image->height, filter, u, v);
    }

    // The same where each lane's pixel covers a round footprint of 2^lod in
    // (u, v) units (tests, single points; -infinity or NaN: a point,
    // read as magnified): lambda = lod + log2 sqrt(width * height) picks
    // the level.
    template <typename T>
    FH_HOT_INLINE TexelLanes<T> sample(const Lanes<T>& u, const Lanes<T>& v, const Lanes<T>& lod) const {
        if (!minifies()) return sample<T>(u, v);
        return sample_minified<T>(u, v, lod);
    }

    // The same over each lane's footprint `f`, along its length.
    template <typename T>
    FH_HOT_INLINE TexelLanes<T> sample(const Lanes<T>& u, const Lanes<T>& v, const UvFootprint<T>& f) const {
        if (!minifies()) return sample<T>(u, v);
        return sample_along<T>(u, v, f);
    }

    // One point (tests, cutouts): the packet formula in a packet of one.
    std::array<float, 4> sample(double u, double v) const { return sample(u, v, -kInfinity<double>); }
    std::array<float, 4> sample(double u, double v, double lod) const {
        const TexelLanes<double> c = sample<double>(splat(u), splat(v), splat(lod));
        return {float(c.r[0]), float(c.g[0]), float(c.b[0]), float(c.a[0])};
    }

private:
    // Out of line: the level loop is needed only where a texture is seen
    // from far away.
    template <typename T>
    __attribute__((noinline)) TexelLanes<T> sample_minified(const Lanes<T>& u, const Lanes<T>& v,
                                                            const Lanes<T>& lod) const {
        return sample_levels<T>(u, v, lod + T(0.5) * std::log2(T(image->width) * T(image->height)));
    }

    // Reads i = 0 .. n - 1 at (i + 1/2) / n - 1/2 of the footprint's long
    // axis from (u, v), each a 1 / n share, at the level of the read's
    // width in texels -- the footprint's, at least one texel (reads closer
    // than a texel see what bilinear reads between them see), at least a
    // kMaxProbes-th of the length -- n = ceil(length / that), less a
    // hundredth (a footprint barely longer than wide is read once).
    // Without mipmaps, one read at the level of its length. A lane's reads
    // and sum are its own, whatever the other lanes ask for.
    template <typename T>
    __attribute__((noinline)) TexelLanes<T> sample_along(const Lanes<T>& u, const Lanes<T>& v,
                                                         const UvFootprint<T>& f) const {
        // The diameters in texels, and the ellipse's axes: the eigenvalues
        // and vectors of G G^T, G = (g1 g2) (scaled by their largest entry
        // first, so that no square overflows). All lanes at once; the
        // logarithm only where a lane needs one.
        const T w = T(image->width), h = T(image->height);
        const Lanes<T> au = f.g1u * w, av = f.g1v * h, bu = f.g2u * w, bv = f.g2v * h;
        const Lanes<T> extent = abs(au) + abs(av) + abs(bu) + abs(bv);
        const LaneInts<T> real = (extent > T(0)) & (extent < std::numeric_limits<T>::infinity());
        const Lanes<T> one = splat(T(1)), zero = splat(T(0));
        const Lanes<T> scale = select(real, max(max(abs(au), abs(av)), max(abs(bu), abs(bv))), one);
        const Lanes<T> x1 = au / scale, y1 = av / scale, x2 = bu / scale, y2 = bv / scale;
        const Lanes<T> a = x1 * x1 + x2 * x2, b = x1 * y1 + x2 * y2, c = y1 * y1 + y2 * y2;
        const Lanes<T> longest = T(0.5) * (a + c) + sqrt(T(0.25) * (a - c) * (a - c) + b * b);
        const Lanes<T> length = scale * sqrt(longest);
        const Lanes<T> across = scale * abs(x1 * y2 - y1 * x2) / sqrt(longest);  // the width
        Lanes<T> read = select(across >= length / T(kMaxProbes), across, length / T(kMaxProbes));  // (NaN too)
        read = max(read, one);
        const bool mipmapped = mips != MipFilter::none;
        const LaneInts<T> several = real & (length / read - T(0.01) > one);
        Lanes<T> reads = select(several, min(splat(T(kMaxProbes)), -floor_lanes<T>(T(0.01) - length / read)), one);
        if (!mipmapped) reads = one;
        // Where to take a logarithm: none known, a point or a grazing ray
        // (of the extent, NaN, 0 or +infinity: see UvFootprint); without
        // mipmaps, of the length; with, of a read wider than a texel.
        const Lanes<T> of = select(real, mipmapped ? read : length, extent);
        const LaneInts<T> logarithm = ~real | (mipmapped ? read > one : real);
        Lanes<T> lambda = zero;  // (0: magnified)
        for_each_lane(logarithm, [&](int lane) {
            lambda[lane] = std::log2(of[lane]);
            return false;
        });
        // The long axis (a >= c: (longest - c, b), else (b, longest - a)), back in (u, v).
        const LaneInts<T> wide = a >= c;
        const Lanes<T> ex = select(wide, longest - c, b), ey = select(wide, b, longest - a);
        const Lanes<T> norm = sqrt(ex * ex + ey * ey);
        const LaneInts<T> along = (reads > one) & (norm > T(0));  // (a circle: never more than one read)
        const Lanes<T> axis_u = select(along, length * ex / norm / w, zero);
        const Lanes<T> axis_v = select(along, length * ey / norm / h, zero);
        T most = 1;
        for (int lane = 0; lane < kLanes<T>; ++lane) most = std::max(most, reads[lane]);
        if (most <= 1) return sample_levels<T>(u, v, lambda);
        const Lanes<T> share = T(1) / reads;
        TexelLanes<T> sum{zero, zero, zero, zero};
        for (int i = 0; i < int(most); ++i) {
            const Lanes<T> weight = select(T(i) < reads, share, zero);
            const Lanes<T> at = (T(i) + T(0.5)) * share - T(0.5);
            const TexelLanes<T> t = sample_levels<T>(u + at * axis_u, v + at * axis_v, lambda);
            sum = {sum.r + weight * t.r, sum.g + weight * t.g, sum.b + weight * t.b, sum.a + weight * t.a};
        }
        return sum;
    }

    // Each lane's read at level lambda: magnified where lambda <= 0 (or
    // NaN), between the levels round it (minFilter) beyond.
    template <typename T>
    TexelLanes<T> sample_levels(const Lanes<T>& u, const Lanes<T>& v, const Lanes<T>& lambda) const {
        const LaneInts<T> far = lambda > T(0);  // false for NaN
        if (none(far)) return sample<T>(u, v);
        const int last = mips == MipFilter::none ? 0 : int(smaller->levels.size());
        // Each lane's level and its share of the next: lambda in [0, last].
        const Lanes<T> l = max(splat(T(0)), min(splat(T(last)), select(far, lambda, splat(T(0)))));
        Lanes<T> level = mips == MipFilter::nearest ? floor_lanes<T>(l + T(0.5)) : floor_lanes<T>(l);
        level = min(level, splat(T(last)));
        const Lanes<T> next = mips == MipFilter::linear ? l - level : splat(T(0));
        const LaneInts<T> k = __builtin_convertvector(level, LaneInts<T>);
        int lo = last, hi = 0;
        for_each_lane(far, [&](int lane) {
            lo = std::min(lo, int(k[lane]));
            hi = std::max(hi, int(k[lane]) + (next[lane] > 0 ? 1 : 0));
            return false;
        });
        const Lanes<T> zero = splat(T(0));
        TexelLanes<T> sum{zero, zero, zero, zero};
        for (int at = lo; at <= hi; ++at) {
            const Lanes<T> share = select(far & (k == at), T(1) - next, zero) + select(far & (k + 1 == at), next, zero);
            if (none(share > T(0))) continue;
            const TexelLanes<T> c = at == 0 ? sample_level<T>(image->rgba.data(), image->width, image->height,
                                                               min_filter, u, v)
                                            : level_texels<T>(at, u, v);
            sum = {sum.r + share * c.r, sum.g + share * c.g, sum.b + share * c.b, sum.a + share * c.a};
        }
        const TexelLanes<T> near = any(~far) ? sample<T>(u, v) : sum;
        return {select(far, sum.r, near.r), select(far, sum.g, near.g), select(far, sum.b, near.b),
                select(far, sum.a, near.a)};
    }

    template <typename T>
    TexelLanes<T> level_texels(int at, const Lanes<T>& u, const Lanes<T>& v) const {
        const MipChain::Level& m = smaller->levels[size_t(at - 1)];
        return sample_level<T>(smaller->rgba.data() + m.offset, m.width, m.height, min_filter, u, v);
    }

    // Texels of a w x h level whose first texel is at `rgba`.
    template <typename T>
    FH_HOT_INLINE TexelLanes<T> sample_level(const std::uint8_t* rgba, int w, int h, Filter how, const Lanes<T>& u,
                                             const Lanes<T>& v) const {
        const Lanes<T> shift = splat(how == Filter::bilinear ? T(0.5) : T(0));  // texel centres at i + 1/2
        LaneInts<T> i0, i1, j0, j1;
        Lanes<T> fx, fy;
        texel_pair<T>(u * T(w) - shift, w, wrap_s, i0, i1, fx);
        texel_pair<T>(v * T(h) - shift, h, wrap_t, j0, j1, fy);
        const LaneInts<T> row0 = j0 * w, row1 = j1 * w;
        if (how == Filter::nearest) return read<T>(rgba, row0 + i0);
        const TexelLanes<T> c00 = read<T>(rgba, row0 + i0), c10 = read<T>(rgba, row0 + i1);
        const TexelLanes<T> c01 = read<T>(rgba, row1 + i0), c11 = read<T>(rgba, row1 + i1);
        auto blend = [&](const Lanes<T>& a, const Lanes<T>& b, const Lanes<T>& c, const Lanes<T>& d) {
            const Lanes<T> top = a + fx * (b - a), bottom = c + fx * (d - c);
            return top + fy * (bottom - top);
        };
        return {blend(c00.r, c10.r, c01.r, c11.r), blend(c00.g, c10.g, c01.g, c11.g),
                blend(c00.b, c10.b, c01.b, c11.b), blend(c00.a, c10.a, c01.a, c11.a)};
    }

    // Texels `index` (row * width + column) of every lane, linear: all
    // lanes, which is faster than testing each (texel_pair keeps every
    // index inside the level, used or not).
    template <typename T>
    FH_HOT_INLINE TexelLanes<T> read(const std::uint8_t* rgba, const LaneInts<T>& index) const {
        alignas(sizeof(Lanes<T>)) T r[kLanes<T>], g[kLanes<T>], b[kLanes<T>], a[kLanes<T>];
        if (srgb) {
            for (int k = 0; k < kLanes<T>; ++k) {
                const std::uint8_t* p = rgba + 4 * size_t(index[k]);
                r[k] = T(kSrgbToLinear[p[0]]);
                g[k] = T(kSrgbToLinear[p[1]]);
                b[k] = T(kSrgbToLinear[p[2]]);
                a[k] = T(p[3]) * T(1.0 / 255);
            }
        } else {
            for (int k = 0; k < kLanes<T>; ++k) {
                const std::uint8_t* p = rgba + 4 * size_t(index[k]);
                r[k] = T(p[0]) * T(1.0 / 255);
                g[k] = T(p[1]) * T(1.0 / 255);
                b[k] = T(p[2]) * T(1.0 / 255);
                a[k] = T(p[3]) * T(1.0 / 255);
            }
        }
        return {load(r), load(g), load(b), load(a)};
    }
};

}  // namespace fh
