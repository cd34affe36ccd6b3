// Branch-free acos and whole powers for the shading loops. A call to libm's
// acos or a data-dependent loop stops GCC from vectorising a loop over a
// batch; these are straight-line code, so a loop of them runs on every AVX2
// lane. Both are as exact as the library versions (tests/core/test_fast_math.cpp).
#pragma once

#include <iterator>
#include <cmath>

#include "core/vec.h"

namespace fh {

namespace detail {

// asin(s) = s + s z P(z) with z = s^2, for s in [0, 1/2] (z <= 1/4), with P
// the interpolant of asin's series at Chebyshev points of [0, 1/4]: half the
// terms of the truncated series for the same error, within an ulp of asin
// (double) or 1e-9 (float). scripts/fit_asin.py computes these and checks them.
template <typename T>
struct AsinPoly;
template <>
struct AsinPoly<double> {
    static constexpr double c[] = {
        0.16666666666666635,  0.07500000000023023,  0.04464285710334659,  0.030381947234128386,
        0.022372055086407272, 0.017355078034597682, 0.013932117930380628, 0.011855298653244972,
        0.007905522982279459, 0.015719254811604817, -0.010206222534179688, 0.02777099609375};
};
template <>
struct AsinPoly<float> {
    static constexpr float c[] = {0.16666666337430913f, 0.07500094543496029f, 0.04459940152894563f,
                                  0.031100662730802735f, 0.01714923837880633f, 0.033690847169054905f};
};

template <typename T>
FH_HOT_INLINE T asin_small(T s) {
    constexpr auto& c = AsinPoly<T>::c;
    constexpr int kTerms = int(std::size(c));
    static_assert(kTerms % 2 == 0);
    // P(z) = E(z^2) + z O(z^2): two Horner chains of half the length, which
    // run side by side (a single chain of FMAs waits on each one's latency).
    const T z = s * s;
    const T z2 = z * z;
    T even = c[kTerms - 2], odd = c[kTerms - 1];
#pragma GCC unroll 16  // straight-line code, so the loop around it vectorises
    for (int k = kTerms - 4; k >= 0; k -= 2) {
        even = std::fma(even, z2, c[k]);
        odd = std::fma(odd, z2, c[k + 1]);
    }
    const T p = std::fma(odd, z, even);
    return std::fma(s * z, p, s);
}

}  // namespace detail

// acos(x) for x in [-1, 1] (NaN in, NaN out), within a few ulps of pi.
// |x| <= 1/2: pi/2 - asin(|x|); else 2 asin(sqrt((1 - |x|) / 2)), which is
// exact in the subtraction (Sterbenz) and keeps acos accurate near 1, where
// it is steepest. Negative x: pi - acos(|x|).
template <typename T>
FH_HOT_INLINE T acos_fast(T x) {
    constexpr T kPi = T(3.14159265358979323846);
    const T a = std::abs(x);
    const bool small = a <= T(0.5);
    const T s = small ? a : std::sqrt((T(1) - a) * T(0.5));
    const T asin_s = detail::asin_small(s);
    const T acos_a = small ? kPi / 2 - asin_s : 2 * asin_s;
    return x < T(0) ? kPi - acos_a : acos_a;
}

// x^n for a whole n in [0, kWholePowerLimit], given as a T, by square-and-
// multiply over n's bits from the top: a fixed sequence of selects, no loop
// on n. The report's Phong exponents are whole; this is several times
// cheaper than std::pow and vectorises.
inline constexpr int kWholePowerLimit = 4095;  // 12 bits

// One step: r^2, times x if n >= 2^bit (then n -= 2^bit). Start from r = 1 at
// the top bit of the largest n and go down to bit 0.
template <typename T>
FH_HOT_INLINE void pow_whole_step(T& r, T x, T& n, int bit) {
    const T b = T(1 << bit);
    const bool set = n >= b;
    r *= r;
    r = set ? r * x : r;
    n = set ? n - b : n;
}

template <typename T>
FH_HOT_INLINE T pow_whole(T x, T n) {
    T r = 1;
#pragma GCC unroll 16
    for (int bit = 11; bit >= 0; --bit) pow_whole_step(r, x, n, bit);
    return r;
}

}  // namespace fh
