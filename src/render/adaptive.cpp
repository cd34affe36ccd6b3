#include "render/adaptive.h"

#include <cmath>

namespace fh {

namespace {

// Per byte of two rows of channels: whether they differ by more than t.
void bytes_apart(const std::uint8_t* a, const std::uint8_t* b, int n, int t, std::uint8_t* apart) {
    for (int i = 0; i < n; ++i) {
        const int gap = a[i] > b[i] ? a[i] - b[i] : b[i] - a[i];
        apart[i] = gap > t;
    }
}

}  // namespace

// Being more than the threshold apart is symmetric, so each pair of
// neighbours is compared once -- right, down-left, down, down-right of each
// pixel -- and marks both; a row at a time, channel bytes first (a loop the
// compiler vectorizes), then pixels. It was 8 neighbours a pixel, one byte
// at a time: a third of an adaptive frame's time, on one core.
std::vector<PixelRef> pixels_to_refine(const Image& img, double threshold) {
    const int w = img.width, h = img.height;
    std::vector<PixelRef> out;
    if (w <= 0 || h <= 0 || !(threshold < 255)) return out;  // no gap of bytes exceeds 255
    if (threshold < 0) {  // even a pixel's gap of 0 to itself exceeds it: all of them
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) out.push_back({std::uint16_t(x), std::uint16_t(y)});
        return out;
    }
    // A gap of whole steps exceeds the threshold where it exceeds its floor.
    const int t = int(std::floor(threshold));
    std::vector<std::uint8_t> edge(std::size_t(w) * std::size_t(h), 0);
    std::vector<std::uint8_t> apart(std::size_t(w) * 3);
    auto mark = [&](int y0, int x0, int y1, int x1, int n) {  // pixels (x0.., y0) against (x1.., y1)
        bytes_apart(img.pixel(x0, y0), img.pixel(x1, y1), 3 * n, t, apart.data());
        std::uint8_t* e0 = &edge[std::size_t(y0) * w + x0];
        std::uint8_t* e1 = &edge[std::size_t(y1) * w + x1];
        for (int i = 0; i < n; ++i) {
            const std::uint8_t m = apart[3 * i] | apart[3 * i + 1] | apart[3 * i + 2];
            e0[i] |= m;
            e1[i] |= m;
        }
    };
    for (int y = 0; y < h; ++y) {
        if (w > 1) mark(y, 0, y, 1, w - 1);  // right
        if (y + 1 == h) continue;
        mark(y, 0, y + 1, 0, w);  // down
        if (w > 1) {
            mark(y, 0, y + 1, 1, w - 1);  // down-right
            mark(y, 1, y + 1, 0, w - 1);  // down-left
        }
    }
    for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
            if (edge[std::size_t(y) * w + x]) out.push_back({std::uint16_t(x), std::uint16_t(y)});
    return out;
}

}  // namespace fh
