// Branch-free acos and whole powers for the shading loops. A call to libm's
// acos or a data-dependent loop stops GCC from vectorising a loop over a
// batch; these are straight-line code, so a loop of them runs on every AVX2
// lane. Both are as exact as the library versions (tests/core/test_fast_math.cpp).
#pragma once

#include <array>
#include <cmath>

#include "core/vec.h"

namespace fh {

namespace detail {

// asin(s) = s + s z P(z) with z = s^2: the Taylor series,
//     asin(s) = sum_k c_k s^(2k+1),  c_0 = 1,  c_(k+1) = c_k (2k+1)^2 / ((2k+2)(2k+3)).
// acos_fast only needs s <= 1/2 (z <= 1/4), where term k is below c_k 4^-k:
// 25 terms leave ~1e-18 (double), 12 leave ~1e-9 (float).
template <int Terms>
constexpr std::array<double, Terms> asin_series() {
    std::array<double, Terms> p{};
    double c = 1;
    for (int k = 0; k < Terms; ++k) {
        c = c * (2.0 * k + 1) * (2.0 * k + 1) / ((2.0 * k + 2) * (2.0 * k + 3));
        p[size_t(k)] = c;  // coefficient of z^k in P
    }
    return p;
}

template <typename T>
FH_HOT_INLINE T asin_small(T s) {
    constexpr int kTerms = sizeof(T) == 8 ? 25 : 12;
    constexpr auto c = asin_series<kTerms>();
    const T z = s * s;
    T p = T(c[kTerms - 1]);
#pragma GCC unroll 32  // straight-line code, so the loop around it vectorises
    for (int k = kTerms - 2; k >= 0; --k) p = std::fma(p, z, T(c[size_t(k)]));
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
