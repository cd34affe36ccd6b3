#include "render/adaptive.h"

#include <cstdlib>

namespace fh {

namespace {
int channel_gap(const std::uint8_t* a, const std::uint8_t* b) {
    int gap = 0;
    for (int c = 0; c < 3; ++c) gap = std::max(gap, std::abs(int(a[c]) - int(b[c])));
    return gap;
}
}  // namespace

std::vector<PixelRef> pixels_to_refine(const Image& img, double threshold) {
    std::vector<PixelRef> out;
    for (int y = 0; y < img.height; ++y) {
        for (int x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.pixel(x, y);
            bool edge = false;
            for (int dy = -1; dy <= 1 && !edge; ++dy)
                for (int dx = -1; dx <= 1 && !edge; ++dx) {
                    const int nx = x + dx, ny = y + dy;
                    if (nx < 0 || ny < 0 || nx >= img.width || ny >= img.height) continue;
                    edge = channel_gap(p, img.pixel(nx, ny)) > threshold;
                }
            if (edge) out.push_back({std::uint16_t(x), std::uint16_t(y)});
        }
    }
    return out;
}

}  // namespace fh
