// Small exact-arithmetic helpers for the intersection routines, for one value
// (V = T) or a packet of them (V = Lanes<T>, core/simd.h) alike.
//
// Where the CPU has a fused multiply-add, a*b + c is computed with a single
// rounding, so a product feeding a sum loses nothing: the sphere test uses
// that to find a ray's closest approach to a far-away centre without
// cancellation. orientation() gives the sign of a 2x2 determinant, never
// wrong, which is what makes the triangle test watertight.
#pragma once

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

// v as computed: the compiler may not fuse the product it holds into a
// later sum (an FMA would round differently at different call sites).
template <typename V>
FH_HOT_INLINE V rounded(V v) {
#if defined(__x86_64__) || defined(__i386__)
    asm("" : "+v"(v));
#elif defined(__aarch64__)
    asm("" : "+w"(v));
#endif
    return v;
}

// px*qy - py*qx as the rounded difference of the rounded products, barring
// underflow (coordinates below ~1e-19 in float, ~1e-154 in double):
//  - never of the wrong sign: rounding is monotone, so the products round
//    in the order of their exact values, and the difference of two floats
//    rounds to its exact sign;
//  - zero where the exact value is zero, and also where the two products
//    round to the same value (within an ulp of zero): "on the line";
//  - exactly -orientation(qx, qy, px, py): the same products in the other
//    order, and rounding is symmetric.
// So two triangles that share an edge classify a ray against it the same
// way, and a ray never falls outside every triangle around a point it
// passes through, which is what makes the triangle test watertight. A
// fused multiply-add would break both (fl(a*b - fl(c*d)) can change sign),
// hence rounded().
template <typename V>
FH_HOT_INLINE V orientation(V px, V py, V qx, V qy) {
    return rounded(px * qy) - rounded(py * qx);
}

}  // namespace fh
