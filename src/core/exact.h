// Small exact-arithmetic helpers for the intersection routines, for one value
// (V = T) or a packet of them (V = Lanes<T>, core/simd.h) alike.
//
// Where the CPU has a fused multiply-add, a*b + c is computed with a single
// rounding, so a product feeding a sum loses nothing: the sphere test uses
// that to find a ray's closest approach to a far-away centre without
// cancellation. orientation() gives the exact sign of a 2x2 determinant,
// which is what makes the triangle test watertight.
#pragma once

#include <type_traits>

#include "core/simd.h"

namespace fh {

#if defined(__FMA__) || defined(__aarch64__) || defined(__ARM_FEATURE_FMA)
inline constexpr bool kHardwareFma = true;
#else
inline constexpr bool kHardwareFma = false;
#endif

// a*b + c, with one rounding where the CPU fuses it. Without hardware FMA this
// is the plain expression (std::fma would be a slow library call in the hot
// loop); the result is then only less accurate, never wrong in kind.
template <typename V>
FH_HOT_INLINE V mul_add(V a, V b, V c) {
    if constexpr (kHardwareFma) return fused_mul_add(a, b, c);
    else return a * b + c;
}

// a*b - c*d with the same rounding wherever it is used: with FMA the product
// c*d is rounded and a*b is not; without, both are. (Left to itself the
// compiler may fuse either product, differently at different call sites.)
template <typename V>
FH_HOT_INLINE V mul_sub(V a, V b, V c, V d) {
    return mul_add(a, b, -(c * d));
}

// The rounding error of the product p = fl(a*b): a*b - p, exactly (barring
// underflow). With FMA one instruction; without, Dekker's product over
// Veltkamp's split (no compiler may fuse there: the CPU has no FMA).
template <typename V>
FH_HOT_INLINE V product_error(V a, V b, V p) {
    if constexpr (kHardwareFma) {
        return fused_mul_add(a, b, -p);
    } else {
        using T = ScalarOf<V>;
        constexpr T split = std::is_same_v<T, float> ? T(4097) : T(134217729);  // 2^12+1, 2^27+1
        const V ca = split * a, cb = split * b;
        const V ah = ca - (ca - a), al = a - ah;
        const V bh = cb - (cb - b), bl = b - bh;
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
// Written without a select, as straight-line arithmetic that is the same on
// one value and on a packet. The products a and b have other uses than the
// subtraction, so the compiler does not fuse them into it.
template <typename V>
FH_HOT_INLINE V orientation(V px, V py, V qx, V qy) {
    const V a = px * qy;
    const V b = py * qx;
    return (a - b) + (product_error(px, qy, a) - product_error(py, qx, b));
}

}  // namespace fh
