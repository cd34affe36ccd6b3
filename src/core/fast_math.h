// Branch-free acos and whole powers for shading, on one value (V = T) or a
// packet of them (V = Lanes<T>, core/simd.h): libm has no packet acos, and
// std::pow with a per-lane exponent would be one call per lane. Both are as
// exact as the library versions (tests/core/test_fast_math.cpp).
#pragma once

#include <iterator>

#include "core/simd.h"

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

template <typename V>
FH_HOT_INLINE V asin_small(V s) {
    using T = ScalarOf<V>;
    constexpr auto& c = AsinPoly<T>::c;
    constexpr int kTerms = int(std::size(c));
    static_assert(kTerms % 2 == 0);
    // P(z) = E(z^2) + z O(z^2): two Horner chains of half the length, which
    // run side by side (a single chain of FMAs waits on each one's latency).
    const V z = s * s;
    const V z2 = z * z;
    V even = as_lanes<V>(c[kTerms - 2]), odd = as_lanes<V>(c[kTerms - 1]);
#pragma GCC unroll 16
    for (int k = kTerms - 4; k >= 0; k -= 2) {
        even = fused_mul_add(even, z2, as_lanes<V>(c[k]));
        odd = fused_mul_add(odd, z2, as_lanes<V>(c[k + 1]));
    }
    const V p = fused_mul_add(odd, z, even);
    return fused_mul_add(s * z, p, s);
}

}  // namespace detail

// acos(x) for x in [-1, 1] (NaN in, NaN out), within a few ulps of pi.
// |x| <= 1/2: pi/2 - asin(|x|); else 2 asin(sqrt((1 - |x|) / 2)), which is
// exact in the subtraction (Sterbenz) and keeps acos accurate near 1, where
// it is steepest. Negative x: pi - acos(|x|).
template <typename V>
FH_HOT_INLINE V acos_fast(V x) {
    using T = ScalarOf<V>;
    constexpr T kPi = T(3.14159265358979323846);
    const V a = abs(x);
    const auto small = a <= T(0.5);
    const V s = select(small, a, sqrt((T(1) - a) * T(0.5)));
    const V asin_s = detail::asin_small(s);
    const V acos_a = select(small, kPi / 2 - asin_s, T(2) * asin_s);
    return select(x < T(0), kPi - acos_a, acos_a);
}

// x^n for a whole n in [0, kWholePowerLimit], given per lane as a T, by
// square-and-multiply over n's bits from the top: a fixed sequence of selects,
// no branch on n, so each lane may have its own n. The report's Phong
// exponents are whole; this is several times cheaper than std::pow. The
// shader runs one step per bit of the scene's largest exponent.
inline constexpr int kWholePowerLimit = 4095;  // 12 bits

// One step: r^2, times x if n >= 2^bit (then n -= 2^bit). Start from r = 1 at
// the top bit of the largest n and go down to bit 0.
template <typename V>
FH_HOT_INLINE void pow_whole_step(V& r, V x, V& n, int bit) {
    using T = ScalarOf<V>;
    const T b = T(1 << bit);
    const auto set = n >= b;
    r *= r;
    r = select(set, r * x, r);
    n = select(set, n - b, n);
}

}  // namespace fh
