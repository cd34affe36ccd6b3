// A packet of rays: kLanes<T> rays in structure-of-arrays form, one ray per
// SIMD lane (core/simd.h). The tracer's unit of work: every intersection and
// shading formula runs on a whole packet at once.
//
// Vec3Lanes<T> is one 3-vector per lane, with the few operations the
// formulas need; mixed with a plain Vec3<T> (a sphere's centre, a light's
// direction) that vector counts for every lane. The operations round as glm's
// do (dot = x*x' + y*y' + z*z', normalize = v * (1 / |v|)), so a formula
// gives the same bits as its scalar form.
#pragma once

#include "core/ray.h"
#include "core/simd.h"

namespace fh {

template <typename T>
struct Vec3Lanes {
    using V = Lanes<T>;
    V x, y, z;

    static FH_HOT_INLINE Vec3Lanes splat(const Vec3<T>& v) {
        return {fh::splat(v.x), fh::splat(v.y), fh::splat(v.z)};
    }
    Vec3<T> lane(int i) const { return {x[i], y[i], z[i]}; }
    FH_HOT_INLINE Vec3Lanes splat_lane(int i) const {
        return {fh::splat_lane(x, i), fh::splat_lane(y, i), fh::splat_lane(z, i)};
    }

    FH_HOT_INLINE Vec3Lanes& operator+=(const Vec3Lanes& o) {
        x += o.x;
        y += o.y;
        z += o.z;
        return *this;
    }
};

template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator+(const Vec3Lanes<T>& a, const Vec3Lanes<T>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator+(const Vec3Lanes<T>& a, const Vec3<T>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator+(const Vec3<T>& a, const Vec3Lanes<T>& b) {
    return {a.x + b.x, a.y + b.y, a.z + b.z};
}
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator-(const Vec3Lanes<T>& a, const Vec3Lanes<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator-(const Vec3Lanes<T>& a, const Vec3<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator-(const Vec3<T>& a, const Vec3Lanes<T>& b) {
    return {a.x - b.x, a.y - b.y, a.z - b.z};
}
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator-(const Vec3Lanes<T>& a) {
    return {-a.x, -a.y, -a.z};
}
// Scale each lane's vector by that lane's value, or by one value.
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator*(const Lanes<T>& s, const Vec3Lanes<T>& v) {
    return {s * v.x, s * v.y, s * v.z};
}
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator*(const Vec3Lanes<T>& v, const Lanes<T>& s) {
    return {v.x * s, v.y * s, v.z * s};
}
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator*(T s, const Vec3Lanes<T>& v) {
    return {s * v.x, s * v.y, s * v.z};
}
// One vector for every lane, scaled per lane.
template <typename T>
FH_HOT_INLINE Vec3Lanes<T> operator*(const Lanes<T>& s, const Vec3<T>& v) {
    return {s * v.x, s * v.y, s * v.z};
}

template <typename T>
FH_HOT_INLINE Lanes<T> dot(const Vec3Lanes<T>& a, const Vec3Lanes<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
FH_HOT_INLINE Lanes<T> dot(const Vec3Lanes<T>& a, const Vec3<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <typename T>
FH_HOT_INLINE Lanes<T> dot(const Vec3<T>& a, const Vec3Lanes<T>& b) {
    return a.x * b.x + a.y * b.y + a.z * b.z;
}

template <typename T>
FH_HOT_INLINE Vec3Lanes<T> cross(const Vec3Lanes<T>& a, const Vec3Lanes<T>& b) {
    return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}

template <typename T>
FH_HOT_INLINE Vec3Lanes<T> normalize(const Vec3Lanes<T>& v) {
    return v * (T(1) / sqrt(dot(v, v)));
}

template <typename T>
FH_HOT_INLINE Lanes<T> max_abs_component(const Vec3Lanes<T>& v) {
    return max(abs(v.x), max(abs(v.y), abs(v.z)));
}

template <typename T>
FH_HOT_INLINE Vec3Lanes<T> select(const LaneInts<T>& m, const Vec3Lanes<T>& a,
                                  const Vec3Lanes<T>& b) {
    return {m ? a.x : b.x, m ? a.y : b.y, m ? a.z : b.z};
}

template <typename T>
using ColorLanes = Vec3Lanes<T>;

template <typename T>
struct RayPacket {
    Vec3Lanes<T> origin;
    Vec3Lanes<T> direction;  // unit length in every lane

    // One ray in every lane: how a single ray goes through the packet code.
    static RayPacket splat(const Ray<T>& r) {
        return {Vec3Lanes<T>::splat(r.origin), Vec3Lanes<T>::splat(r.direction)};
    }
    Ray<T> lane(int i) const { return {origin.lane(i), direction.lane(i)}; }

    FH_HOT_INLINE Vec3Lanes<T> at(const Lanes<T>& t) const { return origin + t * direction; }
};

}  // namespace fh
