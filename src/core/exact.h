// Small exact-arithmetic helpers for the intersection routines. All of them
// are branch-free, so the batch loops over rays (render/batch_intersect.h)
// still vectorise.
//
// Where the CPU has a fused multiply-add, a*b + c is computed with a single
// rounding, so a product feeding a sum loses nothing: the sphere test uses
// that to find a ray's closest approach to a far-away centre without
// cancellation. orientation() gives the exact sign of a 2x2 determinant,
// which is what makes the triangle test watertight.
#pragma once

#include <cmath>
#include <type_traits>

namespace fh {

#if defined(__FMA__) || defined(__aarch64__) || defined(__ARM_FEATURE_FMA)
inline constexpr bool kHardwareFma = true;
#else
inline constexpr bool kHardwareFma = false;
#endif

// a*b + c, with one rounding where the CPU fuses it. Without hardware FMA this
// is the plain expression (std::fma would be a slow library call in the hot
// loop); the result is then only less accurate, never wrong in kind.
template <typename T>
inline T mul_add(T a, T b, T c) {
    if constexpr (kHardwareFma) return std::fma(a, b, c);
    else return a * b + c;
}

// a*b - c*d with the same rounding wherever it is used: with FMA the product
// c*d is rounded and a*b is not; without, both are. (Left to itself the
// compiler may fuse either product, differently at different call sites.)
template <typename T>
inline T mul_sub(T a, T b, T c, T d) {
    return mul_add(a, b, -(c * d));
}

// The rounding error of the product p = fl(a*b): a*b - p, exactly (barring
// underflow). With FMA one instruction; without, Dekker's product over
// Veltkamp's split (no compiler may fuse there: the CPU has no FMA).
template <typename T>
inline T product_error(T a, T b, T p) {
    if constexpr (kHardwareFma) {
        return std::fma(a, b, -p);
    } else {
        constexpr T split = std::is_same_v<T, float> ? T(4097) : T(134217729);  // 2^12+1, 2^27+1
        const T ca = split * a, cb = split * b;
        const T ah = ca - (ca - a), al = a - ah;
        const T bh = cb - (cb - b), bl = b - bh;
        return ((ah * bh - p) + ah * bl + al * bh) + al * bl;
    }
}

// px*qy - py*qx with its exact sign: never of the wrong sign, and zero only
// where the exact value is zero or (rarely) within an ulp of it. Barring
// underflow, i.e. coordinates below ~1e-19 in float, ~1e-154 in double.
//
// The value is the rounded difference of the rounded products plus the
// difference of their exact rounding errors (product_error), a compensated
// determinant:
//  - when the products round apart, rounding is monotone, so their order is
//    that of the exact products; the correction is below an ulp of them and
//    can at worst cancel the difference to zero, never flip its sign;
//  - when they round to the same value, the difference is 0 and the
//    correction alone, exact up to one rounding, gives the sign.
// And orientation(q, p) is exactly -orientation(p, q): the same products and
// errors in the other order, and rounding is symmetric. So two triangles that
// share an edge classify a ray against it consistently, which is what makes
// the triangle test watertight.
//
// Written without a select: with one the compiler moves each side into a
// branch of its own, and the batch loops stop vectorising (it may not
// speculate floating-point operations). The products a and b have other uses
// than the subtraction, so the compiler does not fuse them into it.
template <typename T>
inline T orientation(T px, T py, T qx, T qy) {
    const T a = px * qy;
    const T b = py * qx;
    return (a - b) + (product_error(px, qy, a) - product_error(py, qx, b));
}

}  // namespace fh
