#include "video/yuv420.h"

#include <algorithm>

namespace fh {

namespace {

// BT.601 times 219/255 (luma) or 224/255 (chroma), in units of 2^-15: the
// integers libswscale derives for limited range.
constexpr int kRY = 8414, kGY = 16519, kBY = 3208;
constexpr int kRU = -4857, kGU = -9535, kBU = 14392;
constexpr int kRV = 14392, kGV = -12052, kBV = -2340;

// swscale rounds twice: to a 14-bit intermediate (Y times 64), then to 8 bits.
inline std::uint8_t luma(int r, int g, int b) {
    const int y14 = (kRY * r + kGY * g + kBY * b + (16 << 15) + (1 << 8)) >> 9;
    return std::uint8_t((y14 + 32) >> 6);
}

// Chroma from the sums of four pixels' r, g, b: 128 + coefficients . sums
// / (4 * 2^15), rounded. Always positive before the shift (|sum| < 128 * 2^17).
inline std::uint8_t chroma(int kr, int kg, int kb, int r4, int g4, int b4) {
    return std::uint8_t((kr * r4 + kg * g4 + kb * b4 + (128 << 17) + (1 << 16)) >> 17);
}

}  // namespace

size_t yuv420p_size(int width, int height) {
    const size_t cw = size_t(width + 1) / 2, ch = size_t(height + 1) / 2;
    return size_t(width) * size_t(height) + 2 * cw * ch;
}

Bytes to_yuv420p(const Image& image) {
    const int w = image.width, h = image.height;
    const int cw = (w + 1) / 2, ch = (h + 1) / 2;
    Bytes out(yuv420p_size(w, h));
    std::uint8_t* y_plane = out.data();
    std::uint8_t* u_plane = y_plane + size_t(w) * size_t(h);
    std::uint8_t* v_plane = u_plane + size_t(cw) * size_t(ch);
    if (w == 0 || h == 0) return out;

    for (size_t i = 0, n = size_t(w) * size_t(h); i < n; ++i) {
        const std::uint8_t* p = &image.rgb[3 * i];
        y_plane[i] = luma(p[0], p[1], p[2]);
    }
    // Per pair of rows: the columns' sums of r, g and b, planar (a stride
    // the vectoriser takes), then the sums of column pairs.
    std::vector<std::uint16_t> sums(3 * size_t(w) + 3);
    std::uint16_t* __restrict r2 = sums.data();
    std::uint16_t* __restrict g2 = r2 + w + 1;
    std::uint16_t* __restrict b2 = g2 + w + 1;
    for (int cy = 0; cy < ch; ++cy) {
        const std::uint8_t* __restrict top = image.pixel(0, 2 * cy);
        const std::uint8_t* __restrict bottom = image.pixel(0, std::min(2 * cy + 1, h - 1));
        for (int x = 0; x < w; ++x) {
            r2[x] = std::uint16_t(top[3 * x] + bottom[3 * x]);
            g2[x] = std::uint16_t(top[3 * x + 1] + bottom[3 * x + 1]);
            b2[x] = std::uint16_t(top[3 * x + 2] + bottom[3 * x + 2]);
        }
        // An odd width's last block: its missing column repeats the edge.
        r2[w] = r2[w - 1], g2[w] = g2[w - 1], b2[w] = b2[w - 1];
        std::uint8_t* __restrict u = u_plane + size_t(cy) * size_t(cw);
        std::uint8_t* __restrict v = v_plane + size_t(cy) * size_t(cw);
        for (int cx = 0; cx < cw; ++cx) {
            const int r4 = r2[2 * cx] + r2[2 * cx + 1];
            const int g4 = g2[2 * cx] + g2[2 * cx + 1];
            const int b4 = b2[2 * cx] + b2[2 * cx + 1];
            u[cx] = chroma(kRU, kGU, kBU, r4, g4, b4);
            v[cx] = chroma(kRV, kGV, kBV, r4, g4, b4);
        }
    }
    return out;
}

}  // namespace fh
