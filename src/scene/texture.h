// A colour texture (glTF's baseColorTexture): an image of 8-bit RGBA texels
// and how a point of it is read -- the sampler's wrap mode per axis and its
// filter. Texture coordinates (u, v) run over the image from its top-left
// corner: u = 1 is one image width to the right, v = 1 one height down.
//
// Texels hold sRGB-encoded colour and linear alpha, as glTF stores them;
// a read returns linear colour (the spec's transfer function, inverted by
// a 256-entry table) and alpha, in [0, 1]. Bilinear filtering blends the
// four nearest texel centres in linear colour. There are no mipmaps: a
// texture seen from far away is read at one point per ray, as a pixel's
// sample (docs/gltf.md, "Textures").
#pragma once

#include <array>
#include <cmath>
#include <cstdint>
#include <memory>
#include <vector>

#include "core/simd.h"

namespace fh {

enum class Wrap : std::uint8_t { repeat, mirrored_repeat, clamp_to_edge };
enum class Filter : std::uint8_t { nearest, bilinear };

struct TextureImage {
    int width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // width * height texels, rows from the top
};

// sRGB byte -> linear value in [0, 1] (IEC 61966-2-1).
extern const std::array<float, 256> kSrgbToLinear;

// One texel index along an axis of n texels, for any whole i, by the wrap
// mode: repeat tiles, mirrored_repeat tiles with every other copy flipped,
// clamp_to_edge repeats the edge texel.
inline int wrap_texel(long i, int n, Wrap wrap) {
    switch (wrap) {
    case Wrap::clamp_to_edge: return int(i < 0 ? 0 : i >= n ? n - 1 : i);
    case Wrap::repeat: {
        const long m = i % n;
        return int(m < 0 ? m + n : m);
    }
    default: {
        long m = i % (2L * n);
        if (m < 0) m += 2L * n;
        return int(m < n ? m : 2L * n - 1 - m);
    }
    }
}

struct Texture {
    std::shared_ptr<const TextureImage> image;
    Wrap wrap_s = Wrap::repeat, wrap_t = Wrap::repeat;  // along u, along v
    Filter filter = Filter::bilinear;

    // Linear red, green, blue and alpha at (u, v). Coordinates past what a
    // long holds (or NaN) read texel 0's row or column: never undefined.
    FH_HOT_INLINE std::array<float, 4> sample(double u, double v) const {
        const int w = image->width, h = image->height;
        double x = u * w, y = v * h;
        if (filter == Filter::nearest) return texel(wrap_texel(whole(x), w, wrap_s), wrap_texel(whole(y), h, wrap_t));
        // Texel centres sit at half-integers: blend the four around (x, y).
        x -= 0.5;
        y -= 0.5;
        const long x0 = whole(x), y0 = whole(y);
        const float fx = float(x - double(x0)), fy = float(y - double(y0));
        const int i0 = wrap_texel(x0, w, wrap_s), i1 = wrap_texel(x0 + 1, w, wrap_s);
        const int j0 = wrap_texel(y0, h, wrap_t), j1 = wrap_texel(y0 + 1, h, wrap_t);
        const std::array<float, 4> a = texel(i0, j0), b = texel(i1, j0), c = texel(i0, j1), d = texel(i1, j1);
        std::array<float, 4> out;
        for (int k = 0; k < 4; ++k) {
            const float top = a[size_t(k)] + fx * (b[size_t(k)] - a[size_t(k)]);
            const float bottom = c[size_t(k)] + fx * (d[size_t(k)] - c[size_t(k)]);
            out[size_t(k)] = top + fy * (bottom - top);
        }
        return out;
    }

    // Texel (i, j) of the image, linear.
    FH_HOT_INLINE std::array<float, 4> texel(int i, int j) const {
        const std::uint8_t* p = &image->rgba[4 * (size_t(j) * size_t(image->width) + size_t(i))];
        return {kSrgbToLinear[p[0]], kSrgbToLinear[p[1]], kSrgbToLinear[p[2]], float(p[3]) * (1.0f / 255)};
    }

private:
    // floor(x) as a long; 0 for NaN and for |x| past 2^52 (where no
    // fraction is left to read anyway).
    static long whole(double x) { return std::fabs(x) < 0x1p52 ? long(std::floor(x)) : 0; }
};

}  // namespace fh
