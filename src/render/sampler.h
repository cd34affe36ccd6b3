// Where a pixel's samples go. One sample: the pixel's centre. n samples: the
// pixel is cut into an nx x ny grid of strata (nx * ny = n, as square as n
// allows) and each stratum gets one sample, multi-jittered (Chiu, Shirley
// and Wang, "Multi-Jittered Sampling", Graphics Gems IV, 1994; shuffled
// per pixel as Kensler's correlated multi-jittering is): within its
// stratum each sample takes one of ny sub-columns and one of nx sub-rows,
// so that the n samples' x lie in n different n-ths of the pixel, and so
// do their y -- an edge along either side of the pixel is met by as many
// samples as its share of the pixel, to within one, where plain jitter in
// the strata only promises that to within a row or column of strata. Which
// sub-column goes to which row of strata, and which sub-row to which
// column, are permutations of the pixel's; where the sample lies in its
// sub-cell is a hash of (pixel, sample). Every sample is a pure function of
// its pixel, so an image is the same for any thread count, tile order or
// shard.
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

// A 64-bit finaliser (splitmix64): a cheap, well-mixed hash, in place -- of
// one number, or lane by lane of a vector of them (taken by reference: a
// vector wider than the level's registers passed by value changes the ABI).
template <typename U>
inline void mix64_in_place(U& z) {
    z += 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    z ^= z >> 31;
}

inline std::uint64_t mix64(std::uint64_t z) {
    mix64_in_place(z);
    return z;
}

// A number in [0, 1) from the top 24 bits: exact in float and double alike.
inline double unit_from_bits(std::uint64_t bits) { return double(bits >> 40) * 0x1p-24; }

// A permutation of [0, count), chosen by a key: a bijection of the numbers
// of as many bits as count needs (xor, multiply by an odd number, xorshift,
// multiply-add -- each step invertible), applied again until the value
// falls in [0, count), which the cycle through any i there reaches.
class Permutation {
public:
    Permutation(int count, std::uint64_t key)
        : count_(unsigned(count)), a_(unsigned(key)), m1_(unsigned(key >> 16) | 1u),
          m2_(unsigned(key >> 32) | 1u), b_(unsigned(key >> 48)) {
        while ((1u << bits_) < count_) ++bits_;
        mask_ = (1u << bits_) - 1;
    }

    int operator()(int i) const {
        unsigned v = unsigned(i);
        do step(v);
        while (v >= count_);
        return int(v);
    }

    // Whether every value lands in [0, count) at the first step: count is
    // a power of two. Then `step` alone is the permutation, and it can run
    // lane by lane.
    bool one_step() const { return count_ == mask_ + 1; }

    // One application of the bijection, in place: to one number or to a
    // vector of unsigned lanes (by reference, as mix64_in_place).
    template <typename V>
    void step(V& v) const {
        v = ((v ^ a_) * m1_) & mask_;
        v ^= v >> ((bits_ + 1) / 2);
        v = (v * m2_ + b_) & mask_;
    }

private:
    unsigned count_, a_, m1_, m2_, b_;
    unsigned bits_ = 0, mask_ = 0;
};

struct SampleOffset {
    double x, y;  // in [0, 1) within the pixel
};

// A sample before its jitter: the sub-cell (x, y) it lies in, of the pixel
// cut n x n for n samples, and what its jitter is hashed from.
struct SampleCell {
    int x, y;
    std::uint64_t seed;
};

// Where in its sub-cell a sample lies, from its cell's seed: x from the
// seed's hash h, y from h's hash.
inline SampleOffset jittered(const SampleCell& c, double unit) {
    const std::uint64_t h = mix64(c.seed);
    return {(c.x + unit_from_bits(h)) * unit, (c.y + unit_from_bits(mix64(h))) * unit};
}

// One pixel's samples, what depends on the pixel alone worked out once.
class PixelSamples {
public:
    PixelSamples(int px, int py, StrataGrid grid)
        : grid_(grid), key_(mix64((std::uint64_t(std::uint32_t(py)) << 32) | std::uint32_t(px))),
          column_of_row_(grid.ny, mix64(key_ ^ 0x9e3779b97f4a7c15ull)),
          row_of_column_(grid.nx, mix64(key_ ^ 0xbf58476d1ce4e5b9ull)), column_(column_of_row_(0)) {}

    // The width of a sub-cell, a pixel's 1 / n.
    double unit() const { return 1.0 / double(grid_.nx * grid_.ny); }

    // Whether cells_at_once applies: nx and ny powers of two (4, 8, 16, 64,
    // 256 samples ...), so that each permutation is one step.
    bool at_once() const { return row_of_column_.one_step() && column_of_row_.one_step(); }

    // The cells of the samples first, first + 1, ... one a lane, at once
    // (at_once() only): x and y as next_cell gives them, and their seeds.
    // U: a vector of unsigned 32-bit lanes, S: of 64-bit ones, as many.
    template <typename U, typename S>
    void cells_at_once(int first, U& x, U& y, S& seed) const {
        U s;
        for (int i = 0; i < int(sizeof(U) / sizeof(unsigned)); ++i) s[i] = unsigned(first + i);
        const unsigned log_nx = unsigned(__builtin_ctz(unsigned(grid_.nx)));
        U sx = s & unsigned(grid_.nx - 1), sy = s >> log_nx;
        seed = __builtin_convertvector(s, S) * 0xd1b54a32d192ed03ull ^ key_;
        x = sx * unsigned(grid_.ny);
        y = sy * unsigned(grid_.nx);
        column_of_row_.step(sy);  // now each lane's sub-column
        row_of_column_.step(sx);  // and sub-row
        x += sy;
        y += sx;
    }

    // Any one sample.
    SampleOffset operator[](int sample) const {
        if (grid_.nx * grid_.ny == 1) return {0.5, 0.5};
        return jittered(cell(sample, sample % grid_.nx, sample / grid_.nx, column_of_row_(sample / grid_.nx)),
                        unit());
    }

    // The samples' cells in order, 0, 1, 2, ... as operator[] takes them
    // (for n > 1), for the renderer's loop, which jitters a packet's lanes
    // at once: the stratum counted along instead of divided out, and a row
    // of strata's sub-column worked out once a row.
    SampleCell next_cell() {
        const SampleCell c = cell(sample_++, sx_, sy_, column_);
        if (++sx_ == grid_.nx) {
            sx_ = 0;
            // (Not past the last row: a permutation's walk from outside its
            // range need not come back into it.)
            if (++sy_ < grid_.ny) column_ = column_of_row_(sy_);
        }
        return c;
    }

private:
    // Sample `sample` in stratum (sx, sy), whose row of strata has
    // sub-column `column`: x = (sx + (sub-column + jitter) / ny) / nx, and
    // y alike, as one product each.
    SampleCell cell(int sample, int sx, int sy, int column) const {
        return {sx * grid_.ny + column, sy * grid_.nx + row_of_column_(sx),
                key_ ^ std::uint64_t(sample) * 0xd1b54a32d192ed03ull};
    }

    StrataGrid grid_;
    std::uint64_t key_;
    Permutation column_of_row_, row_of_column_;
    int sample_ = 0, sx_ = 0, sy_ = 0, column_;  // next_cell()'s place
};

inline SampleOffset sample_offset(int px, int py, int sample, StrataGrid grid) {
    return PixelSamples(px, py, grid)[sample];
}

}  // namespace fh
