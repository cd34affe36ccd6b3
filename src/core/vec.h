// Vectors and colours of the tracer, over its scalar type T (float or double).
// The tracer is a template on T so both precisions live in one binary
// (the `precision` render setting picks one at run time).
#pragma once

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <limits>

// For the packet formulas (core/packet.h): they are fast only inlined into
// the loop that calls them, and GCC's heuristics do not always inline them.
// The sanitizer builds (scripts/build_asan.sh, test_tsan.sh) define
// FIRSTHIT_NO_FORCED_INLINE and let the compiler choose: forced inlining
// under AddressSanitizer made render_float.cpp alone a 174 s compile (19 s
// without), for code whose speed those builds do not measure.
#ifdef FIRSTHIT_NO_FORCED_INLINE
#define FH_HOT_INLINE inline
#define FH_HOT_LAMBDA
#else
#define FH_HOT_INLINE inline __attribute__((always_inline))
#define FH_HOT_LAMBDA __attribute__((always_inline))
#endif

namespace fh {

template <typename T>
using Vec3 = glm::vec<3, T, glm::defaultp>;

using dvec3 = Vec3<double>;
using dvec2 = glm::vec<2, double, glm::defaultp>;  // texture coordinates

// Colours are the report's 0..255 values, kept unclamped until the final pixel.
template <typename T>
using Color = Vec3<T>;

template <typename T>
inline constexpr T kInfinity = std::numeric_limits<T>::infinity();

template <typename T>
inline bool is_finite(const Vec3<T>& v) {
    return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

template <typename T>
inline T max_abs_component(const Vec3<T>& v) {
    return std::max(std::abs(v.x), std::max(std::abs(v.y), std::abs(v.z)));
}

// v times the power of two that brings its largest component into [1, 2):
// the same direction to the bit (a power of two scales exactly), and
// nothing computed from it -- a length, a cross product -- under- or
// overflows. A direction of 1e-300 once made every camera ray NaN. v itself
// when it is zero or not finite.
template <typename T>
inline Vec3<T> power_of_two_scaled(const Vec3<T>& v) {
    const T m = max_abs_component(v);
    if (!(m > 0) || !std::isfinite(m)) return v;
    const int e = std::ilogb(m);
    return {std::scalbn(v.x, -e), std::scalbn(v.y, -e), std::scalbn(v.z, -e)};
}

// v / |v|, scaled first so that huge or tiny components neither overflow
// nor underflow in the length; the zero vector for a zero or non-finite v.
template <typename T>
inline Vec3<T> unit_or_zero(const Vec3<T>& v) {
    const T m = max_abs_component(v);
    if (!(m > 0) || !std::isfinite(m)) return Vec3<T>(0);
    const Vec3<T> scaled = v / m;
    return scaled / glm::length(scaled);
}

}  // namespace fh
