// Where a pixel's samples go. One sample: the pixel's centre. n samples: the
// pixel is cut into an nx x ny grid of strata (nx * ny = n, as square as n
// allows) and each stratum gets one sample, jittered inside it by a hash of
// (pixel, sample). The hash makes every sample a pure function of its pixel,
// so an image is the same for any thread count, tile order or shard.
#pragma once

#include <cstdint>

namespace fh {

struct StrataGrid {
    int nx = 1;
    int ny = 1;
};

// The most nearly square factorisation n = nx * ny with nx >= ny.
inline StrataGrid strata_for(int n) {
    int ny = 1;
    for (int k = 1; k * k <= n; ++k)
        if (n % k == 0) ny = k;
    return {n / ny, ny};
}

// A 64-bit finaliser (splitmix64): a cheap, well-mixed hash.
inline std::uint64_t mix64(std::uint64_t z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
}

// A number in [0, 1) from the top 24 bits: exact in float and double alike.
inline double unit_from_bits(std::uint64_t bits) { return double(bits >> 40) * 0x1p-24; }

struct SampleOffset {
    double x, y;  // in [0, 1) within the pixel
};

inline SampleOffset sample_offset(int px, int py, int sample, StrataGrid grid) {
    if (grid.nx * grid.ny == 1) return {0.5, 0.5};
    const std::uint64_t key = mix64((std::uint64_t(std::uint32_t(py)) << 32) | std::uint32_t(px));
    const std::uint64_t h = mix64(key ^ std::uint64_t(sample) * 0xd1b54a32d192ed03ull);
    const int sx = sample % grid.nx;
    const int sy = sample / grid.nx;
    return {(sx + unit_from_bits(h)) / grid.nx, (sy + unit_from_bits(mix64(h))) / grid.ny};
}

}  // namespace fh
