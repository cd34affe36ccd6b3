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
#include <type_traits>

#include "core/simd.h"  // any
#include "core/vec.h"  // FH_HOT_INLINE

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
    Permutation(int count, std::uint64_t key) : count_(unsigned(count)), bits_(bits_for(count_)) {
        key_parts(key, a_, m1_, m2_, b_);
    }

    int operator()(int i) const {
        unsigned v = unsigned(i);
        do step(v);
        while (v >= count_);
        return int(v);
    }

    // One application of the bijection, in place: to one number or to a
    // vector of unsigned lanes (by reference, as mix64_in_place). Where
    // count is a power of two, every value lands in [0, count) at the first
    // step: `step` alone is the permutation, and it can run lane by lane.
    template <typename V>
    void step(V& v) const {
        step(v, a_, m1_, m2_, b_, bits_);
    }

    // The same step with the key's four parts given (each lane its own
    // permutation, for vectors), of a count of 2^bits.
    template <typename V, typename K>
    static void step(V& v, const K& a, const K& m1, const K& m2, const K& b, unsigned bits) {
        const unsigned mask = (1u << bits) - 1;
        v = ((v ^ a) * m1) & mask;
        v ^= v >> ((bits + 1) / 2);
        v = (v * m2 + b) & mask;
    }

    // operator() of every lane of a vector at once, each lane its own key's
    // parts: the lanes still past count step again, until none is.
    template <typename V, typename K>
    static void walk(V& v, const K& a, const K& m1, const K& m2, const K& b, unsigned count) {
        const unsigned bits = bits_for(count);
        step(v, a, m1, m2, b, bits);
        if ((count & (count - 1)) == 0) return;  // 2^bits: in range at once
        for (V past = V(v >= count); any(past); past = V(v >= count)) {
            V again = v;
            step(again, a, m1, m2, b, bits);
            v = (again & past) | (v & ~past);
        }
    }

    // The four parts of a 64-bit key, its low 32 bits and three shifts of
    // it: of one key, or lane by lane of a vector of them.
    template <typename U, typename S>
    static void key_parts(const S& key, U& a, U& m1, U& m2, U& b) {
        auto low = [](const S& k) {
            if constexpr (std::is_arithmetic_v<S>) return U(k);
            else return __builtin_convertvector(k, U);
        };
        a = low(key), m1 = low(key >> 16) | 1u, m2 = low(key >> 32) | 1u, b = low(key >> 48);
    }

private:
    // The bits of the numbers the bijection permutes: the fewest that count.
    static unsigned bits_for(unsigned count) {
        return count <= 1 ? 0 : 32 - unsigned(__builtin_clz(count - 1));
    }

    unsigned count_, bits_, a_ = 0, m1_ = 0, m2_ = 0, b_ = 0;
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

// A pixel's key, the keys of its two permutations (xor'd in, then mixed)
// and its samples' seeds: of one pixel, or lane by lane (written through a
// reference, as mix64_in_place).
template <typename S>
inline void pixel_key(const S& x, const S& y, S& key) {
    key = (y << 32) | x;
    mix64_in_place(key);
}
inline constexpr std::uint64_t kColumnKey = 0x9e3779b97f4a7c15ull, kRowKey = 0xbf58476d1ce4e5b9ull;
template <typename S>
inline void sample_seed(const S& key, const S& sample, S& seed) {
    seed = key ^ sample * 0xd1b54a32d192ed03ull;
}

// One pixel's samples, what depends on the pixel alone worked out once.
class PixelSamples {
public:
    PixelSamples(int px, int py, StrataGrid grid)
        : grid_(grid), key_(key_of(px, py)), column_of_row_(grid.ny, mix64(key_ ^ kColumnKey)),
          row_of_column_(grid.nx, mix64(key_ ^ kRowKey)), column_(column_of_row_(0)) {}

    // The width of a sub-cell, a pixel's 1 / n.
    double unit() const { return 1.0 / double(grid_.nx * grid_.ny); }

    // Any one sample.
    SampleOffset operator[](int sample) const {
        if (grid_.nx * grid_.ny == 1) return {0.5, 0.5};
        return jittered(cell(sample, sample % grid_.nx, sample / grid_.nx, column_of_row_(sample / grid_.nx)),
                        unit());
    }

