// SIMD lanes: Lanes<T> holds kLanes<T> values of T that one instruction
// works on together -- 8 doubles or 16 floats with AVX-512, half as many
// with AVX2. The tracer runs every ray in packets of that many (core/packet.h).
//
// These are GCC/Clang vector extensions, not intrinsics: +, -, *, / and the
// comparisons work lane by lane, a comparison gives LaneInts<T> (all bits
// set where true), and `m ? a : b` selects per lane. The compiler emits the
// widest instructions the target has, and plain SSE2 code without AVX: the
// code is vectorised as written, not by the auto-vectoriser's judgement.
//
// Each helper has a scalar overload with the same meaning, so formulas
// written over "V" (T or Lanes<T>) read the same either way.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include "core/vec.h"

namespace fh {

// Bytes per vector: the target's widest, unless the build fixes it
// (-DFIRSTHIT_SIMD_BYTES=32 measures AVX2-width code on an AVX-512 machine).
#if defined(FIRSTHIT_SIMD_BYTES)
inline constexpr int kSimdBytes = FIRSTHIT_SIMD_BYTES;
#elif defined(__AVX512F__)
inline constexpr int kSimdBytes = 64;
#elif defined(__AVX__)
inline constexpr int kSimdBytes = 32;
#else
inline constexpr int kSimdBytes = 16;
#endif
static_assert(kSimdBytes == 16 || kSimdBytes == 32 || kSimdBytes == 64,
              "FIRSTHIT_SIMD_BYTES: 16, 32 or 64 (a vector the target has)");

template <typename T>
inline constexpr int kLanes = kSimdBytes / int(sizeof(T));

template <typename T>
struct LaneTypes {
    static_assert(std::is_same_v<T, float> || std::is_same_v<T, double>);
    using Int = std::conditional_t<sizeof(T) == 8, std::int64_t, std::int32_t>;
    typedef T Values __attribute__((vector_size(kSimdBytes)));
    typedef Int Ints __attribute__((vector_size(kSimdBytes)));
};

template <typename T>
using Lanes = typename LaneTypes<T>::Values;
// Per-lane integers as wide as T, so they line up with Lanes<T>: primitive
// ids, and masks -- a comparison gives 0 or all bits set in each lane.
template <typename T>
using LaneInts = typename LaneTypes<T>::Ints;

// The scalar type of V: T for T and for Lanes<T>.
template <typename V>
struct ScalarOfImpl {
    using type = std::remove_cvref_t<decltype(std::declval<V>()[0])>;
};
template <typename V>
    requires std::is_floating_point_v<V>
struct ScalarOfImpl<V> {
    using type = V;
};
template <typename V>
using ScalarOf = typename ScalarOfImpl<V>::type;

// A packet of float or double lanes (what the helpers below take).
template <typename V>
concept LaneValues = std::is_same_v<V, Lanes<float>> || std::is_same_v<V, Lanes<double>>;
// Any one value per lane: floating-point or integer lanes, or a plain scalar.
template <typename V>
concept LaneWise = LaneValues<V> || std::is_same_v<V, LaneInts<float>> ||
                   std::is_same_v<V, LaneInts<double>> || std::is_arithmetic_v<V>;

template <typename T>
FH_HOT_INLINE Lanes<T> splat(T x) {
    return Lanes<T>{} + x;
}

// x in every lane of V (x itself when V is a scalar).
template <typename V>
FH_HOT_INLINE V as_lanes(ScalarOf<V> x) {
    if constexpr (std::is_floating_point_v<V>) return x;
    else return splat(x);
}

template <typename T>
FH_HOT_INLINE LaneInts<T> lane_index() {
    LaneInts<T> r;
    for (int i = 0; i < kLanes<T>; ++i) r[i] = i;
    return r;
}

// Lane i of v in every lane: one permute, with v left in its register (an
// element read or write by index would send it through memory).
template <typename V>
FH_HOT_INLINE V splat_lane(const V& v, int i) {
#if defined(__clang__)  // no variable-index shuffle builtin
    return V{} + v[i];
#else
    using Int = std::conditional_t<sizeof(ScalarOf<V>) == 8, std::int64_t, std::int32_t>;
    typedef Int Index __attribute__((vector_size(sizeof(V))));
    return __builtin_shuffle(v, Index{} + Int(i));
#endif
}

// Lanes [0, n) set: a packet's first n rays.
template <typename T>
FH_HOT_INLINE LaneInts<T> first_lanes(int n) {
    return lane_index<T>() < typename LaneTypes<T>::Int(n);
}

template <typename T>
FH_HOT_INLINE Lanes<T> load(const T* p) {
    Lanes<T> v;
    std::memcpy(&v, p, sizeof v);
    return v;
}

template <typename T>
FH_HOT_INLINE void store(T* p, const Lanes<T>& v) {
    std::memcpy(p, &v, sizeof v);
}

// ---- Masks ------------------------------------------------------------------

// Some lane is set. One instruction where the target has one.
template <typename M>
FH_HOT_INLINE bool any(const M& m) {
#if defined(__AVX512F__)
    if constexpr (sizeof(M) == 64) return _mm512_test_epi32_mask(__m512i(m), __m512i(m)) != 0;
#endif
#if defined(__AVX__)
    if constexpr (sizeof(M) == 32) return !_mm256_testz_si256(__m256i(m), __m256i(m));
#endif
#if defined(__SSE2__)
    if constexpr (sizeof(M) == 16) return _mm_movemask_epi8(__m128i(m)) != 0;
#endif
    constexpr int n = int(sizeof(M) / sizeof(m[0]));
    bool r = false;
    for (int i = 0; i < n; ++i) r |= m[i] != 0;
    return r;
}
FH_HOT_INLINE bool any(bool m) { return m; }

template <typename M>
FH_HOT_INLINE bool none(const M& m) {
    return !any(m);
}

// Every lane is set.
template <typename M>
FH_HOT_INLINE bool all(const M& m) {
    return !any(~m);
}
FH_HOT_INLINE bool all(bool m) { return m; }

// Bit i set where lane i is: a mask as an integer, to visit its lanes one
// by one (for_each_lane). One instruction where the target has one.
template <typename M>
FH_HOT_INLINE unsigned lane_bits(const M& m) {
#if defined(__AVX512F__)
    if constexpr (sizeof(M) == 64 && sizeof(m[0]) == 8) return _mm512_test_epi64_mask(__m512i(m), __m512i(m));
    if constexpr (sizeof(M) == 64 && sizeof(m[0]) == 4) return _mm512_test_epi32_mask(__m512i(m), __m512i(m));
#endif
#if defined(__AVX__)
    if constexpr (sizeof(M) == 32 && sizeof(m[0]) == 8) return unsigned(_mm256_movemask_pd(__m256d(m)));
    if constexpr (sizeof(M) == 32 && sizeof(m[0]) == 4) return unsigned(_mm256_movemask_ps(__m256(m)));
#endif
    constexpr int n = int(sizeof(M) / sizeof(m[0]));
    unsigned r = 0;
    for (int i = 0; i < n; ++i) r |= unsigned(m[i] != 0) << i;
    return r;
}

// How many lanes are set.
template <typename M>
FH_HOT_INLINE int count(const M& m) {
    return __builtin_popcount(lane_bits(m));
}

// fn(i) for each set lane i, in increasing order; stops early (and returns
// true) when fn does.
template <typename M, typename Fn>
FH_HOT_INLINE bool for_each_lane(const M& m, Fn&& fn) {
    for (unsigned b = lane_bits(m); b != 0; b &= b - 1)
        if (fn(__builtin_ctz(b))) return true;
    return false;
}

// ---- Arithmetic, lane by lane, with scalar twins ------------------------------

// Per lane, m ? a : b (a vector condition selects lane by lane).
template <typename M, LaneWise V>
FH_HOT_INLINE V select(const M& m, const V& a, const V& b) {
    return m ? a : b;
}

// As std::min and std::max, also for NaN: the first argument wins a tie or
// an unordered comparison.
template <typename V>
FH_HOT_INLINE V min(const V& a, const V& b) {
    return select(b < a, b, a);
}
template <typename V>
FH_HOT_INLINE V max(const V& a, const V& b) {
    return select(a < b, b, a);
}

// The lane loops below compile to one instruction each (vsqrtpd, vandpd,
// vfmadd...) once inlined: GCC vectorises a loop over a vector's lanes.
template <LaneValues V>
FH_HOT_INLINE V sqrt(const V& v) {
    V r = v;  // overwritten lane by lane (a copy only quiets -Wmaybe-uninitialized)
    for (int i = 0; i < kLanes<ScalarOf<V>>; ++i) r[i] = std::sqrt(v[i]);
    return r;
}
template <LaneValues V>
FH_HOT_INLINE V abs(const V& v) {
    V r = v;  // overwritten lane by lane
    for (int i = 0; i < kLanes<ScalarOf<V>>; ++i) r[i] = std::abs(v[i]);
    return r;
}
template <LaneValues V>
FH_HOT_INLINE V copysign(const V& magnitude, const V& sign) {
    V r = magnitude;  // overwritten lane by lane
    for (int i = 0; i < kLanes<ScalarOf<V>>; ++i) r[i] = std::copysign(magnitude[i], sign[i]);
    return r;
}
// a*b + c with one rounding, lane by lane (hardware FMA only: see exact.h).
template <LaneValues V>
FH_HOT_INLINE V fused_mul_add(const V& a, const V& b, const V& c) {
    V r = c;  // overwritten lane by lane
    for (int i = 0; i < kLanes<ScalarOf<V>>; ++i) r[i] = std::fma(a[i], b[i], c[i]);
    return r;
}

template <typename T, typename = std::enable_if_t<std::is_floating_point_v<T>>>
FH_HOT_INLINE T sqrt(T v) {
    return std::sqrt(v);
}
template <typename T, typename = std::enable_if_t<std::is_floating_point_v<T>>>
FH_HOT_INLINE T abs(T v) {
    return std::abs(v);
}
template <typename T, typename = std::enable_if_t<std::is_floating_point_v<T>>>
FH_HOT_INLINE T copysign(T magnitude, T sign) {
    return std::copysign(magnitude, sign);
}
template <typename T, typename = std::enable_if_t<std::is_floating_point_v<T>>>
FH_HOT_INLINE T fused_mul_add(T a, T b, T c) {
    return std::fma(a, b, c);
}

// No lane is NaN or infinite.
template <LaneValues V>
FH_HOT_INLINE auto finite(const V& v) {
    return abs(v) <= std::numeric_limits<ScalarOf<V>>::max();  // false for NaN and +-inf
}

}  // namespace fh
