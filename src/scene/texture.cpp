#include "scene/texture.h"

#include <algorithm>

namespace fh {

// Filled once before main: the table every texel read goes through.
const std::array<float, 256> kSrgbToLinear = [] {
    std::array<float, 256> t{};
    for (int i = 0; i < 256; ++i) {
        const double c = i / 255.0;
        t[size_t(i)] = float(c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4));
    }
    return t;
}();

std::uint8_t linear_to_srgb_byte(double linear) {
    const double c = std::clamp(linear, 0.0, 1.0);
    const double encoded = c <= 0.0031308 ? 12.92 * c : 1.055 * std::pow(c, 1 / 2.4) - 0.055;
    return std::uint8_t(std::lround(255 * encoded));
}

namespace {

// The texels of level n (along one axis) that texel i of the next level
// down, of n' = max(1, n / 2) texels, averages: [first, end).
struct Span {
    int first, end;
};
Span span_of(int i, int n, int n_next) {
    return {int(long(i) * n / n_next), int((long(i + 1) * n + n_next - 1) / n_next)};
}

}  // namespace

std::shared_ptr<const MipChain> mip_chain(const TextureImage& image, bool srgb, bool alpha_weighted) {
    auto chain = std::make_shared<MipChain>();
    // The level above as linear values (rgba per texel): the image's bytes
    // through the table, then each level's floats as computed, not its
    // rounded bytes. No copy of the image: a float level below it needs as
    // much memory as its bytes.
    int w = image.width, h = image.height;
    std::vector<float> above;
    size_t bytes = 0;  // the levels' together, reserved at once: no doubling on the way
    for (int lw = w, lh = h; lw > 1 || lh > 1;) {
        lw = std::max(1, lw / 2), lh = std::max(1, lh / 2);
        bytes += 4 * size_t(lw) * size_t(lh);
    }
    chain->rgba.reserve(bytes);
    auto value = [&](size_t k) {
        if (!above.empty()) return above[k];
        const std::uint8_t byte = image.rgba[k];
        return srgb && k % 4 != 3 ? kSrgbToLinear[byte] : float(byte) * (1.0f / 255);
    };
    while (w > 1 || h > 1) {
        const int nw = std::max(1, w / 2), nh = std::max(1, h / 2);
        std::vector<float> level(4 * size_t(nw) * size_t(nh));
        for (int j = 0; j < nh; ++j) {
            const Span rows = span_of(j, h, nh);
            for (int i = 0; i < nw; ++i) {
                const Span columns = span_of(i, w, nw);
                // Colour weighted by alpha where alpha hides texels: a
                // cutout's clear texels lend the mean none of their colour.
                double sum[4] = {0, 0, 0, 0}, weighted[3] = {0, 0, 0};
                for (int y = rows.first; y < rows.end; ++y)
                    for (int x = columns.first; x < columns.end; ++x) {
                        const size_t at = 4 * (size_t(y) * size_t(w) + size_t(x));
                        const double alpha = value(at + 3);
                        for (int c = 0; c < 4; ++c) sum[c] += value(at + size_t(c));
                        for (int c = 0; c < 3; ++c) weighted[c] += alpha * value(at + size_t(c));
                    }
                const double n = double(rows.end - rows.first) * double(columns.end - columns.first);
                float* out = &level[4 * (size_t(j) * size_t(nw) + size_t(i))];
                for (int c = 0; c < 3; ++c)
                    out[c] = float(alpha_weighted && sum[3] > 0 ? weighted[c] / sum[3] : sum[c] / n);
                out[3] = float(sum[3] / n);
            }
        }
        chain->levels.push_back({nw, nh, chain->rgba.size()});
        for (size_t k = 0; k < level.size(); ++k)
            chain->rgba.push_back(srgb && k % 4 != 3 ? linear_to_srgb_byte(level[k])
                                                     : std::uint8_t(std::lround(255 * std::clamp(double(level[k]), 0.0, 1.0))));
        above = std::move(level);
        w = nw, h = nh;
    }
    return chain;
}

}  // namespace fh