    // The samples' cells in order, 0, 1, 2, ... as operator[] takes them
    // (for n > 1), one at a time: the stratum counted along instead of
    // divided out, and a row of strata's sub-column worked out once a row.
    // What cells_at_once, which the renderer runs, is tested against.
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
        std::uint64_t seed;
        sample_seed(key_, std::uint64_t(sample), seed);
        return {sx * grid_.ny + column, sy * grid_.nx + row_of_column_(sx), seed};
    }

    static std::uint64_t key_of(int px, int py) {
        std::uint64_t key;
        pixel_key(std::uint64_t(std::uint32_t(px)), std::uint64_t(std::uint32_t(py)), key);
        return key;
    }

    StrataGrid grid_;
    std::uint64_t key_;
    Permutation column_of_row_, row_of_column_;
    int sample_ = 0, sx_ = 0, sy_ = 0, column_;  // next_cell()'s place
};

// s / d and s % d of every lane (d > 0, s d < 2^32: samples below 4096)
// by one multiply, as compilers divide by a constant: floor(s m / 2^32)
// with m = ceil(2^32 / d) is floor(s / d) while s d < 2^32.
template <typename U>
FH_HOT_INLINE void divide_lanes(const U& s, unsigned d, U& quotient, U& remainder) {
    typedef std::uint64_t Wide __attribute__((vector_size(2 * sizeof(U))));
    const std::uint64_t m = ((std::uint64_t(1) << 32) + d - 1) / d;
    quotient = __builtin_convertvector((__builtin_convertvector(s, Wide) * m) >> 32, U);
    remainder = s - quotient * d;
}

// Many pixels' keys at once, a pixel a lane (PixelSamples' key_ and the
// parts of its permutations' keys), for cells_at_once. U: a vector of
// unsigned 32-bit lanes, S: of 64-bit ones, as many.
template <typename U, typename S>
struct PixelKeys {
    S key;
    U column[4], row[4];  // a, m1, m2, b of column_of_row_'s key, and of row_of_column_'s

    PixelKeys() = default;

    FH_HOT_INLINE PixelKeys(const U& px, const U& py) {
        pixel_key(__builtin_convertvector(px, S), __builtin_convertvector(py, S), key);
        permutation_parts(key, column, row);
    }

    // One pixel's keys in every lane, worked out once.
    FH_HOT_INLINE PixelKeys(unsigned px, unsigned py) {
        std::uint64_t k;
        pixel_key(std::uint64_t(px), std::uint64_t(py), k);
        unsigned c[4], r[4];
        permutation_parts(k, c, r);
        key = S{} + k;
        for (int i = 0; i < 4; ++i) column[i] = U{} + c[i], row[i] = U{} + r[i];
    }

private:
    // The parts of the two permutations' keys, from the pixel's key: of
    // one pixel (V, K scalars) or lane by lane.
    template <typename V, typename K>
    FH_HOT_INLINE static void permutation_parts(const K& pixel, V (&c)[4], V (&r)[4]) {
        K column_key = pixel ^ kColumnKey, row_key = pixel ^ kRowKey;
        mix64_in_place(column_key);
        mix64_in_place(row_key);
        Permutation::key_parts(column_key, c[0], c[1], c[2], c[3]);
        Permutation::key_parts(row_key, r[0], r[1], r[2], r[3]);
    }
};

// Many samples' cells at once, a sample a lane: lane i is sample s[i] of
// the pixel of keys' lane i, its cell (x[i], y[i]) and seed as
// PixelSamples' next_cell gives them. Where nx and ny are powers of two
// (2, 4, 8, 16, 64, 256 ... samples) the strata are shifts and masks and
// each permutation one step; otherwise a multiply and a walk.
template <typename U, typename S>
FH_HOT_INLINE void cells_at_once(StrataGrid grid, const PixelKeys<U, S>& keys, const U& s, U& x, U& y, S& seed) {
    const unsigned nx = unsigned(grid.nx), ny = unsigned(grid.ny);
    U sx, sy;
    if ((nx & (nx - 1)) == 0) sx = s & (nx - 1), sy = s >> __builtin_ctz(nx);
    else divide_lanes(s, nx, sy, sx);
    sample_seed(keys.key, __builtin_convertvector(s, S), seed);
    x = sx * ny;
    y = sy * nx;
    // Now each lane's sub-column, and sub-row.
    Permutation::walk(sy, keys.column[0], keys.column[1], keys.column[2], keys.column[3], ny);
    Permutation::walk(sx, keys.row[0], keys.row[1], keys.row[2], keys.row[3], nx);
    x += sy;
    y += sx;
}

inline SampleOffset sample_offset(int px, int py, int sample, StrataGrid grid) {
    return PixelSamples(px, py, grid)[sample];
}

}  // namespace fh
